"""``facesynth train-trajectory``: the compact key-shape trajectory model (Huang et al. §5.4;
:mod:`facesynth.motion.trajectory`) of a motion database's training takes, over the joint
key-shapes of a ``keyshapes`` artifact, written as a ``trajectory`` artifact that
``facesynth synthesize --method trajectory`` reads alone.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path

from ..artifacts import check_output
from ..config import TrajectorySettings, settings_json
from ..model.keyshapes import KeyShapes
from ..model.motiondb import MotionDatabase
from ..motion.trajectory import train_model


@dataclass(frozen=True)
class TrainTrajectoryResult:
    """What ``facesynth train-trajectory`` trained.

    keyshapes: key-shapes the weights are over (every emotion's, joined).
    phones: phones with a Gaussian.
    pairs: (phone, emotion) pairs with their own Gaussian.
    samples: training frames.
    fit_rms_mm: RMS per marker of the frames' key-shape fit (mm).
    train_s: seconds spent on the weights and the Gaussians.
    bytes: the model file's size.
    """

    keyshapes: int
    phones: int
    pairs: int
    samples: int
    fit_rms_mm: float
    train_s: float
    bytes: int


def run(db_path: Path, keyshapes_path: Path, out: Path, settings: TrajectorySettings,
        overwrite: bool = False) -> TrainTrajectoryResult:
    """Train the model on ``db_path``'s training takes with the key-shapes of ``keyshapes_path``
    and write ``out``."""
    check_output(out, overwrite)
    db = MotionDatabase.read(db_path)
    keyshapes = KeyShapes.read(keyshapes_path)
    t0 = time.perf_counter()
    model, samples = train_model(db, keyshapes, settings, f"{keyshapes_path}")
    train_s = time.perf_counter() - t0
    model.write(out, config=settings_json(settings), inputs=[db_path, keyshapes_path], overwrite=overwrite)
    return TrainTrajectoryResult(model.count, len(model.phones), len(model.pair_phone), len(samples.rows),
                                 model.fit_rms, train_s, out.stat().st_size)

