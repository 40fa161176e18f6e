"""The examples of facesynth's ``--help`` texts, and running their lines as a user would: what
tests/test_examples.py checks, and what the ``chain`` fixture of tests/conftest.py builds (the
top-level help's example, the whole chain on the ``small`` sample corpus)."""

from __future__ import annotations

import os
import shlex
from pathlib import Path

import click
from click.testing import CliRunner

from facesynth.cli import main

#: Options whose value is a file or folder the command writes.
OUTPUT_OPTIONS = {"-o", "--output", "--images"}


def command_paths(group: click.Group = main, path: tuple[str, ...] = ()):
    """Every command path below ``group``, the group's own first: ('isomap', 'pick'), ..."""
    yield path, group
    if isinstance(group, click.Group):
        for name in group.list_commands(click.Context(group)):
            yield from command_paths(group.commands[name], path + (name,))


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


HELP = {" ".join(path) or "facesynth": examples(help_text(path)) for path, _ in command_paths()}


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


def run_chain(folder: Path) -> None:
    """Run the top-level help's example (sample corpus to video) in the empty ``folder``."""
    for line in HELP["facesynth"]:
        run_line(line, folder)
