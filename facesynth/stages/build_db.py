"""``facesynth build-db``: the motion-node database (paper III, VI-B).

The nodes (one per phone occurrence of the training takes) and their DSC features (Eq. 6) are
:mod:`facesynth.domain.search.nodes`; the boundary states of PGap and VGap (Eq. 8-9) are
:func:`facesynth.domain.search.pairs.boundary_states`. The transition cost (Table I) of any ordered
pair is computed on demand from these small per-node features; no (N, N) table is stored, so
the database grows linearly with the number of nodes N. The frames of all nodes, with their
relative time in the node, form the phoneme clusters.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.config import BuildDbSettings, settings_json
from facesynth.base.limits import bound, require_memory
from facesynth.domain.search.nodes import build_nodes, dsc_features
from facesynth.domain.search.pairs import boundary_states, pivot_distances
from facesynth.model.motiondb import MotionDatabase, TransitionFeatures
from facesynth.model.pca import PcaFrames


def build(pca: PcaFrames, settings: BuildDbSettings, source: str = "") -> tuple[MotionDatabase, TransitionFeatures, dict]:
    """The database and its per-node transition features for a PCA artifact's contents
    (read from ``source``, named in refusals); returns them with the seconds spent on the DSC
    features and the boundary states."""
    coeffs = pca.coefficients
    nodes = build_nodes(pca.takes, pca.phones, pca.frames.fps)
    bound(len(nodes), "max_nodes", "the number of motion nodes", source)
    # four (N, 3M) float32 boundary states and their float64 working copies
    require_memory(3.0 * 4 * 4 * len(nodes) * 3 * len(pca.marker_names), f"the boundary states of {len(nodes)} motion nodes",
                   source)
    timings = {}
    t0 = time.perf_counter()
    x, y, scale = dsc_features(coeffs, nodes, settings.dsc_samples)
    timings["dsc_s"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    states = boundary_states(coeffs, nodes, pca.model, settings.boundary_fit_frames)
    timings["boundary_s"] = time.perf_counter() - t0
    features = TransitionFeatures(*(np.ascontiguousarray(a, np.float32) for a in states[:2]),  # type: ignore[arg-type, call-arg]
                                  *(np.ascontiguousarray(a, np.float32) for a in states[2:]), x, y, scale,
                                  nodes.viseme, nodes.pre)
    features.pivot_distances = pivot_distances(features)
    db = MotionDatabase(pca.takes, pca.phones, pca.marker_names, pca.model, coeffs, pca.frames, nodes)
    return db, features, timings


@dataclass(frozen=True)
class BuildDbResult:
    """What ``facesynth build-db`` built.

    nodes: motion nodes (one per phone segment of the training takes).
    with_predecessor: nodes with a captured predecessor.
    dsc_s, boundary_s, write_s: seconds spent on the DSC features, the boundary states and writing.
    """

    nodes: int
    with_predecessor: int
    dsc_s: float
    boundary_s: float
    write_s: float


def run(pca_path: Path, out: Path, settings: BuildDbSettings, overwrite: bool = False) -> BuildDbResult:
    """Build the database from ``pca_path`` and write ``out`` (a ``motiondb`` artifact)."""
    pca = PcaFrames.read(pca_path)
    db, features, timings = build(pca, settings, str(pca_path))
    t0 = time.perf_counter()
    db.write(out, features, config=settings_json(settings), inputs=[pca_path], overwrite=overwrite)
    timings["write_s"] = time.perf_counter() - t0
    nodes = db.nodes
    return BuildDbResult(len(nodes), int((nodes.pre >= 0).sum()), timings["dsc_s"], timings["boundary_s"],
                         timings["write_s"])

