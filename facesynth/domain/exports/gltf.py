"""The ``gltf`` and ``glb`` exports: the rig mesh with its morph targets and a weights animation,
the speech beside it (the file itself: :mod:`facesynth.formats.gltf`, the one module that reads
and writes glTF). Units and axes are in ``docs/exports.md``.
"""

from __future__ import annotations

from pathlib import Path

from facesynth.formats import gltf

from .animation import Exportable
from .format import ExportFormat, ExportOptions


class Gltf(ExportFormat):
    """The rig mesh with its morph targets and one weights animation (``binary``: GLB), the
    provenance in ``extras``, naming the speech beside it where there is one."""

    carries = "weights"
    takes_audio = True

    def __init__(self, binary: bool) -> None:
        self.binary = binary
        self.name = "glb" if binary else "gltf"

    def write(self, anim: Exportable, path: Path, options: ExportOptions, audio_name: str | None) -> list[Path]:
        (rest, faces), (rig, weights) = anim.mesh(), anim.rig_weights()
        rotation, translation = anim.head() if options.head_motion else (None, None)
        doc, data = gltf.build(rest, faces, rig.deltas, rig.shape_names, anim.times, weights, rotation, translation,
                               audio_name, name=options.name or Path(path).stem, provenance=anim.provenance)
        gltf.write(path, doc, data, binary=self.binary)
        return [path]


GLTF = Gltf(binary=False)
GLB = Gltf(binary=True)
