"""The numba kernels of the CPU fallback give the NumPy references' results, bit for bit: the
rasterizer's triangle ids and frames, the DP's phi, cost and path, the pair costs and the
pruned DP's column minima."""

import dataclasses

import numpy as np
import pytest

from facesynth.base.config import Config
from facesynth.domain.rendering import parts
from facesynth.domain.rendering.camera import Camera
from facesynth.domain.rendering.raster import NumbaRasterizer, NumpyRasterizer
from facesynth.domain.rig.face import load_face_rig
from facesynth.domain.search import pruned
from facesynth.domain.search.dp import dp_bounded, dp_numpy
from facesynth.domain.search.dp_numba import dp_bounded_numba, dp_numba
from facesynth.domain.search.pairs import transition_costs
from facesynth.domain.search.pairs_numba import block_numba, column_minima_numba, pairs_numba
from facesynth.model.motiondb import MotionDatabase


def _rig_frame(width, height, samples, **named):
    rig = load_face_rig()
    w = np.zeros(len(rig.shape_names))
    for name, value in named.items():
        w[rig.shape_index(name)] = value
    scene = parts.build_scene(rig.neutral, rig.faces)
    cam = Camera.fit(parts.frame_points(scene), width, height, 30.0, 25.0, 6.0).scaled(samples)
    points = scene.positions(rig.evaluate(w), np.array([[0.3, 0.1], [0.3, 0.1]]))
    normals = parts.vertex_normals(points, scene.faces, scene.incidence)
    return scene, cam.project(points), cam.directions(normals)


@pytest.mark.parametrize("samples", [1, 2, 3])
def test_numba_rasterizer_is_the_numpy_reference(samples):
    scene, screen, normals = _rig_frame(120, 96, samples, jawOpen=0.8, mouthSmile_L=0.4)
    args = (scene.faces, scene.albedo, scene.eye, 120, 96, samples)
    ref, new = NumpyRasterizer(*args), NumbaRasterizer(*args)
    image, expected = new.render(screen, normals), ref.render(screen, normals)
    assert (ref.ids >= 0).mean() > 0.2
    assert np.array_equal(new.triangle_ids(), ref.triangle_ids())
    assert np.array_equal(image, expected)


def test_numba_rasterizer_corner_cases():
    """Exact depth ties (the lowest id wins), both windings, degenerate, off-screen, behind the
    camera and non-finite triangles."""
    rng = np.random.default_rng(0)
    n_v, w, h = 300, 48, 40
    screen = np.c_[rng.uniform(-20, 116, n_v), rng.uniform(-16, 96, n_v), rng.choice([1.0, 1.5, 2.0], n_v),
                   np.zeros(n_v)].astype(np.float32)
    screen[:4, 2] = -1.0
    screen[4, 0], screen[5, 1], screen[6, 0] = np.nan, np.inf, -1e30
    faces = rng.integers(0, n_v, (200, 3))
    faces = np.concatenate([faces, faces[:40], faces[:20, ::-1], [[7, 7, 8]]])
    normals = np.c_[rng.normal(size=(n_v, 3)), np.zeros(n_v)].astype(np.float32)
    albedo = rng.uniform(0, 1, (n_v, 4)).astype(np.float32)
    eye = np.where(rng.random(n_v) < 0.3, rng.uniform(0.5, 1.0, n_v), -2.0).astype(np.float32)
    ref, new = NumpyRasterizer(faces, albedo, eye, w, h, 2), NumbaRasterizer(faces, albedo, eye, w, h, 2)
    with np.errstate(all="ignore"):
        expected = ref.render(screen, normals)
    assert np.array_equal(new.render(screen, normals), expected)
    assert np.array_equal(new.triangle_ids(), ref.triangle_ids())


def test_numba_dp_is_the_numpy_reference():
    rng = np.random.default_rng(1)
    for tc in (rng.integers(0, 4, (200, 200)).astype(np.float32),  # many exact ties
               np.where(rng.random((150, 150)) < 0.3, np.inf, rng.random((150, 150))).astype(np.float32)):
        obs = rng.integers(0, 3, (9, len(tc))).astype(np.float32)
        ref, new = dp_numpy(tc, obs), dp_numba(tc, obs)
        assert new.cost == ref.cost and np.array_equal(new.path, ref.path) and np.array_equal(new.phi, ref.phi)
        (b_ref, f_ref), (b_new, f_new) = dp_bounded(tc, obs, ref.cost + 1), dp_bounded_numba(tc, obs, ref.cost + 1)
        assert b_new.cost == b_ref.cost and np.array_equal(b_new.path, b_ref.path) and np.array_equal(f_new, f_ref)


def test_numba_pair_costs_and_pruned_scan_are_the_numpy_reference(tiny_db):
    db = MotionDatabase.read(tiny_db)
    s = dataclasses.replace(Config.load().settings("synthesize"), use_opencl=False)
    tc = transition_costs(db, s, False)
    rng = np.random.default_rng(2)
    rows, cols = rng.integers(0, tc.n, 200), rng.integers(0, tc.n, 200)
    linked = np.nonzero(tc.pre >= 0)[0][:10]
    cols[:10], rows[:10] = linked, tc.pre[linked]  # rule 1 among them
    assert np.array_equal(block_numba(tc, rows, cols), tc.block_numpy(rows, cols))
    assert np.array_equal(pairs_numba(tc, rows, cols), tc.pairs_numpy(rows, cols))
    obs = rng.uniform(0, 50, (8, tc.n)).astype(np.float32)
    for backward in (False, True):
        phi = np.sort(rng.uniform(0, 30, tc.n)).astype(np.float32)
        order = rng.permutation(tc.n).astype(np.int32)
        init = np.where(rng.random(tc.n) < 0.5, np.inf, 40.0).astype(np.float32)
        ref, _ = pruned._column_minima_numpy(tc, order, phi, np.arange(tc.n, dtype=np.int32), init, backward)
        new, _ = column_minima_numba(tc, order, phi, np.arange(tc.n, dtype=np.int32), init, backward)
        assert np.array_equal(new, ref)
    ref = dp_numpy(tc.block_numpy(np.arange(tc.n), np.arange(tc.n)), obs)
    new = dp_numba(block_numba(tc, np.arange(tc.n), np.arange(tc.n)), obs)
    assert new.cost == ref.cost and np.array_equal(new.path, ref.path)
