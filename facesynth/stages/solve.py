"""``facesynth solve``: a direct facial solve. Per frame, the rig weights in [0, 1] that best
explain the motion's markers at the rig's marker vertices, with a small temporal smoothness term
(:func:`facesynth.retarget.solve.solve_curves`), written as ``curves`` (``source = "solve"``).

The markers are carried into the rig's frame and units by a similarity fitted from the motion's
neutral reference to the rig's neutral at the bound vertices (as ``deform`` does); the solve fits
displacements from the reference. This is what users call a facial solve, and the reference that
key-shape retargeting (``facesynth retarget``) is judged against.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..artifacts import check_output
from ..config import SolveSettings, settings_json
from ..model.curves import RigCurves
from ..model.motion import Motion
from ..retarget.rig import TargetRig, load_rig, marker_map
from ..retarget.solve import solve_curves


def solve(motion: Motion, rig: TargetRig, settings: SolveSettings, where: str) -> tuple[np.ndarray, np.ndarray, int]:
    """(T, E) rig weights, (T,) RMS marker residual in rig units and iterations for ``motion``."""
    mmap = marker_map(rig, motion.marker_names, motion.reference, where)
    disp = mmap.displacements(motion.markers, motion.reference)
    basis = rig.deltas[:, mmap.vertices]
    return solve_curves(disp, basis, smooth=settings.smooth, ridge=settings.ridge, iterations=settings.iterations,
                        tolerance=settings.tolerance)


def run(motion_path: Path, out: Path, settings: SolveSettings, rig_path: Path | None = None,
        binding: Path | None = None, overwrite: bool = False) -> dict:
    """Solve ``motion_path`` on the rig (built-in when ``rig_path`` is None) and write ``out``."""
    check_output(out, overwrite)
    rig = load_rig(rig_path, binding)
    motion = Motion.read(motion_path)
    weights, residual, iterations = solve(motion, rig, settings, str(motion_path))
    inputs = [motion_path] + ([rig_path] if rig_path is not None and Path(rig_path).is_file() else [])
    RigCurves(weights, motion.fps, list(rig.shape_names), rig.name, rig.sha256, "solve", motion.head_rotation,
              motion.head_translation, residual=residual, method="bounded least squares with temporal smoothness").write(
        out, config=settings_json(settings), inputs=inputs, overwrite=overwrite)
    return {"frames": len(weights), "shapes": len(rig.shape_names), "iterations": iterations,
            "residual_rms": float(np.sqrt(np.nanmean(residual**2))), "rig": rig.name}
