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
from dataclasses import dataclass

import numpy as np

Statistic = Callable[[np.ndarray], float]

#: Resamples :func:`pooled_percentile` works on at once, bounding its (resamples, 2, sentences) work arrays.
RESAMPLES_PER_BLOCK = 256


@dataclass(frozen=True)
class ResampledStatistic:
    """A :data:`Statistic` computed on many resamples at once: ``of_resamples`` maps the sentence
    indices (B, n) of B resamples to their (B,) float statistics (NaN where undefined), each as the
    statistic of that row alone would be. Called with the indices (n,) of one resample, it is that
    row's statistic as a float."""

    of_resamples: Callable[[np.ndarray], np.ndarray]

    def __call__(self, idx: np.ndarray) -> float:
        return float(self.of_resamples(np.asarray(idx)[None, :])[0])


def resamples(n: int, count: int, seed: int) -> np.ndarray:
    """(count, n) int64 indices: ``count`` resamples of ``n`` sentences with replacement."""
    return np.random.default_rng(seed).integers(0, n, size=(count, n))


def resample_counts(index: np.ndarray, n: int) -> np.ndarray:
    """(B, n) int64: how often each of the B resamples ``index`` (B, k) draws each of ``n`` sentences."""
    index = np.asarray(index, np.int64)
    rows = index.shape[0]
    offsets = n * np.arange(rows, dtype=np.int64)[:, None]
    return np.bincount((index + offsets).ravel(), minlength=rows * n).reshape(rows, n)


def on_resamples(stat: Statistic, index: np.ndarray) -> np.ndarray:
    """(B,) float: ``stat`` on each resample of ``index`` (B, n), all at once where it is a
    :class:`ResampledStatistic`, else one resample after the other."""
    if isinstance(stat, ResampledStatistic):
        return np.asarray(stat.of_resamples(np.asarray(index)), float)
    return np.array([stat(i) for i in index], float)


def pooled_means(values: list[np.ndarray], index: np.ndarray) -> np.ndarray:
    """The mean of ``np.concatenate([values[i] for i in idx])`` for every resample ``idx`` of
    ``index`` (..., n), shape (...): NumPy's mean of that concatenation to the last bit (its
    pairwise sum runs over the concatenation in draw order, so resamples are summed in groups of
    equal length, each row as one contiguous array). ``values``: one 1-D array per sentence; NaN
    where a resample holds no value."""
    index = np.asarray(index, np.int64)
    draws = index.reshape(int(np.prod(index.shape[:-1])), index.shape[-1])
    sizes = np.array([np.size(v) for v in values], np.int64)
    pool = np.concatenate([np.asarray(v, float).ravel() for v in values]) if values else np.zeros(0)
    first = np.cumsum(sizes) - sizes                    # (n,) where each sentence's values start in the pool
    drawn = sizes[draws].ravel()                        # values of every draw, resample after resample
    lengths = sizes[draws].sum(axis=1)                  # (B,) values in each resample
    # every resample's concatenation, one after the other: the k-th value comes from pool position
    # first[sentence] + (k - the number of values drawn before its draw)
    positions = np.repeat(first[draws].ravel() - (np.cumsum(drawn) - drawn), drawn) + np.arange(drawn.sum())
    row = np.repeat(np.arange(len(draws)), lengths)
    column = np.arange(len(row)) - np.repeat(np.cumsum(lengths) - lengths, lengths)
    padded = np.zeros((len(draws), int(lengths.max()) if len(lengths) else 0))
    padded[row, column] = pool[positions]
    means = np.full(len(draws), np.nan)
    for length in np.unique(lengths[lengths > 0]):
        same = np.nonzero(lengths == length)[0]
        means[same] = padded[same, :length].sum(axis=1) / length
    return means.reshape(index.shape[:-1])


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
    return _summary(point, on_resamples(stat, index), confidence)


def pooled_percentile(values: list[np.ndarray], q: float) -> ResampledStatistic:
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

    held_by_length: dict[int, np.ndarray] = {}

    def held_up_to(length: int) -> np.ndarray:
        """(length, len(values)) int64: per pool position from the near end, how many of each
        sentence's values lie up to it (computed once per length)."""
        if length not in held_by_length:
            held = np.zeros((length, len(values)), np.int64)
            held[np.arange(length), owner[:length]] = 1
            held_by_length[length] = np.cumsum(held, axis=0)
        return held_by_length[length]

    def nth(counts: np.ndarray, ranks: np.ndarray) -> np.ndarray:
        """The values (B, 2) at 0-based ``ranks`` (B, 2) from the pool's near end, the pool of
        resample b repeated by ``counts`` (B, len(values)). The cumulative count of resample b at
        pool position j is ``held[j] @ counts[b]``, ``held`` (length, len(values)) counting each
        sentence's values up to j; a binary search per rank finds the first position whose count
        passes it, reading only as far from the near end as the highest rank needs."""
        found = np.empty(ranks.shape, np.int64)
        pending = np.arange(len(counts))
        length = first_read
        while len(pending):
            held = held_up_to(length)
            done = (held[-1] @ counts[pending].T > ranks[pending].max(axis=1)) | (length == len(ordered))
            rows = pending[done]
            row_counts, row_ranks = counts[rows][:, None, :], ranks[rows]
            low, high = np.zeros(row_ranks.shape, np.int64), np.full(row_ranks.shape, length, np.int64)
            while (low < high).any():  # low: positions whose cumulative count is at most the rank, so far
                middle = (low + high) // 2
                at_most = (held[np.minimum(middle, length - 1)] * row_counts).sum(axis=2) <= row_ranks
                searching = low < high
                low = np.where(searching & at_most, middle + 1, low)
                high = np.where(searching & ~at_most, middle, high)
            found[rows] = low  # np.searchsorted(cumulative, rank, side="right")
            pending = pending[~done]
            length = min(len(ordered), 2 * length)
        return ordered[found]

    def of_resamples(index: np.ndarray) -> np.ndarray:
        out = np.full(len(index), np.nan)
        for block in range(0, len(index), RESAMPLES_PER_BLOCK):
            counts = resample_counts(index[block:block + RESAMPLES_PER_BLOCK], len(values))
            total = counts @ sizes
            defined = (total > 0) & ~counts[:, nan_owners].any(axis=1)
            counts, total = counts[defined], total[defined]
            position = (total - 1) * fraction  # NumPy's virtual index for the linear method
            below = np.floor(position)
            t = position - below
            ranks = np.stack([below, np.minimum(below + 1, total - 1)], axis=1).astype(np.int64)
            a, b = nth(counts, total[:, None] - 1 - ranks if from_top else ranks).T
            difference = b - a
            with np.errstate(invalid="ignore"):  # the branch np.where does not take may be inf - inf
                value = np.where(t >= 0.5, b - difference * (1 - t), a + difference * t)  # NumPy's _lerp
            out[np.arange(block, block + len(defined))[defined]] = value
        return out

    return ResampledStatistic(of_resamples)


def paired_difference(stat_a: Statistic, stat_b: Statistic, n: int, index: np.ndarray, confidence: float = 0.95) -> dict:
    """``stat_a - stat_b`` on the same sentences and the same resamples; {value, low, high}."""
    point = stat_a(np.arange(n)) - stat_b(np.arange(n))
    return _summary(point, on_resamples(stat_a, index) - on_resamples(stat_b, index), confidence)
