"""``facesynth render``: mesh animations or rig curves -> AVI with the audio muxed in.

The views (``shaded``, ``markers``, ``side-by-side``), the camera, the audio fitted to each clip
and the video writing are :mod:`facesynth.domain.rendering.video` (shared with ``facesynth batch``); the
left half of ``side-by-side`` is labelled "synthesis", the right half, ``--compare``, "capture",
or as ``render.labels`` says. Rig curves (``solve``, ``retarget``, ``openfacefx``) pose their rig
in memory (the built-in rig, or ``--rig``), with the gaze of the rig's ``eyeLook*`` shapes and the
head motion they carry (``render.head_motion``). Marker motion does not record gaze, so ``deform``
leaves it unknown and the eyes of its mesh animation look ahead.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from facesynth.base.config import RenderSettings
from facesynth.domain.rendering.video import render_video


@dataclass(frozen=True)
class RenderResult:
    """What ``facesynth render`` wrote.

    frames: video frames.
    seconds: the video's length (s).
    frames_per_s: frames rendered per second of wall time.
    notes: what a plain mesh lacks (eye or mouth holes), once each.
    """

    frames: int
    seconds: float
    frames_per_s: float
    notes: list[str]


def run(anims: list[Path], audios: list[Path], out: Path, settings: RenderSettings, compare: list[Path] | None = None,
        overwrite: bool = False, rig_path: Path | None = None, binding: Path | None = None) -> RenderResult:
    """Render the animations (mesh animations or rig curves) one after another, each with its audio
    (none: silence), into the AVI ``out``; ``compare``: one animation beside all, or one per animation
    (side-by-side view); curves pose ``rig_path`` (None: the built-in rig)."""
    video = render_video(anims, audios, out, settings, compare, overwrite, rig_path, binding)
    return RenderResult(video.frames, video.seconds, video.frames_per_s, video.notes)
