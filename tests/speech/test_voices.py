"""Synthetic speakers (facesynth.domain.voice.synthetic): the vocal tract's length moves the spectrum,
the channel filters it, and the same voice makes the same audio."""

import numpy as np

from facesynth.domain.voice import synthetic

RATE = 16000


def peak_hz(x: np.ndarray) -> float:
    spec = np.abs(np.fft.rfft(x * np.hanning(len(x))))
    return float(np.fft.rfftfreq(len(x), 1 / RATE)[int(np.argmax(spec))])


def band_db(x: np.ndarray, lo: float, hi: float) -> float:
    spec = np.abs(np.fft.rfft(x)) ** 2
    f = np.fft.rfftfreq(len(x), 1 / RATE)
    return float(10 * np.log10(spec[(f >= lo) & (f < hi)].sum() + 1e-30))


def test_a_longer_or_shorter_tract_moves_the_spectrum_by_its_factor():
    t = np.arange(RATE) / RATE
    tone = np.sin(2 * np.pi * 1000 * t)
    for warp in (0.85, 1.2):
        moved = synthetic.warp_spectrum(tone, RATE, warp)
        assert len(moved) == len(tone)
        assert abs(peak_hz(moved[2000:-2000]) - 1000 * warp) < 40  # within a 32 ms frame's bin
    np.testing.assert_allclose(synthetic.warp_spectrum(tone, RATE, 1.0), tone)


def test_the_channel_band_limits_and_the_voice_is_deterministic():
    rng = np.random.default_rng(0)
    x = rng.normal(0, 0.1, 2 * RATE)
    phone = synthetic.Voice(low_hz=300.0, high_hz=3400.0)
    y = synthetic.channel(x, RATE, phone)
    assert band_db(x, 5000, 7000) - band_db(y, 5000, 7000) > 20  # above the telephone band: gone
    assert abs(band_db(x, 1000, 2000) - band_db(y, 1000, 2000)) < 1.5  # within it: kept
    voice = synthetic.random_voice(np.random.default_rng(3))
    assert 0.82 <= voice.warp <= 1.22
    a, b = synthetic.transform(x, RATE, voice), synthetic.transform(x, RATE, voice)
    assert np.array_equal(a, b) and len(a) == len(x)
    assert not np.allclose(a, synthetic.transform(x, RATE, synthetic.random_voice(np.random.default_rng(4))))
