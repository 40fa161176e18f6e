"""``facesynth fit-method``: fit a member of the method family (:mod:`facesynth.methods`) on a
motion database's training takes and write its model artifact, which ``facesynth synthesize
--method NAME`` (and ``batch``) then read alone: ``trajectory`` (Huang et al. §5.4, over the
key-shapes of a ``keyshapes`` artifact; ``facesynth train-trajectory`` is the same) and
``coarticulation`` (Cohen-Massaro per (phone, emotion)). The other members read the database
itself and have nothing to fit.
"""

from __future__ import annotations

import time
from pathlib import Path

from .. import methods
from ..artifacts import check_output
from ..config import settings_json
from ..methods import MethodSettings
from ..model.keyshapes import KeyShapes
from ..model.motiondb import MotionDatabase


def run(method: str, db_path: Path, out: Path, settings: MethodSettings, *, keyshapes_path: Path | None = None,
        overwrite: bool = False) -> dict:
    """Fit ``method`` on ``db_path``'s training takes (the trajectory method over the key-shapes of
    ``keyshapes_path``) and write ``out``; returns the method's summary (sizes, the fit's RMS) with
    ``method``, ``fit_s`` and ``bytes``."""
    member = methods.get(method)
    if not member.fitted:
        member.fit(None, settings)  # says, in one sentence, that there is nothing to fit
    if keyshapes_path is not None and member.name != "trajectory":
        from ..errors import UsageError

        raise UsageError(f"--keyshapes is for the trajectory method; the {member.name} method is fitted without them.")
    check_output(out, overwrite)
    db = MotionDatabase.read(db_path)
    keyshapes = KeyShapes.read(keyshapes_path) if keyshapes_path is not None else None
    t0 = time.perf_counter()
    model, summary = member.fit(db, settings, keyshapes=keyshapes, where=str(keyshapes_path or db_path))
    fit_s = time.perf_counter() - t0
    section = settings.trajectory if member.name == "trajectory" else settings.coarticulation
    model.write(out, config=settings_json(section), inputs=[p for p in (db_path, keyshapes_path) if p is not None],
                overwrite=overwrite)
    return {"method": member.name, **summary, "fit_s": fit_s, "bytes": out.stat().st_size}
