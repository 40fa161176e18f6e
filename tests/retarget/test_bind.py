"""Placing a capture's markers on the rig (facesynth.domain.retarget.bind): the sample corpus's markers,
whose true vertices markers.csv gives, moved by a random similarity, must land back on them."""

import csv

import numpy as np
import pytest
from scipy.spatial import cKDTree
from scipy.spatial.transform import Rotation

from facesynth.domain.geometry.rigid import similarity_fit, typical_frame
from facesynth.domain.retarget.bind import _icp, _start_rotations, axis_rotation, bind_markers, front_surface
from facesynth.domain.rig.face import load_face_rig
from facesynth.formats.mocap import read_mocap


def _truth(tiny_corpus):
    rows = list(csv.DictReader(open(tiny_corpus / "markers.csv")))
    return {r["marker"]: int(r["vertex"]) for r in rows}


def _moved(points, seed, scale):
    """points (N, 3) under a random rotation, ``scale`` and a far translation, and the rotation."""
    r = Rotation.random(random_state=seed).as_matrix()
    return scale * points @ r.T + np.array([300.0, -1200.0, 800.0]), r


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_markers_on_the_rig_are_recovered_after_a_random_similarity(tiny_corpus, seed):
    rig = load_face_rig()
    truth = _truth(tiny_corpus)
    names = list(truth)
    rng = np.random.default_rng(seed)
    points = rig.neutral[[truth[n] for n in names]] + rng.normal(0.0, 0.5, (len(names), 3))  # 0.5 mm noise
    moved, _ = _moved(points, seed, scale=rng.uniform(0.8, 1.25))
    binding = bind_markers(moved, names, rig.neutral, rig.faces, max_residual_mm=8.0)
    error = np.linalg.norm(rig.neutral[binding.vertices] - rig.neutral[[truth[n] for n in binding.names]], axis=1)
    assert binding.names == names and not binding.unbound
    assert np.median(error) < 0.5 and np.percentile(error, 95) < 2.0  # the rig's vertices lie 1-4 mm apart
    assert np.median(binding.residual_mm) < 1.0 and not binding.flagged.any()


def test_a_captured_frame_lands_near_the_true_vertices(tiny_corpus):
    """A real take of the actress (noise, gaps, her face moving) in a turned capture frame."""
    rig = load_face_rig()
    truth = _truth(tiny_corpus)
    take = read_mocap(sorted((tiny_corpus / "mocap").glob("neutral_*.c3d"))[0])
    frame = typical_frame(take.positions)
    moved, _ = _moved(take.positions[frame].astype(np.float64), 7, scale=1.1)
    binding = bind_markers(moved, take.names, rig.neutral, rig.faces, max_residual_mm=8.0)
    error = np.linalg.norm(rig.neutral[binding.vertices] - rig.neutral[[truth[n] for n in binding.names]], axis=1)
    assert np.median(error) < 1.5 and np.percentile(error, 95) < 8.0  # the moving lips and jaw stray most
    assert binding.fit.scale * 1.1 == pytest.approx(1.0, abs=0.05)


def test_given_axes_start_from_them(tiny_corpus):
    """A capture with z up and the face toward -y (a common mocap frame) binds with --up/--forward."""
    rig = load_face_rig()
    truth = _truth(tiny_corpus)
    names = list(truth)
    points = rig.neutral[[truth[n] for n in names]]
    to_capture = axis_rotation("+z", "-y").T  # rig -> capture
    captured = points @ to_capture.T
    binding = bind_markers(captured, names, rig.neutral, rig.faces, max_residual_mm=8.0, up="+z", forward="-y")
    assert binding.fit.start.startswith("up +z, forward -y")
    assert (binding.vertices == [truth[n] for n in names]).mean() > 0.95
    with pytest.raises(ValueError, match="not perpendicular"):
        axis_rotation("+z", "-z")


def test_a_marker_off_the_face_is_flagged_and_an_unseen_one_left_out(tiny_corpus):
    rig = load_face_rig()
    truth = _truth(tiny_corpus)
    names = list(truth)
    points = rig.neutral[[truth[n] for n in names]].copy()
    points[names.index("FH_T")] += [0.0, 40.0, 0.0]  # 40 mm above the head, like a headband marker
    points[names.index("CHIN_C")] = np.nan
    binding = bind_markers(points, names, rig.neutral, rig.faces, max_residual_mm=8.0)
    assert binding.unbound == ["CHIN_C"] and "CHIN_C" not in binding.names
    flagged = [n for n, f in zip(binding.names, binding.flagged) if f]
    assert flagged == ["FH_T"]
    assert binding.residual_mm[binding.names.index("FH_T")] > 20.0


def test_too_few_markers_are_refused():
    rig = load_face_rig()
    with pytest.raises(ValueError, match="only 3 markers are seen"):
        bind_markers(rig.neutral[:3], ["a", "b", "c"], rig.neutral, max_residual_mm=8.0)


def test_jaw_sides_keeps_markers_on_their_side_of_the_jaw():
    """A chin moving 20 mm with the jaw, a lower lip with it, an upper lip rising against it and a
    still forehead: the first two may take only vertices the rig's jaw carries, the others only
    vertices it does not; a cheek moving a third as much, half with the jaw, is left free."""
    from facesynth.domain.retarget.bind import jaw_sides

    rng = np.random.default_rng(0)
    opening = np.abs(np.sin(np.linspace(0, 12, 300)))  # (T,) 0..1
    down = np.array([0.0, -1.0, 0.0])
    d = np.zeros((300, 5, 3))
    d[:, 0] = 20.0 * opening[:, None] * down  # chin
    d[:, 1] = 16.0 * opening[:, None] * down  # lower lip
    d[:, 2] = -4.0 * opening[:, None] * down  # upper lip, rising
    d[:, 4] = (7.0 * (0.5 * opening + 0.5 * rng.random(300)))[:, None] * down  # cheek
    d += rng.normal(0, 0.1, d.shape)
    jaw_motion = np.array([0.0, 1.0, 20.0, 15.0, 5.0, 8.0])  # (V,): vertices 2, 3, 5 ride on the jaw (>= 35%)
    sides = jaw_sides(d, jaw_motion)
    assert sides[0].tolist() == sides[1].tolist() == [2, 3, 5]
    assert sides[2].tolist() == sides[3].tolist() == [0, 1, 4]
    assert sides[4] is None


def _icp_one_start(points, surface, tree, scale, rotation, keep, iterations, scale_bounds):
    """Trimmed ICP with scale from one start, step by step with :func:`similarity_fit` (what
    each start of the batched ICP must equal, bit for bit)."""
    t = surface.mean(0) - scale * rotation @ points.mean(0)
    n_keep = max(3, int(np.ceil(keep * len(points))))
    rms = np.inf
    for _ in range(iterations):
        dist, nearest = tree.query(scale * points @ rotation.T + t)
        best = np.argsort(dist)[:n_keep]
        new_rms = float(np.sqrt(np.mean(dist[best] ** 2)))
        s, r, _, _ = similarity_fit(points[best], surface[nearest[best]])
        scale, rotation = float(np.clip(s, *scale_bounds)), r
        t = surface[nearest[best]].mean(0) - scale * rotation @ points[best].mean(0)
        if abs(rms - new_rms) < 1e-6 * max(new_rms, 1e-12):
            break
        rms = new_rms
    dist, _ = tree.query(scale * points @ rotation.T + t)
    return scale, rotation, t, float(np.sqrt(np.mean(np.sort(dist)[:n_keep] ** 2)))


def test_the_starts_stepped_together_are_each_starts_own_icp(tiny_corpus):
    rig = load_face_rig()
    truth = _truth(tiny_corpus)
    points = _moved(rig.neutral[list(truth.values())], 3, scale=1.2)[0]
    surface = rig.neutral[front_surface(rig.neutral)].astype(np.float64)
    tree = cKDTree(surface)
    starts = _start_rotations(points)[::8]  # capture and principal axes, some far from the answer
    scales = np.array([0.7, 1.0, 1.4, 1.0, 0.7, 1.4][: len(starts)])
    together = _icp(points, surface, tree, scales, np.array([r for _, r in starts]), 0.8, 60, (0.3, 3.0))
    for k, (_, rotation) in enumerate(starts):
        alone = _icp_one_start(points, surface, tree, scales[k], rotation, 0.8, 60, (0.3, 3.0))
        assert together[0][k] == alone[0] and together[3][k] == alone[3]
        np.testing.assert_array_equal(together[1][k], alone[1])
        np.testing.assert_array_equal(together[2][k], alone[2])
