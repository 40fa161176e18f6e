"""``facesynth fit-method``: fit a member of the method family (:mod:`facesynth.domain.methods`) on a
motion database's training takes and write its model artifact, which ``facesynth synthesize
--method NAME`` (and ``batch``) then read alone: ``trajectory`` (Huang et al. §5.4, over the
key-shapes of a ``keyshapes`` artifact; ``facesynth fit-method trajectory`` is the same) and
``coarticulation`` (Cohen-Massaro per (phone, emotion)). The other members read the database
itself and have nothing to fit.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from facesynth.domain.methods import MethodSettings
from facesynth.domain.methods.fitting import FittedModel, fit_to_file


@dataclass(frozen=True)
class FitMethodResult:
    """What ``facesynth fit-method`` fitted.

    model: the model fitted and written: the member, what it reports about its fit
        (:class:`~facesynth.domain.methods.FitSummary`: sizes, the fit's RMS in mm), the seconds
        spent fitting and the file's size.
    """

    model: FittedModel


def run(method: str, db_path: Path, out: Path, settings: MethodSettings, *, keyshapes_path: Path | None = None,
        overwrite: bool = False) -> FitMethodResult:
    """Fit ``method`` on ``db_path``'s training takes (the trajectory method over the key-shapes of
    ``keyshapes_path``) and write ``out``."""
    return FitMethodResult(fit_to_file(method, db_path, out, settings, keyshapes_path=keyshapes_path,
                                       overwrite=overwrite))
