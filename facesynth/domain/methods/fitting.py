"""Fitting a member of the method family into its model artifact (``facesynth fit-method``,
``facesynth train-trajectory``): the database read, the member's :meth:`~facesynth.domain.methods.Method.fit`
on its training takes, the model written with the settings and inputs that made it."""

from __future__ import annotations

import time
from pathlib import Path

from facesynth.base.config import settings_json
from facesynth.base.errors import UsageError
from facesynth.model.artifacts import check_output
from facesynth.model.keyshapes import KeyShapes
from facesynth.model.motiondb import MotionDatabase

from . import MethodSettings, get


def fit_to_file(method: str, db_path: Path, out: Path, settings: MethodSettings, *, keyshapes_path: Path | None = None,
                overwrite: bool = False) -> dict:
    """Fit ``method`` on ``db_path``'s training takes (the trajectory method over the key-shapes of
    ``keyshapes_path``) and write ``out``; returns the method's summary (sizes, the fit's RMS) with
    ``method``, ``fit_s`` and ``bytes``."""
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
    return {"method": member.name, **summary, "fit_s": fit_s, "bytes": out.stat().st_size}
