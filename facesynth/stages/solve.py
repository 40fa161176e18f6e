"""``facesynth solve``: a direct facial solve. Per frame, the rig weights in [0, 1] that best
explain the motion's markers at the rig's marker vertices, with a small temporal smoothness term
(:func:`facesynth.domain.retarget.solve.solve_motion`), written as ``curves`` (``source = "solve"``).

The markers are carried into the rig's frame and units by a similarity fitted from the motion's
neutral reference to the rig's neutral at the bound vertices (as ``deform`` does); the solve fits
displacements from the reference. This is what users call a facial solve, and the reference that
key-shape retargeting (``facesynth retarget``) is judged against.

The input is a ``motion`` artifact, or a ``normalized`` one (a user's own capture after
``ingest`` and ``normalize``, with no database): then one take of it (``--take``, or the only
one) is solved, its markers resampled to ``solve.output_fps``, the head motion kept relative to
the take's mean pose as ``capture`` does, and the normalize reference serves as the rest pose.

A normalized capture posed from curves (``capture = posed``: Live Link Face, another rig's
curves) has no measurement noise: its markers are the rig's surface, its reference the rig's rest
pose and its head pose known. The smoothing and ridge terms are priors against marker noise and
only bias such a solve (they damp the eye shapes, which move the markers by 2-3 mm), so with
``solve.posed_captures = "exact"`` (the default) it is solved without them, to
``solve.exact_iterations`` and ``solve.exact_tolerance``
(:func:`facesynth.domain.retarget.facial_solve.settings_for`); the curves record
the settings used (their ``config``) and say so in ``method``. A ``motion`` artifact (a
synthesis) is always solved with the regularized settings.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from facesynth.base.config import SolveSettings
from facesynth.domain.retarget import facial_solve
from facesynth.domain.rig.loading import load_rig
from facesynth.model.artifacts import check_output


@dataclass(frozen=True)
class SolveResult:
    """What ``facesynth solve`` solved.

    frames: frames of the curves.
    shapes: the rig's blendshapes.
    iterations: the solver's iterations.
    residual_rms: RMS marker residual (rig units).
    rig: the rig's name.
    marker_residual_median_mm, marker_residual_p95_mm: the median and 95th percentile of each
        bound marker's distance from the solved rig, per frame, in the motion's millimetres.
    take: the solved take (a capture), or None.
    exact: solved without smoothing or ridge (a capture posed from curves, ``solve.posed_captures``).
    """

    frames: int
    shapes: int
    iterations: int
    residual_rms: float
    rig: str
    marker_residual_median_mm: float
    marker_residual_p95_mm: float
    take: str | None
    exact: bool = False


def run(motion_path: Path, out: Path, settings: SolveSettings, rig_path: Path | None = None,
        binding: Path | None = None, overwrite: bool = False, take: str | None = None) -> SolveResult:
    """Solve ``motion_path`` (a ``motion``, or one take of a ``normalized`` artifact) on the rig
    (built-in when ``rig_path`` is None, with ``binding`` when given) and write ``out``.

    The steps are the ones :mod:`facesynth.api` calls (:mod:`facesynth.domain.retarget.facial_solve`),
    so the command and the API write the same artifact."""
    check_output(out, overwrite)
    rig = load_rig(rig_path, binding)
    motion = facial_solve.read_motion(motion_path, settings, take)
    used, exact = facial_solve.settings_for(motion_path, settings)
    solved = facial_solve.solve(motion, rig, used, str(motion_path), exact=exact)
    facial_solve.write(solved, out, used, facial_solve.recorded_inputs(motion_path, rig_path), overwrite=overwrite)
    return SolveResult(len(solved.curves.weights), len(rig.shape_names), solved.iterations, solved.residual_rms,
                       rig.name, solved.marker_residual_median_mm, solved.marker_residual_p95_mm, motion.take,
                       solved.exact)
