"""Three C3D readers on a folder of real files: facesynth's own decoder, ezc3d and ``c3d``.

    .venv/bin/python benchmarks/mocap_readers.py FOLDER [FOLDER...] > readers.json

Reads every ``*.c3d`` under the folders with each reader and prints JSON, one entry per file.
``mocap_readers.json`` holds the run on the c3d.org sample set (as ``tests/c3d_org_samples`` of
the biomechanics-foundation/c3dio repository keeps it), the ezc3d test files
(pyomeca/ezc3d-testFiles) and the C3D files of opensim-org/opensim-core, 106 files:

* ``facesynth``: what ``read_mocap`` gives (frames, markers, rate, left-out model outputs,
  NaN fraction), or the sentence it refuses the file with;
* ``ezc3d`` / ``c3d``: the frames and points each library reads, or its error (a file ezc3d
  refuses is read again with its ``ignore_bad_formatting``, only to compare values);
* ``agree_ezc3d`` / ``agree_c3d``: the largest difference (in the file's units) between
  facesynth's decoded points and the library's over the samples both call valid, and the number
  of samples whose validity (residual word not negative) they disagree on (needs the same frame
  and point counts);
* ``seconds``: each reader's time on the file (ezc3d's includes starting the child process
  it runs in, since it can crash the interpreter on a malformed file).

A summary counts, per reader, the files read and refused, and the files where the readers
disagree. ezc3d is optional (``pip install ezc3d``); without it its columns say so.
"""

from __future__ import annotations

import json
import logging
import subprocess
import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

from facesynth.base.errors import InputError
from facesynth.formats.c3dfile import read_points
from facesynth.formats.mocap import read_mocap


def _facesynth(path: Path) -> dict:
    try:
        take = read_mocap(path)
    except InputError as exc:
        return {"status": "refused", "reason": str(exc).replace(str(path), "FILE")}
    return {"status": "read", "frames": int(take.positions.shape[0]), "markers": len(take.names),
            "rate": take.fps, "left_out": len(take.left_out),
            "nan_fraction": round(float(np.isnan(take.positions).any(axis=2).mean()), 4)}


def _ezc3d_child(path: str, out: str) -> None:
    """Read ``path`` with ezc3d and save what it read to ``out`` (.npz); run in a child process,
    since ezc3d can crash the interpreter on a malformed file (it does with
    ``ignore_bad_formatting`` on one of the samples)."""
    import ezc3d

    lenient = sys.argv[-1] == "lenient"
    c = ezc3d.c3d(path, ignore_bad_formatting=lenient)
    np.savez(out, points=c["data"]["points"], residuals=c["data"]["meta_points"]["residuals"])


def _ezc3d(path: Path):
    try:
        import ezc3d  # noqa: F401
    except ImportError:
        return {"status": "absent"}, None
    result, error = None, None
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "ezc3d.npz"
        for mode in ("strict", "lenient"):
            run = subprocess.run([sys.executable, __file__, "--ezc3d-child", str(path), str(out), mode],
                                 check=False, capture_output=True, text=True, timeout=300)
            if run.returncode == 0:
                with np.load(out) as saved:
                    result = (saved["points"], saved["residuals"], mode == "lenient")
                break
            if error is None:
                lines = (run.stderr.strip().splitlines() or [f"crashed (exit status {run.returncode})"])
                error = lines[-1][:200]
    if result is None:
        return {"status": "error", "reason": error}, None
    points, residuals, lenient = result  # (4, n_points, n_frames), (1, n_points, n_frames)
    status = "read with ignore_bad_formatting (refused by default)" if lenient else "read"
    report = {"status": status, "frames": int(points.shape[2]), "points": int(points.shape[1])}
    if lenient:
        report["reason"] = error
    return report, (np.transpose(points[:3], (2, 1, 0)), np.transpose(residuals[0], (1, 0)))


def _c3d(path: Path):
    import c3d

    try:
        with open(path, "rb") as fh, warnings.catch_warnings():
            warnings.simplefilter("ignore")
            reader = c3d.Reader(fh)
            frames = [np.array(points[:, :4], np.float64) for _, points, _ in reader.read_frames(copy=False)]
            report = {"status": "read", "frames": len(frames), "points": int(reader.point_used),
                      "labels": len(reader.point_labels)}
    except Exception as exc:  # noqa: BLE001 - the library raises anything from AssertionError to struct.error
        return {"status": "error", "reason": f"{type(exc).__name__}: {str(exc)[:160]}"}, None
    values = np.stack(frames) if frames else np.zeros((0, 0, 4))
    return report, (values[:, :, :3], values[:, :, 3])


def _agreement(path: Path, ez) -> dict | None:
    if ez is None:
        return None
    try:
        points = read_points(path)
    except InputError:
        return None
    xyz, residuals = ez
    if xyz.shape != points.xyz.shape:
        return {"same_shape": False, "ezc3d": list(xyz.shape), "facesynth": list(points.xyz.shape)}
    ours_valid = (points.residual_word >= 0) & np.isfinite(points.xyz).all(axis=2)
    theirs_valid = np.isfinite(xyz).all(axis=2) & (residuals >= 0)
    both = ours_valid & theirs_valid
    diff = float(np.abs(points.xyz[both] - xyz[both]).max()) if both.any() else 0.0
    return {"same_shape": True, "max_abs_diff": diff, "validity_disagrees": int((ours_valid != theirs_valid).sum()),
            "samples": int(ours_valid.size)}


def main(folders: list[str]) -> None:
    logging.getLogger("facesynth").setLevel(logging.ERROR)
    files = sorted(p for folder in folders for p in Path(folder).rglob("*") if p.suffix.lower() == ".c3d")
    rows, summary = [], {"files": len(files)}
    for path in files:
        row = {"file": str(path.relative_to(path.parents[1])), "bytes": path.stat().st_size, "seconds": {}}
        start = time.perf_counter()
        row["facesynth"] = _facesynth(path)
        row["seconds"]["facesynth"] = round(time.perf_counter() - start, 4)
        start = time.perf_counter()
        row["ezc3d"], ez = _ezc3d(path)
        row["seconds"]["ezc3d"] = round(time.perf_counter() - start, 4)
        start = time.perf_counter()
        row["c3d"], lib = _c3d(path)
        row["seconds"]["c3d"] = round(time.perf_counter() - start, 4)
        row["agree_ezc3d"] = _agreement(path, ez)
        row["agree_c3d"] = _agreement(path, lib)
        rows.append(row)
    for reader in ("facesynth", "ezc3d", "c3d"):
        summary[reader] = {status: sum(r[reader]["status"] == status for r in rows)
                           for status in sorted({r[reader]["status"] for r in rows})}
    for reader in ("ezc3d", "c3d"):
        agree = [r[f"agree_{reader}"] for r in rows if r[f"agree_{reader}"]]
        summary[f"{reader}_compared"] = len(agree)
        summary[f"{reader}_other_shape"] = sum(not a["same_shape"] for a in agree)
        summary[f"{reader}_values_differ"] = sum(a["same_shape"] and a["max_abs_diff"] > 0.01 for a in agree)
        summary[f"{reader}_validity_differs"] = sum(a["same_shape"] and a["validity_disagrees"] > 0 for a in agree)
    print(json.dumps({"summary": summary, "files": rows}, indent=1))


if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] == "--ezc3d-child":
        _ezc3d_child(sys.argv[2], sys.argv[3])
        sys.exit(0)
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
