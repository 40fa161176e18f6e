"""The direct facial solve of a motion or of one take of a capture: the steps ``facesynth solve``
and :func:`facesynth.solve` share (:func:`read_motion`, :func:`settings_for`, :func:`solve`,
:func:`write`, :func:`recorded_inputs`), so the command and the API write the same artifact.

Per frame, the rig weights in [0, 1] that best explain the motion's markers at the rig's marker
vertices (:func:`facesynth.domain.retarget.solve.solve_motion`), as ``curves`` (``source = "solve"``).
A ``normalized`` capture is solved one take at a time (:func:`take_motion`); one posed from curves
is solved without smoothing or ridge when ``solve.posed_captures = "exact"`` (:func:`settings_for`;
``facesynth.stages.solve`` says why).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from facesynth.base.config import SolveSettings, settings_json
from facesynth.base.errors import InputError
from facesynth.domain.postprocess.concatenation import downsample
from facesynth.domain.retarget.solve import solve_motion, solved_curves
from facesynth.domain.rig.face import Rig
from facesynth.domain.rig.face_mesh import bound_for
from facesynth.domain.rig.loading import marker_map
from facesynth.domain.rig.neutral import NeutralChoice, chosen_frames, lip_gap, neutral_pose, quietest_of, quietness
from facesynth.model.artifacts import artifact_kind
from facesynth.model.curves import RigCurves
from facesynth.model.frames import NormalizedFrames, relative_to_take
from facesynth.model.motion import Motion


def take_motion(normalized: NormalizedFrames, take: str | None, output_fps: float, where: str,
                neutral: NeutralChoice | None = None) -> Motion:
    """One take of a ``normalized`` artifact as captured motion (``source = "capture"``) at
    ``output_fps``: markers (T, M, 3) mm in the head frame, the performer's ``neutral`` face as
    rest pose (:func:`neutral_reference`; None or ``off``: the normalize reference), the head
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
    all_markers = frames.loaded_markers()
    markers = all_markers[sl].astype(np.float32)
    reference = frames.reference
    if neutral is not None and neutral.kind != "off":
        takes = normalized.takes
        if neutral.kind == "take":
            if neutral.take not in names:
                raise InputError(f"{where}: no take {neutral.take!r} for the neutral face; it has {', '.join(names[:5])}.")
            spans, choice = [takes.frames(names.index(neutral.take))], NeutralChoice("auto")
        elif neutral.kind == "auto":  # one performer, one neutral face: the quietest of every take
            spans, choice = [takes.frames(i) for i in range(len(names))], neutral
        else:
            spans, choice = [sl], neutral
        reference = neutral_reference(all_markers, normalized.marker_names, frames.fps, choice, spans,
                                      frames.reference, f"{where}, take {take!r}")
    rel_r, rel_t = relative_to_take(frames.head_rotation[sl], frames.head_translation[sl], [slice(0, len(markers))])
    return Motion(downsample(markers, frames.fps, output_fps), output_fps, markers, frames.fps, normalized.marker_names,
                  reference, downsample(rel_r, frames.fps, output_fps).astype(np.float32),
                  downsample(rel_t, frames.fps, output_fps).astype(np.float32), source="capture", take=take)


def neutral_reference(markers: np.ndarray, names: list[str], fps: float, choice: NeutralChoice, spans: list[slice],
                      fallback: np.ndarray, where: str) -> np.ndarray:
    """(M, 3) float32 the performer's neutral face in a capture's markers (T, M, 3) mm at ``fps``:
    their median over the frames ``choice`` names (:mod:`facesynth.domain.rig.neutral`) in the
    takes ``spans``: for ``auto`` the quietest half second of any of them (scored over the whole
    capture), else the frame named in the first (the solved take); a marker unseen there keeps
    its place in ``fallback`` (the normalize reference)."""
    score = quietness(markers, fps, lip_gap(markers, names))
    if choice.kind == "auto":
        frames: slice | None = quietest_of(score, spans, fps)
    else:
        own = chosen_frames(choice, score[spans[0]], fps, where)
        frames = None if own is None else slice(spans[0].start + own.start, spans[0].start + own.stop)
    if frames is None:
        return np.asarray(fallback, np.float32)
    pose = neutral_pose(markers, frames)
    return np.where(np.isnan(pose), fallback, pose).astype(np.float32)


def settings_for(motion_path: Path, settings: SolveSettings) -> tuple[SolveSettings, bool]:
    """(the settings ``motion_path`` is solved with, whether they are the exact ones): for a
    normalized capture posed from curves with ``posed_captures = "exact"``, ``settings`` without
    smoothing or ridge, with ``exact_iterations`` and ``exact_tolerance`` (see the module
    docstring); else ``settings``."""
    if settings.posed_captures == "exact" and artifact_kind(motion_path) == NormalizedFrames.KIND \
            and NormalizedFrames.read_posed(motion_path):
        return replace(settings, smooth=0.0, ridge=0.0, sparsity=0.0, antagonist=0.0, symmetry=0.0,
                       iterations=settings.exact_iterations, tolerance=settings.exact_tolerance), True
    return settings, False


def read_motion(motion_path: Path, settings: SolveSettings, take: str | None = None) -> Motion:
    """What ``solve`` solves from ``motion_path``: a ``motion`` artifact (with its search path and
    provenance), or the take ``take`` of a ``normalized`` one (:func:`take_motion`, at
    ``settings.output_fps``, measured from the performer's neutral face ``settings.neutral``
    unless it was posed from curves, whose neutral ``ingest`` took off)."""
    if artifact_kind(motion_path) == NormalizedFrames.KIND:
        neutral = NeutralChoice.parse(settings.neutral, "solve.neutral")
        # a capture posed from curves rests at the rig's neutral by construction; its performer's
        # neutral was taken off its weights at ingest (ingest.neutral)
        posed = NormalizedFrames.read_posed(motion_path)
        return take_motion(NormalizedFrames.read(motion_path), take, settings.output_fps, str(motion_path),
                           None if posed else neutral)
    if take is not None:
        raise InputError(f"{motion_path}: --take picks a take of a normalized capture; a motion artifact has one.")
    return Motion.read(motion_path, search=True)


@dataclass
class Solved:
    """The curves of a solve and what it reports about them.

    curves: the ``curves`` artifact's content (weights (T, E) float32, head motion, provenance).
    iterations: the solver's iterations.
    residual_rms: RMS marker residual (rig units).
    marker_residual_median_mm, marker_residual_p95_mm: the median and 95th percentile of each
        bound marker's distance from the solved rig, per frame, in the motion's millimetres.
    exact: solved without smoothing or ridge (a capture posed from curves, ``solve.posed_captures``).
    """

    curves: RigCurves
    iterations: int
    residual_rms: float
    marker_residual_median_mm: float
    marker_residual_p95_mm: float
    exact: bool


def solve(motion: Motion, rig: Rig, settings: SolveSettings, where: str = "the motion", exact: bool = False) -> Solved:
    """The core of ``solve``: ``motion`` solved on ``rig`` (:func:`solve_motion`), as ``curves``
    (``source = "solve"``) carrying where each frame came from (the motion's own provenance).
    Messages name ``where``; ``exact``: ``settings`` are the exact ones (:func:`settings_for`).
    A filmed take (Face Mesh's markers) on the built-in rig without a binding of its own is bound
    by the shipped one (:func:`facesynth.domain.rig.face_mesh.bound_for`)."""
    rig = bound_for(rig, motion.marker_names)
    weights, residual, iterations = solve_motion(motion, rig, settings, where)
    method = "bounded least squares, no smoothing or ridge (a capture posed from curves)" if exact else None
    curves = solved_curves(motion, rig, weights, residual, motion.frame_provenance(), method)
    marker_mm = per_marker_residual_mm(motion, rig, weights)
    return Solved(curves, iterations, float(np.sqrt(np.nanmean(residual**2))), float(np.nanmedian(marker_mm)),
                  float(np.nanpercentile(marker_mm, 95)), exact)


def write(solved: Solved, out: Path, settings: SolveSettings, inputs: list[Path], *, overwrite: bool = False) -> None:
    """Write the ``curves`` artifact of ``solved`` at ``out``: ``settings`` as its ``config``,
    ``inputs`` (:func:`recorded_inputs`) as its provenance."""
    solved.curves.write(out, config=settings_json(settings), inputs=inputs, overwrite=overwrite)


def recorded_inputs(motion: Path | None, rig: Path | str | None = None) -> list[Path]:
    """The files solved curves record as their inputs: the motion's, and the rig's when it is one
    file (a glTF; a folder of OBJs is named by the curves' ``rig_name`` and ``rig_sha256``)."""
    return ([Path(motion)] if motion is not None else []) + (
        [Path(rig)] if rig is not None and Path(rig).is_file() else [])


def per_marker_residual_mm(motion: Motion, rig: Rig, weights: np.ndarray) -> np.ndarray:
    """(T, B) distance in the motion's millimetres between each bound marker's displacement and
    the solved rig's displacement at its vertex (NaN where the marker is unseen)."""
    mmap = marker_map(rig, motion.marker_names, motion.reference, "")
    disp = mmap.displacements(motion.markers, motion.reference)
    fitted = np.tensordot(weights, rig.deltas[:, mmap.vertices], axes=(1, 0))
    return np.linalg.norm(disp - fitted, axis=2) / mmap.scale
