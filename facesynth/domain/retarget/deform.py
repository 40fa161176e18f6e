"""Marker motion -> face-mesh animation (paper VII-A, Eq. 14-15), the math of ``facesynth deform``.

For each marker's bound vertex, "mesh distances" to every vertex are shortest paths along
the mesh's edges (Dijkstra), so they go around holes: a lower-lip marker does not reach
the upper lip across the mouth opening, and markers reach no other component. A vertex
within ``distance_threshold`` of a marker gets the weight ``exp(-d^2 / (2 sigma^2))``
(Eq. 14; the constant C cancels in Eq. 15) and moves by the weighted mean of the markers'
motions (Eq. 15). The weights depend only on the mesh and binding, are computed once
(:func:`bind`) and stored in the artifact as a sparse matrix.

Scale: on the production rig (11,248 vertices, ~90 markers) binding takes a fraction of a
second; Dijkstra stops at the threshold and the weights are kept sparse from the start
(:func:`deformation_weights`), so memory follows the number of non-zero weights.
The lips still share the mouth corners: with the default sigma an upper-lip marker reaches
the lower lip's middle only with the small weight of the ~45 mm way round the corner.

Marker motion is the displacement from the database's neutral rest pose; a similarity
transform (rotation, uniform scale, translation) fitted from the rest pose to the bound
vertices carries it into the mesh's frame and units (:func:`animate`). With a head motion
the motion's rigid head motion is put back through the same transform.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import sparse
from scipy.sparse.csgraph import dijkstra

from facesynth.base.config import DeformSettings
from facesynth.base.errors import InputError
from facesynth.domain.geometry.rigid import similarity_fit
from facesynth.domain.geometry.rotations import apply


def edge_graph(vertices: np.ndarray, faces: np.ndarray) -> sparse.csr_matrix:
    """Symmetric sparse graph of mesh edges weighted by their length."""
    e = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    e = np.unique(np.sort(e, axis=1), axis=0)
    w = np.linalg.norm(vertices[e[:, 0]] - vertices[e[:, 1]], axis=1)
    n = len(vertices)
    g = sparse.coo_matrix((np.concatenate([w, w]), (np.concatenate([e[:, 0], e[:, 1]]), np.concatenate([e[:, 1], e[:, 0]]))), shape=(n, n))
    return g.tocsr()


def mesh_distances(vertices: np.ndarray, faces: np.ndarray, sources: np.ndarray, limit: float,
                   graph: sparse.csr_matrix | None = None) -> np.ndarray:
    """(K, V) shortest-path distances along mesh edges from each source vertex; inf beyond ``limit``."""
    g = edge_graph(vertices, faces) if graph is None else graph
    return dijkstra(g, directed=False, indices=sources, limit=limit)


#: Markers whose distances are computed at once: bounds the dense (chunk, V) distance block.
DISTANCE_CHUNK = 32


def deformation_weights(vertices: np.ndarray, faces: np.ndarray, sources: np.ndarray, sigma: float,
                        threshold: float) -> sparse.csr_matrix:
    """Eq. 14-15 as a (V, K) row-normalized sparse matrix: vertex motion = W @ marker motion.

    sources : (K,) the markers' vertices. Distances are found :data:`DISTANCE_CHUNK` markers at
    a time and only those within ``threshold`` are kept, so memory grows with the non-zero
    weights, not with V x K (a 100k-vertex mesh with 300 markers needs no 240 MB table)."""
    graph = edge_graph(vertices, faces)
    rows, cols, vals = [], [], []
    for start in range(0, len(sources), DISTANCE_CHUNK):
        d = mesh_distances(vertices, faces, sources[start:start + DISTANCE_CHUNK], threshold, graph)
        k, v = np.nonzero(d <= threshold)
        rows.append(v)
        cols.append(k + start)
        vals.append(np.exp(-(d[k, v] ** 2) / (2.0 * sigma**2)))
    rows, cols, vals = (np.concatenate(a) for a in (rows, cols, vals))
    total = np.bincount(rows, weights=vals, minlength=len(vertices))
    w = sparse.csr_matrix(((vals / total[rows]).astype(np.float32), (rows, cols)), shape=(len(vertices), len(sources)))
    w.sort_indices()
    return w


@dataclass
class BoundMesh:
    """A mesh bound to markers: everything needed to animate it from marker motion."""

    rest: np.ndarray          # (V, 3) mesh units
    faces: np.ndarray         # (F, 3)
    markers: list[str]        # bound markers, in weight-column order
    vertex_of: np.ndarray     # (K,) bound vertex of each marker
    weights: sparse.csr_matrix  # (V, K)
    unreached: int            # vertices no marker reaches (they stay at rest)


def bind(vertices: np.ndarray, faces: np.ndarray, binding: dict[str, int], motion_markers: list[str],
         settings: DeformSettings, mesh_name: str, binding_name: str) -> BoundMesh:
    """Bind the markers of ``binding`` (those present in the motion) to the mesh and compute the
    Eq. 14 weights by mesh distance; names the files in its errors.
    """
    unknown = [m for m in binding if m not in motion_markers]
    if unknown:
        raise InputError(f"{binding_name}: marker(s) {unknown[:5]} are not in the motion; bind only markers it has ({motion_markers[:4]}...).")
    bad = {m: v for m, v in binding.items() if not 0 <= v < len(vertices)}
    if bad:
        m, v = next(iter(bad.items()))
        raise InputError(f"{binding_name}: marker {m!r} is bound to vertex {v}, but {mesh_name} has vertices 0 to {len(vertices) - 1}; use the binding made for this mesh.")
    if len(binding) < 3:
        raise InputError(f"{binding_name}: at least three bound markers are needed to place the motion on the mesh.")
    if faces.max() >= len(vertices):
        raise InputError(f"{mesh_name}: a face names vertex {faces.max()} beyond the {len(vertices)} vertices; re-export the mesh.")
    names = list(binding)
    sources = np.array([binding[m] for m in names])
    weights = deformation_weights(vertices, faces, sources, settings.sigma, settings.distance_threshold)
    unreached = int((np.asarray(weights.sum(axis=1)).ravel() == 0).sum())
    return BoundMesh(vertices, faces, names, sources, weights, unreached)


@dataclass(frozen=True)
class PlacementFit:
    """How the motion's reference markers were placed on the mesh (the similarity of
    :func:`animate`).

    scale: the similarity's scale from marker millimetres to mesh units.
    fit_rms: RMS distance of the placed reference markers to their bound vertices (mesh units).
    """

    scale: float
    fit_rms: float


def animate(bound: BoundMesh, markers: np.ndarray, marker_names: list[str], reference: np.ndarray,
            head: tuple[np.ndarray, np.ndarray] | None = None) -> tuple[np.ndarray, PlacementFit]:
    """Vertices (T, V, 3) float32 for marker frames (T, M, 3) mm, optionally moved by a head
    motion (rotations (T, 3, 3), translations (T, 3) mm in the marker frame). Also returns
    how the markers were placed on the mesh."""
    cols = np.array([marker_names.index(m) for m in bound.markers])
    s, r, offset, residual = similarity_fit(reference[cols].astype(np.float64), bound.rest[bound.vertex_of])
    motion = (markers[:, cols] - reference[cols]) @ (s * r).T  # (T, K, 3) in mesh units
    out = np.empty((len(markers),) + bound.rest.shape, np.float32)
    for t in range(len(markers)):
        out[t] = bound.rest + bound.weights @ motion[t]
        if head is not None:
            out[t] = apply(out[t], head[0][t], head[1][t], s, r, offset)
    return out, PlacementFit(s, residual)
