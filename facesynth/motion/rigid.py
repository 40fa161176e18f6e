"""Gap filling and rigid alignment of marker frames (paper III, Eq. 1-2).

Every frame is translated so the origin marker is at 0 and rotated onto a neutral
closed-mouth reference frame ``y`` by SVD: ``y^T x_i = U D V^T``, ``R = V U^T`` (a
reflection is turned into the nearest rotation). The per-frame rigid transform is kept, so
``captured = R_i @ normalized + t_i`` for every marker.
"""

from __future__ import annotations

import numpy as np
from scipy.interpolate import CubicSpline


def fill_gaps(track: np.ndarray, max_gap: int) -> tuple[np.ndarray, list[tuple[int, int]]]:
    """Fill NaN runs of at most ``max_gap`` frames in one marker's (T, 3) track.

    Interior runs are filled by a cubic spline through the valid samples within
    ``max_gap`` frames on either side (what capture software calls a spline fill), runs at
    the ends by holding the nearest sample. Returns the filled track and the (start, length)
    of runs left unfilled.
    """
    missing = np.isnan(track).any(axis=1)
    if not missing.any():
        return track, []
    valid = np.nonzero(~missing)[0]
    if len(valid) == 0:
        return track, [(0, len(track))]
    out = track.copy()
    long_runs = []
    edges = np.diff(np.concatenate([[0], missing.astype(np.int8), [0]]))
    starts, ends = np.nonzero(edges == 1)[0], np.nonzero(edges == -1)[0]
    for s, e in zip(starts, ends):
        if e - s > max_gap:
            long_runs.append((int(s), int(e - s)))
            continue
        if s == 0 or e == len(track):
            out[s:e] = track[valid[0]] if s == 0 else track[valid[-1]]
            continue
        near = valid[(valid >= s - max_gap) & (valid < e + max_gap)]
        frames = np.arange(s, e)
        if len(near) >= 4:
            out[s:e] = CubicSpline(near, track[near], axis=0)(frames)
        else:
            out[s:e] = np.stack([np.interp(frames, near, track[near, a]) for a in range(3)], 1)
    return out, long_runs


def rigid_align(frames: np.ndarray, reference: np.ndarray, origin: int, rigid: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Align each frame to the reference with Eq. 1-2.

    frames : (T, M, 3) mm; reference : (M, 3) mm with the origin marker at 0;
    origin : index of the origin marker; rigid : indices of the markers used for the SVD.
    Returns normalized (T, M, 3), rotations (T, 3, 3) and translations (T, 3) with
    ``frames[t, m] = rotations[t] @ normalized[t, m] + translations[t]``.
    """
    translations = frames[:, origin, :].copy()
    x = frames - translations[:, None, :]
    xs, ys = x[:, rigid, :], reference[rigid]
    visible = ~np.isnan(xs).any(axis=2)  # (T, K): only markers seen in this frame
    xs0 = np.where(visible[:, :, None], xs, 0.0)
    h = np.einsum("kj,tki->tji", ys, xs0)  # y^T x_i, (T, 3, 3)
    u, _, vt = np.linalg.svd(h)
    v = np.swapaxes(vt, 1, 2)
    r = v @ np.swapaxes(u, 1, 2)  # R = V U^T, maps x_i onto y: x_i R ~ y
    flip = np.linalg.det(r) < 0
    if flip.any():  # nearest proper rotation: flip the axis of the smallest singular value
        v[flip, :, 2] *= -1
        r[flip] = v[flip] @ np.swapaxes(u[flip], 1, 2)
    normalized = np.einsum("tmi,tij->tmj", x, r)  # rows: x_i R, so as columns x = R @ normalized
    return normalized, r, translations


def procrustes_align(frames: np.ndarray, reference: np.ndarray, rigid: np.ndarray,
                     weights: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Weighted Procrustes of each frame onto the reference, fitted on the rigid markers only.

    frames : (T, M, 3) mm (NaN where unseen); reference : (M, 3) mm; rigid : (K,) marker
    indices; weights : (K,) non-negative, or None for equal weights. Per frame, the weighted
    centroids ``c_x``, ``c_y`` of the visible rigid markers and the rotation R minimizing
    ``sum_k w_k |(x_k - c_x) R - (y_k - c_y)|^2`` (SVD, reflections turned into the nearest
    rotation); the markers that move with speech take no part, so jaw opening does not leak
    into the head pose. Returns normalized (T, M, 3), rotations (T, 3, 3) and translations
    (T, 3) mm with ``frames[t, m] = rotations[t] @ normalized[t, m] + translations[t]``.
    """
    w = np.ones(len(rigid)) if weights is None else np.asarray(weights, np.float64)
    xs, ys = frames[:, rigid, :], reference[rigid]
    visible = ~np.isnan(xs).any(axis=2)  # (T, K)
    wt = np.where(visible, w[None, :], 0.0)
    total = np.maximum(wt.sum(axis=1), 1e-12)[:, None]  # (T, 1)
    xs0 = np.where(visible[:, :, None], xs, 0.0)
    cx = np.einsum("tk,tki->ti", wt, xs0) / total  # (T, 3)
    cy = np.einsum("tk,ki->ti", wt, ys) / total  # (T, 3): the reference's centroid over the same markers
    h = np.einsum("tk,tkj,tki->tji", wt, ys[None] - cy[:, None], xs0 - cx[:, None])  # (T, 3, 3)
    u, _, vt = np.linalg.svd(h)
    v = np.swapaxes(vt, 1, 2)
    r = v @ np.swapaxes(u, 1, 2)
    flip = np.linalg.det(r) < 0
    if flip.any():
        v[flip, :, 2] *= -1
        r[flip] = v[flip] @ np.swapaxes(u[flip], 1, 2)
    normalized = np.einsum("tmi,tij->tmj", frames - cx[:, None], r) + cy[:, None]
    translations = cx - np.einsum("tij,tj->ti", r, cy)
    return normalized, r, translations


def head_pose(frames: np.ndarray, reference: np.ndarray, rigid: np.ndarray, iterations: int = 2):
    """:func:`procrustes_align` with weights from the data: a fit with equal weights, then
    ``iterations - 1`` refits weighting each rigid marker by the inverse of its mean squared
    residual (mm^2, floored at 1e-2 mm^2), so a noisy or slightly sliding marker counts less.
    frames (T, M, 3), reference (M, 3), rigid (K,) indices. Returns what
    :func:`procrustes_align` returns, then the (K,) weights (summing to K)."""
    weights = np.ones(len(rigid))
    for i in range(iterations):
        normalized, r, t = procrustes_align(frames, reference, rigid, weights)
        if i == iterations - 1 or len(rigid) < 4:
            break
        residual = np.nanmean(np.sum((normalized[:, rigid] - reference[rigid]) ** 2, axis=2), axis=0)
        inverse = 1.0 / np.maximum(np.nan_to_num(residual, nan=np.inf), 1e-2)
        weights = inverse * len(rigid) / inverse.sum()
    return normalized, r, t, weights


def rigid_indices(names: list[str], chosen, corpus_rigid) -> tuple[np.ndarray, str]:
    """The marker indices the head pose is fitted on: ``chosen`` names (the normalize setting)
    if any, else the corpus's rigid set, else every marker with a warning (returned as the
    second value; empty when there is none). Unknown names are refused by the caller."""
    for source in (chosen, corpus_rigid):
        if source:
            return np.array([names.index(n) for n in source]), ""
    return np.arange(len(names)), ("the corpus marks no rigid markers and normalize.rigid_markers is empty: the head pose "
                                   "is fitted on every marker, so speech motion leaks into it; name the markers that move "
                                   "only with the head with --set normalize.rigid_markers=[...] or a `rigid` column in markers.csv.")


def similarity_fit(source: np.ndarray, target: np.ndarray) -> tuple[float, np.ndarray, np.ndarray, float]:
    """Umeyama: scale s, rotation R, translation t minimizing ||s R source + t - target||.
    Returns (s, R, t, RMS residual in target units)."""
    mu_s, mu_t = source.mean(0), target.mean(0)
    a, b = source - mu_s, target - mu_t
    u, sing, vt = np.linalg.svd(b.T @ a)
    d = np.ones(3)
    if np.linalg.det(u @ vt) < 0:
        d[2] = -1.0
    r = u @ np.diag(d) @ vt
    s = float((sing * d).sum() / (a**2).sum())
    t = mu_t - s * r @ mu_s
    residual = float(np.sqrt(np.mean(np.sum((s * a @ r.T - b) ** 2, axis=1))))
    return s, r, t, residual
