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

import numpy as np

from facesynth.base.config import ExportSettings
from facesynth.base.errors import UsageError
from facesynth.base.registry import EXPORT_FORMATS
from facesynth.domain.exports.animation import Exportable, load, use_mesh
from facesynth.domain.exports.format import ExportFormat, ExportOptions, audio_path, write_export
from facesynth.formats.audio import read_audio
from facesynth.model.artifacts import check_output, check_output_folder


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

    The steps are the ones :mod:`facesynth.api` calls (:func:`export_format`, :func:`write`), so
    the command and the API write the same files."""
    form = export_format(fmt, output, audio, overwrite)
    return write(form, load(artifact), output, settings, fps=fps, head_motion=head_motion, audio=audio, mesh=mesh,
                 overwrite=overwrite)


def export_format(fmt: str, output: Path, audio: Path | None = None, overwrite: bool = False) -> ExportFormat:
    """The registered export format ``fmt``, after the checks made before any work: its optional
    dependency installed, ``audio`` only for a format that names one (and a WAV that reads), the
    outputs writable and not clobbered."""
    if fmt not in EXPORT_FORMATS:
        raise UsageError(f"unknown format {fmt!r}; choose one of {', '.join(EXPORT_FORMATS.names())}.")
    form: ExportFormat = EXPORT_FORMATS.get(fmt)
    form.require()
    if audio is not None and not form.takes_audio:
        takes = [e.name for e in EXPORT_FORMATS.entries() if e.load().takes_audio]
        raise UsageError(f"--audio goes with {' and '.join(takes)} (the other formats carry no audio reference).")
    if form.folder:
        check_output_folder(output, form.folder_what, overwrite)
    else:
        check_output(output, overwrite)
    if audio is not None:
        check_output(audio_path(output), overwrite)
        read_audio(audio)  # a WAV that cannot be read is refused before anything is written
    return form


def write(form: ExportFormat, anim: Exportable, output: Path, settings: ExportSettings, *, fps: float | None = None,
          head_motion: bool = False, audio: Path | None = None, mesh: Path | None = None,
          overwrite: bool = False) -> ExportResult:
    """The core of ``export``: ``anim`` (with the faces of ``mesh`` when given) written as ``form``
    at ``output``, at ``fps`` or the format's rate (:meth:`ExportFormat.rate`)."""
    if mesh is not None:
        anim = use_mesh(anim, mesh)
    form.check(anim, head_motion)
    rate = fps if fps is not None else form.rate(anim, settings)
    if not (np.isfinite(rate) and 0 < rate <= 1000):
        raise UsageError(f"--fps {rate:g} is not a frame rate; give a number of frames per second in (0, 1000].")
    anim = anim.resampled(rate)
    files = write_export(form, anim, output, ExportOptions(head_motion, Path(output).stem, audio), overwrite)
    return ExportResult(anim.n_frames, anim.fps, anim.duration_s, files, anim.kind)
