"""How much head motion ``normalize`` leaves in the normalized frames, measured against the
sample corpus's clean head-frame markers (``groundtruth/<take>.c3d``). Prints JSON.

Per frame, the rigid transform (rotation and translation, least squares over every marker)
that carries the clean head-frame markers onto the normalized frame; both differ only by noise
and by that transform, whose part that varies over frames is head motion left over (or
speech motion put into the head pose). Reported: the variance of that leftover motion over
the markers (mm^2 per marker) as a fraction of the normalized frames' variance; and, for each
PCA component, the fraction of its coefficient's variance that the six leftover-pose
parameters explain (R^2 of a linear fit), the variance-weighted mean and the worst component.

    python benchmarks/rigid_leftover.py --corpus out/corpus.h5 --clean out/corpus/groundtruth out/pca.h5 [more]
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import numpy as np
from scipy.spatial.transform import Rotation

from facesynth.formats.mocap import read_mocap
from facesynth.model.corpus import Corpus
from facesynth.model.pca import PcaFrames


def kabsch(source: np.ndarray, target: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per frame, R (T, 3, 3) and t (T, 3) minimizing |R source + t - target|^2 over the markers
    (both (T, M, 3) mm, NaN-free)."""
    cs, ct = source.mean(axis=1), target.mean(axis=1)
    h = np.einsum("tmi,tmj->tij", source - cs[:, None], target - ct[:, None])
    u, _, vt = np.linalg.svd(h)
    d = np.sign(np.linalg.det(np.swapaxes(vt, 1, 2) @ np.swapaxes(u, 1, 2)))
    fix = np.ones((len(source), 3))
    fix[:, 2] = d
    r = np.swapaxes(vt, 1, 2) @ (fix[:, :, None] * np.swapaxes(u, 1, 2))
    return r, ct - np.einsum("tij,tj->ti", r, cs)


def leftover(pca_path: Path, corpus_path: Path, clean_dir: Path) -> dict:
    pca = PcaFrames.read(pca_path)
    corpus = Corpus.read(corpus_path, audio=False)
    names = pca.marker_names
    normalized = pca.frames.markers.astype(np.float64)
    clean = np.empty_like(normalized)
    for i in range(len(corpus.takes)):
        take = read_mocap(clean_dir / f"{corpus.takes.name[i]}.c3d")
        clean[corpus.takes.frames(i)] = take.positions[:, [take.names.index(n) for n in names]]
    ok = ~np.isnan(normalized).any(axis=(1, 2))
    x, y = normalized[ok], clean[ok]
    r, t = kabsch(y, x)
    shape = y.mean(axis=0)  # (M, 3)
    moved = np.einsum("tij,mj->tmi", r, shape) + t[:, None]  # where the leftover pose puts the mean shape
    rigid_var = float(np.mean(np.sum((moved - moved.mean(axis=0)) ** 2, axis=2)))
    total_var = float(np.mean(np.sum((x - x.mean(axis=0)) ** 2, axis=2)))
    params = np.hstack([Rotation.from_matrix(r).as_rotvec(), t])
    design = np.hstack([params - params.mean(axis=0), np.ones((len(params), 1))])
    coeffs = pca.coefficients[ok].astype(np.float64)
    fit = design @ np.linalg.lstsq(design, coeffs, rcond=None)[0]
    r2 = 1 - ((coeffs - fit) ** 2).sum(axis=0) / ((coeffs - coeffs.mean(axis=0)) ** 2).sum(axis=0)
    var = coeffs.var(axis=0)
    worst = int(np.argmax(r2))
    return {"pca": str(pca_path), "frames": int(ok.sum()),
            "leftover_rigid_variance_mm2_per_marker": round(rigid_var, 4),
            "normalized_variance_mm2_per_marker": round(total_var, 4),
            "leftover_fraction": round(rigid_var / total_var, 5),
            "pca_variance_explained_by_leftover_pose": round(float(r2 @ var / var.sum()), 5),
            "worst_component": worst + 1, "worst_component_r2": round(float(r2[worst]), 4),
            "per_component_r2": [round(float(v), 4) for v in r2]}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("pca", nargs="+", type=Path)
    ap.add_argument("--corpus", type=Path, required=True)
    ap.add_argument("--clean", type=Path, required=True, help="the folder of clean head-frame <take>.c3d files")
    args = ap.parse_args()
    print(json.dumps([leftover(p, args.corpus, args.clean) for p in args.pca], indent=1))


if __name__ == "__main__":
    main()
