"""The Python examples of ``docs/api.md`` run as written: every ```python block, in order, in one
namespace (as one session at a Python prompt), in a folder laid out as the README's example
leaves it: ``db.h5`` and ``corpus/``, and ``traj.h5``, a trajectory model fitted there.

The folder is made of the tiny sample corpus's session fixtures (built once for the whole test
session): its database, its trajectory model, and its corpus, in which the small corpus's held-out
sentence the examples name, ``neutral_s016``, is the tiny corpus's held-out sentence (its phone
timing and audio linked under that name)."""

from __future__ import annotations

import logging
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "api.md"
#: The held-out sentence of the small corpus, which the README and the examples name.
SENTENCE = "neutral_s016"


def python_blocks(page: Path) -> list[tuple[int, str]]:
    """(line of the opening fence, code) of every ```python block of ``page``."""
    lines, blocks, i = page.read_text(encoding="utf-8").splitlines(), [], 0
    while i < len(lines):
        if re.match(r"^```python\s*$", lines[i]):
            j = i + 1
            while j < len(lines) and lines[j].strip() != "```":
                j += 1
            assert j < len(lines), f"{page.name}:{i + 1}: a code block that is never closed"
            blocks.append((i + 1, "\n".join(lines[i + 1:j]) + "\n"))
            i = j
        i += 1
    return blocks


@pytest.fixture
def readme_folder(tiny_db, tiny_trajectory, tiny_corpus, held_out_take, tmp_path) -> Path:
    """A folder with what the examples read, linked to the session's tiny artifacts."""
    folder = tmp_path / "example"
    corpus = folder / "corpus"
    corpus.mkdir(parents=True)
    (folder / "db.h5").symlink_to(tiny_db)
    (folder / "traj.h5").symlink_to(tiny_trajectory)
    for entry in tiny_corpus.iterdir():
        if entry.name in ("labels", "audio"):
            (corpus / entry.name).mkdir()
            for f in entry.iterdir():
                (corpus / entry.name / f.name).symlink_to(f)
        else:
            (corpus / entry.name).symlink_to(entry, target_is_directory=entry.is_dir())
    for sub, suffix in (("labels", ".TextGrid"), ("audio", ".wav")):
        (corpus / sub / f"{SENTENCE}{suffix}").symlink_to(tiny_corpus / sub / f"{held_out_take}{suffix}")
    return folder


def test_the_page_has_examples():
    blocks = python_blocks(PAGE)
    assert len(blocks) >= 5 and all("facesynth." in code for _, code in blocks)


def test_the_examples_run(readme_folder, monkeypatch, capsys):
    monkeypatch.chdir(readme_folder)
    namespace: dict = {"__name__": "__docs__"}
    logger = logging.getLogger("facesynth")
    level = logger.level
    try:
        for line, code in python_blocks(PAGE):
            try:
                exec(compile(code, f"{PAGE.relative_to(ROOT)}:{line}", "exec"), namespace)
            except Exception as exc:
                raise AssertionError(f"docs/api.md, the block at line {line} failed: {exc!r}\n{code}") from exc
    finally:
        logger.setLevel(level)
    printed = capsys.readouterr().out
    # what the comments of the last block say it prints (the numbers before depend on the corpus)
    assert printed.splitlines()[-3:] == ["60.0", "the dp method reads a motion database; a trajectory model was given.",
                                         "the phones given, 0.200 s: segment 'hh' ends at or before it starts."]
    for written in ("api_motion.h5", "api_curves.h5", "api_face.glb", "api_face.wav", "api_face.csv", "api_files.h5"):
        assert (readme_folder / written).stat().st_size > 0, written
