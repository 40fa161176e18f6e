"""``facesynth export``: a motion, mesh animation or rig curves -> a file another tool reads.

The formats are the registered ones (:data:`facesynth.base.registry.EXPORT_FORMATS`, written by
:mod:`facesynth.domain.exports`); the built-in ones (units and axes per format in
``docs/exports.md``):

* ``arkit-csv``: Live Link Face CSV (Unreal Live Link, MetaHuman) from rig curves, at
  ``export.arkit_fps`` (60 frames/s, the app's rate) unless ``--fps``;
* ``gltf`` / ``glb``: the rig mesh with its morph targets and one weights animation, from curves;
* ``usd`` / ``usda``: a mesh with time-sampled points (mesh animation) or UsdSkel blendshapes
  driven by a SkelAnimation (curves);
* ``c3d``: the markers (motion, mesh animation), mm, labelled, at the animation's rate;
* ``obj-seq``: a folder of OBJs, one per frame (``frame_000001.obj`` ...), from a mesh animation
  or curves.

A format that cannot carry what the artifact holds says what to run first; nothing is written
then. Outputs are written under a temporary name and published whole (a folder is renamed into
place), never replacing an existing output without ``--overwrite``.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from facesynth.base.config import ExportSettings
from facesynth.domain.exports import format as exporting
from facesynth.domain.exports.animation import load


@dataclass(frozen=True)
class ExportResult:
    """What ``facesynth export`` wrote.

    frames: frames exported.
    fps: their rate (frames/s).
    seconds: the animation's length (s).
    files: every file written: the output first, then a glTF's audio beside it, or an OBJ
        sequence's files inside its folder.
    kind: the kind of artifact exported ('motion', 'meshanim' or 'curves').
    """

    frames: int
    fps: float
    seconds: float
    files: list[Path]
    kind: str


def run(artifact: Path, fmt: str, output: Path, settings: ExportSettings, *, fps: float | None = None,
        head_motion: bool = False, audio: Path | None = None, mesh: Path | None = None,
        overwrite: bool = False) -> ExportResult:
    """Export ``artifact`` as ``fmt`` (a registered export format) to ``output``.

    The steps are the ones :mod:`facesynth.api` calls (:func:`exporting.chosen_format`,
    :func:`exporting.speech_beside`, :func:`exporting.export`), so the command and the API write
    the same files."""
    form = exporting.chosen_format(fmt, output, audio, overwrite)
    speech = exporting.speech_beside(audio)
    anim, files = exporting.export(form, load(artifact), output, settings, fps=fps, head_motion=head_motion,
                                   audio=speech, mesh=mesh, overwrite=overwrite)
    return ExportResult(anim.n_frames, anim.fps, anim.duration_s, files, anim.kind)
