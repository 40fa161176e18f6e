"""``facesynth stream``: live synthesis. Audio in as it arrives (standard input, or WebSocket
clients), frames of ARKit curves out with a fixed latency (JSON lines, WebSocket messages, and
optionally Live Link Face UDP packets). The work is in :mod:`facesynth.domain.live` (an audio
file or standard input: :mod:`~facesynth.domain.live.pipe`; the server's processes:
:mod:`~facesynth.domain.live.workers`); this module reads the database once and starts a
transport. See docs/live.md.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

from facesynth.base.config import AlignSettings, SolveSettings, StreamSettings, SynthesizeSettings, TrajectorySettings
from facesynth.base.errors import InputError
from facesynth.domain import methods
from facesynth.domain.live import workers as live_workers
from facesynth.domain.live.pipe import stream_audio
from facesynth.domain.live.synthesizer import LiveModel
from facesynth.domain.methods import MethodSettings
from facesynth.model.artifacts import artifact_kind


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


def run(model: LiveModel, align: AlignSettings, audio: str | Path, write: Callable[[str], None], *,
        livelink: str | None = None, markers: bool = False, realtime: bool = False) -> int:
    """Stream the audio file ``audio`` ('-': standard input, a WAV or raw PCM; a ``.pcm`` or
    ``.raw`` file: raw 16 kHz PCM; any other file decoded) and ``write`` each message; returns the
    number of frames (:func:`facesynth.domain.live.pipe.stream_audio`). ``livelink``: HOST:PORT
    to send the frames to as well; ``realtime``: read the audio no faster than it plays."""
    return stream_audio(model, align, audio, write, livelink=livelink, markers=markers, realtime=realtime)


def serve(model: LiveModel, align: AlignSettings, address: str, *, livelink: str | None = None,
          ready: Callable[[str], None] | None = None, workers: int = 1) -> None:
    """Serve WebSocket clients on ``address`` (HOST:PORT) from ``workers`` processes until SIGINT
    or SIGTERM (:func:`facesynth.domain.live.workers.serve`); ``ready`` gets a line naming the
    address once the server listens."""
    live_workers.serve(model, align, address, livelink=livelink, ready=ready, workers=workers)
