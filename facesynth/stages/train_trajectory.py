"""``facesynth train-trajectory``: the compact key-shape trajectory model (Huang et al. §5.4;
:mod:`facesynth.methods.trajectory`) of a motion database's training takes, over the joint
key-shapes of a ``keyshapes`` artifact, written as a ``trajectory`` artifact that
``facesynth synthesize --method trajectory`` reads alone. The same as ``facesynth fit-method
trajectory`` (:func:`facesynth.methods.fitting.fit_to_file`), kept under its own name.
"""

from __future__ import annotations

from pathlib import Path

from ..config import TrajectorySettings
from ..methods.fitting import fit_to_file


def run(db_path: Path, keyshapes_path: Path, out: Path, settings: TrajectorySettings, overwrite: bool = False) -> dict:
    """Train the model on ``db_path``'s training takes with the key-shapes of ``keyshapes_path``
    and write ``out``; returns a summary (sizes, seconds, the fit's RMS: ``train_s`` the fit's seconds)."""
    from ..methods import MethodSettings

    s = fit_to_file("trajectory", db_path, out, MethodSettings.packaged(trajectory=settings), keyshapes_path=keyshapes_path,
            overwrite=overwrite)
    return {**s, "train_s": s["fit_s"]}
