"""Speed and size of the compact key-shape trajectory method (Huang et al. §5.4: "less than a few
milliseconds" for 10 s of speech; goal here: under 5 ms). Prints JSON.

A 10-second utterance is made from the model's own phones (seeded draw, durations 60-160 ms, a
pause every 8 phones, neutral). Measured, median of ``--repeats`` runs each, wall and CPU
(``time.process_time``) time:

* ``solve``: Eq. 7 alone (the banded solve), on the model's capture-rate grid and on the paper's
  30 frames/s grid;
* ``synthesis``: the whole in-process synthesis of the motion (each frame's Gaussian, the solve,
  interpolation to the capture rate, back-projection to markers, down-sampling to 30 frames/s),
  as ``facesynth synthesize --method trajectory`` runs it between reading the model and writing;
* sizes: the model file against the database file, and the numbers the Gaussians take.

    python benchmarks/trajectory_speed.py --db db.h5 --model traj.h5 [--repeats 300]
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np

from facesynth.base.config import Config
from facesynth.domain.methods.trajectory import (
    duration_weights,
    effective_lambda,
    frame_targets,
    solve,
    synthesize_motion,
)
from facesynth.domain.speech.utterance import utterance
from facesynth.model.trajectory import TrajectoryModel


def ten_seconds(model: TrajectoryModel, seed: int = 0, seconds: float = 10.0):
    """A seeded utterance of about ``seconds`` s from the model's spoken phones."""
    rng = np.random.default_rng(seed)
    spoken = [p for p in model.phones if p != "pau"]
    phones, starts, ends, t = ["pau"], [0.0], [0.2], 0.2
    while t < seconds - 0.2:
        p = "pau" if len(phones) % 9 == 8 else spoken[int(rng.integers(len(spoken)))]
        d = float(rng.uniform(0.06, 0.16))
        phones.append(p)
        starts.append(t)
        ends.append(t + d)
        t += d
    phones.append("pau")
    starts.append(t)
    ends.append(seconds)
    return utterance(phones, starts, ends, ["neutral"] * len(phones))


def timed(fn, repeats: int) -> dict:
    """Median wall and CPU seconds of ``fn()`` over ``repeats`` runs (after one warm-up)."""
    fn()
    wall, cpu = [], []
    for _ in range(repeats):
        w0, c0 = time.perf_counter(), time.process_time()
        fn()
        cpu.append(time.process_time() - c0)
        wall.append(time.perf_counter() - w0)
    return {"median_ms": 1000 * float(np.median(wall)), "median_cpu_ms": 1000 * float(np.median(cpu)),
            "min_ms": 1000 * float(np.min(wall)), "repeats": repeats}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--db", type=Path, required=True, help="The database the model was trained on (for its size).")
    ap.add_argument("--model", type=Path, required=True, help="A trajectory model (facesynth train-trajectory).")
    ap.add_argument("--repeats", type=int, default=300)
    args = ap.parse_args()
    settings = Config.load().settings("trajectory")
    model = TrajectoryModel.read(args.model)
    utt = ten_seconds(model)
    out = {"utterance_s": float(utt.ends[-1]), "phones": len(utt), "keyshapes": model.count,
           "smoothness": settings.smoothness, "solve": {}}
    for fps in (model.fps, 30.0):
        targets = frame_targets(model, utt.phones, utt.emotions, utt.starts, utt.ends, fps)
        d = duration_weights(targets.ranges, len(targets.means))
        precisions = d[:, None] / targets.variances
        lam = effective_lambda(settings.smoothness, fps, settings.smoothness_fps)
        out["solve"][f"{fps:g}fps"] = {"frames": len(targets.means), "unknowns": int(targets.means.size),
                                       **timed(lambda: solve(targets.means, precisions, lam), args.repeats)}
    out["synthesis"] = {"solve_fps": settings.fps or model.fps, "output_fps": 30.0,
                        **timed(lambda: synthesize_motion(model, utt, settings, 30.0), args.repeats)}
    gaussians = 2 * (len(model.phones) + len(model.pair_phone)) * model.count
    out["size"] = {"model_bytes": args.model.stat().st_size, "db_bytes": args.db.stat().st_size,
                   "ratio": args.model.stat().st_size / args.db.stat().st_size,
                   "gaussian_numbers": gaussians, "phone_gaussian_numbers": 2 * len(model.phones) * model.count,
                   "keyshape_numbers": int(model.keyshapes.size)}
    print(json.dumps(out, indent=2))


if __name__ == "__main__":
    main()
