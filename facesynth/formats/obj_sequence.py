"""OBJ sequences: one Wavefront OBJ per frame, for tools that import a numbered mesh sequence
(Blender's "Stop-motion OBJ", Maya, MotionBuilder, Houdini's file SOP with ``$F``).

Files ``frame_000001.obj`` ... (numbered from 1, six digits, so they sort), each with the frame's
vertices (``v x y z`` in millimetres, facesynth's axes: +y up, the face toward +z) and the same
triangle list (``f a b c``, 1-based, counter-clockwise seen from outside), formatted once and
written after every frame's vertices so every file is a complete mesh. The first line comments the
frame, its time in seconds and the rate.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

import numpy as np


def frame_name(i: int) -> str:
    """File name of frame ``i`` (0-based): ``frame_000001.obj`` for the first."""
    return f"frame_{i + 1:06d}.obj"


def write_obj_sequence(folder: Path, faces: np.ndarray, blocks: Iterable[tuple[int, np.ndarray]], n_frames: int,
                       fps: float) -> list[Path]:
    """Write a frame's OBJ into ``folder`` for each frame of ``blocks`` ((start, (n, V, 3) mm
    vertices of frames start .. start + n - 1), in order, so that memory stays one block) of an
    animation of ``n_frames`` frames at ``fps`` frames/s; ``faces`` (F, 3) 0-based triangles.
    Returns the files in order."""
    faces_text = "".join(f"f {a} {b} {c}\n" for a, b, c in (np.asarray(faces) + 1))
    files: list[Path] = []
    for start, block in blocks:
        for k, v in enumerate(block):
            i = start + k
            path = Path(folder) / frame_name(i)
            vertices = np.asarray(v, np.float64)
            lines = [f"# facesynth export: frame {i + 1} of {n_frames}, t = {i / fps:.6f} s at {fps:g} "
                     "frames/s; millimetres, +y up, face toward +z\n"]
            lines.append(("v %.4f %.4f %.4f\n" * len(vertices)) % tuple(vertices.ravel().tolist()))
            lines.append(faces_text)
            path.write_text("".join(lines), encoding="utf-8")
            files.append(path)
    return files
