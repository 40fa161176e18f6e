"""Voice features meant not to carry the speaker, on voices made here: the cepstrally liftered
envelope (facesynth.domain.voice.articulation.envelope_of) does not follow the pitch, and the
vocal-tract warp (facesynth.domain.voice.tract) recovers a known scaling of a voice's spectrum
made by facesynth.domain.voice.synthetic."""

from __future__ import annotations

import numpy as np
import pytest

from facesynth.domain.voice import articulation as A
from facesynth.domain.voice import synthetic, tract

RATE = A.RATE
#: Formants (Hz) of five vowels (a, i, u, e, o of an adult voice).
VOWELS = ((700, 1200, 2600), (300, 2300, 3000), (350, 800, 2400), (500, 1700, 2500), (600, 1000, 2500))


def vowels(f0: float, seconds: float = 6.0, seed: int = 0) -> np.ndarray:
    """(n,) float64 at 16 kHz: 0.3 s vowels (a glottal pulse train at ``f0`` Hz through three
    formant resonances), in an order drawn from ``seed``."""
    from scipy.signal import lfilter

    rng = np.random.default_rng(seed)
    n, seg = int(seconds * RATE), int(0.3 * RATE)
    out = np.zeros(n)
    for start in range(0, n, seg):
        formants = VOWELS[rng.integers(len(VOWELS))]
        m = min(seg, n - start)
        phase = np.cumsum(np.full(m, f0) / RATE)
        y = np.diff(np.floor(phase), prepend=0.0)
        for f in formants:
            r = np.exp(-np.pi * 80 / RATE)
            y = lfilter([1 - r], [1, -2 * r * np.cos(2 * np.pi * f / RATE), r * r], y)
        out[start:start + m] = y * np.hanning(m)
    return out / np.abs(out).max() * 0.5


def low_band_profile_r(a: np.ndarray, b: np.ndarray) -> float:
    """Mean over loud frames of the correlation between two feature sets' band profiles below
    about 1.3 kHz (the first 12 mel bands, where a pitch's harmonics are resolved)."""
    loud = a[:, A.I_LOG_RMS] > a[:, A.I_LOG_RMS].max() - 2.0
    pa, pb = a[loud, :12], b[loud, :12]
    return float(np.mean([np.corrcoef(x, y)[0, 1] for x, y in zip(pa, pb)]))


def test_the_liftered_envelope_does_not_follow_the_pitch():
    low, high = vowels(100.0), vowels(250.0)  # the same vowels, a man's pitch and a child's
    plain = low_band_profile_r(A.frame_features(low, RATE), A.frame_features(high, RATE))
    lifted = low_band_profile_r(A.frame_features(low, RATE, envelope=True),
                                A.frame_features(high, RATE, envelope=True))
    assert lifted > 0.93  # the formants' shape, whatever the pitch
    assert plain < 0.8  # the plain log-mel bands see the harmonics
    # the other columns are the plain features' own
    assert np.array_equal(A.frame_features(low, RATE, envelope=True)[:, A.I_LOG_RMS],
                          A.frame_features(low, RATE)[:, A.I_LOG_RMS])


def test_the_envelope_of_a_flat_spectrum_is_flat():
    log_power = np.full((3, A.NFFT // 2 + 1), -2.0)
    assert np.allclose(A.envelope_of(log_power), -2.0, atol=1e-4)


@pytest.mark.parametrize("warp", [0.87, 1.0, 1.15])
def test_the_warp_recovers_a_known_vocal_tract_scaling(warp):
    voice = vowels(120.0)
    step = int(round(tract.MAX_LOG_WARP / 0.01))
    reference = tract.long_term_envelope(voice, RATE)[step:step + len(tract.WARP_GRID)]
    other = synthetic.transform(voice, RATE, synthetic.Voice(warp=warp, tilt_db=3.0, gain_db=-10.0))
    assert tract.estimate_warp(tract.long_term_envelope(other, RATE), reference) == pytest.approx(warp, abs=0.02)


def test_features_read_at_the_warp_undo_it():
    voice = vowels(120.0)
    longer = synthetic.warp_spectrum(voice, RATE, 0.85)  # a longer tract: every formant at 0.85 times
    base = A.frame_features(voice, RATE, envelope=True)
    as_is = A.frame_features(longer, RATE, envelope=True)
    undone = A.frame_features(longer, RATE, envelope=True, warp=0.85)
    loud = base[:, A.I_LOG_RMS] > base[:, A.I_LOG_RMS].max() - 2.0

    def distance(x):
        d = x[loud, :A.N_MELS] - base[loud, :A.N_MELS]
        return float(np.sqrt(np.mean((d - d.mean(1, keepdims=True)) ** 2)))

    assert distance(undone) < 0.5 * distance(as_is)
    assert np.array_equal(A.warped_filterbank(1.0), A.warped_filterbank(1.0 + 1e-12))


def test_no_voiced_frames_leave_the_voice_unwarped():
    silence = np.zeros(RATE)
    assert tract.long_term_envelope(silence, RATE) is None
    assert tract.estimate_warp(None, np.zeros(len(tract.WARP_GRID))) == 1.0


@pytest.mark.parametrize("f0", [95.0, 210.0])
def test_the_median_pitch_of_a_voice_is_its_pulse_rate(f0):
    assert tract.median_pitch(vowels(f0), RATE) == pytest.approx(f0, rel=0.02)
    assert tract.median_pitch(np.zeros(RATE), RATE) is None


def test_a_higher_voice_reads_as_a_shorter_tract_within_bounds():
    assert tract.pitch_warp(216.0, 120.0) == pytest.approx(1.8 ** tract.PITCH_TO_WARP)
    assert tract.pitch_warp(120.0, 120.0) == 1.0
    assert tract.pitch_warp(4000.0, 60.0) == pytest.approx(np.exp(tract.MAX_LOG_WARP))
    assert tract.pitch_warp(None, 120.0) == 1.0
