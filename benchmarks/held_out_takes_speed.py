"""Speed of ``fit-articulation``'s held-out takes: each take predicted by the model fitted on the
others, adapting the packaged model (the default, ``synthesize.articulation_prior = 3``). Prints JSON.

Measured on a capture's takes (the targets solved and the voice's features read once, as
``fit-articulation`` reads them), for the first 12, 36 and all of them, CPU seconds
(``time.process_time``, best of ``--repeats``) of:

* ``leaving_each_out``: :func:`facesynth.domain.voice.articulation.fit_leaving_each_out` (what
  ``fit-articulation`` runs: each take's context once, each fit from the sums of all the takes
  less its own);
* ``fit_per_take``: :func:`facesynth.domain.voice.articulation.fit` on the other takes, once per
  take (the release before), whose cost grows with the takes squared;

and the largest difference between the two paths' coefficients, relative to the largest
coefficient (they are the same fits to float rounding).

    facesynth sample-corpus corpus --preset small --seed 0
    facesynth ingest corpus/manifest.csv -o corpus.h5 && facesynth normalize corpus.h5 -o normalized.h5
    python benchmarks/held_out_takes_speed.py --corpus corpus.h5 --normalized normalized.h5
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np

from facesynth.base.config import Config
from facesynth.domain.rig.loading import load_rig
from facesynth.domain.voice import articulation
from facesynth.domain.voice.fitting import FIT_FPS, performer_takes
from facesynth.domain.voice.fusion import articulation_model
from facesynth.model.corpus import Corpus
from facesynth.model.frames import NormalizedFrames


def best_cpu_s(fn, repeats: int):
    """(the best CPU seconds of ``repeats`` calls of ``fn``, its last result)."""
    best, out = float("inf"), None
    for _ in range(repeats):
        start = time.process_time()
        out = fn()
        best = min(best, time.process_time() - start)
    return best, out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--corpus", type=Path, required=True, help="an ingested capture with audio (corpus.h5)")
    parser.add_argument("--normalized", type=Path, required=True, help="its normalized frames (normalized.h5)")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    config = Config.load()
    synth = config.settings("synthesize")
    data = performer_takes(Corpus.read(args.corpus), NormalizedFrames.read(args.normalized),
                           load_rig(None, None, need_binding=False), config.settings("solve"),
                           tuple(synth.loudness_lip_markers))
    prior, strength = articulation_model(synth.articulation_model), synth.articulation_prior
    rows = []
    for count in sorted({min(12, len(data.takes)), min(36, len(data.takes)), len(data.takes)}):
        takes = data.takes[:count]
        fast_s, fast = best_cpu_s(lambda: articulation.fit_leaving_each_out(
            takes, data.names, prior=prior, prior_strength=strength), args.repeats)
        slow_s, slow = best_cpu_s(lambda: [articulation.fit(
            takes[:i] + takes[i + 1:], data.names, prior=prior, prior_strength=strength)
            for i in range(len(takes))], args.repeats)
        diff = max(float(np.abs(a.coef - b.coef).max() / np.abs(b.coef).max()) for a, b in zip(fast, slow))
        rows.append({"takes": count, "seconds": round(sum(len(t.targets) for t in takes) / FIT_FPS, 1),
                     "leaving_each_out_cpu_s": round(fast_s, 3), "fit_per_take_cpu_s": round(slow_s, 3),
                     "ratio": round(slow_s / fast_s, 1), "largest_relative_coefficient_difference": diff})
    print(json.dumps({"prior_strength": strength, "runs": rows}, indent=2))


if __name__ == "__main__":
    main()
