"""The ``c3d`` export: the markers, labelled, in millimetres (the file itself:
:func:`facesynth.formats.mocap.write_c3d`, beside its reader).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from facesynth.formats.mocap import MarkerTake, write_c3d

from .animation import Exportable
from .format import ExportFormat, ExportOptions


class C3d(ExportFormat):
    """The markers, mm, labelled, at the animation's rate."""

    name = "c3d"
    carries = "markers"

    def write(self, anim: Exportable, path: Path, options: ExportOptions, audio_name: str | None) -> list[Path]:
        markers, names = anim.marker_motion()
        if options.head_motion:
            markers = anim.with_head(markers)
        write_c3d(path, MarkerTake(np.asarray(markers, np.float32), list(names), anim.fps))
        return [path]


C3D = C3d()
