"""Writes ``expected.json``: the values of every capture file here, read without facesynth.

    .venv/bin/python tests/formats/captures/reference.py     # needs ezc3d and c3d

Each C3D file is read by the reader that reads it right (see README.md): ezc3d where it does,
the ``c3d`` library where ezc3d misreads and it does not, and otherwise :func:`decode_c3d`, a
plain ``struct`` decoding written for these files alone (header, the few parameters it needs
and the data block, nothing shared with facesynth's reader). TRC files are parsed with the
``csv`` module. From those values the script writes, per file: frames, markers, frame rate,
left-out model outputs, the fraction of missing samples and the coordinates (mm) of three
markers at three frames each, which ``test_real_captures.py`` compares with facesynth's.
A missing sample is one whose residual is negative, or that is NaN or exactly (0, 0, 0).
"""

from __future__ import annotations

import csv
import json
import struct
import sys
import warnings
from pathlib import Path

import numpy as np

HERE = Path(__file__).parent
MODEL_OUTPUTS = ("ANGLES", "FORCES", "MOMENTS", "POWERS", "SCALARS", "REACTIONS")
MM = {"mm": 1.0, "m": 1000.0, "mete": 1000.0, "cm": 10.0}

#: file -> (how to read it, writer) ; "refuse" files hold the words facesynth's message must contain
C3D = {
    "pc_real.c3d": ("ezc3d", "AMASS / Vicon 370, Intel float"),
    "dec_real.c3d": ("ezc3d", "AMASS / Vicon 370, DEC float"),
    "dec_int.c3d": ("ezc3d", "AMASS / Vicon 370, DEC integer"),
    "sgi_real.c3d": ("c3d", "AMASS / Vicon 370, SGI float (ezc3d: MIPS not supported)"),
    "sgi_int.c3d": ("c3d", "AMASS / Vicon 370, SGI integer (ezc3d: MIPS not supported)"),
    "gait-pig.c3d": ("ezc3d", "Vicon Plug-in Gait, DEC integer, model outputs"),
    "Capture0002.c3d": ("ezc3d", "Qualisys, invalid samples as residual 65535.0 at (0, 0, 0)"),
    "admarche2.c3d": ("ezc3d", "Biogesta, residual words stored as integers in float fields"),
    "evart.c3d": ("struct", "Motion Analysis EVaRT, 17 analog samples a frame (ezc3d takes 16)"),
    "kyowadengyo.c3d": ("struct", "Vicon with Kyowa Dengyo plates, POINT:USED 12 for 11 points (ezc3d reads 12)"),
    "FP1.C3D": ("ezc3d", "Peak Performance, POINT:UNITS 'mete', ANALOG:USED disagrees with the header"),
    "type1.C3D": ("c3d", "BTS (corrected by c3d.org), no ANALOG:RATE (ezc3d drops the analog samples)"),
    "MACsample.c3d": ("struct", "Motion Analysis (early), SGI integer, 'mm\\0\\0', four-letter labels repeated"),
    "Facial-Sing.c3d": ("struct", "NaturalPoint ARENA, facial capture, parameter offsets without description byte"),
    "labels2.c3d": ("ezc3d", "ezc3d 1.7.2 writer, 300 points (POINT:LABELS2)"),
}
C3D_REFUSED = {
    "basketball.c3d": ("SIMI, every residual -1", "marked invalid"),
}
TRC = {
    "init100.trc": ("OpenSim Gait2354 scale data: rows ending in a tab, no final line break", None),
    "std_walking5_markers.trc": ("OpenSim test data: header 250 Hz, Time column 25 Hz", 25.0),
    "exampleFormat.trc": ("OpenSim test data: blank cells, no final line break", None),
    "dataWithEformat.trc": ("OpenSim test data: E-notation, header lines padded with tabs", None),
    "dataWithNaNsOfDifferentCases.trc": ("OpenSim test data: NaN, nan, NAN cells", None),
    "gait10dof18musc_walk_CRLF_line_ending.trc": ("OpenSim test data (tested with CRLF line ends)", None),
    "subject01_synthetic_marker_data.trc": ("OpenSim IK test data: names one column off, metres", None),
    "markers_walk.trc": ("OpenSim Moco example: header values separated by two tabs", None),
    "walk_free_01.trc": ("OpenSim Matlab example: NumFrames 900 kept from the trial, 73 rows", None),
}


def decode_c3d(path: Path) -> dict:
    """The points of a C3D file by plain struct reads: the header's counts, the processor type
    and POINT:LABELS/DESCRIPTIONS/UNITS/SCALE found by walking the parameter section."""
    data = path.read_bytes()
    param = (data[0] - 1) * 512
    processor = {84: "Intel", 85: "DEC", 86: "SGI"}[data[param + 3]]
    end = ">" if processor == "SGI" else "<"

    def f32(raw: bytes) -> float:
        if processor == "DEC":
            return struct.unpack("<f", raw[2:4] + raw[0:2])[0] / 4
        return struct.unpack(end + "f", raw)[0]

    n_points, analog, first, last = struct.unpack(end + "4H", data[2:10])
    data_start = struct.unpack(end + "H", data[16:18])[0]
    params, groups, pos = {}, {}, param + 4
    while True:
        n = abs(struct.unpack("b", data[pos : pos + 1])[0])
        gid = struct.unpack("b", data[pos + 1 : pos + 2])[0]
        if n == 0:
            break
        name = data[pos + 2 : pos + 2 + n].decode("latin-1").upper()
        offset = struct.unpack(end + "H", data[pos + 2 + n : pos + 4 + n])[0]
        body = pos + 4 + n
        if gid < 0:
            groups[-gid] = name
        else:
            kind = struct.unpack("b", data[body : body + 1])[0]
            dims = list(data[body + 2 : body + 2 + data[body + 1]])
            start = body + 2 + len(dims)
            size = abs(kind) * int(np.prod(dims)) if dims else abs(kind)
            params[(gid, name)] = (kind, dims, data[start : start + size])
        if offset == 0:
            break
        pos = body - 2 + offset
    named = {f"{groups[g]}:{n}": v for (g, n), v in params.items()}

    def strings(key: str) -> list[str]:
        if key not in named:
            return []
        _, dims, raw = named[key]
        width = dims[0] if dims else len(raw)
        if width == 0:
            return []
        return [raw[i : i + width].decode("latin-1").strip(" \x00") for i in range(0, len(raw), width)]

    kind, _, raw = named["POINT:SCALE"]
    scale = f32(raw)
    value = 4 if scale < 0 else 2
    stride = (4 * n_points + analog) * value
    frames = last - first + 1
    xyz = np.zeros((frames, n_points, 3))
    residual = np.zeros((frames, n_points))
    base = (data_start - 1) * 512
    for i in range(frames):
        for j in range(n_points):
            at = base + i * stride + j * 4 * value
            if value == 4:
                words = [f32(data[at + 4 * k : at + 4 * k + 4]) for k in range(4)]
                residual[i, j] = struct.unpack(end + "h", struct.pack(end + "H", int(words[3]) & 0xFFFF))[0] \
                    if words[3] == int(words[3]) else words[3]
            else:
                words = list(struct.unpack(end + "4h", data[at : at + 8]))
                words[:3] = [w * scale for w in words[:3]]
                residual[i, j] = words[3]
            xyz[i, j] = words[:3]
    rate = f32(named["POINT:RATE"][2])
    return {"xyz": xyz, "residual": residual, "labels": strings("POINT:LABELS")[:n_points],
            "descriptions": strings("POINT:DESCRIPTIONS")[:n_points], "unit": strings("POINT:UNITS")[0],
            "rate": rate, "outputs": [s for g in MODEL_OUTPUTS for s in strings(f"POINT:{g}")]}


def read_ezc3d(path: Path) -> dict:
    import ezc3d

    c = ezc3d.c3d(str(path))
    point = c["parameters"]["POINT"]
    labels = list(point["LABELS"]["value"]) + [s for k in range(2, 10) for s in point.get(f"LABELS{k}", {}).get("value", [])]
    xyz = np.transpose(c["data"]["points"][:3], (2, 1, 0))
    residual = np.transpose(c["data"]["meta_points"]["residuals"][0], (1, 0))
    outputs = [s for g in MODEL_OUTPUTS for s in point.get(g, {}).get("value", [])]
    return {"xyz": xyz, "residual": residual, "labels": [s.strip() for s in labels[: xyz.shape[1]]],
            "descriptions": [], "unit": point["UNITS"]["value"][0].strip(), "rate": float(point["RATE"]["value"][0]),
            "outputs": [s.strip() for s in outputs]}


def read_c3d_library(path: Path) -> dict:
    import c3d

    with open(path, "rb") as fh, warnings.catch_warnings():
        warnings.simplefilter("ignore")
        reader = c3d.Reader(fh)
        frames = [np.array(p[:, :4], np.float64) for _, p, _ in reader.read_frames(copy=False)]
        group = reader.get("POINT")
        outputs = []
        for g in MODEL_OUTPUTS:
            p = group.get(g)
            if p is not None:
                outputs += [s.strip() for s in p.string_array]
        unit = group.get("UNITS").string_value.strip(" \x00")
        labels = [s.strip() for s in reader.point_labels][: int(reader.point_used)]  # the library keeps them all
        rate = float(reader.point_rate)
    values = np.stack(frames)
    return {"xyz": values[:, :, :3], "residual": values[:, :, 3], "labels": labels, "descriptions": [],
            "unit": unit, "rate": rate, "outputs": outputs}


def _c3d_entry(name: str, how: str, writer: str) -> dict:
    path = HERE / name
    got = {"ezc3d": read_ezc3d, "c3d": read_c3d_library, "struct": decode_c3d}[how](path)
    xyz = got["xyz"] * MM[got["unit"].lower()]
    missing = (got["residual"] < 0) | ~np.isfinite(xyz).all(axis=2) | np.all(xyz == 0, axis=2)
    labels, descriptions = got["labels"], got["descriptions"]
    keep = [j for j, label in enumerate(labels) if label not in set(got["outputs"])]
    names = []
    for j in keep:  # a label repeated by trajectories that differ takes the point's description
        repeated = sum(labels[k] == labels[j] for k in keep) > 1
        names.append(descriptions[j] if repeated and descriptions else labels[j])
    samples = []
    seen = [j for j in keep if not missing[:, j].all()]
    for j in (seen[0], seen[len(seen) // 2], seen[-1]):
        valid = np.flatnonzero(~missing[:, j])
        for i in (valid[0], valid[len(valid) // 2], valid[-1]):
            samples.append([int(i), names[keep.index(j)], *[round(float(v), 4) for v in xyz[i, j]]])
        gaps = np.flatnonzero(missing[:, j])
        if gaps.size:
            samples.append([int(gaps[0]), names[keep.index(j)], None, None, None])
    return {"writer": writer, "reference": how, "frames": int(xyz.shape[0]), "markers": len(keep),
            "rate": round(got["rate"], 4), "left_out": len(labels) - len(keep),
            "nan_fraction": round(float(missing[:, keep].mean()), 6), "samples": samples}


def _trc_entry(name: str, writer: str, rate: float | None) -> dict:
    lines = (HERE / name).read_text("utf-8").splitlines()
    keys = [k for k in lines[1].split("\t") if k.strip()]
    values = [v.strip() for v in lines[2].split("\t") if v.strip()]
    meta = dict(zip(keys, values))
    names = [n.strip() for n in lines[3].split("\t")[2:] if n.strip()]
    rows = [r for r in csv.reader(lines[5:], delimiter="\t") if any(c.strip() for c in r)]
    xyz = np.full((len(rows), len(names), 3), np.nan)
    for i, row in enumerate(rows):
        for k, cell in enumerate(row[2 : 2 + 3 * len(names)]):
            if cell.strip() and cell.strip().lower() != "nan":
                xyz[i, k // 3, k % 3] = float(cell)
    xyz *= MM[meta["Units"].lower()]
    missing = np.isnan(xyz).any(axis=2)
    samples = []
    for j in (0, len(names) // 2, len(names) - 1):
        valid = np.flatnonzero(~missing[:, j])
        for i in (valid[0], valid[len(valid) // 2], valid[-1]) if valid.size else ():
            samples.append([int(i), names[j], *[round(float(v), 4) for v in xyz[i, j]]])
    return {"writer": writer, "reference": "csv", "frames": len(rows), "markers": len(names),
            "rate": rate if rate is not None else float(meta["DataRate"]), "left_out": 0,
            "nan_fraction": round(float(missing.mean()), 6), "samples": samples}


def main() -> None:
    expected = {}
    for name, (how, writer) in C3D.items():
        expected[name] = _c3d_entry(name, how, writer)
    for name, (writer, words) in C3D_REFUSED.items():
        expected[name] = {"writer": writer, "refused": words}
    for name, (writer, rate) in TRC.items():
        expected[name] = _trc_entry(name, writer, rate)
    (HERE / "expected.json").write_text(json.dumps(expected, indent=1) + "\n")
    print(f"wrote {len(expected)} entries", file=sys.stderr)


if __name__ == "__main__":
    main()
