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
