"""How well each transition term of Table I detects a true discontinuity. Prints JSON.

Continuous joins: every captured pair (o_i, o_j) with pre(o_j) = o_i (the capture itself
runs on). Discontinuous joins: for each of those, o_i followed by another node o_k of o_j's
phone (the alternative the search weighs; ``--any`` for a node of any phone). A term is a
good detector when it is larger on the discontinuous joins: the area under the ROC curve
(AUC, 0.5 = chance, 1 = perfect), with a bootstrap 95% interval over the pairs, for PGap
(mm), VGap (mm/frame) and DSC (the database's units).

    python benchmarks/transition_auc.py out/db.h5 [--any] [--seed 0]
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import numpy as np
from scipy.stats import rankdata

from facesynth.domain.search.pairs import node_features, pair_terms
from facesynth.model.motiondb import MotionDatabase


def auc(negative: np.ndarray, positive: np.ndarray) -> float:
    """P(positive > negative) + P(tie) / 2 (Mann-Whitney), float."""
    ranks = rankdata(np.concatenate([negative, positive]))
    n, p = len(negative), len(positive)
    return float((ranks[n:].sum() - p * (p + 1) / 2) / (n * p))


def measure(db_path: Path, any_phone: bool, seed: int, boot: int = 500) -> dict:
    db = MotionDatabase.read(db_path)
    features = node_features(db)
    nodes = db.nodes
    rng = np.random.default_rng(seed)
    j = np.nonzero(nodes.pre >= 0)[0]
    i = nodes.pre[j]
    phones = np.array(nodes.phone)
    k = np.empty_like(j)
    for n, jj in enumerate(j):
        pool = np.nonzero(phones == phones[jj])[0] if not any_phone else np.arange(len(nodes))
        pool = pool[(pool != jj) & (nodes.pre[pool] != i[n])]
        k[n] = rng.choice(pool) if len(pool) else rng.integers(len(nodes))
    out = {"db": str(db_path), "pairs": int(len(j)), "alternatives": "any phone" if any_phone else "same phone"}
    names = ("dsc", "pgap", "vgap")
    cont = [np.empty(len(j)) for _ in names]
    disc = [np.empty(len(j)) for _ in names]
    for n in range(len(j)):
        a = pair_terms(features, np.array([i[n]]), np.array([j[n], k[n]]))
        for t in range(3):
            cont[t][n], disc[t][n] = a[t][0, 0], a[t][0, 1]
    for t, name in enumerate(names):
        value = auc(cont[t], disc[t])
        draws = [auc(cont[t][s], disc[t][s]) for s in (rng.integers(0, len(j), len(j)) for _ in range(boot))]
        out[name] = {"auc": round(value, 4), "ci95": [round(float(np.percentile(draws, 2.5)), 4), round(float(np.percentile(draws, 97.5)), 4)],
                     "median_continuous": round(float(np.median(cont[t])), 5), "median_discontinuous": round(float(np.median(disc[t])), 5)}
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("db", nargs="+", type=Path)
    ap.add_argument("--any", action="store_true", help="alternatives of any phone, not just o_j's")
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    print(json.dumps([measure(p, args.any, args.seed) for p in args.db], indent=1))


if __name__ == "__main__":
    main()
