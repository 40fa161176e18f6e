"""One sentence of speech in the files users have: the held-out sentence of the tiny sample corpus
(a 16 kHz WAV) encoded by the ffmpeg that ships with facesynth (``imageio-ffmpeg``) as M4A (AAC),
MP3, Opus (``.opus``, and Opus in ``.ogg``) and an MP4 (a tiny grey picture and AAC sound), with
a video without sound and a text file named like audio, for the tests of every command that takes
speech (the ``coded_speech`` fixture of conftest.py).

Each encoder is looked up in the bundled ffmpeg's ``-encoders`` list: a build without one leaves
that format out, and :func:`coded` skips its tests, naming the encoder.
"""

from __future__ import annotations

import subprocess
from pathlib import Path

import imageio_ffmpeg
import numpy as np
import pytest

#: name -> (file, the encoder it needs, ffmpeg's options after the inputs).
FORMATS = {
    "m4a": ("speech.m4a", "aac", ["-c:a", "aac", "-b:a", "96k"]),
    "mp3": ("speech.mp3", "libmp3lame", ["-c:a", "libmp3lame", "-b:a", "96k"]),
    "opus": ("speech.opus", "libopus", ["-c:a", "libopus", "-b:a", "48k"]),
    "ogg": ("speech.ogg", "libopus", ["-c:a", "libopus", "-b:a", "48k"]),
    "mp4": ("speech.mp4", "aac", ["-c:v", "mpeg4", "-c:a", "aac", "-b:a", "96k", "-shortest"]),
}

#: The compressed formats the command tests compare with the WAV.
COMPRESSED = tuple(FORMATS)


def same_motion(name: str) -> float:
    """The r (:func:`correlation`) above which a motion from the sentence coded as ``name`` is the
    WAV's. The tolerance is the aligner's, not the decoder's: AAC (``m4a``, ``mp4``) puts one
    boundary 30 ms later and the DP takes a different node there, and with the voice's articulation
    in the mouth (the method's gaps in the voice's order) that node moves more of the mouth: r 0.930
    (0.962 with the loudness step), while the articulation model's curves from the AAC follow the
    MP3's at r 0.993-0.995; MP3, Opus and Ogg keep every boundary within 10 ms: r 0.993."""
    return 0.92 if FORMATS[name][1] == "aac" else 0.98


def encoders() -> set[str]:
    """The audio encoders of the bundled ffmpeg."""
    out = subprocess.run([imageio_ffmpeg.get_ffmpeg_exe(), "-hide_banner", "-encoders"], capture_output=True,
                         text=True, check=True).stdout
    return {line.split()[1] for line in out.splitlines() if line.strip().startswith("A") and len(line.split()) > 1}


def _ffmpeg(*args: str) -> None:
    subprocess.run([imageio_ffmpeg.get_ffmpeg_exe(), "-hide_banner", "-nostdin", "-v", "error", "-y", *args],
                   check=True)


def encode_all(wav: Path, folder: Path) -> None:
    """Write every format of :data:`FORMATS` whose encoder the bundled ffmpeg has, from ``wav``,
    into ``folder``; also ``silent.mp4`` (a second of picture, no sound) and ``notes.m4a`` (text)."""
    have = encoders()
    for file, encoder, options in FORMATS.values():
        if encoder not in have:
            continue
        if file.endswith(".mp4"):  # a moving picture's container: a grey picture at 25 frames/s, and the sound
            _ffmpeg("-f", "lavfi", "-i", "color=c=gray:s=64x48:r=25", "-i", str(wav), "-map", "0:v", "-map", "1:a",
                    *options, str(folder / file))
        else:
            _ffmpeg("-i", str(wav), *options, str(folder / file))
    _ffmpeg("-f", "lavfi", "-i", "color=c=gray:s=64x48:r=25:d=1", "-c:v", "mpeg4", str(folder / "silent.mp4"))
    (folder / "notes.m4a").write_text("these are notes about the take, not its sound\n", encoding="utf-8")


def coded(files: dict[str, Path], name: str) -> Path:
    """The sentence as ``name`` (a key of :data:`FORMATS`), or a skip naming the missing encoder."""
    if name not in files:
        pytest.skip(f"the bundled ffmpeg has no {FORMATS[name][1]} encoder for {name}")
    return files[name]


def correlation(a: np.ndarray, b: np.ndarray) -> float:
    """Pearson's r of two motions over every coordinate of their common frames (their mean
    pose removed), the measure of "the same motion" in the tests of coded audio."""
    n = min(len(a), len(b))
    x = np.asarray(a[:n], np.float64).reshape(n, -1)
    y = np.asarray(b[:n], np.float64).reshape(n, -1)
    x, y = x - x.mean(axis=0), y - y.mean(axis=0)
    return float((x * y).sum() / np.sqrt((x * x).sum() * (y * y).sum()))


def boundary_shift(a, b) -> float:
    """The largest shift (s) between the phone boundaries of two segmentations with the same
    phones (``Segment``-like: start, end, label); the phones must be the same."""
    assert [s.label for s in a] == [s.label for s in b]
    return max((max(abs(x.start - y.start), abs(x.end - y.end)) for x, y in zip(a, b)), default=0.0)
