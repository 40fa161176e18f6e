"""Placing a user's markers on a rig: ``facesynth bind``.

A real capture has its own marker names and count and no binding to any rig. One frame of it
(the neutral, or a chosen one) is fitted to the rig's surface by a similarity (scale, rotation,
translation) with no known correspondence, then each marker takes its nearest surface vertex.

Markers the capture shows riding on the jaw are kept on vertices the rig's jaw opening carries,
and the others off them (:func:`jaw_sides`): a similarity cannot absorb a face's proportions.

The fit (:func:`fit_to_surface`) is iterative closest point with scale (Umeyama's similarity on
the nearest vertices, trimmed: the worst ``1 - keep`` of the markers, e.g. a headband or a
marker on the neck, take no part), started from several poses; the best few are refined
point-to-plane (markers slide along a smooth surface, where point-to-point steps crawl) and the
best kept:

- the capture's up and forward axes, when the user gives them (``--up``, ``--forward``): one start;
- else every proper rotation taking the capture's axes (x, y, z, either sign) or its markers'
  principal axes onto the rig's: 48 starts. Capture systems put up and forward along an axis of
  their frame, and a face held upright is caught by one of them; principal axes cover a tilted one.

Each start is tried at three scales around the ratio of the markers' RMS radius to the RMS radius
of the rig's front half. The rig is taken in the built-in rig's frame, glTF's convention: +y up,
the face toward +z, +x the subject's left; the surface fitted is its front half (z above the middle
of its depth), so no marker lands on the back of the head.

Residuals are distances from each fitted marker to its vertex, in the capture's millimetres
(rig distances divided by the fitted scale); markers farther than a setting are flagged, to be
checked or deleted in the CSV by the user (a headband, a marker on the ear or the neck).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np
from scipy.spatial import cKDTree

#: A rig vertex rides on the jaw when jaw opening moves it by at least this share of its largest move.
JAW_VERTEX_SHARE = 0.35

#: How many of the best point-to-point fits are refined point-to-plane.
REFINED_STARTS = 6

#: Axis names for ``--up`` / ``--forward``.
AXES = {"+x": (1, 0, 0), "-x": (-1, 0, 0), "+y": (0, 1, 0), "-y": (0, -1, 0), "+z": (0, 0, 1), "-z": (0, 0, -1)}


@dataclass(frozen=True)
class SurfaceFit:
    """A similarity taking capture points x (mm) onto the rig: ``scale * rotation @ x + translation``.

    scale : rig units per capture mm; rotation : (3, 3); translation : (3,) rig units;
    rms : RMS distance (rig units) of the kept (trimmed) markers to their nearest vertex;
    start : which start won (a short description).
    """

    scale: float
    rotation: np.ndarray
    translation: np.ndarray
    rms: float
    start: str

    def apply(self, points: np.ndarray) -> np.ndarray:
        """(N, 3) capture points -> (N, 3) rig coordinates."""
        return self.scale * np.asarray(points, np.float64) @ self.rotation.T + self.translation


@dataclass(frozen=True)
class Binding:
    """Markers placed on a rig.

    names : the M bound marker names (markers seen in the fitted frame), in capture order;
    vertices : (M,) int64 rig vertices; residual_mm : (M,) distance of each fitted marker to its
    vertex in capture mm; flagged : (M,) bool, residual over the setting; unbound : markers unseen
    in the fitted frame (no place on the rig); frame : the fitted frame; fit : the similarity.
    """

    names: list[str]
    vertices: np.ndarray
    residual_mm: np.ndarray
    flagged: np.ndarray
    unbound: list[str]
    frame: int
    fit: SurfaceFit


def axis_rotation(up: str, forward: str) -> np.ndarray:
    """(3, 3) rotation taking the capture's ``up`` and ``forward`` axes (names of :data:`AXES`) to
    the rig's +y and +z (and so up x forward, the subject's left, to +x).
    Raises ValueError when the two are not perpendicular."""
    u, f = np.array(AXES[up], float), np.array(AXES[forward], float)
    if abs(u @ f) > 0:
        raise ValueError(f"up {up} and forward {forward} are not perpendicular")
    return np.stack([np.cross(u, f), u, f])


def _start_rotations(points: np.ndarray) -> list[tuple[str, np.ndarray]]:
    """The 48 starting rotations: the 24 proper rotations among the capture's signed axes, and
    the 24 taking its markers' principal axes onto the rig's axes."""
    out = []
    for perm in itertools.permutations(range(3)):
        for signs in itertools.product((1, -1), repeat=3):
            r = np.zeros((3, 3))
            r[range(3), perm] = signs
            if np.linalg.det(r) > 0:
                out.append((f"capture axes {perm} {signs}", r))
    centred = points - points.mean(0)
    _, _, vt = np.linalg.svd(centred, full_matrices=False)
    for name, r in out[:24]:
        out.append((f"principal axes {name[len('capture axes '):]}", r @ vt))
    return out


def front_surface(vertices: np.ndarray) -> np.ndarray:
    """Indices of the rig vertices on its front half: z above the middle of the rig's depth."""
    z = vertices[:, 2]
    return np.nonzero(z >= 0.5 * (z.min() + z.max()))[0]


def _icp(points: np.ndarray, surface: np.ndarray, tree: cKDTree, scales: np.ndarray, rotations: np.ndarray,
         keep: float, iterations: int, scale_bounds: tuple[float, float]
         ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Trimmed ICP with scale from S starts at once (``scales`` (S,), ``rotations`` (S, 3, 3); the
    centroids matched), each start stepping until its trimmed RMS settles or ``iterations`` are
    done. The starts step together, so each step is one nearest-vertex query and one batch of
    3 x 3 fits for all of them. Returns (scales (S,), rotations (S, 3, 3), translations (S, 3),
    trimmed RMS (S,) in rig units)."""
    scale = np.array(scales, np.float64)
    rotation = np.array(rotations, np.float64)
    t = surface.mean(0) - (scale[:, None, None] * rotation) @ points.mean(0)
    n_keep = max(3, int(np.ceil(keep * len(points))))
    rms = np.full(len(scale), np.inf)
    going = np.arange(len(scale))  # the starts still stepping
    for _ in range(iterations):
        if not len(going):
            break
        dist, nearest = _nearest(points, tree, scale[going], rotation[going], t[going])
        best = np.argsort(dist, axis=1)[:, :n_keep]
        new_rms = np.sqrt(np.mean(np.take_along_axis(dist, best, 1) ** 2, axis=1))
        source, target = points[best], surface[np.take_along_axis(nearest, best, 1)]
        s, r = _similarities(source, target)
        s = np.clip(s, *scale_bounds)
        scale[going], rotation[going] = s, r
        t[going] = target.mean(1) - ((s[:, None, None] * r) @ source.mean(1)[:, :, None])[..., 0]
        settled = np.abs(rms[going] - new_rms) < 1e-6 * np.maximum(new_rms, 1e-12)
        rms[going] = new_rms
        going = going[~settled]
    dist, _ = _nearest(points, tree, scale, rotation, t)
    return scale, rotation, t, np.sqrt(np.mean(np.sort(dist, axis=1)[:, :n_keep] ** 2, axis=1))


def _nearest(points: np.ndarray, tree: cKDTree, scale: np.ndarray, rotation: np.ndarray, t: np.ndarray
             ) -> tuple[np.ndarray, np.ndarray]:
    """Distances and indices ((S, N) each) of the nearest surface vertex to each of the (N, 3)
    ``points`` moved by each of S similarities (``scale * points @ rotation.T + t``)."""
    moved = (scale[:, None, None] * points) @ rotation.transpose(0, 2, 1) + t[:, None, :]
    dist, nearest = tree.query(moved.reshape(-1, 3))
    return dist.reshape(moved.shape[:2]), nearest.reshape(moved.shape[:2])


def _similarities(source: np.ndarray, target: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Umeyama's scale and rotation of S point sets at once (as
    :func:`facesynth.domain.geometry.rigid.similarity_fit` fits one): (S,) scales and
    (S, 3, 3) rotations best taking each (S, K, 3) ``source`` onto its ``target``."""
    a = source - source.mean(1)[:, None, :]
    b = target - target.mean(1)[:, None, :]
    u, sing, vt = np.linalg.svd(b.transpose(0, 2, 1) @ a)
    d = np.ones((len(source), 3))
    d[np.linalg.det(u @ vt) < 0, 2] = -1.0
    return (sing * d).sum(1) / (a**2).sum((1, 2)), (u * d[:, None, :]) @ vt


def vertex_normals(vertices: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """(V, 3) unit area-weighted vertex normals of a triangle mesh (zero for a vertex on no triangle)."""
    v = np.asarray(vertices, np.float64)
    f = np.asarray(faces, np.int64)
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    out = np.zeros_like(v)
    for k in range(3):
        np.add.at(out, f[:, k], n)
    length = np.linalg.norm(out, axis=1, keepdims=True)
    return np.divide(out, length, out=np.zeros_like(out), where=length > 0)


def _refine_to_planes(points: np.ndarray, surface: np.ndarray, normals: np.ndarray, tree: cKDTree, fit: SurfaceFit,
                      keep: float, iterations: int, scale_bounds: tuple[float, float]) -> SurfaceFit:
    """Point-to-plane refinement of a fit: each step solves the linearised similarity update
    (rotation vector w, relative scale ds, translation dt) minimising the trimmed sum of squared
    distances of the moved markers to the tangent planes of their nearest vertices. Point-to-point
    steps crawl where markers slide along a smooth surface; this converges in a few steps."""
    scale, rotation, t = fit.scale, fit.rotation, fit.translation
    n_keep = max(3, int(np.ceil(keep * len(points))))
    for _ in range(iterations):
        moved = scale * points @ rotation.T + t
        _, nearest = tree.query(moved)
        q, n = surface[nearest], normals[nearest]
        residual = np.einsum("ij,ij->i", n, moved - q)
        best = np.argsort(np.abs(residual))[:n_keep]
        c = moved - moved[best].mean(0)  # rotate and scale about the kept markers' centroid
        a = np.concatenate([np.cross(c, n), np.einsum("ij,ij->i", n, c)[:, None], n], axis=1)[best]  # (K, 7)
        x, *_ = np.linalg.lstsq(a, -residual[best], rcond=None)
        w, ds, dt = x[:3], x[3], x[4:]
        angle = np.linalg.norm(w)
        step = _rotvec(w) if angle > 0 else np.eye(3)
        centre = moved[best].mean(0)
        new_scale = float(np.clip(scale * (1 + ds), *scale_bounds))
        factor = new_scale / scale
        rotation = step @ rotation
        t = factor * (step @ (t - centre)) + centre + dt
        scale = new_scale
        if angle < 1e-7 and abs(ds) < 1e-7 and np.linalg.norm(dt) < 1e-6 * max(np.abs(surface).max(), 1.0):
            break
    # scored like the point-to-point fits, by the distance to the nearest vertex: a distance to
    # tangent planes would favour a fit shrunk into the face, where more markers lie near a plane
    dist, _ = tree.query(scale * points @ rotation.T + t)
    return SurfaceFit(scale, rotation, t, float(np.sqrt(np.mean(np.sort(dist)[:n_keep] ** 2))), fit.start + ", refined")


def _rotvec(w: np.ndarray) -> np.ndarray:
    """(3, 3) rotation by the rotation vector w (Rodrigues)."""
    angle = np.linalg.norm(w)
    k = w / angle
    cross = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(angle) * cross + (1 - np.cos(angle)) * cross @ cross


def fit_to_surface(points: np.ndarray, vertices: np.ndarray, faces: np.ndarray | None = None, *,
                   up: str | None = None, forward: str | None = None, keep: float = 0.8,
                   iterations: int = 60) -> SurfaceFit:
    """The similarity placing one capture frame on the rig's front surface (see the module).

    points : (N, 3) mm, the markers seen in the frame (N >= 4); vertices : (V, 3) the rig's
    neutral, in rig units, +y up and +z forward. up, forward : the capture's axes (names of
    :data:`AXES`), both or neither. keep : fraction of markers each ICP step fits (the rest are
    taken as off the face). Returns the best :class:`SurfaceFit` over the starts.
    """
    points = np.asarray(points, np.float64)
    front = front_surface(np.asarray(vertices))
    surface = np.asarray(vertices, np.float64)[front]
    tree = cKDTree(surface)
    if up is not None and forward is not None:
        starts = [(f"up {up}, forward {forward}", axis_rotation(up, forward))]
    else:
        starts = _start_rotations(points)
    radius_points = np.sqrt(((points - points.mean(0)) ** 2).sum(1).mean())
    radius_rig = np.sqrt(((surface - surface.mean(0)) ** 2).sum(1).mean())
    s0 = radius_rig / max(radius_points, 1e-9)
    tried = [(f"{name}, scale x{factor:g}", s0 * factor, rotation) for name, rotation in starts for factor in (0.7, 1.0, 1.4)]
    fitted = _icp(points, surface, tree, np.array([s for _, s, _ in tried]), np.array([r for _, _, r in tried]),
                  keep, iterations, (0.35 * s0, 2.8 * s0))
    fits = [SurfaceFit(float(s), r, t, float(rms), name) for (name, _, _), s, r, t, rms in zip(tried, *fitted)]
    # compare fits in the capture's millimetres, so a shrunken fit does not win by its scale
    fits.sort(key=lambda f: f.rms / f.scale)
    if faces is None:
        return fits[0]
    normals = vertex_normals(vertices, faces)[front]
    # refine the best few point-to-point fits: their order can change once each has converged
    refined = [_refine_to_planes(points, surface, normals, tree, f, keep, iterations, (0.35 * s0, 2.8 * s0))
               for f in fits[:REFINED_STARTS]]
    return min(refined + fits[:1], key=lambda f: f.rms / f.scale)


def bind_markers(frame: np.ndarray, names: list[str], vertices: np.ndarray, faces: np.ndarray | None = None, *,
                 max_residual_mm: float,
                 up: str | None = None, forward: str | None = None, keep: float = 0.8, iterations: int = 60,
                 frame_index: int = 0, allowed: list | None = None) -> Binding:
    """Place the markers of one capture frame on the rig.

    frame : (M, 3) mm, NaN for markers unseen in it; names : the M marker names; vertices : (V, 3)
    the rig's neutral (rig units; every vertex may be chosen, not only the front half); faces :
    (F, 3) its triangles, for the point-to-plane refinement (None: point-to-point only).
    max_residual_mm : markers farther than this from their vertex (capture mm) are flagged.
    allowed : per marker, None or the (K,) vertex indices it may take (:func:`jaw_sides`); a
    marker takes the nearest of them unless that is more than ``2 max_residual_mm`` farther than
    its nearest vertex.
    Raises ValueError when fewer than four markers are seen in the frame.
    """
    frame = np.asarray(frame, np.float64)
    seen = ~np.isnan(frame).any(axis=1)
    if seen.sum() < 4:
        raise ValueError(f"only {int(seen.sum())} markers are seen in frame {frame_index}; a fit needs at least 4")
    fit = fit_to_surface(frame[seen], vertices, faces, up=up, forward=forward, keep=keep, iterations=iterations)
    placed = fit.apply(frame[seen])
    dist, nearest = cKDTree(np.asarray(vertices, np.float64)).query(placed)
    if allowed is not None:  # a marker limited to some vertices (its side of the jaw) takes the nearest of those
        for k, m in enumerate(np.nonzero(seen)[0]):
            if allowed[m] is not None and len(allowed[m]):
                d = np.linalg.norm(np.asarray(vertices)[allowed[m]] - placed[k], axis=1)
                if d.min() <= dist[k] + 2 * max_residual_mm * fit.scale:
                    dist[k], nearest[k] = d.min(), allowed[m][np.argmin(d)]
    residual = dist / fit.scale
    return Binding([n for n, s in zip(names, seen) if s], nearest.astype(np.int64), residual,
                   residual > max_residual_mm, [n for n, s in zip(names, seen) if not s], frame_index, fit)



def jaw_sides(displacements: np.ndarray, jaw_motion: np.ndarray, *, jaw_share: float = 0.5) -> list:
    """Which rig vertices each marker may take, by the side of the jaw it moves with.

    A similarity cannot absorb a face's proportions: a capture whose mouth sits lower under the
    nose than the rig's puts upper-lip markers on the rig's lower lip, and a solve then explains
    an upper lip that rises with jaw opening plus lip closing. The capture says which markers the
    jaw carries: the marker moving most against the head (the chin or lower lip in speech and
    song) gives the jaw's direction (its first principal axis); a marker whose motion along it
    correlates with the jaw's by 0.8 or more and reaches ``jaw_share`` of its size rides on the
    jaw, one that correlates by at most 0.3 or moves less than a quarter as much does not, the
    rest (cheeks, the jaw's sides) are left free. The rig says which vertices jaw opening carries
    (``jaw_motion``, its displacement length per vertex): those moving at least
    :data:`JAW_VERTEX_SHARE` of its largest (on the built-in rig: the lower lip, chin and mouth
    corners; the upper lip moves under an eighth).

    displacements : (T, M, 3) mm, the markers' motion with head motion removed, from a rest frame
    (NaN where unseen); jaw_motion : (V,) rig units. Returns per marker None (free) or the (K,)
    vertex indices it may take.
    """
    d = np.asarray(displacements, np.float64)
    seen = (~np.isnan(d).any(axis=2)).mean(axis=0) >= 0.5
    size = np.zeros(d.shape[1])
    size[seen] = np.sqrt(np.nanmean((d[:, seen] ** 2).sum(axis=2), axis=0))  # (M,) RMS displacement, mm
    if not seen.any():
        return [None] * d.shape[1]
    jaw = int(np.argmax(np.where(seen, size, -np.inf)))
    track = d[:, jaw]
    ok = ~np.isnan(track).any(axis=1)
    _, _, vt = np.linalg.svd(track[ok] - track[ok].mean(0), full_matrices=False)
    signal = track @ vt[0]
    carried = jaw_motion >= JAW_VERTEX_SHARE * jaw_motion.max()
    on_jaw, off_jaw = np.nonzero(carried)[0], np.nonzero(~carried)[0]
    out: list = []
    for m in range(d.shape[1]):
        along = d[:, m] @ vt[0]
        both = ~np.isnan(along) & ~np.isnan(signal)
        if not seen[m] or both.sum() < 3 or np.std(along[both]) == 0:
            out.append(None)
            continue
        r = float(np.corrcoef(along[both], signal[both])[0, 1])
        share = size[m] / max(size[jaw], 1e-9)
        if r >= 0.8 and share >= jaw_share:
            out.append(on_jaw)
        elif r <= 0.3 or share < 0.25:
            out.append(off_jaw)
        else:
            out.append(None)
    return out
