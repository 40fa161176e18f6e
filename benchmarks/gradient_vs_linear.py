"""Where deformation-gradient and linear blending differ on the built-in rig: a wide jaw opening
mixed with a pucker (issue 17, item 5).

    .venv/bin/python benchmarks/gradient_vs_linear.py > benchmarks/gradient_vs_linear.json

Examples: the rig at jawOpen = 1 and at mouthPucker = 1. For blend weights (a, b) it prints the
largest and mean vertex distance (mm) between the two blends over the vertices that move, and
the chin-to-nose-tip distance of each (the jaw's swing: a linear blend pulls a rotating chin
along the chord, toward the face).
"""

from __future__ import annotations

import json
import sys

import numpy as np

from facesynth.domain.retarget.gradients import GradientBlender
from facesynth.domain.rig.face import load_face_rig
from facesynth.domain.rig.markers import build_marker_set


def main() -> int:
    rig = load_face_rig()
    names = ["jawOpen", "mouthPucker"]
    w = np.zeros((2, len(rig.shape_names)))
    for k, n in enumerate(names):
        w[k, rig.shape_index(n)] = 1.0
    examples = rig.evaluate(w)
    blender = GradientBlender(rig.neutral, rig.faces, examples)
    ms = build_marker_set(rig)
    chin, nose = (ms.vertices[ms.names.index(m)] for m in ("CHIN_C", "NOSE_TIP"))
    rows = []
    for a, b in ((0.5, 0.0), (1.0, 1.0), (0.5, 0.5), (0.7, 1.0)):
        alpha = np.array([[a, b]])
        lin, grad = blender.linear(alpha)[0], blender.blend(alpha)[0]
        moving = np.linalg.norm(lin - rig.neutral, axis=1) > 0.1
        d = np.linalg.norm(lin - grad, axis=1)
        row = {"jawOpen": a, "mouthPucker": b, "max_mm": float(d.max()), "mean_moving_mm": float(d[moving].mean())}
        row["chin_to_nose_linear_mm"] = float(np.linalg.norm(lin[chin] - lin[nose]))
        row["chin_to_nose_gradient_mm"] = float(np.linalg.norm(grad[chin] - grad[nose]))
        rows.append(row)
    json.dump({"examples": names, "rows": rows}, sys.stdout, indent=1)
    print()
    return 0


if __name__ == "__main__":
    sys.exit(main())
