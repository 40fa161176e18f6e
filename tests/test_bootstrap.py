"""The bootstrap's pooled percentile equals NumPy's percentile of the concatenated resample."""

import numpy as np
import pytest

from facesynth.domain.evaluation.bootstrap import (
    ResampledStatistic,
    interval,
    on_resamples,
    pooled_means,
    pooled_percentile,
    resamples,
)


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


def test_pooled_means_are_numpys_mean_of_the_resample():
    rng = np.random.default_rng(5)
    values = [rng.normal(size=size) * scale for size, scale in [(0, 1.0), (3, 0.01), (30, 1.0), (9, 100.0), (1, 7.0)]]
    index = resamples(len(values), 300, 4)
    means = pooled_means(values, index)
    assert means.shape == (300,)
    for idx, mean in zip(index, means):
        pooled = np.concatenate([values[i] for i in idx])
        assert mean == np.mean(pooled) if len(pooled) else np.isnan(mean)
    assert np.isnan(pooled_means(values, np.array([0, 0])))


def test_a_resampled_statistic_gives_the_interval_of_its_one_by_one_form():
    rng = np.random.default_rng(2)
    data = rng.normal(size=25)
    index = resamples(len(data), 500, 1)
    at_once = ResampledStatistic(lambda idx: data[idx].mean(axis=-1))
    assert np.array_equal(on_resamples(at_once, index), [float(data[i].mean()) for i in index])
    assert interval(at_once, len(data), index) == interval(lambda i: float(data[i].mean()), len(data), index)
