"""``facesynth stream --audio FILE`` reads any file ``read_audio`` reads, resampled to the live
16 kHz: the held-out sentence as M4A, MP3, Opus, Ogg and MP4 streams the WAV's number of frames
(70) with the same mouth. Before, a container was streamed as raw PCM: noise, 26 frames for
100, exit 0.

Measured: the jawOpen curve of every coded file follows the WAV's at r 0.971 (MP3 at 96 kb/s),
0.968 (AAC at 96 kb/s, M4A and MP4) and 0.996 (Opus at 48 kb/s); from the first frame with
sound on, every frame within 0.09 (MP3), 0.07 (AAC) and 0.03 (Opus). The test asks r > 0.95 and
0.1. The WAV's pauses are digital silence, on which the voice's noise floor does not stand
(:mod:`facesynth.domain.voice.activity`): its floor is the sentence's own quietest moments, and
its first 0.1 s of sound waits for the voice activity detector to settle. A codec fills the
12 ms before the sound with faint pre-echo (-66 to -48 dBFS), which ends the digital silence
earlier and gives the floor a quieter frame, so the first and last syllables open the jaw a
little more (by up to 0.15 in the first 0.1 s). The streams take the voice's frames
(``stream.voice = "articulation"``, the default, set whatever the configuration), whose mouth
follows the sound frame by frame, so the comparison measures the decoder; with ``"off"`` the
frames come from the recognised phones, which a codec can tip one way or the other.
"""

from __future__ import annotations

import json
import wave

import numpy as np
import pytest
import soundfile as sf
from click.testing import CliRunner
from coded_audio import COMPRESSED, coded

from facesynth.cli import main


def _stream(tiny_db, *args, **kw) -> tuple[int, list[dict], str]:
    result = CliRunner().invoke(main, ["stream", str(tiny_db), "--set", "stream.voice=articulation", *args], **kw)
    lines = [json.loads(line) for line in result.stdout.splitlines()]
    return result.exit_code, lines, result.output


def _jaw(messages: list[dict]) -> np.ndarray:
    jaw = messages[0]["arkit_names"].index("jawOpen")
    return np.array([m["arkit"][jaw] for m in messages if m["type"] == "frame"])


@pytest.fixture(scope="module")
def from_wav(tiny_db, coded_speech) -> list[dict]:
    code, messages, output = _stream(tiny_db, "--audio", str(coded_speech["wav"]))
    assert code == 0, output
    return messages


def test_a_wav_file_streams_as_on_standard_input(tiny_db, coded_speech, from_wav):
    """The file is decoded and written back as 16 kHz 16-bit PCM: the same samples, the same frames."""
    code, piped, output = _stream(tiny_db, input=coded_speech["wav"].read_bytes())
    assert code == 0, output
    assert piped == from_wav and len(_jaw(from_wav)) == 70


@pytest.mark.parametrize("name", COMPRESSED)
def test_each_format_streams_the_wavs_frames(tiny_db, coded_speech, from_wav, name):
    code, messages, output = _stream(tiny_db, "--audio", str(coded(coded_speech, name)))
    assert code == 0, output
    assert messages[-1] == {"type": "end", "frames": 70} == from_wav[-1]
    coded_jaw, wav_jaw = _jaw(messages), _jaw(from_wav)
    assert np.corrcoef(coded_jaw, wav_jaw)[0, 1] > 0.95
    sound = int(np.flatnonzero(wav_jaw > 0)[0])  # the first frame that hears the sentence
    assert np.abs(coded_jaw - wav_jaw)[sound:].max() < 0.1


def test_a_wav_at_another_rate_and_in_stereo_is_resampled(tiny_db, coded_speech, tmp_path, from_wav):
    samples, rate = sf.read(coded_speech["wav"], dtype="float32")
    from facesynth.formats.audio import resample

    up = resample(samples, rate, 44100)
    sf.write(tmp_path / "stereo44k.wav", np.stack([up, up], 1), 44100, subtype="PCM_16")
    code, messages, output = _stream(tiny_db, "--audio", str(tmp_path / "stereo44k.wav"))
    assert code == 0, output
    assert messages[-1]["frames"] == 70 and np.corrcoef(_jaw(messages), _jaw(from_wav))[0, 1] > 0.99


def test_a_pcm_file_is_raw_as_on_standard_input(tiny_db, coded_speech, tmp_path, from_wav):
    with wave.open(str(coded_speech["wav"])) as w:
        (tmp_path / "speech.pcm").write_bytes(w.readframes(w.getnframes()))
    code, messages, output = _stream(tiny_db, "--audio", str(tmp_path / "speech.pcm"))
    assert code == 0, output
    assert messages == from_wav


@pytest.mark.parametrize("name, said", [
    ("silent", ": has no audio stream (it holds video only); give a file with sound, or the speech as a sound file of "
               "its own."),
    ("notes", ": unreadable audio: ffmpeg reads neither sound nor video in it ("),
])
def test_what_is_no_speech_is_refused_before_a_frame(tiny_db, coded_speech, name, said):
    code, messages, output = _stream(tiny_db, "--audio", str(coded_speech[name]))
    assert code == 1 and messages == []
    assert output.startswith(f"error: {coded_speech[name]}{said}") and output.count("\n") == 1


@pytest.mark.parametrize("name", ["m4a", "mp4", "opus", "ogg", "mp3"])
def test_a_sound_file_on_standard_input_is_refused_not_streamed_as_noise(tiny_db, coded_speech, name):
    """Standard input takes PCM (or a WAV); a container there was streamed as raw samples."""
    code, messages, output = _stream(tiny_db, input=coded(coded_speech, name).read_bytes())
    assert code == 1 and messages == [] and output.count("\n") == 1
    assert output.startswith("error: standard input: this is ") and "give the file with --audio FILE" in output
