"""The job of ``facesynth batch``: the request checked before any work (the outputs, the rig of the
rig outputs, the method's source, the script's columns, the output folder) and what every line's
task carries (:class:`~facesynth.domain.batch.line.Job`), including the ``[limits]`` in force.
"""

from __future__ import annotations

import logging
from pathlib import Path

from facesynth.base import limits
from facesynth.base.config import (
    AlignSettings,
    BatchSettings,
    Config,
    DeformSettings,
    ExportSettings,
    IngestSettings,
    RenderSettings,
    SolveSettings,
    SynthesizeSettings,
)
from facesynth.base.errors import InputError, UsageError
from facesynth.base.registry import EXPORT_FORMATS
from facesynth.domain import methods
from facesynth.domain.batch.line import Job, output_names, rig_output
from facesynth.domain.batch.script import Line, read_script
from facesynth.domain.methods import MethodSettings, steps
from facesynth.domain.rig.loading import BUILTIN, arkit_to_rig, load_rig
from facesynth.model.artifacts import check_output_folder, open_artifact, sha256_of

log = logging.getLogger(__name__)


def prepare(script: Path, db: Path, out_dir: Path, settings: BatchSettings, synthesize: SynthesizeSettings | MethodSettings,
            ingest: IngestSettings, align: AlignSettings, deform: DeformSettings, render: RenderSettings, *,
            method: str | None = None, mesh: Path | None = None, binding: Path | None = None, overwrite: bool = False,
            solve: SolveSettings | None = None, export: ExportSettings | None = None, rig: Path | None = None,
            rig_binding: Path | None = None) -> tuple[list[Line], Job]:
    """Check the request and read the script; returns (lines, Job). Creates ``out_dir``.
    ``synthesize``: the :class:`MethodSettings`, or ``[synthesize]`` alone (the packaged defaults
    for the rest); ``db``: the method's source (the motion database, or its fitted model);
    ``solve``, ``export``: ``[solve]`` and ``[export]`` (None: the packaged defaults); ``rig``,
    ``rig_binding``: the rig of the curves, avi and export-format outputs (None: the built-in
    rig) and the markers placed on it. The job carries the ``[limits]`` in force
    (:func:`facesynth.base.limits.current`)."""
    if isinstance(synthesize, SynthesizeSettings):
        synthesize = MethodSettings.packaged(synthesize=synthesize)
    member = methods.get(steps.chosen_method(method, synthesize.synthesize))
    outputs, renamed = output_names(settings.outputs)
    for warning in renamed:
        log.warning("warning: %s", warning)
    if "anim" in outputs and (mesh is None or binding is None):
        raise UsageError("the anim output needs --mesh and --binding (e.g. corpus/face.obj and corpus/markers.csv).")
    rig_sha256 = ""
    if rig is not None and str(rig) == BUILTIN:
        rig = None
    if any(rig_output(o) for o in outputs):
        rig_sha256 = _check_rig(rig, rig_binding, outputs)
    elif rig is not None or rig_binding is not None:
        rig_kinds = ["curves", "avi"] + [e.name for e in EXPORT_FORMATS.entries() if e.facts.get("batch")]
        raise UsageError(f"--rig is for the {', '.join(sorted(rig_kinds))} outputs; add one to --outputs.")
    if solve is None or export is None:
        packaged = Config.load()
        solve, export = solve or packaged.settings("solve"), export or packaged.settings("export")
    if "avi" in outputs and abs(render.fps - synthesize.synthesize.output_fps) > 1e-6:
        raise InputError(f"render.fps ({render.fps:g}) differs from synthesize.output_fps ({synthesize.synthesize.output_fps:g}); "
                         "set one to the other for the avi output.")
    lines = read_script(script)
    open_artifact(db, member.source_kind).close()
    check_output_folder(out_dir, "the batch outputs")
    out_dir.mkdir(parents=True, exist_ok=True)
    job = Job(db.resolve(), sha256_of(db), out_dir.resolve(), outputs, synthesize, ingest, align,
              deform, render, limits.current(), member.name, mesh.resolve() if mesh else None,
              binding.resolve() if binding else None, overwrite, solve, export, rig.resolve() if rig else None,
              rig_binding.resolve() if rig_binding else None, rig_sha256)
    return lines, job


def _check_rig(rig: Path | None, rig_binding: Path | None, outputs) -> str:
    """Read the rig of the rig outputs once, before any work (a user's rig without its binding, or
    without the ARKit names an arkit output needs, is refused); returns its sha256."""
    if rig is not None and rig_binding is None:
        raise UsageError(f"{rig}: a user's rig needs --rig-binding, a CSV of marker,vertex placing the motion's "
                         "markers on it.")
    loaded = load_rig(rig, rig_binding)
    if "arkit-csv" in outputs:
        arkit_to_rig(loaded, str(rig))  # a rig none of whose shapes has an ARKit name is refused
    return loaded.sha256
