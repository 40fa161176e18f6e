"""Does each cost weight matter? Prints JSON.

Every held-out sentence is synthesized with the configured weights and again with one weight
scaled (by 0, 0.1 and 10 by default; PNT, alpha1, alpha2 (DSC), alpha3 (PGap) and alpha6
(emotion) by default). Reported per weight and factor: the fraction of the sentences' spoken
phones whose node changed, the mean change of the DP's total cost relative to the configured
one, and the RMS marker error against the capture (mm), each over all sentences, with the
unscaled error beside it. A weight whose scaling changes no node is inert at this scale.

    python benchmarks/term_sensitivity.py --db out/db_clean.h5 --corpus out/corpus.h5 \\
        [--weights pnt,alpha2] [--factors 0,0.1,10] [--split test]
"""

from __future__ import annotations

import argparse
import dataclasses
import json
from pathlib import Path

import numpy as np

from facesynth.base.config import Config
from facesynth.base.phonemes import PAU
from facesynth.domain.evaluation.held_out import heldout
from facesynth.domain.search.pairs import transition_costs
from facesynth.domain.search.synthesis import synthesize
from facesynth.model.motiondb import MotionDatabase


def run(db: MotionDatabase, sentences, settings) -> tuple[list[np.ndarray], list[float], float]:
    """Paths, DP costs and the pooled RMS error (mm) against the capture of every sentence."""
    tc = transition_costs(db, settings, False)
    paths, costs, squared, frames = [], [], 0.0, 0
    for s in sentences:
        res = synthesize(db, s.utterance, {}, settings, tc=tc)
        paths.append(np.asarray(res.path))
        costs.append(float(res.cost))
        x = res.rendered.markers_capture.astype(np.float64)
        n = min(len(x), len(s.truth))
        err = np.nansum((x[:n] - s.truth[:n]) ** 2, axis=2)
        squared, frames = squared + float(np.nansum(err)), frames + int(np.isfinite(err).sum())
    return paths, costs, float(np.sqrt(squared / max(frames, 1)))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--db", type=Path, required=True)
    ap.add_argument("--corpus", type=Path, required=True)
    ap.add_argument("--weights", default="pnt,alpha1,alpha2,alpha3,alpha6")
    ap.add_argument("--factors", default="0,0.1,10")
    ap.add_argument("--split", default="test")
    args = ap.parse_args()
    config = Config.load()
    synth = dataclasses.replace(config.settings("synthesize"), use_opencl=False)
    db = MotionDatabase.read(args.db)
    sentences = heldout(args.corpus, db, args.split, config.settings("normalize"))
    spoken = [np.array([p != PAU for p in s.utterance.phones]) for s in sentences]
    base_paths, base_costs, base_rms = run(db, sentences, synth)
    out = {"db": str(args.db), "sentences": len(sentences), "phones": int(sum(m.sum() for m in spoken)),
           "rms_mm": round(base_rms, 4), "weights": {}}
    for name in args.weights.split(","):
        rows = []
        for factor in (float(f) for f in args.factors.split(",")):
            value = getattr(synth, name) * factor
            if name == "pnt" and value <= 0:
                value = getattr(synth, name) * 1e-6  # PNT > 0: the weakest allowed
            paths, costs, rms = run(db, sentences, dataclasses.replace(synth, **{name: value}))
            changed = sum(int((p != b)[m].sum()) for p, b, m in zip(paths, base_paths, spoken))
            rows.append({"factor": factor, "value": value, "nodes_changed": round(changed / out["phones"], 4),
                         "cost_change": round(float(np.mean([c / b - 1 for c, b in zip(costs, base_costs)])), 4),
                         "rms_mm": round(rms, 4)})
        out["weights"][name] = rows
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
