"""``facesynth rig-mesh``: rig weight curves (``solve`` or ``retarget``) -> the rig's mesh animation
(``meshanim``), so ``facesynth render`` shows a solve or a retargeting on the face.

The mesh is ``neutral + sum_e w_e deltas_e`` in the rig's frame and units; the head motion the
curves carry is not applied (the face stays in the head frame)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy import sparse

from ..artifacts import check_output
from ..errors import InputError
from ..model.curves import RigCurves
from ..model.meshanim import MeshAnimation
from ..retarget.rig import load_rig


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
    rig = load_rig(rig_path, binding)
    curves = RigCurves.read(curves_path)
    if curves.rig_sha256 != rig.sha256:
        raise InputError(f"{curves_path}: the curves were made for rig {curves.rig_name!r}, not {rig.name!r}; "
                         f"give that rig with --rig.")
    if list(curves.shape_names) != list(rig.shape_names):
        raise InputError(f"{curves_path}: its shape names differ from rig {rig.name!r}'s; remake the curves on this rig.")
    vertices = rig.evaluate(curves.weights).astype(np.float32)
    names = list(rig.binding)
    verts = np.array([rig.binding[n] for n in names], np.int64)
    empty = sparse.csr_matrix((len(rig.neutral), len(names)), dtype=np.float32)
    MeshAnimation(vertices, curves.fps, rig.neutral.astype(np.float32), rig.faces, vertices[:, verts], names, empty,
                  names, verts, 0.0, np.full((len(vertices), 2, 2), np.nan, np.float32), curves.provenance).write(
        out, config="{}", inputs=[curves_path], overwrite=overwrite)
    return RigMeshResult(len(vertices), len(rig.neutral), rig.name)

