"""The virtual actress against a real capture, and the truth-level checks of the corpus.

    .venv/bin/python benchmarks/actress_statistics.py --preset small --seed 0 \
        [--capture ../shared/assets/ict-face/llf_capture.csv] [--corpus out/corpus]

Generates the sample corpus (or reads ``--corpus``), reads the truth of every take
(``groundtruth/<take>_truth.csv``) and prints JSON with:

* ``shapes``: per ARKit shape, the corpus's and the capture's 5th/95th percentiles and mean
  absolute velocity (weight/s), both at 60 frames/s (the corpus is resampled from 120 Hz);
* ``mouth_correlation``: the Pearson correlation matrices of the main mouth shapes, both;
* ``blinks``: blinks per minute (left eyelid above half closure) and their durations (s);
* ``lip_closure``: the lip gap on the mesh (mm) at the centre of every /p b m/: fraction
  under 1 mm, median, 95th percentile and largest;
* ``emotion_changes``: the fraction of takes whose emotion changes inside the sentence.
"""

from __future__ import annotations

import argparse
import csv
import dataclasses
import json
import sys
import tempfile
from pathlib import Path

import numpy as np

from facesynth.domain.corpus.generate import generate
from facesynth.domain.corpus.statistics import (
    bilabial_gaps,
    blink_events,
    curve_statistics,
    read_live_link_face,
    resample,
)
from facesynth.domain.corpus.truth import read_truth
from facesynth.domain.rig.face import load_face_rig
from facesynth.domain.rig.markers import build_marker_set
from facesynth.formats.labels import read_textgrid

DEFAULT_CAPTURE = Path(__file__).resolve().parents[2] / "shared" / "assets" / "ict-face" / "llf_capture.csv"


def corpus_statistics(corpus: Path) -> dict:
    """Everything above but the capture's side, for the corpus in ``corpus``."""
    rig = load_face_rig()
    markers = build_marker_set(rig)
    takes = list(csv.DictReader(open(corpus / "manifest.csv")))
    curves, gaps, blink_lengths = [], [], []
    blinks, seconds, changed = 0, 0.0, 0
    for r in takes:
        truth = read_truth(corpus / "groundtruth" / f"{r['take']}_truth.csv")
        tiers = read_textgrid(corpus / r["alignment"])
        curves.append(resample(truth.arkit_weights, 120.0, 60.0))
        phones = [(s.start, s.end, s.label) for s in tiers["phones"]]
        gaps += bilabial_gaps(rig, truth.rig_weights, phones, markers.lip_upper, markers.lip_lower, 120.0)
        events = blink_events(truth.rig_weights[:, rig.shape_index("eyeBlink_L")], 120.0)
        blinks += len(events)
        blink_lengths += [e[1] for e in events]
        seconds += len(truth.time_s) / 120.0
        changed += len(tiers["emotion"]) > 1
    gaps = np.array(gaps)
    return {
        "curves": dataclasses.asdict(curve_statistics(curves, list(rig.arkit_names), 60.0)),
        "blinks": {"per_minute": 60.0 * blinks / seconds, "count": blinks, "seconds": seconds,
                   "above_half_closure_s": {"median": float(np.median(blink_lengths)) if blink_lengths else None,
                                            "p90": float(np.percentile(blink_lengths, 90)) if blink_lengths else None}},
        "lip_closure": {"bilabials": len(gaps), "fraction_under_1mm": float((gaps < 1.0).mean()),
                        "median_mm": float(np.median(gaps)), "p95_mm": float(np.percentile(gaps, 95)), "max_mm": float(gaps.max())},
        "emotion_changes": {"takes": len(takes), "changed": changed, "fraction": changed / len(takes)},
    }


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--preset", default="small")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--corpus", type=Path, help="an existing sample corpus (else one is generated)")
    parser.add_argument("--capture", type=Path, default=DEFAULT_CAPTURE, help="a Live Link Face CSV")
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        corpus = args.corpus
        if corpus is None:
            corpus = Path(tmp) / "corpus"
            generate(corpus, args.preset, args.seed)
        ours = corpus_statistics(corpus)
    out = {"preset": args.preset, "seed": args.seed, **ours}
    if args.capture.exists():
        names, weights = read_live_link_face(args.capture)
        real = dataclasses.asdict(curve_statistics([weights], names, 60.0))
        out["capture"] = {"path": args.capture.name, "frames": len(weights), "curves": real}
        out["side_by_side"] = {
            name: {"corpus_p5_p95": [round(v["p5"], 3), round(v["p95"], 3)],
                   "capture_p5_p95": [round(real["shapes"][name]["p5"], 3), round(real["shapes"][name]["p95"], 3)],
                   "corpus_mean_abs_velocity": round(v["mean_abs_velocity"], 3),
                   "capture_mean_abs_velocity": round(real["shapes"][name]["mean_abs_velocity"], 3)}
            for name, v in ours["curves"]["shapes"].items()}
    json.dump(out, sys.stdout, indent=1)
    print()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
