"""Streaming an audio file or standard input through :func:`.server.run_pipe`
(``facesynth stream --audio``): a file of any format decoded to the live input's format
(:func:`live_wav`), optionally paced as if it were arriving live, the frames optionally sent to
Live Link as well.
"""

from __future__ import annotations

import io
import sys
import time
import wave
from collections.abc import Callable
from pathlib import Path
from typing import BinaryIO, cast

from facesynth.base.config import AlignSettings
from facesynth.base.errors import InputError
from facesynth.domain.live.livelink import LiveLinkSender
from facesynth.domain.live.phones import SAMPLE_RATE
from facesynth.domain.live.server import run_pipe
from facesynth.domain.live.synthesizer import LiveModel
from facesynth.formats.audio import pcm16, read_audio, resample

#: Files ``--audio`` streams as they are, raw 16-bit little-endian PCM at 16 kHz mono (as standard
#: input); every other file is decoded (:func:`live_wav`).
RAW_SUFFIXES = (".pcm", ".raw")


def parse_address(text: str, what: str) -> tuple[str, int]:
    """``HOST:PORT`` as (host, port); port 0 (a free port) is allowed."""
    host, sep, port = text.rpartition(":")
    if not sep or not host or not port.isdigit() or not 0 <= int(port) <= 65535:
        raise InputError(f"{what} {text!r}: give HOST:PORT, e.g. 127.0.0.1:8765.")
    return host.strip("[]"), int(port)


def run_stdin(model: LiveModel, align: AlignSettings, source: BinaryIO, write: Callable[[str], None], *,
              where: str, livelink: str | None = None, markers: bool = False, realtime: bool = False) -> int:
    """Stream ``source`` (WAV or raw PCM); returns the number of frames. ``realtime`` paces the
    reading at the audio's own speed (a file played as if it were arriving live)."""
    sender = None
    if livelink is not None:
        host, port = parse_address(livelink, "--livelink")
        sender = LiveLinkSender(host, port, "facesynth", "facesynth-0", model.stream.fps, model.arkit_names)
    if realtime:
        source = cast(BinaryIO, Paced(source))
    try:
        return run_pipe(model, align, source, write, where=where, livelink=sender, markers=markers)
    finally:
        if sender is not None:
            sender.close()


def stream_audio(model: LiveModel, align: AlignSettings, audio: str | Path, write: Callable[[str], None], *,
                 livelink: str | None = None, markers: bool = False, realtime: bool = False) -> int:
    """Stream the audio file ``audio`` ('-': standard input, a WAV or raw PCM) through
    :func:`run_stdin`; returns the number of frames. A file is decoded by :func:`live_wav`
    (whatever its format and rate), except a ``.pcm`` or ``.raw`` file: raw 16 kHz PCM as on
    standard input."""
    if str(audio) == "-":
        return run_stdin(model, align, sys.stdin.buffer, write, where="standard input", livelink=livelink,
                         markers=markers, realtime=realtime)
    path = Path(audio)
    if not path.is_file():
        raise InputError(f"{path}: no such audio file.")
    if path.suffix.lower() in RAW_SUFFIXES:
        with open(path, "rb") as fh:
            return run_stdin(model, align, fh, write, where=str(path), livelink=livelink, markers=markers,
                             realtime=realtime)
    return run_stdin(model, align, live_wav(path), write, where=str(path), livelink=livelink, markers=markers,
                     realtime=realtime)


def live_wav(path: Path) -> BinaryIO:
    """The speech of the file ``path`` (any file :func:`read_audio` reads: WAV, FLAC, M4A, MP3,
    Opus, a video's sound, ...) as an in-memory WAV in the live input's format: 16 kHz
    (polyphase resampling), mono, 16-bit. A 16 kHz 16-bit mono WAV comes out with its own samples,
    so it streams exactly as it does on standard input."""
    samples, rate = read_audio(path)
    buffer = io.BytesIO()
    with wave.open(buffer, "wb") as w:
        w.setnchannels(1)
        w.setsampwidth(2)
        w.setframerate(SAMPLE_RATE)
        w.writeframes(pcm16(resample(samples, rate, SAMPLE_RATE)))
    buffer.seek(0)
    return buffer


class Paced:
    """A byte stream read no faster than 16 kHz 16-bit mono audio plays."""

    def __init__(self, source: BinaryIO):
        self.source, self.read_bytes = source, 0
        self.t0: float | None = None

    def read(self, n: int = -1) -> bytes:
        if self.t0 is None:
            self.t0 = time.monotonic()
        data = self.source.read(n)
        self.read_bytes += len(data)
        ahead = self.read_bytes / (2 * SAMPLE_RATE) - (time.monotonic() - self.t0)
        if ahead > 0:
            time.sleep(ahead)
        return data
