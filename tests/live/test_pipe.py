"""The audio input of ``facesynth stream --audio`` (facesynth.domain.live.pipe): addresses, files
decoded to the live format, and pacing, on inputs made here."""

import io
import wave

import numpy as np
import pytest

from facesynth.base.errors import InputError
from facesynth.domain.live import pipe
from facesynth.formats.audio import write_wav


@pytest.mark.parametrize("text, expected", [("127.0.0.1:8765", ("127.0.0.1", 8765)), ("localhost:0", ("localhost", 0)),
                                            ("[::1]:11111", ("::1", 11111))])
def test_addresses_are_host_and_port(text, expected):
    assert pipe.parse_address(text, "--serve") == expected


@pytest.mark.parametrize("text", ["8765", "host:", ":8765", "host:port", "host:70000"])
def test_a_bad_address_names_the_option_and_the_form(text):
    with pytest.raises(InputError, match=f"--livelink '{text}': give HOST:PORT"):
        pipe.parse_address(text, "--livelink")


def test_a_file_is_decoded_to_16_khz_mono_16_bit(tmp_path):
    path = tmp_path / "a.wav"
    t = np.arange(8000) / 8000
    write_wav(path, (0.5 * np.sin(2 * np.pi * 200 * t)).astype(np.float32), 8000)  # 1 s at 8 kHz
    with wave.open(pipe.live_wav(path), "rb") as w:
        assert (w.getframerate(), w.getnchannels(), w.getsampwidth()) == (16000, 1, 2)
        assert w.getnframes() == 16000


def test_paced_reading_waits_for_the_audio_to_play(monkeypatch):
    clock = {"now": 100.0}
    slept = []
    monkeypatch.setattr(pipe.time, "monotonic", lambda: clock["now"])
    monkeypatch.setattr(pipe.time, "sleep", lambda s: (slept.append(s), clock.__setitem__("now", clock["now"] + s)))
    paced = pipe.Paced(io.BytesIO(bytes(64000)))  # 2 s of 16 kHz 16-bit audio
    assert len(paced.read(32000)) == 32000  # 1 s read at once: wait 1 s
    assert slept == [pytest.approx(1.0)]
    clock["now"] += 3.0  # the reader fell behind: no wait
    paced.read(16000)
    assert slept == [pytest.approx(1.0)]


def test_a_missing_file_is_named(tmp_path):
    with pytest.raises(InputError, match="no such audio file"):
        pipe.stream_audio(None, None, tmp_path / "missing.wav", print)  # type: ignore[arg-type]
