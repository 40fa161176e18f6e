"""The batch script: a CSV with one dialogue line per row.

Columns (header names are case-insensitive; others are ignored):

- ``id`` (required): the line's name, used for its output files (letters, digits, ``. _ -``);
- ``audio`` (required): its speech (any sound file or video with sound that ffmpeg reads: WAV, FLAC, M4A, MP3, Opus, MP4, ...);
- ``text`` (optional): what is said (aligned with :func:`facesynth.domain.speech.alignment.align_robust`);
  a line without text (no such column, or an empty cell) is recognised from its audio
  (:mod:`facesynth.domain.speech.recognition`);
- ``alignment`` (optional): the line's phone timing (TextGrid or ``.lab``), used as is when
  given (before any text);
- ``emotion`` (optional): one emotion for the whole line (default ``neutral``), or
  ``emotions``: a per-phone emotion file (``start_s end_s emotion`` lines or a TextGrid tier);
- ``constraints`` (optional): a motion-node constraint file, as for ``synthesize``;
- ``language`` (optional): the line's language, a BCP-47 tag (``de``, ``fr``, ``cmn``...; an empty
  cell: ``align.language``), for its text (:mod:`facesynth.domain.speech.languages`) or, without a
  text, its audio (decoded as phones, not English words).

File paths are relative to the script's folder. A file that lacks the required columns is
refused before any work; a bad row (a missing file, an unknown emotion, a
duplicated or unusable id) fails only its line, with the reason in the summary.
"""

from __future__ import annotations

import csv
import re
from dataclasses import dataclass
from pathlib import Path

from facesynth.base.errors import InputError

REQUIRED = ("id", "audio")
OPTIONAL = ("text", "alignment", "emotion", "emotions", "constraints", "language")
_ID = re.compile(r"[A-Za-z0-9][A-Za-z0-9._-]{0,127}")


@dataclass(frozen=True)
class Line:
    """One row of the script, paths resolved against the script's folder.

    ``row`` is the 1-based line number in the CSV file (the header is row 1); ``problem`` is
    a reason known from the script alone (duplicated or unusable id) that fails the line.
    """

    id: str
    row: int
    audio: Path | None
    text: str | None
    alignment: Path | None
    emotion: str | None
    emotions: Path | None
    constraints: Path | None
    problem: str | None = None
    language: str | None = None

    @property
    def where(self) -> str:
        return f"line {self.id!r} (row {self.row})"


def read_script(path: Path) -> list[Line]:
    """The lines of the script at ``path``; raises InputError for a file that cannot be read as
    a CSV with the required columns (naming the missing ones)."""
    path = Path(path)
    if not path.is_file():
        raise InputError(f"{path}: script not found; give a CSV with columns id, audio (and text or alignment).")
    try:
        with open(path, newline="", encoding="utf-8-sig") as fh:
            rows = list(csv.reader(fh))
    except UnicodeDecodeError as exc:
        raise InputError(f"{path}: not UTF-8 text ({exc.reason} at byte {exc.start}); save the script as UTF-8 CSV.") from None
    except csv.Error as exc:
        raise InputError(f"{path}: not a readable CSV ({exc}); save it as comma-separated values.") from None
    if not rows:
        raise InputError(f"{path}: the script is empty; its first row must name the columns id, audio (and text).")
    header = [h.strip().lower() for h in rows[0]]
    missing = [c for c in REQUIRED if c not in header]
    if missing:
        raise InputError(f"{path}: the header lacks the column(s) {', '.join(missing)}; "
                         f"the first row must name id and audio, and text or alignment where known "
                         f"(found {', '.join(header) or 'none'}).")
    col = {name: header.index(name) for name in REQUIRED + OPTIONAL if name in header}
    base = path.parent
    lines: list[Line] = []
    seen: dict[str, int] = {}
    for number, raw in enumerate(rows[1:], 2):
        if not any(cell.strip() for cell in raw):
            continue

        def cell(name: str) -> str:
            k = col.get(name)
            return raw[k].strip() if k is not None and k < len(raw) else ""

        def file(name: str) -> Path | None:
            value = cell(name)
            return (base / value) if value else None

        line_id = cell("id")
        problem = None
        if not _ID.fullmatch(line_id):
            problem = (f"row {number}: id {line_id!r} is not usable as a file name; use letters, digits, '.', '_' "
                       "and '-' (at most 128, starting with a letter or digit).")
            line_id = line_id if line_id else f"row{number}"
        elif line_id in seen:
            problem = f"row {number}: id {line_id!r} is already used by row {seen[line_id]}; give every line its own id."
        else:
            seen[line_id] = number
        lines.append(Line(line_id, number, file("audio"), cell("text") or None, file("alignment"),
                          cell("emotion") or None, file("emotions"), file("constraints"), problem,
                          cell("language") or None))
    if not lines:
        raise InputError(f"{path}: the script has a header but no lines.")
    return lines
