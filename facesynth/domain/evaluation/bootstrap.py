"""Bootstrap confidence intervals over sentences (Efron & Tibshirani 1993, percentile method).

Every figure of ``facesynth evaluate`` is a statistic of a set of sentences (a pooled RMS, a
rate over tokens, a percentile over joins). Its interval resamples the sentences with
replacement, recomputes the statistic on each resample and takes the central ``confidence``
quantiles. Differences between two methods are *paired*: both statistics are computed on the
same resample of sentences, so the interval of ``A - B`` accounts for the sentences' shared
difficulty, and an interval that excludes 0 means one method is better on this corpus.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

Statistic = Callable[[np.ndarray], float]


def resamples(n: int, count: int, seed: int) -> np.ndarray:
    """(count, n) int64 indices: ``count`` resamples of ``n`` sentences with replacement."""
    return np.random.default_rng(seed).integers(0, n, size=(count, n))


def _summary(point: float, values: np.ndarray, confidence: float) -> dict:
    values = values[np.isfinite(values)]
    if not np.isfinite(point) or len(values) == 0:
        return {"value": None if not np.isfinite(point) else float(point), "low": None, "high": None}
    tail = 100.0 * (1.0 - confidence) / 2.0
    low, high = np.percentile(values, [tail, 100.0 - tail])
    return {"value": float(point), "low": float(low), "high": float(high)}


def interval(stat: Statistic, n: int, index: np.ndarray, confidence: float = 0.95) -> dict:
    """``stat`` (indices of sentences -> float) on all ``n`` sentences, with its percentile
    interval over the resamples ``index`` (B, n). Returns {value, low, high} (None where the
    statistic is undefined, e.g. no bilabial in any sentence)."""
    point = stat(np.arange(n))
    return _summary(point, np.array([stat(i) for i in index], float), confidence)


def pooled_percentile(values: list[np.ndarray], q: float) -> Statistic:
    """The statistic ``idx -> np.percentile(np.concatenate([values[i] for i in idx]), q)`` (linear
    interpolation, NumPy's default, to the last bit), computed from one sort of all the values
    rather than one per resample. A resample holds sentence ``i`` as often as ``idx`` draws it, so
    its sorted pool is the sorted pool of all values with each value repeated that many times,
    and an order statistic is found on cumulative counts, counted from the nearer end of the
    pool (the top for a 99th percentile, where only about 1% of it is read). ``values``: one
    1-D array per sentence; NaN where the resample holds no value, or holds a NaN."""
    sizes = np.array([np.size(v) for v in values], np.int64)
    pool = np.concatenate([np.asarray(v, float).ravel() for v in values]) if values else np.zeros(0)
    owner = np.repeat(np.arange(len(values)), sizes)
    order = np.argsort(pool, kind="stable")
    ordered, owner = pool[order], owner[order]
    fraction = np.true_divide(q, 100.0)
    from_top = fraction >= 0.5
    if from_top:
        ordered, owner = ordered[::-1], owner[::-1]
    nan_owners = np.unique(owner[np.isnan(ordered)])
    first_read = min(len(ordered), 2 * int(np.ceil(min(fraction, 1 - fraction) * len(ordered))) + 64)

    def nth(counts: np.ndarray, ranks: np.ndarray) -> np.ndarray:
        """The values at 0-based ``ranks`` from the pool's near end, repeated by ``counts``."""
        length = first_read
        while True:
            cumulative = np.cumsum(counts[owner[:length]])
            if length == len(ordered) or cumulative[-1] > ranks.max():
                return ordered[np.searchsorted(cumulative, ranks, side="right")]
            length = min(len(ordered), 2 * length)

    def stat(idx: np.ndarray) -> float:
        counts = np.bincount(np.asarray(idx), minlength=len(values))
        total = int(counts @ sizes)
        if total == 0 or counts[nan_owners].any():
            return float("nan")
        position = (total - 1) * fraction  # NumPy's virtual index for the linear method
        below = np.floor(position)
        t = position - below
        ranks = np.array([below, min(below + 1, total - 1)], np.int64)
        a, b = nth(counts, total - 1 - ranks if from_top else ranks)
        difference = b - a
        return float(b - difference * (1 - t) if t >= 0.5 else a + difference * t)  # NumPy's _lerp

    return stat


def paired_difference(stat_a: Statistic, stat_b: Statistic, n: int, index: np.ndarray, confidence: float = 0.95) -> dict:
    """``stat_a - stat_b`` on the same sentences and the same resamples; {value, low, high}."""
    point = stat_a(np.arange(n)) - stat_b(np.arange(n))
    return _summary(point, np.array([stat_a(i) - stat_b(i) for i in index], float), confidence)
