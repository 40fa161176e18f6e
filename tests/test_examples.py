"""Examples are tests: every example in every ``--help``, every line of the README's shell
block and every shell block of ``docs/*.md`` runs as written, so that a changed option breaks
the build, not the user.

The README's block (the whole chain on the ``small`` sample corpus, then audio alone) runs once
per session with bash in an empty folder of its own, with ``.venv/bin/facesynth`` (its first
line) pointing at this installation: the ``chain`` fixture of conftest.py. The top-level help's
example is the same commands (a test holds them together), and the folder the chain leaves is
the one the top-level help promises every other command's example runs in: each command's
example runs in a fresh folder holding links to everything that chain left, except the outputs
the example writes.

The shell blocks of a page of ``docs/`` (fenced ``sh``, ``bash`` or ``console``) run with bash,
in order, in one such linked folder per page, with ``facesynth`` on the ``PATH``. A block that
cannot run here says so in an HTML comment on the line before it, ``<!-- not run: REASON -->``
(the reason is reported); a block that needs an optional extra names the module it imports,
``<!-- needs: MODULE (EXTRA) -->``, and runs where that module is installed (CI installs them);
every other block runs. Links between the README and the pages of
``docs/`` must resolve, anchors included.
"""

from __future__ import annotations

import importlib.util
import re
import shlex
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest
from click.testing import CliRunner
from help_examples import (
    HELP,
    ROOT,
    command_paths,
    facesynth_launcher,
    help_text,
    outputs,
    readme_commands,
    run_bash,
    run_line,
)

from facesynth.cli import main


def test_every_help_has_an_example():
    missing = [name for name, lines in HELP.items() if not lines]
    assert not missing


def test_the_top_level_help_and_the_readme_show_the_same_chain():
    """One chain in two places, run once (the ``chain`` fixture runs the README's block)."""
    assert [shlex.split(line) for line in HELP["facesynth"]] == readme_commands()


def test_the_readme_block_goes_from_corpus_to_video_and_from_audio_alone(chain):
    steps = [words[1] for words in readme_commands() if words[0] == "facesynth"]
    assert steps[0] == "sample-corpus"
    assert {"ingest", "normalize", "pca", "build-db", "synthesize", "solve", "render"} <= set(steps)
    assert (chain / "neutral_s016.avi").stat().st_size > 0
    assert (chain / "heard.h5").stat().st_size > 0  # audio alone


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
    for path, command in command_paths():
        summary = command.get_short_help_str(limit=1000)
        whole = summary.endswith((".", ")")) and not re.search(r"\b(Eqs?|Figs?|Tab)\.$", summary)
        assert whole and summary.count("(") == summary.count(")"), (path, summary)


def test_top_level_help_lists_commands_in_pipeline_order():
    listed = re.findall(r"^  (\S+)  ", help_text(()).split("Commands:")[1], flags=re.M)
    assert listed[:6] == ["sample-corpus", "align", "ingest", "normalize", "pca", "build-db"]
    assert listed.index("synthesize") < listed.index("deform") < listed.index("render") < listed.index("evaluate")
    assert sorted(listed) == sorted(main.commands)


# --- the shell blocks of docs/ -------------------------------------------------------------

DOCS = ROOT / "docs"
SHELL_LANGUAGES = ("sh", "bash", "console")
NOT_RUN = re.compile(r"^<!--\s*not run:\s*(?P<reason>.*?)\s*-->$")
NEEDS = re.compile(r"^<!--\s*needs:\s*(?P<module>[\w.]+)\s*\((?P<extra>[^)]*)\)\s*-->$")


@dataclass(frozen=True)
class Block:
    """A fenced code block of a Markdown page: its language tag ('' for none), its text
    (dedented to the fence), the line of its opening fence, and the reason given before it
    for not running it (None: it runs), or the module of an optional extra it needs (None: none).
    """

    page: Path
    line: int
    language: str
    text: str
    not_run: str | None
    needs: str | None = None

    def runs_here(self) -> bool:
        """Not marked ``not run``, and the module it needs (if any) is installed."""
        return self.not_run is None and (self.needs is None or importlib.util.find_spec(self.needs) is not None)

    @property
    def where(self) -> str:
        return f"{self.page.relative_to(ROOT)}:{self.line}"

    def script(self) -> str:
        """The shell commands: the block itself, or a console block's ``$ `` lines."""
        if self.language != "console":
            return self.text
        return "".join(line[2:] + "\n" for line in self.text.splitlines() if line.startswith("$ "))


def fenced_blocks(page: Path) -> list[Block]:
    """Every fenced code block of ``page``, in order (fences may be indented, as in a list)."""
    lines, blocks, i = page.read_text(encoding="utf-8").splitlines(), [], 0
    while i < len(lines):
        opening = re.match(r"^(\s*)```\s*([\w-]*)\s*$", lines[i])
        if not opening:
            i += 1
            continue
        indent, language = opening.group(1), opening.group(2).lower()
        before = next((line.strip() for line in reversed(lines[:i]) if line.strip()), "")
        reason = NOT_RUN.match(before)
        needs = NEEDS.match(before)
        body, j = [], i + 1
        while j < len(lines) and lines[j].strip() != "```":
            body.append(lines[j][len(indent):] if lines[j].startswith(indent) else lines[j].lstrip())
            j += 1
        assert j < len(lines), f"{page.relative_to(ROOT)}:{i + 1}: a code block that is never closed"
        blocks.append(Block(page, i + 1, language, "".join(line + "\n" for line in body),
                            reason.group("reason") if reason else None, needs.group("module") if needs else None))
        i = j + 1
    return blocks


def doc_pages() -> list[Path]:
    return sorted(DOCS.glob("*.md"))


def shell_blocks(page: Path) -> list[Block]:
    return [b for b in fenced_blocks(page) if b.language in SHELL_LANGUAGES]


def test_every_not_run_mark_gives_its_reason_and_stands_before_a_shell_block():
    for page in [ROOT / "README.md", *doc_pages()]:
        text = page.read_text(encoding="utf-8")
        marks = [m for m in re.finditer(r"<!--\s*not run\b[^>]*-->", text)]
        marked = [b for b in fenced_blocks(page) if b.not_run is not None]
        assert len(marks) == len(marked), f"{page.name}: a '<!-- not run: ... -->' that is not on the line before a block"
        for block in marked:
            assert block.language in SHELL_LANGUAGES, f"{block.where}: 'not run' marks a block that is not a shell block"
            assert len(block.not_run.split()) >= 3, f"{block.where}: say why the block cannot run here"


def test_no_command_hides_in_an_untagged_block():
    """A block holding facesynth command lines is tagged ``sh`` (so it runs) or another
    language; an untagged one would escape this test."""
    for page in [ROOT / "README.md", *doc_pages()]:
        for block in fenced_blocks(page):
            if block.language == "":
                commands = [line for line in block.text.splitlines() if re.match(r"^\s*(\$ )?facesynth\s", line)]
                assert not commands, f"{block.where}: tag this block ```sh (it then runs as a test): {commands[0]!r}"


def _tree(folder: Path) -> dict[str, tuple[int, int]]:
    return {str(p.relative_to(folder)): (p.stat().st_size, p.stat().st_mtime_ns)
            for p in sorted(folder.rglob("*")) if p.is_file()}


def _written(blocks: list[Block]) -> set[str]:
    """The files and folders the blocks' facesynth lines write (shell syntax aside)."""
    written = set()
    for block in blocks:
        for line in block.script().splitlines():
            try:
                words = shlex.split(line, comments=True)
            except ValueError:
                continue
            if words[:1] == ["facesynth"]:
                written.update(outputs(shlex.join(words)))
    return written


@pytest.mark.parametrize("page", [p.name for p in doc_pages() if any(b.not_run is None for b in shell_blocks(p))])
def test_doc_blocks_run(page, chain, tmp_path):
    """The page's shell blocks, in order, in one folder linked to what the chain left."""
    blocks = shell_blocks(DOCS / page)
    runnable = [b for b in blocks if b.runs_here()]
    folder = tmp_path / "work"
    folder.mkdir()
    written = _written(runnable)
    for entry in chain.iterdir():
        if entry.name not in written:
            (folder / entry.name).symlink_to(entry, target_is_directory=entry.is_dir())
    launcher = facesynth_launcher(tmp_path / "bin" / "facesynth")
    before = _tree(chain)
    for block in runnable:
        done = run_bash(block.script(), folder, path_first=launcher.parent)
        assert done.returncode == 0, f"{block.where}\n{block.script()}\n{done.stderr[-4000:]}"
    assert _tree(chain) == before, f"{page}: a block wrote into the shared chain folder (write to new names instead)"


# --- links ----------------------------------------------------------------------------------

def _anchors(page: Path) -> set[str]:
    """The anchors GitHub gives the page's headings."""
    anchors = set()
    for heading in re.findall(r"^#{1,6}\s+(.*?)\s*#*\s*$", page.read_text(encoding="utf-8"), flags=re.M):
        slug = re.sub(r"[^\w\- ]", "", heading.lower().replace("`", "")).replace(" ", "-")
        anchors.add(slug)
    return anchors


def test_links_between_readme_and_docs_resolve():
    broken = []
    for page in [ROOT / "README.md", *doc_pages()]:
        text = re.sub(r"```.*?```", "", page.read_text(encoding="utf-8"), flags=re.S)
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            if re.match(r"^[a-z]+:", target):
                continue
            file, _, anchor = target.partition("#")
            linked = (page.parent / file).resolve() if file else page
            if not linked.exists():
                broken.append(f"{page.name}: {target} (no such file)")
            elif anchor and linked.suffix == ".md" and anchor not in _anchors(linked):
                broken.append(f"{page.name}: {target} (no such heading)")
    assert not broken


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
