"""The bilinear model (Chuang & Bregler §3) on data made from a known bilinear model."""

import numpy as np

from facesynth.domain.expression import bilinear


def _exact_data(rng, S=3, C=60, K=12, J=4):
    E = rng.normal(size=(S, S))
    W = rng.normal(size=(K, S, J))
    Cm = rng.normal(size=(C, J))
    return np.einsum("si,kij,cj->sck", E, W, Cm), E, W, Cm


def _model(rng, **kw):
    Y, *_ = _exact_data(rng, **kw)
    K = Y.shape[2]
    return bilinear.fit(Y, ["neutral", "happy", "sad"], np.zeros(K), np.eye(K), content_dim=4, max_iterations=50,
                        tolerance=1e-9), Y


def test_the_fit_reproduces_exactly_bilinear_data_and_its_error_never_rises():
    model, Y = _model(np.random.default_rng(0))
    fitted = np.einsum("si,kij,cj->sck", model.styles, model.W, np.zeros((Y.shape[1], 4)))  # shape check only
    assert fitted.shape == Y.shape
    assert model.errors[-1] < 1e-18 * max(1.0, float(np.mean(Y ** 2))) + 1e-20
    assert np.all(np.diff(model.errors) <= 1e-12)


def test_the_fit_error_falls_over_iterations_when_the_style_space_is_smaller_than_the_data():
    rng = np.random.default_rng(1)
    Y = rng.normal(size=(3, 40, 8))            # not bilinear at all: the fit can only approximate it
    model = bilinear.fit(Y, ["a", "b", "c"], np.zeros(8), np.eye(8), content_dim=2, max_iterations=30, tolerance=0.0)
    assert np.all(np.diff(model.errors) <= 1e-12)
    assert 0 < model.errors[-1] < np.mean(Y ** 2)


def test_analysis_recovers_the_style_of_frames_made_with_a_fitted_style():
    rng = np.random.default_rng(2)
    model, Y = _model(rng)
    for s in range(3):
        e, c = bilinear.analyze(model, Y[s], iterations=30, init="best_style")
        assert np.allclose(e, model.styles[s], atol=1e-6)
        assert np.allclose(bilinear.synthesize(model, e, c), Y[s], atol=1e-6)


def test_restyle_at_full_intensity_gives_the_same_content_in_the_target_style_and_zero_changes_nothing():
    rng = np.random.default_rng(3)
    model, Y = _model(rng)
    frames = Y[0].reshape(len(Y[0]), -1, 3)     # K = 12 components as 4 "markers" (identity basis)
    target = np.repeat(model.style("sad")[None], len(frames), 0)
    out, styles = bilinear.restyle(model, frames, target, np.ones(len(frames)), iterations=30, init="best_style")
    assert np.allclose(out.reshape(len(frames), -1), Y[2], atol=1e-4)
    assert np.allclose(styles, model.styles[0], atol=1e-6)
    same, _ = bilinear.restyle(model, frames, target, np.zeros(len(frames)), iterations=30, init="best_style")
    assert np.allclose(same, frames, atol=1e-5)
    half, _ = bilinear.restyle(model, frames, target, np.full(len(frames), 0.5), iterations=30, init="best_style")
    assert np.allclose(half.reshape(len(frames), -1), 0.5 * (Y[0] + Y[2]), atol=1e-4)   # Eq. 7 is linear in alpha


def test_restyle_leaves_frames_with_gaps_as_they_are():
    rng = np.random.default_rng(4)
    model, Y = _model(rng)
    frames = Y[0].reshape(len(Y[0]), -1, 3).copy()
    frames[5, 1, 0] = np.nan
    out, styles = bilinear.restyle(model, frames, np.repeat(model.style("happy")[None], len(frames), 0),
                                   np.ones(len(frames)), iterations=10)
    assert np.isnan(out[5, 1, 0]) and np.isnan(styles[5]).all()
    assert np.isfinite(out[[4, 6]]).all()


def test_warping_maps_each_phone_onto_the_reference_phone_linearly():
    markers = np.arange(100, dtype=float)[:, None, None] * np.ones((1, 2, 3))   # value = frame index, at 100 fps
    src = (np.array([0.0, 0.2]), np.array([0.2, 1.0]))     # phone 1 is 0.2 s, phone 2 is 0.8 s long
    ref = (np.array([0.0, 0.5]), np.array([0.5, 1.0]))     # both 0.5 s in the reference
    out = bilinear.warp_take(markers, 100.0, src, ref, np.array([0.25, 0.5, 0.75]))
    assert np.allclose(out[:, 0, 0], [10.0, 20.0, 60.0])
