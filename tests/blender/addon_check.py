"""Helpers of the Blender add-on's tests: the add-on's Blender-free module and zip builder loaded
by path (the add-on is no part of the facesynth package), the facesynth command the tests run,
and what the add-on should key, worked out here from a curves artifact read with h5py."""

from __future__ import annotations

import importlib.util
import os
import shlex
import subprocess
import sys
from functools import lru_cache
from pathlib import Path

import h5py
import numpy as np

ROOT = Path(__file__).resolve().parents[2]
ADDON = ROOT / "blender" / "facesynth_blender"

#: Environment variable naming the facesynth command the tests give the add-on (default: the
#: ``facesynth`` beside this Python, as ``pip install`` puts it in .venv/bin).
EXECUTABLE_ENV = "FACESYNTH_EXECUTABLE"

#: ARKit shapes that ICT-FaceKit (the built-in rig) splits into _L/_R halves: one ARKit weight is
#: the mean of the two (docs/exports.md, arkit-csv).
SPLIT = ("browInnerUp", "cheekPuff")


def _load(name: str, path: Path):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module  # dataclasses look their module up
    spec.loader.exec_module(module)
    return module


@lru_cache(maxsize=1)
def core():
    """``blender/facesynth_blender/core.py``: the add-on's part that needs no Blender."""
    return _load("facesynth_blender_core", ADDON / "core.py")


@lru_cache(maxsize=1)
def make_zip():
    """``blender/make_zip.py``, which ``make blender-addon`` runs."""
    return _load("facesynth_blender_make_zip", ROOT / "blender" / "make_zip.py")


def facesynth_command(folder: Path) -> str:
    """The facesynth command for the add-on: ``$FACESYNTH_EXECUTABLE``, else the ``facesynth``
    beside this Python, else a launcher in ``folder`` that runs this installation's CLI."""
    override = os.environ.get(EXECUTABLE_ENV)
    if override:
        return override
    beside = Path(sys.executable).parent / "facesynth"
    if beside.is_file() and os.access(beside, os.X_OK):
        return str(beside)
    folder.mkdir(parents=True, exist_ok=True)
    launcher = folder / "facesynth"
    launcher.write_text(f"#!/bin/sh\nexec {shlex.quote(sys.executable)} -c "
                        "'from facesynth.cli import main; main(prog_name=\"facesynth\")' \"$@\"\n")
    launcher.chmod(0o755)
    return str(launcher)


def run(command: list, **kwargs) -> subprocess.CompletedProcess:
    result = subprocess.run([str(c) for c in command], capture_output=True, text=True, **kwargs)
    assert result.returncode == 0, f"{command}: {result.stderr or result.stdout}"
    return result


def read_curves(path: Path) -> dict:
    """A curves artifact as h5py reads it: ``weights`` (T, E), ``names``, ``fps``, and
    ``head_rotation`` (T, 3, 3) or None."""
    with h5py.File(path, "r") as f:
        weights = f["weights"][()].astype(np.float64)
        names = [n.decode() if isinstance(n, bytes) else str(n) for n in f["shape_names"][()]]
        head = f["head_rotation"][()].astype(np.float64) if "head_rotation" in f else None
        emotion = ([e.decode() if isinstance(e, bytes) else str(e) for e in f["provenance/emotion"][()]]
                   if "provenance/emotion" in f else None)
        return {"weights": weights, "names": names, "fps": float(f["weights"].attrs["fps"]), "head_rotation": head,
                "emotion": emotion}


def arkit_sources(arkit: str) -> list[str]:
    """The built-in rig's shapes whose mean is the ARKit weight ``arkit`` (ICT-FaceKit's spelling:
    sides as _L/_R; the split shapes as both halves; tongueOut has none)."""
    if arkit in SPLIT:
        return [f"{arkit}_L", f"{arkit}_R"]
    if arkit == "tongueOut":
        return []
    for side, suffix in (("Left", "_L"), ("Right", "_R")):
        if arkit.endswith(side) and arkit not in ("jawLeft", "jawRight", "mouthLeft", "mouthRight"):
            return [arkit[: -len(side)] + suffix]
    return [arkit]


def resampled(curves: dict, fps: float) -> tuple[np.ndarray, np.ndarray]:
    """(times (n,), source positions (n,)) of the curves at ``fps`` over their duration: frame i at
    i / fps, n = floor(duration x fps), as docs/exports.md says the export resamples."""
    count = len(curves["weights"])
    n = max(1, int(np.floor(count / curves["fps"] * fps + 1e-6)))
    times = np.arange(n) / fps
    return times, np.clip(times * curves["fps"], 0, count - 1)


def expected_arkit(curves: dict, fps: float) -> dict[str, np.ndarray]:
    """{ARKit name: (n,) weights at ``fps``}: linear interpolation of the rig's weights, then the
    mean of each ARKit shape's sources, clipped to [0, 1]."""
    _, src = resampled(curves, fps)
    lo = np.floor(src).astype(int)
    hi = np.minimum(lo + 1, len(curves["weights"]) - 1)
    a = (src - lo)[:, None]
    weights = (1 - a) * curves["weights"][lo] + a * curves["weights"][hi]
    index = {n: i for i, n in enumerate(curves["names"])}
    out = {}
    for name in core().ARKIT_NAMES:
        sources = arkit_sources(name)
        value = weights[:, [index[s] for s in sources]].mean(axis=1) if sources else np.zeros(len(weights))
        out[name] = np.clip(value, 0.0, 1.0)
    return out


def expected_head(curves: dict, fps: float) -> np.ndarray:
    """(n, 3, 3) the head rotations at ``fps`` (spherical interpolation), in facesynth's axes."""
    from scipy.spatial.transform import Rotation, Slerp

    times, _ = resampled(curves, fps)
    source_times = np.arange(len(curves["head_rotation"])) / curves["fps"]
    slerp = Slerp(source_times, Rotation.from_matrix(curves["head_rotation"]))
    return slerp(np.clip(times, 0, source_times[-1])).as_matrix()


#: facesynth's axes (+y up, the face toward +z) -> Blender's (+Z up, the face toward -Y).
TO_BLENDER = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])


def read_glb(path: Path) -> dict:
    """The mesh of a GLB that ``facesynth export --format glb`` wrote: ``positions`` (V, 3) m,
    ``indices`` (F, 3), ``targets`` (E, V, 3) m and their ``names`` (glTF's axes)."""
    import json
    import struct

    data = Path(path).read_bytes()
    (json_length,) = struct.unpack_from("<I", data, 12)
    doc = json.loads(data[20:20 + json_length])
    binary = data[20 + json_length + 8:]
    kinds = {5126: np.float32, 5125: np.uint32, 5123: np.uint16}
    widths = {"SCALAR": 1, "VEC3": 3, "VEC4": 4}

    def accessor(i: int) -> np.ndarray:
        acc = doc["accessors"][i]
        view = doc["bufferViews"][acc["bufferView"]]
        dtype, width = np.dtype(kinds[acc["componentType"]]), widths[acc["type"]]
        start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
        stride = view.get("byteStride") or dtype.itemsize * width
        rows = np.lib.stride_tricks.as_strided(np.frombuffer(binary, np.uint8, offset=start),
                                               (acc["count"], dtype.itemsize * width), (stride, 1))
        return np.ascontiguousarray(rows).view(dtype).reshape(acc["count"], width)

    mesh = doc["meshes"][0]
    [primitive] = mesh["primitives"]
    return {"positions": accessor(primitive["attributes"]["POSITION"]).astype(np.float64),
            "indices": accessor(primitive["indices"]).reshape(-1, 3).astype(np.int64),
            "targets": np.stack([accessor(t["POSITION"]) for t in primitive["targets"]]).astype(np.float64),
            "names": list(mesh["extras"]["targetNames"])}
