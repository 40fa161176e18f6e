"""Speech from any file ffmpeg reads (:func:`facesynth.formats.audio.read_audio`): the held-out
sentence as M4A, MP3, Opus, Opus in Ogg and an MP4's sound gives the WAV's samples within the
codec's error, at the WAV's timing; WAV and FLAC keep libsndfile's exact reading; what is not
speech is refused in one sentence.

Measured on the held-out sentence (2.3 s, 16 kHz): every format decodes to exactly the WAV's
length (Opus at its own 48 kHz, resampled), at lag 0, with r 1.000 (AAC at 96 kb/s), 0.9986 (MP3
96 kb/s) and 0.996 (Opus 48 kb/s) against the WAV's samples; the bounds below leave room for
another ffmpeg build (1 ms of length, r 0.99).
"""

from __future__ import annotations

import dataclasses
import re
import shutil
import subprocess
from pathlib import Path

import imageio_ffmpeg
import numpy as np
import pytest
import soundfile as sf
from coded_audio import COMPRESSED, coded

from facesynth.base import limits
from facesynth.base.errors import InputError
from facesynth.formats.audio import is_wav, pcm16, read_audio, resample

#: The rates ffmpeg decodes at: AAC and MP3 keep the WAV's 16 kHz; Opus always decodes at 48 kHz.
NATIVE_RATE = {"m4a": 16000, "mp3": 16000, "opus": 48000, "ogg": 48000, "mp4": 16000}


def _ffmpeg(*args) -> None:
    subprocess.run([imageio_ffmpeg.get_ffmpeg_exe(), "-hide_banner", "-nostdin", "-v", "error", "-y", *map(str, args)],
                   check=True)


@pytest.mark.parametrize("name", COMPRESSED)
def test_each_format_gives_the_wavs_samples_within_the_codecs_error(coded_speech, name):
    wav, rate = read_audio(coded_speech["wav"])
    got, got_rate = read_audio(coded(coded_speech, name))
    assert got_rate == NATIVE_RATE[name] and got.dtype == np.float32 and got.ndim == 1
    got = resample(got, got_rate, rate)
    assert abs(len(got) - len(wav)) <= rate // 1000  # the same length, within a millisecond
    n = min(len(got), len(wav))
    lags = {lag: float(np.dot(wav[max(lag, 0):n + min(lag, 0)], got[max(-lag, 0):n - max(lag, 0)]))
            for lag in range(-80, 81)}
    assert abs(max(lags, key=lags.get)) <= 1  # no delay: the encoder's priming samples are dropped
    assert np.corrcoef(wav[:n], got[:n])[0, 1] > 0.99


def test_a_wav_reads_exactly_as_libsndfile_reads_it(coded_speech, tmp_path):
    data, rate = sf.read(coded_speech["wav"], dtype="float32", always_2d=True)
    got, got_rate = read_audio(coded_speech["wav"])
    assert got_rate == rate
    np.testing.assert_array_equal(got, data.mean(axis=1).astype(np.float32))
    # and 16-bit samples written back are the file's own bytes
    with sf.SoundFile(coded_speech["wav"]) as fh:
        assert fh.subtype == "PCM_16"
        raw = fh.read(dtype="int16").tobytes()
    assert pcm16(got) == raw


def test_the_content_decides_not_the_name(coded_speech, tmp_path):
    """An M4A named .wav is decoded by ffmpeg (libsndfile cannot read it) to the same samples."""
    m4a = coded(coded_speech, "m4a")
    shutil.copyfile(m4a, tmp_path / "speech.wav")
    a, rate = read_audio(m4a)
    b, rate_b = read_audio(tmp_path / "speech.wav")
    assert rate == rate_b
    np.testing.assert_array_equal(a, b)
    assert not is_wav(tmp_path / "speech.wav") and is_wav(coded_speech["wav"])


def test_ffmpeg_keeps_the_rate_and_averages_the_channels(tmp_path):
    """PCM in Matroska (lossless, read by ffmpeg): 22.05 kHz stays 22.05 kHz, stereo becomes the
    mean of its channels, as libsndfile's route does."""
    rate = 22050
    t = np.arange(rate // 2) / rate
    left, right = 0.5 * np.sin(2 * np.pi * 440 * t), np.full_like(t, 0.25)
    sf.write(tmp_path / "st.wav", np.stack([left, right], 1), rate, subtype="PCM_24")
    _ffmpeg("-i", tmp_path / "st.wav", "-c:a", "pcm_s24le", tmp_path / "st.mkv")
    got, got_rate = read_audio(tmp_path / "st.mkv")
    assert got_rate == rate and got.shape == left.shape
    np.testing.assert_allclose(got, (left + right) / 2, atol=1e-6)
    ref, _ = read_audio(tmp_path / "st.wav")
    np.testing.assert_allclose(got, ref, atol=1e-7)


def test_the_length_limit_holds_for_decoded_files(coded_speech):
    short = dataclasses.replace(limits.current(), max_utterance_s=1.0)
    with limits.using(short), pytest.raises(InputError, match=r"speech\.m4a: the audio's length \(s\) is 2\.32.*"
                                                              r"above limits\.max_utterance_s = 1"):
        read_audio(coded(coded_speech, "m4a"))


# --- refused in one sentence -------------------------------------------------------------------


def test_a_video_without_sound_is_refused(coded_speech):
    path = coded_speech["silent"]
    with pytest.raises(InputError) as err:
        read_audio(path)
    assert str(err.value) == (f"{path}: has no audio stream (it holds video only); give a file with sound, or the "
                              "speech as a sound file of its own.")


def test_a_file_that_is_no_media_is_refused(coded_speech):
    path = coded_speech["notes"]
    with pytest.raises(InputError) as err:
        read_audio(path)
    said = str(err.value)
    assert said.startswith(f"{path}: unreadable audio: ffmpeg reads neither sound nor video in it (")
    assert said.endswith("give a sound file (WAV, FLAC, M4A/AAC, MP3, Opus, Ogg, ...) or a video with sound "
                         "(MP4, MOV, MKV, ...).")
    assert "\n" not in said and said.count(". ") == 0


def test_an_audio_stream_without_samples_is_refused(tmp_path):
    """A Core Audio file (decoded by ffmpeg) whose one stream holds no sample."""
    path = tmp_path / "empty.caf"
    sf.write(path, np.zeros((0, 1)), 16000, format="CAF")
    with pytest.raises(InputError, match=re.escape(f"{path}: the audio file has no samples.")):
        read_audio(path)


def test_a_missing_file_is_named(tmp_path):
    with pytest.raises(InputError, match=re.escape(f"{tmp_path / 'take.m4a'}: audio file not found; check the path.")):
        read_audio(tmp_path / "take.m4a")


def test_a_name_ffmpeg_would_take_for_a_protocol_or_an_option_is_a_file(coded_speech, tmp_path, monkeypatch):
    m4a = coded(coded_speech, "m4a")
    monkeypatch.chdir(tmp_path)
    for name in ("take:2.m4a", "-y.m4a"):  # relative, as a user types them
        shutil.copyfile(m4a, name)
        np.testing.assert_array_equal(read_audio(Path(name))[0], read_audio(m4a)[0])
