"""The bootstrap's pooled percentile equals NumPy's percentile of the concatenated resample."""

import numpy as np
import pytest

from facesynth.domain.evaluation.bootstrap import interval, pooled_percentile, resamples


@pytest.mark.parametrize("q", [0.0, 2.5, 33.3, 49.9, 50.0, 97.5, 99.0, 100.0])
def test_pooled_percentile_is_numpys_percentile_of_the_resample(q):
    rng = np.random.default_rng(7)
    values = [rng.normal(size=size) * scale for size, scale in [(0, 1.0), (40, 0.01), (300, 1.0), (7, 100.0)]]
    values.append(np.round(rng.normal(size=120), 1))  # ties
    stat = pooled_percentile(values, q)
    for idx in resamples(len(values), 200, 3):
        pooled = np.concatenate([values[i] for i in idx])
        expected = np.percentile(pooled, q) if len(pooled) else np.nan
        assert stat(idx) == expected or (np.isnan(expected) and np.isnan(stat(idx)))


def test_pooled_percentile_is_nan_without_values_or_with_a_nan():
    stat = pooled_percentile([np.zeros(0), np.array([1.0, np.nan]), np.array([2.0, 3.0])], 99.0)
    assert np.isnan(stat(np.array([0, 0])))
    assert np.isnan(stat(np.array([1, 2])))
    assert stat(np.array([2, 0])) == np.percentile([2.0, 3.0], 99.0)
    summary = interval(stat, 3, resamples(3, 100, 0))
    assert summary["value"] is None and summary["low"] is None
