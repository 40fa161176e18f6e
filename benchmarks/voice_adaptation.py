"""A performer's own articulation model adapted from the general one (``fit-articulation`` with
``synthesize.articulation_prior``): the gain on the performer's held-out takes, the loss on other
speakers. Prints JSON.

The performer is FACEGOOD's (``--facegood``, as in ``benchmarks/real_speech_lipsync.py``): her
model is fitted on the calibration takes 1114_2_01..03 and scored on the takes used for no choice
(1114_2_04, 1114_2_05, 1114_3_15). The general model is fitted (as ``benchmarks/voice_speakers.py``
fits a fold) on every real speaker of ``--speech-data`` but FACEGOOD and the ``--check`` sources,
whose speakers measure what the performer's model forgets of other voices. For each prior strength
(0: her takes alone; ``general``: the general model itself) the voice model's own predicted opening
is scored (Pearson r per 10 s window or utterance against the real opening; FACEGOOD's mean over
windows with a bootstrap interval over windows, the check speakers' mean over speakers with one
over speakers; 2000 resamples, seed 0).

    python benchmarks/voice_adaptation.py --facegood FACEGOOD_DIR --speech-data DIR --work WORK \\
        > benchmarks/voice_adaptation.json
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

from facesynth.domain.evaluation.bootstrap import interval, resamples
from facesynth.domain.voice import articulation as A

sys.path.insert(0, str(Path(__file__).resolve().parent))

import voice_speakers as vs  # noqa: E402  (its loaders, targets and fold fit)

CALIBRATION = ("1114_2_01", "1114_2_02", "1114_2_03")
FAIR = ("1114_2_04", "1114_2_05", "1114_3_15")
STRENGTHS = (0.0, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0)


def opening_r(model: A.ArticulationModel, utts: list[vs.Utt], window_s: float) -> list[float]:
    """Window r's of the model's predicted opening against each utterance's real one."""
    out: list[float] = []
    for u in utts:
        pred = A.predict_raw(model, u.raw, np.arange(u.n) / vs.FPS)[:, model.column("opening")]
        out += vs.window_scores(pred, u.real["opening"], u.n, window_s)
    return out


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--facegood", type=Path, required=True)
    ap.add_argument("--speech-data", type=Path, required=True)
    ap.add_argument("--work", type=Path, required=True)
    ap.add_argument("--check", default="haskins,video_retalking",
                    help="sources whose speakers score the loss on other voices (left out of the general model)")
    ap.add_argument("--window-s", type=float, default=10.0)
    ap.add_argument("--resamples", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args(argv)
    started = time.perf_counter()
    check_sources = args.check.split(",")
    utts = vs.facegood_utterances(args.facegood) + vs.speech_data_utterances(args.speech_data, ("facegood",))
    for u in utts:
        u.raw = A.frame_features(u.samples, u.rate)
    ref = vs.reference_ranges([u for u in utts if u.speaker == vs.FACEGOOD_SPEAKER])
    by_speaker: dict[str, list[vs.Utt]] = {}
    for u in utts:
        by_speaker.setdefault(u.speaker, []).append(u)
    general_train = {s: v for s, v in by_speaker.items()
                     if s != vs.FACEGOOD_SPEAKER and v[0].source not in check_sources}
    check = {s: v for s, v in by_speaker.items() if v[0].source in check_sources}
    general = vs.fit_fold(general_train, ref, "default", 0, args.seed, speaker_weights="frames")
    her = by_speaker[vs.FACEGOOD_SPEAKER]
    calibration = [u for u in her if u.name in CALIBRATION]
    fair = [u for u in her if u.name in FAIR]
    takes = [A.Take(u.raw, y, vs.FPS) for u, y in zip(calibration, vs.speaker_targets(calibration, ref))]
    names = tuple(vs.TARGETS)
    models = {"general": general}
    for s in STRENGTHS:
        models[f"{s:g}"] = A.fit(takes, names, prior=general if s > 0 else None, prior_strength=s)
    fair_r = {m: np.array(opening_r(model, fair, args.window_s)) for m, model in models.items()}
    check_r = {m: np.array([np.nanmean(opening_r(model, v, args.window_s)) for _, v in sorted(check.items())])
               for m, model in models.items()}
    n, k = len(fair_r["general"]), len(check)
    wi, si = resamples(n, args.resamples, args.seed), resamples(k, args.resamples, args.seed)

    def mean_of(v):
        return lambda i: float(np.nanmean(v[i]))

    def rounded(d):
        return {a: (None if b is None else round(float(b), 4)) for a, b in d.items()}

    out = {}
    for m in models:
        out[m] = {"performer_held_out_takes": rounded(interval(mean_of(fair_r[m]), n, wi)),
                  "other_speakers": rounded(interval(mean_of(check_r[m]), k, si)),
                  "performer_gain_over_general": round(float(np.nanmean(fair_r[m]) - np.nanmean(fair_r["general"])), 4),
                  "other_speakers_change": round(float(np.nanmean(check_r[m]) - np.nanmean(check_r["general"])), 4)}
    return {"benchmark": "voice_adaptation", "performer": vs.FACEGOOD_SPEAKER, "fitted_on": list(CALIBRATION),
            "scored_on": list(FAIR), "general_fitted_on": sorted(general_train), "other_speakers": sorted(check),
            "by_prior_strength": out, "seconds": round(time.perf_counter() - started, 1)}


if __name__ == "__main__":
    print(json.dumps(main(), indent=2))
