"""One line of a batch, done in a Dask worker process: the utterance read (its alignment, or its
audio aligned to its text, or recognised when there is none) and synthesized by the job's
method through the shared core (:mod:`facesynth.domain.methods.steps`: the same transcript-mismatch
policy, emotion names, memory check and method code as ``facesynth synthesize``), under the
job's ``[limits]``; then the asked outputs and a manifest.

State kept per worker process (never shipped with a task): the method's source (the motion
database, or its fitted model) and what the method prepares from it (the searches' transition
costs), read once per file (:func:`database`), the mesh bound to the
markers (:func:`bound_mesh`) and, through :mod:`facesynth.base.opencl`, the OpenCL context. The
caches are keyed by the file's path, size and modification time (and the settings), so a
database rebuilt between two batches on a long-lived cluster is read again.

Outputs of line ``ID`` in the batch folder, as asked: ``ID.motion.h5``; ``ID.curves.h5`` (the rig
curves of the facial solve of the motion, on the built-in rig or the job's rig, as ``facesynth
solve`` makes them), ``ID.arkit.csv`` (their Live Link Face CSV), ``ID.gltf`` with ``ID.wav``
(the rig with its morph targets, the weights animation and the line's audio), ``ID.usd`` (UsdSkel
blendshapes) and ``ID.avi`` (the rig posed by the curves, rendered with the line's audio), all
made from the one solve; ``ID.anim.h5`` (the Gaussian deformation of the job's plain mesh);
``ID.TextGrid`` (the alignment, when the line was aligned) and ``ID.json``, the manifest written
last: the sha256 of every input, the settings, the outputs asked, and every file written with its
sha256. A rerun skips a line whose manifest matches its inputs and whose files are all there
unchanged. Every file is written to a temporary name in the folder and renamed into place, so a
killed worker leaves no half-written output, and no manifest for a line it did not finish.
"""

from __future__ import annotations

import hashlib
import json
import os
import time
from dataclasses import dataclass, field, replace
from pathlib import Path

from facesynth import __version__
from facesynth.base.config import (
    AlignSettings,
    DeformSettings,
    ExportSettings,
    IngestSettings,
    LimitsSettings,
    RenderSettings,
    SolveSettings,
    settings_json,
)
from facesynth.base.errors import FacesynthError, InputError
from facesynth.base.limits import using
from facesynth.base.phonemes import PAU
from facesynth.base.registry import EXPORT_FORMATS
from facesynth.domain import methods
from facesynth.domain.exports.animation import from_curves
from facesynth.domain.exports.format import ExportOptions, write_export
from facesynth.domain.methods import MethodSettings, steps
from facesynth.domain.rendering.video import render_video
from facesynth.domain.retarget.deform import animate, bind
from facesynth.domain.retarget.solve import solve_motion, solved_curves
from facesynth.domain.rig.loading import arkit_to_rig, load_rig
from facesynth.formats.audio import is_wav, read_audio
from facesynth.formats.labels import write_textgrid
from facesynth.formats.mesh import read_binding, read_mesh
from facesynth.model.artifacts import atomic_path, sha256_of
from facesynth.model.meshanim import MeshAnimation
from facesynth.model.motion import Motion

from .script import Line

#: The outputs that are no export format, and the file each writes, by line id; an export format
#: (:data:`facesynth.base.registry.EXPORT_FORMATS`, those registered with ``batch``) writes
#: ``ID`` + its ``suffix`` (``gltf`` also ``ID.wav`` beside it).
OWN_SUFFIXES = {"motion": ".motion.h5", "curves": ".curves.h5", "avi": ".avi", "anim": ".anim.h5"}
#: Earlier names of outputs, kept for a while with a warning.
DEPRECATED_OUTPUTS = {"arkit": "arkit-csv"}


def line_align(align: AlignSettings, line: Line) -> AlignSettings:
    """The ``[align]`` settings of ``line``: its ``language`` cell in force when it has one."""
    return replace(align, language=line.language) if line.language else align


def suffix(output: str) -> str:
    """The file name ending of an output, after the line's id."""
    return OWN_SUFFIXES[output] if output in OWN_SUFFIXES else EXPORT_FORMATS.entry(output).facts["suffix"]


def rig_output(output: str) -> bool:
    """Whether an output is made from the rig curves of the facial solve (the curves themselves,
    the video and every export format)."""
    return output in ("curves", "avi") or output in EXPORT_FORMATS


def output_names(asked) -> tuple[tuple[str, ...], list[str]]:
    """The outputs asked, with deprecated names replaced, and a warning for each."""
    names, warnings = [], []
    for name in asked:
        if name in DEPRECATED_OUTPUTS:
            warnings.append(f"the batch output {name!r} is now called {DEPRECATED_OUTPUTS[name]!r}; the old name "
                            "will go in a later release.")
            name = DEPRECATED_OUTPUTS[name]
        if name not in names:
            names.append(name)
    return tuple(names), warnings


@dataclass(frozen=True)
class Job:
    """What every line of one batch shares: inputs by path, settings, and what to write.

    ``method``: the member of the method family every line is synthesized by, ``db`` its source
    (the motion database, or the method's fitted model), ``db_sha256`` that file's sha256,
    computed once by the client; ``settings`` the methods' settings; ``limits`` the command's
    ``[limits]``, put in force in the worker for each line; ``mesh`` and ``binding`` are needed
    for the ``anim`` output; ``redo`` (``--overwrite``) redoes lines whose manifest matches.
    The rig outputs (:func:`rig_output`) solve on ``rig`` (None: the built-in rig) with
    ``rig_binding`` (the markers placed on a user's rig), whose data ``rig_sha256`` identifies,
    under ``solve``; ``export`` gives the ARKit CSV's rate.
    """

    db: Path
    db_sha256: str
    out_dir: Path
    outputs: tuple[str, ...]
    settings: MethodSettings
    ingest: IngestSettings
    align: AlignSettings
    deform: DeformSettings
    render: RenderSettings
    limits: LimitsSettings
    method: str = "dp"
    mesh: Path | None = None
    binding: Path | None = None
    redo: bool = False
    solve: SolveSettings | None = None
    export: ExportSettings | None = None
    rig: Path | None = None
    rig_binding: Path | None = None
    rig_sha256: str = ""


@dataclass
class LineResult:
    """The outcome of one line, one row of the summary. ``status``: ``ok``, ``skipped`` (up to
    date from an earlier run) or ``failed`` (``reason`` says why); ``recognized``: the words (or
    phones) recognised for a line without text. Times in seconds: wall time
    of each phase, ``total_s`` of the whole line, ``cpu_s`` the CPU time of the worker process
    for the line (all its threads), ``load_s`` reading the database (once per worker)."""

    id: str
    row: int
    status: str
    reason: str = ""
    method: str = ""
    phones: int = 0
    audio_s: float = 0.0
    align_s: float = 0.0
    synthesize_s: float = 0.0
    outputs_s: float = 0.0
    total_s: float = 0.0
    cpu_s: float = 0.0
    load_s: float = 0.0
    outputs: list[str] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    worker: str = ""
    recognized: str = ""


_CACHE: dict = {}


def _file_key(path: Path) -> tuple:
    st = os.stat(path)
    return (str(Path(path).resolve()), st.st_size, st.st_mtime_ns)


def database(path: Path, method: str, settings: MethodSettings):
    """(the method's source read from ``path``, what the method prepares from it for ``settings``),
    read once per worker process, method and file version; returns the seconds spent loading (0
    when cached) as a third item."""
    member = methods.get(method)
    key = ("db", method, _file_key(path), settings_json(member.recorded_settings(settings)))
    if key not in _CACHE:
        started = time.perf_counter()
        for old in [k for k in _CACHE if k[0] == "db"]:  # one source per worker at a time
            del _CACHE[old]
        source = member.read(path)
        prepared = member.prepare(source, settings)
        _CACHE[key] = (source, prepared, time.perf_counter() - started)
        return _CACHE[key]
    source, prepared, _ = _CACHE[key]
    return source, prepared, 0.0


def bound_mesh(mesh: Path, binding: Path, marker_names: list[str], settings: DeformSettings):
    """The mesh bound to the markers (Eq. 14 weights), computed once per worker process."""
    key = ("mesh", _file_key(mesh), _file_key(binding), tuple(marker_names), settings_json(settings))
    if key not in _CACHE:
        vertices, faces = read_mesh(mesh)
        _CACHE[key] = bind(vertices, faces, read_binding(binding), marker_names, settings, str(mesh), str(binding))
    return _CACHE[key]


def rig_of(job: Job):
    """The job's rig (built-in, or the user's with its binding), read once per worker process.
    For the arkit-csv output a user's rig gets the ARKit map by shape name, as ``openfacefx`` drives
    it (:func:`facesynth.domain.rig.loading.arkit_to_rig`)."""
    import dataclasses

    files = tuple(_file_key(p) for p in (job.rig, job.rig_binding) if p is not None and p.is_file())
    key = ("rig", str(job.rig), files, "arkit-csv" in job.outputs)
    if key not in _CACHE:
        rig = load_rig(job.rig, job.rig_binding)
        if "arkit-csv" in job.outputs and rig.arkit_to_rig is None:
            names, matrix = arkit_to_rig(rig, str(job.rig))
            rig = dataclasses.replace(rig, arkit_names=names, arkit_to_rig=matrix)
        _CACHE[key] = rig
    return _CACHE[key]


def _text_sha(text: str | None) -> str:
    return hashlib.sha256((text or "").encode("utf-8")).hexdigest()


def input_key(line: Line, job: Job) -> dict:
    """Everything a line's outputs depend on: the sha256 of each input file, the text, the
    emotion, the settings, the outputs asked and the facesynth version."""
    files = {"audio": line.audio, "alignment": line.alignment, "emotions": line.emotions,
             "constraints": line.constraints}
    if "anim" in job.outputs:
        files.update(mesh=job.mesh, binding=job.binding)
    rig_outputs = any(rig_output(o) for o in job.outputs)
    if rig_outputs:
        files.update(rig_binding=job.rig_binding)
    if job.settings.synthesize.articulation_model:  # a performer's own voice model, by its content
        files.update(articulation_model=Path(job.settings.synthesize.articulation_model))
    key: dict[str, object] = {name: sha256_of(p) for name, p in files.items() if p is not None}
    key.update(db=job.db_sha256, text=_text_sha(line.text) if line.alignment is None else "", emotion=line.emotion or "",
               outputs=sorted(job.outputs), version=__version__, method=job.method,
               settings={"synthesize": settings_json(job.settings.synthesize), "ingest": settings_json(job.ingest),
                         "method": settings_json(methods.get(job.method).recorded_settings(job.settings)),
                         "align": settings_json(line_align(job.align, line)) if line.alignment is None else "",
                         "deform": settings_json(job.deform) if "anim" in job.outputs else "",
                         "render": settings_json(job.render) if "avi" in job.outputs else "",
                         "solve": settings_json(job.solve) if rig_outputs and job.solve is not None else "",
                         "export": settings_json(job.export) if "arkit-csv" in job.outputs and job.export else ""})
    if rig_outputs:
        key["rig"] = job.rig_sha256
    return key


def manifest_path(job: Job, line_id: str) -> Path:
    return job.out_dir / f"{line_id}.json"


def output_paths(job: Job, line_id: str) -> dict[str, Path]:
    """The file of every output asked, by kind (a glTF's WAV: :func:`extra_paths`)."""
    return {kind: job.out_dir / f"{line_id}{suffix(kind)}" for kind in job.outputs}


def extra_paths(job: Job, line_id: str) -> list[Path]:
    """Files an output writes beside its own: the glTF's audio, ``ID.wav``."""
    return [job.out_dir / f"{line_id}.wav"] if any(o in EXPORT_FORMATS and EXPORT_FORMATS.get(o).takes_audio
                                                    for o in job.outputs) else []


def recorded_outputs(manifest: dict) -> dict[str, str | None]:
    """The files a manifest names, with their sha256 (None in a manifest of an older version,
    which listed names only)."""
    outputs = manifest.get("outputs", {})
    return dict(outputs) if isinstance(outputs, dict) else {name: None for name in outputs}


def _unchanged(job: Job, recorded: dict[str, str | None]) -> bool:
    """Whether every recorded file is there with its recorded sha256."""
    for name, digest in recorded.items():
        path = job.out_dir / name
        if not path.is_file() or (digest is not None and sha256_of(path) != digest):
            return False
    return True


def _write_json(path: Path, data: dict) -> None:
    with atomic_path(path, overwrite=True) as tmp:
        tmp.write_text(json.dumps(data, indent=1, sort_keys=True) + "\n", encoding="utf-8")


def _check_inputs(line: Line, job: Job) -> tuple[str, Path]:
    """The line's emotion name (default neutral) and audio file; raises InputError for a bad row."""
    if line.audio is None:
        raise InputError("no audio file given in the 'audio' column.")
    for name, p in (("audio", line.audio), ("alignment", line.alignment), ("emotions", line.emotions),
                    ("constraints", line.constraints)):
        if p is not None and not p.is_file():
            raise InputError(f"{name} file {p} not found; check the path (relative to the script's folder).")
    if line.emotion and line.emotions:
        raise InputError("both an emotion and an emotions file are given; give one.")
    if line.constraints is not None:
        methods.get(job.method).refuse_constraints({0: 0})
    for name in job.outputs:  # an optional dependency missing is refused before any work
        if name in EXPORT_FORMATS:
            EXPORT_FORMATS.get(name).require()
    return steps.emotion_name(line.emotion or "neutral", job.ingest.emotions, job.ingest.emotion_aliases,
                             "the emotion column"), line.audio


def run_line(line: Line, job: Job) -> LineResult:
    """Do one line under the job's ``[limits]``; never raises for a problem of the line's inputs
    (the result says why it failed). A bug still raises, so the runner records its traceback."""
    with using(job.limits):
        return _run_line(line, job)


def _run_line(line: Line, job: Job) -> LineResult:
    started, cpu = time.perf_counter(), time.process_time()
    result = LineResult(line.id, line.row, "failed", worker=f"pid {os.getpid()}")
    old = key = None
    try:
        if line.problem:
            raise InputError(line.problem)
        old = _read_manifest(manifest_path(job, line.id))
        emotion, audio = _check_inputs(line, job)
        key = input_key(line, job)
        outputs = output_paths(job, line.id)
        if not job.redo and old is not None and old.get("inputs") == key and old.get("status") == "ok" \
                and all(p.exists() for p in outputs.values()) and _unchanged(job, recorded_outputs(old)):
            recorded = old.get("result", {})
            for name in ("method", "phones", "audio_s", "warnings", "recognized"):
                if name in recorded:
                    setattr(result, name, recorded[name])
            result.status = "skipped"
            result.outputs = sorted(p.name for p in list(outputs.values()) + extra_paths(job, line.id))
            result.total_s, result.cpu_s = time.perf_counter() - started, time.process_time() - cpu
            return result
        made_here = set(recorded_outputs(old)) if old is not None else set()
        for p in list(outputs.values()) + extra_paths(job, line.id) + [job.out_dir / f"{line.id}.TextGrid"]:
            if p.exists() and p.name not in made_here and not job.redo:
                raise InputError(f"{p} exists and was not written by this batch; remove it or pass --overwrite.")
        _do_line(line, job, emotion, audio, key, outputs, result)
        result.status = "ok"
    except FacesynthError as exc:
        if not line.problem:  # a line with a duplicated id must not touch the first one's files
            stale = old if old is not None and old.get("inputs") != key else None
            _remove_partial(job, line.id, result.outputs, stale)
        result.status, result.reason, result.outputs = "failed", str(exc), []
    result.total_s, result.cpu_s = time.perf_counter() - started, time.process_time() - cpu
    return result


def _remove_partial(job: Job, line_id: str, written: list[str], stale: dict | None) -> None:
    """After a line failed: remove what this attempt wrote, and the outputs and manifest of an
    earlier run from other inputs (``stale``), so the folder never shows outputs that do not
    belong to the script's line."""
    names = set(written) | (set(recorded_outputs(stale)) | {f"{line_id}.json"} if stale is not None else set())
    for name in names:
        (job.out_dir / name).unlink(missing_ok=True)


def _read_manifest(path: Path) -> dict | None:
    try:
        return json.loads(path.read_text("utf-8"))
    except (OSError, ValueError):
        return None


def _do_line(line: Line, job: Job, emotion: str, audio: Path, key: dict, outputs: dict[str, Path],
             result: LineResult) -> None:
    """The line's outputs; ``emotion`` and ``audio`` (its audio file) as :func:`_check_inputs` found them."""
    t0 = time.perf_counter()
    samples, rate = read_audio(audio)
    result.audio_s = len(samples) / rate
    one_emotion = None if line.emotions is not None else emotion
    if line.alignment is not None:
        read = steps.read_utterance(job.ingest, phones_path=line.alignment, audio=audio,
                                   emotions_path=line.emotions, emotion=one_emotion, samples=(samples, rate))
        result.method = "given"
    else:  # a line without text is recognised (the script reader makes an empty cell None)
        read = steps.read_utterance(job.ingest, audio=audio, text=line.text, align=line_align(job.align, line),
                                   emotions_path=line.emotions, emotion=one_emotion, samples=(samples, rate))
        assert read.alignment is not None  # audio is aligned or recognised
        result.method, result.recognized = read.alignment.method, read.alignment.recognized
    result.warnings = list(read.warnings)
    utt = read.utterance
    result.phones = sum(p != PAU for p in utt.phones)
    result.align_s = time.perf_counter() - t0

    t0 = time.perf_counter()
    member = methods.get(job.method)
    source, prepared, result.load_s = database(job.db, job.method, job.settings)
    constraints = steps.constraints_for(member, source, line.constraints, utt)
    synthesis = steps.synthesize(member, source, utt, job.settings, constraints, prepared=prepared,
                                source_where=str(job.db), where=str(line.alignment or audio),
                                audio=(samples, rate), recognized=read.recognized)
    motion = synthesis.motion
    result.warnings += list(synthesis.summary.warnings)
    result.synthesize_s = time.perf_counter() - t0 - result.load_s

    t0 = time.perf_counter()
    if read.alignment is not None:
        grid = job.out_dir / f"{line.id}.TextGrid"
        with atomic_path(grid, overwrite=True) as tmp:
            segments, words = read.alignment.phones, read.alignment.words
            write_textgrid(tmp, {"phones": segments, "words": words} if words else {"phones": segments}, segments[-1].end)
        result.outputs.append(grid.name)
    records: list[dict[str, str | None]] = [{"path": str(job.db), "kind": member.source_kind, "sha256": job.db_sha256}]
    records += [{"path": str(p), "kind": None, "sha256": key[name]}
                for name, p in (("audio", line.audio), ("alignment", line.alignment), ("emotions", line.emotions),
                                ("constraints", line.constraints)) if p is not None]
    motion_path = outputs.get("motion") or job.out_dir / f"{line.id}.motion.h5.part-{os.getpid()}"
    keep_motion = "motion" in outputs
    motion.write(motion_path, config=steps.recorded_config(member, job.settings, True), records=records,
                 overwrite=True)
    if keep_motion:
        result.outputs.append(motion_path.name)
    try:
        if any(rig_output(o) for o in job.outputs):
            _rig_outputs(line, job, motion_path, outputs, audio, (samples, rate), result)
        if "anim" in job.outputs:
            _mesh_outputs(line, job, motion, motion_path, outputs, result)
    finally:
        if not keep_motion:
            motion_path.unlink(missing_ok=True)
    result.outputs_s = time.perf_counter() - t0
    _write_json(manifest_path(job, line.id), {
        "id": line.id, "status": "ok", "inputs": key,
        "outputs": {name: sha256_of(job.out_dir / name) for name in sorted(result.outputs)},
        "result": {"method": result.method, "phones": result.phones, "audio_s": result.audio_s,
                   "warnings": result.warnings, "recognized": result.recognized}})


def _rig_outputs(line: Line, job: Job, motion_path: Path, outputs: dict[str, Path], audio_path: Path, audio: tuple,
                 result: LineResult) -> None:
    """The facial solve of the line's motion (as written at ``motion_path``, so the curves are
    those ``facesynth solve`` makes of it) on the job's rig, and what is made of its curves: the
    curves themselves, the Live Link Face CSV (at ``export.arkit_fps``), the glTF with the line's
    audio beside it, the USD and the video (``audio_path``: the line's audio file; ``audio``: its
    samples and rate, for a glTF beside an audio file that is no WAV)."""
    assert job.solve is not None and job.export is not None  # prepare() fills them
    rig = rig_of(job)
    motion = Motion.read(motion_path)
    where = str(line.alignment or audio_path)
    weights, residual, _ = solve_motion(motion, rig, job.solve, where)
    curves = solved_curves(motion, rig, weights, residual, motion.frame_provenance(motion_path))
    curves_path = outputs.get("curves") or job.out_dir / f"{line.id}.curves.h5.part-{os.getpid()}"
    inputs = [motion_path] + ([job.rig] if job.rig is not None and job.rig.is_file() else [])
    curves.write(curves_path, config=settings_json(job.solve), inputs=inputs, overwrite=True)
    try:
        if "curves" in outputs:
            result.outputs.append(curves_path.name)
        anim = from_curves(curves, rig, curves_path)
        beside = audio_path if is_wav(audio_path) else audio  # a WAV is copied as it is, any other file written as one
        for name in job.outputs:
            if name in EXPORT_FORMATS:
                fmt = EXPORT_FORMATS.get(name)
                written = write_export(fmt, anim.resampled(fmt.rate(anim, job.export)), outputs[name],
                                       ExportOptions(name=line.id, audio=beside), overwrite=True)
                result.outputs += [f.name for f in written]
        if "avi" in outputs:
            render_video([curves_path], [audio_path], outputs["avi"], job.render, None, overwrite=True,
                         rig_path=job.rig, binding=job.rig_binding)
            result.outputs.append(outputs["avi"].name)
    finally:
        if "curves" not in outputs:
            curves_path.unlink(missing_ok=True)


def _mesh_outputs(line: Line, job: Job, motion, motion_path: Path, outputs: dict[str, Path], result: LineResult) -> None:
    """The mesh animation of the job's plain mesh (Gaussian deformation, Eq. 14-15)."""
    if job.mesh is None or job.binding is None:
        raise InputError("the anim output needs --mesh and --binding.")
    bound = bound_mesh(job.mesh, job.binding, motion.marker_names, job.deform)
    head = motion.head() if job.deform.apply_head_motion else None
    frames, fit = animate(bound, motion.markers, motion.marker_names, motion.reference, head)
    anim = MeshAnimation(frames, motion.fps, bound.rest, bound.faces, motion.markers, motion.marker_names,
                         bound.weights, bound.markers, bound.vertex_of, fit.fit_rms,
                         provenance=motion.frame_provenance(motion_path))
    anim.write(outputs["anim"], config=settings_json(job.deform), inputs=[motion_path, job.mesh, job.binding],
               overwrite=True)
    result.outputs.append(outputs["anim"].name)
