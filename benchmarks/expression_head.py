"""The bilinear expression model and pitch-driven head motion (Chuang & Bregler 2005 §3, §5),
measured on the held-out takes of the sample corpus.

    .venv/bin/python benchmarks/expression_head.py --preset small --seed 0 --work out/bench_expr \\
        [--plot out/bench_expr/head_motion.png]

Makes the corpus and its artifacts in ``--work`` (kept between runs) and prints JSON:

* ``restyle``: every held-out (val and test split) sentence's neutral take restyled into
  each other emotion at intensity 0.25 / 0.5 / 1.0, against the captured take of the same
  sentence in that emotion, time-warped phone by phone onto the neutral take: RMS marker
  distance (mm), with the unchanged neutral take as the baseline; and the fraction of frames a
  logistic-regression classifier trained on the captured training frames labels with the
  target emotion (the captured target take is the reference). Means over (sentence, emotion)
  pairs with bootstrap 95% intervals (2000 resamples of the pairs).
* ``head_motion``: for every held-out take, head motion from its own audio against its
  captured head motion: per-axis RMS (degrees; rotation-vector components), the
  Wasserstein distance between angular-speed distributions (deg/s), and the mean |Pearson r|
  of pitch with the three rotation axes (captured: the reference), for the method and two
  baselines (no motion; a random captured segment sequence, blended the same way). Means over
  takes with bootstrap 95% intervals.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
from pathlib import Path

import numpy as np

from facesynth.base.config import Config
from facesynth.domain.expression import bilinear, training
from facesynth.domain.head_motion import from_pitch
from facesynth.model.corpus import Corpus
from facesynth.model.frames import NormalizedFrames, relative_to_take
from facesynth.model.motiondb import MotionDatabase

HELD_OUT = ("val", "test")
INTENSITIES = (0.25, 0.5, 1.0)


def build(work: Path, preset: str, seed: int) -> None:
    """The corpus and its artifacts in ``work`` (skipped when present)."""
    fs = [sys.executable, "-m", "facesynth.cli"]
    steps = [("corpus", ["sample-corpus", str(work / "corpus"), "--preset", preset, "--seed", str(seed)]),
             ("corpus.h5", ["ingest", str(work / "corpus" / "manifest.csv"), "-o", str(work / "corpus.h5")]),
             ("normalized.h5", ["normalize", str(work / "corpus.h5"), "-o", str(work / "normalized.h5")]),
             ("pca.h5", ["pca", str(work / "normalized.h5"), "-o", str(work / "pca.h5")]),
             ("db.h5", ["build-db", str(work / "pca.h5"), "-o", str(work / "db.h5")])]
    for name, args in steps:
        if not (work / name).exists():
            subprocess.run(fs + args + ["-q"], check=True)


def bootstrap(values: np.ndarray, rng: np.random.Generator, n: int = 2000) -> dict:
    """Mean and bootstrap 95% interval of the mean over the rows of ``values``."""
    values = np.asarray(values, float)
    means = values[rng.integers(0, len(values), (n, len(values)))].mean(axis=1)
    return {"mean": float(values.mean()), "ci95": [float(np.percentile(means, 2.5)), float(np.percentile(means, 97.5))],
            "n": int(len(values))}


def rms_mm(a: np.ndarray, b: np.ndarray) -> float:
    """RMS over frames and markers of the 3D marker distance (mm)."""
    return float(np.sqrt(np.mean(np.sum((a - b) ** 2, axis=-1))))


def restyle_eval(norm: NormalizedFrames, config: Config, rng: np.random.Generator) -> dict:
    from sklearn.linear_model import LogisticRegression

    settings = config.settings("expression")
    X, emotions, _, _ = training.aligned_data(norm, settings.splits, settings.frame_step)
    model = training.fit_model(X, emotions, settings)
    # the classifier: captured training frames (every 4th, 30 Hz), in the model's PCA coefficients
    takes, fr = norm.takes, norm.frames
    feats, labels = [], []
    for i in range(len(takes)):
        if takes.split[i] == "train":
            m = fr.markers[takes.frames(i)][::4]
            m = m[np.isfinite(m.reshape(len(m), -1)).all(1)]
            feats.append(model.coefficients(m))
            labels += [takes.emotion[i]] * len(m)
    clf = LogisticRegression(max_iter=2000).fit(np.concatenate(feats), labels)
    step = max(1, int(round(fr.fps / 30)))
    blocks, emos, used, _ = training.aligned_blocks(norm, HELD_OUT, step)
    assert emos == emotions, (emos, emotions)
    neutral = emotions.index("neutral")
    rows = {"baseline_neutral": []} | {f"restyled_{a:g}": [] for a in INTENSITIES}
    recog = {"baseline_neutral": [], "captured_target": []} | {f"restyled_{a:g}": [] for a in INTENSITIES}
    units = []
    for block, sentence in zip(blocks, used):
        src = block[neutral]
        for k, e in enumerate(emotions):
            if k == neutral:
                continue
            truth = block[k]
            units.append(f"{sentence}/{e}")
            rows["baseline_neutral"].append(rms_mm(src, truth))
            recog["baseline_neutral"].append(float(np.mean(clf.predict(model.coefficients(src)) == e)))
            recog["captured_target"].append(float(np.mean(clf.predict(model.coefficients(truth)) == e)))
            for a in INTENSITIES:
                out, _ = bilinear.restyle(model, src, np.repeat(model.style(e)[None], len(src), 0), np.full(len(src), a),
                                          iterations=settings.analyze_iterations,
                                          smooth_frames=settings.style_smoothing_s * fr.fps / step,
                                          init=settings.analyze_init)
                rows[f"restyled_{a:g}"].append(rms_mm(out, truth))
                recog[f"restyled_{a:g}"].append(float(np.mean(clf.predict(model.coefficients(out)) == e)))
    base = np.array(rows["baseline_neutral"])
    return {"units": units, "fit_errors_mm2": model.errors.tolist(),
            "rms_mm": {k: bootstrap(v, rng) for k, v in rows.items()},
            "rms_minus_baseline_mm": {k: bootstrap(np.array(v) - base, rng) for k, v in rows.items() if k != "baseline_neutral"},
            "target_recognised": {k: bootstrap(v, rng) for k, v in recog.items()}}


def _angular_speed(rotvec_deg: np.ndarray, fps: float) -> np.ndarray:
    from scipy.spatial.transform import Rotation

    r = Rotation.from_rotvec(np.radians(rotvec_deg))
    return np.degrees((r[1:] * r[:-1].inv()).magnitude()) * fps


def _pitch_corr(pitch: np.ndarray, hop_s: float, head: np.ndarray, fps: float) -> float:
    """Mean |Pearson r| of the voiced pitch (Hz) with the three rotation axes."""
    t = np.arange(len(head)) / fps
    p = np.interp(t, np.arange(len(pitch)) * hop_s, np.nan_to_num(pitch, nan=-1.0))
    voiced = np.interp(t, np.arange(len(pitch)) * hop_s, np.isfinite(pitch).astype(float)) > 0.99
    if voiced.sum() < 3:
        return 0.0
    out = []
    for a in range(3):
        x = head[voiced, a]
        out.append(0.0 if x.std() < 1e-9 else abs(float(np.corrcoef(p[voiced], x)[0, 1])))
    return float(np.mean(out))


def head_eval(work: Path, config: Config, rng: np.random.Generator, plot: Path | None) -> dict:
    from scipy.stats import wasserstein_distance

    s = config.settings("head_motion")
    db = MotionDatabase.read(work / "db.h5")
    corpus = Corpus.read(work / "corpus.h5")
    norm = NormalizedFrames.read(work / "normalized.h5")
    lib = from_pitch.library(db, corpus, work / "db.h5", work / "corpus.h5", s)
    rel_r, rel_t = relative_to_take(norm.frames.head_rotation, norm.frames.head_translation,
                                    [norm.takes.frames(i) for i in range(len(norm.takes))])
    truth_all = from_pitch.head_channels(rel_r, rel_t)
    methods = ("method", "no_motion", "random_segments")
    rms = {m: [] for m in methods}
    speed = {m: [] for m in methods}
    corr = {m: [] for m in methods + ("captured",)}
    takes_used = []
    plotted = None
    for i, name in enumerate(norm.takes.name):
        if norm.takes.split[i] not in HELD_OUT:
            continue
        k = corpus.takes.index(name)
        a = int(corpus.audio_start[k])
        samples = corpus.audio[a:a + int(corpus.audio_count[k])]
        dur = len(samples) / corpus.sample_rate
        p = from_pitch.clean_pitch(samples, corpus.sample_rate, s)
        truth_c = truth_all[norm.takes.frames(i)]
        res, _ = from_pitch.synthesize(lib, p, dur, s, exclude={norm.takes.sentence[i]})
        rnd, _ = from_pitch.synthesize(lib, p, dur, s, exclude={norm.takes.sentence[i]}, random=rng)
        T = len(res.head)
        src = np.arange(len(truth_c)) / norm.frames.fps
        truth = np.stack([np.interp(np.arange(T) / s.fps, src, truth_c[:, d]) for d in range(6)], 1)
        heads = {"method": res.head, "no_motion": np.zeros_like(res.head), "random_segments": rnd.head}
        truth_speed = _angular_speed(truth[:, :3], s.fps)
        for m, h in heads.items():
            rms[m].append(np.sqrt(np.mean((h[:, :3] - truth[:, :3]) ** 2, axis=0)))
            speed[m].append(wasserstein_distance(_angular_speed(h[:, :3], s.fps), truth_speed))
            corr[m].append(_pitch_corr(p, s.hop_s, h, s.fps))
        corr["captured"].append(_pitch_corr(p, s.hop_s, truth, s.fps))
        takes_used.append(name)
        if plotted is None:
            plotted = (name, p, res, rnd, truth, lib)
    out = {"takes": takes_used, "library_takes": len(lib),
           "per_axis_rms_deg": {m: {ax: bootstrap(np.array(v)[:, j], rng) for j, ax in enumerate("xyz")}
                                for m, v in rms.items()},
           "rms_deg_all_axes": {m: bootstrap(np.sqrt(np.mean(np.array(v) ** 2, axis=1)), rng) for m, v in rms.items()},
           "angular_speed_wasserstein_deg_s": {m: bootstrap(v, rng) for m, v in speed.items()},
           "pitch_correlation_abs_r": {m: bootstrap(v, rng) for m, v in corr.items()}}
    if plot is not None and plotted is not None:
        _plot(plot, plotted, s)
        out["plot"] = str(plot)
    return out


def _plot(path: Path, plotted, s) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    name, p, res, rnd, truth, lib = plotted
    fig, ax = plt.subplots(4, 1, figsize=(10, 9), sharex=True)
    t = np.arange(len(p)) * s.hop_s
    ax[0].plot(t, p, "k")
    for g, c in zip(res.segments, res.choices):
        ax[0].axvline(g.start, color="tab:blue", lw=0.8)
        ax[0].text(g.start, np.nanmax(p) if np.isfinite(p).any() else 0, f"{lib[c.take].name}#{c.index}",
                   fontsize=7, rotation=90, va="top")
    ax[0].set_ylabel("pitch (Hz)")
    ax[0].set_title(f"{name}: cleaned pitch, segments and the captured segment chosen for each")
    th = np.arange(len(res.head)) / s.fps
    for j, axis in enumerate("xyz"):
        ax[j + 1].plot(th, truth[:, j], "k", label="captured")
        ax[j + 1].plot(th, res.head[:, j], "tab:blue", label="pitch-driven (§5)")
        ax[j + 1].plot(th, rnd.head[:, j], "tab:orange", lw=0.8, label="random segments")
        ax[j + 1].set_ylabel(f"rotation {axis} (deg)")
    ax[1].legend(fontsize=8)
    ax[-1].set_xlabel("time (s)")
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=100)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--preset", default="small")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--work", type=Path, required=True)
    ap.add_argument("--plot", type=Path, default=None)
    args = ap.parse_args()
    args.work.mkdir(parents=True, exist_ok=True)
    build(args.work, args.preset, args.seed)
    config = Config.load(None, ())
    rng = np.random.default_rng(args.seed)
    norm = NormalizedFrames.read(args.work / "normalized.h5")
    result = {"preset": args.preset, "seed": args.seed, "held_out_splits": list(HELD_OUT),
              "restyle": restyle_eval(norm, config, rng),
              "head_motion": head_eval(args.work, config, rng, args.plot)}
    json.dump(result, sys.stdout, indent=1)
    print()


if __name__ == "__main__":
    main()
