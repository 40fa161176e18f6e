"""Removing head motion (facesynth.domain.head_motion.removal, paper Eq. 1-2) on markers made
here: a known head motion is recovered, a posed corpus's known pose is removed as it is, and bad
settings name what to change."""

from dataclasses import replace

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from facesynth.base.config import Config
from facesynth.base.errors import InputError
from facesynth.domain.head_motion.removal import normalize, uses_known_pose
from facesynth.model.tables import Phones, Takes

FPS = 30.0


def _capture(frames=40, seed=0):
    """A face of 8 markers, the first 5 rigid (a head), the last 3 a jaw that opens, moved by a
    known head motion; one take, a leading silence of 0.5 s."""
    rng = np.random.default_rng(seed)
    face = rng.normal(0, 40, (8, 3))
    local = np.repeat(face[None], frames, axis=0)
    local[:, 5:, 1] -= np.linspace(0, 12, frames)[:, None]  # the jaw opens: not rigid
    rotations = Rotation.from_euler("xyz", rng.normal(0, 8, (frames, 3)), degrees=True).as_matrix()
    translations = rng.normal(0, 20, (frames, 3))
    captured = np.einsum("fij,fmj->fmi", rotations, local) + translations[:, None]
    takes = Takes(["a"], ["neutral"], ["a"], ["train"], [""], np.array([0]), np.array([frames]))
    phones = Phones(np.array([0, 0], np.int64), np.array([0.0, 0.5]), np.array([0.5, frames / FPS]), ["pau", "aa"],
                    ["neutral", "neutral"])
    return captured.astype(np.float32), [f"m{i}" for i in range(8)], takes, phones, rotations, translations, local


def _settings(**changes):
    return replace(Config.load().settings("normalize"), **changes)


def test_the_head_motion_is_removed_and_the_transform_kept():
    captured, names, takes, phones, _, _, local = _capture()
    n = normalize(captured, names, takes, phones, FPS, _settings(rigid_markers=[f"m{i}" for i in range(5)]))
    assert n.rigid.source == "settings" and list(n.rigid.indices) == [0, 1, 2, 3, 4] and not n.known_pose
    assert n.reference[n.origin] == pytest.approx(np.zeros(3))
    # the rigid markers keep their place in the head frame whatever the head did
    np.testing.assert_allclose(n.normalized[:, :5], np.broadcast_to(n.normalized[0, :5], (40, 5, 3)), atol=1e-3)
    # the jaw's own motion stays: its opening is 12 mm
    opening = np.linalg.norm(n.normalized[-1, 5:] - n.normalized[0, 5:], axis=1)
    np.testing.assert_allclose(opening, 12.0, atol=1e-3)
    # captured = R normalized + t
    back = np.einsum("fij,fmj->fmi", n.rotations, n.normalized) + n.translations[:, None]
    np.testing.assert_allclose(back, captured, atol=1e-2)


def test_a_known_pose_is_removed_as_it_is():
    captured, names, takes, phones, rotations, translations, local = _capture()
    known = (local[0], rotations, translations)
    n = normalize(captured, names, takes, phones, FPS, _settings(), known=known)
    assert n.known_pose and n.rigid.source == "known" and len(n.weights) == 0
    np.testing.assert_allclose(n.normalized, local - local[0][n.origin], atol=1e-2)
    assert uses_known_pose(_settings(), known)
    assert not uses_known_pose(_settings(known_pose=False), known)
    assert not uses_known_pose(_settings(reference_frame=3), known)  # a reference named: fitted


@pytest.mark.parametrize("changes, message", [
    ({"rigid_markers": ["nope"]}, "normalize.rigid_markers names unknown markers \\['nope'\\]"),
    ({"rigid_markers": ["m0", "m1"]}, "names 2 markers; a head pose needs at least 3"),
    ({"origin_marker": "nope"}, "normalize.origin_marker 'nope' is not a marker"),
    ({"reference_take": "b"}, "normalize.reference_take 'b' is not a take"),
    ({"reference_frame": 99}, "normalize.reference_frame 99 is beyond take 'a' \\(40 frames\\)"),
])
def test_bad_settings_are_named(changes, message):
    captured, names, takes, phones, *_ = _capture()
    settings = _settings(**({"rigid_markers": [f"m{i}" for i in range(5)]} | changes))
    with pytest.raises(InputError, match=message):
        normalize(captured, names, takes, phones, FPS, settings)
