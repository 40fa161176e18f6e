"""Serving WebSocket clients from one or more processes (``facesynth stream --serve``,
``--workers``): the processes share the port (Linux's SO_REUSEPORT spreads the connections over
them), each running a :class:`.server.StreamServer` of the same live model.
"""

from __future__ import annotations

import asyncio
import socket
import sys
from collections.abc import Callable

from facesynth.base.config import AlignSettings
from facesynth.base.errors import InputError
from facesynth.domain.live.pipe import parse_address
from facesynth.domain.live.server import StreamServer
from facesynth.domain.live.synthesizer import LiveModel


def serve(model: LiveModel, align: AlignSettings, address: str, *, livelink: str | None = None,
          ready: Callable[[str], None] | None = None, workers: int = 1) -> None:
    """Serve WebSocket clients on ``address`` until SIGINT or SIGTERM; ``ready`` gets a line
    naming the address once the server listens. ``workers`` processes share the port (Linux's
    SO_REUSEPORT spreads the connections over them), so streams use more than one core: each
    stream's work holds Python's global lock most of the time. The workers are forked from this
    process after the database is read, so they share its memory; a signal to this process stops
    them too."""
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
    model.warm()  # before the workers fork: they share it, and no client's first phones wait for it
    children = []
    if workers > 1:
        import multiprocessing  # only for more than one process: the pipe and one server start without it

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
