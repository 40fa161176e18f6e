"""Does a filmed face rest on the rig, and what does it cost the lips? For each video take: the
documented chain without ``bind`` (``ingest``, ``normalize``, ``solve``) under four settings of the
solve (the neutral face ``auto`` or ``off``, a face's priors on or off), and for each:

* ``rest``: the largest median weight of a mouth, jaw or brow channel over the 10% of frames with
  the smallest ``jawOpen`` (issue 51's check: <= 0.10);
* ``antagonists``: the mean over frames of min(left, right) over jawLeft/jawRight,
  mouthLeft/mouthRight and each side's smile/frown (<= 0.02);
* ``lip_r``: where the truth is known (the rendered actress), the solved rig's inner-lip gap
  against hers (the lips' round trip; >= 0.90).

With no ``--video``, the first ``--takes`` takes of the ``tiny`` sample corpus (seed 0) spoken
with ``--emotion`` (neutral: a speaker at rest between words, like the filmed speakers) are
rendered frontally at 25 frames/s by ``facesynth render``, each its own capture, and the truth's
own scores are given beside (a take spoken smiling rests smiling). Real filmed
faces: ``--video a.mp4 --video b.mov`` (frontal, with sound; no lip truth). Means over takes with
95% bootstrap intervals (takes resampled, 2000 draws, seed 0). Needs ``facesynth[video]``. Prints JSON.

    python benchmarks/video_rest.py [--takes 5] [--emotion neutral|happy|...|all] [--video FILE ...] [--work DIR]
"""

from __future__ import annotations

import argparse
import csv
import dataclasses
import json
import tempfile
from pathlib import Path

import numpy as np

from facesynth.base.config import Config
from facesynth.domain.corpus.generate import generate
from facesynth.domain.corpus.truth import read_truth
from facesynth.domain.postprocess.concatenation import downsample
from facesynth.domain.retarget import facial_solve
from facesynth.domain.rig.face import BUILTIN_RIG_NAME, builtin_rig_sha256, load_face_rig
from facesynth.domain.rig.loading import load_rig
from facesynth.domain.rig.markers import build_marker_set
from facesynth.model.curves import RigCurves
from facesynth.stages import ingest, normalize, render

FPS = 25.0
ANTAGONISTS = (("jawLeft", "jawRight"), ("mouthLeft", "mouthRight"), ("mouthSmile_L", "mouthFrown_L"),
               ("mouthSmile_R", "mouthFrown_R"))
VARIANTS = {"neutral+priors": ("auto", True), "neutral only": ("auto", False), "priors only": ("off", True),
            "neither": ("off", False)}


def scores(w: np.ndarray, names: list[str]) -> tuple[float, float]:
    """(rest, antagonists) of weights (T, E) on the built-in rig (see the module docstring)."""
    jaw = w[:, names.index("jawOpen")]
    rest = np.median(w[jaw <= np.quantile(jaw, 0.1)], axis=0)
    face = [i for i, n in enumerate(names) if n.startswith(("mouth", "jaw", "brow"))]
    both = np.mean([np.minimum(w[:, names.index(a)], w[:, names.index(b)]).mean() for a, b in ANTAGONISTS])
    return float(rest[face].max()), float(both)


def lip_gap(rig, weights: np.ndarray) -> np.ndarray:
    markers = build_marker_set(rig)
    lips = [markers.vertices[markers.names.index(m)] for m in ("ULI_C", "LLI_C")]
    p = rig.evaluate(weights.astype(np.float64), vertices=lips)
    return np.linalg.norm(p[:, 0] - p[:, 1], axis=1)


def interval(values: list[float]) -> dict[str, float]:
    x = np.asarray([v for v in values if np.isfinite(v)])
    if not len(x):
        return {}
    draws = np.random.default_rng(0).choice(x, (2000, len(x))).mean(1)
    return {"mean": float(x.mean()), "ci95": [float(np.percentile(draws, 2.5)), float(np.percentile(draws, 97.5))]}


def rendered_takes(work: Path, count: int, emotion: str, config: Config) -> list[tuple[Path, np.ndarray]]:
    """(video, truth weights at 25 frames/s) of the first ``count`` takes of the tiny corpus spoken
    with ``emotion`` ("all": any)."""
    rig = load_face_rig()
    corpus = work / "corpus"
    if not corpus.exists():
        generate(corpus, "tiny", seed=0)
    rows = [r for r in csv.DictReader(open(corpus / "manifest.csv")) if emotion in ("all", r["emotion"])][:count]
    out = []
    for row in rows:
        take = row["take"]
        truth = read_truth(corpus / "groundtruth" / f"{take}_truth.csv")
        rate = 1.0 / float(np.median(np.diff(truth.time_s)))
        w = downsample(truth.rig_weights.astype(np.float32), rate, FPS)
        video = work / f"{take}.avi"
        if not video.exists():
            RigCurves(w, FPS, list(rig.shape_names), BUILTIN_RIG_NAME, builtin_rig_sha256(), "truth").write(
                work / f"{take}_truth.h5", config="{}", inputs=[], overwrite=True)
            settings = dataclasses.replace(config.settings("render"), fps=FPS, yaw_deg=0.0, pitch_deg=0.0)
            render.run([work / f"{take}_truth.h5"], [corpus / "audio" / f"{take}.wav"], video, settings, overwrite=True)
        out.append((video, w))
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--takes", type=int, default=5)
    parser.add_argument("--emotion", default="neutral", help="the rendered takes' emotion, or 'all'")
    parser.add_argument("--video", type=Path, action="append", default=[])
    parser.add_argument("--work", type=Path, default=None)
    args = parser.parse_args()
    config = Config.load()
    rig = load_rig(None, None)
    names = list(rig.shape_names)
    with tempfile.TemporaryDirectory() as tmp:
        work = args.work or Path(tmp)
        work.mkdir(parents=True, exist_ok=True)
        takes = [(v, None) for v in args.video] or rendered_takes(work, args.takes, args.emotion, config)
        rows = []
        for k, (video, truth) in enumerate(takes):
            (work / f"m{k}.csv").write_text(f"take,mocap\nfilmed,{video.resolve()}\n")
            ingest.run(work / f"m{k}.csv", work / f"c{k}.h5", dataclasses.replace(config.settings("ingest"),
                       recognize_phones=False), config.settings("align"), overwrite=True)
            normalize.run(work / f"c{k}.h5", work / f"n{k}.h5", config.settings("normalize"), overwrite=True)
            row: dict = {"take": video.name}
            if truth is not None:  # the actress's own rest (a take spoken smiling rests smiling)
                rest, both = scores(truth.astype(np.float64), names)
                row["truth"] = {"rest": rest, "antagonists": both, "lip_r": 1.0}
            for label, (neutral, priors) in VARIANTS.items():
                s = dataclasses.replace(config.settings("solve"), output_fps=FPS, neutral=neutral)
                if not priors:
                    s = dataclasses.replace(s, sparsity=0.0, antagonist=0.0, symmetry=0.0)
                motion = facial_solve.read_motion(work / f"n{k}.h5", s)
                w = facial_solve.solve(motion, rig, s).curves.weights.astype(np.float64)
                rest, both = scores(w, names)
                lip = float("nan")
                if truth is not None:
                    n = min(len(w), len(truth))
                    lip = float(np.corrcoef(lip_gap(rig, w[:n]), lip_gap(rig, truth[:n]))[0, 1])
                row[label] = {"rest": rest, "antagonists": both, "lip_r": lip}
            rows.append(row)
    labels = [*VARIANTS, *(["truth"] if rows and "truth" in rows[0] else [])]
    summary = {label: {m: interval([r[label][m] for r in rows]) for m in ("rest", "antagonists", "lip_r")}
               for label in labels}
    print(json.dumps({"takes": rows, "summary": summary,
                      "source": "videos given" if args.video else f"{len(rows)} rendered takes of the tiny corpus"},
                     indent=1))


if __name__ == "__main__":
    main()
