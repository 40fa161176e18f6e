"""Retargeting onto the built-in rig, scored on the virtual actress (issue 17).

    .venv/bin/python benchmarks/retarget_accuracy.py --corpus out/corpus --corpus-h5 out/corpus.h5 \
        --db out/db.h5 [--corpus ... --corpus-h5 ... --db ... (more corpora)] [--takes 0] \
        [--counts 7,14,20,30] [--set solve.sparsity=0 ...] > benchmarks/retarget_accuracy.json

Several corpora (e.g. sample corpora of other seeds) pool their held-out takes; key-shapes and
keymorphs of each come from its own database. Runs about 7 minutes per small-preset corpus on
a busy two-core machine.

For held-out (``test``) takes, captured through ``facesynth capture``'s core at 30 frames/s,
against the truth (``groundtruth/<take>_truth.csv``, down-sampled alike; truth mesh =
rig.evaluate(truth rig weights)):

* ``weights``: RMS error of the 52 ARKit weights and mean per-shape Pearson correlation (over
  the shapes that move in the take) of the direct solve and of linear key-shape retargeting;
* ``mesh_mm``: mean full-mesh vertex error (11,248 vertices, mm) of Gaussian ``deform`` (Eq.
  14-15 on the rig's neutral mesh), the direct solve, linear key-shape retargeting and
  deformation-gradient retargeting;
* lip closure: ``*_gap`` the mean lip gap (mm) on the final mesh at the centre of every /p b m/
  (truth beside it), ``*_closed`` the fraction of them under 1 mm;
* rows for both selection methods and key-shape counts; every number with a bootstrap 95%
  confidence interval over takes (``--takes 0``: every test take of each corpus), and paired
  differences per take (``diff_*``: the first method minus the second, so intervals that
  exclude 0 say which is better on these takes).

``synthesized``: the same held-out sentences synthesized by the DP search (no truth there):
marker residual of the solve and of the key-shape fit, lip closure on /p b m/ for each
method, and the RMS difference between the solve's and retargeting's ARKit weights.

Speed is measured by ``benchmarks/retarget_speed.py``.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from facesynth.base.config import Config
from facesynth.domain.corpus.truth import read_truth
from facesynth.domain.postprocess.concatenation import downsample
from facesynth.domain.retarget import deform
from facesynth.domain.retarget.gradients import GradientBlender
from facesynth.domain.retarget.solve import solve_motion
from facesynth.domain.rig.face import load_face_rig
from facesynth.domain.rig.markers import build_marker_set
from facesynth.formats.mesh import read_binding, read_mesh
from facesynth.model.corpus import Corpus
from facesynth.model.motion import Motion
from facesynth.model.motiondb import MotionDatabase
from facesynth.stages import capture, keyshapes, retarget, synthesize

BILABIALS = ("p", "b", "m")


def boot(values, seed: int = 0, n: int = 2000) -> dict:
    """Mean over takes and its bootstrap 95% interval; takes without a value (NaN: e.g. no /p b m/
    in the sentence) are left out, and ``n`` says how many counted."""
    v = np.asarray(values, float)
    v = v[np.isfinite(v)]
    rng = np.random.default_rng(seed)
    means = v[rng.integers(0, len(v), (n, len(v)))].mean(1)
    return {"mean": float(v.mean()), "ci95": [float(np.percentile(means, 2.5)), float(np.percentile(means, 97.5))],
            "n": int(len(v))}


def lip_gap(vertices: np.ndarray, upper: np.ndarray, lower: np.ndarray) -> np.ndarray:
    """(T,) smallest distance (mm) between the upper and lower central lip surfaces."""
    a, b = vertices[:, upper], vertices[:, lower]
    return np.sqrt(((a[:, :, None] - b[:, None]) ** 2).sum(-1)).min(axis=(1, 2))


def mean_gap(vertices: np.ndarray, ms) -> float:
    """Mean lip gap (mm) over the frames given; NaN for none (a sentence without /p b m/)."""
    return float(lip_gap(vertices, ms.lip_upper, ms.lip_lower).mean()) if len(vertices) else float("nan")


def bilabial_frames(corpus: Corpus, take: str, fps: float, n: int) -> np.ndarray:
    i = corpus.takes.name.index(take)
    rows = np.flatnonzero(corpus.phones.take == i)
    centres = [(corpus.phones.start[r] + corpus.phones.end[r]) / 2 for r in rows if corpus.phones.phone[r] in BILABIALS]
    return np.array([f for f in (int(round(c * fps)) for c in centres) if f < n], int)


def closed(vertices: np.ndarray, ms) -> float:
    """Fraction of frames whose lips are closer than 1 mm."""
    return float((lip_gap(vertices, ms.lip_upper, ms.lip_lower) < 1.0).mean()) if len(vertices) else float("nan")


def weight_scores(rig, est: np.ndarray, truth: np.ndarray) -> tuple[float, float]:
    a, t = rig.to_arkit(est), rig.to_arkit(truth)
    rms = float(np.sqrt(((a - t) ** 2).mean()))
    moving = [j for j in range(a.shape[1]) if t[:, j].std() > 1e-3 and a[:, j].std() > 1e-9]
    corr = float(np.mean([np.corrcoef(a[:, j], t[:, j])[0, 1] for j in moving])) if moving else float("nan")
    return rms, corr


def load_takes(label: str, corpus_dir: Path, corpus_h5: Path, db_path: Path, limit: int, config, tmp: Path,
               fps: float) -> dict:
    """Held-out takes of one corpus, captured at ``fps``, with their truth, Gaussian deform and
    DP synthesis; keyed ``<label>/<take>``."""
    corpus = Corpus.read(corpus_h5, audio=False)
    db = MotionDatabase.read(db_path)
    tests = [n for n, s in zip(db.takes.name, db.takes.split) if s == "test"][: limit or None]
    mesh_v, mesh_f = read_mesh(corpus_dir / "face.obj")
    binding = read_binding(corpus_dir / "markers.csv")
    dset = config.settings("deform")
    bound = None
    takes = {}
    for take in tests:
        key = f"{label}/{take}"
        cap = tmp / f"{label}_{take}.h5"
        capture.run(db_path, corpus_h5, take, cap, config.settings("normalize"), fps)
        motion = Motion.read(cap)
        truth = read_truth(corpus_dir / "groundtruth" / f"{take}_truth.csv")
        tw = downsample(truth.rig_weights, db.fps, fps)
        n = min(len(tw), len(motion.markers))
        if bound is None:
            bound = deform.bind(mesh_v, mesh_f, binding, motion.marker_names, dset, "face.obj", "markers.csv")
        gauss, _ = deform.animate(bound, motion.markers[:n], motion.marker_names, motion.reference, None)
        syn = tmp / f"{label}_{take}_syn.h5"
        synthesize.run(db_path, syn, config.settings("synthesize"), config.settings("ingest"), config.settings("align"),
                       phones_path=corpus_dir / "labels" / f"{take}.TextGrid")
        takes[key] = {"take": take, "db": db, "db_path": db_path, "motion": motion, "truth": tw[:n], "n": n,
                      "gauss": gauss, "bilabial": bilabial_frames(corpus, take, fps, n), "synth": Motion.read(syn),
                      "corpus": corpus}
        print(f"captured {key}", file=sys.stderr, flush=True)
    return takes


def main(argv: list[str]) -> int:
    p = argparse.ArgumentParser()
    p.add_argument("--corpus", type=Path, action="append", required=True, help="corpus folder (repeatable)")
    p.add_argument("--corpus-h5", type=Path, action="append", required=True, help="its ingested corpus.h5")
    p.add_argument("--db", type=Path, action="append", required=True, help="its motion database")
    p.add_argument("--takes", type=int, default=0, help="held-out takes per corpus to score (0: all)")
    p.add_argument("--counts", default="7,14,20,30")
    p.add_argument("--methods", default="pca,affinity")
    p.add_argument("--set", action="append", default=[], metavar="SECTION.KEY=VALUE",
                   help="a setting changed from the defaults (repeatable), e.g. solve.sparsity=0")
    args = p.parse_args(argv)
    if not len(args.corpus) == len(args.corpus_h5) == len(args.db):
        p.error("give --corpus, --corpus-h5 and --db once per corpus")
    config = Config.load(overrides=tuple(args.set))
    rig = load_face_rig()
    ms = build_marker_set(rig)
    tmp = Path(tempfile.mkdtemp())
    fps = 30.0
    started = time.perf_counter()
    takes = {}
    for i, (corpus_dir, corpus_h5, db_path) in enumerate(zip(args.corpus, args.corpus_h5, args.db)):
        takes.update(load_takes(f"c{i}", corpus_dir, corpus_h5, db_path, args.takes, config, tmp, fps))

    from facesynth.domain.rig.loading import builtin_rig

    target = builtin_rig()
    ssolve = config.settings("solve")
    result = {"corpora": {f"c{i}": str(c) for i, c in enumerate(args.corpus)},
              **({"settings_changed": args.set} if args.set else {}), "takes": list(takes), "fps": fps,
              "vertices": int(len(rig.neutral)), "rows": [], "baselines": {}}
    per = {k: [] for k in ("solve_rms", "solve_corr", "solve_mesh", "deform_mesh", "truth_gap", "solve_gap", "deform_gap",
                           "truth_closed", "solve_closed", "deform_closed", "syn_solve_resid", "syn_solve_gap")}
    for key, d in takes.items():
        w, _, _ = solve_motion(d["motion"], target, ssolve, key)
        w = w[: d["n"]]
        rms, corr = weight_scores(rig, w, d["truth"])
        tv, sv = rig.evaluate(d["truth"]), rig.evaluate(w)
        per["solve_rms"].append(rms)
        per["solve_corr"].append(corr)
        per["solve_mesh"].append(float(np.sqrt(((sv - tv) ** 2).sum(-1)).mean()))
        per["deform_mesh"].append(float(np.sqrt(((d["gauss"] - tv) ** 2).sum(-1)).mean()))
        b = d["bilabial"]
        per["truth_gap"].append(mean_gap(tv[b], ms))
        per["solve_gap"].append(mean_gap(sv[b], ms))
        per["deform_gap"].append(mean_gap(d["gauss"][b], ms))
        per["truth_closed"].append(closed(tv[b], ms))
        per["solve_closed"].append(closed(sv[b], ms))
        per["deform_closed"].append(closed(d["gauss"][b], ms))
        ws, rs, _ = solve_motion(d["synth"], target, ssolve, key)
        d["synth_solve"] = ws
        per["syn_solve_resid"].append(float(np.sqrt(np.nanmean(rs**2))))
        sb = bilabial_frames(d["corpus"], d["take"], fps, len(ws))
        per["syn_solve_gap"].append(mean_gap(rig.evaluate(ws[sb]), ms))
    result["baselines"] = {k: boot(v) for k, v in per.items()}
    result["baselines"]["diff_solve_vs_deform_mesh"] = boot(np.subtract(per["solve_mesh"], per["deform_mesh"]))
    print("baselines done", file=sys.stderr, flush=True)

    kss = config.settings("keyshapes")
    rset = config.settings("retarget")
    for method in args.methods.split(","):
        for count in [int(c) for c in args.counts.split(",")]:
            rows = {k: [] for k in ("rms", "corr", "lin_mesh", "grad_mesh", "lin_gap", "grad_gap", "lin_closed",
                                    "grad_closed", "fit_mm", "syn_fit_mm", "syn_lin_gap", "syn_grad_gap", "syn_vs_solve_rms")}
            counts, recon, select_s, factor_s = {}, {}, [], []
            for db_path in args.db:  # key-shapes and keymorphs from each corpus's own database
                mine = {key: d for key, d in takes.items() if d["db_path"] == db_path}
                if not mine:
                    continue
                db = next(iter(mine.values()))["db"]
                t0 = time.perf_counter()
                ks = keyshapes.build(db, dataclasses.replace(kss, method=method, count=count), method, count, str(db_path))
                select_s.append(time.perf_counter() - t0)
                weights_k, meshes_k = retarget.keymorphs(ks, target, None, kss.keymorph_ridge, "keyshapes")
                t0 = time.perf_counter()
                blender = GradientBlender(target.neutral, target.faces, meshes_k, rset.anchor,
                                          use_opencl=rset.use_opencl)
                factor_s.append(time.perf_counter() - t0)
                counts[str(db_path)] = {e: k.count for e, k in ks.emotions.items()}
                recon[str(db_path)] = {e: float(k.rms) for e, k in ks.emotions.items()}
                for key, d in mine.items():
                    r = retarget.retarget(d["motion"], ks, rset, None, key)
                    alpha = r.alpha[: d["n"]]
                    w = np.clip(alpha @ weights_k, 0, 1)
                    rms, corr = weight_scores(rig, w, d["truth"])
                    tv = rig.evaluate(d["truth"])
                    lin = blender.linear(alpha)
                    grad = blender.blend(alpha)
                    b = d["bilabial"]
                    rows["rms"].append(rms)
                    rows["corr"].append(corr)
                    rows["lin_mesh"].append(float(np.sqrt(((lin - tv) ** 2).sum(-1)).mean()))
                    rows["grad_mesh"].append(float(np.sqrt(((grad - tv) ** 2).sum(-1)).mean()))
                    rows["lin_gap"].append(mean_gap(lin[b], ms))
                    rows["grad_gap"].append(mean_gap(grad[b], ms))
                    rows["lin_closed"].append(closed(lin[b], ms))
                    rows["grad_closed"].append(closed(grad[b], ms))
                    dom = r.emotion_weights.argmax(1)
                    rows["fit_mm"].append(float(np.sqrt(np.mean(r.residual[np.arange(len(dom)), dom] ** 2))))
                    rs = retarget.retarget(d["synth"], ks, rset, None, key)
                    dom = rs.emotion_weights.argmax(1)
                    rows["syn_fit_mm"].append(float(np.sqrt(np.mean(rs.residual[np.arange(len(dom)), dom] ** 2))))
                    sb = bilabial_frames(d["corpus"], d["take"], fps, len(rs.alpha))
                    rows["syn_lin_gap"].append(mean_gap(blender.linear(rs.alpha[sb]), ms))
                    rows["syn_grad_gap"].append(mean_gap(blender.blend(rs.alpha[sb]), ms))
                    ws = np.clip(rs.alpha @ weights_k, 0, 1)
                    rows["syn_vs_solve_rms"].append(float(np.sqrt(((rig.to_arkit(ws) - rig.to_arkit(d["synth_solve"])) ** 2).mean())))
            result["rows"].append({"method": method, "count": count, "keyshapes": counts,
                                   "reconstruction_rms_mm": recon, "select_s": select_s, "factorize_s": factor_s,
                                   **{k: boot(v) for k, v in rows.items()},
                                   "diff_rms_vs_solve": boot(np.subtract(rows["rms"], per["solve_rms"])),
                                   "diff_corr_vs_solve": boot(np.subtract(rows["corr"], per["solve_corr"])),
                                   "diff_lin_vs_solve_mesh": boot(np.subtract(rows["lin_mesh"], per["solve_mesh"])),
                                   "diff_grad_vs_lin_mesh": boot(np.subtract(rows["grad_mesh"], rows["lin_mesh"])),
                                   "diff_grad_vs_lin_gap": boot(np.subtract(rows["grad_gap"], rows["lin_gap"]))})
            print(f"{method} {count} done", file=sys.stderr, flush=True)

    result["runtime_s"] = time.perf_counter() - started
    result["load_average"] = list(os.getloadavg())
    json.dump(result, sys.stdout, indent=1)
    print()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
