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


def paired_difference(stat_a: Statistic, stat_b: Statistic, n: int, index: np.ndarray, confidence: float = 0.95) -> dict:
    """``stat_a - stat_b`` on the same sentences and the same resamples; {value, low, high}."""
    point = stat_a(np.arange(n)) - stat_b(np.arange(n))
    return _summary(point, np.array([stat_a(i) - stat_b(i) for i in index], float), confidence)
