"""The voice's articulation on real speech (issue 42, step 1): the acoustic articulation model
(:mod:`facesynth.domain.voice.articulation`) fitted on FACEGOOD's calibration takes and scored on
its fair takes, against the voice's loudness alone; then leave-one-take-out over all seven takes.

FACEGOOD (one speaker, Mandarin, ARKit-like curves at 30 frames/s; ``--data`` laid out as for
``benchmarks/real_speech_lipsync.py``): the model is fitted on the calibration takes 1114_2_01..03
(the only takes any choice of the model was made on, by leave-one-take-out within them), scored on
the fair takes 1114_2_04, 1114_2_05, 1114_3_15 (used for no choice, as in docs/real-speech.md).
The targets are the benchmark's own real channels (``real_speech_lipsync.real_curves``): the mouth
opening, jawOpen, mouthFunnel, mouthPucker, and two closure scores made of the opening (every
closure, and the closings within speech). Scores are that benchmark's: Pearson r per 10 s
window, the mean over windows with 95% bootstrap intervals over windows and over takes (2000
resamples, seed 0), and paired differences against the loudness envelope alone (``energy``,
:func:`facesynth.domain.speech.loudness.envelope` smoothed over 0.1 s, as in that benchmark).

Leave-one-take-out: each of the seven takes (1114_3_16 included) scored by the model fitted on the
other six; the fitting never sees the take it scores.

    python benchmarks/voice_articulation.py --data FACEGOOD_DIR [--model-out articulation.h5] \\
        > benchmarks/voice_articulation.json

``--model-out`` writes the model fitted on the calibration takes as an ``articulation`` artifact
(the one writer of that kind so far; ``facesynth/data/articulation.h5``, the packaged model, is
its output). Takes seconds (the features of about 12 minutes of audio,
and eight ridge fits).
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

from facesynth.base.hashing import sha256_of
from facesynth.domain.evaluation.bootstrap import interval, paired_difference, resamples
from facesynth.domain.speech.loudness import envelope
from facesynth.domain.voice import articulation as A
from facesynth.formats.audio import read_audio

sys.path.insert(0, str(Path(__file__).resolve().parent))

import real_speech_lipsync as bench  # noqa: E402  (its loaders and scoring functions)

FPS = bench.FPS
CALIBRATION = ("1114_2_01", "1114_2_02", "1114_2_03")
FAIR = ("1114_2_04", "1114_2_05", "1114_3_15")
ALL = ("1114_2_01", "1114_2_02", "1114_2_03", "1114_2_04", "1114_2_05", "1114_3_15", "1114_3_16")
#: The model's targets: the real channels, and the closure scores made of the real opening
#: (:func:`facesynth.domain.voice.articulation.closure_target`: every closure, and the closings
#: within speech), which the fusion's closures come from.
TARGETS = ("opening", "closure", "closing", "jawOpen", "mouthFunnel", "mouthPucker")
#: The channels the loudness envelope alone is scored on (it says nothing of rounding).
ENERGY_CHANNELS = ("opening", "jawOpen")


def load_take(data: Path, take: str, names: list[str], table: dict) -> dict:
    """{take, samples, rate, n (frames at FPS), real {channel: (n,)}, raw (K, D) voice features}."""
    wav, curves = data / "wav" / f"{take}.wav", data / "bs_value_npy" / f"bs_value_{take}.npy"
    if not wav.exists() or not curves.exists():
        raise SystemExit(f"{data}: take {take!r} needs wav/{take}.wav and bs_value_npy/bs_value_{take}.npy")
    values = np.asarray(bench.load_npy(curves), np.float64)
    samples, rate = read_audio(wav)
    n = min(len(values), int(np.floor(len(samples) / rate * FPS)))
    real = {k: v[:n] for k, v in bench.real_curves(values, names, table).items()}
    real["closure"] = A.closure_target(real["opening"], FPS)
    real["closing"] = A.closure_target(real["opening"], FPS, kind="closing")
    return {"take": take, "samples": samples, "rate": rate, "n": n, "real": real,
            "raw": A.frame_features(samples, rate), "paths": [wav, curves]}


def fit_on(takes: list[dict]) -> A.ArticulationModel:
    """The model (default settings) fitted on ``takes``."""
    return A.fit([A.Take(t["raw"], np.stack([t["real"][c] for c in TARGETS], 1), FPS) for t in takes], TARGETS)


def methods_of(model: A.ArticulationModel, take: dict, smooth_s: float) -> dict[str, dict[str, np.ndarray]]:
    """{method: {channel: (n,)}}: the voice model's curves and the loudness envelope's."""
    pred = A.predict_raw(model, take["raw"], np.arange(take["n"]) / FPS)
    env = envelope(take["samples"], take["rate"], take["n"], FPS, smooth_s)
    return {"voice": {c: pred[:, model.column(c)] for c in TARGETS},
            "energy": {c: env for c in ENERGY_CHANNELS}}


def _round(d: dict) -> dict:
    return {k: (None if v is None else round(float(v), 4)) for k, v in d.items()}


def score(rows: list[tuple[dict, dict]], window_s: float, resample_count: int, seed: int) -> dict:
    """Window r's of each (take, methods) pair, their means with intervals over windows and over
    takes, and ``voice - energy`` paired differences."""
    r: dict[str, dict[str, list[np.ndarray]]] = {}
    groups, per_take = [], {}
    for g, (take, methods) in enumerate(rows):
        spans = bench.windows(take["n"], FPS, window_s)
        groups.append(np.full(len(spans), g))
        for method, curves in methods.items():
            for channel, curve in curves.items():
                v = bench.window_r(curve, take["real"][channel], spans)
                r.setdefault(channel, {}).setdefault(method, []).append(v)
                if channel == "opening":
                    per_take.setdefault(take["take"], {})[method] = round(float(np.nanmean(v)), 4)
    group = np.concatenate(groups)
    n, k = len(group), len(rows)
    idx, tidx = resamples(n, resample_count, seed), resamples(k, resample_count, seed)
    out: dict = {"windows": n, "takes": k, "r": {}, "r_takes": {}, "paired": {}, "paired_takes": {}}
    for channel, per in r.items():
        stats = {m: bench.mean_r_statistic(np.concatenate(v)) for m, v in per.items()}
        out["r"][channel] = {m: _round(interval(s, n, idx)) for m, s in stats.items()}
        out["r_takes"][channel] = {m: _round(interval(bench.by_take(s, group), k, tidx)) for m, s in stats.items()}
        if "energy" in stats:
            a, b = stats["voice"], stats["energy"]
            out["paired"][channel] = {"voice - energy": _round(paired_difference(a, b, n, idx))}
            out["paired_takes"][channel] = {"voice - energy": _round(
                paired_difference(bench.by_take(a, group), bench.by_take(b, group), k, tidx))}
    out["per_take_opening_r"] = per_take
    return out


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--data", type=Path, required=True, help="the FACEGOOD folder (see real_speech_lipsync.py)")
    ap.add_argument("--model-out", type=Path, default=None,
                    help="write the model fitted on the calibration takes here (an articulation artifact)")
    ap.add_argument("--window-s", type=float, default=10.0)
    ap.add_argument("--energy-smooth-s", type=float, default=0.1)
    ap.add_argument("--resamples", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args(argv)
    names = bench.channel_names(args.data)
    table = bench.read_table()
    started = time.perf_counter()
    takes = {t: load_take(args.data, t, names, table) for t in ALL}
    features_s = time.perf_counter() - started

    model = fit_on([takes[t] for t in CALIBRATION])
    fair = score([(takes[t], methods_of(model, takes[t], args.energy_smooth_s)) for t in FAIR],
                 args.window_s, args.resamples, args.seed)
    fair.update(fitted_on=list(CALIBRATION), scored_on=list(FAIR), look_ahead_s=round(A.model_look_ahead_s(model), 4))
    if args.model_out:
        # the takes it was fitted on by name and digest, not by path: the packaged model names no
        # folder of the machine that fitted it
        settings = {"offsets_s": list(A.DEFAULT_OFFSETS_S), "pool": model.pool, "alpha": model.alpha,
                    "normalization": model.normalization, "tau_s": model.tau_s, "expand": model.expand,
                    "fitted_on": {f"FACEGOOD/{p.parent.name}/{p.name}": sha256_of(p)
                                  for t in CALIBRATION for p in takes[t]["paths"]}}
        model.write(args.model_out, config=json.dumps(settings, sort_keys=True), inputs=[], overwrite=True)

    loto = score([(takes[held], methods_of(fit_on([takes[t] for t in ALL if t != held]), takes[held],
                                           args.energy_smooth_s)) for held in ALL],
                 args.window_s, args.resamples, args.seed)
    loto["protocol"] = "each of the 7 takes scored by the model fitted on the other 6"
    return {"benchmark": "voice_articulation", "data": "FACEGOOD (one speaker, Mandarin, 30 frames/s)",
            "model": {"offsets_s": list(A.DEFAULT_OFFSETS_S), "pool": model.pool, "alpha": model.alpha,
                      "normalization": model.normalization, "tau_s": model.tau_s, "expand": model.expand,
                      "features": len(A.FEATURE_NAMES), "targets": list(TARGETS)},
            "fair": fair, "leave_one_take_out": loto,
            "seconds": {"features": round(features_s, 1), "total": round(time.perf_counter() - started, 1)}}


if __name__ == "__main__":
    print(json.dumps(main(), indent=2))
