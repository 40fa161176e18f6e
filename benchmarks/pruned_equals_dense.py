"""The exact pruned search against the dense DP on one database: for paper Table V's 14, 24,
53 and 63-phone phrases, with one emotion and with four emotions cycling per phone, both
searches' costs, whether the paths and costs are identical, and the fraction of pair costs the
pruned search computed. The dense DP needs the whole N x N float32 matrix (4 N^2 bytes: 2 GB
at 22,000 nodes), built from the per-node features on the device first. Prints JSON.

    python benchmarks/pruned_equals_dense.py --db out/scale/x4/db.h5
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

from facesynth.domain.search.pairs import transition_costs

HERE = Path(__file__).resolve().parent
EMOTIONS = ("neutral", "angry", "sad", "happy")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--db", type=Path, required=True, help="a motion database (db.h5)")
    ap.add_argument("--set", dest="overrides", action="append", default=[], help="a setting, e.g. synthesize.pnt=1e-6")
    args = ap.parse_args()
    sys.path.insert(0, str(HERE))
    from dp_table_v import PHRASES, phrase_phones

    from facesynth.base.config import Config
    from facesynth.base.opencl import use_opencl
    from facesynth.domain.search.costs import step_costs
    from facesynth.domain.search.dp import OpenCLDp, dp_numpy
    from facesynth.domain.search.pruned import dp_pruned
    from facesynth.model.motiondb import MotionDatabase

    s = Config.load(None, tuple(args.overrides)).settings("synthesize")
    db = MotionDatabase.read(args.db)
    opencl = use_opencl(s.use_opencl)
    tc = transition_costs(db, s, opencl)
    t0 = time.perf_counter()
    dense_tc = tc.panels() if opencl else tc.dense()
    report = {"db": str(args.db), "nodes": tc.n, "settings": args.overrides, "opencl": opencl,
              "dense_matrix_s": round(time.perf_counter() - t0, 1), "phrases": []}
    dense_dp = OpenCLDp(dense_tc).run if opencl else (lambda obs: dp_numpy(dense_tc, obs))
    for length in sorted(PHRASES):
        phones = phrase_phones(PHRASES[length], length)
        for emotions in (["neutral"] * length, [EMOTIONS[k % 4] for k in range(length)]):
            obs = step_costs(phones, emotions, db.nodes.phone, db.nodes.emotion, {}, s).total
            dense = dense_dp(obs)
            pruned, stats = dp_pruned(tc, obs)
            report["phrases"].append({
                "phones": length, "emotions": len(set(emotions)), "dense_cost": dense.cost, "pruned_cost": pruned.cost,
                "same_cost": dense.cost == pruned.cost, "same_path": dense.path.tolist() == pruned.path.tolist(),
                "pairs_fraction": float(f"{stats.fraction:.3g}")})
    report["all_identical"] = all(p["same_cost"] and p["same_path"] for p in report["phrases"])
    print(json.dumps(report, indent=1))


if __name__ == "__main__":
    main()
