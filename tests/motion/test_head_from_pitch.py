"""Head motion from speech with the [head_motion] settings (facesynth.domain.head_motion.from_pitch),
on values made here."""

from dataclasses import replace

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from facesynth.base.config import Config
from facesynth.base.errors import InputError
from facesynth.domain.head_motion import from_pitch
from facesynth.domain.head_motion.synthesis import Choice


def _settings(**changes):
    return replace(Config.load().settings("head_motion"), **changes)


def test_channels_are_degrees_and_millimetres_and_go_back_to_poses():
    rotation = Rotation.from_rotvec([[0.0, 0.0, np.radians(10.0)], [np.radians(-5.0), 0.0, 0.0]]).as_matrix()
    translation = np.array([[1.0, 2.0, 3.0], [-4.0, 0.0, 0.5]])
    channels = from_pitch.head_channels(rotation, translation)
    np.testing.assert_allclose(channels, [[0, 0, 10, 1, 2, 3], [-5, 0, 0, -4, 0, 0.5]], atol=1e-9)
    back_r, back_t = from_pitch.head_poses(channels)
    np.testing.assert_allclose(back_r, rotation, atol=1e-12)
    np.testing.assert_allclose(back_t, translation)


@pytest.mark.parametrize("changes, message", [
    ({"pitch_min_hz": 300.0, "pitch_max_hz": 200.0}, "head_motion.pitch_min_hz 300 must be below pitch_max_hz 200"),
    ({"b": 0.7, "c": 0.6}, "head_motion.b \\+ head_motion.c = 1.3"),
])
def test_settings_that_bound_nothing_are_refused(changes, message):
    with pytest.raises(InputError, match=message):
        from_pitch.check_settings(_settings(**changes))
    from_pitch.check_settings(_settings())  # the defaults pass


def test_consecutive_counts_joins_that_follow_in_their_take():
    choices = [Choice(0, 3, 0.0), Choice(0, 4, 0.0), Choice(1, 5, 0.0), Choice(1, 7, 0.0), Choice(1, 8, 0.0)]
    assert from_pitch.consecutive(choices) == 2
    assert from_pitch.consecutive([]) == 0


def test_speech_without_voice_keeps_the_head_at_rest_with_a_warning():
    s = _settings()
    silent = np.full(int(round(1.0 / s.hop_s)), np.nan)  # 1 s, every frame unvoiced
    result, warnings = from_pitch.synthesize([], silent, 1.0, s)
    assert result.head.shape == (int(np.ceil(s.fps)), 6) and not result.head.any()
    assert result.segments == [] and result.choices == []
    assert warnings and "the head stays at rest" in warnings[0]
