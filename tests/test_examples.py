"""Examples are tests: every example in every ``--help`` and every line of the README's shell
block runs as written, so that a changed option breaks the build, not the user.

The top-level help's example (the whole chain on the ``small`` sample corpus) runs once per
session in an empty folder; it is the folder the top-level help promises every other command's
example runs in. Each command's example then runs in a fresh folder holding links to everything
that chain left, except the outputs the example writes. The README block runs with bash in an
empty folder of its own, with ``.venv/bin/facesynth`` (its first line) pointing at this
installation.
"""

from __future__ import annotations

import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

import click
import pytest
from click.testing import CliRunner

from facesynth.cli import main

ROOT = Path(__file__).resolve().parents[1]
#: Options whose value is a file or folder the command writes.
OUTPUT_OPTIONS = {"-o", "--output", "--images"}


def _commands(group: click.Group = main, path: tuple[str, ...] = ()):
    """Every command path below ``group``, the group's own first: ('isomap', 'pick'), ..."""
    yield path, group
    if isinstance(group, click.Group):
        for name in group.list_commands(click.Context(group)):
            yield from _commands(group.commands[name], path + (name,))


def help_text(path: tuple[str, ...]) -> str:
    """The ``--help`` output of a command, as a user sees it."""
    result = CliRunner().invoke(main, [*path, "--help"], prog_name="facesynth")
    assert result.exit_code == 0, result.output
    return result.output


def examples(text: str) -> list[str]:
    """The example lines of a help text: the indented lines after a line 'Example...:' up to
    the next blank line, with backslash continuations joined."""
    lines, out, inside = text.splitlines(), [], False
    for line in lines:
        stripped = line.strip()
        if stripped.startswith("Example") and stripped.endswith(":"):
            inside = True
        elif inside and not stripped:
            inside = False
        elif inside:
            if out and out[-1].endswith("\\"):
                out[-1] = out[-1][:-1].rstrip() + " " + stripped
            else:
                out.append(stripped)
    return out


HELP = {" ".join(path) or "facesynth": examples(help_text(path)) for path, _ in _commands()}


def outputs(line: str) -> list[str]:
    """The files and folders an example line writes (relative to the folder it runs in)."""
    words = shlex.split(line)
    out = [words[i + 1] for i, w in enumerate(words[:-1]) if w in OUTPUT_OPTIONS or w in (">", ">>")]
    if words[:2] == ["facesynth", "sample-corpus"]:
        out.append(words[2])
    return [w.rstrip("/") for w in out]


def run_line(line: str, folder: Path) -> None:
    """Run one example line in ``folder``: ``facesynth ARGS [> FILE]`` through click's CliRunner,
    or ``echo TEXT > FILE`` (``>> FILE`` appends); anything else is an error, so examples stay
    within what runs here."""
    words = shlex.split(line)
    target, append = None, False
    if len(words) >= 2 and words[-2] in (">", ">>"):
        words, target, append = words[:-2], folder / words[-1], words[-2] == ">>"
    if words[0] == "echo" and target is not None:
        with open(target, "a" if append else "w") as fh:
            fh.write(" ".join(words[1:]) + "\n")
        return
    assert words[0] == "facesynth", f"an example line this test cannot run: {line!r}"
    cwd = os.getcwd()
    os.chdir(folder)
    try:
        result = CliRunner().invoke(main, words[1:], prog_name="facesynth", catch_exceptions=False)
    finally:
        os.chdir(cwd)
    assert result.exit_code == 0, f"{line}\n{result.output}"
    if target is not None:
        target.write_text(result.stdout)


@pytest.fixture(scope="session")
def chain(built_once) -> Path:
    """The folder where the top-level help's example (the whole chain on the small corpus) ran."""

    def build(folder: Path) -> None:
        for line in HELP["facesynth"]:
            run_line(line, folder)

    return built_once("chain", build)


def test_every_help_has_an_example():
    missing = [name for name, lines in HELP.items() if not lines]
    assert not missing


def test_the_whole_chain_goes_from_corpus_to_video(chain):
    steps = [shlex.split(line)[1] for line in HELP["facesynth"]]
    assert steps[0] == "sample-corpus" and steps[-1] == "render"
    assert (chain / "neutral_s016.avi").stat().st_size > 0


@pytest.mark.parametrize("name", [name for name in HELP if name != "facesynth"])
def test_help_example_runs(name, chain, tmp_path):
    lines = HELP[name]
    written = {w for line in lines for w in outputs(line)}
    for entry in chain.iterdir():
        if entry.name not in written:
            (tmp_path / entry.name).symlink_to(entry, target_is_directory=entry.is_dir())
    for line in lines:
        run_line(line, tmp_path)


def test_short_help_is_never_cut_mid_sentence():
    """Click ends a command's one-line summary at the first word ending in '.' (such as
    'Eq.'), so the first sentence of every help must be whole."""
    for path, command in _commands():
        summary = command.get_short_help_str(limit=1000)
        whole = summary.endswith((".", ")")) and not re.search(r"\b(Eqs?|Figs?|Tab)\.$", summary)
        assert whole and summary.count("(") == summary.count(")"), (path, summary)


def test_top_level_help_lists_commands_in_pipeline_order():
    listed = re.findall(r"^  (\S+)  ", help_text(()).split("Commands:")[1], flags=re.M)
    assert listed[:6] == ["sample-corpus", "align", "ingest", "normalize", "pca", "build-db"]
    assert listed.index("synthesize") < listed.index("deform") < listed.index("render") < listed.index("evaluate")
    assert sorted(listed) == sorted(main.commands)


def readme_block() -> str:
    """The README's shell block that runs the pipeline (the one that sets ``fs``)."""
    blocks = re.findall(r"```sh\n(.*?)```", (ROOT / "README.md").read_text(), flags=re.S)
    [block] = [b for b in blocks if re.search(r"^fs=", b, flags=re.M)]
    return block


def test_readme_block_runs(tmp_path):
    block = readme_block()
    launcher = tmp_path / ".venv" / "bin" / "facesynth"
    launcher.parent.mkdir(parents=True)
    launcher.write_text(f"#!/bin/sh\nexec {shlex.quote(sys.executable)} -c "
                        "'from facesynth.cli import main; main(prog_name=\"facesynth\")' \"$@\"\n")
    launcher.chmod(0o755)
    done = subprocess.run(["bash", "-euo", "pipefail", "-x", "-c", block], cwd=tmp_path, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr[-4000:]
    commands = [line for line in block.splitlines() if line.lstrip().startswith("$fs ")]
    assert len(commands) >= 20 and (tmp_path / "compare.avi").stat().st_size > 0


def test_isomap_pick_takes_negative_coordinates(tiny_db, tmp_path):
    isomap = tmp_path / "isomap.h5"  # the options are tested, so the tiny corpus's maps do
    run_line(f"facesynth isomap {tiny_db} -o {isomap} -q", tmp_path)
    for args in (["-0.5", "-1.2"], ["0.5", "-1.2", "--pca-map"], ["--pca-map", "-0.5", "1.2"], ["-1e-1", "-.2"]):
        r = CliRunner().invoke(main, ["isomap", "pick", str(isomap), "aa", *args])
        assert r.exit_code == 0 and r.stdout.startswith("marker,x_mm"), (args, r.output)
    r = CliRunner().invoke(main, ["isomap", "pick", str(isomap), "aa", "0.5", "--bogus"])
    assert r.exit_code == 2 and "'--bogus' is not a valid float" in r.output


def test_db_show_takes_any_phone_label_and_a_closed_pipe(chain):
    db = chain / "db.h5"
    lower = CliRunner().invoke(main, ["db", "show", str(db), "--phoneme", "zh"])
    for label in ("ZH", "zh"):
        r = CliRunner().invoke(main, ["db", "show", str(db), "--phoneme", label])
        assert r.exit_code == 0 and r.stdout == lower.stdout and "\tzh\t" in r.stdout
    r = CliRunner().invoke(main, ["db", "show", str(db), "--phoneme", "q"])
    assert r.exit_code == 1 and "--phoneme 'q': unknown phone" in r.output
    shown = subprocess.run(f"{shlex.quote(sys.executable)} -c 'from facesynth.cli import main; main()' "
                           f"db show {shlex.quote(str(db))} | head -1; exit ${{PIPESTATUS[0]}}",
                           shell=True, executable="/bin/bash", capture_output=True, text=True)
    assert shown.returncode == 0 and shown.stdout.startswith("id\t") and not shown.stderr, shown.stderr
