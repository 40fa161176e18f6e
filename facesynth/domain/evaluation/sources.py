"""The fitted models given to ``facesynth evaluate`` (``--model``), each read by the member of the
method family whose model kind it is and checked to have been fitted on the evaluated database."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

from facesynth.base.errors import InputError
from facesynth.domain import methods
from facesynth.model.artifacts import artifact_kind, sha256_of


def trained_on(model: Any, model_path: Path, db_path: Path, member: str) -> None:
    """Refuse a model whose recorded training database (its ``inputs`` records) is not ``db_path``
    (by sha256): the methods must learn from the same takes, and the held-out ones must stay unseen."""
    dbs = [r for r in getattr(model, "inputs", []) if r.get("kind") == "motiondb"]
    digest = sha256_of(db_path)  # once, not per record
    if not any(r.get("sha256") == digest for r in dbs):
        was = f" ({dbs[0].get('path')})" if dbs else ""
        raise InputError(f"{model_path}: was trained on another database{was}, not {db_path}; train it on {db_path} "
                         f"with `facesynth fit-method {member}` so that every method learns from the same takes.")


def given_models(paths: Sequence[Path], db_path: Path) -> dict[str, Any]:
    """{member: its model read from one of ``paths``}: each file's artifact kind names the fitted
    member that reads it; a file of another kind, or a second model for one member, is refused."""
    out: dict[str, Any] = {}
    fitted = ", ".join(methods.fitted_names())
    for path in paths:
        kind = artifact_kind(path)
        member = methods.reader_of(kind) if kind is not None else None
        if member is None:
            raise InputError(f"{path}: is {f'a {kind} artifact' if kind else 'no facesynth artifact'}, not a fitted model; "
                             f"give --model the output of `facesynth fit-method` ({fitted}).")
        if member in out:
            raise InputError(f"{path}: a second {kind} model; give --model one model per method.")
        model = methods.get(member).read(path)
        trained_on(model, path, db_path, member)
        out[member] = model
    return out
