"""Key-shapes chosen from data, per emotion (arrays in, arrays out).

Frames are marker displacements from the neutral reference, flattened: (N, 3M) mm. A key-shape
is one of the frames. Working on displacements (not absolute positions) makes the neutral face
the all-zero weight vector, so Eq. 8's non-negative combination needs no affine constraint and
keymorphs blend as offsets from the target's neutral.

* :func:`select_pca` (Chuang & Bregler 2005 §4.1): the frames with the largest and smallest
  projection on each principal axis in turn, from the first; an extreme within
  ``duplicate_mm`` (RMS per marker) of one already chosen is dropped (the one from the lower
  axis stays).
* :func:`select_affinity` (Huang et al. §5.2): affinity propagation (scikit-learn) on a sample
  of the frames with similarity ``-|x_i - x_j|^2`` and every preference the minimum similarity;
  then the two groups whose exemplars are closest are merged (the merged group's exemplar is its
  medoid) until ``count`` remain, or, with no count, until the reconstruction error jumps: the
  knee of the error-versus-count curve (the point farthest below the chord between its ends).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from facesynth.base.errors import InputError

from .solve import nnls_weights


@dataclass
class Selection:
    """Chosen key-shapes of one emotion.

    frames : (K,) int64 rows of the emotion's frames, in selection order; counts, errors : (n,)
    the key-shape counts tried and the frames' NNLS reconstruction RMS (mm per marker) with them.
    """

    frames: np.ndarray
    counts: np.ndarray
    errors: np.ndarray


def reconstruction_rms(frames: np.ndarray, shapes: np.ndarray) -> float:
    """RMS per marker (mm) of the frames' NNLS reconstruction from ``shapes`` (K, D)."""
    _, rms = nnls_weights(frames, shapes)
    return float(np.sqrt(np.mean(rms**2)))


def _sample(n: int, limit: int, rng: np.random.Generator) -> np.ndarray:
    return np.arange(n) if n <= limit else np.sort(rng.choice(n, limit, replace=False))


def select_pca(frames: np.ndarray, count: int, duplicate_mm: float, curve_frames: int, seed: int) -> Selection:
    """Chuang & Bregler's PCA extremes; see the module. frames : (N, D) displacements, mm."""
    x = np.asarray(frames, np.float64)
    if len(x) < 2:
        raise InputError("an emotion has fewer than two frames; key-shapes need more data.")
    centred = x - x.mean(0)
    _, _, vt = np.linalg.svd(centred, full_matrices=False)
    proj = centred @ vt.T
    n_points = x.shape[1] / 3
    chosen: list[int] = []
    for axis in range(proj.shape[1]):
        for row in (int(np.argmax(proj[:, axis])), int(np.argmin(proj[:, axis]))):
            if len(chosen) == count:
                break
            if chosen:
                gap = np.sqrt(((x[chosen] - x[row]) ** 2).sum(1) / n_points).min()
                if gap < duplicate_mm:
                    continue
            chosen.append(row)
        if len(chosen) == count:
            break
    rng = np.random.default_rng(seed)
    sample = x[_sample(len(x), curve_frames, rng)]
    counts = np.arange(1, len(chosen) + 1)
    errors = np.array([reconstruction_rms(sample, x[chosen[:k]]) for k in counts])
    return Selection(np.array(chosen, np.int64), counts, errors)


def knee(counts: np.ndarray, errors: np.ndarray) -> int:
    """The count at the knee of a decreasing error curve: farthest below the chord between its ends."""
    if len(counts) < 3:
        return int(counts[-1])
    c = (counts - counts[0]) / max(counts[-1] - counts[0], 1)
    e = (errors - errors.min()) / max(errors.max() - errors.min(), 1e-12)
    chord = e[0] + (e[-1] - e[0]) * c
    return int(counts[int(np.argmax(chord - e))])


#: Longest reconstruction-error curve of the automatic (knee) choice.
CURVE_MAX = 60


def _medoid(x: np.ndarray) -> int:
    sq = (x**2).sum(1)
    d = sq[:, None] + sq[None] - 2 * x @ x.T
    return int(np.argmin(d.sum(1)))


def select_affinity(frames: np.ndarray, count: int, affinity_frames: int, curve_frames: int, seed: int,
                    max_iter: int = 400) -> Selection:
    """Huang et al.'s affinity propagation with merging; see the module. count 0: stop at the knee."""
    from sklearn.cluster import AffinityPropagation

    x = np.asarray(frames, np.float64)
    if len(x) < 2:
        raise InputError("an emotion has fewer than two frames; key-shapes need more data.")
    rng = np.random.default_rng(seed)
    rows = _sample(len(x), affinity_frames, rng)
    s = x[rows]
    sq = (s**2).sum(1)
    sim = -np.maximum(sq[:, None] + sq[None] - 2 * s @ s.T, 0.0)
    preference = float(sim.min())
    labels = _propagate(sim, preference, max_iter, seed, AffinityPropagation)
    if count and len(np.unique(labels)) < count:
        # The minimum preference found fewer groups than asked: the median similarity (the
        # scikit-learn default) yields many more, which the merging then brings down to ``count``.
        labels = _propagate(sim, float(np.median(sim)), max_iter, seed, AffinityPropagation)
    groups = [np.flatnonzero(labels == g) for g in np.unique(labels)]
    exemplars = [int(g[_medoid(s[g])]) for g in groups]
    sample = x[_sample(len(x), curve_frames, rng)]
    history: list[tuple[int, list[int]]] = [(len(exemplars), list(exemplars))]
    while len(groups) > 1:
        e = s[exemplars]
        esq = (e**2).sum(1)
        d = esq[:, None] + esq[None] - 2 * e @ e.T
        d[np.diag_indices_from(d)] = np.inf
        i, j = np.unravel_index(int(np.argmin(d)), d.shape)
        i, j = min(i, j), max(i, j)
        merged = np.concatenate([groups[i], groups[j]])
        groups[i], exemplars[i] = merged, int(merged[_medoid(s[merged])])
        del groups[j], exemplars[j]
        history.append((len(exemplars), list(exemplars)))
    history.reverse()  # increasing counts, 1 to the groups found
    # The error curve runs to the count asked for, or to the groups affinity propagation found
    # (capped at CURVE_MAX: each point is an NNLS of the sample).
    top = min(count or len(history), CURVE_MAX if not count else count, len(history))
    history = history[:top]
    counts = np.array([h[0] for h in history])
    errors = np.array([reconstruction_rms(sample, s[h[1]]) for h in history])
    k = count if count else knee(counts, errors)
    pick = history[min(k, len(history)) - 1][1]
    keep = counts <= len(pick)
    return Selection(rows[np.array(pick, np.int64)], counts[keep], errors[keep])


def _propagate(sim: np.ndarray, preference: float, max_iter: int, seed: int, cls) -> np.ndarray:
    import warnings

    from sklearn.exceptions import ConvergenceWarning

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)
        model = cls(affinity="precomputed", preference=preference, damping=0.9, max_iter=max_iter,
                    convergence_iter=30, random_state=seed).fit(sim)
    labels = model.labels_
    if labels.min() < 0:  # did not converge: every frame its own exemplar is useless; fall back to nearest exemplar
        centres = model.cluster_centers_indices_
        if centres is None or len(centres) == 0:
            centres = np.array([int(np.argmax(sim.sum(1)))])
        labels = np.argmax(sim[:, centres], axis=1)
    return labels
