"""facesynth's public Python API, importable from the top of the package (``import facesynth``):
read a database or a fitted model, make an utterance, synthesize it with any member of the
method family, solve it onto a rig and export it (``docs/api.md`` says what is public and how
versions change it).

A thin facade over the domain: each function calls the very steps its command runs
(:func:`facesynth.domain.methods.steps.synthesize_utterance`,
:mod:`facesynth.domain.retarget.facial_solve`, :func:`facesynth.domain.exports.format.export`),
so an output written here holds the same bytes as the command's for the same inputs and
settings. The API sits below the stages and imports none of them. Each function returns the
model objects the stages use (:class:`Motion`, :class:`RigCurves`, ...), and writes its artifact
too when given ``output``.

Settings come from a :class:`Config` (:func:`load_config`: the packaged defaults, a TOML file
and ``section.key=value`` overrides, as the command line's ``--config`` and ``--set``); without
one, the packaged defaults. The config's ``[limits]`` are in force during each call.

An artifact written here records as its inputs (its ``inputs`` attribute, with their sha256)
the files the call was given by path, the database's own file (a :class:`MotionDatabase` keeps
it), and the files an :class:`Utterance` was read from; an object made in memory has no file to
record.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any, TypeAlias

import numpy as np

from facesynth import __version__
from facesynth.base import limits
from facesynth.base.config import Config
from facesynth.base.errors import (
    ArtifactError,
    ConfigError,
    FacesynthError,
    InputError,
    OutputExistsError,
    SearchError,
    UsageError,
)
from facesynth.base.registry import EXPORT_FORMATS, METHODS
from facesynth.domain import methods as family
from facesynth.domain.exports import format as exporting
from facesynth.domain.exports.animation import load, of_artifact
from facesynth.domain.methods import Method, MethodSettings, steps
from facesynth.domain.retarget import facial_solve
from facesynth.domain.rig.face import Rig
from facesynth.domain.rig.loading import load_rig
from facesynth.domain.search.constraints import given_constraints, read_constraints
from facesynth.domain.speech.alignment import Alignment
from facesynth.domain.speech.utterance import phones_utterance
from facesynth.model.artifacts import artifact_kind, check_output, input_record
from facesynth.model.coarticulation import CoarticulationModel
from facesynth.model.curves import RigCurves
from facesynth.model.head_motion import HeadMotion
from facesynth.model.meshanim import MeshAnimation
from facesynth.model.motion import Motion
from facesynth.model.motiondb import MotionDatabase
from facesynth.model.trajectory import TrajectoryModel

__all__ = [
    "__version__",
    # settings
    "Config", "load_config",
    # reading artifacts
    "read_database", "read_model", "read_motion", "read_curves", "read_rig",
    # utterances
    "Utterance", "utterance_from_phones", "utterance_from_audio",
    # the pipeline
    "methods", "synthesize", "solve", "export_formats", "export",
    # the model objects returned
    "MotionDatabase", "TrajectoryModel", "CoarticulationModel", "Motion", "RigCurves", "MeshAnimation", "Rig",
    "HeadMotion", "Alignment",
    # errors
    "FacesynthError", "InputError", "UsageError", "ArtifactError", "ConfigError", "SearchError",
    "OutputExistsError",
]

#: A file name: a string or a path.
StrPath = str | os.PathLike
#: A fitted model of a member of the method family (``facesynth fit-method``).
FittedModel: TypeAlias = TrajectoryModel | CoarticulationModel


def load_config(path: StrPath | None = None, overrides: Sequence[str] = ()) -> Config:
    """The settings: the packaged defaults, then the TOML file at ``path``, then each
    ``section.key=value`` of ``overrides`` (as ``--config`` and ``--set``). Every value is
    checked now: a bad one is a :class:`ConfigError` naming it."""
    return Config.load(None if path is None else Path(path), tuple(overrides))


# --- reading artifacts ----------------------------------------------------------------------

def read_database(path: StrPath) -> MotionDatabase:
    """The motion database at ``path`` (``facesynth build-db``'s ``db.h5``). It keeps its file
    open, so what is read later (the transition features) comes from the file validated now."""
    return MotionDatabase.read(Path(path))


def read_model(path: StrPath) -> FittedModel:
    """The fitted model at ``path`` (``facesynth fit-method``): a :class:`TrajectoryModel` or a
    :class:`CoarticulationModel`, by the artifact's kind."""
    return _fitted_member(Path(path)).read(Path(path))


def read_motion(path: StrPath) -> Motion:
    """The ``motion`` artifact at ``path`` (``synthesize``, ``capture``, ``expression restyle``),
    with its search path and per-frame provenance."""
    return Motion.read(Path(path), search=True)


def read_curves(path: StrPath) -> RigCurves:
    """The rig curves at ``path`` (``solve``, ``retarget``, ``openfacefx``)."""
    return RigCurves.read(Path(path))


def read_rig(path: StrPath | None = None, binding: StrPath | None = None) -> Rig:
    """A face rig: the built-in one (``path`` None or ``"builtin"``), or a user's, a folder of
    OBJ files (``neutral.obj`` and one per shape) or a glTF/GLB file with morph targets.
    ``binding``: a CSV of ``marker,vertex`` placing the motion's markers on it (a user's rig
    needs one to be solved onto; the built-in rig has its own)."""
    return load_rig(None if path is None else Path(path), None if binding is None else Path(binding),
                    need_binding=False)


# --- utterances -----------------------------------------------------------------------------

@dataclass(frozen=True)
class Utterance:
    """An utterance to synthesize: its phones with times and an emotion per phone, and the files
    it was read from (recorded by the artifacts made of it).

    data: the shared core's :class:`~facesynth.domain.methods.steps.UtteranceInput` (the phone
        sequence, the alignment when it came from audio, warnings, the audio samples).
    phones_file, emotions_file, audio_file: the files given, or None.
    """

    data: steps.UtteranceInput
    phones_file: Path | None = None
    emotions_file: Path | None = None
    audio_file: Path | None = None

    @property
    def phones(self) -> list[str]:
        """The phones, in the Festival set (adjacent pauses merged into one ``pau``)."""
        return list(self.data.utterance.phones)

    @property
    def starts(self) -> np.ndarray:
        """(n,) float64, each phone's start, seconds."""
        return self.data.utterance.starts

    @property
    def ends(self) -> np.ndarray:
        """(n,) float64, each phone's end, seconds."""
        return self.data.utterance.ends

    @property
    def emotions(self) -> list[str]:
        """Each phone's emotion."""
        return list(self.data.utterance.emotions)

    @property
    def alignment(self) -> Alignment | None:
        """The alignment of the audio (its words, phones and how they were found: ``recognized``
        holds the words heard when no text was given); None for phones given."""
        return self.data.alignment

    @property
    def warnings(self) -> list[str]:
        """Sentences for the user (e.g. a transcript that does not match the speech)."""
        return list(self.data.warnings)

    @property
    def duration_s(self) -> float:
        """The end of the last phone, seconds."""
        return float(self.data.utterance.ends[-1])

    def __len__(self) -> int:
        return len(self.data.utterance)

    @property
    def where(self) -> str:
        """How messages name it: its phone or audio file."""
        return str(self.phones_file or self.audio_file or "the phones given")


def utterance_from_phones(phones: StrPath | Sequence[tuple[str, float, float]], *,
                          emotions: StrPath | Sequence[tuple[float, float, str]] | None = None,
                          audio: StrPath | None = None, config: Config | None = None) -> Utterance:
    """An utterance from its phone timing: a TextGrid or ``.lab`` file (as ``synthesize
    --phonemes``), or (phone, start_s, end_s) triples in time order (Festival or CMU/ARPAbet
    names). ``emotions``: a spans file (``start_s end_s emotion`` lines, or a TextGrid tier
    ``emotions``) or (start_s, end_s, emotion) triples; a phone takes the span holding its middle,
    neutral outside every span. ``audio``: the speech these phones time (any sound file or video with sound): the mouth then
    opens with its loudness too (``synthesize.loudness_weight``)."""
    cfg = _config(config)
    with _limits(cfg):
        if isinstance(phones, (str, os.PathLike)):
            phones_file, made = Path(phones), None
        else:
            phones_file, made = None, phones_utterance(phones)
        data = steps.read_utterance(cfg.settings("ingest"), phones_path=phones_file, phones=made, audio=_path(audio),
                                   align=cfg.settings("align"), **_emotions(emotions))
    return Utterance(data, phones_file, _file(emotions), _path(audio))


def utterance_from_audio(audio: StrPath, text: str | None = None, *,
                         emotions: StrPath | Sequence[tuple[float, float, str]] | None = None,
                         language: str | None = None, config: Config | None = None) -> Utterance:
    """An utterance from speech (any sound file or video with sound ffmpeg reads: WAV, M4A, MP3,
    Opus, MP4, ...): aligned to ``text``, what it says, or without text recognised from the audio,
    as ``synthesize --audio [--text] [--language]``. ``language``: a BCP-47 tag (``de``, ``fr``,
    ``cmn``...; None: ``align.language``, English by default); without a text, audio in another
    language is decoded as phones, not English words. A transcript that
    does not match the speech is a warning (:attr:`Utterance.warnings`), not an error.
    ``emotions`` as for :func:`utterance_from_phones`."""
    cfg = _config(config)
    align = cfg.settings("align")
    if language is not None:
        align = replace(align, language=language)
    with _limits(cfg):
        data = steps.read_utterance(cfg.settings("ingest"), audio=Path(audio), text=text, align=align,
                                   **_emotions(emotions))
    return Utterance(data, None, _file(emotions), Path(audio))


# --- the pipeline ---------------------------------------------------------------------------

def methods() -> tuple[str, ...]:
    """The members of the method family, by name (the registry :data:`facesynth.base.registry.METHODS`)."""
    return METHODS.names()


def export_formats() -> tuple[str, ...]:
    """The export formats, by name (the registry :data:`facesynth.base.registry.EXPORT_FORMATS`)."""
    return EXPORT_FORMATS.names()


def synthesize(source: StrPath | MotionDatabase | FittedModel, utterance: Utterance, *, method: str | None = None,
               constraints: StrPath | Mapping[int, int] | None = None,
               head_motion: StrPath | HeadMotion | None = None, config: Config | None = None,
               output: StrPath | None = None, overwrite: bool = False) -> Motion:
    """The motion of ``utterance`` made by ``method`` from ``source``, as ``facesynth synthesize``.

    source: the motion database (or its file) for ``dp``, ``greedy`` and ``mean``; a fitted model
        (or its file) for ``trajectory`` and ``coarticulation``.
    method: a member of the family (:func:`methods`); default: ``synthesize.method`` (``dp``) for
        a database, the model's own member for a fitted model.
    constraints: motion nodes the DP must use: a file (``INDEX NODE`` or ``TIMEs NODE`` lines) or
        {phone index: node id} (``dp`` only).
    head_motion: a ``headmotion`` artifact (``facesynth head-motion``) or its file, put on the
        output instead of the source takes' head motion.
    output: where to write the ``motion`` artifact too (never replaced unless ``overwrite``).

    Returns the :class:`Motion`: markers (T, M, 3) float32 mm at ``fps``, its head motion, the
    search path (``path``: nodes, cost terms, ``total_cost``) and per-frame provenance."""
    cfg = _config(config)
    settings = MethodSettings.of(cfg)
    source_path = _file(source)
    member = family.get(method or _default_method(source, source_path, settings))
    if constraints is not None:
        member.refuse_constraints({0: 0})
    if output is not None:
        check_output(Path(output), overwrite)
    with _limits(cfg):
        src: Any
        if source_path is not None:
            src, source_where, source_file = member.read(source_path), str(source_path), source_path
        else:
            src = source
            _check_source(member, src)
            source_file = getattr(src, "path", None)
            source_where = str(source_file or f"the {_KIND_WHAT.get(src.KIND, src.KIND)} given")
        head_path = _file(head_motion)
        head = HeadMotion.read(head_path) if head_path is not None else head_motion
        assert head is None or isinstance(head, HeadMotion)
        constraints_path = _file(constraints)
        chosen: dict[int, int] = {}
        if constraints_path is not None:
            chosen = read_constraints(constraints_path, utterance.data.utterance, src.nodes.phone)
        elif constraints is not None:
            assert isinstance(constraints, Mapping)
            chosen = given_constraints(constraints, utterance.data.utterance, src.nodes.phone)
        made = steps.synthesize_utterance(member, src, utterance.data, settings, chosen, head=head,
                                         source_where=source_where, where=utterance.where)
        if output is not None:
            recorded = steps.motion_inputs(source_file, utterance.phones_file, utterance.emotions_file,
                                          constraints_path, utterance.audio_file, head_path,
                                          settings.synthesize.articulation_model)
            steps.write_motion(made, Path(output), [input_record(p) for p in recorded], overwrite=overwrite)
    return made.motion


def solve(motion: StrPath | Motion, *, rig: StrPath | Rig | None = None, binding: StrPath | None = None,
          take: str | None = None, config: Config | None = None, output: StrPath | None = None,
          overwrite: bool = False) -> RigCurves:
    """The rig curves of ``motion`` by a direct facial solve, as ``facesynth solve``: per frame
    the rig's blendshape weights in [0, 1] that best explain its markers.

    motion: a :class:`Motion`, or the file of a ``motion`` artifact, or of a ``normalized``
        capture (then ``take`` picks its take; the only one by default).
    rig: the built-in rig (None or ``"builtin"``), a user's rig (a folder of OBJ files or a
        glTF/GLB file, with ``binding``) or a :class:`Rig` (:func:`read_rig`).
    output: where to write the ``curves`` artifact too.

    Returns the :class:`RigCurves`: weights (T, E) float32 at the motion's rate, the head motion,
    the per-frame fit residual and where each frame came from."""
    cfg = _config(config)
    settings = cfg.settings("solve")
    if output is not None:
        check_output(Path(output), overwrite)
    with _limits(cfg):
        rig_path = _file(rig)
        target = rig if isinstance(rig, Rig) else load_rig(rig_path, _path(binding))
        motion_path = _file(motion)
        exact = False
        if motion_path is not None:
            moving = facial_solve.read_motion(motion_path, settings, take)
            settings, exact = facial_solve.settings_for(motion_path, settings)  # a posed capture: the exact solve
        elif take is not None:
            raise UsageError("take picks a take of a normalized capture's file; a Motion is one take already.")
        else:
            assert isinstance(motion, Motion)
            moving = motion
        solved = facial_solve.solve(moving, target, settings, str(motion_path or "the motion given"), exact=exact)
        if output is not None:
            facial_solve.write(solved, Path(output), settings, facial_solve.recorded_inputs(motion_path, rig_path),
                               overwrite=overwrite)
    return solved.curves


def export(animation: StrPath | Motion | MeshAnimation | RigCurves, format: str, output: StrPath, *,
           fps: float | None = None, head_motion: bool = False, audio: StrPath | None = None,
           mesh: StrPath | None = None, config: Config | None = None, overwrite: bool = False) -> list[Path]:
    """Write ``animation`` (a motion, a mesh animation or rig curves on the built-in rig, or its
    file) for another tool as ``format`` (:func:`export_formats`: ``arkit-csv``, ``gltf``,
    ``glb``, ``usd``, ``usda``, ``c3d``, ``obj-seq``, ...) at ``output``, as ``facesynth export``:
    at ``fps`` (default: the format's rate), with the head motion when ``head_motion``, the speech
    ``audio`` beside a glTF as a WAV (a WAV copied, any other file decoded), the faces of ``mesh``. Returns every file written, the output
    first (an OBJ sequence: the files in its folder)."""
    cfg = _config(config)
    out = Path(output)
    with _limits(cfg):
        form = exporting.chosen_format(format, out, _path(audio), overwrite)
        speech = exporting.speech_beside(_path(audio))
        animation_path = _file(animation)
        if animation_path is not None:
            anim = load(animation_path)
        else:
            assert isinstance(animation, (Motion, MeshAnimation, RigCurves))
            anim = of_artifact(animation, Path(f"the {_KIND_WHAT[animation.KIND]} given"))
        _, files = exporting.export(form, anim, out, cfg.settings("export"), fps=fps, head_motion=head_motion,
                                    audio=speech, mesh=_path(mesh), overwrite=overwrite)
    return list(files)


# --- helpers --------------------------------------------------------------------------------

#: How messages name an object given in memory, by its artifact kind.
_KIND_WHAT = {"motiondb": "database", "trajectory": "trajectory model", "coarticulation": "coarticulation model",
              "motion": "motion", "meshanim": "mesh animation", "curves": "curves"}


def _config(config: Config | None) -> Config:
    return config if config is not None else Config.load()


@contextlib.contextmanager
def _limits(config: Config) -> Iterator[None]:
    """The config's ``[limits]`` in force, as the command line puts them around a command."""
    with limits.using(config.settings("limits")):
        yield


def _file(value: object) -> Path | None:
    """``value`` as a path when it names a file (a string or a path), else None (an object)."""
    return Path(value) if isinstance(value, (str, os.PathLike)) else None


def _path(value: StrPath | None) -> Path | None:
    return None if value is None else Path(value)


def _emotions(emotions: StrPath | Sequence[tuple[float, float, str]] | None) -> dict[str, Any]:
    """The emotion arguments of :func:`steps.read_utterance`: a spans file, or the spans themselves."""
    if emotions is None:
        return {}
    if isinstance(emotions, (str, os.PathLike)):
        return {"emotions_path": Path(emotions)}
    return {"spans": list(emotions)}


def _fitted_member(path: Path) -> Method:
    """The member whose fitted model the artifact at ``path`` is."""
    kind = artifact_kind(path)
    for entry in METHODS.entries():
        if entry.facts.get("fitted") and entry.facts.get("source_kind") == kind:
            return family.get(entry.name)
    if kind is None and not path.exists():
        raise InputError(f"{path}: file not found; give a model written by `facesynth fit-method`.")
    found = f"a '{kind}' artifact" if kind else "no facesynth artifact"
    raise InputError(f"{path}: is {found}, not a fitted model; fit one with `facesynth fit-method`.")


def _default_method(source: object, path: Path | None, settings: MethodSettings) -> str:
    """The member that reads ``source`` when none is named: the fitted member of a model,
    ``synthesize.method`` otherwise."""
    kind = artifact_kind(path) if path is not None else getattr(source, "KIND", None)
    for entry in METHODS.entries():
        if entry.facts.get("fitted") and entry.facts.get("source_kind") == kind:
            return entry.name
    return steps.chosen_method(None, settings.synthesize)


def _check_source(member: Method, source: object) -> None:
    """Refuse, in one sentence, a source object the member does not read."""
    kind = getattr(source, "KIND", None)
    if kind != member.source_kind:
        given = f"a {_KIND_WHAT.get(kind, kind)}" if isinstance(kind, str) else f"a {type(source).__name__}"
        reads = ("a motion database" if member.source_kind == "motiondb"
                 else f"a {member.name} model (`facesynth fit-method`)")
        raise UsageError(f"the {member.name} method reads {reads}; {given} was given.")
