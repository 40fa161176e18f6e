"""Another rig's blendshape curves (FACEGOOD, Faceware, MetaHuman exports...) and the mapping
CSV from its channels to the 52 ARKit shapes: the files, read and written here; posing the
built-in rig with them is :mod:`facesynth.domain.capture.curve_take`.

The curves: per-frame weights of the source rig's channels, either

* a CSV with a header naming the channels, optionally a ``time`` column (seconds, evenly
  stepped: the rate comes from it) and a ``frame`` or ``timecode`` column (ignored); without
  ``time`` the rate must be given (the manifest's ``fps`` column or ``ingest.curves_fps``); or
* a NumPy ``.npy`` array (T, C) of numbers with its C channel names in a names file: a ``.npy``
  array of C strings, or text (one name a line, or one comma-separated line), the rate given as
  above.

An empty or NaN cell makes its frame a gap; an infinite value is refused.

The mapping: a CSV with the header ``source,arkit,weight`` (more columns, e.g. ``note``, are
ignored; lines starting with ``#`` are comments), one row per (source channel, ARKit shape)
pair. ``ARKit[a] = clip(sum over the rows (s, a, w) of w * curves[s], 0, 1)``: several rows for
one ARKit shape add up. ARKit names match in any case (FACEGOOD's ``browDownleft`` is
``browDownLeft``). A row naming a channel the curves lack, or a shape that is not ARKit's, is
refused in one sentence naming the line.
"""

from __future__ import annotations

import csv
import warnings
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from facesynth.base.errors import InputError

#: The mapping CSV's columns.
MAPPING_COLUMNS = ("source", "arkit", "weight")


def read_mapping(path: Path, channels: Sequence[str], arkit_names: Sequence[str], where: str) -> np.ndarray:
    """The (C, 52) matrix of the mapping CSV at ``path`` from the curves' C ``channels`` (the
    curves named ``where`` in errors) to the ARKit weights in ``arkit_names`` order."""
    path = Path(path)
    if not path.is_file():
        raise InputError(f"{path}: mapping file not found; give a CSV of source,arkit,weight rows.")
    arkit_index = {n.lower(): a for a, n in enumerate(arkit_names)}
    channel_index = {c: k for k, c in enumerate(channels)}
    with open(path, encoding="utf-8-sig", errors="replace", newline="") as fh:
        lines = [(n, line) for n, line in enumerate(fh, 1) if line.strip() and not line.lstrip().startswith("#")]
    if not lines:
        raise InputError(f"{path}: the mapping is empty; give a header source,arkit,weight and one row per pair.")
    rows = list(csv.reader(line for _, line in lines))
    header = [h.strip().lower() for h in rows[0]]
    missing = [c for c in MAPPING_COLUMNS if c not in header]
    if missing:
        raise InputError(f"{path}, line {lines[0][0]}: the mapping's header lacks {', '.join(missing)}; it needs the "
                         "columns source,arkit,weight.")
    col = {c: header.index(c) for c in MAPPING_COLUMNS}
    matrix = np.zeros((len(channels), len(arkit_names)))
    for (number, _), row in zip(lines[1:], rows[1:]):
        if len(row) <= max(col.values()):
            raise InputError(f"{path}, line {number}: the row has {len(row)} cells; every row needs source, arkit "
                             "and weight.")
        source, arkit, weight = (row[col[c]].strip() for c in MAPPING_COLUMNS)
        if source not in channel_index:
            close = [c for c in channels if c.lower() == source.lower()]
            hint = f" (did you mean {close[0]!r}?)" if close else ""
            raise InputError(f"{path}, line {number}: the source channel {source!r} is not a channel of {where}"
                             f"{hint}; name one of its {len(channels)} channels ({', '.join(channels[:3])}, ...).")
        if arkit.lower() not in arkit_index:
            raise InputError(f"{path}, line {number}: {arkit!r} is not an ARKit blendshape; use one of the 52 ARKit "
                             "names (jawOpen, mouthClose, eyeBlinkLeft, ...).")
        try:
            value = float(weight)
        except ValueError:
            raise InputError(f"{path}, line {number}: the weight {weight!r} is not a number.") from None
        if not np.isfinite(value) or abs(value) > 100:
            raise InputError(f"{path}, line {number}: the weight {weight!r} is not a number between -100 and 100.")
        matrix[channel_index[source], arkit_index[arkit.lower()]] += value
    if not matrix.any():
        raise InputError(f"{path}: every weight of the mapping is 0 (or it has no rows); it drives no ARKit shape.")
    return matrix


def write_mapping(path: Path, rows: Sequence[tuple[str, str, float, str]], comments: Sequence[str] = ()) -> None:
    """Write a mapping CSV: ``#`` comment lines, then ``source,arkit,weight,note`` rows."""
    with open(path, "w", encoding="utf-8", newline="") as fh:
        for line in comments:
            fh.write(f"# {line}\n")
        writer = csv.writer(fh, lineterminator="\n")
        writer.writerow([*MAPPING_COLUMNS, "note"])
        for source, arkit, weight, note in rows:
            writer.writerow([source, arkit, f"{weight:.6g}", note])


def read_channel_names(path: Path) -> list[str]:
    """The channel names of a ``.npy`` curve file: a ``.npy`` array of strings, or text with one
    name a line (or all on one comma-separated line)."""
    path = Path(path)
    if not path.is_file():
        raise InputError(f"{path}: channel-names file not found; give the names of the curves' columns in the "
                         "manifest's names column.")
    if path.suffix.lower() == ".npy":
        array = _load_npy(path, "names")
        if array.dtype.kind not in "US":
            raise InputError(f"{path}: holds a {array.dtype} array, not names; save the channel names as an array of "
                             "strings with numpy.save.")
        names = [str(n) for n in array.reshape(-1)]
    else:
        with open(path, encoding="utf-8-sig", errors="replace") as fh:
            lines = [line.strip() for line in fh if line.strip()]
        names = next(csv.reader(lines[:1])) if len(lines) == 1 and "," in lines[0] else lines
        names = [n.strip() for n in names]
    if len(set(names)) != len(names):
        repeated = next(n for n in names if names.count(n) > 1)
        raise InputError(f"{path}: the channel name {repeated!r} appears twice; every column needs its own name.")
    return names


def _load_npy(path: Path, what: str) -> np.ndarray:
    """A .npy array without pickles (FACEGOOD's files were written by Python 2, which NumPy warns about)."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)
            return np.load(path, allow_pickle=False)
    except (ValueError, OSError, EOFError) as exc:
        raise InputError(f"{path}: not a NumPy array of {what} ({str(exc).rstrip('.')}); save it with numpy.save."
                         ) from None


def read_curves(path: Path, names_path: Path | None, fps: float | None) -> tuple[np.ndarray, list[str], float]:
    """(values (T, C) float64, NaN in gaps; the C channel names; frames/s) of a curve file (see
    the module docstring). ``names_path``: the names of a ``.npy``'s columns; ``fps``: the rate
    of curves without a time column (None: none given)."""
    path = Path(path)
    if path.suffix.lower() == ".npy":
        if names_path is None:
            raise InputError(f"{path}: a .npy curve file needs its channel names; give the names file in the "
                             "manifest's names column.")
        names = read_channel_names(names_path)
        values = _load_npy(path, "curves")
        if values.ndim != 2 or values.dtype.kind not in "fiu":
            raise InputError(f"{path}: holds a {values.dtype} array of shape {values.shape}; curves are a (frames, "
                             "channels) array of numbers.")
        if values.shape[1] != len(names):
            raise InputError(f"{path}: {values.shape[1]} columns but {names_path} names {len(names)} channels; give "
                             "the names file made with these curves.")
        if not fps:
            raise InputError(f"{path}: a .npy curve file has no time; give its frame rate in the manifest's fps "
                             "column or with --set ingest.curves_fps=RATE.")
        values = values.astype(np.float64)
        if np.isinf(values).any():
            frame = int(np.nonzero(np.isinf(values).any(axis=1))[0][0])
            raise InputError(f"{path}: frame {frame + 1} holds an infinite value; leave a missing sample NaN.")
        return values, names, float(fps)
    with open(path, encoding="utf-8-sig", errors="replace", newline="") as fh:
        rows = [(n, r) for n, r in enumerate(csv.reader(fh), 1) if any(c.strip() for c in r)]
    if len(rows) < 2:
        raise InputError(f"{path}: a curve CSV needs a header and at least one row.")
    header = [h.strip() for h in rows[0][1]]
    lower = [h.lower() for h in header]
    time_col = lower.index("time") if "time" in lower else None
    channels = [k for k, h in enumerate(lower) if h not in ("time", "frame", "timecode") and header[k]]
    names = [header[k] for k in channels]
    if len(set(names)) != len(names):
        repeated = next(n for n in names if names.count(n) > 1)
        raise InputError(f"{path}, line 1: the channel {repeated!r} appears twice; every column needs its own name.")
    if not names:
        raise InputError(f"{path}, line 1: the header names no channels; give one column per channel of the rig.")
    values = np.full((len(rows) - 1, len(channels)), np.nan)
    times = np.zeros(len(rows) - 1)
    for i, (line, row) in enumerate(rows[1:]):
        if len(row) < len(header):
            raise InputError(f"{path}, line {line}: {len(row)} cells but the header has {len(header)}; the file was "
                             "cut short or edited.")
        for j, k in enumerate(channels):
            cell = row[k].strip()
            if cell and cell.lower() != "nan":
                try:
                    values[i, j] = float(cell)
                except ValueError:
                    raise InputError(f"{path}, line {line}, column {header[k]}: {cell!r} is not a number.") from None
                if not np.isfinite(values[i, j]):
                    raise InputError(f"{path}, line {line}, column {header[k]}: {cell!r} is not a finite number; "
                                     "leave a missing sample empty.")
        if time_col is not None:
            try:
                times[i] = float(row[time_col])
            except ValueError:
                raise InputError(f"{path}, line {line}, column time: {row[time_col]!r} is not a number (seconds)."
                                 ) from None
    if time_col is None:
        if not fps:
            raise InputError(f"{path}: the curve CSV has no time column; add one (seconds) or give the frame rate in "
                             "the manifest's fps column or with --set ingest.curves_fps=RATE.")
        return values, names, float(fps)
    if len(times) < 2:
        raise InputError(f"{path}: the time column needs at least two rows to give a rate; add rows.")
    steps = np.diff(times)
    if not (np.isfinite(times).all() and (steps > 0).all()):
        k = int(np.argmax(~(steps > 0))) if not (steps > 0).all() else int(np.argmax(~np.isfinite(times[1:])))
        raise InputError(f"{path}, line {rows[k + 2][0]}, column time: the time does not increase; fix the export.")
    rate = 1.0 / float(np.median(steps))
    off = np.abs(steps * rate - 1)
    if off.max() > 0.25:
        raise InputError(f"{path}, line {rows[int(np.argmax(off)) + 2][0]}, column time: the time steps unevenly "
                         f"(median step {1 / rate:.6g} s); export the curves at one rate.")
    rate = float(np.round(rate, 3))
    if fps and abs(rate / fps - 1) > 0.01:
        raise InputError(f"{path}: the time column steps at {rate:g} frames/s but {fps:g} was given; drop one.")
    return values, names, rate
