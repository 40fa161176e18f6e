"""Live Link Face CSV: the file the iPhone app records and Unreal's Live Link (and MetaHuman
animators) import. The column set, order and timecode format are the app's own, taken from the
real capture that ships with the rig (``ict_face_arkit.tsv`` lists its columns):

``Timecode,BlendShapeCount,`` the 52 ARKit blendshapes (``EyeBlinkLeft`` ... ``TongueOut``),
then ``HeadYaw,HeadPitch,HeadRoll,LeftEyeYaw,LeftEyePitch,LeftEyeRoll,RightEyeYaw,RightEyePitch,
RightEyeRoll``: 61 value columns, ``BlendShapeCount`` always 61. The timecode is
``HH:MM:SS:FF.sss``: FF the frame within the second at the file's rate (0..59 at 60 frames/s)
and ``.sss`` the sub-frame fraction; the file starts at 00:00:00:00.000.

Rotations are radians as the phone's camera sees the face, i.e. mirrored (x -> -x) from
facesynth's frame: with the head rotation ``R = Ry(a) @ Rx(b) @ Rz(c)`` (about +y, +x, +z of
facesynth's frame) ``HeadYaw = -a`` (positive: the face turns toward the subject's right, the
camera's left), ``HeadPitch = b`` (positive: the face looks down), ``HeadRoll = -c``. Eyes:
``LeftEye*`` is the eye at -x, ``RightEye*`` the eye at +x (the app's left and right are the
camera's), yaw positive toward -x and pitch positive down. This mirror convention reproduces the
eye columns of the shipped capture from its own ``EyeLook*`` weights to within 0.02 rad.

Reading (:func:`read`, what ``ingest`` calls for a Live Link Face take):

* a file is told by its header (:func:`is_live_link_face`): a ``Timecode`` and a
  ``BlendShapeCount`` column, any case. The 52 ARKit curves must all be there (any case, any
  order); ``HeadYaw``, ``HeadPitch`` and ``HeadRoll`` are optional; the eye rotations are not
  read (the eyelids' part of gaze is in the ``EyeLook*`` curves).
* a row's time is ``HH*3600 + MM*60 + SS + (FF + 0.mmm) / N`` seconds, N the timecode rate: the
  standard rate (:data:`STANDARD_RATES`) above the largest FF under which the times step evenly,
  also across the seconds' boundaries (a wrong N makes the step jump where FF wraps); where
  several fit (a take that crosses no boundary), 60, the app's. The fraction accumulates (the
  phone samples at about 59.96 frames/s on a 60 frames/s clock), so FF skips a number now and
  then without a frame lost: the times, not the row count, say where the frames are.
* the curves are resampled linearly onto a uniform grid at N frames/s from the first row's time
  (frame 0 = the first row = time 0 of the take's audio, where the app's own .mov starts); a
  stretch between rows more than ``max_interpolated_s`` apart, or a row with an empty or NaN
  cell, is a gap (NaN). Weights beyond 0..1 are clipped (with a note); an infinite value, a head
  angle beyond 2 pi, a cell that is not a number, a row cut short and a timecode that is broken
  or does not come after the previous row's are refused in one sentence naming the line and
  column.
"""

from __future__ import annotations

import csv
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from scipy.spatial.transform import Rotation

from facesynth.base.errors import InputError

#: The head and eye rotation columns after the blendshapes, in the app's order.
ROTATION_COLUMNS = ("HeadYaw", "HeadPitch", "HeadRoll", "LeftEyeYaw", "LeftEyePitch", "LeftEyeRoll",
                    "RightEyeYaw", "RightEyePitch", "RightEyeRoll")


def columns(arkit_names) -> list[str]:
    """The header: Timecode, BlendShapeCount, the 52 ARKit names capitalized, the 9 rotations."""
    return ["Timecode", "BlendShapeCount"] + [n[0].upper() + n[1:] for n in arkit_names] + list(ROTATION_COLUMNS)


def timecode(frame: int, fps: float) -> str:
    """``HH:MM:SS:FF.sss`` of ``frame`` at ``fps`` frames/s from 00:00:00:00.000."""
    t = frame / fps
    whole = int(np.floor(t + 1e-9))
    within = (t - whole) * fps
    ff = int(np.floor(within + 1e-6))
    sub = int(round((within - ff) * 1000))
    if sub >= 1000:
        ff, sub = ff + 1, 0
    h, rest = divmod(whole, 3600)
    m, s = divmod(rest, 60)
    return f"{h:02d}:{m:02d}:{s:02d}:{ff:02d}.{sub:03d}"


def head_angles(rotation: np.ndarray) -> np.ndarray:
    """(T, 3) radians (HeadYaw, HeadPitch, HeadRoll) of head rotations (T, 3, 3), mirrored as the
    module docstring says."""
    a, b, c = Rotation.from_matrix(np.asarray(rotation, np.float64)).as_euler("YXZ").T  # R = Ry(a) Rx(b) Rz(c)
    return np.stack([-a, b, -c], axis=1)


def eye_angles(gaze: np.ndarray) -> np.ndarray:
    """(T, 6) radians (LeftEyeYaw, LeftEyePitch, LeftEyeRoll, RightEyeYaw, RightEyePitch,
    RightEyeRoll) of facesynth's gaze (T, 2, 2): per eye (+x eye first) yaw toward +x, pitch up."""
    g = np.asarray(gaze, np.float64)
    zero = np.zeros(len(g))
    return np.stack([-g[:, 1, 0], -g[:, 1, 1], zero, -g[:, 0, 0], -g[:, 0, 1], zero], axis=1)


def write(path: Path, arkit_names, arkit: np.ndarray, fps: float, head: np.ndarray | None = None,
          eyes: np.ndarray | None = None) -> None:
    """Write a Live Link Face CSV.

    arkit : (T, 52) weights in [0, 1] in ``arkit_names`` order; head : optional (T, 3) radians
    (:func:`head_angles`), zeros when None; eyes : optional (T, 6) radians (:func:`eye_angles`),
    zeros when None. Values with ten decimals, as the app writes them."""
    arkit = np.clip(np.asarray(arkit, np.float64), 0.0, 1.0)
    n = len(arkit)
    head = np.zeros((n, 3)) if head is None else np.asarray(head, np.float64)
    eyes = np.zeros((n, 6)) if eyes is None else np.asarray(eyes, np.float64)
    values = np.concatenate([arkit, head, eyes], axis=1)
    count = values.shape[1]
    with open(path, "w", encoding="utf-8", newline="") as fh:
        fh.write(",".join(columns(arkit_names)) + "\n")
        for i in range(n):
            fh.write(f"{timecode(i, fps)},{count}," + ",".join(f"{v:.10f}" for v in values[i]) + "\n")


# ---------------------------------------------------------------- reading

#: Timecode rates a take may have been recorded at (frames/s).
STANDARD_RATES = (24, 25, 30, 48, 50, 60, 100, 120)
#: The app's rate, taken when the timecodes fit several rates.
APP_RATE = 60
#: Rows further apart than this (s) leave a gap instead of being interpolated across.
MAX_INTERPOLATED_S = 0.05
HEAD_COLUMNS = ROTATION_COLUMNS[:3]
_TIMECODE = re.compile(r"^\s*(\d{1,3}):(\d{2}):(\d{2})[:;](\d{1,3})(?:\.(\d+))?\s*$")
_DAY_S = 86400.0


@dataclass
class LiveLinkFaceTake:
    """A Live Link Face CSV on a uniform grid (see the module docstring).

    fps : the timecode rate (frames/s). arkit : (T, 52) float64 weights in [0, 1], in the
    ``arkit_names`` order :func:`read` was given, NaN rows where the take has a gap. head :
    (T, 3) radians (HeadYaw, HeadPitch, HeadRoll; NaN in gaps), None without head columns or
    when they never move. notes : what was assumed or repaired, one sentence each."""

    fps: float
    arkit: np.ndarray
    head: np.ndarray | None
    notes: list[str] = field(default_factory=list)


def is_live_link_face(path: Path) -> bool:
    """Whether the CSV at ``path`` has a Live Link Face header: a ``Timecode`` and a
    ``BlendShapeCount`` column, any case (its first line only is read)."""
    try:
        with open(path, encoding="utf-8-sig", errors="replace", newline="") as fh:
            first = fh.readline(1 << 16)
    except OSError:
        return False
    lower = {h.strip().lower() for h in next(csv.reader([first]), [])}
    return "timecode" in lower and "blendshapecount" in lower


def parse_timecode(cell: str) -> tuple[int, int, float] | None:
    """(whole seconds of the day, FF, fraction of a frame) of ``HH:MM:SS:FF.mmm``; None if it is not one."""
    m = _TIMECODE.match(cell)
    if m is None:
        return None
    hh, mm, ss, ff, sub = m.groups()
    if int(mm) > 59 or int(ss) > 59:
        return None
    return int(hh) * 3600 + int(mm) * 60 + int(ss), int(ff), float("0." + sub) if sub else 0.0


def timecode_rate(seconds: np.ndarray, frames: np.ndarray, fraction: np.ndarray, where: str) -> int:
    """The timecode rate N (frames/s) of rows with whole ``seconds``, frame numbers ``frames`` and
    frame fractions ``fraction`` (each (R,)): the standard rate above the largest frame number
    whose steps are most even (see the module docstring)."""
    top = int(frames.max())
    candidates = [n for n in STANDARD_RATES if n > top]
    if not candidates:
        raise InputError(f"{where}: the timecodes count frames up to {top}, more than any capture rate "
                         f"({STANDARD_RATES[-1]} frames/s); give the take's rate in the manifest's fps column.")
    if len(seconds) < 2:
        return APP_RATE if APP_RATE in candidates else candidates[0]
    scores = []
    for n in candidates:
        steps = np.diff(seconds + (frames + fraction) / n) * n  # in frames of n
        scores.append(int(np.sum(np.abs(steps - float(np.median(steps))) > 0.5)))
    fitting = [n for n, s in zip(candidates, scores) if s == min(scores)]
    return APP_RATE if APP_RATE in fitting else fitting[0]


def _resample(times: np.ndarray, values: np.ndarray, grid: np.ndarray, max_gap_s: float) -> np.ndarray:
    """(G, K) ``values`` (R, K) at the rows' ``times`` (R,) interpolated linearly at ``grid`` (G,);
    NaN between rows more than ``max_gap_s`` apart and next to a row holding a NaN."""
    if len(times) == 1:
        return np.repeat(values[:1], len(grid), axis=0)
    right = np.clip(np.searchsorted(times, grid, side="left"), 1, len(times) - 1)
    left = right - 1
    span = times[right] - times[left]
    w = np.clip((grid - times[left]) / span, 0.0, 1.0)[:, None]
    with np.errstate(invalid="ignore"):
        out = (1 - w) * values[left] + w * values[right]
    at_left = np.isclose(grid, times[left], rtol=0, atol=1e-9)
    at_right = np.isclose(grid, times[right], rtol=0, atol=1e-9)
    out = np.where(at_left[:, None], values[left], np.where(at_right[:, None], values[right], out))
    out[(span > max_gap_s + 1e-9) & ~at_left & ~at_right] = np.nan
    return out


def read(path: Path, arkit_names: Sequence[str], fps: float | None = None,
         max_interpolated_s: float = MAX_INTERPOLATED_S) -> LiveLinkFaceTake:
    """A Live Link Face CSV on a uniform grid at its timecode rate (see the module docstring).

    arkit_names : the 52 ARKit names (lower camel case) in the order wanted; fps : the timecode
    rate, None to find it from the timecodes. Refuses, in one sentence naming the file, line and
    column: a header without the columns, a cell that is not a finite number, a head angle beyond
    2 pi, a row cut short, a broken or backward timecode."""
    path = Path(path)
    with open(path, encoding="utf-8-sig", errors="replace", newline="") as fh:
        lines = list(enumerate(csv.reader(fh), 1))
    if not lines:
        raise InputError(f"{path}: the file is empty; export the take again from Live Link Face.")
    header = [h.strip() for h in lines[0][1]]
    while header and not header[-1]:
        header.pop()
    index = {h.lower(): k for k, h in enumerate(header)}
    if len(index) != len(header):
        repeated = next(h for h in header if sum(x.lower() == h.lower() for x in header) > 1)
        raise InputError(f"{path}, line 1: the column {repeated!r} appears twice; export the take again from Live "
                         "Link Face.")
    if "timecode" not in index or "blendshapecount" not in index:
        raise InputError(f"{path}, line 1: not a Live Link Face header (it needs the columns Timecode and "
                         "BlendShapeCount); export the take from the Live Link Face app.")
    missing = [n[0].upper() + n[1:] for n in arkit_names if n.lower() not in index]
    if missing:
        more = f" and {len(missing) - 3} more" if len(missing) > 3 else ""
        raise InputError(f"{path}, line 1: the Live Link Face header lacks the ARKit column(s) "
                         f"{', '.join(missing[:3])}{more}; export the take again with all 52 blendshapes.")
    curve_cols = [index[n.lower()] for n in arkit_names]
    head_cols = [index[c.lower()] for c in HEAD_COLUMNS if c.lower() in index]
    wanted = curve_cols + (head_cols if len(head_cols) == 3 else [])
    tc_col = index["timecode"]
    rows = [(n, r) for n, r in lines[1:] if any(c.strip() for c in r)]
    if not rows:
        raise InputError(f"{path}: the take has a header but no rows; export it again.")
    seconds, frames, fraction = np.zeros(len(rows)), np.zeros(len(rows), np.int64), np.zeros(len(rows))
    values = np.full((len(rows), len(wanted)), np.nan)
    last = max(wanted + [tc_col])
    for i, (line, row) in enumerate(rows):
        if len(row) <= last:
            raise InputError(f"{path}, line {line}: the row has {len(row)} cells but the header {len(header)}; the "
                             "file was cut short or edited: export the take again.")
        parsed = parse_timecode(row[tc_col])
        if parsed is None:
            raise InputError(f"{path}, line {line}, column Timecode: {row[tc_col].strip()!r} is not a timecode "
                             "HH:MM:SS:FF.mmm; repair that row's timecode or export the take again.")
        seconds[i], frames[i], fraction[i] = parsed
        for k, col in enumerate(wanted):
            cell = row[col].strip()
            if not cell or cell.lower() == "nan":
                continue  # a gap
            try:
                value = float(cell)
            except ValueError:
                raise InputError(f"{path}, line {line}, column {header[col]}: {cell!r} is not a number; repair the "
                                 "cell or export the take again.") from None
            if not np.isfinite(value) or (k >= len(curve_cols) and abs(value) > 2 * np.pi):
                what = "an angle in radians" if k >= len(curve_cols) else "a finite weight"
                raise InputError(f"{path}, line {line}, column {header[col]}: {cell!r} is not {what}; repair the "
                                 "cell or export the take again.")
            values[i, k] = value
    if fps is None:
        rate = float(timecode_rate(seconds, frames, fraction, f"{path}, column Timecode"))
    else:
        rate = float(fps)
        if frames.max() >= rate:
            line = rows[int(np.argmax(frames))][0]
            raise InputError(f"{path}, line {line}, column Timecode: frame {int(frames.max())} does not exist at "
                             f"{rate:g} frames/s; give the take's timecode rate in the manifest's fps column.")
    times = seconds + (frames + fraction) / rate
    times = times + np.concatenate([[0.0], np.cumsum(np.diff(times) < -_DAY_S / 2)]) * _DAY_S  # past midnight
    steps = np.diff(times)
    if (steps <= 0).any():
        k = int(np.argmax(steps <= 0))
        raise InputError(f"{path}, line {rows[k + 1][0]}, column Timecode: {rows[k + 1][1][tc_col].strip()!r} does "
                         f"not come after the previous row's {rows[k][1][tc_col].strip()!r}; the rows are out of "
                         "order or two takes are joined: export the take again.")
    notes = []
    n = len(curve_cols)
    curves = values[:, :n]
    with np.errstate(invalid="ignore"):
        outside = float(np.nanmax(np.abs(np.clip(curves, 0.0, 1.0) - curves))) if np.isfinite(curves).any() else 0.0
    if outside > 1e-3:
        notes.append(f"weights up to {outside:.3g} outside 0..1 were clipped")
    values[:, :n] = np.clip(curves, 0.0, 1.0)
    grid = times[0] + np.arange(int(np.floor((times[-1] - times[0]) * rate + 1e-6)) + 1) / rate
    sampled = _resample(times, values, grid, max_interpolated_s)
    gap = np.isnan(sampled).any(axis=1)
    sampled[gap] = np.nan
    if gap.any():
        notes.append(f"{int(gap.sum())} of {len(grid)} frames are gaps (no row within {max_interpolated_s:g} s, or "
                     "an empty cell)")
    head = None
    if len(wanted) > n:
        angles = sampled[:, n:]
        if np.nanmax(np.abs(angles), initial=0.0) > 0:
            head = angles
    else:
        notes.append("no HeadYaw, HeadPitch and HeadRoll columns: the take has no head motion")
    return LiveLinkFaceTake(rate, sampled[:, :n], head, notes)


def head_rotations(angles: np.ndarray) -> np.ndarray:
    """(T, 3, 3) head rotations in facesynth's frame from (T, 3) radians (HeadYaw, HeadPitch,
    HeadRoll) as the app records them (the inverse of :func:`head_angles`):
    ``R = Ry(-yaw) Rx(pitch) Rz(-roll)``; identity for a NaN row."""
    a = np.nan_to_num(np.asarray(angles, np.float64))
    return Rotation.from_euler("YXZ", np.stack([-a[:, 0], a[:, 1], -a[:, 2]], axis=1)).as_matrix()
