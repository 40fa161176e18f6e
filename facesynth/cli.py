"""The ``facesynth`` command line: thin click commands that parse, load settings, call a
stage and map user errors to exit statuses: 0 ok, 1 bad input or data (one line), 2 bad
usage (a missing or contradictory option, a bad ``--set``; click's usage message), 130
interrupted (Ctrl-C), 143 terminated (SIGTERM); outputs are checked before any work."""

from __future__ import annotations

import contextlib
import functools
import importlib
import logging
import signal
import statistics
import sys
import threading
import time
from pathlib import Path

import click

from facesynth import __version__
from facesynth.base import limits, pipeline
from facesynth.base.config import SAMPLE_CORPUS_PRESETS, Config, choices, parse_override
from facesynth.base.errors import FacesynthError, OverrideError, UsageError
from facesynth.base.registry import EXPORT_FORMATS, METHODS, Entry, Registry

PATH = click.Path(path_type=Path)
EXISTING = click.Path(path_type=Path, dir_okay=False)


class RegistryChoice(click.Choice):
    """A choice among a registry's members (those ``where`` accepts), read when the command line
    is parsed or its help shown, so a member registered after this module was imported is offered
    too (:mod:`facesynth.base.registry`)."""

    def __init__(self, registry: Registry, where=lambda entry: True) -> None:
        self.registry = registry
        self.where = where
        super().__init__(())

    @property
    def choices(self) -> tuple[str, ...]:
        return tuple(e.name for e in self.registry.entries() if self.where(e))

    @choices.setter
    def choices(self, value) -> None:  # click.Choice.__init__ assigns the (empty) tuple given
        pass


#: ``--language``'s help (align, synthesize).
LANGUAGE_HELP = ("The text's language, a BCP-47 tag (en, de, fr, es, it, pt, nl, ru, cmn, ...; default "
                 "align.language, English); without a text, audio in another language is decoded as phones.")


def _with_language(settings, language: str | None):
    """The ``[align]`` settings with ``--language`` in force (None: as configured)."""
    import dataclasses

    return settings if language is None else dataclasses.replace(settings, language=language)


def _fitted(entry: Entry) -> bool:
    return bool(entry.facts.get("fitted"))


class DefaultGroup(click.Group):
    """A group that runs its default command when the first argument is no subcommand:
    ``facesynth isomap db.h5 -o x.h5`` and ``facesynth isomap pick ...`` both work."""

    default_command = "build"

    def resolve_command(self, ctx, args):
        if args and args[0] not in self.commands and args[0] not in ("-h", "--help"):
            args = [self.default_command] + list(args)
        return super().resolve_command(ctx, args)


class PipelineGroup(click.Group):
    """The top-level group: ``facesynth --help`` lists the commands in pipeline order (the
    order of the README and docs/pipeline.md), then any others alphabetically."""

    order = pipeline.COMMAND_ORDER

    def list_commands(self, ctx):
        listed = [name for name in self.order if name in self.commands]
        return listed + sorted(set(self.commands) - set(listed))


def _echo_lines(lines) -> None:
    """Print lines to stdout; a reader that stops early (``| head``) ends the command quietly
    with status 0 instead of a BrokenPipeError."""
    import os

    try:
        for line in lines:
            click.echo(line)
        sys.stdout.flush()
    except BrokenPipeError:
        # Python would flush stdout again at exit and fail; point it at /dev/null first.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        sys.exit(0)


class Context:
    """What a command's body gets: its settings (only the sections it declares), the global
    options, and its stage's declaration (:data:`facesynth.base.pipeline.STAGE`), through which it
    calls its core: commands import no stage by hand."""

    def __init__(self, config: Config, verbose: int, quiet: bool, overwrite: bool, declared: pipeline.Stage):
        self.config, self.verbose, self.quiet, self.overwrite = config, verbose, quiet, overwrite
        self.declared = declared

    def core(self, *args, **kwargs):
        """Call the command's core (its stage's ``core``, imported now) with these arguments."""
        return self.declared.load_core()(*args, **kwargs)

    @property
    def stage_module(self):
        """The module of the command's core, for the few helpers its output needs (the
        suggestions' table, the Isomap pick's CSV)."""
        return importlib.import_module(self.declared.core.partition(":")[0])

    def say(self, message: str) -> None:
        if not self.quiet:
            click.echo(message, err=True)

    def detail(self, message: str) -> None:
        if self.verbose and not self.quiet:
            click.echo(message, err=True)


class _MessageFormatter(logging.Formatter):
    """Warnings as 'warning: ...', everything else as the bare message."""

    def format(self, record: logging.LogRecord) -> str:
        message = record.getMessage()
        return f"warning: {message}" if record.levelno >= logging.WARNING else message


#: How many items of a list a line names before it says how many more there are (``-v``: all).
LISTED_ITEMS = 8


def _summarised(items: list[str], verbose: int) -> str:
    """``items`` joined by commas; without ``verbose``, the first :data:`LISTED_ITEMS` and how many more."""
    if verbose or len(items) <= LISTED_ITEMS:
        return ", ".join(items)
    return ", ".join(items[:LISTED_ITEMS]) + f" and {len(items) - LISTED_ITEMS} more (-v lists them)"


def _configure_logging(verbose: int, quiet: bool) -> None:
    """Messages of the ``facesynth`` logger (e.g. the OpenCL device choice) go to stderr:
    warnings by default, details with -v, nothing but errors with -q."""
    logger = logging.getLogger("facesynth")
    logger.handlers.clear()
    handler = logging.StreamHandler(sys.stderr)
    handler.setFormatter(_MessageFormatter())
    logger.addHandler(handler)
    logger.setLevel(logging.ERROR if quiet else logging.INFO if verbose else logging.WARNING)
    logger.propagate = False


#: The configuration sections each command reads (``[limits]`` included), by command path
#: ("isomap build"), from the declarations in facesynth.base.pipeline. A ``--set`` must name one of
#: them; ``Config.settings`` refuses any other, keeping this true.
READS = pipeline.READS


def _command_path() -> str:
    """The running command's path below ``facesynth``: 'synthesize', 'isomap build'."""
    names: list[str] = []
    ctx = click.get_current_context()
    while ctx.parent is not None:
        names.append(ctx.info_name or "")  # click names the context of every subcommand it invokes
        ctx = ctx.parent
    return " ".join(reversed(names))


def _check_overrides_read(command: str, overrides: tuple[str, ...]) -> None:
    """Refuse a ``--set`` for a section ``command`` never reads: it would be ignored silently."""
    reads = READS[command]
    for item in overrides:
        section = parse_override(item)[0]
        if section not in reads:
            readers = [name for name, sections in READS.items() if section in sections]
            mine = ", ".join(f"[{name}]" for name in reads if name != "limits") or "no settings"
            raise OverrideError(f"--set {item}: [{section}] is read by "
                                f"{', '.join('facesynth ' + name for name in readers)}; "
                                f"facesynth {command} reads {mine}, so this setting would be ignored.")


class Terminated(KeyboardInterrupt):
    """SIGTERM, raised in the main thread like Ctrl-C so that every ``finally`` runs (temporary
    outputs are removed) and the command ends with status 143."""


def _terminate(signum, frame):
    raise Terminated()


@contextlib.contextmanager
def _sigterm_raises():
    """While a command runs, SIGTERM raises :class:`Terminated`; the handler found before is put
    back after it, also when the command runs inside another program (a test calling
    :func:`main`), so that program's SIGTERM works as it did. Only the main thread can set
    handlers, and a handler set outside Python (which could not be put back) is left alone."""
    if threading.current_thread() is not threading.main_thread() or signal.getsignal(signal.SIGTERM) is None:
        yield
        return
    previous = signal.signal(signal.SIGTERM, _terminate)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


#: The root context's ``obj`` when facesynth is the program (:func:`run`), not a command called
#: inside another program through :func:`main` (a test, a notebook).
PROGRAM = "facesynth program"


def _hand_sigterm_on() -> None:
    """After a command ended by SIGTERM has cleaned up: inside another program, raise the signal
    again for that program's own handler (by default the program stops, as the signal asked, so
    a test run under a time-out ends); the facesynth program itself goes on to exit 143."""
    if click.get_current_context().find_root().obj != PROGRAM and threading.current_thread() is threading.main_thread():
        signal.raise_signal(signal.SIGTERM)


def _left_behind(published: list[Path], in_place: list[Path] | None = None) -> str:
    """The end of an interrupted command's message: which outputs it had written (complete), or
    that a folder it fills in place (batch's) keeps the work finished before the interrupt."""
    kept = [folder for folder in in_place or () if folder.is_dir()]
    if kept:
        return f"{', '.join(map(str, kept))} keeps what was finished before it; a rerun goes on from there."
    if not published:
        return "no output was written."
    names = ", ".join(map(str, published[:3])) + (f" and {len(published) - 3} more" if len(published) > 3 else "")
    return f"{names} {'was' if len(published) == 1 else 'were'} written before it (complete); nothing else was."


#: Output options that name a folder rather than a file, by command path (facesynth.base.pipeline).
FOLDER_OUTPUTS = pipeline.FOLDER_OUTPUTS


def _check_outputs(command: str, kwargs: dict, overwrite: bool) -> None:
    """Check every output path the command declares (``-o``, ``--images``, a corpus folder) for
    writability and no-clobber before any work, so a wrong path costs nothing. A folder written
    in place and kept between runs (batch's) may exist."""
    from facesynth.model.artifacts import check_output, check_output_folder

    declared = pipeline.STAGE[command]
    folders = declared.folders(kwargs)
    for name in declared.output_options:
        value = kwargs.get(name)
        if value is None:
            continue
        if name in folders:
            check_output_folder(Path(value), folders[name].what, None if folders[name].in_place else overwrite)
        else:
            check_output(Path(value), overwrite)


def stage(func=None, *, writes: bool = True):
    """Add the global options to a command (``--overwrite`` only when it ``writes`` files) and map
    its errors to exit statuses: UsageError (bad usage, e.g. a bad ``--set``) to click's usage
    message and 2, any other FacesynthError to one line and 1, Ctrl-C to 130, SIGTERM to 143.
    Before the command runs, its output paths are checked (writable, no clobbering) and the
    ``[limits]`` section is put in force (:mod:`facesynth.base.limits`)."""
    if func is None:
        return functools.partial(stage, writes=writes)

    @functools.wraps(func)
    def wrapper(config_path, overrides, verbose, quiet, overwrite=False, **kwargs):
        _configure_logging(verbose, quiet)
        started = time.perf_counter()
        published: list[Path] = []  # what an interrupt leaves behind, for its message
        in_place: list[Path] = []  # output folders filled in place, kept between runs
        try:
            command = _command_path()
            config = Config.load(config_path, tuple(overrides))
            _check_overrides_read(command, tuple(overrides))
            ctx = Context(config.only(READS[command]), verbose, quiet, overwrite, pipeline.STAGE[command])
            recording: contextlib.AbstractContextManager = contextlib.nullcontext()
            if writes:
                from facesynth.model.artifacts import recording_published

                _check_outputs(command, kwargs, overwrite)
                in_place = [Path(kwargs[name]) for name, folder in pipeline.STAGE[command].folders(kwargs).items()
                            if folder.in_place and kwargs.get(name) is not None]
                recording = recording_published(published)
            with limits.using(ctx.config.settings("limits")), _sigterm_raises(), recording:
                func(ctx, **kwargs)
        except UsageError as exc:
            raise click.UsageError(str(exc)) from None
        except FacesynthError as exc:
            click.echo(f"error: {exc}", err=True)
            sys.exit(1)
        except Terminated:
            click.echo(f"terminated (SIGTERM); {_left_behind(published, in_place)}", err=True)
            _hand_sigterm_on()
            sys.exit(143)
        except KeyboardInterrupt:
            click.echo(f"interrupted; {_left_behind(published, in_place)}", err=True)
            sys.exit(130)
        if verbose and not quiet:
            click.echo(f"done in {time.perf_counter() - started:.2f} s", err=True)

    if writes:
        wrapper = click.option("--overwrite", is_flag=True, help="Replace existing outputs.")(wrapper)
    wrapper = click.option("-q", "--quiet", is_flag=True, help="Say nothing but errors; no progress bars.")(wrapper)
    wrapper = click.option("-v", "--verbose", count=True, help="Say more.")(wrapper)
    wrapper = click.option("--set", "overrides", multiple=True, metavar="SECTION.KEY=VALUE",
                           help="Override one setting (repeatable).")(wrapper)
    return click.option("--config", "config_path", type=EXISTING, default=None,
                        help="TOML file overriding configs/default.toml.")(wrapper)


@click.group(cls=PipelineGroup, context_settings={"help_option_names": ["-h", "--help"], "max_content_width": 100})
@click.version_option(__version__, prog_name="facesynth")
def main():
    """Expressive, lip-synced 3D facial animation from a facial motion-capture database.

    Commands are listed in pipeline order. Every example in their help runs as written on the
    small built-in corpus, in a folder where the whole chain below has run (outputs are never
    replaced: remove them first, or add --overwrite).

    \b
    Example (the whole chain on the built-in corpus, from capture to video, then audio alone):
      facesynth sample-corpus corpus/ --preset small
      facesynth ingest corpus/manifest.csv -o corpus.h5
      facesynth normalize corpus.h5 -o normalized.h5
      facesynth pca normalized.h5 -o pca.h5
      facesynth build-db pca.h5 -o db.h5
      echo "0 1000 happy" > happy.txt
      facesynth synthesize db.h5 --phonemes corpus/labels/neutral_s016.TextGrid --emotions happy.txt \\
          -o motion.h5
      facesynth solve motion.h5 -o curves.h5
      facesynth render curves.h5 --audio corpus/audio/neutral_s016.wav -o neutral_s016.avi
      facesynth synthesize db.h5 --audio corpus/audio/neutral_s016.wav -o heard.h5
    """


@main.command("sample-corpus")
@click.argument("out_dir", type=PATH)
@click.option("--preset", type=click.Choice(SAMPLE_CORPUS_PRESETS), default="small", show_default=True)
@click.option("--seed", type=int, default=0, show_default=True)
@stage
def sample_corpus_cmd(ctx: Context, out_dir: Path, preset: str, seed: int):
    """Write the built-in virtual-actress corpus (C3D, WAV, TextGrid, manifest, face mesh).

    Presets: tiny (a few takes, for quick tests), small (the demo corpus: sentences s000 to
    s017 in four emotions; every example in facesynth's help uses it) and paper (the size of
    the paper's database). facegood: not the actress but a real performer shipped with
    facesynth, FACEGOOD's seven takes (one speaker, presumably Mandarin, neutral, 11 minutes,
    face solved from video into blendshape curves; MIT), as curves, WAV and a manifest whose
    phones ingest recognises from the audio.

    \b
    Example:
      facesynth sample-corpus corpus/ --preset small --seed 0
    """
    summary = ctx.core(out_dir, preset, seed, ctx.config.settings("sample_corpus"), ctx.overwrite)
    if preset == "facegood":
        ctx.say(f"wrote {summary.takes} takes of {summary.performer}, {summary.seconds:.1f} s of speech and curves, "
                f"to {out_dir}; ingest recognises their phones from the audio")
        return
    ctx.say(f"wrote {summary.takes} takes, {summary.seconds:.1f} s of capture, "
            f"{summary.train_phones} training phones, {summary.contamination_events} contamination events to {out_dir}")


@main.command()
@click.argument("audio", type=EXISTING)
@click.option("--text", default=None, help="What is said (without it or --transcript: recognised from the audio).")
@click.option("--transcript", type=EXISTING, default=None, help="A file holding what is said.")
@click.option("--dict", "dict_path", type=EXISTING, default=None, help="Extra pronunciations: lines 'word  W ER D'.")
@click.option("--language", default=None, help=LANGUAGE_HELP)
@click.option("-o", "--output", type=PATH, required=True, help="Output TextGrid.")
@stage
def align(ctx: Context, audio: Path, text: str | None, transcript: Path | None, dict_path: Path | None,
          language: str | None, output: Path):
    """Forced-align speech to its text; writes a phone TextGrid in the Festival phone set.

    AUDIO is any sound file or video with sound that ffmpeg reads (WAV, FLAC, M4A, MP3, Opus,
    MP4, ...). pocketsphinx first; when it fails or places fewer words, a wider beam, then chunks cut at
    silences, then typical phone durations over the voiced span (align.methods; the one used
    is printed). Speech aligned as pause for longer than align.max_voiced_pause_s is warned
    about: the text may lack words. Non-speech marked in the text ([breath], [laugh],
    <noise>) is aligned as pause. Without --text or --transcript the speech is recognised
    first (align.recognition: words recognised then aligned, or a phone loop).

    \b
    Example:
      facesynth align corpus/audio/neutral_s000.wav --text "beautiful he men from began pretty strong" \\
          -o s000.TextGrid
    """
    if text is not None and transcript is not None:
        raise UsageError("give one of --text or --transcript, not both.")
    summary = ctx.core(audio, text if transcript is None else ctx.stage_module.read_transcript(transcript), output,
                              _with_language(ctx.config.settings("align"), language), dict_path, ctx.overwrite)
    if summary.recognized:
        ctx.say(f"recognised: {summary.recognized}")
    for reason in summary.attempts:
        ctx.detail(f"not used: {reason}")
    for warning in summary.warnings:
        ctx.say(f"warning: {warning}")
    ctx.say(f"aligned {summary.phones} phones over {summary.seconds:.2f} s ({summary.method}) -> {output}")


@main.command()
@click.argument("manifest", type=EXISTING)
@click.option("-o", "--output", type=PATH, required=True, help="Output corpus.h5.")
@click.option("--rig", type=PATH, default=None,
              help="The rig Live Link Face takes and other curves pose (default: the built-in rig, recorded at the "
                   "virtual actress's markers); a folder of OBJ files or a .gltf/.glb, with --binding.")
@click.option("--binding", type=EXISTING, default=None,
              help="CSV marker,vertex: the markers recorded on the rig that curve takes pose.")
@stage
def ingest(ctx: Context, manifest: Path, output: Path, rig: Path | None, binding: Path | None):
    """Read a capture manifest into a corpus artifact: per take markers (C3D, TRC, CSV), a Live
    Link Face CSV, another rig's curves with a mapping to ARKit, or a video (facesynth[video]);
    audio; phone timing (a TextGrid, a transcript to align, or recognised from the audio).

    \b
    Example:
      facesynth ingest corpus/manifest.csv -o corpus.h5
    """
    s = ctx.core(manifest, output, ctx.config.settings("ingest"), ctx.config.settings("align"), ctx.overwrite,
                         rig, binding)
    def takes(names: list[str]) -> str:
        listed = ", ".join(names[:4]) + (", ..." if len(names) > 4 else "")
        return f"{len(names)} take{'s' if len(names) != 1 else ''} ({listed})"

    if s.recognized:
        ctx.say(f"note: no alignment or transcript for {takes(s.recognized)}: phones recognised from the audio.")
    if s.posed:
        ctx.say("note: every take was posed from curves; its rest pose and head pose are recorded for normalize.")
    if s.without_audio:
        ctx.say(f"note: no audio for {takes(s.without_audio)}; head-motion needs it.")
    if s.without_phones:
        ctx.say(f"note: no phone timing for {takes(s.without_phones)}; "
                f"build-db and what needs a database leave them out; normalize, pca and solve take them.")
    ctx.say(f"ingested {s.takes} takes, {s.frames} frames of {s.markers} markers at {s.fps:g} Hz, "
            f"{s.phones} phone segments ({100 * s.missing_fraction:.2f}% samples missing) -> {output}")


@main.command()
@click.argument("corpus", type=EXISTING)
@click.option("-o", "--output", type=PATH, required=True, help="Output normalized.h5.")
@stage
def normalize(ctx: Context, corpus: Path, output: Path):
    """Fill marker gaps and remove head motion, keeping it as per-frame transforms.

    Head motion is removed as in Eq. 1-2 of the paper.

    \b
    Example:
      facesynth normalize corpus.h5 -o normalized.h5
    """
    s = ctx.core(corpus, output, ctx.config.settings("normalize"), ctx.overwrite)
    for take, marker, start, length in s.long_gaps:
        ctx.detail(f"take {take!r}, marker {marker}: gap of {length:.3f} s at {start:.3f} s is too long to fill; "
                   "PCA will project those frames from the visible markers.")
    gaps = (f"; {len(s.long_gaps)} gaps too long to fill are left for PCA to project (-v lists them)"
            if s.long_gaps else "")
    for warning in s.warnings:
        ctx.say(f"warning: {warning}")
    if s.rigid_spreads_mm is not None:  # rigid_source 'data': found from the data
        ctx.say("no rigid markers are named; found from the data (spread: how much each one's distances to the others "
                "vary): " + ", ".join(f"{n} {x:.2f} mm" for n, x in zip(s.rigid_markers, s.rigid_spreads_mm)))
    ctx.detail("head pose fitted on " + ", ".join(f"{n} (weight {w:.2f})" for n, w in zip(s.rigid_markers, s.rigid_weights)))
    pose = "known head pose of takes posed from curves" if s.rigid_source == "known" else \
        f"head pose on {len(s.rigid_markers)} rigid markers"
    ctx.say(f"normalized {s.frames} frames ({pose}){gaps} -> {output}")


@main.command()
@click.argument("normalized", type=EXISTING)
@click.option("-o", "--output", type=PATH, required=True, help="Output pca.h5.")
@stage
def pca(ctx: Context, normalized: Path, output: Path):
    """Reduce the normalized frames with PCA (25 components by default, paper III).

    \b
    Example:
      facesynth pca normalized.h5 -o pca.h5 --set pca.n_components=25
    """
    s = ctx.core(normalized, output, ctx.config.settings("pca"), ctx.overwrite)
    ctx.say(f"PCA: {s.components} components cover {100 * s.explained:.2f}% of the variance "
            f"(reconstruction RMS {s.rms_error_mm:.3f} mm per marker) -> {output}")


@main.command("build-db")
@click.argument("pca_path", metavar="PCA", type=EXISTING)
@click.option("-o", "--output", type=PATH, required=True, help="Output db.h5.")
@stage
def build_db(ctx: Context, pca_path: Path, output: Path):
    """Build the motion-node database and the per-node features of its transition terms (DSC, PGap, VGap).

    \b
    Example:
      facesynth build-db pca.h5 -o db.h5
    """
    s = ctx.core(pca_path, output, ctx.config.settings("build_db"), ctx.overwrite)
    ctx.say(f"built {s.nodes} motion nodes ({s.with_predecessor} with a captured predecessor); "
            f"DSC features {s.dsc_s:.2f} s, boundary states {s.boundary_s:.2f} s, write {s.write_s:.2f} s -> {output}")


@main.command()
@click.argument("db", metavar="DB|MODEL", type=EXISTING)
@click.option("--method", type=RegistryChoice(METHODS), default=None,
              help="The synthesis method (default: synthesize.method, dp): dp and greedy search the motion database (DB), "
                   "mean takes its per-(phone, emotion) mean poses; trajectory and coarticulation read a MODEL "
                   "fitted on it (facesynth fit-method).")
@click.option("--phonemes", type=EXISTING, default=None, help="The utterance's phone timing (TextGrid or .lab).")
@click.option("--audio", type=EXISTING, default=None,
              help="The speech (any sound file or video with sound ffmpeg reads: WAV, FLAC, M4A, MP3, Opus, MP4, "
                   "...): aligned on the fly to --text (without it, recognised: align.recognition), or "
                   "with --phonemes its timing; the voice shapes the mouth too (synthesize.voice_recognized, "
                   "synthesize.voice_given).")
@click.option("--text", default=None, help="What --audio says.")
@click.option("--language", default=None, help=LANGUAGE_HELP)
@click.option("--emotions", type=EXISTING, default=None, help="Emotion spans: 'start_s end_s emotion' lines, or a TextGrid tier 'emotions'.")
@click.option("--constraints", type=EXISTING, default=None, help="Motion-node constraints: 'INDEX NODE' or 'TIMEs NODE' lines (dp only).")
@click.option("--search", type=click.Choice(choices("synthesize", "search")), default=None, hidden=True,
              help="Deprecated: --method.")
@click.option("--head-motion", "head_motion_path", type=EXISTING, default=None,
              help="Head motion from `facesynth head-motion` to put on the output instead of the source takes'.")
@click.option("-o", "--output", type=PATH, required=True, help="Output motion.h5.")
@stage
def synthesize(ctx: Context, db: Path, method, phonemes, audio, text, language, emotions, constraints, search,
               head_motion_path, output: Path):
    """Synthesize expressive marker motion for a new utterance (paper VI, Algorithm 1).

    --method (or synthesize.method) picks the member of the method family: dp (the default),
    greedy, mean, and the fitted
    trajectory (Huang et al. Eq. 6-7) and coarticulation (Cohen-Massaro) models, whose model file
    (facesynth fit-method) is then the first argument. With --audio the voice shapes the mouth
    too: its articulation (the acoustic articulation model: opening, rounding, closures), with the
    phones recognised (without --text or --phonemes: synthesize.voice_recognized) or given
    (synthesize.voice_given); "loudness" takes its loudness instead (synthesize.loudness_weight),
    "off" the phones alone.

    \b
    Example:
      echo "0 100 sad" > spans.txt
      facesynth synthesize db.h5 --phonemes corpus/labels/neutral_s016.TextGrid \\
          --emotions spans.txt -o motion.h5
    """
    from facesynth.domain.methods import MethodSettings, steps
    settings = MethodSettings.of(ctx.config)
    name, warnings = steps.deprecated_search(method, search, settings.synthesize, ctx.config.given("synthesize.search"))
    for warning in warnings:
        ctx.say(f"warning: {warning}")
    s = ctx.core(db, output, settings, ctx.config.settings("ingest"),
                  _with_language(ctx.config.settings("align"), language), method=name,
                  phones_path=phonemes, emotions_path=emotions, constraints_path=constraints, audio=audio, text=text,
                  head_motion_path=head_motion_path, overwrite=ctx.overwrite)
    on_database = not _fitted(METHODS.entry(s.method))
    made = s.summary
    for phone, how in made.unseen.items():
        what = f"database has no node of /{phone}/" if on_database else f"model has no {phone}"
        ctx.say(f"warning: the {what}; it will be covered by {how}.")
    for phone, group in made.fallbacks.items():
        ctx.say(f"warning: the trajectory model has no Gaussian of /{phone}/; it uses the pooled Gaussian of its "
                f"viseme class ({group}).")
    phases = [("device choice", "device_choice_s"), ("transition costs", "transition_s"), ("step costs", "steps_s"),
              ("OpenCL set-up", "opencl_setup_s"), ("search", "search_s"), ("post-processing", "postprocess_s"),
              ("the voice", "voice_s")]
    timed = ([("read database" if on_database else "read model", s.load_s)]
             + [(label, made.phases[key]) for label, key in phases if made.phases.get(key) is not None]
             + [("input hashes", s.hash_wait_s), ("write", s.write_s)])
    ctx.detail("phases: " + ", ".join(f"{label} {value:.3f} s" for label, value in timed)
               + (f"; search on {made.device}" if made.device else ""))
    if made.cost is not None:
        ctx.say(f"synthesized {made.phones} phones, {made.frames} frames, cost {made.cost:.2f}, "
                f"{made.joins} non-captured joins -> {output}")
    elif made.energy is not None:
        ctx.detail(f"lambda {made.lam:g} per frame")
        ctx.say(f"synthesized {made.phones} phones, {made.frames} frames by the trajectory method, "
                f"Eq. 6 energy {made.energy:.2f} -> {output}")
    else:
        ctx.say(f"synthesized {made.phones} phones, {made.frames} frames by the {s.method} method -> {output}")


@main.command()
@click.argument("db", type=EXISTING)
@click.option("--phonemes", type=EXISTING, required=True, help="The utterance's phone timing (TextGrid or .lab).")
@click.option("--at", "at_s", type=float, required=True, help="Time (s) of the phone to constrain.")
@click.option("--emotions", type=EXISTING, default=None, help="Emotion spans, as for synthesize.")
@click.option("--constraints", type=EXISTING, default=None, help="Constraints already chosen, as for synthesize.")
@click.option("--top", type=int, default=15, show_default=True, help="How many to list.")
@click.option("--context-only", is_flag=True, help="Only context-correct nodes (same triphone context).")
@stage(writes=False)
def suggest(ctx: Context, db: Path, phonemes: Path, at_s: float, emotions, constraints, top: int, context_only: bool):
    """Suggest motion nodes for a constraint at a time: time- and context-correct, best first (paper VI-A).

    \b
    Example:
      facesynth suggest db.h5 --phonemes corpus/labels/sad_s017.TextGrid --at 1.25
    """
    from facesynth.base.errors import InputError
    if top < 1:
        raise click.BadParameter(f"{top}: list at least one suggestion.", param_hint="--top")
    found = ctx.core(db, phonemes, at_s, ctx.config.settings("synthesize"), ctx.config.settings("ingest"),
                     emotions, constraints).suggestions
    rows, stage = found.rows, ctx.stage_module
    listed = stage.shown(rows, top, context_only)
    if not listed:  # only --context-only can leave nothing: every phone has at least one node
        raise InputError(stage.no_context_message(found, at_s) + "; drop --context-only to see the time-correct nodes.")
    ctx.say(f"phone {found.index} /{found.phone}/ in context {found.context}, relative time {found.relative_time:.2f}; "
            f"unconstrained optimum {found.optimum:.2f} uses node {found.optimal_node}")
    if not any(r.context_correct for r in rows):
        ctx.say("warning: " + stage.no_context_message(found, at_s) + ".")
    for line in stage.table(rows, top, context_only):
        click.echo(line)
    best = listed[0]
    ctx.say(f"best: rank 1 (the first row under the header), node {best.node}, "
            f"{'context-correct' if best.context_correct else 'time-correct only'}, cost {best.cost:.2f}; to use it:")
    ctx.say(f"  {stage.use_line(at_s, best, constraints)}")
    emotion_option = f" --emotions {emotions}" if emotions else ""
    ctx.say(f"  facesynth synthesize {db} --phonemes {phonemes}{emotion_option} "
            f"--constraints {constraints or 'constraints.txt'} -o constrained.h5")


@main.command()
@click.argument("motion", type=EXISTING)
@click.option("--mesh", type=EXISTING, required=True, help="Face mesh (.obj or .ply).")
@click.option("--binding", type=EXISTING, required=True, help="CSV 'marker,vertex' binding markers to mesh vertices.")
@click.option("-o", "--output", type=PATH, required=True, help="Output anim.h5.")
@stage
def deform(ctx: Context, motion: Path, mesh: Path, binding: Path, output: Path):
    """Deform a plain face mesh, one without blendshapes, by the markers, with mesh-distance Gaussian weights.

    The weights and the deformation are Eq. 14-15 of the paper. For a rig (the built-in one, or
    your own with blendshapes) use `facesynth solve` and render the curves: the rig's own shapes
    give a clean jaw line where Gaussian weights crease the skin under an open jaw.

    \b
    Example:
      facesynth deform motion.h5 --mesh corpus/face.obj --binding corpus/markers.csv -o anim.h5
    """
    s = ctx.core(motion, mesh, binding, output, ctx.config.settings("deform"), ctx.overwrite)
    if s.unreached:  # eyes, teeth, the back of the head: expected, so only with -v
        ctx.detail(f"{s.unreached} vertices are farther than deform.distance_threshold from every marker and stay at rest.")
    ctx.say(f"deformed {s.vertices} vertices over {s.frames} frames (marker fit RMS {s.fit_rms:.3g} mesh units) -> {output}")


_RIG_HELP = "A user's rig: a folder with neutral.obj and one OBJ per shape, or a .gltf/.glb with morph targets (default, or 'builtin': the built-in ICT-FaceKit rig)."
_BINDING_HELP = "CSV 'marker,vertex' placing the motion's markers on the rig's vertices (facesynth bind writes one); needed with a user's --rig."


@main.command()
@click.argument("db", type=EXISTING)
@click.option("--method", type=click.Choice(choices("keyshapes", "method")), default=None,
              help="pca: principal-axis extremes (Chuang & Bregler); affinity: affinity propagation + merging (Huang et al.). Default: keyshapes.method.")
@click.option("--count", type=click.IntRange(0, 200), default=None,
              help="Key-shapes per emotion; 0: the error knee (affinity) or 20 (pca). Default: keyshapes.count.")
@click.option("--sheet", type=PATH, default=None, help="Also write a contact sheet (.png) of the keymorphs on the rig.")
@click.option("-o", "--output", type=PATH, required=True, help="Output keyshapes.h5.")
@stage
def keyshapes(ctx: Context, db: Path, method, count, sheet, output: Path):
    """Choose key-shapes per emotion from the database's training takes, with their keymorphs on the rig.

    Frames are non-negative combinations of their emotion's key-shapes (Chuang & Bregler Eq. 8);
    the reconstruction error per key-shape count is stored beside them.

    \b
    Example:
      facesynth keyshapes db.h5 --method pca --count 7 -o keyshapes.h5
    """
    import dataclasses

    settings = ctx.config.settings("keyshapes")
    settings = dataclasses.replace(settings, **{k: v for k, v in (("method", method), ("count", count)) if v is not None})
    s = ctx.core(db, output, settings, sheet, ctx.overwrite)
    per = ", ".join(f"{e} {v.count} ({v.rms_mm:.2f} mm)" for e, v in s.emotions.items())
    ctx.say(f"key-shapes by {s.method}: {per} -> {output}" + (f" (sheet {sheet})" if sheet else ""))


@main.command("train-trajectory")
@click.argument("db", type=EXISTING)
@click.option("--keyshapes", "keyshapes_path", type=EXISTING, required=True, help="Key-shapes (facesynth keyshapes).")
@click.option("-o", "--output", type=PATH, required=True, help="Output traj.h5.")
@stage
def train_trajectory(ctx: Context, db: Path, keyshapes_path: Path, output: Path):
    """Deprecated: the same as `facesynth fit-method trajectory DB --keyshapes K -o OUT`.

    \b
    Example:
      facesynth keyshapes db.h5 --method pca --count 7 -o keyshapes.h5
      facesynth train-trajectory db.h5 --keyshapes keyshapes.h5 -o traj.h5
    """
    ctx.say("warning: `facesynth train-trajectory` is deprecated and will go in a later release; it runs "
            "`facesynth fit-method trajectory`, which does the same.")
    _fit_method(ctx, "trajectory", db, keyshapes_path, output)


@main.command("fit-method")
@click.argument("method", type=RegistryChoice(METHODS, _fitted))
@click.argument("db", type=EXISTING)
@click.option("--keyshapes", "keyshapes_path", type=EXISTING, default=None,
              help="Key-shapes (facesynth keyshapes): the trajectory method's weights are over them.")
@click.option("-o", "--output", type=PATH, required=True, help="Output model .h5.")
@stage
def fit_method(ctx: Context, method: str, db: Path, keyshapes_path: Path | None, output: Path):
    """Fit a synthesis method on the database's training takes and write its model.

    coarticulation: a Cohen-Massaro model per (phone, emotion) (coarticulation.iterations);
    trajectory: Huang et al.'s Gaussians of key-shape weights (needs --keyshapes). `facesynth synthesize --method METHOD MODEL` then needs the model
    file alone. dp, greedy and mean read the database itself and have nothing to fit. The example
    asks for a quick fit of 8 iterations; the default is coarticulation.iterations = 40.

    \b
    Example:
      facesynth fit-method coarticulation db.h5 -o coart.h5 --set coarticulation.iterations=8
      facesynth synthesize --method coarticulation coart.h5 --phonemes corpus/labels/sad_s017.TextGrid -o coart_motion.h5
    """
    _fit_method(ctx, method, db, keyshapes_path, output)


def _fit_method(ctx: Context, method: str, db: Path, keyshapes_path: Path | None, output: Path) -> None:
    from facesynth.domain.methods import MethodSettings
    m = ctx.core(method, db, output, MethodSettings.of(ctx.config), keyshapes_path=keyshapes_path,
                  overwrite=ctx.overwrite).model
    f = m.fit
    ctx.detail(f"fitted in {m.fit_s:.2f} s")
    parts = [f"{f.phones} phones and {f.pairs} (phone, emotion) Gaussians over {f.keyshapes} key-shapes"
             if f.keyshapes is not None else "", f"{f.labels} (phone, emotion) types" if f.labels is not None else ""]
    what = "; ".join(p for p in parts if p) or "fitted"
    ctx.say(f"{method} model: {what} (fit RMS {f.fit_rms_mm:.2f} mm per marker), {m.bytes} bytes -> {output}")


@main.command()
@click.argument("capture", type=EXISTING)
@click.option("--rig", type=PATH, default="builtin", show_default=True,
              help="'builtin' (the ICT-FaceKit rig), or a user's rig: a folder with neutral.obj and one OBJ per shape, "
                   "or a .gltf/.glb (taken +y up, the face toward +z).")
@click.option("--frame", type=click.IntRange(min=0), default=None,
              help="Capture frame to fit (0-based). Default: bind.frame (-1: the take's most typical frame).")
@click.option("--up", type=click.Choice(["+x", "-x", "+y", "-y", "+z", "-z"]), default=None,
              help="The capture's up axis (with --forward). Default: found from the data.")
@click.option("--forward", type=click.Choice(["+x", "-x", "+y", "-y", "+z", "-z"]), default=None,
              help="The axis the capture's face looks along (with --up).")
@click.option("-o", "--output", type=PATH, required=True, help="Output binding CSV (marker,vertex,rigid,residual_mm,flagged).")
@stage
def bind(ctx: Context, capture: Path, rig, frame, up, forward, output: Path):
    """Place a capture's own markers on a rig: a binding CSV to check and edit, for solve, rig-mesh and deform.

    One frame is fitted to the rig's surface (a similarity found by closest points from several
    starts), each marker takes its nearest vertex; markers far from the surface are flagged.
    Rigid (head) markers are found from the data. Save it as markers.csv beside the manifest
    so ingest records the rigid flags.

    \b
    Example:
      facesynth bind corpus/mocap/neutral_s000.c3d --rig builtin -o bound.csv
    """
    import dataclasses

    settings = ctx.config.settings("bind")
    if frame is not None:
        settings = dataclasses.replace(settings, frame=frame)
    s = ctx.core(capture, output, settings, ctx.config.settings("normalize"), rig, up, forward, ctx.overwrite)
    for name, r in s.residual_mm.items():
        ctx.detail(f"  {name}: {r:.2f} mm from its vertex" + ("  (flagged)" if name in s.flagged else ""))
    if s.unbound:
        ctx.say(f"warning: not seen in frame {s.frame}, left out: {', '.join(s.unbound)}; choose another --frame to bind them.")
    if s.flagged:
        ctx.say(f"warning: {len(s.flagged)} markers lie more than {s.max_residual_mm:g} mm from the rig's surface: "
                + _summarised([f"{n} {s.residual_mm[n]:.1f} mm" for n in s.flagged], ctx.verbose)
                + "; check them in the CSV (flagged = 1), or delete their rows.")
    for note in s.notes:
        ctx.say(f"note: {note}.")
    if s.shared_vertices:
        ctx.say(f"note: {s.shared_vertices} markers share their vertex with another; check the CSV.")
    if s.rigid:
        spreads = sorted(s.rigid_spreads_mm)
        ctx.say(f"{len(s.rigid)} rigid markers found from the data (spread {spreads[0]:.2f} to {spreads[-1]:.2f} mm, "
                f"median {statistics.median(spreads):.2f}; flagged in the CSV's rigid column)"
                + ("" if ctx.verbose else "; -v lists them"))
        ctx.detail("rigid markers (spread in mm): " + ", ".join(f"{n} {x:.2f}" for n, x in zip(s.rigid, s.rigid_spreads_mm)))
    ctx.say(f"bound {s.markers} markers of frame {s.frame} to rig {s.rig} (scale {s.scale:.3g}; residual "
            f"median {s.residual_median_mm:.2f} mm, 95th percentile {s.residual_p95_mm:.2f} mm) -> {output}")


@main.command("fit-articulation")
@click.argument("normalized", type=EXISTING)
@click.option("--corpus", "corpus_path", type=EXISTING, required=True,
              help="The ingested capture NORMALIZED was made from (facesynth ingest): its audio.")
@click.option("--binding", type=EXISTING, default=None, help=_BINDING_HELP)
@click.option("--takes", default=None, help="Comma-separated takes to fit on (default: every take with audio).")
@click.option("-o", "--output", type=PATH, required=True, help="Output articulation.h5.")
@stage
def fit_articulation(ctx: Context, normalized: Path, corpus_path: Path, binding, takes, output: Path):
    """Fit the voice's articulation model on a performer's own capture with its audio.

    Per take: the voice's features against the mouth's opening, its closures and, where the
    markers are bound on the built-in rig, the rig's jawOpen, mouthFunnel and mouthPucker (a
    facial solve); ridge regression with a 46 ms look-ahead. Name the output in
    synthesize.articulation_model so that this performer's voice shapes the mouth.

    \b
    Example:
      facesynth fit-articulation normalized.h5 --corpus corpus.h5 -o articulation.h5
      facesynth synthesize db.h5 --audio corpus/audio/neutral_s016.wav --set synthesize.articulation_model=articulation.h5 -o voiced.h5
    """
    c = ctx.config
    s = ctx.core(normalized, corpus_path, output, c.settings("synthesize"), c.settings("solve"), binding=binding,
                  takes=None if takes is None else [t.strip() for t in takes.split(",") if t.strip()],
                  overwrite=ctx.overwrite)
    if not s.solved:
        ctx.say("note: the capture's markers are not bound on the rig (give --binding): the model predicts the "
                "opening and closures alone, and the phones keep the lips' rounding.")
    ctx.say(f"fitted the voice's articulation on {len(s.takes)} takes ({s.seconds:.0f} s of audio; look-ahead "
            f"{1000 * s.look_ahead_s:.0f} ms): " + ", ".join(f"{k} r {v:.2f}" for k, v in s.fit_r.items())
            + f" on the takes fitted -> {output}")
    h = s.held_out
    if h is None:
        ctx.say("note: with one take nothing is held out: the voice closes no lips of its own "
                "(synthesize.voice_closure_threshold); fit on two takes or more to choose where it may.")
        return
    ctx.say("each take predicted by the model fitted on the others: " + ", ".join(f"{k} r {v:.2f}" for k, v in h.r.items()))
    met = f"{100 * h.recall:.0f}% of the {h.closures} closures captured, {100 * h.precision:.0f}% of its closures right"
    if h.closure_threshold is not None:
        ctx.say(f"the voice's own closures: at closure score {h.closure_threshold:.2f} they met {met}; the model "
                "carries that threshold (synthesize.voice_closure_threshold = -1, the default, takes it)")
    else:
        ctx.say(f"the voice's own closures: at best they met {met}; fewer than half right, so the model makes none")


@main.command()
@click.argument("motion", type=EXISTING)
@click.option("--rig", type=PATH, default=None, help=_RIG_HELP)
@click.option("--binding", type=EXISTING, default=None, help=_BINDING_HELP)
@click.option("--take", default=None, help="With a normalized capture: the take to solve (default: its only take).")
@click.option("--neutral", default=None,
              help="With a normalized capture: the performer's neutral face, which the weights are measured from: "
                   "auto (the take's quietest half second), frame:N, time:SECONDSs, take:NAME (a neutral take) or off. "
                   "Default: solve.neutral.")
@click.option("-o", "--output", type=PATH, required=True, help="Output curves.h5.")
@stage
def solve(ctx: Context, motion: Path, rig, binding, take, neutral, output: Path):
    """Solve the rig's blendshape weights, between 0 and 1, that best explain the markers, frame by frame.

    A direct facial solve with a temporal smoothness term and a face's priors (sparse weights,
    antagonists not both on, mirrored channels alike); the reference for retarget. MOTION is a
    motion artifact, or a normalized capture (one take of it, at solve.output_fps, measured from
    the performer's neutral face). A filmed take needs no binding on the built-in rig.

    \b
    Example:
      facesynth solve motion.h5 -o solved.h5
      facesynth rig-mesh solved.h5 -o solved_anim.h5
    """
    import dataclasses

    settings = ctx.config.settings("solve")
    if neutral is not None:
        settings = dataclasses.replace(settings, neutral=neutral)
    s = ctx.core(motion, output, settings, rig, binding, ctx.overwrite, take)
    if s.exact:
        ctx.say("note: a capture posed from curves (noise-free markers) is solved without smoothing or ridge "
                "(solve.posed_captures).")
    ctx.say(f"solved {s.shapes} shapes of rig {s.rig} over {s.frames} frames ({s.iterations} iterations, "
            f"marker residual RMS {s.residual_rms:.3g} rig units; per marker median "
            f"{s.marker_residual_median_mm:.2f} mm, 95th percentile {s.marker_residual_p95_mm:.2f} mm) -> {output}")


@main.command()
@click.argument("motion", type=EXISTING)
@click.option("--keyshapes", "keyshapes_path", type=EXISTING, required=True, help="Key-shapes (facesynth keyshapes).")
@click.option("--rig", type=PATH, default=None, help=_RIG_HELP)
@click.option("--binding", type=EXISTING, default=None, help=_BINDING_HELP)
@click.option("--keymorphs", type=PATH, default=None,
              help="Artist keymorphs: a folder of <keyshape>.obj, or a CSV with a 'keyshape' column and one column per rig shape.")
@click.option("--emotion", default=None, help="Use this emotion's keymorphs alone (default: blend emotions frame by frame).")
@click.option("--blend", type=click.Choice(choices("retarget", "blend")), default=None,
              help="Mesh blending for --mesh: linear or gradient (deformation gradients). Default: retarget.blend.")
@click.option("--mesh", "mesh_out", type=PATH, default=None, help="Also write the rig mesh animation (anim.h5) blended from the keymorphs.")
@click.option("-o", "--output", type=PATH, required=True, help="Output curves.h5.")
@stage
def retarget(ctx: Context, motion: Path, keyshapes_path: Path, rig, binding, keymorphs, emotion, blend, mesh_out, output: Path):
    """Retarget marker motion onto a rig through key-shapes and keymorphs, as Chuang and Bregler do.

    Writes the rig's weight curves, and with --mesh the mesh blended from the keymorph meshes.

    \b
    Example:
      facesynth keyshapes db.h5 --count 7 -o keyshapes.h5
      facesynth retarget motion.h5 --keyshapes keyshapes.h5 --blend linear --mesh retargeted_anim.h5 -o retargeted.h5
    """
    import dataclasses

    settings = ctx.config.settings("retarget")
    if blend:
        settings = dataclasses.replace(settings, blend=blend)
    s = ctx.core(motion, keyshapes_path, output, settings, ctx.config.settings("keyshapes"), rig, binding, keymorphs,
                  mesh_out, emotion, ctx.overwrite)
    ctx.say(f"retargeted {s.frames} frames through {s.keyshapes} key-shapes onto rig {s.rig} (key-shape fit RMS "
            f"{s.residual_rms_mm:.3g} mm) -> {output}" + (f", {s.blend} mesh -> {mesh_out}" if mesh_out else ""))


@main.command("rig-mesh")
@click.argument("curves", type=EXISTING)
@click.option("--rig", type=PATH, default=None, help=_RIG_HELP)
@click.option("--binding", type=EXISTING, default=None, help=_BINDING_HELP)
@click.option("-o", "--output", type=PATH, required=True, help="Output anim.h5.")
@stage
def rig_mesh(ctx: Context, curves: Path, rig, binding, output: Path):
    """Pose the rig with weight curves (solve, retarget) into a mesh animation file.

    Optional: render, player and export read curves directly; this keeps the posed mesh as a file.

    \b
    Example:
      facesynth solve motion.h5 -o solved.h5
      facesynth rig-mesh solved.h5 -o solved_anim.h5
    """
    s = ctx.core(curves, output, rig, binding, ctx.overwrite)
    ctx.say(f"posed rig {s.rig} ({s.vertices} vertices) over {s.frames} frames -> {output}")


@main.command()
@click.argument("motion", type=EXISTING)
@click.option("--rig", type=PATH, default=None, help="The rig to drive (default: the built-in rig; a user's rig "
              "whose blendshapes have ARKit names: a folder of OBJ files or a .gltf/.glb file).")
@click.option("-o", "--output", type=PATH, required=True, help="Output curves.h5.")
@stage
def openfacefx(ctx: Context, motion: Path, rig, output: Path):
    """Write openfacefx's lip sync of a synthesized motion's phones as rig curves, to compare with facesynth.

    The same phones, timing, frame rate and rig; render shows both side by side. Needs the
    openfacefx package (the 'baselines' extra).

    \b
    Example:
      facesynth openfacefx motion.h5 -o openfacefx.h5
      facesynth render curves.h5 --compare openfacefx.h5 --view side-by-side -o compare.avi
    """
    s = ctx.core(motion, output, rig, ctx.overwrite)
    ctx.say(f"openfacefx lip sync of {s.phones} phones on rig {s.rig} over {s.frames} frames "
            f"({s.fps:g} frames/s) -> {output}")


@main.command()
@click.argument("anims", nargs=-1, required=True, type=EXISTING)
@click.option("--audio", "audios", multiple=True, type=EXISTING,
              help="Audio of each animation, in order (any sound file or video with sound; none: a silent "
                   "soundtrack).")
@click.option("--view", type=click.Choice(choices("render", "view")), default=None, help="Default: render.view.")
@click.option("--compare", multiple=True, type=EXISTING,
              help="Animation shown beside for the side-by-side view: one for all, or one per animation in order.")
@click.option("--rig", type=PATH, default=None, help="The rig that rig curves pose (default: the built-in rig; "
              "a folder of OBJ files or a .gltf/.glb file).")
@click.option("--binding", type=EXISTING, default=None, help="With --rig: the markers' vertices (the markers view).")
@click.option("-o", "--output", type=PATH, required=True, help="Output .avi.")
@stage
def render(ctx: Context, anims, audios, view, compare, rig, binding, output: Path):
    """Render rig curves or mesh animations to an AVI with their audio (several play one after another).

    Rig curves (solve, retarget, openfacefx) pose the rig with its own blendshapes, with eyes,
    teeth and tongue; a mesh animation (deform, rig-mesh) is drawn as stored.

    \b
    Examples:
      facesynth render curves.h5 --audio corpus/audio/neutral_s016.wav -o neutral_s016.avi
      facesynth openfacefx motion.h5 -o openfacefx.h5
      facesynth render curves.h5 --compare openfacefx.h5 --view side-by-side \\
          --set 'render.labels=["facesynth","openfacefx"]' --audio corpus/audio/neutral_s016.wav -o compare.avi
    """
    import dataclasses

    settings = ctx.config.settings("render")
    if view:
        settings = dataclasses.replace(settings, view=view)
    s = ctx.core(list(anims), list(audios), output, settings, list(compare), ctx.overwrite, rig, binding)
    for note in s.notes:  # a mesh without eye or mouth holes: expected for plain meshes, so only with -v
        ctx.detail(f"render: {note}.")
    ctx.say(f"rendered {s.frames} frames ({s.seconds:.2f} s of video, {s.frames_per_s:.1f} frames/s) -> {output}")


@main.command()
@click.argument("artifact", type=EXISTING)
@click.option("--format", "fmt", type=RegistryChoice(EXPORT_FORMATS),
              required=True, help="What to write (units and axes: docs/exports.md).")
@click.option("--fps", type=float, default=None,
              help="Frame rate of the output (default: export.arkit_fps for arkit-csv, else the animation's).")
@click.option("--head-motion", is_flag=True, help="Put the head motion in (Head* columns, node or xform animation).")
@click.option("--audio", type=EXISTING, default=None,
              help="Speech put beside a gltf/glb as a WAV and named in it (a WAV is copied; any other sound file or "
                   "video with sound, decoded).")
@click.option("--mesh", type=EXISTING, default=None,
              help="Mesh (.obj/.ply) whose faces to write, with the animation's vertex count.")
@click.option("-o", "--output", type=PATH, required=True, help="Output file (a folder for obj-seq).")
@stage
def export(ctx: Context, artifact: Path, fmt: str, fps: float | None, head_motion: bool, audio: Path | None,
           mesh: Path | None, output: Path):
    """Write a motion, mesh animation or rig curves for another tool.

    arkit-csv (Unreal Live Link, MetaHuman) and gltf/glb need rig curves (`facesynth solve`);
    usd/usda and obj-seq a mesh (mesh animation or curves); c3d markers (motion or mesh animation).

    \b
    Example:
      facesynth export motion.h5 --format c3d -o motion.c3d
      facesynth export curves.h5 --format obj-seq -o anim_obj
    """
    s = ctx.core(artifact, fmt, output, ctx.config.settings("export"), fps=fps, head_motion=head_motion, audio=audio,
                  mesh=mesh, overwrite=ctx.overwrite)
    folder = EXPORT_FORMATS.entry(fmt).facts.get("folder", False)
    extra = f" (+ {s.files[1].name})" if not folder and len(s.files) > 1 else ""
    what = f"{len(s.files)} files" if folder else fmt
    ctx.say(f"exported {s.frames} frames ({s.seconds:.2f} s at {s.fps:g} frames/s) of the {s.kind} "
            f"as {what} -> {output}{extra}")


@main.command()
@click.argument("artifact", type=EXISTING, required=False)
@click.option("--audio", type=EXISTING, default=None,
              help="Speech played with the animation (embedded in the page; any sound file or video with sound); "
                   "with --live, the speech the page sends.")
@click.option("--motion", type=EXISTING, default=None,
              help="The synthesized motion a mesh animation or curves came from: its phones, emotion and provenance.")
@click.option("--live", "live_url", default=None, metavar="WS_URL",
              help="Instead of an artifact: a live page that connects to 'facesynth stream DB --serve' at this "
                   "WebSocket URL (e.g. ws://127.0.0.1:8765) and animates the built-in rig's face as frames arrive.")
@click.option("-o", "--output", type=PATH, required=True, help="Output .html.")
@stage
def player(ctx: Context, artifact: Path | None, audio: Path | None, motion: Path | None, live_url: str | None,
           output: Path):
    """Write one self-contained HTML page that plays the animation in 3D with its audio.

    Orbit with the mouse, play/pause and scrub; the timeline shows each phone, its emotion and
    (for synthesized motion) the take and database node it came from. No network is needed to view it.

    With --live WS_URL (and no ARTIFACT) the page is the live mode: it holds the built-in rig with
    its 52 ARKit blendshapes, connects to the stream server, sends the --audio speech (or a WAV the
    viewer picks) in real time when 'start' is pressed, and shows each frame at its time after a
    small jitter buffer, playing the speech in sync; it shows the connection state. A '?live=URL'
    parameter of the page's address overrides the URL, '#start' starts at once.

    \b
    Examples:
      facesynth player curves.h5 --motion motion.h5 --audio corpus/audio/neutral_s016.wav -o player.html
      facesynth player --live ws://127.0.0.1:8765 --audio corpus/audio/neutral_s016.wav -o live.html
    """
    if (artifact is None) == (live_url is None):
        raise click.UsageError("give either an ARTIFACT to play or --live WS_URL (a live page), not both or neither.")
    if live_url is not None:
        if motion is not None:
            raise click.UsageError("--motion is for an ARTIFACT; a live page takes its frames from the stream.")
        s = ctx.stage_module.run_live(live_url, output, audio=audio, view=ctx.config.settings("render"), overwrite=ctx.overwrite)
        ctx.say(f"live player for {live_url} ({s.vertices} vertices, {s.targets} ARKit morph targets, "
                f"{s.seconds:.2f} s of speech to send) -> {output} ({s.bytes / 1e6:.1f} MB)")
        return
    assert artifact is not None
    s = ctx.core(artifact, output, audio=audio, motion=motion, view=ctx.config.settings("render"),
                  overwrite=ctx.overwrite)
    ctx.say(f"player of {s.frames} frames ({s.seconds:.2f} s at {s.fps:g} frames/s, "
            f"{s.phones} phones) -> {output} ({s.bytes / 1e6:.1f} MB)")


@main.command()
@click.argument("script", type=EXISTING)
@click.option("--db", "db_path", type=EXISTING, required=True,
              help="The motion database (db.h5), or for --method trajectory / coarticulation its fitted model.")
@click.option("--method", type=RegistryChoice(METHODS), default=None,
              help="The synthesis method of every line (default: synthesize.method, dp), as for synthesize.")
@click.option("-o", "--output", type=PATH, required=True, help="Output folder (per-line files and the summary).")
@click.option("--outputs", default=None, metavar="KINDS",
              help="Comma-separated: motion, curves, avi, anim and the export formats (arkit-csv, gltf, usd, ...; default: batch.outputs).")
@click.option("--rig", type=PATH, default=None,
              help="The rig of curves, arkit, gltf, usd and avi: a folder of OBJ files or a .gltf/.glb (default: built-in).")
@click.option("--rig-binding", type=EXISTING, default=None,
              help="CSV 'marker,vertex' placing the markers on --rig (a user's rig needs it).")
@click.option("--mesh", type=EXISTING, default=None, help="A plain face mesh for anim (.obj or .ply).")
@click.option("--binding", type=EXISTING, default=None, help="CSV 'marker,vertex' binding of --mesh, for anim.")
@click.option("--scheduler", default=None, metavar="ADDRESS", help="An existing Dask scheduler (tcp://host:8786).")
@click.option("--workers", type=click.IntRange(min=1), default=None,
              help="Local worker processes (default: batch.workers, 0 = one per core).")
@stage
def batch(ctx: Context, script: Path, db_path: Path, method: str | None, output: Path, outputs: str | None,
          rig: Path | None, rig_binding: Path | None, mesh, binding, scheduler: str | None, workers: int | None):
    """Synthesize every line of a dialogue script on Dask, with a summary of what failed.

    SCRIPT is a CSV with columns id, audio, text (or alignment: a TextGrid or .lab), and
    optionally emotion (or emotions: a per-phone emotion file) and constraints; paths are
    relative to its folder. Each line is aligned (when no alignment is given), synthesized and
    written to OUTPUT as ID.motion.h5, and as asked ID.curves.h5 (the facial solve on the rig),
    ID.arkit.csv, ID.gltf with ID.wav, ID.usd, ID.avi (the rig rendered) and ID.anim.h5 (a plain
    mesh deformed), with ID.TextGrid and ID.json (its manifest: every file with its sha256); a
    rerun skips lines whose outputs are unchanged and whose inputs did not change.
    OUTPUT/summary.csv and summary.html list every line's status, alignment method, phone
    count, timings and the reason of each failure. Exit status 1 when any line failed.

    \b
    Example:
      echo id,audio,text,emotion > script.csv
      echo l1,corpus/audio/neutral_s000.wav,beautiful he men from began pretty strong,happy >> script.csv
      facesynth batch script.csv --db db.h5 -o lines/ --workers 1
      facesynth batch script.csv --db db.h5 -o lines/ --outputs curves,gltf,avi
    """
    import dataclasses

    settings = ctx.config.settings("batch")
    if outputs is not None:
        kinds = tuple(k.strip() for k in outputs.split(",") if k.strip())
        allowed = choices("batch", "outputs")
        unknown = [k for k in kinds if k not in allowed]
        if unknown or not kinds:
            raise click.BadParameter(f"{outputs!r}: give a comma-separated list of {', '.join(allowed)}.",
                                     param_hint="--outputs")
        settings = dataclasses.replace(settings, outputs=kinds)
    if workers is not None:
        settings = dataclasses.replace(settings, workers=workers)

    def on_result(r):
        if r.status == "failed":
            ctx.detail(f"{r.id}: failed: {r.reason}")
        else:
            ctx.detail(f"{r.id}: {r.status} ({r.method}, {r.phones} phones, {r.total_s:.2f} s)")

    from facesynth.domain.methods import MethodSettings, steps

    method_settings = MethodSettings.of(ctx.config)
    chosen, warnings = steps.deprecated_search(method, None, method_settings.synthesize,
                                               ctx.config.given("synthesize.search"))
    for warning in warnings:
        ctx.say(f"warning: {warning}")
    s = ctx.core(script, db_path, output, settings, method_settings, ctx.config.settings("ingest"),
                  ctx.config.settings("align"), ctx.config.settings("deform"), ctx.config.settings("render"),
                  method=chosen, mesh=mesh, binding=binding,
                  scheduler=scheduler, overwrite=ctx.overwrite, on_result=on_result, solve=ctx.config.settings("solve"),
                  export=ctx.config.settings("export"), rig=rig, rig_binding=rig_binding)
    skipped = f", {s.skipped} up to date" if s.skipped else ""
    ctx.say(f"{s.ok} of {s.lines} lines done{skipped}, {s.failed} failed in {s.seconds:.1f} s; "
            f"summary: {s.html}")
    if s.failed:
        first = next(r for r in s.results if r.status == "failed")
        raise FacesynthError(f"{s.failed} of {s.lines} lines failed (first: {first.id}: {first.reason.rstrip('.')}); "
                             f"every reason is in {s.csv}.")


@main.command()
@click.argument("db", type=EXISTING)
@click.option("--heldout", type=EXISTING, required=True, help="The corpus.h5 holding the held-out takes.")
@click.option("--truth", type=PATH, default=None,
              help="The corpus folder with clean ground truth (groundtruth/, markers.csv): adds errors against it and openfacefx.")
@click.option("--model", "models", type=EXISTING, multiple=True,
              help="A model fitted on DB (facesynth fit-method), scored by its method (trajectory needs one; "
                   "coarticulation is fitted here without); repeat for several.")
@click.option("--trajectory", type=EXISTING, default=None, hidden=True, help="Deprecated: --model.")
@click.option("-o", "--output", type=PATH, required=True, help="Report folder (metrics.json, table.md, index.html, plots).")
@stage
def evaluate(ctx: Context, db: Path, heldout: Path, truth: Path | None, models: tuple[Path, ...],
             trajectory: Path | None, output: Path):
    """Synthesize every held-out sentence and compare it with its capture and baselines.

    The measures: Eq. 12-13 of the paper against the capture and (with --truth) the clean
    ground truth, lip-closure timing on /p b m/, join smoothness, emotion recognisability,
    each with a bootstrap 95% interval over sentences and paired DP - baseline differences.

    \b
    Example:
      facesynth evaluate db.h5 --heldout corpus.h5 --truth corpus/ -o report/
    """
    from facesynth.domain.methods import MethodSettings
    if trajectory is not None:
        ctx.say("warning: `--trajectory` is deprecated and will go in a later release; give the model with "
                "`--model` (it is scored by the method whose model it is).")
        models = models + (trajectory,)
    s = ctx.core(db, heldout, output, ctx.config.settings("evaluate"), MethodSettings.of(ctx.config),
                  ctx.config.settings("normalize"), ctx.overwrite, truth=truth, models=models)
    for method, m in s.methods.items():
        f = m.get("figures", {})
        clean = f" (clean truth {f['rms_clean_mm']['value']:.3f} mm)" if f.get("rms_clean_mm", {}).get("value") is not None else ""
        ctx.say(f"{method}: RMS {m['rms_mm']:.3f} mm{clean}, velocity RMS {m['velocity_rms_mm_s']:.1f} mm/s")
    ctx.say(f"report -> {output}/index.html, table -> {output}/table.md")
    if s.recommendation:
        ctx.say(s.recommendation)


@main.command()
@click.argument("corpus", type=EXISTING)
@click.option("--db", "db_path", type=EXISTING, required=True, help="The database whose head frame and rest pose to use.")
@click.option("--take", required=True, help="The take to export (e.g. a held-out one).")
@click.option("-o", "--output", type=PATH, required=True, help="Output motion.h5.")
@stage
def capture(ctx: Context, corpus: Path, db_path: Path, take: str, output: Path):
    """Export a captured take as a motion artifact: the ground truth to render beside a synthesis.

    \b
    Example:
      facesynth capture corpus.h5 --db db.h5 --take neutral_s016 -o truth.h5
      facesynth solve truth.h5 -o truth_curves.h5
      facesynth render curves.h5 --audio corpus/audio/neutral_s016.wav --view side-by-side \\
          --compare truth_curves.h5 -o compare.avi
    """
    s = ctx.core(db_path, corpus, take, output, ctx.config.settings("normalize"),
                      ctx.config.settings("synthesize").output_fps, ctx.overwrite)
    ctx.say(f"exported take {s.take} ({s.frames} frames) -> {output}")


@main.command()
@click.argument("db", type=EXISTING)
@click.option("--validation", type=EXISTING, required=True, help="The corpus.h5 with val (tuning) and test (report) takes.")
@click.option("--method", type=RegistryChoice(METHODS), default=None,
              help="The method whose weights to tune (default: synthesize.method); only dp and greedy have any.")
@click.option("-o", "--output", type=PATH, required=True, help="Output TOML with the tuned [synthesize] weights.")
@stage
def tune(ctx: Context, db: Path, validation: Path, method: str | None, output: Path):
    """Tune the cost weights (alpha1..alpha6, PNT), the join smoothing window and the
    boundary-fit length by cross-validation on the validation sentences (paper VI-D).

    One progress bar shows the evaluations with the best validation error so far (a line every
    few evaluations when stderr is not a terminal). Settings worse on the validation sentences
    than the start are never written: if nothing beats the start, the start is written with a
    warning. The example asks for a quick run of 12 weight evaluations from 3 starts; the
    default budget is tune.max_evaluations = 60 from tune.starts = 6.

    \b
    Example:
      facesynth tune db.h5 --validation corpus.h5 -o tuned.toml --set tune.max_evaluations=6 --set tune.starts=2
      facesynth synthesize db.h5 --phonemes corpus/labels/neutral_s016.TextGrid --config tuned.toml -o tuned.h5
    """
    from facesynth.base.progress import Overall
    bar = None

    def show(done: int, total: int, err: float, best: float) -> None:
        nonlocal bar
        if bar is None:
            bar = Overall(total, "tune", ctx.say)
        bar.step(f"best {best:.4f} mm^2 (last {err:.4f})")

    try:
        s = ctx.core(db, validation, output, ctx.config.settings("tune"), ctx.config.settings("synthesize"),
                      ctx.config.settings("build_db"), ctx.config.settings("normalize"), ctx.overwrite, progress_fn=show,
                      method=method)
    finally:
        if bar is not None:
            bar.close()
    t = s.tuning
    for warning in t.warnings:
        ctx.say(f"warning: {warning}")
    ctx.say(f"{t.evaluations} evaluations in {s.seconds:.1f} s on {t.validation_sentences} validation sentences: "
            f"error {t.validation_err_before:.4f} -> {t.validation_err_after:.4f} mm^2")
    if t.test_ci_before is not None and t.test_ci_after is not None:  # with test takes, as the test errors
        (lb, hb), (la, ha) = t.test_ci_before, t.test_ci_after
        ctx.say(f"on {t.test_sentences} test sentences not used for tuning: {t.test_err_before:.4f} [{lb:.4f}, {hb:.4f}] -> "
                f"{t.test_err_after:.4f} [{la:.4f}, {ha:.4f}] mm^2 (bootstrap 95%)")
    ctx.say("weights: " + ", ".join(f"{k}={v:.4g}" for k, v in t.weights.items())
            + f"; smoothing_half_window={t.smoothing_half_window}, boundary_fit_frames={t.boundary_fit_frames} -> {output}")
    if t.boundary_fit_changed:
        ctx.say(f"the boundary-fit length changed: run build-db (and prune) again with --config {output} for it to take effect.")


@main.group(cls=DefaultGroup)
def isomap():
    """Phoneme-Isomaps (paper IV): build them, pick a new frame from one, or choose constraints on them.

    \b
    Example:
      facesynth isomap db.h5 -o isomap.h5
      facesynth isomap pick isomap.h5 aa 0.5 -1.2
    """


@isomap.command("build")
@click.argument("db", type=EXISTING)
@click.option("-o", "--output", type=PATH, required=True, help="Output isomap.h5.")
@click.option("--images", type=PATH, default=None, help="Folder for the PNG maps and index.html.")
@stage
def isomap_build(ctx: Context, db: Path, output: Path, images: Path | None):
    """Per phoneme cluster: 2D Isomap, PCA map, Delaunay triangulation and images.

    The images show the frames over the map as in Eq. 3 of the paper.

    \b
    Example:
      facesynth isomap build db.h5 -o isomap.h5 --images isomaps/
    """
    s = ctx.core(db, output, ctx.config.settings("isomap"), images, ctx.overwrite)
    for phone, note in s.notes.items():  # small clusters get fewer neighbours: expected, so only with -v
        ctx.detail(f"/{phone}/: {note}")
    where = f"; images in {images}/index.html" if images else ""
    ctx.say(f"embedded {s.clusters} phoneme clusters ({s.frames} frames, largest {s.largest}) "
            f"in {s.embed_s:.1f} s -> {output}{where}")


# ignore_unknown_options: a negative coordinate ('-1.2') is an argument, not an unknown option.
@isomap.command("pick", context_settings={"ignore_unknown_options": True})
@click.argument("isomap_path", metavar="ISOMAP", type=EXISTING)
@click.argument("phoneme")
@click.argument("x", type=float)
@click.argument("y", type=float)
@click.option("--pca-map", is_flag=True, help="Pick on the PCA map instead of the Isomap.")
@stage(writes=False)
def isomap_pick(ctx: Context, isomap_path: Path, phoneme: str, x: float, y: float, pca_map: bool):
    """Print the frame at a point of a phoneme's map as CSV markers.

    The frame blends the three frames around the point, as in Fig. 7 of the paper.

    \b
    Example:
      facesynth isomap db.h5 -o isomap.h5
      facesynth isomap pick isomap.h5 aa 0.5 -1.2 > frame.csv
    """
    picked = ctx.core(isomap_path, phoneme, x, y, pca_map)
    ctx.detail(f"triangle of frames {picked.corners} (nodes {picked.nodes}), weights {picked.weights}")
    _echo_lines(ctx.stage_module.markers_csv(picked.markers, picked.marker_names))


@isomap.command("page")
@click.argument("isomap_path", metavar="ISOMAP", type=EXISTING)
@click.argument("db", type=EXISTING)
@click.option("--phonemes", type=EXISTING, required=True, help="The utterance's phone timing (TextGrid or .lab).")
@click.option("--emotions", type=EXISTING, default=None, help="Emotion spans, as for synthesize.")
@click.option("--constraints", type=EXISTING, default=None, help="Constraints already chosen, as for synthesize: shown and kept.")
@click.option("--motion", type=EXISTING, default=None, help="The motion synthesized for this utterance: its path's nodes are marked.")
@click.option("-o", "--output", type=PATH, required=True, help="Output page (.html).")
@stage
def isomap_page(ctx: Context, isomap_path: Path, db: Path, phonemes: Path, emotions, constraints, motion, output: Path):
    """Write the constraint page of an utterance: pick a phone, click a node on its Isomap (paper VI-A).

    The page highlights the phone's time-correct and context-correct nodes (those facesynth
    suggest lists), marks the node the motion's path chose, and a click on a node writes the
    line 'TIMEs NODE' for synthesize --constraints (copy or download it). ISOMAP must be built
    from DB. One self-contained HTML file; the GUI of Fig. 9 of the paper.

    \b
    Example:
      facesynth isomap build db.h5 -o isomap.h5
      facesynth isomap page isomap.h5 db.h5 --phonemes corpus/labels/neutral_s016.TextGrid \\
          --motion motion.h5 -o constraints.html
    """
    s = ctx.core(isomap_path, db, phonemes, output, ctx.config.settings("isomap"), ctx.config.settings("ingest"),
                   emotions, constraints, motion, ctx.overwrite)
    if s.missing:
        ctx.say(f"warning: the database has no node of {', '.join('/' + p + '/' for p in s.missing)}; "
                "those phones cannot be constrained (synthesize covers them with nodes of the same viseme).")
    for note in s.notes:
        ctx.say(f"warning: {note}.")
    ctx.say(f"wrote the constraint page of {s.phones} spoken phones ({s.maps} maps, "
            f"{s.constraints} constraints given, {s.bytes / 1e6:.1f} MB) -> {output}")


@main.group()
def db():
    """Browse the motion-node database (paper V).

    \b
    Example:
      facesynth db show db.h5 --phoneme aa
    """


@db.command("show")
@click.argument("db_path", metavar="DB", type=EXISTING)
@click.option("--phoneme", default=None, help="Only this phone's nodes.")
@click.option("--node", type=int, default=None, help="One node in detail.")
@stage(writes=False)
def db_show(ctx: Context, db_path: Path, phoneme: str | None, node: int | None):
    """List motion nodes: phone, triphone context, emotion, take, frames, neighbours.

    \b
    Example:
      facesynth db show db.h5 --node 42
    """
    from facesynth.model.motiondb import MotionDatabase, describe

    _echo_lines(describe(MotionDatabase.read(db_path), phoneme, node))


@main.group()
def expression():
    """The bilinear style/content expression model of Chuang & Bregler 2005, section 3.

    The paper factors 2D video shape and texture; facesynth factors 3D marker motion, so
    restyled motion goes through deform, retarget and render unchanged.

    \b
    Example:
      facesynth expression fit normalized.h5 -o expr.h5
    """


@expression.command("fit")
@click.argument("normalized", type=EXISTING)
@click.option("-o", "--output", type=PATH, required=True, help="Output expr.h5.")
@stage
def expression_fit(ctx: Context, normalized: Path, output: Path):
    """Fit the bilinear model on the takes of each sentence in every emotion, aligned phone by phone.

    The error of each alternating least-squares iteration is printed with -v.

    \b
    Example:
      facesynth expression fit normalized.h5 -o expr.h5
    """
    s = ctx.core(normalized, output, ctx.config.settings("expression"), ctx.overwrite)
    for note in s.skipped:
        ctx.detail(f"skipped {note}.")
    for n, err in enumerate(s.errors, 1):
        ctx.detail(f"iteration {n}: mean squared error {err:.6g} mm^2")
    ctx.say(f"fitted {', '.join(s.emotions)} on {s.sentences} sentences ({s.frames} aligned frames, "
            f"{s.components} components, content size {s.content_dim}); error {s.errors[-1]:.4g} mm^2 "
            f"after {len(s.errors)} iterations -> {output}")


@expression.command("analyze")
@click.argument("model", type=EXISTING)
@click.argument("motion", type=EXISTING)
@stage(writes=False)
def expression_analyze(ctx: Context, model: Path, motion: Path):
    """Print each frame's style vector, nearest emotion and content vector as CSV (equations 5 and 6).

    \b
    Example:
      facesynth expression fit normalized.h5 -o expr.h5
      facesynth expression analyze expr.h5 motion.h5 > styles.csv
    """
    _echo_lines(ctx.core(model, motion, ctx.config.settings("expression")))


@expression.command("restyle")
@click.argument("model", type=EXISTING)
@click.argument("motion", type=EXISTING)
@click.option("--to", "to", default=None, help="The target emotion (one the model was fitted with).")
@click.option("--emotions", type=EXISTING, default=None,
              help="Emotion spans over time instead of --to: 'start_s end_s emotion' lines, or a TextGrid tier 'emotions'.")
@click.option("--intensity", type=float, default=1.0, show_default=True, help="Eq. 7 blend, 0 (unchanged) to 1.")
@click.option("-o", "--output", type=PATH, required=True, help="Output motion.h5.")
@stage
def expression_restyle(ctx: Context, model: Path, motion: Path, to, emotions, intensity: float, output: Path):
    """Re-synthesize marker motion (captured or synthesized) in another expression (equation 7).

    Frames outside every --emotions span keep their own expression. The output is a motion
    artifact: deform, render and evaluate take it as they take a synthesis.

    \b
    Example:
      facesynth expression fit normalized.h5 -o expr.h5
      facesynth expression restyle expr.h5 motion.h5 --to happy --intensity 0.6 -o happy.h5
      echo "0.5 1.5 angry" > spans.txt
      facesynth expression restyle expr.h5 motion.h5 --emotions spans.txt --intensity 1 -o angry.h5
    """
    if (to is None) == (emotions is None):
        raise UsageError("give exactly one of --to or --emotions.")
    s = ctx.core(model, motion, output, ctx.config.settings("expression"), ctx.config.settings("ingest"), to=to,
                      intensity=intensity, emotions_path=emotions, overwrite=ctx.overwrite)
    ctx.say(f"restyled {s.frames} frames (mostly {s.from_emotion} before) to {to or emotions} at intensity {intensity:g}; "
            f"RMS marker change {s.change_mm:.2f} mm -> {output}")


@main.command("head-motion")
@click.argument("db", type=EXISTING)
@click.option("--audio", type=EXISTING, required=True,
              help="The speech to move the head to (any sound file or video with sound).")
@click.option("--corpus", "corpus_path", type=EXISTING, required=True,
              help="The corpus artifact (ingest's) the database was built from: it holds every take's audio.")
@click.option("-o", "--output", type=PATH, required=True, help="Output head.h5.")
@stage
def head_motion(ctx: Context, db: Path, audio: Path, corpus_path: Path, output: Path):
    """Head motion for new speech from captured segments matched by pitch (Chuang & Bregler 2005 §5).

    The training takes' audio comes from the corpus artifact (ingest stores every take's
    samples); pitch is pYIN's (librosa). An utterance without voiced speech gets the rest pose
    and a warning.

    \b
    Example:
      facesynth head-motion db.h5 --corpus corpus.h5 --audio corpus/audio/neutral_s016.wav -o head.h5
      facesynth synthesize db.h5 --phonemes corpus/labels/neutral_s016.TextGrid --head-motion head.h5 -o moving.h5
      facesynth deform moving.h5 --mesh corpus/face.obj --binding corpus/markers.csv \\
          --set deform.apply_head_motion=true -o moving_anim.h5
    """
    s = ctx.core(db, corpus_path, audio, output, ctx.config.settings("head_motion"), ctx.overwrite)
    for warning in s.warnings:
        ctx.say(f"warning: {warning}")
    ctx.say(f"head motion for {s.seconds:.2f} s from {s.segments} pitch segments ({s.consecutive} joins "
            f"kept consecutive), pitch of {s.library_takes} takes in {s.pitch_s:.1f} s -> {output}")


@main.command()
@click.argument("db_path", metavar="DB", type=EXISTING)
@click.option("--audio", type=PATH, default="-", show_default=True,
              help="A sound file or video with sound (any format and rate, decoded and resampled to 16 kHz; .pcm "
                   "or .raw: raw 16-bit PCM at 16 kHz); '-' reads standard input: a 16 kHz mono 16-bit WAV or raw "
                   "PCM.")
@click.option("--serve", default=None, metavar="HOST:PORT", help="Serve WebSocket clients instead (e.g. 127.0.0.1:8765).")
@click.option("--livelink", default=None, metavar="HOST:PORT", help="Also send Live Link Face UDP packets (port 11111).")
@click.option("--method", type=RegistryChoice(METHODS, lambda e: bool(e.facts.get("streams"))), default=None,
              help="The member streamed, one with a live form (default: stream.method).")
@click.option("--lookahead", type=int, default=None, help="Phones of look-ahead (default: stream.lookahead_phones).")
@click.option("--markers", is_flag=True, help="Add the markers (mm) to every frame.")
@click.option("--realtime", is_flag=True, help="Read --audio at its own speed, as if it arrived live.")
@click.option("--workers", type=int, default=1, show_default=True, help="With --serve: processes sharing the port.")
@stage(writes=False)
def stream(ctx: Context, db_path: Path, audio: str, serve: str | None, livelink: str | None, method: str | None,
           lookahead: int | None, markers: bool, realtime: bool, workers: int):
    """Live synthesis: audio in as it arrives, frames of ARKit curves out with a fixed latency
    (JSON lines on standard output, or WebSocket messages), never revised (docs/live.md). From a
    voice alone each frame goes out once its audio and 46 ms more have arrived, the mouth the
    voice's articulation (stream.voice); with phones given by a TTS engine, the motion nodes are
    chosen with a bounded look-ahead. DB is the motion database, or with --method trajectory a
    trajectory model (fit-method trajectory).
    With --serve it serves WebSocket clients until Ctrl-C or SIGTERM, e.g.
    `facesynth stream db.h5 --serve 127.0.0.1:8765 --livelink 127.0.0.1:11111`.

    \b
    Example:
      facesynth stream db.h5 --audio corpus/audio/neutral_s016.wav > frames.jsonl
    """
    from facesynth.domain.methods import MethodSettings
    c = ctx.config
    model = ctx.stage_module.load_model(db_path, MethodSettings.of(c), c.settings("stream"), c.settings("solve"), method, lookahead)
    if serve is not None:
        ctx.stage_module.serve(model, c.settings("align"), serve, livelink=livelink, ready=ctx.say, workers=workers)
        ctx.say("stopped.")
        return
    frames = ctx.core(model, c.settings("align"), audio, click.echo, livelink=livelink, markers=markers,
                       realtime=realtime)
    ctx.detail(f"{frames} frames")


@main.command()
@click.argument("db_path", metavar="DB", type=EXISTING)
@click.option("--remove", default=None, help="Node ids to remove: '3,5,10-12'.")
@click.option("--auto", is_flag=True, help="Find contaminated nodes (spikes, swapped markers, cluster outliers).")
@click.option("--reason", default="removed by hand", show_default=True, help="Why, recorded with --remove.")
@click.option("-o", "--output", type=PATH, required=True, help="Output db.h5 (the input is never changed).")
@stage
def prune(ctx: Context, db_path: Path, remove: str | None, auto: bool, reason: str, output: Path):
    """Remove contaminated motion nodes into a new database (paper V).

    \b
    Example:
      facesynth prune db.h5 --auto -o db_clean.h5
      facesynth prune db.h5 --remove 12,40-42 --reason "lip marker swap" -o db_hand.h5
    """
    s = ctx.core(db_path, output, ctx.config.settings("prune"), remove, auto, reason, ctx.overwrite)
    if not s.removed:
        ctx.say("nothing to remove; no output written.")
        return
    if auto:
        ctx.say("found " + ", ".join(f"{v} {k}" for k, v in ctx.stage_module.count_by_kind(s.found).items()))
        ctx.detail("removed: " + ",".join(str(i) for i in s.found))
    ctx.say(f"removed {s.removed} nodes, kept {s.kept} ({s.links_cut} captured links cut) -> {output}")


@main.command()
@stage(writes=False)
def devices(ctx: Context):
    """List every OpenCL platform and device, whether facesynth's kernels build on it, and
    which one it uses (PYOPENCL_CTX=PLATFORM:DEVICE chooses another).

    \b
    Example:
      facesynth devices
    """
    from facesynth.base.opencl import describe_devices

    for line in describe_devices():
        click.echo(line)


@main.command()
@click.argument("files", metavar="FILE...", nargs=-1, required=True, type=PATH)
@stage(writes=False)
def check(ctx: Context, files: tuple[Path, ...]):
    """Validate artifacts against docs/file-format.md: kind, schema, every group and dataset
    (dtype, shape, units, fps, encoding-type), no links or data outside the file, finite
    numbers, and inputs that still exist with the recorded sha256 (relative paths from the
    current directory). Prints one line per problem, or 'FILE: ok (kind, schema N)'.

    \b
    Example:
      facesynth check corpus.h5 db.h5 motion.h5
    """
    from facesynth.model.check import check_files

    reports = check_files(files)
    for report in reports:
        if not (report.ok and ctx.quiet):
            click.echo("\n".join(report.lines()))
    bad = [r for r in reports if not r.ok]
    if bad:
        n = sum(len(r.problems) for r in bad)
        raise FacesynthError(f"{n} problem{'s' * (n > 1)} in {len(bad)} of {len(reports)} file{'s' * (len(reports) > 1)}.")


def run() -> None:
    """The ``facesynth`` console script: :func:`main`, then a quick exit. Once the command has
    finished (outputs written and closed, Python's exit handlers run, the streams flushed),
    the interpreter's own teardown (freeing every module, the OpenCL driver's destructors)
    only costs time, about 0.15 s after an OpenCL command, so the process ends there with the
    command's exit status."""
    import atexit
    import os

    try:
        main(obj=PROGRAM)
        code = 0
    except SystemExit as exc:
        code = exc.code
    if code is None:
        code = 0
    elif not isinstance(code, int):
        print(code, file=sys.stderr)
        code = 1
    atexit._run_exitfuncs()
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(OSError, ValueError):
            stream.flush()
    os._exit(code)


if __name__ == "__main__":  # pragma: no cover
    run()
