"""``facesynth train-trajectory``: the compact key-shape trajectory model (Huang et al. §5.4;
:mod:`facesynth.motion.trajectory`) of a motion database's training takes, over the joint
key-shapes of a ``keyshapes`` artifact, written as a ``trajectory`` artifact that
``facesynth synthesize --method trajectory`` reads alone.
"""

from __future__ import annotations

import time
from pathlib import Path

from ..artifacts import check_output
from ..config import TrajectorySettings, settings_json
from ..model.keyshapes import KeyShapes
from ..model.motiondb import MotionDatabase
from ..motion.trajectory import train_model


def run(db_path: Path, keyshapes_path: Path, out: Path, settings: TrajectorySettings, overwrite: bool = False) -> dict:
    """Train the model on ``db_path``'s training takes with the key-shapes of ``keyshapes_path``
    and write ``out``; returns a summary (sizes, seconds, the fit's RMS)."""
    check_output(out, overwrite)
    db = MotionDatabase.read(db_path)
    keyshapes = KeyShapes.read(keyshapes_path)
    t0 = time.perf_counter()
    model, samples = train_model(db, keyshapes, settings, f"{keyshapes_path}")
    train_s = time.perf_counter() - t0
    model.write(out, config=settings_json(settings), inputs=[db_path, keyshapes_path], overwrite=overwrite)
    return {"keyshapes": model.count, "phones": len(model.phones), "pairs": len(model.pair_phone),
            "samples": len(samples.rows), "fit_rms_mm": model.fit_rms, "train_s": train_s,
            "bytes": out.stat().st_size}
