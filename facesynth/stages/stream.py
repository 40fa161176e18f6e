"""``facesynth stream``: live synthesis. Audio in as it arrives (standard input, or WebSocket
clients), frames of ARKit curves out with a fixed latency (JSON lines, WebSocket messages, and
optionally Live Link Face UDP packets). The work is in :mod:`facesynth.domain.live`; this module reads
the database once and starts a transport. See docs/live.md.
"""

from __future__ import annotations

import asyncio
import io
import sys
import time
import wave
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path
from typing import BinaryIO, cast

from facesynth.base.config import AlignSettings, SolveSettings, StreamSettings, SynthesizeSettings, TrajectorySettings
from facesynth.base.errors import InputError
from facesynth.domain import methods
from facesynth.domain.live.livelink import LiveLinkSender
from facesynth.domain.live.phones import SAMPLE_RATE
from facesynth.domain.live.server import StreamServer, run_pipe
from facesynth.domain.live.synthesizer import LiveModel
from facesynth.domain.methods import MethodSettings
from facesynth.formats.audio import pcm16, read_audio, resample
from facesynth.model.artifacts import artifact_kind

#: Files ``--audio`` streams as they are, raw 16-bit little-endian PCM at 16 kHz mono (as standard
#: input); every other file is decoded (:func:`live_wav`).
RAW_SUFFIXES = (".pcm", ".raw")


def parse_address(text: str, what: str) -> tuple[str, int]:
    """``HOST:PORT`` as (host, port); port 0 (a free port) is allowed."""
    host, sep, port = text.rpartition(":")
    if not sep or not host or not port.isdigit() or not 0 <= int(port) <= 65535:
        raise InputError(f"{what} {text!r}: give HOST:PORT, e.g. 127.0.0.1:8765.")
    return host.strip("[]"), int(port)


def load_model(source_path: Path, synth: SynthesizeSettings | MethodSettings, stream: StreamSettings, solve: SolveSettings,
               method: str | None = None, lookahead: int | None = None,
               trajectory: TrajectorySettings | None = None) -> LiveModel:
    """The shared live model of ``source_path``: the motion database, or the streamed member's
    fitted model (``method``/``lookahead`` override ``stream``'s; ``synth``: the
    :class:`~facesynth.domain.methods.MethodSettings`, or ``[synthesize]`` with ``trajectory``)."""
    if method is not None:
        stream = replace(stream, method=method)
    if lookahead is not None:
        if lookahead < 0:
            raise InputError(f"--lookahead {lookahead}: give 0 or more phones.")
        stream = replace(stream, lookahead_phones=lookahead)
    member, kind = methods.get(stream.method), artifact_kind(source_path)
    owner = methods.reader_of(kind) if kind is not None and kind != member.source_kind else None
    if owner is not None:  # a fitted model given to another member: name the one that reads it
        raise InputError(f"{source_path}: a {kind} model streams with the {owner} method; add --method {owner}, "
                         "or give the motion database." if owner in methods.live_names() else
                         f"{source_path}: a {kind} model is read by the {owner} method, which does not stream "
                         f"({methods.get(owner).not_live}); give the motion database.")
    # each method reads its own source, as `synthesize --method` does
    return LiveModel(member.read(source_path), synth, stream, solve, trajectory)


def run_stdin(model: LiveModel, align: AlignSettings, source: BinaryIO, write: Callable[[str], None], *,
              where: str, livelink: str | None = None, markers: bool = False, realtime: bool = False) -> int:
    """Stream ``source`` (WAV or raw PCM); returns the number of frames. ``realtime`` paces the
    reading at the audio's own speed (a file played as if it were arriving live)."""
    sender = None
    if livelink is not None:
        host, port = parse_address(livelink, "--livelink")
        sender = LiveLinkSender(host, port, "facesynth", "facesynth-0", model.stream.fps, model.arkit_names)
    if realtime:
        source = cast(BinaryIO, _Paced(source, model.stream.chunk_s))
    try:
        return run_pipe(model, align, source, write, where=where, livelink=sender, markers=markers)
    finally:
        if sender is not None:
            sender.close()


def run(model: LiveModel, align: AlignSettings, audio: str | Path, write: Callable[[str], None], *,
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


class _Paced:

    """A byte stream read no faster than 16 kHz 16-bit mono audio plays."""

    def __init__(self, source: BinaryIO, chunk_s: float):
        self.source, self.read_bytes = source, 0
        self.t0: float | None = None

    def read(self, n: int = -1) -> bytes:
        if self.t0 is None:
            self.t0 = time.monotonic()
        data = self.source.read(n)
        self.read_bytes += len(data)
        ahead = self.read_bytes / (2 * 16000) - (time.monotonic() - self.t0)
        if ahead > 0:
            time.sleep(ahead)
        return data


def serve(model: LiveModel, align: AlignSettings, address: str, *, livelink: str | None = None,
          ready: Callable[[str], None] | None = None, workers: int = 1) -> None:
    """Serve WebSocket clients on ``address`` until SIGINT or SIGTERM; ``ready`` gets a line
    naming the address once the server listens. ``workers`` processes share the port (Linux's
    SO_REUSEPORT spreads the connections over them), so streams use more than one core: each
    stream's work holds Python's global lock most of the time. The workers are forked from this
    process after the database is read, so they share its memory; a signal to this process stops
    them too."""
    import multiprocessing
    import socket

    host, port = parse_address(address, "--serve")
    udp = parse_address(livelink, "--livelink") if livelink is not None else None
    if workers < 1:
        raise InputError(f"--workers {workers}: give 1 or more processes.")
    if workers > 1 and not hasattr(socket, "SO_REUSEPORT"):
        raise InputError("--workers above 1 needs SO_REUSEPORT (Linux, BSD, macOS); use --workers 1 here.")
    if workers > 1 and port == 0:  # one free port for every worker
        with socket.socket(socket.AF_INET6 if ":" in host else socket.AF_INET) as probe:
            try:
                probe.bind((host, 0))
            except OSError as exc:
                raise InputError(f"--serve {address}: cannot listen there ({exc.strerror or exc}).") from None
            port = probe.getsockname()[1]
    children = []
    if workers > 1:
        context = multiprocessing.get_context("fork")
        children = [context.Process(target=_worker, args=(model, align, host, port, udp), daemon=True)
                    for _ in range(workers - 1)]
        for child in children:
            child.start()
    server = StreamServer(model, align, host, port, livelink=udp, reuse_port=workers > 1)

    def announce(bound: int) -> None:
        if ready is not None:
            ready(f"listening on ws://{host}:{bound}" + (f" ({workers} processes)" if workers > 1 else ""))
        sys.stdout.flush()

    try:
        asyncio.run(server.serve_until_signal(announce))
    except OSError as exc:
        raise InputError(f"--serve {address}: cannot listen there ({exc.strerror or exc}).") from None
    finally:
        for child in children:
            child.terminate()  # SIGTERM: it closes its connections (1001) and ends
        for child in children:
            child.join(10)
            if child.is_alive():
                child.kill()


def _worker(model: LiveModel, align: AlignSettings, host: str, port: int, udp) -> None:
    """One more process serving the same port."""
    asyncio.run(StreamServer(model, align, host, port, livelink=udp, reuse_port=True).serve_until_signal())
