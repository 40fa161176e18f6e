"""Pops at joins: the second difference of synthesized markers at non-captured joins against
clean capture, and the error, on the held-out takes. Prints JSON.

Every held-out sentence is synthesized from its phones and emotions (the settings of
``--config``/``--set``). At each join between two spoken phones whose nodes are not captured
neighbours, the second differences |x[f+1] - 2 x[f] + x[f-1]| (mm/frame^2 at the capture
rate, per marker) at the join's two frames are pooled; the same statistic over every frame of
the clean (noise-free) capture of the same takes, aligned like the corpus, is the reference.
The error is the RMS marker distance (mm) against the captured markers and against the clean
capture, with bootstrap 95% intervals over sentences.

    python benchmarks/join_smoothness.py --db out/db_clean.h5 --corpus out/corpus.h5 \\
        --clean out/corpus/groundtruth [--split test] [--set synthesize.join_smoothing=eq16]
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np

from facesynth.base.config import Config
from facesynth.base.phonemes import PAU
from facesynth.domain.evaluation.held_out import heldout, normalized_take
from facesynth.domain.search.pairs import transition_costs
from facesynth.domain.search.synthesis import synthesize
from facesynth.formats.mocap import read_mocap
from facesynth.model.corpus import Corpus
from facesynth.model.motiondb import MotionDatabase


def second_differences(x: np.ndarray) -> np.ndarray:
    """(T - 2, M) per-marker norms of the second difference of (T, M, 3) frames."""
    return np.linalg.norm(x[2:] - 2 * x[1:-1] + x[:-2], axis=2)


def interval(values: np.ndarray, stat, rng, boot: int = 1000) -> list[float]:
    """Bootstrap 95% interval of ``stat`` over the rows of ``values``."""
    draws = [stat(values[rng.integers(0, len(values), len(values))]) for _ in range(boot)]
    return [round(float(np.percentile(draws, 2.5)), 4), round(float(np.percentile(draws, 97.5)), 4)]


def measure(db_path: Path, corpus_path: Path, clean_dir: Path, split: str, overrides: tuple[str, ...], seed: int = 0) -> dict:
    config = Config.load(None, overrides)
    synth, norm = config.settings("synthesize"), config.settings("normalize")
    db = MotionDatabase.read(db_path)
    corpus = Corpus.read(corpus_path, audio=False)
    sentences = heldout(corpus_path, db, split, norm)
    tc = transition_costs(db, synth, False)
    at_joins, clean_d2, rows = [], [], []
    t0 = time.perf_counter()
    for s in sentences:
        res = synthesize(db, s.utterance, {}, synth, tc=tc)
        x = res.rendered.markers_capture.astype(np.float64)
        cat = res.rendered.concatenated
        node, step = cat.node, cat.step
        d2 = second_differences(x)  # row f - 1 is centred on frame f
        joins = [f for f in range(1, len(node) - 1)
                 if step[f] != step[f - 1] and node[f] >= 0 and node[f - 1] >= 0 and db.nodes.pre[node[f]] != node[f - 1]
                 and s.utterance.phones[step[f]] != PAU and s.utterance.phones[step[f - 1]] != PAU]
        for f in joins:
            at_joins.append(d2[f - 2 : f].ravel() if f >= 2 else d2[f - 1 : f].ravel())
        raw = read_mocap(clean_dir / f"{s.take}.c3d")
        order = [raw.names.index(n) for n in db.marker_names]
        clean = normalized_take(raw.positions[:, order], db, norm, corpus.rigid_markers)[0]
        clean_d2.append(second_differences(clean).ravel())
        n = min(len(x), len(s.truth), len(clean))
        rows.append((float(np.nanmean(np.sum((x[:n] - s.truth[:n]) ** 2, axis=2))),
                     float(np.nanmean(np.sum((x[:n] - clean[:n]) ** 2, axis=2))), n))
    seconds = time.perf_counter() - t0
    joined = np.concatenate(at_joins) if at_joins else np.zeros(1)
    clean_all = np.concatenate(clean_d2)
    rng = np.random.default_rng(seed)
    r = np.array(rows)

    def rms(col):
        return lambda a: float(np.sqrt(np.average(a[:, col], weights=a[:, 2])))

    p99_join = float(np.percentile(joined, 99))
    p99_clean = float(np.percentile(clean_all, 99))
    return {"db": str(db_path), "split": split, "sentences": len(sentences), "joins": len(at_joins),
            "settings": list(overrides),
            "join_d2_p99_mm_per_frame2": round(p99_join, 4), "clean_d2_p99_mm_per_frame2": round(p99_clean, 4),
            "ratio": round(p99_join / p99_clean, 3), "join_d2_median": round(float(np.median(joined)), 4),
            "rms_vs_captured_mm": round(rms(0)(r), 4), "rms_vs_captured_ci95": interval(r, rms(0), rng),
            "rms_vs_clean_mm": round(rms(1)(r), 4), "rms_vs_clean_ci95": interval(r, rms(1), rng),
            "seconds": round(seconds, 2)}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--db", type=Path, required=True)
    ap.add_argument("--corpus", type=Path, required=True)
    ap.add_argument("--clean", type=Path, required=True, help="the folder of clean <take>.c3d files")
    ap.add_argument("--split", default="test")
    ap.add_argument("--set", dest="overrides", action="append", default=[])
    args = ap.parse_args()
    print(json.dumps(measure(args.db, args.corpus, args.clean, args.split, tuple(args.overrides)), indent=1))


if __name__ == "__main__":
    main()
