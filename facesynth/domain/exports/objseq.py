"""OBJ sequences: one Wavefront OBJ per frame, for tools that import a numbered mesh sequence
(Blender's "Stop-motion OBJ", Maya, MotionBuilder, Houdini's file SOP with ``$F``).

Files ``frame_000001.obj`` ... (numbered from 1, six digits, so they sort), each with the frame's
vertices (``v x y z`` in millimetres, facesynth's axes: +y up, the face toward +z) and the same
triangle list (``f a b c``, 1-based, counter-clockwise seen from outside), formatted once and
written after every frame's vertices so every file is a complete mesh. The first line comments the
frame, its time in seconds and the rate.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .animation import Exportable
from .format import ExportFormat, ExportOptions

#: Frames evaluated at once (memory: one block of vertices).
BLOCK = 64


def frame_name(i: int) -> str:
    """File name of frame ``i`` (0-based): ``frame_000001.obj`` for the first."""
    return f"frame_{i + 1:06d}.obj"


def write_sequence(folder: Path, anim: Exportable, head_motion: bool = False) -> list[Path]:
    """Write every frame of ``anim`` into ``folder``; returns the files in order."""
    rest, faces = anim.mesh()
    faces_text = "".join(f"f {a} {b} {c}\n" for a, b, c in (np.asarray(faces) + 1))
    vertex_format = "v %.4f %.4f %.4f\n" * len(rest)
    files = []
    for start in range(0, anim.n_frames, BLOCK):
        stop = min(start + BLOCK, anim.n_frames)
        block = anim.mesh_frames(start, stop)
        if head_motion:
            block = anim.with_head(block, start)
        for k, v in enumerate(block):
            i = start + k
            path = Path(folder) / frame_name(i)
            lines = [f"# facesynth export: frame {i + 1} of {anim.n_frames}, t = {i / anim.fps:.6f} s at {anim.fps:g} "
                     "frames/s; millimetres, +y up, face toward +z\n"]
            lines.append(vertex_format % tuple(np.asarray(v, np.float64).ravel().tolist()))
            lines.append(faces_text)
            path.write_text("".join(lines), encoding="utf-8")
            files.append(path)
    return files


class ObjSequence(ExportFormat):
    """A folder of OBJs, one per frame (:func:`write_sequence`)."""

    name = "obj-seq"
    carries = "mesh"
    folder = True
    folder_what = "the OBJ sequence"

    def write(self, anim: Exportable, path: Path, options: ExportOptions, audio_name: str | None) -> list[Path]:
        return write_sequence(path, anim, options.head_motion)


OBJ_SEQUENCE = ObjSequence()
