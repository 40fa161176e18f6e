"""The ``usd`` and ``usda`` exports: UsdSkel blendshapes for rig curves, time-sampled points for a
mesh animation (the stage itself, its layout, units and provenance: :mod:`facesynth.formats.usd`,
through Pixar's usd-core, an optional dependency).
"""

from __future__ import annotations

from pathlib import Path

from facesynth.base.errors import InputError
from facesynth.formats import usd

from .animation import Exportable
from .format import ExportFormat, ExportOptions


def require_usd(fmt: str = "usd") -> None:
    """Refuse, in one sentence saying what to install, a USD output without Pixar's usd-core."""
    if not usd.available():
        raise InputError(f"{fmt} export needs Pixar's usd-core, which is not installed; "
                         "run `pip install 'facesynth[usd]'` (or `pip install usd-core`).")


class Usd(ExportFormat):
    """UsdSkel blendshapes driven by a SkelAnimation for rig weights, else time-sampled points;
    the provenance in metadata (``usda``: the text encoding, picked by the file's suffix)."""

    carries = "mesh"
    named_file = True

    def __init__(self, name: str) -> None:
        self.name = name

    def require(self) -> None:
        require_usd(self.name)

    def write(self, anim: Exportable, path: Path, options: ExportOptions, audio_name: str | None) -> list[Path]:
        head = anim.head() if options.head_motion else None
        rest, faces = anim.mesh()
        if anim.weights is not None:
            rig, weights = anim.rig_weights()
            usd.write_blendshapes(path, rest, faces, rig.deltas, rig.shape_names, weights, anim.fps, head,
                                  provenance=anim.provenance)
        else:
            usd.write_points(path, rest, faces, anim.mesh_frames, anim.n_frames, anim.fps, head,
                             provenance=anim.provenance)
        return [path]


USD = Usd("usd")
USDA = Usd("usda")
