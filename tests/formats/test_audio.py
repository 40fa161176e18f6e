"""Audio reading (WAV, FLAC; mono) and polyphase resampling."""

import re

import numpy as np
import pytest
import soundfile as sf

from facesynth.base.errors import InputError
from facesynth.formats.audio import read_audio, resample, write_wav

RATES = [(48000, 44100), (44100, 48000), (44100, 16000), (48000, 16000), (16000, 48000), (16000, 44100)]


def _tone(f, rate, seconds=1.0, amplitude=0.7, phase=0.3):
    t = np.arange(int(round(seconds * rate))) / rate
    return amplitude * np.sin(2 * np.pi * f * t + phase)


def _peak(x, rate):
    """(frequency Hz, amplitude) of the strongest sinusoid in the middle half second of x; the
    window holds whole periods of every tone used here (2 Hz bins), so no window function."""
    n = rate // 2
    mid = np.asarray(x[len(x) // 2 - n // 2 : len(x) // 2 - n // 2 + n], np.float64)
    spectrum = np.abs(np.fft.rfft(mid)) * 2 / n
    k = int(np.argmax(spectrum))
    return k * rate / n, spectrum[k]


# --- reading -----------------------------------------------------------------------------------


@pytest.mark.parametrize("rate", [16000, 44100, 48000])
def test_wav_written_then_read(tmp_path, rate):
    x = _tone(440, rate, 0.25)
    write_wav(tmp_path / "a.wav", x, rate)
    got, got_rate = read_audio(tmp_path / "a.wav")
    assert got_rate == rate and isinstance(got_rate, int)
    assert got.dtype == np.float32 and got.shape == x.shape
    np.testing.assert_allclose(got, x, atol=1 / 32768)  # 16-bit PCM


def test_write_wav_clips_instead_of_wrapping(tmp_path):
    write_wav(tmp_path / "loud.wav", np.array([-3.0, -1.0, 0.0, 0.5, 1.0, 2.0]), 16000)
    got, _ = read_audio(tmp_path / "loud.wav")
    np.testing.assert_allclose(got, [-1.0, -1.0, 0.0, 0.5, 1.0, 1.0], atol=1 / 32768)


@pytest.mark.parametrize("subtype", ["PCM_16", "PCM_24"])
def test_flac_is_read(tmp_path, subtype):
    x = _tone(1000, 44100, 0.25)
    sf.write(tmp_path / "a.flac", x, 44100, subtype=subtype)
    got, rate = read_audio(tmp_path / "a.flac")
    assert rate == 44100 and got.dtype == np.float32
    np.testing.assert_allclose(got, x, atol=1 / 32768)


@pytest.mark.parametrize("suffix", ["wav", "flac"])
def test_several_channels_are_mixed_to_their_mean(tmp_path, suffix):
    left = _tone(440, 16000, 0.1, amplitude=0.5)
    right = np.full_like(left, 0.25)
    sf.write(tmp_path / f"st.{suffix}", np.stack([left, right], 1), 16000, subtype="PCM_24")
    got, rate = read_audio(tmp_path / f"st.{suffix}")
    assert rate == 16000 and got.shape == left.shape  # one channel, as many samples
    np.testing.assert_allclose(got, (left + right) / 2, atol=1e-6)


def test_float_wav_keeps_its_values(tmp_path):
    x = np.linspace(-1, 1, 101).astype(np.float32)
    sf.write(tmp_path / "f.wav", x, 22050, subtype="FLOAT")
    got, rate = read_audio(tmp_path / "f.wav")
    assert rate == 22050
    np.testing.assert_array_equal(got, x)


# --- bad files ---------------------------------------------------------------------------------


def _zero_samples(p):
    sf.write(p, np.zeros((0, 1)), 16000)


def _truncated(p):
    sf.write(p, np.zeros(1000), 16000)
    p.write_bytes(p.read_bytes()[:30])  # cut inside the header


@pytest.mark.parametrize("make, message", [
    (lambda p: p.write_bytes(b""), "unreadable audio"),
    (lambda p: p.write_text("not audio at all", encoding="utf-8"), "unreadable audio"),
    (_truncated, "unreadable audio"),
    (_zero_samples, "the audio file has no samples"),
    (lambda p: p.mkdir(), "unreadable audio"),
], ids=["empty", "text", "truncated", "no samples", "a folder"])
def test_unreadable_or_empty_audio_is_refused_naming_the_file(tmp_path, make, message):
    p = tmp_path / "take.wav"
    make(p)
    with pytest.raises(InputError, match=re.escape(str(p)) + ": " + message):
        read_audio(p)


def test_missing_audio_file_is_named(tmp_path):
    with pytest.raises(InputError, match=re.escape(str(tmp_path / "nowhere.flac")) + ": audio file not found"):
        read_audio(tmp_path / "nowhere.flac")


# --- resampling --------------------------------------------------------------------------------


@pytest.mark.parametrize("rate, target", RATES)
@pytest.mark.parametrize("f", [440.0, 3000.0])
def test_resampling_keeps_a_tones_frequency_amplitude_and_timing(rate, target, f):
    x = _tone(f, rate).astype(np.float32)
    y = resample(x, rate, target)
    assert y.dtype == np.float32 and len(y) == target  # one second stays one second
    got_f, got_a = _peak(y, target)
    assert got_f == f
    assert got_a == pytest.approx(0.7, rel=2e-3)
    # sample by sample: the same tone sampled at the new rate, with no delay (away from the ends)
    ref = _tone(f, target)
    np.testing.assert_allclose(y[target // 10 : -target // 10], ref[target // 10 : -target // 10], atol=2e-3)


def test_down_sampling_removes_what_the_new_rate_cannot_hold():
    # 12 kHz is above 16 kHz's Nyquist frequency: it must be filtered out, not folded to 4 kHz
    y = resample(_tone(12000, 48000, amplitude=1.0).astype(np.float32), 48000, 16000)
    assert np.abs(y[1600:-1600]).max() < 0.01
    assert np.abs(np.fft.rfft(y[4000:12000]))[4000 * 8000 // 16000] * 2 / 8000 < 0.005  # nothing at 4 kHz


@pytest.mark.parametrize("n", [1, 999, 1001, 16000, 16001])
@pytest.mark.parametrize("rate, target", RATES)
def test_resampled_length_is_the_duration_at_the_new_rate(n, rate, target):
    y = resample(np.zeros(n, np.float32), rate, target)
    assert n * target / rate <= len(y) < n * target / rate + 1  # ceil(n * target / rate)


def test_worked_lengths():
    assert len(resample(np.zeros(1001, np.float32), 16000, 44100)) == 2760  # 1001 * 441 / 160 = 2759.006
    assert len(resample(np.zeros(441, np.float32), 44100, 16000)) == 160


def test_equal_rates_return_the_samples_unchanged():
    x = np.random.default_rng(0).uniform(-1, 1, 1234).astype(np.float32)
    np.testing.assert_array_equal(resample(x, 16000, 16000), x)
