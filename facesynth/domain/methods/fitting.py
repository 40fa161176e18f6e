"""Fitting a member of the method family into its model artifact (``facesynth fit-method``,
``facesynth fit-method trajectory``): the database read, the member's :meth:`~facesynth.domain.methods.Method.fit`
on its training takes, the model written with the settings and inputs that made it."""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path

from facesynth.base.config import settings_json
from facesynth.base.errors import UsageError
from facesynth.model.artifacts import check_output
from facesynth.model.keyshapes import KeyShapes
from facesynth.model.motiondb import MotionDatabase

from . import FitSummary, MethodSettings, get


@dataclass(frozen=True)
class FittedModel:
    """A model :func:`fit_to_file` fitted and wrote.

    method: the member fitted.
    fit: what the member reports about its fit (sizes, the fit's RMS in mm).
    fit_s: seconds spent fitting.
    bytes: the model file's size.
    """

    method: str
    fit: FitSummary
    fit_s: float
    bytes: int


def fit_to_file(method: str, db_path: Path, out: Path, settings: MethodSettings, *, keyshapes_path: Path | None = None,
                overwrite: bool = False) -> FittedModel:
    """Fit ``method`` on ``db_path``'s training takes (the trajectory method over the key-shapes of
    ``keyshapes_path``) and write ``out``."""
    member = get(method)
    if not member.fitted:
        member.fit(None, settings)  # says, in one sentence, that there is nothing to fit
    if keyshapes_path is not None and member.name != "trajectory":
        raise UsageError(f"--keyshapes is for the trajectory method; the {member.name} method is fitted without them.")
    check_output(out, overwrite)
    db = MotionDatabase.read(db_path)
    keyshapes = KeyShapes.read(keyshapes_path) if keyshapes_path is not None else None
    t0 = time.perf_counter()
    model, summary = member.fit(db, settings, keyshapes=keyshapes, where=str(keyshapes_path or db_path))
    fit_s = time.perf_counter() - t0
    model.write(out, config=settings_json(member.fit_settings(settings)), inputs=[p for p in (db_path, keyshapes_path) if p is not None],
                overwrite=overwrite)
    return FittedModel(member.name, summary, fit_s, out.stat().st_size)
