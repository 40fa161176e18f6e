"""``facesynth tune``: the cost weights, PNT, the join smoothing window and the boundary-fit
length by cross-validation on the validation takes (paper VI-D).

The search, its objective (Eq. 12-13 on the validation takes, never in the database) and its
safety (the written settings are never worse there than the start) are
:mod:`facesynth.domain.search.tuning`; this module reads the database and the held-out takes,
runs it and writes the tuned settings as a TOML file ``--config`` accepts.
"""

from __future__ import annotations

import dataclasses
import time
from pathlib import Path

from facesynth.base.config import BuildDbSettings, NormalizeSettings, SynthesizeSettings, TuneSettings
from facesynth.base.errors import InputError, UsageError
from facesynth.base.opencl import use_opencl
from facesynth.domain import methods
from facesynth.domain.evaluation.held_out import heldout
from facesynth.domain.methods import Method, MethodSettings, steps
from facesynth.domain.search import tuning
from facesynth.domain.search.tuning import WEIGHTS, Objective, Tuning
from facesynth.model.artifacts import atomic_path, check_output
from facesynth.model.motiondb import MotionDatabase


def tunable(method: str | None, synth: SynthesizeSettings) -> tuple[Method, SynthesizeSettings]:
    """The member of the method family to tune (default ``synthesize.method``) and ``synth`` with
    its search; a usage error for a method without the search's cost weights."""
    member = methods.get(steps.chosen_method(method, synth))
    if not member.tunable:
        tunables = [n for n in methods.names() if methods.get(n).tunable]
        raise UsageError(f"facesynth tune tunes the cost weights of the database searches (alpha1..alpha6, PNT); "
                         f"the {member.name} method has no weights to tune: use --method {' or '.join(tunables)}.")
    return member, dataclasses.replace(synth, search=member.name)


@dataclasses.dataclass(frozen=True)
class TuneResult:
    """What ``facesynth tune`` found.

    method: the search tuned (dp or greedy; both use the same cost weights).
    seconds: wall time (s).
    tuning: the search's settings and errors (Eq. 13, mm^2) on the validation and test takes.
    """

    method: str
    seconds: float
    tuning: Tuning


def tune(db_path: Path, corpus: Path, settings: TuneSettings, synth: SynthesizeSettings, build: BuildDbSettings,
         normalize_settings: NormalizeSettings, progress_fn=None, method: str | None = None) -> TuneResult:
    """Tune the weights, the boundary-fit length and the smoothing window of ``method`` (a search
    member, default ``synthesize.method``) on the validation takes of ``corpus``; returns the
    settings and the errors (mm^2) before and after on the validation and test takes.
    ``progress_fn(done, total, error, best)`` is called after each evaluation."""
    member, synth = tunable(method, synth)
    for name in WEIGHTS:
        if getattr(synth, name) <= 0:
            raise InputError(f"synthesize.{name} must be positive to tune it (got {getattr(synth, name)}).")
    t0 = time.perf_counter()
    db = MotionDatabase.read(db_path)
    validation = heldout(corpus, db, "val", normalize_settings)
    test = heldout(corpus, db, "test", normalize_settings)
    longest = max(validation + test, key=lambda sentence: len(sentence.utterance)).utterance
    steps.check_memory(member, db, longest, MethodSettings.packaged(synthesize=synth), str(db_path))
    objective = Objective(db, synth, use_opencl(synth.use_opencl))
    found = tuning.tune(objective, validation, test, settings, build.boundary_fit_frames, progress_fn)
    return TuneResult(member.name, time.perf_counter() - t0, found)


def run(db_path: Path, corpus: Path, out: Path, settings: TuneSettings, synth: SynthesizeSettings,
        build: BuildDbSettings, normalize_settings: NormalizeSettings, overwrite: bool = False,
        progress_fn=None, method: str | None = None) -> TuneResult:
    """Tune ``method`` (a search member; default ``synthesize.method``) and write ``out``."""
    tunable(method, synth)  # refused before anything is read
    check_output(out, overwrite)
    result = tune(db_path, corpus, settings, synth, build, normalize_settings, progress_fn, method)
    with atomic_path(out, overwrite) as tmp:
        tmp.write_text(tuning.config_text(result.tuning, result.method), encoding="utf-8")
    return result
