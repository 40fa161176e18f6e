import numpy as np
import pytest

from facesynth.domain.postprocess.concatenation import (
    concatenate,
    downsample,
    frame_ranges,
    interpolate,
    smooth_join,
    time_warp,
)


def test_smoothing_with_no_smoothness_weight_keeps_the_data():
    f = np.random.default_rng(0).normal(size=(6, 3))
    np.testing.assert_allclose(smooth_join(f, 2.0, 0.5, lam=0.0), f)


def test_strong_smoothing_fits_the_weighted_straight_line():
    f = np.array([0, 0, 0, 1, 1, 1], float)[:, None]
    g = smooth_join(f, 1.0, 1.0, lam=1e9)
    assert np.allclose(np.diff(g[:, 0], 2), 0.0, atol=1e-6)  # a line
    # weighted least-squares line through a symmetric step passes through its middle
    assert g[:, 0].mean() == pytest.approx(0.5)
    heavy_right = smooth_join(f, 0.5, 2.0, lam=1e9)  # Table IV: a high-visibility phone wins
    assert heavy_right[:, 0].mean() > 0.5


def test_time_warp_and_frame_grid():
    seq = np.arange(5, dtype=float)[:, None]
    out, src = time_warp(seq, 0, 5, 9)
    np.testing.assert_allclose(out[:, 0], np.linspace(0, 4, 9))
    assert src.tolist() == [0, 0, 1, 2, 2, 2, 3, 4, 4]  # nearest source frame (round half to even)
    assert frame_ranges(np.array([0.0, 0.1]), np.array([0.1, 0.25]), 120.0) == [(0, 12), (12, 30)]


def test_silence_is_linear_between_its_boundaries():
    out = interpolate(np.array([0.0]), np.array([4.0]), 3, "linear")
    np.testing.assert_allclose(out[:, 0], [1.0, 2.0, 3.0])


def test_downsample_120_to_30_takes_every_fourth_frame():
    x = np.arange(13, dtype=float)
    assert downsample(x, 120.0, 30.0).tolist() == [0, 4, 8, 12]


def test_concatenation_regenerates_pauses_and_counts_provenance():
    coeffs = np.arange(20, dtype=np.float32)[:, None]  # two nodes: frames 0-9 and 10-19
    cat = concatenate(
        np.array([0, 0, 1]), ["pau", "aa", "b"], np.array([0.0, 0.1, 0.2]), np.array([0.1, 0.2, 0.3]),
        np.array([0, 10]), np.array([10, 10]), np.array([-1, 0]), ["aa", "b"], coeffs, rest=np.array([-5.0]),
        fps=100.0, half_window=3, lam=1.0, weight_of=lambda p: 1.0,
    )
    assert len(cat.coeffs) == 30
    assert (cat.node[:10] == -1).all() and (cat.node[10:20] == 0).all() and (cat.node[20:] == 1).all()
    # node 1's captured predecessor is node 0: the join is not smoothed, frames are copied
    assert not cat.smoothed.any()
    np.testing.assert_allclose(cat.coeffs[10:30, 0], np.arange(20))
    # the leading pause goes from the rest pose (-5) to the first spoken frame (0)
    np.testing.assert_allclose(cat.coeffs[:10, 0], -5 + 5 * np.arange(1, 11) / 11, atol=1e-5)
