"""Marker trajectories: C3D (through the ``c3d`` library), TRC and plain CSV.

All readers return a :class:`MarkerTake` with positions in millimetres; missing samples
(C3D residual < 0, empty TRC/CSV fields) are NaN.
"""

from __future__ import annotations

import csv
import struct
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .. import limits
from ..errors import InputError

_UNIT_TO_MM = {"mm": 1.0, "cm": 10.0, "m": 1000.0, "millimeters": 1.0, "meters": 1000.0}


@dataclass
class MarkerTake:
    """positions : (n_frames, n_markers, 3) float32, millimetres, NaN where missing."""

    positions: np.ndarray
    names: list[str]
    fps: float


def _unit_scale(unit: str, path: Path) -> float:
    key = unit.strip().lower()
    if key not in _UNIT_TO_MM:
        raise InputError(f"{path}: unknown length unit {unit!r}; use mm, cm or m.")
    return _UNIT_TO_MM[key]


def read_mocap(path: Path) -> MarkerTake:
    """Read a marker file by its extension (.c3d, .trc, .csv)."""
    path = Path(path)
    if not path.exists():
        raise InputError(f"{path}: mocap file not found; check the manifest's mocap column.")
    suffix = path.suffix.lower()
    readers = {".c3d": read_c3d, ".trc": read_trc, ".csv": read_csv}
    if suffix not in readers:
        raise InputError(f"{path}: unsupported mocap format {suffix!r}; use .c3d, .trc or .csv.")
    take = readers[suffix](path)
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
    """Markers of a C3D file (millimetres, as C3D stores them; missing samples NaN)."""
    import c3d

    try:
        with open(path, "rb") as fh, warnings.catch_warnings():
            warnings.simplefilter("ignore")  # "no analog data" is normal for marker-only files
            reader = c3d.Reader(fh)
            names = [str(n).strip() for n in reader.point_labels]
            fps = float(reader.point_rate)
            try:
                unit = reader.get("POINT:UNITS").string_value
            except (AttributeError, KeyError):
                unit = "mm"
            expected = reader.last_frame - reader.first_frame + 1
            frames = []
            for _, points, _ in reader.read_frames(copy=False):
                xyz = np.array(points[:, :3], dtype=np.float32)
                xyz[points[:, 3] < 0] = np.nan
                frames.append(xyz)
    except (struct.error, ValueError, EOFError, IndexError, KeyError, OSError, TypeError, AssertionError,
            OverflowError, MemoryError) as exc:
        raise InputError(f"{path}: unreadable or truncated C3D file ({exc}); re-export it from the capture software.") from None
    if len(frames) != expected:
        raise InputError(
            f"{path}: truncated C3D file ({len(frames)} of {expected} frames); re-export it from the capture software."
        )
    positions = np.stack(frames) if frames else np.zeros((0, len(names), 3), np.float32)
    positions *= _unit_scale(unit, path)
    return MarkerTake(positions.astype(np.float32), names, fps)


def write_c3d(path: Path, take: MarkerTake) -> None:
    """Write markers (mm) as a float C3D; NaN samples are written as missing (residual -1)."""
    import c3d

    writer = c3d.Writer(point_rate=float(take.fps), point_units="mm  ")
    writer.set_point_labels(take.names)
    n_markers = len(take.names)
    empty_analog = np.zeros((0, 0), dtype=np.float32)
    frames = []
    for xyz in take.positions:
        points = np.zeros((n_markers, 5), dtype=np.float32)
        missing = np.isnan(xyz).any(axis=1)
        points[:, :3] = np.where(missing[:, None], 0.0, xyz)
        points[:, 3] = np.where(missing, -1.0, 0.0)
        frames.append((points, empty_analog))
    writer.add_frames(frames)
    with open(path, "wb") as fh, warnings.catch_warnings():
        warnings.simplefilter("ignore")
        writer.write(fh)


def text_ends_with_newline(path: Path) -> bool:
    """Whether the file's last byte is a line break (a file cut mid-line lacks it)."""
    with open(path, "rb") as fh:
        fh.seek(0, 2)
        if fh.tell() == 0:
            return False
        fh.seek(-1, 2)
        return fh.read(1) in (b"\n", b"\r")


def read_trc(path: Path) -> MarkerTake:
    """Markers of a tab-separated TRC file (units from its header, converted to mm; empty cells NaN)."""
    try:
        lines = Path(path).read_text("utf-8", errors="replace").splitlines()
        keys = lines[1].split("\t")
        values = lines[2].split("\t")
        meta = dict(zip([k.strip() for k in keys], [v.strip() for v in values]))
        fps = float(meta["DataRate"])
        unit = meta.get("Units", "mm")
        names = [n.strip() for n in lines[3].split("\t")[2:] if n.strip()]
        numbered = [(n, line.split("\t")) for n, line in enumerate(lines[5:], 6) if line.strip()]
        declared = int(meta["NumFrames"]) if meta.get("NumFrames", "").strip().isdigit() else None
    except (IndexError, KeyError, ValueError) as exc:
        raise InputError(f"{path}: not a valid TRC file ({exc}); check its five header lines.") from None
    # Every exporter ends each line with a line break: a last line without one (or a row with more
    # cells than the header allows) is a file cut short or edited, which would change numbers silently.
    width = 2 + 3 * len(names)
    for number, row in numbered:
        if len(row) > width:
            raise InputError(f"{path}, line {number}: holds {len(row)} cells but the header has {width} "
                             "(frame, time, x y z per marker); fix the export.")
    if numbered and not text_ends_with_newline(path):
        raise InputError(f"{path}, line {numbered[-1][0]}: the file ends in the middle of this line; it was cut short: "
                         "export it again.")
    if declared is not None and declared != len(numbered):
        raise InputError(f"{path}: the header declares {declared} frames but {len(numbered)} follow; the file is "
                         "cut short or edited: export it again.")
    rows = [row for _, row in numbered]
    positions = np.full((len(rows), len(names), 3), np.nan, np.float32)
    for i, row in enumerate(rows):
        cells = row[2 : 2 + 3 * len(names)]
        for j, cell in enumerate(cells):
            if cell.strip():
                try:
                    positions[i, j // 3, j % 3] = float(cell)
                except ValueError:
                    raise InputError(f"{path}, line {i + 6}: {cell!r} is not a number.") from None
    positions *= _unit_scale(unit, path)
    return MarkerTake(positions, names, fps)


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
        raise InputError(f"{path}: the CSV header has no 'time' column (seconds); add one.")
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
