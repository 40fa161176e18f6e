"""``facesynth stream``: live synthesis. Audio in as it arrives (standard input, or WebSocket
clients), frames of ARKit curves out with a fixed latency (JSON lines, WebSocket messages, and
optionally Live Link Face UDP packets). The work is in :mod:`facesynth.live`; this module reads
the database once and starts a transport. See docs/live.md.
"""

from __future__ import annotations

import asyncio
import sys
import time
from dataclasses import replace
from pathlib import Path
from typing import BinaryIO, Callable

from ..config import AlignSettings, SolveSettings, StreamSettings, SynthesizeSettings
from ..errors import InputError
from ..live.core import LiveModel
from ..live.livelink import LiveLinkSender
from ..live.server import StreamServer, run_pipe
from ..model.motiondb import MotionDatabase


def parse_address(text: str, what: str) -> tuple[str, int]:
    """``HOST:PORT`` as (host, port); port 0 (a free port) is allowed."""
    host, sep, port = text.rpartition(":")
    if not sep or not host or not port.isdigit() or not 0 <= int(port) <= 65535:
        raise InputError(f"{what} {text!r}: give HOST:PORT, e.g. 127.0.0.1:8765.")
    return host.strip("[]"), int(port)


def load_model(db_path: Path, synth: SynthesizeSettings, stream: StreamSettings, solve: SolveSettings,
               method: str | None = None, lookahead: int | None = None) -> LiveModel:
    """The shared live model of ``db_path`` (``method``/``lookahead`` override ``stream``'s)."""
    if method is not None:
        stream = replace(stream, method=method)
    if lookahead is not None:
        if lookahead < 0:
            raise InputError(f"--lookahead {lookahead}: give 0 or more phones.")
        stream = replace(stream, lookahead_phones=lookahead)
    return LiveModel(MotionDatabase.read(db_path), synth, stream, solve)


def run_stdin(model: LiveModel, align: AlignSettings, source: BinaryIO, write: Callable[[str], None], *,
              where: str, livelink: str | None = None, markers: bool = False, realtime: bool = False) -> int:
    """Stream ``source`` (WAV or raw PCM); returns the number of frames. ``realtime`` paces the
    reading at the audio's own speed (a file played as if it were arriving live)."""
    sender = None
    if livelink is not None:
        host, port = parse_address(livelink, "--livelink")
        sender = LiveLinkSender(host, port, "facesynth", "facesynth-0", model.stream.fps, model.arkit_names)
    if realtime:
        source = _Paced(source, model.stream.chunk_s)
    try:
        return run_pipe(model, align, source, write, where=where, livelink=sender, markers=markers)
    finally:
        if sender is not None:
            sender.close()


class _Paced:
    """A byte stream read no faster than 16 kHz 16-bit mono audio plays."""

    def __init__(self, source: BinaryIO, chunk_s: float):
        self.source, self.read_bytes, self.t0 = source, 0, None

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
          ready: Callable[[str], None] | None = None) -> None:
    """Serve WebSocket clients on ``address`` until SIGINT or SIGTERM; ``ready`` gets a line
    naming the address once the server listens."""
    host, port = parse_address(address, "--serve")
    udp = parse_address(livelink, "--livelink") if livelink is not None else None
    server = StreamServer(model, align, host, port, livelink=udp)

    def announce(bound: int) -> None:
        if ready is not None:
            ready(f"listening on ws://{host}:{bound}")
        sys.stdout.flush()

    try:
        asyncio.run(server.serve_until_signal(announce))
    except OSError as exc:
        raise InputError(f"--serve {address}: cannot listen there ({exc.strerror or exc}).") from None
