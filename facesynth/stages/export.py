"""``facesynth export``: a motion, mesh animation or rig curves -> a file another tool reads.

Formats (units and axes per format in ``docs/exports.md``):

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

import shutil
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.config import ExportSettings
from facesynth.base.errors import InputError, UsageError
from facesynth.domain.exports import files as files_
from facesynth.domain.exports.animation import Exportable, load, use_mesh
from facesynth.domain.exports.files import audio_path, named_temporary
from facesynth.domain.exports.objseq import write_sequence
from facesynth.formats.audio import read_audio
from facesynth.formats.mocap import MarkerTake, write_c3d
from facesynth.model.artifacts import atomic_folder, atomic_path, check_output, check_output_folder, published_together

FORMATS = ("arkit-csv", "gltf", "glb", "usd", "usda", "c3d", "obj-seq")


def check(anim: Exportable, fmt: str, head_motion: bool) -> None:
    """Refuse, with what to run first, a format that cannot carry ``anim``."""
    p = anim.path
    if fmt in ("arkit-csv", "gltf", "glb") and anim.weights is None:
        what = "marker motion" if anim.kind == "motion" else "a mesh animation"
        todo = ("run `facesynth solve` on the motion first and export its curves" if anim.kind == "motion" else
                "run `facesynth solve` on the motion it was deformed from and export those curves "
                "(a morph target per frame is no rig)")
        extra = "" if fmt == "arkit-csv" else f"; or export {what} as usd or obj-seq"
        raise InputError(f"{p}: {fmt} carries rig blendshape weights, and {what} has none; {todo}{extra}.")
    if fmt in ("usd", "usda", "obj-seq") and not anim.has_mesh:
        raise InputError(f"{p}: {fmt} carries a mesh, and marker motion has none; run `facesynth deform` (or "
                         "`facesynth solve`) first, or export the markers as c3d.")
    if fmt == "c3d" and anim.markers is None:
        raise InputError(f"{p}: c3d carries markers, and rig curves have none; export the motion the curves were "
                         "solved from.")
    if head_motion and anim.head_rotation is None:
        why = ("a mesh animation holds head motion only inside its vertices (deform.apply_head_motion)"
               if anim.kind == "meshanim" else "it has no head motion")
        raise InputError(f"{p}: --head-motion asks for head motion, but {why}; export without --head-motion.")


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
    """Export ``artifact`` as ``fmt`` to ``output``."""
    if fmt not in FORMATS:
        raise UsageError(f"unknown format {fmt!r}; choose one of {', '.join(FORMATS)}.")
    if fmt in ("usd", "usda"):
        files_.require_usd(fmt)
    if audio is not None and fmt not in ("gltf", "glb"):
        raise UsageError("--audio goes with gltf and glb (the other formats carry no audio reference).")
    if fmt == "obj-seq":

        check_output_folder(output, "the OBJ sequence", overwrite)
    else:
        check_output(output, overwrite)
    if audio is not None:
        check_output(audio_path(output), overwrite)

        read_audio(audio)  # a WAV that cannot be read is refused before anything is written
    anim = load(artifact)
    if mesh is not None:
        anim = use_mesh(anim, mesh)
    check(anim, fmt, head_motion)
    rate = fps if fps is not None else (settings.arkit_fps if fmt == "arkit-csv" else anim.fps)
    if not (np.isfinite(rate) and 0 < rate <= 1000):
        raise UsageError(f"--fps {rate:g} is not a frame rate; give a number of frames per second in (0, 1000].")
    anim = anim.resampled(rate)
    files = [output]
    if fmt == "arkit-csv":
        with atomic_path(output, overwrite) as tmp:
            files_.write_arkit_csv(anim, tmp, head_motion)
    elif fmt in ("gltf", "glb"):
        wav = audio_path(output) if audio is not None else None
        with published_together():  # the scene and its audio, or neither
            if wav is not None:
                with atomic_path(wav, overwrite) as tmp:
                    shutil.copyfile(audio, tmp)
                files.append(wav)
            with atomic_path(output, overwrite) as tmp:
                files_.write_gltf(anim, tmp, wav.name if wav is not None else None, head_motion, binary=fmt == "glb",
                                  name=Path(output).stem)
    elif fmt in ("usd", "usda"):
        with named_temporary(output, overwrite) as tmp:
            files_.write_usd(anim, tmp, head_motion)
    elif fmt == "c3d":

        markers = anim.with_head(anim.markers) if head_motion else anim.markers
        with atomic_path(output, overwrite) as tmp:
            write_c3d(tmp, MarkerTake(np.asarray(markers, np.float32), list(anim.marker_names), anim.fps))
    else:

        with atomic_folder(output, "the OBJ sequence", overwrite) as tmp:
            files = write_sequence(tmp, anim, head_motion)
            files = [output / f.name for f in files]
    return ExportResult(anim.n_frames, anim.fps, anim.duration_s, files, anim.kind)

