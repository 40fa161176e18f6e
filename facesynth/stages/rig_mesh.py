"""``facesynth rig-mesh``: rig weight curves (``solve`` or ``retarget``) -> the rig's mesh animation
(``meshanim``), to keep or inspect the posed mesh as a file. ``facesynth render`` reads curves
directly (posing the rig in memory the same way), so this step is optional.

The mesh is ``neutral + sum_e w_e deltas_e`` in the rig's frame and units
(:func:`facesynth.domain.rig.loading.pose_rig`); the head motion the curves carry is not applied (the
face stays in the head frame); the gaze track comes from the rig's ``eyeLook*`` shapes."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from facesynth.domain.rig.loading import load_rig, pose_rig
from facesynth.model.artifacts import check_output
from facesynth.model.curves import RigCurves


@dataclass(frozen=True)
class RigMeshResult:
    """What ``facesynth rig-mesh`` posed.

    frames: frames of the mesh animation.
    vertices: the rig's vertices.
    rig: the rig's name.
    """

    frames: int
    vertices: int
    rig: str


def run(curves_path: Path, out: Path, rig_path: Path | None = None, binding: Path | None = None,
        overwrite: bool = False) -> RigMeshResult:
    """Pose the rig with the curves of ``curves_path`` and write ``out``."""
    check_output(out, overwrite)
    rig = load_rig(rig_path, binding, need_binding=False)
    curves = RigCurves.read(curves_path)
    anim = pose_rig(curves, rig, str(curves_path))
    anim.provenance = curves.provenance
    anim.write(out, config="{}", inputs=[curves_path], overwrite=overwrite)
    return RigMeshResult(len(anim.vertices), len(rig.neutral), rig.name)

