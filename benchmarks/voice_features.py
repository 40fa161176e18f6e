"""Which voice features carry the speaker least: runs of ``benchmarks/voice_speakers.py --no-chain``
with different ``--features`` (the voice model's own predicted opening of every held-out speaker,
``voice``), each against the run of the features that ship (``mel``) with the same folds, paired
by speaker. Prints JSON.

For every run: its folds (``source``: one whole source left out at a time; ``speaker``: one
speaker), its features (and ``--warp-per`` for the vocal-tract warp), the mean r over speakers
with its 95% interval, and the paired difference from the ``mel`` run of the same folds (the mean
over the speakers both scored, 95% bootstrap interval resampling speakers: 2000 resamples, seed 0),
with the mean difference per source, and every speaker's r; for a warped run, the mean warp of the women's and of the
men's voices (from ``--speech-data``'s ``speakers.json``; FACEGOOD's performer is a woman).

    python benchmarks/voice_features.py --speakers SPEECH_DIR/speakers.json RUN.json ... > benchmarks/voice_features.json
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

from facesynth.domain.evaluation.bootstrap import paired_difference, resamples


def rounded(d: dict) -> dict:
    return {k: round(float(v), 4) for k, v in d.items()}


def compare(runs: list[dict], sexes: dict[str, str], count: int = 2000, seed: int = 0) -> list[dict]:
    """Per run (the outputs of voice_speakers.py), its score and its paired difference from the mel run of its folds."""
    base = {r["folds"]: r for r in runs if r.get("features", "mel") == "mel"}
    out = []
    for run in runs:
        entry = {"folds": run["folds"], "features": run.get("features", "mel"), "warp_per": run.get("warp_per"),
                 "speakers": run["speakers"], "voice": run["r"]["voice"]}
        ref = base.get(run["folds"])
        if ref is not None and ref is not run:
            names = sorted(set(ref["per_speaker"]) & set(run["per_speaker"]))
            a = np.array([ref["per_speaker"][s]["voice"] for s in names])
            b = np.array([run["per_speaker"][s]["voice"] for s in names])
            idx = resamples(len(names), count, seed)
            entry["minus_mel"] = rounded(paired_difference(lambda i: float(np.mean(b[i])),
                                                           lambda i: float(np.mean(a[i])), len(names), idx))
            by_source: dict[str, list[float]] = {}
            for s, x, y in zip(names, a, b):
                by_source.setdefault(s.split("/")[0], []).append(float(y - x))
            entry["minus_mel_per_source"] = {k: round(float(np.mean(v)), 4) for k, v in sorted(by_source.items())}
        if run.get("warps"):
            w = run["warps"]
            entry["mean_warp"] = {sex: round(float(np.mean([w[s][0] for s in w if sexes.get(s) == sex])), 3)
                                  for sex in ("F", "M") if any(sexes.get(s) == sex for s in w)}
        entry["per_speaker"] = {s: v["voice"] for s, v in sorted(run["per_speaker"].items())}
        out.append(entry)
    return out


def main(argv=None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("runs", nargs="+", type=Path, help="outputs of voice_speakers.py --no-chain")
    ap.add_argument("--speakers", type=Path, default=None, help="speakers.json of --speech-data (for the sexes)")
    args = ap.parse_args(argv)
    runs = [json.loads(p.read_text()) for p in args.runs]
    sexes = {"facegood/shirley": "F"}
    if args.speakers:
        sexes.update({f"{x['source']}/{x['speaker']}": x["sex"] for x in json.loads(args.speakers.read_text())})
    return {"benchmark": "voice_features", "runs": compare(runs, sexes)}


if __name__ == "__main__":
    json.dump(main(), sys.stdout, indent=2)
    print()
