"""``facesynth train-trajectory``: the compact key-shape trajectory model (Huang et al. §5.4;
:mod:`facesynth.domain.methods.trajectory`) of a motion database's training takes, over the joint
key-shapes of a ``keyshapes`` artifact, written as a ``trajectory`` artifact that
``facesynth synthesize --method trajectory`` reads alone. The same as ``facesynth fit-method
trajectory`` (:func:`facesynth.domain.methods.fitting.fit_to_file`), kept under its own name.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from facesynth.base.config import TrajectorySettings
from facesynth.domain.methods import MethodSettings
from facesynth.domain.methods.fitting import fit_to_file


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
    s = fit_to_file("trajectory", db_path, out, MethodSettings.packaged(trajectory=settings), keyshapes_path=keyshapes_path,
                    overwrite=overwrite)
    return TrainTrajectoryResult(s["keyshapes"], s["phones"], s["pairs"], s["samples"], s["fit_rms_mm"], s["fit_s"],
                                 s["bytes"])

