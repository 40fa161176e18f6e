"""The join blend (continuous position and velocity), end-slope fits and the rigid head pose."""

import numpy as np
import pytest

from facesynth.domain.geometry.rigid import head_pose, procrustes_align
from facesynth.domain.postprocess.concatenation import blend_join, end_slope_weights, hermite


@pytest.mark.parametrize("length", [2, 3, 4, 7, 12])
def test_end_slope_is_exact_on_polynomials_it_can_fit(length):
    x = np.arange(length, dtype=float)
    w = end_slope_weights(length)
    assert w @ (3.0 + 0.5 * x) == pytest.approx(0.5)
    if length >= 4:
        assert w @ (1.0 - 2.0 * x + 0.25 * x * x) == pytest.approx(-2.0)


@pytest.mark.parametrize("share", [0.5, 0.2, 0.8])
def test_blend_closes_a_jump_in_position_and_velocity(share):
    t = np.arange(60.0)
    f = np.where(t < 30, 0.1 * t, 5.0 + 0.3 * (t - 30))[:, None] * np.array([[1.0, -2.0]])
    g = f.copy()
    blend_join(g, 18, 30, 42, share)
    assert np.array_equal(g[:18], f[:18]) and np.array_equal(g[42:], f[42:])  # outside the window: untouched
    d1, d2 = np.diff(g, axis=0), np.diff(g, 2, axis=0)
    assert np.abs(d2).max() < 0.1 * np.abs(np.diff(f, 2, axis=0)).max()  # the pop is gone
    assert d1[29] == pytest.approx(d1[28], abs=0.05) and d1[29] == pytest.approx(d1[30], abs=0.05)  # was a 0.2 and 0.4 jump
    # the heavier side (smaller share) moves less
    left, right = np.abs(g[18:30] - f[18:30]).max(), np.abs(g[30:42] - f[30:42]).max()
    assert (left < right) == (share < 0.5) or share == 0.5


def test_hermite_meets_both_ends_with_their_velocities():
    left, right = np.array([0.0, 1.0]), np.array([4.0, -1.0])
    v0, v1 = np.array([0.5, 0.0]), np.array([-0.25, 0.1])
    mid = hermite(left, right, v0, v1, 200)
    assert mid[0] - left == pytest.approx(v0, abs=1e-2) and right - mid[-1] == pytest.approx(v1, abs=1e-2)


def _cloud(rng, m=12):
    return rng.normal(0, 40, (m, 3))


def test_procrustes_recovers_a_pose_from_the_rigid_markers_only():
    rng = np.random.default_rng(0)
    ref = _cloud(rng)
    angle = 0.3
    r = np.array([[np.cos(angle), -np.sin(angle), 0], [np.sin(angle), np.cos(angle), 0], [0, 0, 1]])
    t = np.array([5.0, -2.0, 1.0])
    face = ref.copy()
    face[6:] += rng.normal(0, 8, (6, 3))  # speech moves the non-rigid markers
    frames = (face @ r.T + t)[None]
    normalized, rot, trans = procrustes_align(frames, ref, np.arange(6))
    assert rot[0] == pytest.approx(r, abs=1e-9) and trans[0] == pytest.approx(t, abs=1e-9)
    assert normalized[0] == pytest.approx(face, abs=1e-9)
    assert frames[0] == pytest.approx(normalized[0] @ rot[0].T + trans[0], abs=1e-9)
    # on every marker, the speech motion leaks into the pose
    _, rot_all, _ = procrustes_align(frames, ref, np.arange(12))
    assert not np.allclose(rot_all[0], r, atol=1e-3)


def test_weights_follow_the_residuals():
    rng = np.random.default_rng(1)
    ref = _cloud(rng, 8)
    frames = np.repeat(ref[None], 50, axis=0) + rng.normal(0, 0.05, (50, 8, 3))
    frames[:, 0] += rng.normal(0, 3.0, (50, 3))  # one noisy marker
    _, _, _, weights = head_pose(frames, ref, np.arange(8))
    assert weights[0] < 0.1 * weights[1:].min() and weights.sum() == pytest.approx(8)


def _two_phone_join(pinned):
    """Two 30-frame phones joined by non-captured nodes with a jump: /m/ (pinned by default) then /aa/."""
    from facesynth.domain.postprocess.concatenation import concatenate

    coeffs = np.concatenate([np.linspace(0.0, 0.3, 30), 5.0 + np.linspace(0.0, 0.9, 30)])[:, None]
    return concatenate(np.array([0, 1]), ["m", "aa"], np.array([0.0, 0.25]), np.array([0.25, 0.5]),
                       np.array([0, 30]), np.array([30, 30]), np.array([-1, -1]), ["m", "aa"], coeffs,
                       np.zeros(1), 120.0, half_window=12, lam=1.0, weight_of=lambda p: 2.0 if p == "m" else 1.0,
                       method="blend", pinned=pinned).coeffs[:, 0]


def test_a_pinned_phone_keeps_its_frames_and_the_other_side_closes_the_gap():
    free, pinned = _two_phone_join(frozenset()), _two_phone_join(frozenset({"m"}))
    captured_m = np.linspace(0.0, 0.3, 30)
    assert np.abs(free[:30] - captured_m).max() > 0.5  # Table IV's share moves the /m/ a third of the gap
    assert np.array_equal(pinned[:30], captured_m.astype(np.float32))  # pinned: untouched
    assert np.abs(np.diff(pinned, 2)).max() < 0.5 * np.abs(np.diff(free, 2)).max() + 0.2  # still no pop
    assert abs(np.diff(pinned)[29] - np.diff(pinned)[28]) < 0.05
