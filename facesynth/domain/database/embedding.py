"""Expressive phoneme-Isomaps (paper IV, Figs. 5 and 7): the 2D embeddings of each phoneme
cluster that ``facesynth isomap`` writes and ``isomap pick`` reads.

For each phoneme cluster (every frame of every node of one phone, :func:`cluster_frames`) a 2D
Isomap with ``n_neighbors`` neighbours (:func:`embed`), the 2D PCA map of the same frames beside
it (:func:`pca_map`, Fig. 5), and a Delaunay triangulation of each map, so a picked 2D point
gives a new frame by barycentric interpolation of three captured frames
(:func:`barycentric_pick`, Fig. 7).

Large clusters: Isomap's geodesic distances and eigendecomposition grow as n^2 to n^3, so
at most ``max_exact_frames`` evenly spaced frames are embedded exactly and the others are
placed by Isomap's out-of-sample extension (the landmark approach; :func:`memory_estimate`).
A cluster too small for ``n_neighbors`` uses one neighbour fewer than it has frames; below
four frames its Isomap map falls back to the PCA map. Both are reported in the cluster's note.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
from scipy.spatial import Delaunay

from facesynth.base.config import IsomapSettings
from facesynth.base.errors import InputError
from facesynth.base.progress import progress
from facesynth.model.isomap import Cluster, PhonemeMaps
from facesynth.model.motiondb import Nodes


def cluster_frames(nodes: Nodes, phone: str) -> tuple[np.ndarray, np.ndarray, np.ndarray, list[str]]:
    """All frames of the nodes of ``phone``, with node, relative time in the node and emotion."""
    frames, node, rel, emo = [], [], [], []
    for k in np.nonzero(np.array(nodes.phone) == phone)[0]:
        c = int(nodes.frame_count[k])
        frames.append(np.arange(nodes.frame_start[k], nodes.frame_start[k] + c))
        node.append(np.full(c, k))
        rel.append(np.linspace(0.0, 1.0, c))
        emo += [nodes.emotion[k]] * c
    return np.concatenate(frames), np.concatenate(node), np.concatenate(rel), emo


def pca_map(x: np.ndarray) -> np.ndarray:
    """Projection on the cluster's two largest principal axes (Fig. 5, left)."""
    centred = x - x.mean(0)
    _, _, vt = np.linalg.svd(centred, full_matrices=False)
    out = centred @ vt[:2].T
    if out.shape[1] < 2:
        out = np.pad(out, ((0, 0), (0, 2 - out.shape[1])))
    return out * np.sign(out[np.abs(out).argmax(0), [0, 1]] + 1e-30)


def embed(x: np.ndarray, n_neighbors: int, max_exact: int) -> tuple[np.ndarray, int, int, str]:
    """2D Isomap of x (n, K). Returns (embedding, neighbours used, frames embedded exactly, note)."""
    from sklearn.manifold import Isomap

    n = len(x)
    if n < 4:
        return pca_map(x), 0, 0, f"only {n} frames: shown as the PCA map"
    k = min(n_neighbors, n - 2)
    note = "" if k == n_neighbors else f"{n} frames: {k} neighbours instead of {n_neighbors}"
    exact = np.arange(n) if (max_exact <= 0 or n <= max_exact) else np.linspace(0, n - 1, max_exact).round().astype(int)
    model = Isomap(n_neighbors=k, n_components=2, eigen_solver="dense" if len(exact) < 600 else "arpack")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # disconnected neighbour graphs are completed by sklearn
        fitted = model.fit_transform(x[exact])
        out = np.empty((n, 2))
        out[exact] = fitted
        rest = np.setdiff1d(np.arange(n), exact)
        if len(rest):
            out[rest] = model.transform(x[rest])
    out *= np.sign(out[np.abs(out).argmax(0), [0, 1]] + 1e-30)  # fixed signs: deterministic output
    return out, k, len(exact), note


def build_clusters(coeffs: np.ndarray, nodes: Nodes, settings: IsomapSettings, phones: list[str] | None = None) -> list[Cluster]:
    """Embed every phoneme cluster (or those of ``phones``) of the database frames ``coeffs`` (F, K)."""
    out = []
    for phone in progress(phones or sorted(set(nodes.phone)), "isomap"):
        frames, node, rel, emo = cluster_frames(nodes, phone)
        x = coeffs[frames].astype(np.float64)
        iso, k, exact, note = embed(x, settings.n_neighbors, settings.max_exact_frames)
        flat = pca_map(x)
        out.append(Cluster(phone, frames, node, rel, emo, iso, flat, k, exact, note, coeffs[frames],
                           {"isomap": _triangulate(iso), "pca_map": _triangulate(flat)}))
    return out


def triangulate(points: np.ndarray) -> Delaunay | None:
    """The Delaunay triangulation of a 2D map (deterministic for the same points), or None if degenerate."""
    unique = np.unique(points.round(9), axis=0)
    if len(unique) < 3 or np.linalg.matrix_rank(unique - unique[0]) < 2:
        return None
    return Delaunay(points, qhull_options="QJ")


def barycentric_pick(points: np.ndarray, xy: tuple[float, float]) -> tuple[np.ndarray, np.ndarray] | None:
    """The triangle (three frame rows) holding xy and its barycentric weights, or None outside."""
    tri = triangulate(points)
    if tri is None:
        return None
    s = int(tri.find_simplex(np.array([xy], float))[0])
    if s < 0:
        return None
    t = tri.transform[s]
    b = t[:2] @ (np.asarray(xy, float) - t[2])
    return tri.simplices[s], np.array([b[0], b[1], 1.0 - b.sum()])


def picked_frame(maps: PhonemeMaps, phone: str, xy: tuple[float, float], use_pca_map: bool,
                 where: Path) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Fig. 7: the frame at the point ``xy`` of ``phone``'s Isomap (or its PCA map), by
    barycentric interpolation of the three captured frames of the covering triangle.

    Returns the frame's markers (M, 3) mm, the triangle's three rows of the cluster (3,) and
    their weights (3,), summing to 1. A point outside the triangulation is an InputError naming
    ``where`` (the maps' file) and the map's range.
    """
    cluster = maps.cluster(phone, where)
    kind = "pca_map" if use_pca_map else "isomap"
    points = getattr(cluster, kind)
    hit = barycentric_pick(points, xy)
    if hit is None:
        lo, hi = points.min(0), points.max(0)
        raise InputError(
            f"/{phone}/: the point ({xy[0]:g}, {xy[1]:g}) lies outside the triangulation of its {kind.replace('_', ' ')} "
            f"(x {lo[0]:.3g} to {hi[0]:.3g}, y {lo[1]:.3g} to {hi[1]:.3g}); pick a point inside it."
        )
    corners, weights = hit
    frame = (weights[:, None] * cluster.coefficients[corners].astype(np.float64)).sum(0)
    return maps.model.reconstruct(frame[None])[0], corners, weights


def memory_estimate(nodes: Nodes, settings: IsomapSettings) -> float:
    """Bytes the largest cluster's Isomap needs: its exactly embedded frames' geodesic distances
    (n x n float64), the neighbour graph's shortest paths and the double-centred copy, about
    three n x n float64 arrays."""
    counts: dict[str, int] = {}
    for phone, c in zip(nodes.phone, nodes.frame_count):
        counts[phone] = counts.get(phone, 0) + int(c)
    largest = max(counts.values(), default=0)
    exact = largest if settings.max_exact_frames <= 0 else min(largest, settings.max_exact_frames)
    return 3.0 * 8 * exact * exact


def _triangulate(points: np.ndarray) -> np.ndarray:
    """(n, 3) int32 triangles of :func:`triangulate` (none when the map is degenerate)."""
    tri = triangulate(points)
    return np.zeros((0, 3), np.int32) if tri is None else tri.simplices.astype(np.int32)
