"""What an export format is, and the one place an export is written and published.

A format is an :class:`ExportFormat` (its own module) registered by one line in
:mod:`facesynth.domain.exports` (:data:`facesynth.base.registry.EXPORT_FORMATS`). ``facesynth
export`` and the outputs of ``facesynth batch`` both write through :func:`write_export`: the
format's refusals (what the artifact lacks, what to run first), its optional dependency, its rate,
the publishing (a file or a folder, renamed into place whole; a glTF's audio beside it, or
neither) and the files written. ``facesynth export`` and :func:`facesynth.export` share the steps
around it: :func:`chosen_format` (the checks made before any work) and :func:`export`.
"""

from __future__ import annotations

import shutil
from abc import ABC, abstractmethod
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.config import ExportSettings
from facesynth.base.errors import InputError, UsageError
from facesynth.base.registry import EXPORT_FORMATS
from facesynth.formats.audio import is_wav, read_audio, write_wav
from facesynth.model.artifacts import (
    atomic_folder,
    atomic_path,
    check_output,
    check_output_folder,
    publish,
    published_together,
    temporary_path,
)

from .animation import Exportable, use_mesh


@dataclass(frozen=True)
class ExportOptions:
    """How one export is written: ``head_motion`` puts the head's motion in; ``name`` names the
    scene (default the output's stem); ``audio``: the speech to put beside the output as a WAV (an
    audio file: a WAV is copied, any other sound file or video decoded and written as 16-bit WAV;
    or (samples, rate) to write), for formats that name an audio file (glTF)."""

    head_motion: bool = False
    name: str | None = None
    audio: Path | tuple[np.ndarray, int] | None = None


class ExportFormat(ABC):
    """One export format. ``carries``: what it writes of an animation, among ``"weights"`` (rig
    blendshape weights), ``"mesh"`` and ``"markers"``; ``folder``: the output is a folder of files;
    ``takes_audio``: it can name the speech beside it; ``named_file``: its writer picks the
    encoding by the file's own name (USD), so it writes under the output's name in a temporary
    folder."""

    name: str
    carries: str
    folder: bool = False
    folder_what: str = "the output folder"
    takes_audio: bool = False
    named_file: bool = False

    def require(self) -> None:  # noqa: B027 (most formats need nothing optional)
        """Refuse, saying what to install, when an optional dependency is missing."""

    def rate(self, anim: Exportable, settings: ExportSettings) -> float:
        """The frame rate (frames/s) it is written at when none is asked: the animation's own."""
        return anim.fps

    def check(self, anim: Exportable, head_motion: bool) -> None:
        """Refuse, with what to run first, an animation this format cannot carry."""
        p, fmt = anim.path, self.name
        if self.carries == "weights" and anim.weights is None:
            what = "marker motion" if anim.kind == "motion" else "a mesh animation"
            todo = ("run `facesynth solve` on the motion first and export its curves" if anim.kind == "motion" else
                    "run `facesynth solve` on the motion it was deformed from and export those curves "
                    "(a morph target per frame is no rig)")
            extra = "" if not self.takes_audio else f"; or export {what} as usd or obj-seq"
            raise InputError(f"{p}: {fmt} carries rig blendshape weights, and {what} has none; {todo}{extra}.")
        if self.carries == "mesh" and not anim.has_mesh:
            raise InputError(f"{p}: {fmt} carries a mesh, and marker motion has none; run `facesynth deform` (or "
                             "`facesynth solve`) first, or export the markers as c3d.")
        if self.carries == "markers" and anim.markers is None:
            raise InputError(f"{p}: {fmt} carries markers, and rig curves have none; export the motion the curves "
                             "were solved from.")
        if head_motion and anim.head_rotation is None:
            why = ("a mesh animation holds head motion only inside its vertices (deform.apply_head_motion)"
                   if anim.kind == "meshanim" else "it has no head motion")
            raise InputError(f"{p}: --head-motion asks for head motion, but {why}; export without --head-motion.")

    @abstractmethod
    def write(self, anim: Exportable, path: Path, options: ExportOptions, audio_name: str | None) -> list[Path]:
        """Write ``anim`` at ``path`` (a temporary file or folder the caller publishes); returns
        the files written (for a folder: inside it). ``audio_name``: the file name of the speech
        beside the output, or None."""


def audio_path(output: Path) -> Path:
    """Where the speech beside an output goes: the output's name with ``.wav``."""
    return Path(output).with_suffix(".wav")


def write_export(fmt: ExportFormat, anim: Exportable, output: Path, options: ExportOptions,
                 overwrite: bool = False) -> list[Path]:
    """Write ``anim`` (at its own rate: resample it first) as ``fmt`` at ``output``, published
    whole with the speech beside it where the options give one; returns every file written, the
    output first (an OBJ sequence: the files inside its folder, at their published place)."""
    fmt.check(anim, options.head_motion)
    if options.audio is not None and fmt.takes_audio:
        wav = audio_path(output)
        with published_together():  # the scene and its audio, or neither
            with atomic_path(wav, overwrite) as tmp:
                if isinstance(options.audio, tuple):
                    write_wav(tmp, *options.audio)
                elif is_wav(options.audio):
                    shutil.copyfile(options.audio, tmp)
                else:  # M4A, MP3, Opus, a video's sound, FLAC ...: decoded, written as 16-bit WAV
                    write_wav(tmp, *read_audio(options.audio))
            _write_one(fmt, anim, output, options, overwrite, wav.name)
        return [output, wav]
    return _write_one(fmt, anim, output, options, overwrite, None)


def _write_one(fmt: ExportFormat, anim: Exportable, output: Path, options: ExportOptions, overwrite: bool,
               audio_name: str | None) -> list[Path]:
    if fmt.folder:
        with atomic_folder(output, fmt.folder_what, overwrite) as tmp:
            written = fmt.write(anim, tmp, options, audio_name)
        return [Path(output) / f.name for f in written]
    if fmt.named_file:
        folder = temporary_path(Path(output))
        if folder.exists():
            shutil.rmtree(folder)
        folder.mkdir()
        try:
            fmt.write(anim, folder / Path(output).name, options, audio_name)
            publish(folder / Path(output).name, Path(output), overwrite)
        finally:
            shutil.rmtree(folder, ignore_errors=True)
        return [Path(output)]
    with atomic_path(output, overwrite) as tmp:
        fmt.write(anim, tmp, options, audio_name)
    return [Path(output)]


def chosen_format(fmt: str, output: Path, audio: Path | None = None, overwrite: bool = False) -> ExportFormat:
    """The registered export format ``fmt``, after the checks made before any work: its optional
    dependency installed, ``audio`` only for a format that names one (and an audio file that reads), the
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
    return form


def speech_beside(audio: Path | None) -> Path | tuple[np.ndarray, int] | None:
    """The speech :func:`export` writes beside its output, read once before anything is written
    (audio that cannot be read is refused here): a WAV's path (copied as it is), any other sound
    file or video decoded (samples, rate), None without audio."""
    if audio is None:
        return None
    decoded = read_audio(audio)
    return Path(audio) if is_wav(Path(audio)) else decoded


def export(form: ExportFormat, anim: Exportable, output: Path, settings: ExportSettings, *, fps: float | None = None,
          head_motion: bool = False, audio: Path | tuple[np.ndarray, int] | None = None, mesh: Path | None = None,
          overwrite: bool = False) -> tuple[Exportable, list[Path]]:
    """What ``facesynth export`` and :func:`facesynth.export` write: ``anim`` (with the faces of
    ``mesh`` when given) written as ``form`` at ``output``, at ``fps`` or the format's rate
    (:meth:`ExportFormat.rate`). Returns the animation as written (resampled) and every file
    written: the output first, then a glTF's audio beside it, or an OBJ sequence's files."""
    if mesh is not None:
        anim = use_mesh(anim, mesh)
    form.check(anim, head_motion)
    rate = fps if fps is not None else form.rate(anim, settings)
    if not (np.isfinite(rate) and 0 < rate <= 1000):
        raise UsageError(f"--fps {rate:g} is not a frame rate; give a number of frames per second in (0, 1000].")
    anim = anim.resampled(rate)
    files = write_export(form, anim, output, ExportOptions(head_motion, Path(output).stem, audio), overwrite)
    return anim, files
