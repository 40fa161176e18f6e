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
from facesynth.domain.methods.fitting import fit_to_file


@dataclass(frozen=True)
class FitMethodResult:
    """What ``facesynth fit-method`` fitted.

    method: the member fitted.
    fit_rms_mm: RMS per marker of the model's fit to the training frames (mm).
    fit_s: seconds spent fitting.
    bytes: the model file's size.
    labels: (phone, emotion) types of a coarticulation model; None for the trajectory model.
    keyshapes, phones, pairs, samples: a trajectory model's key-shapes, phones with a Gaussian,
        (phone, emotion) pairs with their own Gaussian and training frames; None for coarticulation.
    """

    method: str
    fit_rms_mm: float
    fit_s: float
    bytes: int
    labels: int | None = None
    keyshapes: int | None = None
    phones: int | None = None
    pairs: int | None = None
    samples: int | None = None


def run(method: str, db_path: Path, out: Path, settings: MethodSettings, *, keyshapes_path: Path | None = None,
        overwrite: bool = False) -> FitMethodResult:
    """Fit ``method`` on ``db_path``'s training takes (the trajectory method over the key-shapes of
    ``keyshapes_path``) and write ``out``."""
    s = fit_to_file(method, db_path, out, settings, keyshapes_path=keyshapes_path, overwrite=overwrite)
    f = s.fit
    return FitMethodResult(s.method, f.fit_rms_mm, s.fit_s, s.bytes, f.labels, f.keyshapes, f.phones, f.pairs, f.samples)
