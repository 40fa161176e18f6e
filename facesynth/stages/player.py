"""``facesynth player``: a motion, mesh animation or rig curves -> one self-contained HTML page
that plays it in 3D (three.js, orbit controls) with its audio, a scrub bar and, for an artifact
made from a synthesis, a timeline of the phones with their emotion and the take and database node
each came from (:mod:`facesynth.domain.exports.player`). A mesh is drawn whole (eyeballs, mouth cavity,
teeth, tongue) with ``render``'s shading and camera (``[render]`` fov_deg, yaw_deg, pitch_deg),
and the head moves with the artifact's head motion. No network is needed to view it."""

from __future__ import annotations

import base64
from dataclasses import dataclass
from pathlib import Path

from facesynth.base.config import RenderSettings
from facesynth.domain.exports.animation import load
from facesynth.domain.exports.player import live_payload, page, payload
from facesynth.domain.live.phones import SAMPLE_RATE
from facesynth.model.artifacts import atomic_path, check_output


@dataclass(frozen=True)
class PlayerResult:
    """What ``facesynth player ARTIFACT`` wrote.

    frames: frames of the animation.
    fps: their rate (frames/s).
    seconds: the animation's length (s).
    phones: phones on the timeline (none for an artifact not made from a synthesis).
    bytes: the page's size.
    """

    frames: int
    fps: float
    seconds: float
    phones: int
    bytes: int


@dataclass(frozen=True)
class LivePlayerResult:
    """What ``facesynth player --live`` wrote.

    vertices: the built-in rig's vertices.
    targets: its ARKit morph targets.
    seconds: the speech the page sends (s).
    bytes: the page's size.
    """

    vertices: int
    targets: int
    seconds: float
    bytes: int


def run(artifact: Path, output: Path, *, audio: Path | None = None, motion: Path | None = None,
        view: RenderSettings | None = None, overwrite: bool = False) -> PlayerResult:
    """Write the player page of ``artifact`` to ``output`` with the camera of ``view`` (``render``'s
    settings; None: the defaults)."""
    check_output(output, overwrite)
    anim = load(artifact, motion=motion)
    html = page(payload(anim, audio, view))
    with atomic_path(output, overwrite) as tmp:
        Path(tmp).write_text(html, encoding="utf-8")
    return PlayerResult(anim.n_frames, anim.fps, anim.duration_s, len(anim.phones), len(html.encode("utf-8")))


def run_live(url: str, output: Path, *, audio: Path | None = None, view: RenderSettings | None = None,
             overwrite: bool = False) -> LivePlayerResult:
    """Write a live page (the built-in rig, connecting to the stream server at ``url``) to ``output``
    with the camera of ``view`` (``render``'s settings; None: the defaults)."""
    check_output(output, overwrite)
    data = live_payload(url, audio, view=view)
    html = page(data)
    with atomic_path(output, overwrite) as tmp:
        Path(tmp).write_text(html, encoding="utf-8")
    seconds = len(base64.b64decode(data["pcm"])) / 2 / SAMPLE_RATE  # int16 samples at 16 kHz
    return LivePlayerResult(data["vertices"], len(data["targets"]), seconds, len(html.encode("utf-8")))

