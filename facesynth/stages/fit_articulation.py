"""``facesynth fit-articulation``: the acoustic articulation model fitted on a performer's own
capture with its audio (:mod:`facesynth.domain.voice.fitting`), adapted from the general model
(``synthesize.articulation_model``, the packaged one by default) by ``synthesize.articulation_prior``,
written as an
``articulation`` artifact that ``synthesize.articulation_model`` names: the voice of this
performer then shapes the mouth of ``synthesize --audio``, ``batch`` and ``stream``. With two
takes or more each is also predicted by the model fitted on the others: the figures on audio the
model never heard, and the threshold of the voice's own closures the model carries
(:func:`facesynth.domain.voice.fitting.held_out_takes`).
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

from facesynth.base.config import SolveSettings, SynthesizeSettings
from facesynth.domain.rig.loading import load_rig
from facesynth.domain.voice.articulation import model_look_ahead_s
from facesynth.domain.voice.fitting import HeldOutTakes, fit_performer, held_out_takes, performer_takes
from facesynth.domain.voice.fusion import articulation_model
from facesynth.model.artifacts import check_output
from facesynth.model.corpus import Corpus
from facesynth.model.frames import NormalizedFrames


@dataclass(frozen=True)
class FitArticulationResult:
    """What ``facesynth fit-articulation`` fitted.

    takes: the takes fitted on (those with audio).
    seconds: their audio, s.
    targets: the curves the model predicts.
    solved: whether the rig's curves (jawOpen, mouthFunnel, mouthPucker) are among them (the
        capture's markers bound on the rig).
    fit_r: per target, Pearson r of the model's prediction on the takes it was fitted on.
    held_out: each take predicted by the model fitted on the others (r per target, the voice's
        closures and the threshold chosen for them), or None with one take.
    look_ahead_s: how far past a frame's time the model reads the audio, s.
    bytes: the model file's size.
    """

    takes: list[str]
    seconds: float
    targets: list[str]
    solved: bool
    fit_r: dict[str, float]
    held_out: HeldOutTakes | None
    look_ahead_s: float
    bytes: int


def run(normalized_path: Path, corpus_path: Path, out: Path, synthesize: SynthesizeSettings, solve: SolveSettings, *,
        binding: Path | None = None, takes: list[str] | None = None, overwrite: bool = False) -> FitArticulationResult:
    """Fit the articulation model on the takes (all with audio, or ``takes``) of ``corpus_path``
    (an ingested capture: its audio) and ``normalized_path`` (its normalized frames), the markers
    bound on the built-in rig by its own binding or ``binding``, and write ``out``."""
    check_output(out, overwrite)
    corpus = Corpus.read(corpus_path)
    normalized = NormalizedFrames.read(normalized_path)
    rig = load_rig(None, binding, need_binding=False)
    data = performer_takes(corpus, normalized, rig, solve, tuple(synthesize.loudness_lip_markers), takes=takes,
                           where=str(corpus_path), normalized_where=str(normalized_path))
    prior = articulation_model(synthesize.articulation_model) if synthesize.articulation_prior > 0 else None
    model, fit_r = fit_performer(data, prior, synthesize.articulation_prior)
    held_out = held_out_takes(data, prior, synthesize.articulation_prior)
    model.closure_threshold = held_out.closure_threshold if held_out is not None else None
    settings = {"offsets_s": [float(x) for x in model.offsets_s], "pool": model.pool, "alpha": model.alpha,
                "normalization": model.normalization, "tau_s": model.tau_s, "expand": model.expand,
                "lip_markers": list(synthesize.loudness_lip_markers), "takes": data.names_used,
                "articulation_prior": synthesize.articulation_prior,
                "prior_fitted_on": [r["name"] for r in prior.fitted_on] if prior is not None else []}
    prior_file = ([Path(synthesize.articulation_model)] if prior is not None and synthesize.articulation_model
                  else [])  # the packaged prior is named by what it was fitted on (settings), not a path
    inputs = [corpus_path, normalized_path] + ([binding] if binding is not None else []) + prior_file
    model.write(out, config=json.dumps(settings, sort_keys=True), inputs=inputs, overwrite=overwrite)
    return FitArticulationResult(data.names_used, data.seconds, list(data.names), data.solved, fit_r, held_out,
                                 model_look_ahead_s(model), out.stat().st_size)
