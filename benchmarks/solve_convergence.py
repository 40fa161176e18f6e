"""The direct facial solve's convergence: how close the default settings come to the solve's own
minimum, how close to the truth, and in how long, on the virtual actress's held-out takes.

    .venv/bin/python benchmarks/solve_convergence.py --corpus out/corpus --corpus-h5 out/corpus.h5 \
        --db out/db.h5 [--takes 0] > benchmarks/solve_convergence.json

For each held-out (``test``) take, captured through ``facesynth capture``'s core at 30 frames/s,
and the same sentence synthesized by the DP search, the solve runs twice with the ``[solve]``
settings: as configured (``default``: its iterations, tolerance and time), and to its minimum
(``minimum``: tolerance 1e-10, up to 200,000 iterations). Per take it prints:

* ``iterations`` and ``seconds`` of the default solve (one BLAS thread, as the command runs it);
* ``to_minimum``: the largest and the RMS difference of the default solve's rig weights from the
  minimum's (weight units): what stopping early leaves;
* ``arkit_rms``: the RMS error of the 52 ARKit weights against the truth
  (``groundtruth/<take>_truth.csv``) of the default solve and of the minimum (captured takes only).

Pooled: means over takes with their bootstrap 95% interval, and paired differences on the same
resamples (:mod:`facesynth.domain.evaluation.bootstrap`).

To compare another version of the solve (a worktree of another commit, the same corpus), run this
file there with ``--save DIR --no-minimum`` (its default solves' weights, one ``.npy`` per take
and motion), then here with ``--against DIR``: each row gains ``against``, the saved weights'
distance to this version's minimum and their ARKit error, and the pooled figures gain the paired
differences (``against`` minus ``default``).
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from facesynth.base.config import Config
from facesynth.domain.corpus.truth import read_truth
from facesynth.domain.evaluation.bootstrap import interval, paired_difference, resamples
from facesynth.domain.postprocess.concatenation import downsample
from facesynth.domain.retarget.solve import FacePriors, solve_curves
from facesynth.domain.rig.loading import builtin_rig, marker_map
from facesynth.model.motion import Motion
from facesynth.model.motiondb import MotionDatabase
from facesynth.stages import capture, synthesize


def mean_of(values):
    """The statistic (take indices -> float) of the mean of one value per take."""
    v = np.asarray(values, np.float64)
    return lambda i: float(v[i].mean())


def solve(motion: Motion, rig, settings, *, tolerance: float, iterations: int) -> tuple[np.ndarray, int, float]:
    """(T, E) rig weights, the iterations and the seconds of the solve of ``motion`` on ``rig``."""
    mmap = marker_map(rig, motion.marker_names, motion.reference, "the motion")
    disp = mmap.displacements(motion.markers, motion.reference)
    basis = rig.deltas[:, mmap.vertices]
    start = time.perf_counter()
    w, _, its = solve_curves(disp, basis, smooth=settings.smooth, ridge=settings.ridge, iterations=iterations,
                             tolerance=tolerance, priors=FacePriors.of_rig(rig.shape_names, settings))
    return w, its, time.perf_counter() - start


def main(argv: list[str]) -> int:
    p = argparse.ArgumentParser()
    p.add_argument("--corpus", type=Path, required=True, help="the sample corpus folder (its groundtruth/)")
    p.add_argument("--corpus-h5", type=Path, required=True, help="its ingested corpus artifact")
    p.add_argument("--db", type=Path, required=True, help="the database built from it")
    p.add_argument("--takes", type=int, default=0, help="held-out takes to use (0: every one)")
    p.add_argument("--save", type=Path, help="write each default solve's weights here (.npy per take and motion)")
    p.add_argument("--against", type=Path, help="weights another version saved with --save, scored beside")
    p.add_argument("--no-minimum", action="store_true", help="skip the solve to the minimum (with --save)")
    args = p.parse_args(argv)
    if args.save:
        args.save.mkdir(parents=True, exist_ok=True)
    config = Config.load()
    settings = config.settings("solve")
    rig = builtin_rig()
    db = MotionDatabase.read(args.db)
    tests = [n for n, s in zip(db.takes.name, db.takes.split) if s == "test"][: args.takes or None]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for take in tests:
            cap, syn = Path(tmp) / f"{take}.h5", Path(tmp) / f"{take}_syn.h5"
            capture.run(args.db, args.corpus_h5, take, cap, config.settings("normalize"), 30.0)
            synthesize.run(args.db, syn, config.settings("synthesize"), config.settings("ingest"),
                           config.settings("align"), phones_path=args.corpus / "labels" / f"{take}.TextGrid")
            truth = read_truth(args.corpus / "groundtruth" / f"{take}_truth.csv")
            for kind, path in (("captured", cap), ("synthesized", syn)):
                motion = Motion.read(path)
                w, its, seconds = solve(motion, rig, settings, tolerance=settings.tolerance,
                                        iterations=settings.iterations)
                row = {"take": take, "motion": kind, "frames": int(len(w)), "iterations": int(its), "seconds": seconds}
                if args.save:
                    np.save(args.save / f"{take}_{kind}.npy", w)
                print(f"{take} {kind}: {its} iterations, {seconds:.2f} s", file=sys.stderr, flush=True)
                rows.append(row)
                if args.no_minimum:
                    continue
                w_min, its_min, _ = solve(motion, rig, settings, tolerance=1e-10, iterations=200_000)
                solves = {"default": w, "minimum": w_min}
                if args.against:
                    solves["against"] = np.load(args.against / f"{take}_{kind}.npy")
                row["iterations_to_minimum"] = int(its_min)
                for name in ("default", "against"):
                    if name in solves:
                        x = solves[name]
                        row["to_minimum" if name == "default" else "against"] = {
                            "max": float(np.abs(x - w_min).max()), "rms": float(np.sqrt(((x - w_min) ** 2).mean()))}
                if kind == "captured":
                    tw = downsample(truth.rig_weights, db.fps, motion.fps)
                    n = min(len(tw), len(w))
                    t = rig.to_arkit(tw[:n])
                    row["arkit_rms"] = {name: float(np.sqrt(((rig.to_arkit(x[:n]) - t) ** 2).mean()))
                                        for name, x in solves.items()}
    pooled = {}
    for kind in ("captured", "synthesized"):
        mine = [r for r in rows if r["motion"] == kind]
        index = resamples(len(mine), 2000, 0)

        def over_takes(get) -> dict:
            return interval(mean_of([get(r) for r in mine]), len(mine), index)

        pooled[kind] = {"iterations": over_takes(lambda r: r["iterations"]),
                        "seconds": over_takes(lambda r: r["seconds"])}
        if args.no_minimum:
            continue
        for key in ("to_minimum", "against"):
            if key in mine[0]:
                for stat in ("max", "rms"):
                    pooled[kind][f"{key}_{stat}"] = over_takes(lambda r, key=key, stat=stat: r[key][stat])
        if "against" in mine[0]:
            pooled[kind]["against_minus_default_max"] = paired_difference(
                mean_of([r["against"]["max"] for r in mine]), mean_of([r["to_minimum"]["max"] for r in mine]),
                len(mine), index)
        if kind == "captured":
            for name in mine[0]["arkit_rms"]:
                pooled[kind][f"arkit_rms_{name}"] = over_takes(lambda r, name=name: r["arkit_rms"][name])
            if "against" in mine[0]["arkit_rms"]:
                pooled[kind]["arkit_rms_against_minus_default"] = paired_difference(
                    mean_of([r["arkit_rms"]["against"] for r in mine]),
                    mean_of([r["arkit_rms"]["default"] for r in mine]), len(mine), index)
    json.dump({"settings": {"iterations": settings.iterations, "tolerance": settings.tolerance,
                            "smooth": settings.smooth, "ridge": settings.ridge},
               "takes": rows, "pooled": pooled}, sys.stdout, indent=1)
    print()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
