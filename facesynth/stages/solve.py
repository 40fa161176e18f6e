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
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.config import SolveSettings, settings_json
from facesynth.base.errors import InputError
from facesynth.domain.postprocess.concatenation import downsample
from facesynth.domain.retarget.solve import solve_motion, solved_curves
from facesynth.domain.rig.face import Rig
from facesynth.domain.rig.loading import load_rig, marker_map
from facesynth.model.artifacts import artifact_kind, check_output
from facesynth.model.frames import NormalizedFrames, relative_to_take
from facesynth.model.motion import Motion


def take_motion(normalized: NormalizedFrames, take: str | None, output_fps: float, where: str) -> Motion:
    """One take of a ``normalized`` artifact as captured motion (``source = "capture"``) at
    ``output_fps``: markers (T, M, 3) mm in the head frame, the reference as rest pose, the head
    motion relative to the take's mean. ``take`` None: the only take."""
    names = normalized.takes.name
    if take is None:
        if len(names) != 1:
            raise InputError(f"{where}: it holds {len(names)} takes ({', '.join(names[:4])}...); choose one with --take.")
        take = names[0]
    if take not in names:
        raise InputError(f"{where}: no take {take!r}; it has {', '.join(names[:5])}.")
    frames = normalized.frames
    sl = normalized.takes.frames(names.index(take))
    markers = frames.loaded_markers()[sl].astype(np.float32)
    rel_r, rel_t = relative_to_take(frames.head_rotation[sl], frames.head_translation[sl], [slice(0, len(markers))])
    return Motion(downsample(markers, frames.fps, output_fps), output_fps, markers, frames.fps, normalized.marker_names,
                  frames.reference, downsample(rel_r, frames.fps, output_fps).astype(np.float32),
                  downsample(rel_t, frames.fps, output_fps).astype(np.float32), source="capture", take=take)


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
    """

    frames: int
    shapes: int
    iterations: int
    residual_rms: float
    rig: str
    marker_residual_median_mm: float
    marker_residual_p95_mm: float
    take: str | None


def run(motion_path: Path, out: Path, settings: SolveSettings, rig_path: Path | None = None,
        binding: Path | None = None, overwrite: bool = False, take: str | None = None) -> SolveResult:
    """Solve ``motion_path`` (a ``motion``, or one take of a ``normalized`` artifact) on the rig
    (built-in when ``rig_path`` is None, with ``binding`` when given) and write ``out``."""
    check_output(out, overwrite)
    rig = load_rig(rig_path, binding)
    if artifact_kind(motion_path) == NormalizedFrames.KIND:
        motion = take_motion(NormalizedFrames.read(motion_path), take, settings.output_fps, str(motion_path))
    else:
        if take is not None:
            raise InputError(f"{motion_path}: --take picks a take of a normalized capture; a motion artifact has one.")
        motion = Motion.read(motion_path)
    weights, residual, iterations = solve_motion(motion, rig, settings, str(motion_path))
    inputs = [motion_path] + ([rig_path] if rig_path is not None and Path(rig_path).is_file() else [])
    solved_curves(motion, rig, weights, residual, motion.frame_provenance(motion_path)).write(
        out, config=settings_json(settings), inputs=inputs, overwrite=overwrite)
    marker_mm = per_marker_residual_mm(motion, rig, weights)
    return SolveResult(len(weights), len(rig.shape_names), iterations, float(np.sqrt(np.nanmean(residual**2))),
                       rig.name, float(np.nanmedian(marker_mm)), float(np.nanpercentile(marker_mm, 95)), motion.take)



def per_marker_residual_mm(motion: Motion, rig: Rig, weights: np.ndarray) -> np.ndarray:
    """(T, B) distance in the motion's millimetres between each bound marker's displacement and
    the solved rig's displacement at its vertex (NaN where the marker is unseen)."""
    mmap = marker_map(rig, motion.marker_names, motion.reference, "")
    disp = mmap.displacements(motion.markers, motion.reference)
    fitted = np.tensordot(weights, rig.deltas[:, mmap.vertices], axes=(1, 0))
    return np.linalg.norm(disp - fitted, axis=2) / mmap.scale
