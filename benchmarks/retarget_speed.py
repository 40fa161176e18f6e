"""Speed of key-shape retargeting on the full built-in rig mesh (11,248 vertices, 22,288 triangles).

    .venv/bin/python benchmarks/retarget_speed.py --motion take.h5 --keyshapes keyshapes.h5 [--seconds 10]

The motion (a ``facesynth capture`` or ``synthesize`` output) is tiled to ``--seconds`` at its
frame rate. Prints JSON: the one-time work (keymorph meshes' deformation gradients, polar
decompositions, the sparse factorization) and, after it, the whole retargeting of the clip
(NNLS in every emotion's key-shapes, the emotion blend, and the linear or deformation-gradient
mesh), plus the direct solve of the same clip; the machine's load average beside them, since
the timings scale with it.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import os
import sys
import time
from pathlib import Path

import numpy as np

from facesynth.config import Config
from facesynth.model.keyshapes import KeyShapes
from facesynth.model.motion import Motion
from facesynth.retarget.gradients import GradientBlender
from facesynth.retarget.rig import builtin_rig
from facesynth.stages import retarget, solve


def main(argv: list[str]) -> int:
    p = argparse.ArgumentParser()
    p.add_argument("--motion", type=Path, required=True)
    p.add_argument("--keyshapes", type=Path, required=True)
    p.add_argument("--seconds", type=float, default=10.0)
    args = p.parse_args(argv)
    config = Config.load()
    rset, kss = config.settings("retarget"), config.settings("keyshapes")
    motion = Motion.read(args.motion)
    n = int(round(args.seconds * motion.fps))
    reps = int(np.ceil(n / len(motion.markers)))
    clip = dataclasses.replace(motion, markers=np.concatenate([motion.markers] * reps)[:n])
    ks = KeyShapes.read(args.keyshapes)
    rig = builtin_rig()
    t0 = time.perf_counter()
    weights_k, meshes_k = retarget.keymorphs(ks, rig, None, kss.keymorph_ridge, str(args.keyshapes))
    blender = GradientBlender(rig.neutral, rig.faces, meshes_k, rset.anchor)
    once = time.perf_counter() - t0
    t0 = time.perf_counter()
    r = retarget.retarget(clip, ks, rset, None, str(args.motion))
    w = np.clip(r.alpha @ weights_k, 0, 1)
    t1 = time.perf_counter()
    blender.linear(r.alpha)
    t2 = time.perf_counter()
    blender.blend(r.alpha)
    t3 = time.perf_counter()
    _, _, iterations = solve.solve(clip, rig, config.settings("solve"), str(args.motion))
    t4 = time.perf_counter()
    json.dump({"frames": n, "fps": motion.fps, "vertices": len(rig.neutral), "triangles": len(rig.faces),
               "keyshapes": int(r.alpha.shape[1]), "one_time_s": once, "weights_s": t1 - t0,
               "linear_mesh_s": t2 - t1, "gradient_mesh_s": t3 - t2, "retarget_linear_total_s": t2 - t0,
               "retarget_gradient_total_s": t3 - t0, "direct_solve_s": t4 - t3, "direct_solve_iterations": iterations,
               "curves_shape": list(w.shape), "cpu_count": os.cpu_count(), "load_average": list(os.getloadavg())},
              sys.stdout, indent=1)
    print()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
