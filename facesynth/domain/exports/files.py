"""The rig-carrying export formats written from one :class:`~.animation.Exportable`, shared by
``facesynth export`` and ``facesynth batch``: Live Link Face CSV (:func:`write_arkit_csv`), glTF
with its audio beside it (:func:`write_gltf`) and USD (:func:`write_usd`). Each writes one file
at the path given (the callers publish it atomically); the units and axes per format are in
``docs/exports.md``.
"""

from __future__ import annotations

import shutil
from pathlib import Path

from facesynth.base.errors import InputError
from facesynth.formats import gltf
from facesynth.formats import livelink_face as livelink
from facesynth.model.artifacts import publish, temporary_path

from . import usd
from .animation import Exportable


def audio_path(output: Path) -> Path:
    """Where the WAV beside a glTF output goes: the output's name with ``.wav``."""
    return Path(output).with_suffix(".wav")


def require_usd(fmt: str = "usd") -> None:
    """Refuse, in one sentence saying what to install, a USD output without Pixar's usd-core."""
    if not usd.available():
        raise InputError(f"{fmt} export needs Pixar's usd-core, which is not installed; "
                         "run `pip install 'facesynth[usd]'` (or `pip install usd-core`).")


def write_arkit_csv(anim: Exportable, path: Path, head_motion: bool = False) -> None:
    """The Live Link Face CSV of ``anim``'s rig weights (mapped to the 52 ARKit shapes by its
    rig) at ``anim``'s rate, the eyes from its gaze where known and, with ``head_motion``, the
    head's yaw, pitch and roll."""
    head = livelink.head_angles(anim.head_rotation) if head_motion else None
    eyes = livelink.eye_angles(anim.gaze) if anim.gaze is not None else None
    livelink.write(path, anim.rig.arkit_names, anim.rig.to_arkit(anim.weights), anim.fps, head, eyes)


def write_gltf(anim: Exportable, path: Path, audio_name: str | None, head_motion: bool = False, binary: bool = False,
               name: str | None = None) -> None:
    """``anim``'s rig mesh with its morph targets and one weights animation as glTF (``binary``:
    GLB), the provenance in ``extras``; ``audio_name``: the file name of the WAV beside it (the
    caller copies it there), or None; ``name``: the scene's name (default the file's stem)."""
    doc, data = gltf.build(anim.rest, anim.faces, anim.rig.deltas, anim.rig.shape_names, anim.times, anim.weights,
                           anim.head_rotation if head_motion else None,
                           anim.head_translation if head_motion else None,
                           audio_name, name=name or Path(path).stem, provenance=anim.provenance)
    gltf.write(path, doc, data, binary=binary)


def write_usd(anim: Exportable, path: Path, head_motion: bool = False) -> None:
    """``anim`` as USD (the format by ``path``'s extension): UsdSkel blendshapes driven by a
    SkelAnimation for rig weights, else time-sampled points; the provenance in metadata."""
    head = (anim.head_rotation, anim.head_translation) if head_motion else (None, None)
    if anim.weights is not None:
        usd.write_blendshapes(path, anim.rest, anim.faces, anim.rig.deltas, anim.rig.shape_names, anim.weights,
                              anim.fps, *head, provenance=anim.provenance)
    else:
        usd.write_points(path, anim.rest, anim.faces, anim.mesh_frames, anim.n_frames, anim.fps, *head,
                         provenance=anim.provenance)


class named_temporary:
    """A temporary file with the output's own name (libraries such as USD pick the format by the
    extension) inside a temporary folder beside the output, published at the output on success."""

    def __init__(self, output: Path, overwrite: bool):
        self.output, self.overwrite = Path(output), overwrite
        self.folder = temporary_path(self.output)

    def __enter__(self) -> Path:
        if self.folder.exists():
            shutil.rmtree(self.folder)
        self.folder.mkdir()
        return self.folder / self.output.name

    def __exit__(self, exc_type, exc, tb) -> None:
        try:
            if exc_type is None:
                publish(self.folder / self.output.name, self.output, self.overwrite)
        finally:
            shutil.rmtree(self.folder, ignore_errors=True)
