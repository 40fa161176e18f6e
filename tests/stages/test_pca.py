import numpy as np
import pytest

from facesynth.stages.pca import fit_pca


def _low_rank(n=400, m=10, k=4, seed=0):
    rng = np.random.default_rng(seed)
    latent = rng.normal(size=(n, k)) * np.array([10.0, 5.0, 2.0, 1.0])
    mixing = np.linalg.qr(rng.normal(size=(3 * m, k)))[0].T
    return (latent @ mixing + rng.normal(size=3 * m) * 30).reshape(n, m, 3)


def test_rank_k_data_is_reconstructed_exactly_with_k_components():
    frames = _low_rank()
    model = fit_pca(frames, n_components=4)
    assert model.explained == pytest.approx(1.0)
    np.testing.assert_allclose(model.reconstruct(model.project(frames)), frames, atol=1e-3)
    np.testing.assert_allclose(model.basis.T @ model.basis, np.eye(4), atol=1e-10)


def test_fewer_components_leave_the_expected_residual():
    frames = _low_rank()
    model = fit_pca(frames, n_components=3)
    residual = frames - model.reconstruct(model.project(frames))
    # The dropped component has standard deviation 1, so the mean squared residual per frame is ~1.
    assert np.mean(np.sum(residual.reshape(len(frames), -1) ** 2, axis=1)) == pytest.approx(1.0, rel=0.15)


def test_variance_target_picks_the_fewest_components():
    model = fit_pca(_low_rank(), n_components=25, variance_target=0.95)
    assert model.basis.shape[1] == 2  # 100 + 25 = 125 of 130 units of variance


def test_frames_with_missing_markers_are_projected_from_the_visible_ones():
    frames = _low_rank()
    model = fit_pca(frames, n_components=4)
    holed = frames[:5].copy()
    holed[:, 2] = np.nan
    np.testing.assert_allclose(model.project(holed), model.project(frames[:5]), atol=1e-3)
