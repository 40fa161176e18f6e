"""The marker data of a C3D file, decoded from its header, parameters and 3D data block.

A C3D file (https://www.c3d.org/docs/C3D_User_Guide.pdf) is a sequence of 512-byte blocks:
block 1 is the header, the parameter section starts at the block the header's first byte
names, and the data block at the block header word 9 names (``POINT:DATA_START`` repeats it). Each
frame of the data block holds, for every point, X, Y, Z and a residual word, then the frame's
analog samples, all as 16-bit integers (times ``POINT:SCALE``) or 32-bit floats. The byte
order and float format follow the processor type of the parameter section: Intel
(little-endian IEEE), DEC (little-endian words, VAX F floats) or SGI/MIPS (big-endian IEEE).

Only what a marker take needs is read. The stride of a frame (points and analog samples) comes
from the header and the size of the data block, never from the analog parameters alone
(``ANALOG:RATE``, ``ANALOG:OFFSET``, ``ANALOG:USED``), which many writers get wrong or leave
out; the number of points, frames and the data start are the header's. Every liberty taken with
a file that is not as the standard says is recorded in :attr:`C3dPoints.notes`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from facesynth.base.errors import InputError

BLOCK = 512
#: The parameter section's 4th byte: 83 + processor type.
PROCESSORS = {84: "Intel", 85: "DEC", 86: "SGI"}
#: The POINT parameters that list model outputs (computed values stored as points).
MODEL_OUTPUT_GROUPS = ("ANGLES", "FORCES", "MOMENTS", "POWERS", "SCALARS", "REACTIONS")


@dataclass
class C3dParameter:
    """One parameter: ``kind`` is -1 (characters), 1 (byte), 2 (int16) or 4 (float32);
    ``dims`` as stored (the first dimension varies fastest); ``raw`` its data bytes."""

    kind: int
    dims: tuple[int, ...]
    raw: bytes


@dataclass
class C3dPoints:
    """The 3D points of a C3D file.

    xyz : (n_frames, n_points, 3) float64, the file's length unit, as stored (times
        ``POINT:SCALE`` for integer files).
    residual_word : (n_frames, n_points) int32, the 16-bit residual word (negative: invalid).
    labels : n_points names (stripped of spaces and NULs; "" where the file has none).
    rate : frames per second (``POINT:RATE``, or the header's when that is absent).
    unit : ``POINT:UNITS`` stripped ("" when absent).
    processor : "Intel", "DEC" or "SGI".
    storage : "float" or "integer".
    groups : parameter values by "GROUP:NAME" (decoded: list of str, or ndarray).
    notes : one sentence per liberty taken with a file that is not as the standard says.
    """

    xyz: np.ndarray
    residual_word: np.ndarray
    labels: list[str]
    rate: float
    unit: str
    processor: str
    storage: str
    groups: dict = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)


def _refuse(path: Path, what: str) -> InputError:
    return InputError(f"{path}: {what}; re-export it from the capture software.")


def _signed_byte(value: int) -> int:
    return value - 256 if value > 127 else value


def _dec_float(raw: np.ndarray) -> np.ndarray:
    """VAX F floats (PDP-endian words, exponent bias 128 with a hidden 0.1 bit) to IEEE:
    swapping the two 16-bit words gives the IEEE bit layout at 4 times the value."""
    swapped = raw.reshape(-1, 4)[:, [2, 3, 0, 1]].copy()
    return swapped.view("<f4").reshape(-1).astype(np.float64) / 4.0


class _Decoder:
    """Numbers in the byte order and float format of one processor type."""

    def __init__(self, processor: str):
        self.processor = processor
        self.end = ">" if processor == "SGI" else "<"

    def int16(self, raw: bytes) -> np.ndarray:
        return np.frombuffer(raw, self.end + "i2").astype(np.int64)

    def uint16(self, raw: bytes) -> np.ndarray:
        return np.frombuffer(raw, self.end + "u2").astype(np.int64)

    def float32(self, raw: bytes) -> np.ndarray:
        with np.errstate(invalid="ignore"):  # signalling NaNs (a corrupt or Biogesta file) stay NaN
            if self.processor == "DEC":
                return _dec_float(np.frombuffer(raw, np.uint8))
            return np.frombuffer(raw, self.end + "f4").astype(np.float64)


def _parse_parameters(data: bytes, start: int, stop: int, dec: _Decoder) -> tuple[dict, list[str]]:
    """Parameters of the section ``data[start:stop]`` as {"GROUP:NAME": C3dParameter}. The walk
    stops at a zero name length, a zero offset or the end of the section (writers differ)."""
    groups: dict[int, str] = {}
    pending: list[tuple[int, str, C3dParameter]] = []
    notes: list[str] = []
    pos = start + 4
    while pos + 2 <= stop:
        n_chars = abs(_signed_byte(data[pos]))
        group_id = _signed_byte(data[pos + 1])
        if n_chars == 0:
            break
        name = data[pos + 2 : pos + 2 + n_chars].decode("latin-1").strip(" \x00").upper()
        at = pos + 2 + n_chars
        if at + 2 > stop:
            break
        offset = int(dec.uint16(data[at : at + 2])[0])
        body = at + 2
        if group_id < 0:
            groups[-group_id] = name
        elif group_id > 0:
            try:
                kind = _signed_byte(data[body])
                n_dims = data[body + 1]
                dims = tuple(data[body + 2 : body + 2 + n_dims])
                if kind not in (-1, 1, 2, 4) or len(dims) != n_dims:
                    raise ValueError
                size = abs(kind) * int(np.prod(dims, dtype=np.int64)) if n_dims else abs(kind)
                first = body + 2 + n_dims
                if first + size > len(data):
                    raise ValueError
                pending.append((group_id, name, C3dParameter(kind, dims, data[first : first + size])))
            except (ValueError, IndexError):
                notes.append(f"parameter {name} of group {group_id} is malformed and was skipped")
        if offset == 0:
            break
        pos = at + offset
    params = {}
    for group_id, name, param in pending:
        group = groups.get(group_id)
        if group is None:
            continue
        # a group written twice (Vicon Nexus writes an empty second PROCESSING): the first keeps its values
        params.setdefault(f"{group}:{name}", param)
    return params, notes


def _strings(param: C3dParameter) -> list[str]:
    """A character parameter as its strings, stripped of spaces and NULs."""
    raw = param.raw
    if not param.dims:
        return [raw.decode("latin-1").strip(" \x00")]
    width = param.dims[0]
    count = int(np.prod(param.dims[1:], dtype=np.int64)) if len(param.dims) > 1 else 1
    if width == 0:
        return [""] * count
    return [raw[k * width : (k + 1) * width].decode("latin-1").strip(" \x00") for k in range(count)]


def _numbers(param: C3dParameter, dec: _Decoder) -> np.ndarray:
    """A numeric parameter as a flat float64 array (bytes unsigned, as the standard keeps them)."""
    if param.kind == 1:
        return np.frombuffer(param.raw, np.uint8).astype(np.float64)
    if param.kind == 2:
        return dec.int16(param.raw).astype(np.float64)
    if param.kind == 4:
        return dec.float32(param.raw)
    raise ValueError("characters")


def _number(params: dict, key: str, dec: _Decoder, unsigned: bool = False) -> float | None:
    """The first value of a numeric parameter, or None when absent or not numeric."""
    param = params.get(key)
    if param is None or param.kind == -1 or not param.raw:
        return None
    if unsigned and param.kind == 2:
        return float(dec.uint16(param.raw[:2])[0])
    values = _numbers(param, dec)
    return float(values[0]) if values.size else None


def _labels(params: dict, used: int) -> list[str] | None:
    """POINT:LABELS, LABELS2, LABELS3... joined and cut to ``used``; None without POINT:LABELS."""
    if "POINT:LABELS" not in params:
        return None
    labels = []
    for k in range(1, 1000):
        key = "POINT:LABELS" if k == 1 else f"POINT:LABELS{k}"
        if key not in params or len(labels) >= used:
            break
        param = params[key]
        labels += _strings(param) if param.kind == -1 else []
    return labels[:used]


def read_points(path: Path) -> C3dPoints:
    """Decode the 3D points of the C3D file at ``path`` (see the module docstring).

    Raises InputError, one sentence naming the file, for anything that is not a C3D file or
    whose 3D data cannot be located with certainty (no parameter section, a data block that
    ends before its last frame, a frame count or stride the header cannot give).
    """
    path = Path(path)
    data = path.read_bytes()
    if len(data) < 2 * BLOCK or data[1] != 0x50:
        raise _refuse(path, "not a C3D file (its second byte is not 0x50)")
    param_block = data[0]
    param_start = (param_block - 1) * BLOCK
    if param_block < 2 or param_start + 4 > len(data):
        raise _refuse(path, f"the header points to parameter block {param_block}, outside the file")
    processor_byte = data[param_start + 3]
    if processor_byte not in PROCESSORS:
        raise _refuse(path, f"unknown processor type {processor_byte} in the parameter section (84 Intel, 85 DEC, 86 SGI)")
    dec = _Decoder(PROCESSORS[processor_byte])
    header_words = dec.uint16(data[:BLOCK])
    n_points = int(header_words[1])
    analog_per_frame = int(header_words[2])
    first_frame, last_frame = int(header_words[3]), int(header_words[4])
    header_scale = float(dec.float32(data[12:16])[0])
    header_data_start = int(header_words[8])
    header_rate = float(dec.float32(data[20:24])[0])

    n_param_blocks = data[param_start + 2]
    param_stop = min(len(data), param_start + max(n_param_blocks, 1) * BLOCK)
    if header_data_start > param_block:
        param_stop = max(param_stop, min(len(data), (header_data_start - 1) * BLOCK))
    params, notes = _parse_parameters(data, param_start, param_stop, dec)

    if n_points == 0:
        raise InputError(f"{path}: the file holds no 3D points (only analog data), so there are no markers to read; "
                         "export the marker trajectories.")
    used = _number(params, "POINT:USED", dec, unsigned=True)
    if used is not None and int(used) != n_points:
        notes.append(f"POINT:USED says {int(used)} points but the header {n_points}; the header's count was used")
    scale = _number(params, "POINT:SCALE", dec)
    if scale is None or scale == 0:
        scale = header_scale
    if scale == 0 or not np.isfinite(scale):
        raise _refuse(path, "POINT:SCALE and the header's scale are both zero, so the storage type is unknown")
    storage = "float" if scale < 0 else "integer"
    rate = _number(params, "POINT:RATE", dec)
    if rate is None or not rate > 0:
        rate = header_rate
    declared_start = _number(params, "POINT:DATA_START", dec, unsigned=True)
    if declared_start is not None and int(declared_start) != header_data_start:
        notes.append(f"POINT:DATA_START ({int(declared_start)}) differs from the header's ({header_data_start}); "
                     "the header's was used")
    data_start = header_data_start

    n_frames = last_frame - first_frame + 1
    trial_end = params.get("TRIAL:ACTUAL_END_FIELD")
    trial_start = params.get("TRIAL:ACTUAL_START_FIELD")
    if (last_frame == 65535 and trial_end is not None and trial_start is not None and trial_end.kind == 2
            and trial_start.kind == 2 and len(trial_end.raw) >= 4 and len(trial_start.raw) >= 4):
        # more than 65535 frames: the header is saturated; TRIAL holds 32-bit frame numbers as two words
        end = dec.uint16(trial_end.raw[:4])
        begin = dec.uint16(trial_start.raw[:4])
        n_frames = int(end[0] + 65536 * end[1]) - int(begin[0] + 65536 * begin[1]) + 1
    if n_frames < 0:
        raise _refuse(path, f"the header's last frame ({last_frame}) is before its first ({first_frame})")

    value_size = 4 if storage == "float" else 2
    block_start = (data_start - 1) * BLOCK
    if data_start < 2 or block_start > len(data):
        raise _refuse(path, f"truncated C3D file: its 3D data is said to start at block {data_start}, past the end")
    analog_per_frame = _analog_per_frame(params, dec, analog_per_frame, n_points, n_frames, value_size,
                                         len(data) - block_start, notes)
    stride = (4 * n_points + analog_per_frame) * value_size
    available = (len(data) - block_start) // stride if stride else n_frames
    if available < n_frames:
        raise _refuse(path, f"truncated C3D file: its data block holds {available} of the {n_frames} frames "
                      f"the header declares ({n_points} points and {analog_per_frame} analog samples a frame)")
    labels = _labels(params, n_points)
    if labels is None:
        raise InputError(f"{path}: the file has no POINT:LABELS parameter, so its {n_points} points have no "
                         "names; export it again with marker labels.")
    if len(labels) < n_points:
        notes.append(f"the POINT:LABELS parameters name {len(labels)} of {n_points} points")
        labels += [""] * (n_points - len(labels))

    frames = np.frombuffer(data, np.uint8, count=n_frames * stride, offset=block_start).reshape(n_frames, stride)
    point_bytes = frames[:, : 4 * n_points * value_size]
    if storage == "float":
        values = dec.float32(point_bytes.tobytes()).reshape(n_frames, n_points, 4)
        xyz = values[:, :, :3]
        residual_word = _float_residual_word(values[:, :, 3], point_bytes, dec, notes)
    else:
        values = dec.int16(point_bytes.tobytes()).reshape(n_frames, n_points, 4)
        xyz = values[:, :, :3].astype(np.float64) * scale
        residual_word = values[:, :, 3].astype(np.int32)

    decoded = {}
    for key, param in params.items():
        try:
            decoded[key] = _strings(param) if param.kind == -1 else _numbers(param, dec)
        except ValueError:
            continue
    units = decoded.get("POINT:UNITS")
    unit = units[0] if isinstance(units, list) and units else ""
    return C3dPoints(np.ascontiguousarray(xyz, np.float64), residual_word, labels, float(rate), unit,
                     dec.processor, storage, decoded, notes)


def _analog_per_frame(params: dict, dec: _Decoder, header_count: int, n_points: int, n_frames: int,
                      value_size: int, block_bytes: int, notes: list[str]) -> int:
    """The analog samples stored per frame: the header's count (word 3), which fixes the stride of
    the data block. Writers pad the block to whole 512-byte blocks, so the header's count is taken
    when the block's size is its frames plus at most one block. Where it is not, and the count
    the analog parameters give (ANALOG:USED x ANALOG:RATE / POINT:RATE) fits the size exactly
    (MotionMonitor writes the channel count in the header), that count is taken; otherwise the
    header's, and a block too short for it is a truncated file."""

    def slack(count: int) -> int:
        return block_bytes - n_frames * (4 * n_points + count) * value_size

    if 0 <= slack(header_count) <= BLOCK:
        return header_count
    used = _number(params, "ANALOG:USED", dec, unsigned=True)
    analog_rate = _number(params, "ANALOG:RATE", dec)
    point_rate = _number(params, "POINT:RATE", dec)
    if used and analog_rate and point_rate and analog_rate > 0 and point_rate > 0:
        count = int(used) * round(analog_rate / point_rate)
        if count != header_count and 0 <= slack(count) <= BLOCK:
            notes.append(f"the header's {header_count} analog samples a frame do not fit the size of the data block, "
                         f"but the {count} of the ANALOG parameters do; those were used")
            return count
    if slack(header_count) > BLOCK:
        notes.append(f"the data block is followed by {slack(header_count)} bytes that no frame of the header holds")
    return header_count


def _float_residual_word(fourth: np.ndarray, point_bytes: np.ndarray, dec: _Decoder, notes: list[str]) -> np.ndarray:
    """The residual word of a float file, (n_frames, n_points) int32, negative where invalid.

    The standard stores the word as a float of its value: -1.0, or 65535.0 for the same 16 bits
    unsigned (Qualisys), marks an invalid sample. Two writers differ: Biogesta puts the 16-bit
    word itself into the float's first two bytes (the float then reads as huge, infinite, NaN or
    denormal), and read back as an integer it is; MotionMonitor stores the residual as a
    fraction, whose sign alone is kept (negative invalid, else valid)."""
    tiny = np.finfo(np.float32).tiny
    finite = np.isfinite(fourth)
    integer_bytes = ~finite | (np.abs(np.where(finite, fourth, 0)) >= 65536) | ((fourth != 0) & (np.abs(fourth) < tiny))
    fraction = ~integer_bytes & (fourth != np.round(np.where(finite, fourth, 0)))
    words = _as_int16(np.where(integer_bytes | fraction, 0, fourth))
    if fraction.any():
        notes.append(f"{int(fraction.sum())} residual words are fractions (not whole words, as the standard "
                     "says); their sign was kept")
        words = np.where(fraction, np.where(fourth < 0, -1, 0), words)
    if integer_bytes.any():
        n_frames, n_points = fourth.shape
        raw = point_bytes.reshape(n_frames, n_points, 4, 4)[:, :, 3, :2]
        stored = dec.int16(np.ascontiguousarray(raw).tobytes()).reshape(n_frames, n_points)
        notes.append(f"{int(integer_bytes.sum())} residual words are 16-bit integers inside the float fields "
                     "(not floats, as the standard says); they were read as integers")
        words = np.where(integer_bytes, stored, words)
    return words.astype(np.int32)


def _as_int16(values: np.ndarray) -> np.ndarray:
    """Whole numbers (float) as the signed 16-bit words they write (65535 and -1 are both -1)."""
    return (values.astype(np.int64) & 0xFFFF).astype(np.uint16).view(np.int16).astype(np.int32)
