"""``facesynth fit-method``: fit a member of the method family (:mod:`facesynth.methods`) on a
motion database's training takes and write its model artifact, which ``facesynth synthesize
--method NAME`` (and ``batch``) then read alone: ``trajectory`` (Huang et al. §5.4, over the
key-shapes of a ``keyshapes`` artifact; ``facesynth train-trajectory`` is the same) and
``coarticulation`` (Cohen-Massaro per (phone, emotion)). The other members read the database
itself and have nothing to fit.
"""

from __future__ import annotations

from pathlib import Path

from ..methods import MethodSettings
from ..methods.fitting import fit_to_file


def run(method: str, db_path: Path, out: Path, settings: MethodSettings, *, keyshapes_path: Path | None = None,
        overwrite: bool = False) -> dict:
    """Fit ``method`` on ``db_path``'s training takes (the trajectory method over the key-shapes of
    ``keyshapes_path``) and write ``out``; returns the method's summary (sizes, the fit's RMS) with
    ``method``, ``fit_s`` and ``bytes``."""
    return fit_to_file(method, db_path, out, settings, keyshapes_path=keyshapes_path, overwrite=overwrite)
