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

``chain``: the performer's model at the default prior strength (``synthesize.articulation_prior``)
as ``fit-articulation`` writes it, the threshold of the voice's own closures chosen on her
calibration takes held out one by one (:func:`facesynth.domain.voice.fitting.held_out_takes`), in
``synthesize --audio`` on her scored takes: the voice step run on the DP's motion of the phones
recognised from the audio (``benchmarks/voice_speakers.py``'s chain and its cache in ``--work``),
with the default settings (``performer``: her model closes the lips at its threshold), with the
voice's closures off (``performer_closures_off``, ``voice_closure_threshold = 2``: the releases
before), with the general model (``general``) and the phones alone (``phones``). Mouth-opening r
per window with intervals over windows and the paired difference of ``performer``; closures as
``voice_speakers.py`` counts them, summed over the takes (one speaker: within-speaker figures).

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

from facesynth.base.config import Config
from facesynth.domain.evaluation.bootstrap import interval, paired_difference, resamples
from facesynth.domain.voice import articulation as A
from facesynth.domain.voice import fitting

sys.path.insert(0, str(Path(__file__).resolve().parent))

import voice_speakers as vs  # noqa: E402  (its loaders, targets and fold fit)

CALIBRATION = ("1114_2_01", "1114_2_02", "1114_2_03")
FAIR = ("1114_2_04", "1114_2_05", "1114_3_15")
STRENGTHS = (0.0, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0)


def mean_of(v: np.ndarray):
    """The statistic "mean over the chosen rows" of ``v`` (a bootstrap's statistic)."""
    return lambda i: float(np.nanmean(v[i]))


def rounded(d: dict) -> dict:
    """``d`` with its numbers to four decimals (None kept)."""
    return {a: (None if b is None else round(float(b), 4)) for a, b in d.items()}


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
    general = vs.fit_fold(general_train, ref, "default", 0, args.seed)
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

    out = {}
    for m in models:
        out[m] = {"performer_held_out_takes": rounded(interval(mean_of(fair_r[m]), n, wi)),
                  "other_speakers": rounded(interval(mean_of(check_r[m]), k, si)),
                  "performer_gain_over_general": round(float(np.nanmean(fair_r[m]) - np.nanmean(fair_r["general"])), 4),
                  "other_speakers_change": round(float(np.nanmean(check_r[m]) - np.nanmean(check_r["general"])), 4)}
    chain = performer_chain(general, takes, names, fair, args)
    return {"benchmark": "voice_adaptation", "performer": vs.FACEGOOD_SPEAKER, "fitted_on": list(CALIBRATION),
            "scored_on": list(FAIR), "general_fitted_on": sorted(general_train), "other_speakers": sorted(check),
            "by_prior_strength": out, "chain": chain, "seconds": round(time.perf_counter() - started, 1)}


def performer_chain(general: A.ArticulationModel, takes: list[A.Take], names: tuple[str, ...], fair: list[vs.Utt],
                    args) -> dict:
    """The ``chain`` of the module docstring: the performer's model from ``takes`` (adapted from
    ``general``) in ``synthesize --audio`` on the ``fair`` utterances."""
    import real_speech_lipsync as bench

    settings = Config.load().settings("synthesize")
    data = fitting.PerformerTakes(takes, names, list(CALIBRATION), 0.0, True)
    model, _ = fitting.fit_performer(data, general, settings.articulation_prior)
    held = fitting.held_out_takes(data, general, settings.articulation_prior)
    assert held is not None  # three calibration takes
    model.closure_threshold = held.closure_threshold
    args.work.mkdir(parents=True, exist_ok=True)
    paths = {"general": args.work / "adaptation-general.h5", "performer": args.work / "adaptation-performer.h5"}
    general.write(paths["general"], config="{}", inputs=[], overwrite=True)
    model.write(paths["performer"], config="{}", inputs=[], overwrite=True)
    db = bench.build_database(args.work)
    modes = {"performer": ("performer", {}), "performer_closures_off": ("performer", {"voice_closure_threshold": 2.0}),
             "general": ("general", {}), "phones": (None, {})}
    scores: dict[str, list[float]] = {m: [] for m in modes}
    counts = {m: np.zeros(4, np.int64) for m in modes}
    for u in fair:
        motion, phones = vs.phones_motion(db, u, args.work)
        for mode, (which, changes) in modes.items():
            curve = vs.opening_of(motion, settings, u.n) if which is None else \
                vs.voice_step(motion, u, phones, settings, paths[which], True, "articulation", **changes)
            scores[mode] += vs.window_scores(curve, u.real["opening"], u.n, args.window_s)
            counts[mode] += vs.closure_counts(curve, u.real["opening"], 0.25, 0.25, 3)
    n = len(scores["performer"])
    idx = resamples(n, args.resamples, args.seed)
    table = {m: np.array(v) for m, v in scores.items()}
    return {"closure_threshold": held.closure_threshold,
            "held_out_calibration": {"r": {k: round(v, 4) for k, v in held.r.items()}, "closures": held.closures,
                                     "recall": round(held.recall, 4), "precision": round(held.precision, 4)},
            "r": {m: rounded(interval(mean_of(v), n, idx)) for m, v in table.items()},
            "paired": {f"performer - {m}": rounded(paired_difference(mean_of(table["performer"]), mean_of(v), n, idx))
                       for m, v in table.items() if m != "performer"},
            "closures": {m: {"recall": round(float(c[0] / max(c[1], 1)), 4),
                             "precision": round(float(c[2] / max(c[3], 1)), 4),
                             "real_closures": int(c[1]), "closures": int(c[3])} for m, c in counts.items()},
            "windows": n}


if __name__ == "__main__":
    print(json.dumps(main(), indent=2))
