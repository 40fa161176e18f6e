"""``facesynth synthesize``: expressive speech motion from the motion-node database
(paper VI and VII-B; the search and post-processing are :mod:`facesynth.search.synthesis`), or,
with ``--method trajectory``, from a compact trajectory model (Huang et al. §5.4;
:mod:`facesynth.motion.trajectory`).
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..artifacts import check_output, input_records_in_background
from ..config import AlignSettings, IngestSettings, SynthesizeSettings, TrajectorySettings, settings_json
from ..errors import UsageError
from ..limits import require_memory
from ..model.headmotion import HeadMotion
from ..model.motiondb import MotionDatabase
from ..model.trajectory import TrajectoryModel
from ..motion.trajectory import synthesize_motion
from ..search.synthesis import as_motion, prepare, synthesize, unseen_phones


def memory_estimate(nodes: int, phones: int, dp: str = "dense", feature_bytes: int = 0) -> float:
    """Bytes the search needs. The dense DP (``dp = "dense"``): the (N, N) float32 transition
    matrix (twice, while it is assembled panel-major) and per phone a row of float64 costs and
    int32 backpointers. The pruned DP: the per-node transition features (``feature_bytes``)
    three times (read, on the device, in the device's layout) and per phone and node the
    float32 observation costs, accumulated costs and their step's work arrays (12 bytes)."""
    if dp == "pruned":
        return 3.0 * feature_bytes + 12.0 * phones * nodes
    return 2.0 * 4 * nodes * nodes + 12.0 * phones * nodes


@dataclass(frozen=True)
class SynthesizeResult:
    """What ``facesynth synthesize`` (a search of the motion database) made.

    phones: phones of the utterance.
    cost: the path's total cost.
    joins: joins between nodes not captured one after the other.
    device: where the search ran (an OpenCL device's name, or the CPU).
    unseen: phones the database has no node of, with what covers them.
    frames: frames of the motion at the output rate.
    load_s, hash_wait_s, write_s: seconds reading the database, waiting for the inputs' sha256
        (hashed on another thread meanwhile) and writing.
    device_choice_s, transition_s, steps_s, opencl_setup_s, search_s, postprocess_s: seconds of the
        phases of :func:`~facesynth.search.synthesis.synthesize`; None for a phase that did not run.
    """

    phones: int
    cost: float
    joins: int
    device: str
    unseen: dict[str, str]
    frames: int
    load_s: float
    hash_wait_s: float
    write_s: float
    device_choice_s: float | None = None
    transition_s: float | None = None
    steps_s: float | None = None
    opencl_setup_s: float | None = None
    search_s: float | None = None
    postprocess_s: float | None = None


@dataclass(frozen=True)
class TrajectorySynthesisResult:
    """What ``facesynth synthesize --method trajectory`` made.

    phones: phones of the utterance.
    frames: frames of the motion at the output rate.
    energy: the path's Eq. 6 energy.
    lam: the smoothness weight lambda per frame.
    fallbacks: unseen phones and the viseme class whose pooled Gaussian covered each.
    load_s, solve_s, write_s: seconds reading the model, solving the path and back-projecting, writing.
    """

    phones: int
    frames: int
    energy: float
    lam: float
    fallbacks: dict[str, str]
    load_s: float
    solve_s: float
    write_s: float


def run(db_path: Path, out: Path, settings: SynthesizeSettings, ingest_settings: IngestSettings,
        align_settings: AlignSettings, *,
        phones_path: Path | None = None, emotions_path: Path | None = None, constraints_path: Path | None = None,
        audio: Path | None = None, text: str | None = None, head_motion_path: Path | None = None,
        overwrite: bool = False) -> SynthesizeResult:
    """Synthesize the utterance (phones from ``phones_path``, or ``audio`` aligned to ``text``)
    with its emotions and constraints, and write ``out`` (a ``motion`` artifact). ``head_motion_path`` (a
    ``headmotion`` artifact, see ``facesynth head-motion``) replaces the head motion the
    search's source frames carry."""
    if settings.search == "greedy" and constraints_path is not None:
        raise UsageError("motion-node constraints need the DP search (Eq. 10); drop --constraints or use --search dp.")
    check_output(out, overwrite)
    inputs = [p for p in (db_path, phones_path, emotions_path, constraints_path, audio, head_motion_path) if p is not None]
    head = HeadMotion.read(head_motion_path) if head_motion_path is not None else None
    t0 = time.perf_counter()
    db = MotionDatabase.read(db_path)
    load_s = time.perf_counter() - t0
    # hashed from here, while the search runs: the database's record comes from the file just
    # validated (not opened again), and a database replaced meanwhile is refused
    records = input_records_in_background(inputs)
    utt, constraints = prepare(db, phones_path, emotions_path, constraints_path, ingest_settings, audio, text,
                               align_settings)
    require_memory(memory_estimate(len(db.nodes), len(utt), settings.dp, db.feature_bytes()), f"the search over {len(db.nodes)} motion nodes for "
                   f"{len(utt)} phones", str(db_path))
    res = synthesize(db, utt, constraints, settings)
    t0 = time.perf_counter()
    input_records = records()
    hash_wait_s = time.perf_counter() - t0
    t0 = time.perf_counter()
    motion = as_motion(db, utt, res, settings)
    if head is not None:
        motion.head_rotation, motion.head_translation = head.at(np.arange(len(motion.markers)) / motion.fps)
    motion.write(out, config=settings_json(settings), records=input_records,
                                            overwrite=overwrite)
    write_s = time.perf_counter() - t0
    return SynthesizeResult(len(utt), res["cost"], res["non_captured_joins"], res["device"], unseen_phones(utt, db),
                            len(res["markers"]), load_s, hash_wait_s, write_s, **res["timings"])


def run_trajectory(model_path: Path, out: Path, settings: TrajectorySettings, output_fps: float,
                   ingest_settings: IngestSettings, align_settings: AlignSettings, *,
                   phones_path: Path | None = None, emotions_path: Path | None = None, audio: Path | None = None,
                   text: str | None = None, head_motion_path: Path | None = None,
                   overwrite: bool = False) -> TrajectorySynthesisResult:
    """Synthesize the utterance from the trajectory model at ``model_path`` (Huang et al. Eq. 6-7)
    and write ``out``, a ``motion`` artifact with ``source = "trajectory"``, markers at
    ``output_fps``."""
    check_output(out, overwrite)
    inputs = [p for p in (model_path, phones_path, emotions_path, audio, head_motion_path) if p is not None]
    head = HeadMotion.read(head_motion_path) if head_motion_path is not None else None
    t0 = time.perf_counter()
    model = TrajectoryModel.read(model_path)
    load_s = time.perf_counter() - t0
    utt, _ = prepare(None, phones_path, emotions_path, None, ingest_settings, audio, text, align_settings)
    t0 = time.perf_counter()
    motion, path = synthesize_motion(model, utt, settings, output_fps, str(phones_path or audio))
    solve_s = time.perf_counter() - t0
    if head is not None:
        motion.head_rotation, motion.head_translation = head.at(np.arange(len(motion.markers)) / motion.fps)
    t0 = time.perf_counter()
    motion.write(out, config=settings_json(settings), inputs=inputs, overwrite=overwrite)
    return TrajectorySynthesisResult(len(utt), len(motion.markers), path.energy, path.lam, path.targets.fallbacks,
                                     load_s, solve_s, time.perf_counter() - t0)

