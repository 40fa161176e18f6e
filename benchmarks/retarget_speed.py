"""Speed of key-shape retargeting on the full built-in rig mesh (11,248 vertices, 22,288 triangles).

    .venv/bin/python benchmarks/retarget_speed.py --motion take.h5 --keyshapes keyshapes.h5 \
        [--seconds 10] [--repeat 3] > benchmarks/retarget_speed.json

The motion (a ``facesynth capture`` or ``synthesize`` output) is tiled to ``--seconds`` at its
frame rate. Prints JSON with wall time (``*_s``) and CPU time of this process (``*_cpu_s``,
``time.process_time``) of:

* ``one_time``: the keymorphs on the rig (fitted or read from the key-shapes) and their
  deformation-gradient blender (gradients, polar decompositions, the sparse factorization);
* per clip, after it: ``weights`` (NNLS in every emotion's key-shapes and the emotion blend),
  ``curves`` (the rig weights of Eq. 9), ``linear_mesh`` and ``gradient_mesh`` (the 11,248-vertex
  animation), their totals ``retarget_linear`` and ``retarget_gradient`` (weights + curves +
  mesh), and the direct solve of the same clip as the reference.

Per-clip parts are the fastest of ``--repeat`` runs (wall and CPU each). ``gradient_device`` says
where gradient blending ran (``[retarget] use_opencl``; ``FACESYNTH_OPENCL=off`` measures the
NumPy and SuperLU path). The machine's load
average is printed beside them: the wall times of a shared machine scale with it, the CPU times
much less.
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

from facesynth.base.config import Config
from facesynth.base.opencl import device_description
from facesynth.domain.retarget.gradients import GradientBlender
from facesynth.domain.retarget.solve import solve_motion
from facesynth.domain.rig.loading import builtin_rig
from facesynth.model.keyshapes import KeyShapes
from facesynth.model.motion import Motion
from facesynth.stages import retarget


class Clock:
    """Wall and CPU seconds of named parts; the fastest of repeated measurements is kept."""

    def __init__(self) -> None:
        self.wall: dict[str, float] = {}
        self.cpu: dict[str, float] = {}

    def run(self, name: str, fn):
        w0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        w, c = time.perf_counter() - w0, time.process_time() - c0
        self.wall[name] = min(self.wall.get(name, np.inf), w)
        self.cpu[name] = min(self.cpu.get(name, np.inf), c)
        return out

    def report(self) -> dict:
        out = {}
        for name in self.wall:
            out[f"{name}_s"] = round(self.wall[name], 4)
            out[f"{name}_cpu_s"] = round(self.cpu[name], 4)
        return out


def main(argv: list[str]) -> int:
    p = argparse.ArgumentParser()
    p.add_argument("--motion", type=Path, required=True)
    p.add_argument("--keyshapes", type=Path, required=True)
    p.add_argument("--seconds", type=float, default=10.0)
    p.add_argument("--repeat", type=int, default=3)
    args = p.parse_args(argv)
    config = Config.load()
    rset, kss = config.settings("retarget"), config.settings("keyshapes")
    motion = Motion.read(args.motion)
    n = int(round(args.seconds * motion.fps))
    reps = int(np.ceil(n / len(motion.markers)))
    clip = dataclasses.replace(motion, markers=np.concatenate([motion.markers] * reps)[:n])
    ks = KeyShapes.read(args.keyshapes)
    rig = builtin_rig()
    clock = Clock()
    load_before = list(os.getloadavg())

    def once():
        weights_k, meshes_k = retarget.keymorphs(ks, rig, None, kss.keymorph_ridge, str(args.keyshapes))
        return weights_k, GradientBlender(rig.neutral, rig.faces, meshes_k, rset.anchor, use_opencl=rset.use_opencl)

    weights_k, blender = clock.run("one_time", once)
    for _ in range(max(args.repeat, 1)):
        r = clock.run("weights", lambda: retarget.retarget(clip, ks, rset, None, str(args.motion)))
        clock.run("curves", lambda: np.clip(r.alpha @ weights_k, 0, 1))
        clock.run("linear_mesh", lambda: blender.linear(r.alpha))
        clock.run("gradient_mesh", lambda: blender.blend(r.alpha))
    _, _, iterations = clock.run("direct_solve", lambda: solve_motion(clip, rig, config.settings("solve"), str(args.motion)))
    out = {"frames": n, "fps": motion.fps, "vertices": len(rig.neutral), "triangles": len(rig.faces),
           "keyshapes": int(r.alpha.shape[1]), "keyshapes_used": int(r.alpha.any(0).sum()),
           "gradient_device": device_description(blender.use_opencl), **clock.report()}
    for path in ("linear", "gradient"):
        for unit, table in (("s", clock.wall), ("cpu_s", clock.cpu)):
            out[f"retarget_{path}_{unit}"] = round(table["weights"] + table["curves"] + table[f"{path}_mesh"], 4)
    out.update({"direct_solve_iterations": iterations, "repeat": args.repeat, "cpu_count": os.cpu_count(),
                "load_average_before": load_before, "load_average_after": list(os.getloadavg())})
    json.dump(out, sys.stdout, indent=1)
    print()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
