"""The examples of facesynth's ``--help`` texts and the README's shell block, and running them as
a user would: what tests/test_examples.py checks, and what the ``chain`` fixture of
tests/conftest.py builds. The top-level help's example and the README's block are one chain (the
whole pipeline on the ``small`` sample corpus, its video, and audio alone): the chain runs the
README's block as written, with bash, and a test holds the two to the same commands."""

from __future__ import annotations

import os
import re
import shlex
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

import click
from click.testing import CliRunner

from facesynth.cli import main

ROOT = Path(__file__).resolve().parents[1]
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


def readme_block() -> str:
    """The README's shell block that runs the pipeline (the one that sets ``fs``)."""
    blocks = re.findall(r"```sh\n(.*?)```", (ROOT / "README.md").read_text(), flags=re.S)
    [block] = [b for b in blocks if re.search(r"^fs=", b, flags=re.M)]
    return block


def facesynth_launcher(path: Path) -> Path:
    """An executable ``path`` that runs this installation's ``facesynth`` (what ``pip install``
    puts in ``.venv/bin``)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(f"#!/bin/sh\nexec {shlex.quote(sys.executable)} -c "
                    "'import sys; sys.argv[0] = \"facesynth\"; from facesynth.cli import run; run()' \"$@\"\n")
    path.chmod(0o755)
    return path


def run_bash(script: str, folder: Path, path_first: Path | None = None, timeout_s: float = 1200):
    """Run ``script`` with ``bash -euo pipefail`` in ``folder`` (``path_first`` ahead on the
    PATH), in a session of its own whose processes left behind (a server started with ``&``)
    are ended when it returns."""
    env = dict(os.environ)
    if path_first is not None:
        env["PATH"] = f"{path_first}{os.pathsep}{env.get('PATH', '')}"
    # files, not pipes: a process left in the background keeps a pipe open after bash ends
    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        process = subprocess.Popen(["bash", "-euo", "pipefail", "-x", "-c", script], cwd=folder, env=env,
                                   stdout=out, stderr=err, text=True, start_new_session=True)
        try:
            process.wait(timeout=timeout_s)
        finally:
            try:
                os.killpg(process.pid, signal.SIGTERM)
            except ProcessLookupError:
                pass
            if process.poll() is None:
                process.kill()
                process.wait()
        out.seek(0)
        err.seek(0)
        return subprocess.CompletedProcess(process.args, process.returncode, out.read(), err.read())


def readme_commands() -> list[list[str]]:
    """The command lines of the README's block as the top-level help writes them, as words:
    its ``$fs ...`` and ``echo ...`` lines without their comments, ``$fs`` as ``facesynth``."""
    out = []
    for line in readme_block().splitlines():
        words = shlex.split(line, comments=True)
        if words[:1] == ["$fs"]:
            words[0] = "facesynth"
        if words[:1] in (["facesynth"], ["echo"]):
            out.append(words)
    return out


def run_readme(folder: Path) -> None:
    """Run the README's block as written, with bash, in the empty ``folder`` (its first line's
    ``.venv/bin/facesynth`` there runs this installation); it works in ``folder/out/example``."""
    facesynth_launcher(folder / ".venv" / "bin" / "facesynth")
    done = run_bash(readme_block(), folder)
    assert done.returncode == 0, done.stderr[-4000:]
