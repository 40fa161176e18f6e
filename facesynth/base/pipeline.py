"""Every command of facesynth declared once: :data:`STAGES`, in pipeline order.

A :class:`Stage` names a command (its path below ``facesynth``: ``"isomap build"``), the
settings sections it reads, the artifact kinds it reads and writes, its output options (and
which of them name a folder), its core function and the typed result that function returns.
What used to be kept by hand in several places is derived from these declarations:

- :mod:`facesynth.cli`'s ``READS`` (which ``--set`` a command accepts), the order of
  ``facesynth --help`` and the output checks made before any work;
- :data:`facesynth.model.artifacts.PRODUCERS` (the commands named in "pass the output of ..."
  messages) and the writers of each kind in :mod:`facesynth.model.spec` (docs/file-format.md);
- the stage table of ``docs/pipeline.md``: ``python -m facesynth.base.pipeline`` prints it,
  ``python -m facesynth.base.pipeline docs/pipeline.md`` (``make docs``) rewrites it there.

This module imports nothing of facesynth: core functions and results are named as
``"module:attribute"`` strings and imported only when asked for (:meth:`Stage.load_core`).
"""

from __future__ import annotations

import importlib
import sys
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .registry import METHODS

#: The settings section every command reads besides its own (the input bounds, facesynth.base.limits).
ALWAYS_READ = "limits"


@dataclass(frozen=True)
class Folder:
    """An output option that names a folder rather than a file.

    ``what`` names it in messages ('the report'). ``when`` restricts it to one value of another
    option (``("fmt", "obj-seq")``: a folder only for that format; otherwise the option names a
    file). ``in_place``: the folder is filled file by file and kept between runs (a rerun reuses
    it), instead of being written whole beside it and renamed into place."""

    what: str
    when: tuple[str, str] | None = None
    in_place: bool = False

    def applies(self, options: Mapping[str, Any]) -> bool:
        """Whether the option names a folder for these parsed options."""
        return self.when is None or options.get(self.when[0]) == self.when[1]


def _load(name: str) -> Any:
    module, _, attr = name.partition(":")
    return getattr(importlib.import_module(module), attr)


@dataclass(frozen=True)
class Stage:
    """One command of facesynth.

    name: the command path below ``facesynth`` ("normalize", "isomap build").
    summary: what it does, in one line.
    usage: a typical command line (the docs' stage table).
    reads: the settings sections it reads (``[limits]``, read by every command, is not listed;
        :data:`METHOD_SECTIONS` stands for the sections of the method family's members).
    inputs, outputs: the artifact kinds it reads and writes (``facesynth.model.spec.KINDS``).
    output_options: the options (click parameter names) naming the paths it writes, checked
        (writable, not clobbered) before any work.
    folder_outputs: those of them that name a folder, {option: :class:`Folder`}.
    core: the function the command calls, ``"module:attribute"``.
    result: the frozen dataclass ``core`` returns, ``"module:attribute"``; None where the core
        returns the lines to print (or a list of per-file reports).
    takes, makes: the inputs and outputs that are not artifacts (files, text), for the table.
    paper: the section of the papers it implements, for the table.
    """

    name: str
    summary: str
    usage: str
    core: str
    result: str | None = None
    reads: tuple[str, ...] = ()
    inputs: tuple[str, ...] = ()
    outputs: tuple[str, ...] = ()
    output_options: tuple[str, ...] = ()
    folder_outputs: Mapping[str, Folder] = field(default_factory=dict)
    takes: str = ""
    makes: str = ""
    paper: str = ""

    @property
    def command(self) -> str:
        """How a user types it: 'facesynth isomap build'."""
        return f"facesynth {self.name}"

    @property
    def writes(self) -> bool:
        """Whether it writes files (and so takes ``--overwrite``)."""
        return bool(self.output_options)

    def folders(self, options: Mapping[str, Any]) -> dict[str, Folder]:
        """The output options naming a folder, for these parsed options."""
        return {name: folder for name, folder in self.folder_outputs.items() if folder.applies(options)}

    def sections(self) -> tuple[str, ...]:
        """The settings sections it reads, the registered members' sections spelled out
        (``[limits]`` not included)."""
        out: list[str] = []
        for section in self.reads:
            if section == METHOD_SECTIONS:
                out += [e.facts["settings"] for e in METHODS.entries() if e.facts.get("settings")]
            else:
                out.append(section)
        return tuple(dict.fromkeys(out))

    def input_kinds(self) -> tuple[str, ...]:
        """The artifact kinds it reads, the registered fitted models' kinds spelled out."""
        return _kinds(self.inputs)

    def output_kinds(self) -> tuple[str, ...]:
        """The artifact kinds it writes, the registered fitted models' kinds spelled out."""
        return _kinds(self.outputs)

    def load_core(self) -> Any:
        """The core function (imported now)."""
        return _load(self.core)

    def load_result(self) -> type | None:
        """The result class (imported now), or None."""
        return None if self.result is None else _load(self.result)


#: In a stage's inputs or outputs: the model kinds of the fitted members of the method family
#: (``facesynth fit-method``), as registered (:data:`facesynth.base.registry.METHODS`), and
#: those of the fitted members that also stream.
FITTED_MODELS = "<fitted models>"
STREAMING_MODELS = "<fitted models that stream>"
#: In a stage's ``reads``: the settings section of every member of the method family, as
#: registered (the fact ``settings``: ``synthesize`` for the searches and ``mean``, ``trajectory``,
#: ``coarticulation``, a new member's own), so that a command running any member can read it.
METHOD_SECTIONS = "<the members' sections>"


def _kinds(declared: tuple[str, ...]) -> tuple[str, ...]:
    out: list[str] = []
    for kind in declared:
        if kind in (FITTED_MODELS, STREAMING_MODELS):
            out += [e.facts["source_kind"] for e in METHODS.entries()
                    if e.facts.get("fitted") and (kind == FITTED_MODELS or e.facts.get("streams"))]
        else:
            out.append(kind)
    return tuple(dict.fromkeys(out))


def _s(module: str, core: str = "run", result: str | None = None) -> tuple[str, str | None]:
    """(core, result) of a stage module of facesynth.stages."""
    return f"facesynth.stages.{module}:{core}", (f"facesynth.stages.{module}:{result}" if result else None)


def _stage(name: str, summary: str, usage: str, module: tuple[str, str | None], **kwargs: Any) -> Stage:
    core, result = module
    return Stage(name, summary, usage, core, result, **kwargs)


_ANIMATION = ("motion", "meshanim", "curves")  # the kinds export and player take

#: Every command, in pipeline order (the order of ``facesynth --help`` and of docs/pipeline.md).
STAGES: tuple[Stage, ...] = (
    _stage("sample-corpus", "Write the built-in virtual actress's capture corpus.",
           "facesynth sample-corpus DIR", _s("sample_corpus", "run", "SampleCorpusResult"),
           reads=("sample_corpus",), output_options=("out_dir",), folder_outputs={"out_dir": Folder("the corpus")},
           makes="C3D, WAV, TextGrid (phones, words, emotion), manifest, face.obj (the rig), markers.csv (with rigid "
                 "flags), groundtruth/ (per-frame rig weights, head, clean markers)",
           paper="III (a virtual capture)"),
    _stage("align", "Forced-align speech to its text.", "facesynth align WAV --text T -o X.TextGrid",
           _s("align", "run", "AlignResult"), reads=("align",), output_options=("output",),
           takes="speech: any sound file or video with sound (and its text; without one the speech is recognised)", makes="TextGrid",
           paper="III (forced alignment)"),
    _stage("ingest", "Read a capture manifest into a corpus artifact.", "facesynth ingest manifest.csv -o corpus.h5",
           _s("ingest", "run", "IngestResult"), reads=("ingest", "align"), outputs=("corpus",),
           output_options=("output",), takes="manifest + its takes (markers, Live Link Face, curves, video), audio, phones "
           "(a transcript aligned, audio alone recognised)",
           paper="III"),
    _stage("normalize", "Fill marker gaps and remove head motion.", "facesynth normalize corpus.h5 -o normalized.h5",
           _s("normalize", "run", "NormalizeResult"), reads=("normalize",), inputs=("corpus",),
           outputs=("normalized",), output_options=("output",), paper="III, Eq. 1-2"),
    _stage("pca", "Reduce the normalized frames with PCA.", "facesynth pca normalized.h5 -o pca.h5",
           _s("pca", "run", "PcaResult"), reads=("pca",), inputs=("normalized",), outputs=("pca",),
           output_options=("output",), paper="III, Eq. 11"),
    _stage("build-db", "Build the motion-node database and its transition features.",
           "facesynth build-db pca.h5 -o db.h5", _s("build_db", "run", "BuildDbResult"), reads=("build_db",),
           inputs=("pca",), outputs=("motiondb",), output_options=("output",), paper="III, VI-B (Eq. 6-9)"),
    _stage("db show", "List motion nodes.", "facesynth db show db.h5 [--phoneme P] [--node ID]",
           ("facesynth.model.motiondb:describe", None), inputs=("motiondb",), makes="text", paper="V"),
    _stage("check", "Validate artifacts against docs/file-format.md.", "facesynth check FILE...",
           ("facesynth.model.check:check_files", None), takes="any artifact", makes="one line per problem (exit 1 if any)",
           paper="([file format](file-format.md))"),
    _stage("prune", "Remove contaminated motion nodes into a new database.",
           "facesynth prune db.h5 --auto -o db_clean.h5 (or --remove IDS)", _s("prune", "run", "PruneResult"),
           reads=("prune",), inputs=("motiondb",), outputs=("motiondb",), output_options=("output",),
           makes="(with `pruned/`: what was removed, and why)", paper="V"),
    _stage("isomap build", "Per phoneme cluster: Isomap and PCA maps, triangulation, images.",
           "facesynth isomap db.h5 -o isomap.h5 --images DIR", _s("isomap", "run", "IsomapResult"),
           reads=("isomap",), inputs=("motiondb",), outputs=("isomap",), output_options=("output", "images"),
           folder_outputs={"images": Folder("the images")}, makes="PNG, index.html", paper="IV, Eq. 3"),
    _stage("isomap pick", "Print the frame at a point of a phoneme's map.", "facesynth isomap pick isomap.h5 PHONE X Y",
           _s("isomap", "pick", "Pick"), inputs=("isomap",), makes="CSV markers", paper="IV, Fig. 7"),
    _stage("isomap page", "Write the page that picks motion-node constraints on the phoneme maps.",
           "facesynth isomap page isomap.h5 db.h5 --phonemes X.TextGrid [--motion motion.h5] -o page.html",
           _s("isomap", "page", "PageResult"), reads=("isomap", "ingest"), inputs=("isomap", "motiondb", "motion"),
           output_options=("output",), takes="phones, emotions, constraints",
           makes="one HTML page writing `TIMEs NODE` constraint lines", paper="VI-A, Fig. 9"),
    _stage("synthesize", "Synthesize expressive marker motion for a new utterance.",
           "facesynth synthesize [--method M] db.h5|MODEL --phonemes X.TextGrid [--audio X.wav] -o motion.h5",
           _s("synthesize", "run", "SynthesizeResult"),
           reads=("synthesize", "ingest", "align", METHOD_SECTIONS),
           inputs=("motiondb", FITTED_MODELS, "headmotion"), outputs=("motion",),
           output_options=("output",), takes="phones (or audio to align), audio (its loudness), emotions, constraints (dp)",
           paper="VI, VII-B (dp, greedy); mean, coarticulation, trajectory ([methods](methods.md))"),
    _stage("suggest", "Suggest motion nodes for a constraint at a time.",
           "facesynth suggest db.h5 --phonemes X.TextGrid --at 1.25", _s("suggest", "suggest", "SuggestResult"),
           reads=("synthesize", "ingest"), inputs=("motiondb",), takes="phones", makes="table of nodes",
           paper="VI-A"),
    _stage("expression fit", "Fit the bilinear style/content expression model.",
           "facesynth expression fit normalized.h5 -o expr.h5", _s("expression", "fit", "ExpressionFitResult"),
           reads=("expression",), inputs=("normalized",), outputs=("expression",), output_options=("output",),
           paper="Chuang & Bregler §3, Eq. 4-6"),
    _stage("expression analyze", "Print each frame's style and content vectors.",
           "facesynth expression analyze expr.h5 motion.h5", _s("expression", "analyze"),
           reads=("expression",), inputs=("expression", "motion"), makes="CSV: per frame style and content vectors",
           paper="Chuang & Bregler §3.3, Eq. 5-6"),
    _stage("expression restyle", "Re-synthesize marker motion in another expression.",
           "facesynth expression restyle expr.h5 motion.h5 --to happy --intensity 0.6 -o happy.h5 (or --emotions FILE)",
           _s("expression", "restyle", "RestyleResult"), reads=("expression", "ingest"), inputs=("expression", "motion"),
           outputs=("motion",), output_options=("output",), paper="Chuang & Bregler §3.3, Eq. 7"),
    _stage("head-motion", "Head motion for new speech from captured segments matched by pitch.",
           "facesynth head-motion db.h5 --corpus corpus.h5 --audio X.wav -o head.h5",
           _s("head_motion", "run", "HeadMotionResult"), reads=("head_motion",), inputs=("motiondb", "corpus"),
           outputs=("headmotion",), output_options=("output",), takes="speech (any sound file or video with sound)",
           paper="Chuang & Bregler §5, Eq. 10-15"),
    _stage("deform", "Deform a face mesh by the markers.", "facesynth deform motion.h5 --mesh M --binding B -o anim.h5",
           _s("deform", "run", "DeformResult"), reads=("deform",), inputs=("motion",), outputs=("meshanim",),
           output_options=("output",), takes="mesh, binding CSV", paper="VII-A, Eq. 14-15"),
    _stage("keyshapes", "Choose key-shapes per emotion, with their keymorphs on the rig.",
           "facesynth keyshapes db.h5 --method pca|affinity [--count K] [--sheet S.png] -o keyshapes.h5",
           _s("keyshapes", "run", "KeyshapesResult"), reads=("keyshapes",), inputs=("motiondb",),
           outputs=("keyshapes",), output_options=("output", "sheet"), makes="PNG contact sheet",
           paper="Chuang & Bregler 2005 §4.1, Eq. 8; Huang et al. §5.2"),
    _stage("train-trajectory", "Deprecated: the same as fit-method trajectory (warns).",
           "facesynth train-trajectory db.h5 --keyshapes keyshapes.h5 -o traj.h5",
           _s("fit_method", "run", "FitMethodResult"), reads=(METHOD_SECTIONS,),
           inputs=("motiondb", "keyshapes"), outputs=("trajectory",), output_options=("output",),
           paper="Huang, Chen & Chuang §5.4"),
    _stage("fit-method", "Fit a synthesis method (coarticulation, trajectory) and write its model.",
           "facesynth fit-method coarticulation|trajectory db.h5 [--keyshapes K] -o model.h5",
           _s("fit_method", "run", "FitMethodResult"), reads=(METHOD_SECTIONS,),
           inputs=("motiondb", "keyshapes"), outputs=(FITTED_MODELS,), output_options=("output",),
           paper="Cohen & Massaro (coarticulation); Huang, Chen & Chuang §5.4 (trajectory)"),
    _stage("bind", "Place a capture's own markers on a rig.",
           "facesynth bind CAPTURE --rig builtin|RIG [--frame N] [--up AX --forward AX] -o markers.csv",
           _s("bind", "run", "BindResult"), reads=("bind", "normalize"), output_options=("output",),
           takes="a capture (C3D, TRC, CSV) + rig", makes="binding CSV (`marker,vertex,rigid,residual_mm,flagged`)",
           paper="a user's markers placed on a rig"),
    _stage("fit-articulation", "Fit the voice's articulation model on a performer's capture with its audio.",
           "facesynth fit-articulation normalized.h5 --corpus corpus.h5 [--binding B] [--takes T,...] -o articulation.h5",
           _s("fit_articulation", "run", "FitArticulationResult"), reads=("synthesize", "solve"),
           inputs=("normalized", "corpus"), outputs=("articulation",), output_options=("output",),
           takes="binding CSV (a capture's own markers)", paper="the voice's articulation (ridge regression)"),
    _stage("solve", "Solve the rig's blendshape weights that best explain the markers.",
           "facesynth solve motion.h5|normalized.h5 [--take T] [--rig RIG] [--binding B] -o curves.h5",
           _s("solve", "run", "SolveResult"), reads=("solve",), inputs=("motion", "normalized"), outputs=("curves",),
           output_options=("output",), takes="rig", paper="a direct facial solve"),
    _stage("retarget", "Retarget marker motion onto a rig through key-shapes and keymorphs.",
           "facesynth retarget motion.h5 --keyshapes K [--rig RIG] [--keymorphs DIR|CSV] [--mesh anim.h5] -o curves.h5",
           _s("retarget", "run", "RetargetResult"), reads=("retarget", "keyshapes"), inputs=("motion", "keyshapes"),
           outputs=("curves", "meshanim"), output_options=("output", "mesh_out"), takes="rig, keymorphs",
           paper="Chuang & Bregler Eq. 9; Huang et al. §3 (deformation gradients)"),
    _stage("rig-mesh", "Pose the rig with weight curves into a mesh animation.",
           "facesynth rig-mesh curves.h5 [--rig RIG] -o anim.h5", _s("rig_mesh", "run", "RigMeshResult"),
           inputs=("curves",), outputs=("meshanim",), output_options=("output",), takes="rig",
           paper="(rig evaluation)"),
    _stage("openfacefx", "Write openfacefx's lip sync of a motion's phones as rig curves.",
           "facesynth openfacefx motion.h5 [--rig RIG] -o openfacefx.h5", _s("openfacefx", "run", "OpenfacefxResult"),
           inputs=("motion",), outputs=("curves",), output_options=("output",), takes="rig",
           paper="(a baseline beside facesynth)"),
    _stage("render", "Render rig curves or mesh animations to a video with their audio.",
           "facesynth render curves.h5 [--audio X.wav] -o X.avi", _s("render", "run", "RenderResult"),
           reads=("render",), inputs=("curves", "meshanim"), output_options=("output",),
           takes="audio (none: silent), rig (for curves)", makes="AVI", paper="VIII"),
    _stage("export", "Write an animation for another tool.", "facesynth export ARTIFACT --format FMT -o OUT",
           _s("export", "run", "ExportResult"), reads=("export",), inputs=_ANIMATION, output_options=("output",),
           folder_outputs={"output": Folder("the OBJ sequence", when=("fmt", "obj-seq"))},
           makes="Live Link Face CSV, glTF/GLB (+ WAV), USD, C3D or an OBJ folder (docs/exports.md)"),
    _stage("player", "Write one HTML page that plays the animation in 3D with its audio.",
           "facesynth player ARTIFACT --audio X.wav -o player.html (or --live WS_URL)",
           _s("player", "run", "PlayerResult"), reads=("render",), inputs=_ANIMATION, output_options=("output",),
           takes="speech (any sound file or video with sound; and, for files made before provenance was kept, the "
                 "`motion` for phones)",
           makes="one HTML page: the whole face, render's camera, head motion, a phone timeline"),
    _stage("stream", "Live synthesis: audio in, frames of ARKit curves out.",
           "facesynth stream db.h5 [--audio X.wav | --serve HOST:PORT] [--livelink HOST:PORT]",
           _s("stream", "run"), reads=("stream", "synthesize", "align", "solve", METHOD_SECTIONS),
           inputs=("motiondb", STREAMING_MODELS),
           takes="live audio, or any sound file or video with sound (and phone timings, emotion messages)",
           makes="JSON frames of ARKit curves (stdout or WebSocket), Live Link Face UDP",
           paper="VI-VII live: a fixed-lag Algorithm 1 ([live](live.md))"),
    _stage("batch", "Synthesize every line of a dialogue script on Dask.", "facesynth batch script.csv --db db.h5 -o OUT/",
           _s("batch", "run", "BatchResult"),
           reads=("batch", "synthesize", "ingest", "align", "deform", "render", METHOD_SECTIONS, "solve", "export"),
           inputs=("motiondb", FITTED_MODELS), outputs=("motion", "curves", "meshanim"),
           output_options=("output",), folder_outputs={"output": Folder("the batch outputs", in_place=True)},
           takes="per line: audio, text (none: recognised) or phones, emotion(s), constraints",
           makes="per line ARKit CSV, glTF + WAV, USD, AVI, TextGrid, manifest; summary.csv, summary.html",
           paper="VI, VII (every line on Dask)"),
    _stage("capture", "Export a captured take as a motion artifact.",
           "facesynth capture corpus.h5 --db db.h5 --take T -o truth.h5", _s("capture", "run", "CaptureResult"),
           reads=("normalize", "synthesize"), inputs=("corpus", "motiondb"), outputs=("motion",),
           output_options=("output",), paper="VIII (ground truth beside synthesis)"),
    _stage("evaluate", "Synthesize every held-out sentence and compare it with its capture and baselines.",
           "facesynth evaluate db.h5 --heldout corpus.h5 --truth corpus/ -o report/",
           _s("evaluate", "run", "EvaluateResult"), reads=("evaluate", "synthesize", "normalize", METHOD_SECTIONS),
           inputs=("motiondb", "corpus", FITTED_MODELS), output_options=("output",),
           folder_outputs={"output": Folder("the report")},
           takes="the sample corpus folder's `groundtruth/`, `markers.csv`",
           makes="metrics.json, table.md, index.html, PNG", paper="VI-D, VIII, Eq. 12-13, Figs. 15-16"),
    _stage("tune", "Tune the cost weights by cross-validation.", "facesynth tune db.h5 --validation corpus.h5 -o tuned.toml",
           _s("tune", "run", "TuneResult"), reads=("tune", "synthesize", "build_db", "normalize"),
           inputs=("motiondb", "corpus"), output_options=("output",), makes="TOML for `--config`", paper="VI-D"),
    _stage("devices", "List the OpenCL devices and the one facesynth uses.", "facesynth devices",
           ("facesynth.base.opencl:describe_devices", None),
           makes="the OpenCL devices, whether each builds, the one used", paper="([OpenCL](opencl.md))"),
)

#: The stages by command path.
STAGE: dict[str, Stage] = {s.name: s for s in STAGES}

#: The top-level commands (groups for "isomap build", "db show") in pipeline order.
COMMAND_ORDER: tuple[str, ...] = tuple(dict.fromkeys(s.name.split()[0] for s in STAGES))

class _Reads(Mapping):
    """See :data:`READS` (current: a member registered later adds its section)."""

    def __getitem__(self, name: str) -> tuple[str, ...]:
        return STAGE[name].sections() + (ALWAYS_READ,)

    def __iter__(self):
        return iter(STAGE)

    def __len__(self) -> int:
        return len(STAGE)


#: The settings sections each command reads, ``[limits]`` included, by command path (the members'
#: sections as registered when asked).
READS: Mapping[str, tuple[str, ...]] = _Reads()

#: The folder outputs of each command that has any, {command: {option: Folder}}.
FOLDER_OUTPUTS: dict[str, Mapping[str, Folder]] = {s.name: s.folder_outputs for s in STAGES if s.folder_outputs}


#: What writes a kind no command writes yet, for a message ("make it with ... first").
OTHER_WRITERS: dict[str, str] = {}


def writers(kind: str) -> tuple[str, ...]:
    """The commands that write artifacts of ``kind``, in pipeline order ('facesynth synthesize', ...)."""
    return tuple(s.command for s in STAGES if kind in s.output_kinds())


def producers(kind: str) -> str:
    """The commands that write ``kind``, for a message: '`facesynth synthesize` or `facesynth capture`'."""
    names = [f"`{w}`" for w in writers(kind)] or [OTHER_WRITERS.get(kind, "`facesynth`")]
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " or " + names[-1]


# --- the stage table of docs/pipeline.md ---------------------------------------------------

BEGIN = "<!-- stages:begin -->"
END = "<!-- stages:end -->"
_NOTE = ("<!-- Generated from facesynth/base/pipeline.py by `python -m facesynth.base.pipeline docs/pipeline.md` (make docs); "
         "edit the declarations, not the table. -->")


def _cell(text: str) -> str:
    return text.replace("|", "\\|")


def _list(names: tuple[str, ...]) -> str:
    return ", ".join(f"`{n}`" for n in names)


def _join(kinds: str, other: str) -> str:
    if kinds and other:
        return f"{kinds} {other}" if other.startswith("(") else f"{kinds} + {other}"
    return kinds or other or "—"


def table() -> str:
    """The stage table (markdown), one row per stage of :data:`STAGES`."""
    rows = [_NOTE, "", "| command | what it does | reads | writes | settings | paper |", "|---|---|---|---|---|---|"]
    for s in STAGES:
        reads, writes = _join(_list(s.input_kinds()), _cell(s.takes)), _join(_list(s.output_kinds()), _cell(s.makes))
        rows.append(f"| `{_cell(s.usage)}` | {_cell(s.summary)} | {reads} | {writes} | {_list(s.sections()) or '—'} "
                    f"| {_cell(s.paper) or '—'} |")
    return "\n".join(rows) + "\n"


def document(current: str) -> str:
    """``current`` (the text of docs/pipeline.md) with the table between the markers brought up to date."""
    head, begin, rest = current.partition(BEGIN)
    _, end, tail = rest.partition(END)
    if not begin or not end:
        raise ValueError(f"the document has no {BEGIN} ... {END} markers around the stage table.")
    return f"{head}{BEGIN}\n{table()}{END}{tail}"


def main(argv: list[str]) -> int:
    if not argv:
        sys.stdout.write(table())
        return 0
    path = Path(argv[0])
    path.write_text(document(path.read_text(encoding="utf-8")), encoding="utf-8")
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main(sys.argv[1:]))
