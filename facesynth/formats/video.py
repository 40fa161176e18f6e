"""Video files read for their frames (mp4, mov, mkv, avi, mpg, ...), through the
ffmpeg that ``imageio-ffmpeg`` ships: what ``ingest`` tracks a filmed face in
(:mod:`facesynth.domain.capture.video_take`). Writing video is :mod:`facesynth.domain.rendering.video`.

* :func:`probe`: the frame rate, the picture's size and the sound's sample rate (None without
  sound), from ffmpeg's report of the first video and audio streams.
* :func:`frames`: the pictures as (H, W, 3) uint8 RGB at the container's nominal rate (ffmpeg
  ``-r``: a phone's variable-rate video is resampled to its nominal rate).

Its sound is read by :func:`facesynth.formats.audio.read_audio`, the one decoder of every audio input.
"""

from __future__ import annotations

import re
import subprocess
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import imageio_ffmpeg
import numpy as np

from facesynth.base.errors import InputError

#: File names read as video.
SUFFIXES = (".mp4", ".mov", ".mkv", ".avi", ".mpg", ".mpeg", ".m4v", ".webm")


@dataclass(frozen=True)
class VideoInfo:
    """fps : frames/s; size : (width, height) pixels; audio_rate : Hz of the first audio stream,
    None without sound."""

    fps: float
    size: tuple[int, int]
    audio_rate: int | None


def probe(path: Path) -> VideoInfo:
    """What ffmpeg reports of the video at ``path``; one sentence for a file without a video stream."""
    path = Path(path)
    result = subprocess.run([imageio_ffmpeg.get_ffmpeg_exe(), "-hide_banner", "-i", str(path)], capture_output=True,
                            text=True, errors="replace", check=False)
    video = re.search(r"Stream #\S+.*?: Video: .*", result.stderr)
    if video is None:
        raise InputError(f"{path}: ffmpeg finds no video stream in it; give a video file "
                         f"({', '.join(s[1:] for s in SUFFIXES)}).")
    fps = re.search(r"([\d.]+) fps", video.group(0)) or re.search(r"([\d.]+) tbr", video.group(0))
    size = re.search(r", (\d{2,5})x(\d{2,5})", video.group(0))
    if fps is None or size is None or float(fps.group(1)) <= 0:
        raise InputError(f"{path}: ffmpeg reports no frame rate or picture size for its video stream; re-encode it.")
    audio = re.search(r"Stream #\S+.*?: Audio: .*?(\d+) Hz", result.stderr)
    return VideoInfo(float(fps.group(1)), (int(size.group(1)), int(size.group(2))),
                     int(audio.group(1)) if audio else None)


def frames(path: Path, info: VideoInfo) -> Iterator[np.ndarray]:
    """The pictures of the video at ``path`` as (H, W, 3) uint8 RGB arrays at ``info.fps``."""
    reader = imageio_ffmpeg.read_frames(str(path), pix_fmt="rgb24", output_params=["-r", f"{info.fps:g}"])
    try:
        meta = next(reader)
        width, height = meta.get("size", info.size)
        for raw in reader:
            yield np.frombuffer(raw, np.uint8).reshape(height, width, 3)
    except (RuntimeError, OSError) as exc:
        raise InputError(f"{path}: ffmpeg cannot decode its pictures ({str(exc).strip()[-160:]}); re-encode the "
                         "video.") from None
    finally:
        reader.close()
