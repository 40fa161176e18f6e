"""Make ``facesynth/data/face_mesh_builtin.csv``: where MediaPipe Face Mesh's 478 landmarks lie on
the built-in rig, so that ``solve`` of a filmed take needs no ``bind`` on the built-in rig.

The rig is filmed by facesynth itself: the virtual actress's held-out take of the ``tiny`` sample
corpus (seed 0), her truth's rig weights and head motion, rendered frontally at 25 frames/s by
``facesynth render``; the video is bound by ``facesynth bind VIDEO --rig builtin --up +y
--forward +z`` (the rendered picture's axes are the rig's), exactly what a user runs for a rig of
their own. Every step is deterministic, so the file is the same on every run (MediaPipe on CPU).

Run from the repository root, with the ``video`` extra installed::

    python scripts/face_mesh_binding.py facesynth/data/face_mesh_builtin.csv
"""

from __future__ import annotations

import csv
import sys
import tempfile
from pathlib import Path

import numpy as np
from click.testing import CliRunner

from facesynth.cli import main
from facesynth.domain.corpus.generate import generate
from facesynth.domain.corpus.truth import read_truth
from facesynth.domain.postprocess.concatenation import downsample
from facesynth.domain.rig.face import BUILTIN_RIG_NAME, builtin_rig_sha256, load_face_rig
from facesynth.model.curves import RigCurves

FPS = 25.0


def _run(*args: object) -> None:
    result = CliRunner().invoke(main, [*map(str, args), "-q"])
    if result.exit_code != 0:
        raise SystemExit(result.output)


def make(out: Path) -> None:
    """Render the actress's held-out take, bind the video to the built-in rig, write ``out``."""
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        generate(d / "corpus", "tiny", seed=0)
        corpus = d / "corpus"
        take = next(r["take"] for r in csv.DictReader(open(corpus / "manifest.csv")) if r["split"] == "test")
        truth = read_truth(corpus / "groundtruth" / f"{take}_truth.csv")
        rate = 1.0 / float(np.median(np.diff(truth.time_s)))
        head = np.array([[float(v) for v in r] for r in list(csv.reader(open(corpus / "groundtruth" / f"{take}_head.csv")))[1:]])
        rig = load_face_rig()
        RigCurves(downsample(truth.rig_weights.astype(np.float32), rate, FPS), FPS, list(rig.shape_names),
                  BUILTIN_RIG_NAME, builtin_rig_sha256(), "truth",
                  downsample(head[:, :9].reshape(-1, 3, 3).astype(np.float32), rate, FPS),
                  downsample(head[:, 9:].astype(np.float32), rate, FPS)).write(d / "truth.h5", config="{}", inputs=[])
        _run("render", d / "truth.h5", "--audio", corpus / "audio" / f"{take}.wav", "-o", d / "take.avi",
             "--set", "render.fps=25", "--set", "render.yaw_deg=0", "--set", "render.pitch_deg=0")
        _run("bind", d / "take.avi", "--rig", "builtin", "--up", "+y", "--forward", "+z", "-o", d / "binding.csv",
             "--overwrite")
        out.write_bytes((d / "binding.csv").read_bytes())


if __name__ == "__main__":
    if len(sys.argv) != 2:
        raise SystemExit("usage: python scripts/face_mesh_binding.py facesynth/data/face_mesh_builtin.csv")
    make(Path(sys.argv[1]))
