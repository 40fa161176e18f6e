"""The ``facesynth`` command line: thin click commands that parse, load settings, call a
stage and map user errors to one line and exit status 1."""

from __future__ import annotations

import functools
import sys
import time
from pathlib import Path

import click

from . import __version__
from .config import Config
from .errors import FacesynthError
from .progress import set_quiet

PATH = click.Path(path_type=Path)
EXISTING = click.Path(path_type=Path, dir_okay=False)


class Context:
    def __init__(self, config: Config, verbose: int, quiet: bool, overwrite: bool):
        self.config, self.verbose, self.quiet, self.overwrite = config, verbose, quiet, overwrite

    def say(self, message: str) -> None:
        if not self.quiet:
            click.echo(message, err=True)

    def detail(self, message: str) -> None:
        if self.verbose and not self.quiet:
            click.echo(message, err=True)


def stage(func):
    """Add the global options to a command and turn FacesynthError into exit status 1."""
    @click.option("--config", "config_path", type=EXISTING, default=None, help="TOML file overriding configs/default.toml.")
    @click.option("--set", "overrides", multiple=True, metavar="SECTION.KEY=VALUE", help="Override one setting (repeatable).")
    @click.option("-v", "--verbose", count=True, help="Say more.")
    @click.option("-q", "--quiet", is_flag=True, help="Say nothing but errors; no progress bars.")
    @click.option("--overwrite", is_flag=True, help="Replace existing outputs.")
    @functools.wraps(func)
    def wrapper(config_path, overrides, verbose, quiet, overwrite, **kwargs):
        set_quiet(quiet)
        started = time.perf_counter()
        try:
            ctx = Context(Config.load(config_path, tuple(overrides)), verbose, quiet, overwrite)
            func(ctx, **kwargs)
        except FacesynthError as exc:
            click.echo(f"error: {exc}", err=True)
            sys.exit(1)
        except KeyboardInterrupt:
            click.echo("interrupted; no output was written.", err=True)
            sys.exit(130)
        if verbose and not quiet:
            click.echo(f"done in {time.perf_counter() - started:.2f} s", err=True)
    return wrapper


@click.group(context_settings={"help_option_names": ["-h", "--help"], "max_content_width": 100})
@click.version_option(__version__, prog_name="facesynth")
def main():
    """Expressive, lip-synced 3D facial animation from a facial motion-capture database.

    \b
    The whole chain on the built-in corpus:
      facesynth sample-corpus corpus/ --preset small
      facesynth ingest corpus/manifest.csv -o corpus.h5
      facesynth normalize corpus.h5 -o normalized.h5
      facesynth pca normalized.h5 -o pca.h5
    """


@main.command("sample-corpus")
@click.argument("out_dir", type=PATH)
@click.option("--preset", type=click.Choice(["tiny", "small", "paper"]), default="small", show_default=True)
@click.option("--seed", type=int, default=0, show_default=True)
@stage
def sample_corpus_cmd(ctx: Context, out_dir: Path, preset: str, seed: int):
    """Write the built-in virtual-actress corpus (C3D, WAV, TextGrid, manifest, face mesh).

    \b
    Example:
      facesynth sample-corpus corpus/ --preset tiny --seed 0
    """
    from .corpus.generate import generate

    summary = generate(out_dir, preset, seed, overwrite=ctx.overwrite)
    ctx.say(f"wrote {summary['takes']} takes, {summary['seconds']:.1f} s of capture, "
            f"{summary['train_phones']} training phones, {summary['contamination_events']} contamination events to {out_dir}")


@main.command()
@click.argument("audio", type=EXISTING)
@click.option("--text", default=None, help="What is said.")
@click.option("--transcript", type=EXISTING, default=None, help="A file holding what is said.")
@click.option("--dict", "dict_path", type=EXISTING, default=None, help="Extra pronunciations: lines 'word  W ER D'.")
@click.option("-o", "--output", type=PATH, required=True, help="Output TextGrid.")
@stage
def align(ctx: Context, audio: Path, text: str | None, transcript: Path | None, dict_path: Path | None, output: Path):
    """Forced-align speech to its text; writes a phone TextGrid in the Festival phone set.

    \b
    Example:
      facesynth align corpus/audio/neutral_s000.wav --text "beautiful he men" -o s000.TextGrid
    """
    from .errors import InputError
    from .stages import align as stage_align

    if (text is None) == (transcript is None):
        raise InputError("give exactly one of --text or --transcript.")
    if transcript is not None:
        if not transcript.exists():
            raise InputError(f"{transcript}: transcript file not found.")
        text = transcript.read_text("utf-8")
    summary = stage_align.run(audio, text, output, ctx.config.settings("align"), dict_path, ctx.overwrite)
    ctx.say(f"aligned {summary['phones']} phones over {summary['seconds']:.2f} s -> {output}")


@main.command()
@click.argument("manifest", type=EXISTING)
@click.option("-o", "--output", type=PATH, required=True, help="Output corpus.h5.")
@stage
def ingest(ctx: Context, manifest: Path, output: Path):
    """Read a capture manifest (mocap, audio, alignments) into a corpus artifact.

    \b
    Example:
      facesynth ingest corpus/manifest.csv -o corpus.h5
    """
    from .stages import ingest as stage_ingest

    s = stage_ingest.run(manifest, output, ctx.config.settings("ingest"), ctx.overwrite)
    ctx.say(f"ingested {s['takes']} takes, {s['frames']} frames of {s['markers']} markers at {s['fps']:g} Hz, "
            f"{s['phones']} phone segments ({100 * s['missing_fraction']:.2f}% samples missing) -> {output}")


@main.command()
@click.argument("corpus", type=EXISTING)
@click.option("-o", "--output", type=PATH, required=True, help="Output normalized.h5.")
@stage
def normalize(ctx: Context, corpus: Path, output: Path):
    """Fill marker gaps and remove head motion (Eq. 1-2), keeping it as per-frame transforms.

    \b
    Example:
      facesynth normalize corpus.h5 -o normalized.h5
    """
    from .stages import normalize as stage_normalize

    s = stage_normalize.run(corpus, output, ctx.config.settings("normalize"), ctx.overwrite)
    for take, marker, start, length in s["long_gaps"]:
        ctx.say(f"warning: take {take!r}, marker {marker}: gap of {length:.3f} s at {start:.3f} s is too long to fill; "
                "PCA will project those frames from the visible markers.")
    ctx.say(f"normalized {s['frames']} frames (origin marker {s['origin_marker']}) -> {output}")


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
    from .stages import pca as stage_pca

    s = stage_pca.run(normalized, output, ctx.config.settings("pca"), ctx.overwrite)
    ctx.say(f"PCA: {s['components']} components cover {100 * s['explained']:.2f}% of the variance "
            f"(reconstruction RMS {s['rms_error_mm']:.3f} mm per marker) -> {output}")


if __name__ == "__main__":  # pragma: no cover
    main()
