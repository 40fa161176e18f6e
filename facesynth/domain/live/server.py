"""The transports of ``facesynth stream``.

- :func:`run_pipe`: audio on a byte stream (standard input: a WAV or raw 16-bit PCM at 16 kHz
  mono; an MP4, Ogg, FLAC, MP3 or Matroska file there is refused, naming ``--audio FILE``), one
  JSON message per line out (the ``hello``, the frames, the ``end``).
- :class:`StreamServer`: a WebSocket server (the ``websockets`` package). A client sends binary
  messages of PCM and text messages of JSON control (:mod:`.session`); it gets the ``hello``,
  then the frames as JSON text messages, and ``{"type": "error", "message": ...}`` for a bad
  message (the stream goes on). Each client's outgoing messages wait in a queue of at most
  ``stream.queue_messages``; a client that falls further behind is disconnected (close code
  1008, "client too slow"): frames dropped in the middle of a stream would make the face jump,
  and a queue without bound would let one slow client take the server's memory.
  Incoming messages are limited to ``stream.max_message_bytes`` (close code 1009 above it).
  SIGINT and SIGTERM close every connection (code 1001) and stop the server.
- Every frame can also go to Unreal's Live Link as a Live Link Face UDP packet
  (:mod:`.livelink`).
"""

from __future__ import annotations

import asyncio
import io
import json
import logging
import signal
import wave
from collections.abc import Callable
from typing import BinaryIO, cast

from facesynth.base.config import AlignSettings
from facesynth.base.errors import FacesynthError, InputError

from .livelink import LiveLinkSender
from .phones import SAMPLE_RATE
from .session import Session
from .synthesizer import LiveModel

log = logging.getLogger(__name__)


def _audio_source(stream: BinaryIO, where: str) -> tuple[BinaryIO | wave.Wave_read, bytes]:
    """The PCM source of ``stream``: a WAV (checked: 16 kHz, mono, 16-bit) or raw PCM. Returns the
    reader and the bytes already read from a raw stream."""
    head = stream.read(12)
    if head[:4] == b"RIFF" and head[8:12] == b"WAVE":
        try:
            reader = wave.open(cast(BinaryIO, _Prefixed(head, stream)), "rb")
        except (wave.Error, EOFError) as exc:
            raise InputError(f"{where}: not a readable WAV ({exc}).") from None
        if (reader.getframerate(), reader.getnchannels(), reader.getsampwidth()) != (SAMPLE_RATE, 1, 2):
            raise InputError(f"{where}: the WAV is {reader.getframerate()} Hz, {reader.getnchannels()} channel(s), "
                             f"{8 * reader.getsampwidth()}-bit; live input is {SAMPLE_RATE} Hz mono 16-bit "
                             "(give the file with --audio FILE, which converts any sound file, or convert it, "
                             f"e.g. ffmpeg -i IN -ar {SAMPLE_RATE} -ac 1 -c:a pcm_s16le OUT.wav).")
        return reader, b""
    container = _container(head)
    if container is not None:
        raise InputError(f"{where}: this is {container}, not raw PCM; give the file with --audio FILE, which decodes it, "
                         f"or send 16 kHz mono 16-bit PCM (e.g. ffmpeg -i IN -ar {SAMPLE_RATE} -ac 1 -f s16le -).")
    return stream, head


def _container(head: bytes) -> str | None:
    """The kind of sound file whose first 12 bytes are ``head`` (None: taken as raw PCM). Speech
    starts near silence, so raw PCM does not begin with these signatures in practice."""
    if head[4:8] == b"ftyp":
        return "an MP4/M4A/MOV file"
    for magic, kind in ((b"OggS", "an Ogg file (Opus, Vorbis)"), (b"fLaC", "a FLAC file"), (b"ID3", "an MP3 file"),
                        (b"\x1aE\xdf\xa3", "a Matroska/WebM file")):
        if head.startswith(magic):
            return kind
    return None


class _Prefixed(io.RawIOBase):
    """A read-only stream of ``prefix`` followed by ``rest`` (``wave`` reads a pipe from its start)."""

    def __init__(self, prefix: bytes, rest: BinaryIO):
        self.prefix, self.rest = prefix, rest

    def readable(self) -> bool:
        return True

    def readinto(self, buffer) -> int:
        if self.prefix:
            n = min(len(buffer), len(self.prefix))
            buffer[:n], self.prefix = self.prefix[:n], self.prefix[n:]
            return n
        data = self.rest.read(len(buffer))
        buffer[: len(data)] = data
        return len(data)


def run_pipe(model: LiveModel, align: AlignSettings, source: BinaryIO, write: Callable[[str], None],
             where: str = "standard input", livelink: LiveLinkSender | None = None, markers: bool = False) -> int:
    """Stream ``source`` (WAV or raw PCM) through a session; each message is passed to ``write`` as
    one JSON line (without the newline). Returns the number of frames."""
    session = Session(model, align, where)
    session.markers = markers
    reader, first = _audio_source(source, where)
    chunk_samples = max(1, int(round(model.stream.chunk_s * SAMPLE_RATE)))
    write(json.dumps(session.hello()))

    def out(messages):
        for m in messages:
            if livelink is not None and m["type"] == "frame":
                livelink.send(m["index"], m["arkit"])
            write(json.dumps(m))

    if first:
        out(session.audio(first))
    while True:
        data = reader.readframes(chunk_samples) if isinstance(reader, wave.Wave_read) else reader.read(2 * chunk_samples)
        if not data:
            break
        out(session.audio(data))
    out(session.end())
    return session.sent


class StreamServer:
    """The WebSocket server (see the module docstring). ``host`` should be a loopback or LAN
    address the user chose; ``port`` 0 picks a free one (:attr:`port` after :meth:`start`)."""

    def __init__(self, model: LiveModel, align: AlignSettings, host: str, port: int,
                 livelink: tuple[str, int] | None = None, socket_send_buffer: int | None = None,
                 reuse_port: bool = False):
        self.model, self.align = model, align
        self.host, self.port = host, port
        self.livelink = livelink
        self.socket_send_buffer = socket_send_buffer
        self.reuse_port = reuse_port  # several processes serve one port (the kernel spreads the clients)
        self.server = None
        self.clients = 0
        self.connections: set = set()
        self.most_queued = 0   # the most messages that ever waited for one client
        self.stopped = asyncio.Event()

    async def start(self) -> None:
        from websockets.asyncio.server import serve

        s = self.model.stream
        server = await serve(self._handle, self.host, self.port, max_size=s.max_message_bytes, max_queue=16,
                             ping_interval=None, reuse_port=self.reuse_port or None)
        self.server = server
        self.port = server.sockets[0].getsockname()[1]

    async def stop(self) -> None:
        """Close every connection (1001, going away) and the listening socket."""
        if self.server is not None:
            self.server.close(close_connections=True)
            await self.server.wait_closed()
        self.stopped.set()

    async def serve_until_signal(self, ready: Callable[[int], None] | None = None) -> None:
        """Start, call ``ready(port)``, serve until SIGINT or SIGTERM, then stop cleanly."""
        await self.start()
        loop = asyncio.get_running_loop()
        stop = asyncio.Event()
        for sig in (signal.SIGINT, signal.SIGTERM):
            loop.add_signal_handler(sig, stop.set)
        try:
            if ready is not None:
                ready(self.port)
            await stop.wait()
        finally:
            for sig in (signal.SIGINT, signal.SIGTERM):
                loop.remove_signal_handler(sig)
            await self.stop()

    async def _handle(self, ws) -> None:
        from websockets.exceptions import ConnectionClosed

        self.clients += 1
        name = f"client {self.clients}"
        if self.socket_send_buffer is not None:
            import socket

            ws.transport.get_extra_info("socket").setsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF, self.socket_send_buffer)
            ws.transport.set_write_buffer_limits(high=self.socket_send_buffer)
        queue: asyncio.Queue = asyncio.Queue(self.model.stream.queue_messages)
        sender = asyncio.create_task(self._send(ws, queue))
        udp = None
        if self.livelink is not None:
            udp = LiveLinkSender(*self.livelink, subject="facesynth", device_id=f"facesynth-{self.clients}",
                                 fps=self.model.stream.fps, arkit_names=self.model.arkit_names)
        session = Session(self.model, self.align, name)
        self.connections.add(ws)
        too_slow = False

        def put(message: dict) -> bool:
            nonlocal too_slow
            if too_slow:
                return False
            try:
                queue.put_nowait(json.dumps(message))
                self.most_queued = max(self.most_queued, queue.qsize())
            except asyncio.QueueFull:
                too_slow = True
                log.warning("%s: %d messages waiting; disconnected as too slow", name, queue.qsize())
                asyncio.ensure_future(ws.close(1008, "client too slow"))
                return False
            if udp is not None and message["type"] == "frame":
                udp.send(message["index"], message["arkit"])
            return True

        try:
            put(session.hello())
            async for message in ws:
                try:
                    if isinstance(message, bytes):
                        replies = await asyncio.to_thread(session.audio, message)
                    else:
                        replies = await asyncio.to_thread(session.control, message)
                except FacesynthError as exc:
                    replies = [{"type": "error", "message": str(exc)}]
                for reply in replies:
                    if not put(reply):
                        break
                if too_slow:
                    break
        except ConnectionClosed:
            pass
        finally:
            self.connections.discard(ws)
            if udp is not None:
                udp.close()
            if not too_slow:
                await queue.put(None)  # the sender finishes what is queued, then stops
                try:
                    await asyncio.wait_for(sender, 5.0)
                except asyncio.TimeoutError:
                    sender.cancel()
            else:
                sender.cancel()

    @staticmethod
    async def _send(ws, queue: asyncio.Queue) -> None:
        from websockets.exceptions import ConnectionClosed

        while True:
            message = await queue.get()
            if message is None:
                return
            try:
                await ws.send(message)
            except ConnectionClosed:
                return
