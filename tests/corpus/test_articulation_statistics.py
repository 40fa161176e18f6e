"""Articulation statistics (``facesynth.domain.corpus.statistics``) on made-up curves with known answers,
and the ``[sample_corpus]`` settings reaching the actress's articulation."""

import dataclasses

import numpy as np
import pytest

from facesynth.base.config import Config
from facesynth.domain.corpus.actress_mouth import ContactSolver, channel_stiffness_hz
from facesynth.domain.corpus.generate import perform
from facesynth.domain.corpus.statistics import (
    audio_lag,
    autocorrelation_span,
    motion_statistics,
    normalise_by_range,
    opening_events,
    phone_class_opening,
    phone_opening_z,
    speech_masks,
)
from facesynth.domain.rig.face import load_face_rig
from facesynth.domain.rig.markers import build_marker_set, mesh_lip_gap

FPS = 30.0


@pytest.fixture(scope="module")
def rig():
    return load_face_rig()


@pytest.fixture(scope="module")
def marker_set(rig):
    return build_marker_set(rig)


def test_normalise_by_range_maps_the_percentiles_to_0_and_1():
    a, b = np.linspace(0.0, 10.0, 101), np.linspace(10.0, 20.0, 101)
    (na, nb), (low, high) = normalise_by_range([a, b])
    assert low == pytest.approx(np.percentile(np.r_[a, b], 5)) and high == pytest.approx(np.percentile(np.r_[a, b], 95))
    assert np.percentile(np.r_[na, nb], 5) == pytest.approx(0.0) and np.percentile(np.r_[na, nb], 95) == pytest.approx(1.0)
    # a unit change (mm or weight) does not change the normalised curves
    (ma, _), _ = normalise_by_range([a * 7.0, b * 7.0])
    assert np.allclose(ma, na)


def test_motion_statistics_of_a_sine():
    t = np.arange(3000) / FPS
    f = 0.37  # many frames a period, at phases spread evenly
    x = 0.5 + 0.5 * np.sin(2 * np.pi * f * t)
    stats = motion_statistics([x], FPS)
    # |d/dt| = pi f |cos|: median pi f cos(pi/4); 95th percentile pi f cos(0.05 pi / 2);
    # |d2/dt2| = 2 (pi f)^2 |sin|: median 2 (pi f)^2 sin(pi/4)
    assert stats.velocity.p50 == pytest.approx(np.pi * f * np.cos(np.pi / 4), rel=0.02)
    assert stats.velocity.p95 == pytest.approx(np.pi * f * np.cos(0.025 * np.pi), rel=0.02)
    assert stats.acceleration.p50 == pytest.approx(2 * (np.pi * f) ** 2 * np.sin(np.pi / 4), rel=0.05)
    # a mask keeps only the frames it holds: the still half adds nothing
    still = np.r_[x, np.full(3000, 0.5)]
    masked = motion_statistics([still], FPS, [np.r_[np.ones(2990, bool), np.zeros(3010, bool)]])
    assert masked.velocity.p50 == pytest.approx(stats.velocity.p50, rel=0.02)


def test_opening_events_count_syllables_per_second():
    t = np.arange(900) / FPS  # 30 s at 3 openings a second
    x = 0.5 - 0.5 * np.cos(2 * np.pi * 3.0 * t)
    events = opening_events([x], FPS)
    assert events.openings_per_s == pytest.approx(3.0, abs=0.05)
    assert events.closings_per_s == pytest.approx(3.0, abs=0.05)
    # ripples below the prominence are not events
    assert opening_events([0.05 * x], FPS).openings_per_s == 0.0


def test_audio_lag_finds_a_known_delay_of_either_sign():
    rng = np.random.default_rng(0)
    env = np.convolve(rng.normal(size=2000), np.hanning(9), mode="same")
    for delay in (3, -2, 0):
        opening = np.roll(env, delay)
        lag = audio_lag([env[50:-50]], [opening[50:-50]], FPS)
        assert lag.lag_s == pytest.approx(delay / FPS, abs=0.2 / FPS)
        assert lag.r > 0.99
    # a sub-frame delay is found between frames
    fine = np.interp(np.arange(2000) - 1.5, np.arange(2000), env)
    assert audio_lag([env[50:-50]], [fine[50:-50]], FPS).lag_s == pytest.approx(1.5 / FPS, abs=0.35 / FPS)


def test_autocorrelation_span_of_a_cosine_and_of_white_noise():
    t = np.arange(6000) / FPS
    f = 1.0  # autocorrelation cos(2 pi f tau) reaches 0.5 at tau = 1 / (6 f)
    assert autocorrelation_span([np.cos(2 * np.pi * f * t)], FPS) == pytest.approx(1 / 6, abs=0.01)
    noise = np.random.default_rng(1).normal(size=6000)
    assert autocorrelation_span([noise], FPS) < 1.0 / FPS
    # masked frames do not count: a cosine with a long flat stretch keeps its span
    flat = np.r_[np.cos(2 * np.pi * f * t), np.zeros(3000)]
    mask = np.r_[np.ones(6000, bool), np.zeros(3000, bool)]
    assert autocorrelation_span([flat], FPS, masks=[mask]) == pytest.approx(1 / 6, abs=0.01)


def test_speech_masks_drop_long_pauses_only():
    phones = [[(0.0, 0.5, "pau"), (0.5, 0.6, "aa"), (0.6, 0.7, "pau"), (0.7, 0.8, "m"), (0.8, 0.9, "sil"),
               (0.9, 1.05, "pau"), (1.05, 1.2, "iy")]]
    mask = speech_masks(phones, [36], FPS)[0]
    t = np.arange(36) / FPS
    assert not mask[t < 0.5].any()                      # 0.5 s pause: out
    assert mask[(t >= 0.6) & (t < 0.7)].all()           # 0.1 s silence inside speech: kept
    assert not mask[(t >= 0.8 + 1e-9) & (t < 1.05)].any()  # sil + pau merged, 0.25 s: out
    assert mask[(t >= 1.05) & (t < 1.2)].all()


def test_phone_class_opening_averages_the_frames_of_each_class():
    t = np.arange(30) / FPS
    x = np.where(t < 0.5, 1.0, 0.0)
    phones = [[(0.0, 0.5, "aa"), (0.5, 0.8, "m"), (0.8, 1.0, "pau")]]
    out = phone_class_opening([x], phones, FPS)
    assert out["open_vowel"] == 1.0 and out["bilabial"] == 0.0 and out["pause"] == 0.0
    assert out["close_vowel"] is None


def test_phone_opening_z_is_the_standardized_opening_over_each_phone():
    t = np.arange(60) / FPS
    x = np.where(t < 1.0, 2.0, 0.0)  # open for the vowel, closed for /f/
    phones = [[(0.0, 1.0, "aa"), (1.0, 2.0, "f")]]
    out = phone_opening_z([x], phones, [np.ones(60, bool)], FPS)
    assert out["aa"] == pytest.approx(1.0) and out["f"] == pytest.approx(-1.0)  # mean 1, sd 1
    assert out["jh"] is None
    # standardized over speech only: a long closed pause does not move the scale
    quiet = np.concatenate([x, np.zeros(60)])
    mask = np.concatenate([np.ones(60, bool), np.zeros(60, bool)])
    assert phone_opening_z([quiet], phones, [mask], FPS)["aa"] == pytest.approx(1.0)


def test_the_settings_reach_the_articulation(rig, marker_set):
    """Stiffer jaw: a faster jaw; lips closed in pauses: no lip gap there; the uncalibrated
    settings keep the lips apart in a pause."""
    settings = Config.load().settings("sample_corpus")
    assert channel_stiffness_hz("jawOpen", settings) == settings.jaw_stiffness_hz
    scaled = dataclasses.replace(settings, lip_stiffness_scale=2.0 * settings.lip_stiffness_scale)
    assert channel_stiffness_hz("pucker", scaled) == pytest.approx(2.0 * channel_stiffness_hz("pucker", settings))
    assert channel_stiffness_hz("jawForward", scaled) == channel_stiffness_hz("jawForward", settings)
    solver = ContactSolver(rig, marker_set.lip_pairs)
    words = ["please", "go", "home"]
    jaw = rig.shape_index("jawOpen")

    def run(**changes):
        perf = perform(words, "neutral", np.random.default_rng(3), rig, solver, 0.0, change_probability=0.0,
                       settings=dataclasses.replace(settings, **changes))
        return perf

    slow, fast = run(jaw_stiffness_hz=3.0), run(jaw_stiffness_hz=12.0)
    assert np.abs(np.diff(fast.weights[:, jaw])).max() > 1.5 * np.abs(np.diff(slow.weights[:, jaw])).max()
    closed, apart = run(pause_lips_closed=True, pause_jaw_open=0.0), run(pause_lips_closed=False, pause_jaw_open=0.1)
    utt = closed.utterance
    last_pause = (utt.starts[-1] + 0.1, utt.ends[-1] - 0.1)  # the final pause, away from its edges
    frames = np.arange(int(last_pause[0] * 120), int(last_pause[1] * 120))
    assert mesh_lip_gap(rig, closed.weights[frames], marker_set.lip_upper, marker_set.lip_lower).max() < 1.0
    assert mesh_lip_gap(rig, apart.weights[frames], marker_set.lip_upper, marker_set.lip_lower).min() > 2.0
