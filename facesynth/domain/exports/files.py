"""The export formats written from one :class:`~.animation.Exportable` (``facesynth export`` and
the outputs of ``facesynth batch``, through :func:`~.format.write_export`): Live Link Face CSV,
glTF/GLB with the speech beside it, USD/USDA and C3D markers (OBJ sequences:
:mod:`.objseq`). Each writes one file at the path given; the units and axes per format are in
``docs/exports.md``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from facesynth.base.config import ExportSettings
from facesynth.base.errors import InputError
from facesynth.formats import gltf, usd
from facesynth.formats import livelink_face as livelink
from facesynth.formats.mocap import MarkerTake, write_c3d

from .animation import Exportable
from .format import ExportFormat, ExportOptions


def require_usd(fmt: str = "usd") -> None:
    """Refuse, in one sentence saying what to install, a USD output without Pixar's usd-core."""
    if not usd.available():
        raise InputError(f"{fmt} export needs Pixar's usd-core, which is not installed; "
                         "run `pip install 'facesynth[usd]'` (or `pip install usd-core`).")


class ArkitCsv(ExportFormat):
    """The Live Link Face CSV of the rig weights (mapped to the 52 ARKit shapes by the rig), the
    eyes from the gaze where known and, with head motion, the head's yaw, pitch and roll; at
    ``export.arkit_fps`` (the app's 60 frames/s) unless a rate is asked."""

    name = "arkit-csv"
    carries = "weights"

    def rate(self, anim: Exportable, settings: ExportSettings) -> float:
        return settings.arkit_fps

    def write(self, anim: Exportable, path: Path, options: ExportOptions, audio_name: str | None) -> list[Path]:
        rig, weights = anim.rig_weights()
        head = livelink.head_angles(anim.head()[0]) if options.head_motion else None
        eyes = livelink.eye_angles(anim.gaze) if anim.gaze is not None else None
        livelink.write(path, rig.arkit_names, rig.to_arkit(weights), anim.fps, head, eyes)
        return [path]


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


ARKIT_CSV = ArkitCsv()
GLTF = Gltf(binary=False)
GLB = Gltf(binary=True)
USD = Usd("usd")
USDA = Usd("usda")
C3D = C3d()
