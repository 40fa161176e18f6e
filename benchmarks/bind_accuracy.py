"""How well ``facesynth bind`` places markers on the built-in rig, and how fast.

    .venv/bin/python benchmarks/bind_accuracy.py --preset tiny --seed 0 --takes 6 \
        [--capture Facial-Sing.c3d]

Generates the sample corpus, and for each of its first ``--takes`` takes moves the capture by a
random similarity (rotation, scale 0.8-1.25, a metre away) and binds it as a user's capture
would be (``facesynth.stages.bind``: typical frame, 48 starts, jaw sides). Its ``markers.csv``
gives every marker's true vertex. Prints JSON: per take the fitted frame, the distance (mm on
the rig) from each bound vertex to the true one (median, 95th percentile, largest), the bind
residual (median, 95th percentile, capture mm), markers flagged, whether the rigid markers found
include every true one, and seconds. With ``--capture``: the same summary for that file (no
truth): residuals, flagged markers, rigid markers and their spreads, seconds.
"""

from __future__ import annotations

import argparse
import csv
import json
import tempfile
import time
from pathlib import Path

import numpy as np
from scipy.spatial.transform import Rotation

from facesynth.base.config import Config
from facesynth.domain.corpus.generate import generate
from facesynth.domain.rig.face import load_face_rig
from facesynth.formats.mesh import read_binding, read_rigid_markers
from facesynth.formats.mocap import MarkerTake, read_mocap, write_c3d
from facesynth.stages import bind


def _summary(s: bind.BindResult, seconds: float) -> dict:
    return {"frame": s.frame, "residual_median_mm": round(s.residual_median_mm, 3),
            "residual_p95_mm": round(s.residual_p95_mm, 3), "flagged": s.flagged, "scale": round(s.scale, 4),
            "rigid": dict(zip(s.rigid, [round(x, 3) for x in s.rigid_spreads_mm])), "seconds": round(seconds, 2)}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--preset", default="tiny")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--takes", type=int, default=6)
    parser.add_argument("--capture", type=Path, default=None)
    args = parser.parse_args()
    config = Config.load()
    rig = load_face_rig()
    out: dict = {"preset": args.preset, "seed": args.seed, "takes": {}}
    with tempfile.TemporaryDirectory() as tmp:
        corpus = Path(tmp) / "corpus"
        generate(corpus, args.preset, args.seed)
        truth = read_binding(corpus / "markers.csv")
        true_rigid = set(read_rigid_markers(corpus / "markers.csv"))
        rows = list(csv.DictReader(open(corpus / "manifest.csv", encoding="utf-8")))[: args.takes]
        rng = np.random.default_rng(args.seed)
        for row in rows:
            take = read_mocap(corpus / row["mocap"])
            r = Rotation.random(random_state=rng.integers(1 << 31)).as_matrix()
            moved = rng.uniform(0.8, 1.25) * take.positions.astype(np.float64) @ r.T + [600.0, -900.0, 1200.0]
            path = Path(tmp) / f"{row['take']}.c3d"
            write_c3d(path, MarkerTake(moved.astype(np.float32), take.names, take.fps))
            started = time.perf_counter()
            s = bind.run(path, Path(tmp) / f"{row['take']}.csv", config.settings("bind"), config.settings("normalize"))
            seconds = time.perf_counter() - started
            bound = read_binding(Path(tmp) / f"{row['take']}.csv")
            error = np.array([np.linalg.norm(rig.neutral[v] - rig.neutral[truth[n]]) for n, v in bound.items()])
            entry = _summary(s, seconds)
            entry.update({"vertex_error_median_mm": round(float(np.median(error)), 3),
                          "vertex_error_p95_mm": round(float(np.percentile(error, 95)), 3),
                          "vertex_error_max_mm": round(float(error.max()), 3),
                          "on_true_vertex": round(float(np.mean(error == 0)), 3),
                          "true_rigid_found": true_rigid <= set(s.rigid)})
            out["takes"][row["take"]] = entry
        if args.capture is not None:
            started = time.perf_counter()
            s = bind.run(args.capture, Path(tmp) / "capture.csv", config.settings("bind"), config.settings("normalize"))
            out["capture"] = {"file": args.capture.name, **_summary(s, time.perf_counter() - started),
                              "residual_mm": {n: round(x, 2) for n, x in s.residual_mm.items()}}
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
