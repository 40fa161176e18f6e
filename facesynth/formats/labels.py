"""Time-aligned labels: Praat TextGrid (long and short text formats) and .lab files.

``.lab`` covers HTK (``start end label`` in 100 ns units, or the same three fields in seconds:
told apart from the values by :func:`lab_time_unit`, which is logged; an HTS full-context label
``p1^p2-p3+p4=p5...`` stands for its centre phone p3) and Festival/xwaves
(a header ending in ``#``, then ``end_time colour label`` in seconds).
"""

from __future__ import annotations

import logging
import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

from facesynth.base import limits
from facesynth.base.errors import InputError

_TOKEN = re.compile(r'"((?:[^"]|"")*)"|(<exists>)|([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)')
_EPS = 1e-6
#: The centre phone of an HTS full-context label, ``p1^p2-p3+p4=p5@...``.
_HTS_CENTRE = re.compile(r"^[^\^\s]*\^[^-\s]*-([^+\s]+)\+[^=\s]*=")
log = logging.getLogger(__name__)


@dataclass(frozen=True)
class Segment:
    """One labelled interval, times in seconds."""

    start: float
    end: float
    label: str


def _decode(raw: bytes) -> str:
    if raw.startswith(b"\xff\xfe") or raw.startswith(b"\xfe\xff"):
        return raw.decode("utf-16")
    return raw.decode("utf-8-sig", errors="replace")


def read_text(path: Path, what: str) -> str:
    """A UTF-8 text file (``what`` it is, for the message: 'emotion file'), or InputError naming
    the line and byte that are not UTF-8."""
    raw = Path(path).read_bytes()
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = raw.count(b"\n", 0, exc.start) + 1
        raise InputError(f"{path}, line {line}: byte {exc.start} is not UTF-8 text; save the {what} as UTF-8.") from None


def read_textgrid(path: Path) -> dict[str, list[Segment]]:
    """All interval tiers of a TextGrid: tier name -> segments (point tiers are skipped)."""
    path = Path(path)
    if not path.exists():
        raise InputError(f"{path}: alignment file not found; check the path.")
    text = _decode(path.read_bytes())
    if "TextGrid" not in text[:200]:
        raise InputError(f"{path}: not a Praat TextGrid (no 'TextGrid' header).")
    text = re.sub(r"\[\s*\d*\s*\]", "", text)  # long format's "item [1]:" and "intervals [3]:"
    tokens = []
    for m in _TOKEN.finditer(text):
        if m.group(1) is not None:
            tokens.append(m.group(1).replace('""', '"'))
        elif m.group(2):
            tokens.append("<exists>")
        else:
            tokens.append(float(m.group(3)))
    try:
        pos = tokens.index("TextGrid") + 1
        pos += 2  # xmin, xmax
        if tokens[pos] != "<exists>":
            return {}
        n_tiers = int(tokens[pos + 1])
        pos += 2
        tiers: dict[str, list[Segment]] = {}
        for _ in range(n_tiers):
            kind, name = tokens[pos], tokens[pos + 1]
            n_items = int(tokens[pos + 4])
            pos += 5
            if kind == "IntervalTier":
                segs = []
                for _ in range(n_items):
                    segs.append(Segment(float(tokens[pos]), float(tokens[pos + 1]), str(tokens[pos + 2]).strip()))
                    pos += 3
                tiers[str(name)] = segs
            else:
                pos += 2 * n_items
    except (IndexError, ValueError, TypeError):
        raise InputError(f"{path}: malformed TextGrid (it ends early or has a non-number where a time belongs).") from None
    return tiers


def write_textgrid(path: Path, tiers: Mapping[str, Sequence[Segment]], xmax: float | None = None) -> None:
    """Write interval tiers as a long-format TextGrid (UTF-8)."""
    xmax = xmax if xmax is not None else max((s[-1].end for s in tiers.values() if s), default=0.0)
    lines = [
        'File type = "ooTextFile"', 'Object class = "TextGrid"', "",
        "xmin = 0", f"xmax = {xmax:.6f}", "tiers? <exists>", f"size = {len(tiers)}", "item []:",
    ]
    for k, (name, segs) in enumerate(tiers.items(), 1):
        lines += [
            f"    item [{k}]:", '        class = "IntervalTier"', f'        name = "{name}"',
            "        xmin = 0", f"        xmax = {xmax:.6f}", f"        intervals: size = {len(segs)}",
        ]
        for i, s in enumerate(segs, 1):
            label = s.label.replace('"', '""')
            lines += [
                f"        intervals [{i}]:", f"            xmin = {s.start:.6f}",
                f"            xmax = {s.end:.6f}", f'            text = "{label}"',
            ]
    Path(path).write_text("\n".join(lines) + "\n", encoding="utf-8")


def read_lab(path: Path) -> list[Segment]:
    """Read an HTK or Festival ``.lab`` file."""
    path = Path(path)
    if not path.exists():
        raise InputError(f"{path}: alignment file not found; check the path.")
    lines = [line.strip() for line in _decode(path.read_bytes()).splitlines()]
    segs: list[Segment] = []
    number = 0
    try:
        if "#" in lines:  # Festival/xwaves: header, '#', then "end colour label"
            prev = 0.0
            first = lines.index("#") + 1
            for number, line in enumerate(lines[first:], first + 1):  # noqa: B007 (the error names it)
                if not line:
                    continue
                parts = line.split()
                end = float(parts[0])
                segs.append(Segment(prev, end, parts[-1] if len(parts) >= 3 else ""))
                prev = end
        else:  # HTK: "start end label" in units of 100 ns, or the same in seconds
            rows = []
            for number, line in enumerate(lines, 1):  # noqa: B007 (the error names it)
                if not line or line == ".":
                    continue
                parts = line.split()
                label = parts[2] if len(parts) > 2 else ""
                full = _HTS_CENTRE.match(label)  # HTS full-context label: the centre phone
                rows.append((float(parts[0]), float(parts[1]), full.group(1) if full else label, parts[:2]))
            per_s, unit = lab_time_unit([r[3] for r in rows])
            log.info("%s: .lab times read as %s", path, unit)
            segs = [Segment(a / per_s, b / per_s, label) for a, b, label, _ in rows]
    except (ValueError, IndexError):
        raise InputError(f"{path}, line {number}: malformed .lab line {lines[number - 1]!r}; expected HTK "
                         "'start end label' (100 ns units or seconds) or Festival 'end colour label' after a '#' line.") from None
    return segs


def lab_time_unit(times: Sequence[Sequence[str]]) -> tuple[float, str]:
    """The unit of the ``start end`` fields of a ``.lab`` file, from their text: (units per
    second, a phrase naming it). HTK writes integers in 100 ns units, so an end time is at least
    10,000 (1 ms) in any real file; seconds are written with a decimal point or are small
    integers. Any field with a decimal point or exponent, or a largest value below 10,000
    (2.8 hours if it were seconds), means seconds."""
    fields = [t for row in times for t in row]
    integers = all(re.fullmatch(r"[-+]?\d+", t) for t in fields)
    if integers and fields and max(float(t) for t in fields) >= 1e4:
        return 1e7, "HTK 100 ns units (integers of 10,000 and more)"
    return 1.0, "seconds (" + ("values with a decimal point" if not integers else "small integers") + ")"


def write_lab(path: Path, segs: Sequence[Segment]) -> None:
    """Write HTK ``.lab`` (100 ns units)."""
    Path(path).write_text(
        "".join(f"{round(s.start * 1e7)} {round(s.end * 1e7)} {s.label}\n" for s in segs), encoding="utf-8"
    )


def read_phone_segments(path: Path, tier_names: Sequence[str] = ("phones",)) -> list[Segment]:
    """Phone segments from a TextGrid (first tier named in ``tier_names``) or a .lab file."""
    path = Path(path)
    if path.suffix.lower() == ".lab":
        segs = read_lab(path)
    else:
        tiers = read_textgrid(path)
        if not tiers:
            raise InputError(f"{path}: the TextGrid has no interval tier; add a phone tier.")
        lowered = {name.lower(): name for name in tiers}
        chosen = next((lowered[n] for n in tier_names if n in lowered), None)
        if chosen is None:
            if len(tiers) == 1:
                chosen = next(iter(tiers))
            else:
                raise InputError(
                    f"{path}: no phone tier among {sorted(tiers)}; name it one of {list(tier_names)}."
                )
        segs = tiers[chosen]
    check_segments(segs, str(path))
    return segs


def check_segments(segs: Sequence[Segment], where: str) -> None:
    """Refuse empty, unsorted, overlapping or zero-length segment lists, naming the place."""
    if not segs:
        raise InputError(f"{where}: no phone segments; the alignment is empty.")
    for s in segs:
        if not (math.isfinite(s.start) and math.isfinite(s.end)):
            raise InputError(f"{where}: segment {s.label!r} has time {s.start:g} to {s.end:g} s; times must be finite numbers.")
        if s.start < 0:
            raise InputError(f"{where}, {s.start:.3f} s: segment {s.label!r} starts before 0 s; times are seconds from the "
                             "start of the audio.")
    limits.bound(segs[-1].end, "max_utterance_s", "the utterance's end (s)", where)
    prev_end = segs[0].start
    for s in segs:
        limits.bound(s.end - s.start, "max_phone_s", f"the length (s) of segment {s.label!r} at {s.start:.3f} s", where)
        if s.end <= s.start + _EPS:
            raise InputError(f"{where}, {s.start:.3f} s: segment {s.label!r} ends at or before it starts.")
        if s.start < prev_end - _EPS:
            raise InputError(
                f"{where}, {s.start:.3f} s: segment {s.label!r} overlaps or is out of order with the one before; sort and fix the boundaries."
            )
        prev_end = s.end
