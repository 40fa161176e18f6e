"""Marker trajectories: C3D (decoded by :mod:`facesynth.formats.c3dfile`; written with the
``c3d`` library), TRC and plain CSV.

All readers return a :class:`MarkerTake` with positions in millimetres; missing samples
(C3D residual < 0 or (0, 0, 0), empty or NaN TRC/CSV fields) are NaN.
"""

from __future__ import annotations

import csv
import logging
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import c3d
import numpy as np

from facesynth.base import limits
from facesynth.base.errors import InputError

from .c3dfile import MODEL_OUTPUT_GROUPS, C3dPoints, read_points

log = logging.getLogger(__name__)

#: The marker files :func:`read_mocap` reads.
MARKER_SUFFIXES = (".c3d", ".trc", ".csv")
_UNIT_TO_MM = {"mm": 1.0, "cm": 10.0, "m": 1000.0, "millimeters": 1.0, "meters": 1000.0}


@dataclass
class MarkerTake:
    """positions : (n_frames, n_markers, 3) float32, millimetres, NaN where missing.
    names : n_markers labels. fps : frames per second.
    left_out : labels of the points a C3D file lists as model outputs (joint angles, forces,
        moments, powers...), which are not markers and were not read."""

    positions: np.ndarray
    names: list[str]
    fps: float
    left_out: list[str] = field(default_factory=list)


def _unit_scale(unit: str, path: Path) -> float:
    key = unit.strip().lower()
    if key not in _UNIT_TO_MM:
        raise InputError(f"{path}: unknown length unit {unit!r}; use mm, cm or m.")
    return _UNIT_TO_MM[key]


def read_mocap(path: Path) -> MarkerTake:
    """Read a marker file (C3D, TRC or marker CSV, by its suffix: :data:`MARKER_SUFFIXES`) and
    check it (:func:`check_take`). Every kind of take a manifest may name, markers among them, is
    read by :func:`facesynth.domain.capture.readers.read_capture`."""
    path = Path(path)
    if not path.exists():
        raise InputError(f"{path}: mocap file not found; check the manifest's mocap column.")
    suffix = path.suffix.lower()
    if suffix not in MARKER_SUFFIXES:
        raise InputError(f"{path}: not a marker file ({suffix!r}); use .c3d, .trc or .csv.")
    return checked({".c3d": read_c3d, ".trc": read_trc, ".csv": read_csv}[suffix](path), path)


def checked(take: MarkerTake, path: Path) -> MarkerTake:
    """``take`` as read from ``path``, refused in one sentence when it has no frames or two
    markers of one name, or fails :func:`check_take`."""
    if take.positions.shape[0] == 0:
        raise InputError(f"{path}: the take has no frames; re-export it or drop it from the manifest.")
    if len(set(take.names)) != len(take.names):
        raise InputError(f"{path}: duplicate marker names; every marker needs its own label.")
    check_take(take, str(path))
    return take


def check_take(take: MarkerTake, where: str) -> None:
    """Refuse what no capture holds: a frame rate that is not a positive finite number within
    ``limits.max_fps``, more markers than ``limits.max_markers``, a take longer than
    ``limits.max_utterance_s``, or an infinite coordinate (a missing sample is NaN, not inf)."""
    if not (np.isfinite(take.fps) and take.fps > 0):
        raise InputError(f"{where}: the frame rate is {take.fps:g} frames/s; it must be a positive number (fix the header).")
    limits.bound(take.fps, "max_fps", "the frame rate (frames/s)", where)
    limits.bound(len(take.names), "max_markers", "the number of markers", where)
    limits.bound(take.positions.shape[0] / take.fps, "max_utterance_s", "the take's length (s)", where)
    infinite = np.isinf(take.positions)
    if infinite.any():
        frame, marker, _ = (int(i[0]) for i in np.nonzero(infinite))
        raise InputError(f"{where}: frame {frame + 1}, marker {take.names[marker]!r}: a coordinate is infinite; "
                         "leave a missing sample empty (or NaN) and fix the export.")


def read_c3d(path: Path) -> MarkerTake:
    """Markers of a C3D file of any writer (see ``docs/inputs.md``), in millimetres.

    The points come from :func:`facesynth.formats.c3dfile.read_points`. Of them, the model
    outputs that ``POINT:ANGLES``, ``FORCES``, ``MOMENTS``, ``POWERS``, ``SCALARS`` and
    ``REACTIONS`` list (joint angles in degrees, forces...) are left out and named in
    ``MarkerTake.left_out``; repeated or empty labels are resolved by :func:`_resolve_labels`.
    A sample is missing (NaN) when its residual word is negative (the standard's invalid
    flag), a coordinate is NaN, or it is exactly (0, 0, 0), as several writers store a gap.
    Every liberty taken with the file is logged as a warning naming it.
    """
    path = Path(path)
    try:
        points = read_points(path)
    except OSError as exc:
        raise InputError(f"{path}: cannot read the file ({exc.strerror or exc}); check its permissions.") from None
    notes = list(points.notes)
    labels = points.labels
    model_outputs = {label for group in MODEL_OUTPUT_GROUPS
                     for label in points.groups.get(f"POINT:{group}", []) if isinstance(label, str) and label}
    xyz = points.xyz.copy()
    # a NaN coordinate is a gap (Vicon Nexus writes them); an infinite one is refused by check_take
    missing = (points.residual_word < 0) | np.all(xyz == 0, axis=2) | np.isnan(xyz).any(axis=2)
    xyz[missing] = np.nan
    left_out = [label for label in labels if label in model_outputs]
    markers = [i for i, label in enumerate(labels) if label not in model_outputs]
    names, columns = _resolve_labels(path, [labels[i] for i in markers], _descriptions(points, markers),
                                     xyz[:, markers], notes)
    if left_out:
        notes.append(f"left out {len(left_out)} model outputs (angles, forces, moments, powers, scalars, "
                     f"reactions) of {len(labels)} points; {len(names)} markers read")
    if not names:
        raise InputError(f"{path}: none of its {len(labels)} points is a marker ({len(left_out)} are model outputs, "
                         "the others unnamed and empty); export the marker trajectories.")
    positions = np.stack(columns, axis=1)
    if positions.shape[0] and np.isnan(positions).all():
        raise InputError(f"{path}: every marker sample is missing (marked invalid by a negative residual, or at "
                         "(0, 0, 0)); the file holds no marker positions: export the reconstructed trajectories.")
    unit = points.unit
    if not unit:
        notes.append("POINT:UNITS is absent; millimetres (the C3D convention) assumed")
        unit = "mm"
    positions *= _c3d_unit_scale(unit, path)
    for note in notes:
        log.warning("%s: %s.", path, note)
    return MarkerTake(positions.astype(np.float32), names, points.rate, left_out)


def _descriptions(points: C3dPoints, indices: list[int]) -> list[str]:
    """POINT:DESCRIPTIONS of the points at ``indices`` ("" where absent)."""
    described = [d for d in points.groups.get("POINT:DESCRIPTIONS", []) if isinstance(d, str)]
    return [described[i] if i < len(described) else "" for i in indices]


def _resolve_labels(path: Path, labels: list[str], descriptions: list[str], xyz: np.ndarray,
                    notes: list[str]) -> tuple[list[str], list[np.ndarray]]:
    """One column per marker name from points whose labels may be empty or repeated.

    xyz : (n_frames, n_points, 3), NaN where missing. Points of one label whose
    ``POINT:DESCRIPTIONS`` tell them apart (writers that cut labels to four characters: Motion
    Analysis) are named by their descriptions. Otherwise a point that holds no sample and has no
    label, or repeats another's, is dropped; points of one label that agree wherever both hold
    a sample (a trajectory written twice or in pieces: Qualisys) are merged; and points of one
    label that still disagree are refused.
    Returns the names and (n_frames, 3) columns."""
    seen = ~np.isnan(xyz).all(axis=(0, 2))
    order: list[str] = []
    groups: dict[str, list[int]] = {}
    for index, label in enumerate(labels):
        if label not in groups:
            order.append(label)
        groups.setdefault(label, []).append(index)
    names, columns, dropped, merged, described = [], [], 0, 0, 0
    for label in order:
        members = groups[label]
        holding = [i for i in members if seen[i]]
        if not label:
            if holding:
                raise InputError(f"{path}: point {holding[0] + 1} has no label but holds samples, so it cannot be "
                                 "told from the others; name it in the capture software and export again.")
            dropped += len(members)
            continue
        described_as = [descriptions[i] for i in members]
        if len(members) > 1 and all(described_as) and len(set(described_as)) == len(members):
            names += described_as
            columns += [xyz[:, i].copy() for i in members]
            described += len(members)
            continue
        kept = holding or members[:1]
        dropped += len(members) - len(holding or members[:1])
        distinct: list[np.ndarray] = []
        for i in kept:
            for column in distinct:
                both = ~np.isnan(column).any(axis=1) & ~np.isnan(xyz[:, i]).any(axis=1)
                if np.allclose(column[both], xyz[both, i], rtol=0, atol=1e-4):
                    fill = np.isnan(column).any(axis=1)
                    column[fill] = xyz[fill, i]
                    merged += 1
                    break
            else:
                distinct.append(xyz[:, i].copy())
        if len(distinct) == 1:
            names.append(label)
            columns.append(distinct[0])
            continue
        raise InputError(f"{path}: the label {label!r} names {len(distinct)} different trajectories and their "
                         "descriptions do not tell them apart; give every marker its own label and export again.")
    repeated = sorted({n for n in names if names.count(n) > 1})
    if repeated:
        raise InputError(f"{path}: the name {repeated[0]!r} is used by {names.count(repeated[0])} markers (a label "
                         "and a description); give every marker its own label and export again.")
    if dropped:
        notes.append(f"dropped {dropped} unlabelled or repeated points that hold no sample")
    if merged:
        notes.append(f"merged {merged} repeated points into the point of the same label they agree with")
    if described:
        notes.append(f"{described} points share their label with another trajectory and were named by their "
                     "POINT:DESCRIPTIONS")
    return names, columns


def _c3d_unit_scale(unit: str, path: Path) -> float:
    """Millimetres per unit of ``POINT:UNITS``; also the cut spellings some writers store in a
    four-character field ('mete' for metres)."""
    key = unit.strip().lower()
    for full, scale in (("millimeters", 1.0), ("millimetres", 1.0), ("centimeters", 10.0), ("centimetres", 10.0),
                        ("meters", 1000.0), ("metres", 1000.0)):
        if len(key) >= 4 and full.startswith(key):
            return scale
    return _unit_scale(unit, path)


def write_c3d(path: Path, take: MarkerTake) -> None:
    """Write markers (mm) as a float C3D; NaN samples are written as missing (residual -1).

    The header and parameters are the ``c3d`` library's; the frames are :func:`_point_records`,
    the bytes the library's own frame loop writes, encoded for the whole take at once."""
    writer = _RecordsWriter(_point_records(take.positions), point_rate=float(take.fps), point_units="mm  ")
    writer.set_point_labels(take.names)
    with open(path, "wb") as fh, warnings.catch_warnings():
        warnings.simplefilter("ignore")
        writer.write(fh)


def _point_records(positions: np.ndarray) -> np.ndarray:
    """The C3D float point records of a take: positions (T, M, 3) mm, NaN where missing ->
    (T, M, 4) float32 x, y, z and residual word, 0 for a sample and -1 for a missing one.

    A missing sample keeps the coordinates of the marker's last sample before it (0 before its
    first), as the ``c3d`` library's writer leaves them; readers go by the residual."""
    positions = np.asarray(positions, np.float32)
    missing = np.isnan(positions).any(axis=2)                                     # (T, M)
    n_frames, n_markers = missing.shape
    sampled_at = np.where(missing, -1, np.arange(n_frames)[:, None])
    last_sample = np.maximum.accumulate(sampled_at, axis=0)                       # (T, M), -1 before the first
    records = np.empty((n_frames, n_markers, 4), np.float32)
    records[..., :3] = positions
    records[..., 3] = np.where(missing, -1.0, 0.0)
    frame, marker = np.nonzero(missing)
    held = last_sample[frame, marker]
    records[frame, marker, :3] = np.where((held >= 0)[:, None], positions[np.maximum(held, 0), marker], 0.0)
    return records


class _RecordsWriter(c3d.Writer):
    """``c3d.Writer`` for float points (its default, negative point scale) given as their records
    (T, M, 4) (:func:`_point_records`), without analog channels: written in one piece rather
    than frame by frame."""

    def __init__(self, records: np.ndarray, **options) -> None:
        super().__init__(**options)
        self.records = records
        empty_analog = np.zeros((0, 0), np.float32)
        self.add_frames([(frame, empty_analog) for frame in records])  # the header's counts

    def _write_frames(self, handle) -> None:
        handle.write(self.records.astype("<f4", copy=False).tobytes())
        self._pad_block(handle)


def text_ends_with_newline(path: Path) -> bool:
    """Whether the file's last byte is a line break (a file cut mid-line lacks it)."""
    with open(path, "rb") as fh:
        fh.seek(0, 2)
        if fh.tell() == 0:
            return False
        fh.seek(-1, 2)
        return fh.read(1) in (b"\n", b"\r")


def read_trc(path: Path) -> MarkerTake:
    """Markers of a TRC file as OpenSim's readers and the writers of real files produce it.

    Five header lines (``PathFileType``; the keys ``DataRate ... OrigNumFrames``; their values;
    ``Frame# Time`` and the marker names; the ``X1 Y1 Z1`` line), blank lines, then one row per
    frame: frame number, time (s), X Y Z per marker, tab-separated. Cells padded with spaces or
    tabs, CRLF line ends, empty cells between header fields and after the last cell of a row, and
    a last row without a line break are all taken as OpenSim takes them. A missing sample is an
    empty cell or NaN (any case). Units from the header (mm, cm, m), converted to mm.

    The frame rate is the header's ``DataRate`` when the Time column agrees with it (within 1%);
    when it does not, the Time column's rate is used, with a warning, provided the column steps
    regularly (nine steps in ten within a quarter of the fitted step); otherwise the file is
    refused; the corrected rate is rounded to 0.01 frames/s. A last row cut short, or fewer rows than ``NumFrames`` in a file that ends in the
    middle of a line, is refused as a file cut short; fewer rows in a file that ends cleanly (an
    export of part of a trial that kept the header) is warned about.
    """
    path = Path(path)
    lines = path.read_text("utf-8", errors="replace").splitlines()
    if len(lines) < 5:
        raise InputError(f"{path}: not a valid TRC file (it has {len(lines)} lines, fewer than the five of the "
                         "header); export it again.")
    keys = [k.strip() for k in lines[1].split("\t") if k.strip()]
    values = [v.strip() for v in lines[2].split("\t") if v.strip()]
    if len(keys) != len(values) or "DataRate" not in keys:
        raise InputError(f"{path}, lines 2-3: not a valid TRC header ({len(keys)} keys, {len(values)} values, "
                         "DataRate needed); check its five header lines.")
    meta = dict(zip(keys, values))
    try:
        header_fps = float(meta["DataRate"])
    except ValueError:
        raise InputError(f"{path}, line 3: DataRate {meta['DataRate']!r} is not a number; fix the header.") from None
    unit = meta.get("Units", "mm")
    names = [n.strip() for n in lines[3].split("\t")[2:] if n.strip()]
    declared_markers = _header_count(meta, "NumMarkers", path)
    if declared_markers is not None and declared_markers != len(names):
        raise InputError(f"{path}, line 4: the header declares {declared_markers} markers but names {len(names)}; "
                         "fix the header.")
    width = 2 + 3 * len(names)
    numbered = [(n, line.split("\t")) for n, line in enumerate(lines[5:], 6) if line.strip()]
    for number, row in numbered:
        while row and not row[-1].strip():
            row.pop()
        if len(row) > width:
            raise InputError(f"{path}, line {number}: holds {len(row)} cells but the header has {width} "
                             "(frame, time, x y z per marker); fix the export.")
    declared = _header_count(meta, "NumFrames", path)
    _check_not_cut(path, lines, numbered, declared)
    positions = np.full((len(numbered), len(names), 3), np.nan, np.float32)
    times = np.zeros(len(numbered))
    for i, (number, row) in enumerate(numbered):
        try:
            times[i] = float(row[1])
        except (IndexError, ValueError):
            raise InputError(f"{path}, line {number}: the Time cell {row[1] if len(row) > 1 else ''!r} is not a "
                             "number.") from None
        for j, cell in enumerate(row[2:]):
            cell = cell.strip()
            if cell and cell.lower() != "nan":
                try:
                    positions[i, j // 3, j % 3] = float(cell)
                except ValueError:
                    raise InputError(f"{path}, line {number}: {cell!r} is not a number.") from None
    # a marker is missing when any of its three cells is (as OpenSim reads it)
    positions[np.isnan(positions).any(axis=2)] = np.nan
    fps = _trc_rate(path, header_fps, times)
    positions *= _unit_scale(unit, path)
    return MarkerTake(positions, names, fps)


def _header_count(meta: dict, key: str, path: Path) -> int | None:
    """An integer field of the TRC header (``NumFrames``, ``NumMarkers``), None when absent."""
    if key not in meta:
        return None
    try:
        value = float(meta[key])
    except ValueError:
        raise InputError(f"{path}, line 3: {key} {meta[key]!r} is not a number; fix the header.") from None
    if value != int(value) or value < 0:
        raise InputError(f"{path}, line 3: {key} {meta[key]!r} is not a count; fix the header.")
    return int(value)


def _check_not_cut(path: Path, lines: list[str], numbered: list, declared: int | None) -> None:
    """Refuse a TRC cut short; warn when an intact file holds other than ``NumFrames`` rows."""
    if not numbered:
        return
    ends_cleanly = text_ends_with_newline(path)
    last_number, last_row = numbered[-1]
    if not ends_cleanly:
        raw = lines[last_number - 1].split("\t")
        others = [len(lines[n - 1].split("\t")) for n, _ in numbered[-6:-1]]
        if (others and len(raw) < min(others)) or (declared is not None and len(numbered) < declared):
            raise InputError(f"{path}, line {last_number}: the file ends in the middle of this line; it was cut "
                             "short: export it again.")
    if declared is not None and declared != len(numbered):
        log.warning("%s: the header declares %d frames but %d rows follow (frames %s to %s); the rows were read.",
                    path, declared, len(numbered), numbered[0][1][0].strip(), last_row[0].strip())


def _trc_rate(path: Path, header_fps: float, times: np.ndarray) -> float:
    """The frame rate of a TRC: its header's, checked against the Time column (see read_trc)."""
    if len(times) < 3:
        return header_fps
    steps = np.diff(times)
    if not np.all(steps > 0):
        row = int(np.argmax(steps <= 0)) + 2
        raise InputError(f"{path}: the Time column does not increase at data row {row}; fix the export.")
    rows = np.arange(len(times))
    slope, intercept = np.polyfit(rows, times, 1)
    # refit without the rows off the line by more than a quarter step (a last frame kept from the
    # original take, a dropped row), so that they do not bias the rate
    on_line = np.abs(times - (intercept + slope * rows)) <= 0.25 * slope
    step = np.polyfit(rows[on_line], times[on_line], 1)[0] if on_line.sum() >= 2 else slope
    time_fps = 1.0 / step
    if header_fps > 0 and abs(time_fps / header_fps - 1) <= 0.01:
        return header_fps
    irregular = int(np.sum(np.abs(steps / step - 1) > 0.25))
    if irregular > 0.1 * len(steps):
        raise InputError(f"{path}: the header's DataRate is {header_fps:g} frames/s but the Time column steps "
                         f"irregularly ({irregular} of {len(steps)} steps off its mean of {step:.6g} s); fix the "
                         "export.")
    fps = float(np.round(time_fps, 2))  # a Time column printed to the ms does not hold more
    log.warning("%s: the header's DataRate is %g frames/s but the Time column steps at %g frames/s%s; the Time "
                "column's rate was used.", path, header_fps, fps,
                f" ({irregular} of {len(steps)} steps differ)" if irregular else "")
    return fps


def write_trc(path: Path, take: MarkerTake) -> None:
    """Write a take as a TRC file (tab-separated, mm)."""
    n_frames, n_markers, _ = take.positions.shape
    with open(path, "w", encoding="utf-8", newline="\n") as fh:
        fh.write(f"PathFileType\t4\t(X/Y/Z)\t{Path(path).name}\n")
        fh.write("DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames\n")
        fh.write(f"{take.fps:g}\t{take.fps:g}\t{n_frames}\t{n_markers}\tmm\t{take.fps:g}\t1\t{n_frames}\n")
        fh.write("Frame#\tTime\t" + "\t\t\t".join(take.names) + "\n")
        fh.write("\t\t" + "\t".join(f"X{k + 1}\tY{k + 1}\tZ{k + 1}" for k in range(n_markers)) + "\n")
        for i, xyz in enumerate(take.positions):
            cells = ["" if np.isnan(v) else f"{v:.4f}" for v in xyz.reshape(-1)]
            fh.write(f"{i + 1}\t{i / take.fps:.6f}\t" + "\t".join(cells) + "\n")


def read_csv(path: Path) -> MarkerTake:
    """CSV with a ``time`` column (seconds) and ``<marker>_x/_y/_z`` columns.

    An optional first line ``# units: m`` (or cm, mm) gives the length unit; mm otherwise.
    """
    text = Path(path).read_text("utf-8", errors="replace").splitlines()
    unit = "mm"
    if text and text[0].startswith("#"):
        if "units" in text[0]:
            unit = text[0].split(":", 1)[-1].strip()
        text = text[1:]
    reader = csv.reader(text)
    try:
        header = next(reader)
    except StopIteration:
        raise InputError(f"{path}: empty CSV file; export the take again.") from None
    if "time" not in header:
        raise InputError(f"{path}: the CSV header has no 'time' column (seconds) for a marker CSV; add one "
                         "(another rig's curves need their mapping to ARKit in the manifest's mapping column).")
    names = []
    for column in header:
        if column.endswith("_x") and column[:-2] + "_y" in header and column[:-2] + "_z" in header:
            names.append(column[:-2])
    if not names:
        raise InputError(f"{path}: no marker columns named <marker>_x, <marker>_y, <marker>_z in the header.")
    index = {c: k for k, c in enumerate(header)}
    rows = list(reader)
    positions = np.full((len(rows), len(names), 3), np.nan, np.float32)
    times = np.zeros(len(rows))
    for i, row in enumerate(rows):
        try:
            times[i] = float(row[index["time"]])
            for j, name in enumerate(names):
                for a, axis in enumerate("xyz"):
                    cell = row[index[f"{name}_{axis}"]].strip()
                    if cell and cell.lower() != "nan":
                        positions[i, j, a] = float(cell)
        except (ValueError, IndexError):
            raise InputError(f"{path}, line {i + 2}: malformed row; every row needs a number or an empty cell per column.") from None
    if len(times) < 2 or not np.all(np.diff(times) > 0):
        raise InputError(f"{path}: the 'time' column must increase and have at least two rows.")
    fps = float(np.round((len(times) - 1) / (times[-1] - times[0]), 3))
    positions *= _unit_scale(unit, path)
    return MarkerTake(positions, names, fps)


def write_csv(path: Path, take: MarkerTake) -> None:
    """Write a take as CSV: a ``frame`` column and ``NAME_x, NAME_y, NAME_z`` columns in mm."""
    with open(path, "w", encoding="utf-8", newline="") as fh:
        writer = csv.writer(fh)
        writer.writerow(["frame", "time"] + [f"{n}_{a}" for n in take.names for a in "xyz"])
        for i, xyz in enumerate(take.positions):
            writer.writerow([i, f"{i / take.fps:.6f}"] + ["" if np.isnan(v) else f"{v:.4f}" for v in xyz.reshape(-1)])
