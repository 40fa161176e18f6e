"""Gap filling and rigid alignment of marker frames (paper III, Eq. 1-2).

Every frame is translated so the origin marker is at 0 and rotated onto a neutral
closed-mouth reference frame ``y`` by SVD: ``y^T x_i = U D V^T``, ``R = V U^T`` (a
reflection is turned into the nearest rotation). The per-frame rigid transform is kept, so
``captured = R_i @ normalized + t_i`` for every marker.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


def fill_gaps(track: np.ndarray, max_gap: int) -> tuple[np.ndarray, list[tuple[int, int]]]:
    """Fill NaN runs of at most ``max_gap`` frames in one marker's (T, 3) track.

    Interior runs are filled by a cubic spline through the valid samples within
    ``max_gap`` frames on either side (what capture software calls a spline fill), runs at
    the ends by holding the nearest sample. Returns the filled track and the (start, length)
    of runs left unfilled.
    """
    from scipy.interpolate import CubicSpline  # deferred: only gap filling needs scipy.interpolate

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


@dataclass(frozen=True)
class RigidChoice:
    """The markers the head pose is fitted on.

    indices : (K,) marker indices; source : "settings" (``normalize.rigid_markers``), "corpus"
    (the ``rigid`` flags ``ingest`` recorded) or "data" (:func:`find_rigid_markers`);
    spreads : (K,) mm, each marker's spread within the set when found from the data, else None.
    """

    indices: np.ndarray
    source: str
    spreads: np.ndarray | None = None


def choose_rigid(names: list[str], chosen, corpus_rigid, frames: np.ndarray, *, max_spread_mm: float,
                 min_markers: int) -> RigidChoice:
    """The head-pose markers: ``chosen`` names (the normalize setting) if any, else the corpus's
    rigid set, else the markers that keep their mutual distances over ``frames`` (T, M, 3) mm
    (:func:`find_rigid_markers` with ``max_spread_mm`` and ``min_markers``). Unknown names are
    refused by the caller. Raises ValueError when the data has fewer than three usable markers."""
    for source, given in (("settings", chosen), ("corpus", corpus_rigid)):
        if given:
            return RigidChoice(np.array([names.index(n) for n in given]), source)
    indices, spreads = find_rigid_markers(frames, max_spread_mm=max_spread_mm, min_markers=min_markers)
    return RigidChoice(indices, "data", spreads)


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


def _sample_frames(frames: np.ndarray, max_frames: int) -> np.ndarray:
    """At most ``max_frames`` of (T, M, 3) frames, evenly spaced (all of them when fewer)."""
    if len(frames) <= max_frames:
        return np.asarray(frames, np.float64)
    return np.asarray(frames[np.linspace(0, len(frames) - 1, max_frames).round().astype(int)], np.float64)


def _distances(frames: np.ndarray) -> np.ndarray:
    """(T, M, M) float32 distances (mm) between every pair of markers in each frame (NaN where one
    is unseen); one marker at a time, so no (T, M, M, 3) array is made."""
    out = np.empty(frames.shape[:2] + (frames.shape[1],), np.float32)
    for m in range(frames.shape[1]):
        out[:, m] = np.sqrt(((frames - frames[:, m:m + 1]) ** 2).sum(-1))
    return out


def typical_frame(frames: np.ndarray, max_frames: int = 1000) -> int:
    """The take's most typical frame: the face it holds most, found from marker-to-marker
    distances alone (they do not change with head pose, so no alignment is needed).

    Each frame is described by the distances between the markers seen in at least half the
    frames; among the frames that see the most of them (at most ``max_frames`` evenly spaced),
    the typical one is the mode of that description: the frame with the smallest RMS distance (mm)
    to its k-th nearest frame, k one twentieth of the frames. A face at rest is held often and
    still (the lips stop each other when closed) while speech and song pass through open mouths
    at every size, so the densest frame is the rest pose where a median would be half open (a
    singer holds the mouth open much of a take). frames : (T, M, 3) mm, NaN where unseen.
    Returns a frame index into ``frames``.
    """
    frames = np.asarray(frames)
    visible = ~np.isnan(frames).any(axis=2)  # (T, M)
    common = visible.mean(axis=0) >= 0.5  # markers seen in most frames; a rarely seen one does not pick the frame
    if common.sum() < 3:
        common = visible.any(axis=0)
    seen = visible[:, common].sum(axis=1)
    full = np.nonzero(seen == seen.max())[0]
    idx = full if len(full) <= max_frames else full[np.linspace(0, len(full) - 1, max_frames).round().astype(int)]
    d = _distances(np.asarray(frames[idx][:, common], np.float64))
    upper = np.triu_indices(d.shape[1], 1)
    features = np.nan_to_num(d[:, upper[0], upper[1]].astype(np.float64))  # (N, P) mm
    sq = (features**2).sum(1)
    between = np.sqrt(np.maximum(sq[:, None] + sq[None] - 2 * features @ features.T, 0.0) / features.shape[1])
    k = min(max(1, len(idx) // 20), len(idx) - 1)
    if k == 0:
        return int(idx[0])
    kth = np.partition(between, k, axis=1)[:, k]  # column 0 is the frame itself
    return int(idx[np.argmin(kth)])


def find_rigid_markers(frames: np.ndarray, *, max_spread_mm: float, min_markers: int = 3,
                       min_seen: float = 0.5, max_frames: int = 1000) -> tuple[np.ndarray, np.ndarray]:
    """The markers that move only with the head, found from the data: those whose mutual
    distances vary least over the take.

    The spread of a pair is the standard deviation over the frames (mm) of the distance between
    its two markers; a rigid body's pairs spread by marker noise alone, while speech moves the
    lips and jaw tens of millimetres against the head. Starting from every marker seen in at
    least ``min_seen`` of the frames, the marker with the most pairs spreading by more than
    ``max_spread_mm`` within the set (ties: the largest RMS spread) is dropped, one at a time,
    until no such pair is left or only ``min_markers`` are: what is left is the largest group
    whose markers all keep their distances, the head. Counting pairs rather than averaging
    spreads keeps a group of markers that move together (the upper lip) out: each of them
    spreads against every marker of the head.

    frames : (T, M, 3) mm, NaN where unseen (at most ``max_frames`` evenly spaced frames are used).
    Returns the chosen marker indices (K,) in marker order and each one's spread within the
    chosen set (K,) mm: the RMS of its pairs' spreads.
    Raises ValueError when fewer than three markers are seen often enough.
    """
    sample = _sample_frames(frames, max_frames)
    seen = (~np.isnan(sample).any(axis=2)).mean(axis=0)
    candidates = np.nonzero(seen >= min_seen)[0]
    if len(candidates) < 3:
        raise ValueError(f"only {len(candidates)} markers are seen in at least {100 * min_seen:.0f}% of the frames")
    d = _distances(sample[:, candidates])
    both = (~np.isnan(d)).sum(axis=0)
    with np.errstate(invalid="ignore"):
        pair = np.where(both >= 3, np.nanstd(d, axis=0, dtype=np.float64), np.inf)  # (K, K) mm; seldom seen together: moving
    np.fill_diagonal(pair, 0.0)
    keep = np.arange(len(candidates))

    def spreads(rows: np.ndarray) -> np.ndarray:
        sub = np.minimum(pair[np.ix_(rows, rows)], 1e6)
        return np.sqrt((sub**2).sum(axis=1) / max(len(rows) - 1, 1))

    while len(keep) > max(min_markers, 3):
        over = (pair[np.ix_(keep, keep)] > max_spread_mm).sum(axis=1)
        if not over.any():
            break
        worst = np.lexsort((spreads(keep), over))[-1]  # most pairs over the bound, then the largest spread
        keep = np.delete(keep, worst)
    return candidates[keep], spreads(keep)
