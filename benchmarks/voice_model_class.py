"""A model with more capacity, tried: a neural network beside the shipped ridge regression, on
the same context of the voice, leaving whole sources out. Prints JSON.

The articulation model (``facesynth.domain.voice.articulation``) maps its context (40 normalized
voice features and 6 loudness columns at 10 offsets: 460 columns) to the mouth by ridge
regression. A multilayer perceptron (scikit-learn's ``MLPRegressor``: one hidden layer of ReLU
units, Adam, an L2 penalty ``alpha``) can learn what a linear map cannot; whether that carries to
voices it never heard is the question.

Protocol: leave one *source* out (6 folds: FACEGOOD, GRID, Haskins, STEM-E2VA, VoxCeleb2,
video-retalking; the stricter test of a new microphone, room and language), as
``benchmarks/voice_speakers.py --no-chain --folds source`` does. In each fold the ridge model is
fitted as the packaged one is (``voice_speakers.fit_fold``: every speaker weighing alike, targets
in FACEGOOD's units), and each network on the same context (the ridge fit's normalizer, columns
standardized on the training frames), the same opening targets and the same frame weights. Each
held-out speaker's first 60 s are scored: the predicted opening against the real one (Pearson r in
10 s windows, mean per speaker), pooled over speakers with a 95% bootstrap interval resampling
speakers, the ridge model paired against each network. Deterministic (seeded networks, seeded
resamples).

    python benchmarks/voice_model_class.py --facegood FACEGOOD_DIR --speech-data SPEECH_DIR \\
        > benchmarks/voice_model_class.json
"""

from __future__ import annotations

import argparse
import json
import sys
import time
import warnings
from pathlib import Path

import numpy as np

from facesynth.domain.voice import articulation as A

sys.path.insert(0, str(Path(__file__).resolve().parent))

import voice_speakers as vs  # noqa: E402  (the speakers' loaders, targets, folds and scores)

#: The networks tried: name -> MLPRegressor settings (one hidden layer; alpha its L2 penalty).
NETWORKS = {
    "mlp32 alpha=3": {"hidden_layer_sizes": (32,), "alpha": 3.0, "max_iter": 15, "batch_size": 1024},
    "mlp32 alpha=30": {"hidden_layer_sizes": (32,), "alpha": 30.0, "max_iter": 15, "batch_size": 1024},
}


def training_frames(model: A.ArticulationModel, train: dict[str, list], ref) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(context (N, P) float32, opening (N,), weight (N,)) of the training speakers' frames with the
    opening known: ``model``'s context, targets in ``ref``'s units, each speaker weighing alike."""
    column = vs.TARGETS.index("opening")
    xs, ys, ws = [], [], []
    for speaker in sorted(train):
        weight = vs.FPS / sum(u.n for u in train[speaker])
        for u, y in zip(train[speaker], vs.speaker_targets(train[speaker], ref)):
            x = A.design(model, u.raw, np.arange(u.n) / vs.FPS)
            ok = np.isfinite(y[:, column]) & np.isfinite(x).all(1)
            xs.append(x[ok])
            ys.append(y[ok, column])
            ws.append(np.full(int(ok.sum()), weight))
    w = np.concatenate(ws)
    return np.concatenate(xs), np.concatenate(ys), w * len(w) / w.sum()


def main(argv=None) -> dict:
    from sklearn.neural_network import MLPRegressor

    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--facegood", type=Path, required=True, help="FACEGOOD's folder (see real_speech_lipsync.py)")
    ap.add_argument("--speech-data", type=Path, required=True, help="a folder of sources (voice_speakers.py)")
    ap.add_argument("--score-seconds", type=float, default=60.0,
                    help="score each held-out speaker on its first utterances up to this many seconds")
    ap.add_argument("--window-s", type=float, default=10.0, help="Pearson r per window of about this many seconds")
    ap.add_argument("--resamples", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args(argv)
    started = time.perf_counter()
    utts = vs.facegood_utterances(args.facegood) + vs.speech_data_utterances(args.speech_data, ("facegood",))
    by_speaker: dict[str, list] = {}
    for u in utts:
        u.raw = A.frame_features(u.samples, u.rate)
        by_speaker.setdefault(u.speaker, []).append(u)
    ref = vs.reference_ranges([u for u in utts if u.speaker == vs.FACEGOOD_SPEAKER] or utts)
    sources = sorted({v[0].source for v in by_speaker.values()})
    scores: dict[str, dict[str, list[float]]] = {}
    seconds = {}
    for source in sources:
        t0 = time.perf_counter()
        train = {s: v for s, v in by_speaker.items() if v[0].source != source}
        ridge = vs.fit_fold(train, ref, "default", 0, args.seed)
        x, y, w = training_frames(ridge, train, ref)
        mean, std = x.mean(0), x.std(0) + 1e-6
        y_mean, y_std = float(y.mean()), float(y.std())
        networks = {}
        for name, params in NETWORKS.items():
            net = MLPRegressor(random_state=args.seed, **params)
            with warnings.catch_warnings():  # a capped number of epochs is the setting, not a failure
                warnings.simplefilter("ignore")
                net.fit(((x - mean) / std).astype(np.float32), (y - y_mean) / y_std, sample_weight=w)
            networks[name] = net
        for speaker in sorted(s for s, v in by_speaker.items() if v[0].source == source):
            for u in vs.scored_utterances(by_speaker[speaker], args.score_seconds):
                times = np.arange(u.n) / vs.FPS
                context = ((A.design(ridge, u.raw, times) - mean) / std).astype(np.float32)
                curves = {"ridge (as shipped)": A.predict_raw(ridge, u.raw, times)[:, ridge.column("opening")]}
                curves.update({name: net.predict(context) for name, net in networks.items()})
                for name, curve in curves.items():
                    scores.setdefault(speaker, {}).setdefault(name, []).extend(
                        vs.window_scores(curve, u.real["opening"], u.n, args.window_s))
        seconds[source] = round(time.perf_counter() - t0, 1)
    names = ["ridge (as shipped)", *NETWORKS]
    summary = vs.summarize(scores, args.resamples, args.seed, lead=names[0])
    gain = {m: np.array([v[m] - v[names[0]] for v in summary["per_speaker"].values()]) for m in NETWORKS}
    return {"benchmark": "voice_model_class", "folds": "source", "sources": sources, "speakers": summary["speakers"],
            "networks": {n: {a: list(b) if isinstance(b, tuple) else b for a, b in p.items()} for n, p in NETWORKS.items()},
            "r": summary["r"], "paired": summary["paired"],
            "speakers_up_down": {m: [int((g > 0.005).sum()), int((g < -0.005).sum())] for m, g in gain.items()},
            "per_speaker": summary["per_speaker"],
            "settings": {"score_seconds": args.score_seconds, "window_s": args.window_s, "resamples": args.resamples,
                         "seed": args.seed},
            "seconds": {"per_fold": seconds, "total": round(time.perf_counter() - started, 1)}}


if __name__ == "__main__":
    print(json.dumps(main(), indent=2))
