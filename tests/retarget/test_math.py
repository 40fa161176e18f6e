"""The retargeting cores on arrays built here: NNLS weights, key-shape selection, the bounded
solves and deformation-gradient blending."""

from __future__ import annotations

import numpy as np
import pytest
from meshes import grid
from scipy.optimize import nnls

from facesynth.domain.retarget.gradients import GradientBlender, _exp
from facesynth.domain.retarget.keyshapes import knee, select_affinity, select_pca
from facesynth.domain.retarget.retarget import decompose, emotion_blend
from facesynth.domain.retarget.solve import fit_rig_weights, nnls_weights, solve_curves


def test_nnls_on_the_gram_factor_matches_scipy_on_the_full_system():
    rng = np.random.default_rng(0)
    shapes = rng.normal(size=(6, 60))
    frames = rng.normal(size=(40, 60))
    w, rms = nnls_weights(frames, shapes)
    for i in (0, 7, 39):
        ref, _ = nnls(shapes.T, frames[i])
        np.testing.assert_allclose(w[i], ref, atol=1e-7)
    assert (w >= 0).all()
    np.testing.assert_allclose(rms, np.sqrt(((frames - w @ shapes) ** 2).sum(1) / 20))


@pytest.mark.parametrize("stragglers, k", [(0, 12), (8, 12), (8, 40)])  # 0: block pivoting to the end; 40: per frame
def test_batched_block_pivoting_nnls_matches_scipy_frame_by_frame(stragglers, k):
    # Many frames, key-shapes that overlap (a near-duplicate pair) and sparse true mixtures: the
    # solver (batched up to BATCHED_MAX_SHAPES key-shapes, else per frame) lands on scipy's
    # minimizer for every frame.
    from facesynth.domain.retarget.solve import BATCHED_MAX_SHAPES, nnls_gram

    assert (k <= BATCHED_MAX_SHAPES) == (k == 12)
    rng = np.random.default_rng(10)
    shapes = rng.normal(size=(k, 90)) + 1.0
    shapes[7] = shapes[3] + rng.normal(scale=1e-3, size=90)
    mix = rng.uniform(0, 1, (300, k)) * (rng.uniform(size=(300, k)) < 0.2)
    frames = mix @ shapes + rng.normal(scale=0.5, size=(300, 90))
    frames[:50] = rng.normal(scale=3.0, size=(50, 90))  # frames far from the cone: many zeros
    w = nnls_gram(shapes @ shapes.T, frames @ shapes.T, stragglers=stragglers)
    ref = np.array([nnls(shapes.T, f, maxiter=2000)[0] for f in frames])
    assert (w >= 0).all()
    obj = ((frames - w @ shapes) ** 2).sum(1)
    ref_obj = ((frames - ref @ shapes) ** 2).sum(1)
    np.testing.assert_allclose(obj, ref_obj, rtol=1e-9, atol=1e-9)
    keep = np.setdiff1d(np.arange(k), [3, 7])  # the near-duplicate pair may split its weight differently
    np.testing.assert_allclose(w[:, keep], ref[:, keep], atol=1e-6)


def test_nnls_recovers_non_negative_mixtures_and_skips_missing_coordinates():
    rng = np.random.default_rng(1)
    shapes = rng.normal(size=(4, 30))
    truth = rng.uniform(0, 1, size=(10, 4))
    frames = truth @ shapes
    frames[3, :6] = np.nan
    w, rms = nnls_weights(frames, shapes)
    np.testing.assert_allclose(w, truth, atol=1e-6)
    assert rms.max() < 1e-6


def test_pca_extremes_take_the_ends_of_the_first_axes_and_drop_near_duplicates():
    # Frames along x (long axis) and y (short axis): the extremes are the four tips; a copy of a
    # tip 0.1 mm away is a near-duplicate.
    x = np.zeros((9, 3))
    x[:, 0] = [-10, -5, 0, 5, 10, 0, 0, 0, 10.1]
    x[5:8, 1] = [-3, 3, 0]
    sel = select_pca(x, 4, duplicate_mm=1.0, curve_frames=100, seed=0)
    assert set(sel.frames.tolist()) in ({8, 0, 6, 5}, {0, 8, 6, 5})
    assert len(set(sel.frames.tolist()) & {4, 8}) == 1
    assert list(sel.counts) == [1, 2, 3, 4] and sel.errors[-1] <= sel.errors[0]


def test_knee_is_where_the_error_stops_falling_fast():
    counts = np.arange(1, 11)
    errors = np.array([10, 6, 3, 1.2, 1.0, 0.9, 0.85, 0.8, 0.78, 0.75])
    assert knee(counts, errors) == 4


def test_affinity_propagation_finds_well_separated_groups_and_merging_reaches_the_count():
    rng = np.random.default_rng(2)
    centres = rng.normal(scale=20, size=(5, 6))
    x = np.concatenate([c + rng.normal(scale=0.3, size=(40, 6)) for c in centres])
    sel = select_affinity(x, 3, affinity_frames=200, curve_frames=200, seed=0)
    assert len(sel.frames) == 3
    auto = select_affinity(x, 0, affinity_frames=200, curve_frames=200, seed=0)
    assert 2 <= len(auto.frames) <= 6
    assert np.all(np.diff(auto.errors) <= 1e-9)


def test_rig_weights_fit_is_bounded_and_exact_inside_the_bounds():
    rng = np.random.default_rng(3)
    basis = rng.normal(size=(5, 45))
    truth = np.array([[0.2, 0.0, 0.7, 1.0, 0.4]])
    w, rms = fit_rig_weights(truth @ basis, basis)
    np.testing.assert_allclose(w, truth, atol=1e-6)
    w, _ = fit_rig_weights(3 * truth @ basis, basis)
    assert w.min() >= 0 and w.max() <= 1


def test_direct_solve_recovers_weights_and_smoothness_damps_a_single_frame_spike():
    rng = np.random.default_rng(4)
    basis = rng.normal(size=(6, 10, 3))
    t = np.linspace(0, 1, 40)
    truth = np.clip(np.stack([0.5 + 0.4 * np.sin(2 * np.pi * (t + k / 6)) for k in range(6)], 1), 0, 1)
    frames = np.einsum("te,emc->tmc", truth, basis)
    w, rms, _ = solve_curves(frames, basis, smooth=0.0, ridge=0.0, iterations=20000, tolerance=1e-10)
    np.testing.assert_allclose(w, truth, atol=1e-4)
    spiked = frames.copy()
    spiked[20] += basis[0] * 0.5
    free, _, _ = solve_curves(spiked, basis, smooth=0.0, ridge=0.0, iterations=20000, tolerance=1e-10)
    smooth, _, _ = solve_curves(spiked, basis, smooth=0.5, ridge=0.0, iterations=20000, tolerance=1e-10)
    assert abs(smooth[20, 0] - truth[20, 0]) < abs(free[20, 0] - truth[20, 0])
    spiked[5, 2] = np.nan
    w, rms, _ = solve_curves(spiked, basis, smooth=0.0, ridge=0.0, iterations=200, tolerance=1e-6)
    assert np.isfinite(w).all() and np.isfinite(rms).all()


def test_emotion_blend_prefers_the_set_that_fits_and_a_fixed_emotion_is_used_alone():
    residual = np.array([[0.1, 2.0], [0.1, 2.0], [2.0, 0.1]])
    p = emotion_blend(residual, 0.5, 1)
    assert p[0, 0] > 0.99 and p[2, 1] > 0.99
    shapes = [np.eye(3)[:2], np.eye(3)[1:]]
    r = decompose(np.array([[1.0, 0.5, 0.0]]), shapes, 0.5, 1, fixed=1)
    np.testing.assert_allclose(r.emotion_weights, [[0.0, 1.0]])
    assert r.alpha.shape == (1, 4) and np.allclose(r.alpha[0, :2], 0)


def test_rodrigues_matches_scipy():
    from scipy.spatial.transform import Rotation

    r = np.random.default_rng(5).normal(size=(50, 3))
    r[:5] *= 1e-7
    np.testing.assert_allclose(_exp(r), Rotation.from_rotvec(r).as_matrix(), atol=1e-12)


def _strip(n: int = 6):
    """A strip of 2n triangles along x, in the z = 0 plane (mm)."""
    xs = np.arange(n + 1, dtype=float)
    rest = np.concatenate([np.stack([xs, np.zeros_like(xs), np.zeros_like(xs)], 1),
                           np.stack([xs, np.ones_like(xs), np.zeros_like(xs)], 1)])
    faces = []
    for i in range(n):
        a, b, c, d = i, i + 1, n + 1 + i, n + 2 + i
        faces += [(a, b, d), (a, d, c)]
    return rest, np.array(faces)


def test_gradient_blending_reproduces_each_example_and_the_rest():
    rest, faces = _strip()
    rng = np.random.default_rng(6)
    examples = rest + rng.normal(scale=0.1, size=(2,) + rest.shape)
    blender = GradientBlender(rest, faces, examples)
    out = blender.blend(np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]))
    np.testing.assert_allclose(out[0], rest, atol=1e-4)
    np.testing.assert_allclose(out[1], examples[0], atol=1e-4)
    np.testing.assert_allclose(out[2], examples[1], atol=1e-4)


def test_gradient_blending_keeps_lengths_where_linear_blending_shrinks_a_rotation():
    # A jaw-like example: the strip bent by 90 degrees about the y axis at its root. Half of it
    # linearly is a chord that shrinks the strip; blended gradients rotate by 45 degrees instead.
    rest, faces = _strip()
    from scipy.spatial.transform import Rotation

    bent = Rotation.from_rotvec([0, -np.pi / 2, 0]).apply(rest)
    blender = GradientBlender(rest, faces, bent[None])
    half = np.array([[0.5]])
    lin, grad = blender.linear(half)[0], blender.blend(half)[0]
    n = len(rest) // 2

    def length(v):
        return np.linalg.norm(np.diff(v[:n], axis=0), axis=1).sum()

    assert length(rest) == pytest.approx(6.0)
    assert length(lin) == pytest.approx(6.0 * np.cos(np.pi / 4), rel=1e-3)
    assert length(grad) == pytest.approx(6.0, rel=5e-3)  # the small pull toward the linear blend costs ~0.2%


def test_newton_polar_decomposition_matches_the_svd_route():
    from scipy.spatial.transform import Rotation

    from facesynth.domain.retarget.gradients import _polar, _polar_svd

    rng = np.random.default_rng(7)
    n = 400
    rot = Rotation.from_rotvec(rng.normal(size=(n, 3)) * rng.uniform(0, 1.2, (n, 1))).as_matrix()
    rot[:5] = Rotation.from_rotvec(rng.normal(size=(5, 3)) * 1e-7).as_matrix()  # tiny rotations
    rot[5:10] = Rotation.from_rotvec(np.eye(3)[rng.integers(0, 3, 5)] * 3.0).as_matrix()  # near pi
    q = Rotation.random(n, random_state=8).as_matrix()
    stretch = q @ (rng.uniform(0.3, 3.0, (n, 3))[:, :, None] * np.swapaxes(q, 1, 2))
    f = rot @ stretch
    f[10] = np.diag([1.0, 1.0, -0.5])  # inverted
    f[11] = np.diag([1.0, 1.0, 0.0])  # collapsed
    rv, s = _polar(f.reshape(20, 20, 3, 3))
    ref_rv, ref_s = _polar_svd(f)
    np.testing.assert_allclose(rv.reshape(-1, 3), ref_rv, atol=1e-10)
    np.testing.assert_allclose(s.reshape(-1, 3, 3), ref_s, atol=1e-10)
    np.testing.assert_allclose(rv.reshape(-1, 3)[12:], Rotation.from_matrix(rot[12:]).as_rotvec(), atol=1e-10)


def _reference_blend(rest, faces, examples, anchor, alpha):
    """The formulation of the module docstring written out frame by frame: SVD polar factors,
    scipy's rotations, one sparse solve per frame (float64 throughout)."""
    from scipy import sparse
    from scipy.sparse.linalg import spsolve
    from scipy.spatial.transform import Rotation

    from facesynth.domain.retarget.gradients import _frames, _polar_svd

    rf = _frames(rest, faces)
    grads = _frames(examples, faces) @ np.linalg.inv(rf)
    rv, s = _polar_svd(grads.reshape(-1, 3, 3))
    rv, s = rv.reshape(len(examples), -1, 3), s.reshape(len(examples), -1, 3, 3)
    n_f, n_v = len(faces), len(rest)
    e = sparse.lil_matrix((2 * n_f, n_v))
    for f, (a, b, c) in enumerate(faces):
        e[2 * f, a], e[2 * f, b], e[2 * f + 1, a], e[2 * f + 1, c] = -1, 1, -1, 1
    e = e.tocsr()
    lam = anchor * float((rf[:, :, :2] ** 2).sum(1).mean())
    normal = (e.T @ e + lam * sparse.identity(n_v)).tocsc()
    out = []
    for w in alpha:
        rot = Rotation.from_rotvec(np.tensordot(w, rv, 1)).as_matrix()
        stretch = np.eye(3) + np.tensordot(w, s - np.eye(3), 1)
        target = (rot @ stretch @ rf[:, :, :2]).transpose(0, 2, 1).reshape(2 * n_f, 3)
        lin = rest + np.tensordot(w, examples - rest, 1)
        out.append(spsolve(normal, e.T @ target + lam * lin))
    return np.array(out)


@pytest.mark.parametrize("use_opencl", [False, True], ids=["numpy", "opencl"])
def test_blocked_gradient_blend_matches_the_frame_by_frame_formulation(use_opencl):
    from scipy.spatial.transform import Rotation

    from facesynth.base.opencl import use_opencl as device_builds

    if use_opencl and not device_builds():
        pytest.skip("no OpenCL device builds kernels here")
    rest, faces = grid(7)
    rng = np.random.default_rng(9)
    bend = Rotation.from_rotvec([0, -1.2, 0]).apply(rest - [3, 0, 0]) + [3, 0, 0]
    examples = np.stack([rest + rng.normal(scale=0.2, size=rest.shape), bend,
                         rest * [1.3, 0.8, 1.0], rest + rng.normal(scale=0.1, size=rest.shape)])
    alpha = rng.uniform(0, 1, (19, 4))  # more frames than one back-substitution takes
    alpha[:, 3] = 0.0  # a key-shape no frame uses
    alpha[4] = 0.0
    blender = GradientBlender(rest, faces, examples, anchor=1e-3, block=13, use_opencl=use_opencl)  # odd blocks
    assert blender.use_opencl == use_opencl
    blender.GROUP_FRAMES = 12  # two groups of frames (the kernels pad 12 and 7 to 16 and 8); solves of 8 and 4
    # 5e-5 mm: the right-hand sides and the back-substitutions are float32 (of the departures from
    # the linear blend, up to 0.93 mm here; 1.3e-5 mm off). On the full rig with real key-shapes the departures are
    # smaller and the error (8.5e-6 mm against float64) is that of storing the vertices as float32.
    np.testing.assert_allclose(blender.blend(alpha), _reference_blend(rest, faces, examples, 1e-3, alpha), atol=5e-5)
    np.testing.assert_allclose(blender.linear(alpha), rest + np.tensordot(alpha, examples - rest, 1), atol=1e-5)
    assert blender.blend(alpha[:0]).shape == blender.linear(alpha[:0]).shape == (0, len(rest), 3)
