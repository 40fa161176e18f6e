"""Precision and recall of ``facesynth prune --auto`` against the sample corpus's injected
contamination (``contamination.csv``), at the level of motion nodes. Prints JSON.

    python benchmarks/prune_auto.py --db out/bench/db.h5 --truth out/bench/corpus/contamination.csv
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

from facesynth.base.config import Config
from facesynth.domain.database.contamination import contaminated_nodes, detect
from facesynth.model.motiondb import MotionDatabase


def evaluate(db: Path, truth_csv: Path, overrides: tuple[str, ...] = ()) -> dict:
    settings = Config.load(None, overrides).settings("prune")
    database = MotionDatabase.read(db, markers=True)
    nodes, takes = database.nodes, database.takes
    truth = contaminated_nodes(nodes, takes, truth_csv)
    t0 = time.perf_counter()
    found = detect(nodes, takes, database.frames.markers, database.coeffs, database.fps, settings)
    seconds = time.perf_counter() - t0
    flagged = set(found)
    tp = len(flagged & truth)
    by_kind = {}
    for k, kind in found.items():
        row = by_kind.setdefault(kind, {"found": 0, "true": 0})
        row["found"] += 1
        row["true"] += int(k in truth)
    return {"nodes": len(nodes), "contaminated": len(truth), "flagged": len(flagged), "true_positives": tp,
            "precision": round(tp / max(1, len(flagged)), 4), "recall": round(tp / max(1, len(truth)), 4),
            "by_kind": by_kind, "seconds": round(seconds, 3), "settings": settings.__dict__}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--db", type=Path, required=True)
    ap.add_argument("--truth", type=Path, required=True)
    ap.add_argument("--set", dest="overrides", action="append", default=[])
    args = ap.parse_args()
    print(json.dumps(evaluate(args.db, args.truth, tuple(args.overrides)), indent=2))


if __name__ == "__main__":
    main()
