import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from facesynth.domain.geometry.rigid import fill_gaps, rigid_align


def test_known_rotation_and_translation_are_recovered_exactly():
    rng = np.random.default_rng(0)
    reference = rng.normal(0, 40, (20, 3))
    reference -= reference[0]
    rotations = Rotation.random(50, random_state=3).as_matrix()
    translations = rng.normal(0, 300, (50, 3))
    frames = np.einsum("tij,mj->tmi", rotations, reference) + translations[:, None, :]
    normalized, r, t = rigid_align(frames, reference, origin=0, rigid=np.arange(20))
    np.testing.assert_allclose(normalized, np.broadcast_to(reference, normalized.shape), atol=1e-9)
    np.testing.assert_allclose(r, rotations, atol=1e-12)
    np.testing.assert_allclose(t, translations, atol=1e-12)
    assert np.allclose(np.linalg.det(r), 1.0)


def test_a_mirrored_frame_gives_a_rotation_not_a_reflection():
    rng = np.random.default_rng(1)
    reference = rng.normal(0, 40, (10, 3))
    reference -= reference[0]
    mirrored = reference * np.array([-1.0, 1.0, 1.0])
    _, r, _ = rigid_align(mirrored[None], reference, 0, np.arange(10))
    assert np.linalg.det(r[0]) == pytest.approx(1.0)


def test_frames_with_missing_markers_still_align():
    rng = np.random.default_rng(2)
    reference = rng.normal(0, 40, (15, 3))
    reference -= reference[0]
    rot = Rotation.from_euler("xyz", [10, -20, 5], degrees=True).as_matrix()
    frame = reference @ rot.T + 7.0
    frame[4] = np.nan
    normalized, r, _ = rigid_align(frame[None], reference, 0, np.arange(15))
    np.testing.assert_allclose(r[0], rot, atol=1e-9)
    assert np.isnan(normalized[0, 4]).all()


def test_short_gaps_are_filled_and_long_ones_reported():
    t = np.arange(100, dtype=float)
    track = np.stack([np.sin(t / 10), t, np.zeros_like(t)], 1)
    holed = track.copy()
    holed[10:14] = np.nan
    holed[50:80] = np.nan
    filled, long_runs = fill_gaps(holed, max_gap=8)
    np.testing.assert_allclose(filled[10:14], track[10:14], atol=2e-3)
    assert long_runs == [(50, 30)]
    assert np.isnan(filled[50:80]).all()
