"""``facesynth synthesize``: expressive speech motion from the motion-node database
(paper VI and VII-B; the search and post-processing are :mod:`facesynth.search.synthesis`), or,
with ``--method trajectory``, from a compact trajectory model (Huang et al. §5.4;
:mod:`facesynth.motion.trajectory`).
"""

from __future__ import annotations

import time
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


def run(db_path: Path, out: Path, settings: SynthesizeSettings, ingest_settings: IngestSettings,
        align_settings: AlignSettings, *,
        phones_path: Path | None = None, emotions_path: Path | None = None, constraints_path: Path | None = None,
        audio: Path | None = None, text: str | None = None, head_motion_path: Path | None = None,
        overwrite: bool = False) -> dict:
    """Synthesize the utterance (phones from ``phones_path``, or ``audio`` aligned to ``text``)
    with its emotions and constraints, and write ``out`` (a ``motion`` artifact). The summary's
    ``*_s`` entries are the seconds of each phase: ``load_s`` (database tables), those of
    :func:`~facesynth.search.synthesis.synthesize`, ``hash_wait_s`` (waiting for the inputs'
    sha256, computed on another thread from the start) and ``write_s``. ``head_motion_path`` (a
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
    return {"phones": len(utt), "cost": res["cost"], "joins": res["non_captured_joins"], "device": res["device"],
            "unseen": unseen_phones(utt, db), "frames": len(res["markers"]), "load_s": load_s, **res["timings"],
            "hash_wait_s": hash_wait_s, "write_s": write_s}


def run_trajectory(model_path: Path, out: Path, settings: TrajectorySettings, output_fps: float,
                   ingest_settings: IngestSettings, align_settings: AlignSettings, *,
                   phones_path: Path | None = None, emotions_path: Path | None = None, audio: Path | None = None,
                   text: str | None = None, head_motion_path: Path | None = None, overwrite: bool = False) -> dict:
    """Synthesize the utterance from the trajectory model at ``model_path`` (Huang et al. Eq. 6-7)
    and write ``out``, a ``motion`` artifact with ``source = "trajectory"``, markers at
    ``output_fps``. The summary's ``solve_s`` is the path's solve and back-projection, ``fallbacks``
    the unseen phones and the viseme class that covered each."""
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
    return {"phones": len(utt), "frames": len(motion.markers), "energy": path.energy, "lambda": path.lam,
            "fallbacks": path.targets.fallbacks, "load_s": load_s, "solve_s": solve_s,
            "write_s": time.perf_counter() - t0}
