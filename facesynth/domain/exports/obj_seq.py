"""The ``obj-seq`` export: a folder of OBJs, one per frame (the files themselves:
:mod:`facesynth.formats.obj_sequence`).
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import numpy as np

from facesynth.formats.obj_sequence import write_obj_sequence

from .animation import Exportable
from .format import ExportFormat, ExportOptions

#: Frames evaluated at once (memory: one block of vertices).
BLOCK = 64


def mesh_blocks(anim: Exportable, head_motion: bool = False) -> Iterator[tuple[int, np.ndarray]]:
    """The animation's mesh in blocks of :data:`BLOCK` frames: (start, (n, V, 3) mm), with the
    head motion applied when asked."""
    for start in range(0, anim.n_frames, BLOCK):
        block = anim.mesh_frames(start, min(start + BLOCK, anim.n_frames))
        yield start, anim.with_head(block, start) if head_motion else block


class ObjSequence(ExportFormat):
    """A folder of OBJs, one per frame (:func:`~facesynth.formats.obj_sequence.write_obj_sequence`)."""

    name = "obj-seq"
    carries = "mesh"
    folder = True
    folder_what = "the OBJ sequence"

    def write(self, anim: Exportable, path: Path, options: ExportOptions, audio_name: str | None) -> list[Path]:
        return write_obj_sequence(path, anim.mesh()[1], mesh_blocks(anim, options.head_motion), anim.n_frames,
                                  anim.fps)


OBJ_SEQUENCE = ObjSequence()
