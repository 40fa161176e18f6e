"""``facesynth deform``: marker motion -> face-mesh animation (paper VII-A, Eq. 14-15).

Reads the motion, the mesh and the binding, binds the mesh to the markers and animates it
(:mod:`facesynth.domain.retarget.deform`: mesh-distance weights, Eq. 14-15, and the similarity fit
that carries the motion into the mesh's frame), and writes the ``meshanim`` artifact. With
``apply_head_motion`` the motion's rigid head motion is put back through the same transform.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.config import DeformSettings, settings_json
from facesynth.domain.retarget.deform import animate, bind
from facesynth.formats.mesh import read_binding, read_mesh
from facesynth.model.artifacts import check_output
from facesynth.model.meshanim import MeshAnimation
from facesynth.model.motion import Motion


@dataclass(frozen=True)
class DeformResult:
    """What ``facesynth deform`` made.

    frames: frames of the mesh animation.
    vertices: vertices of the mesh.
    unreached: vertices farther than deform.distance_threshold from every marker (they stay at rest).
    scale: the similarity's scale from marker millimetres to mesh units.
    fit_rms: RMS distance of the fitted markers to their vertices (mesh units).
    """

    frames: int
    vertices: int
    unreached: int
    scale: float
    fit_rms: float


def run(motion_path: Path, mesh: Path, binding_path: Path, out: Path, settings: DeformSettings,
        overwrite: bool = False) -> DeformResult:
    """Deform ``mesh`` by the marker motion of ``motion_path`` and write ``out`` (a ``meshanim`` artifact)."""
    check_output(out, overwrite)
    motion = Motion.read(motion_path)
    head = motion.head() if settings.apply_head_motion else None
    vertices, faces = read_mesh(mesh)
    binding = read_binding(binding_path)
    names = motion.marker_names
    bound = bind(vertices, faces, binding, names, settings, str(mesh), str(binding_path))
    frames, fit = animate(bound, motion.markers, names, motion.reference, head)
    # Markers do not record where the eyes look: the gaze track says so (NaN), and the renderer's
    # eyes then look ahead rather than follow an invented gaze.
    gaze = np.full((len(frames), 2, 2), np.nan, np.float32)
    MeshAnimation(frames, motion.fps, vertices, faces, motion.markers, names, bound.weights, bound.markers,
                  bound.vertex_of, fit.fit_rms, gaze, motion.frame_provenance(motion_path)).write(
        out, config=settings_json(settings), inputs=[motion_path, mesh, binding_path], overwrite=overwrite)
    return DeformResult(len(frames), len(vertices), bound.unreached, fit.scale, fit.fit_rms)

