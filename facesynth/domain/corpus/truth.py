"""The truth of every frame of a sample-corpus take: ``groundtruth/<take>_truth.csv``.

One row per frame at the capture rate (120 Hz), columns:

* ``time_s``: the frame's time from the take's start;
* ``emotion``: the dominant emotion of the frame (``neutral``, ``happy``, ``angry``, ``sad``);
  it changes inside the takes whose emotion changes mid-sentence;
* ``intensity``: that emotion's weight in the frame times its intensity in the take (0..1;
  0 for neutral);
* ``rig:<shape>``: the 55 weights of the face rig (:mod:`facesynth.domain.rig.face`, ICT order);
* ``arkit:<name>``: the same pose as the 52 ARKit blendshapes (``Rig.to_arkit``, Live
  Link Face column order; ``tongueOut`` is 0).

Weights are written with four decimals, so the mesh ``rig.evaluate(weights)`` (mm) of the
file differs from the corpus's by at most 0.00005 x the sum of the shapes' largest
displacements. The head transform of each frame is in ``groundtruth/<take>_head.csv``
(row-major rotation ``r00..r22`` and translation ``tx, ty, tz`` in mm); the clean markers in
the head frame are ``groundtruth/<take>.c3d``.
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.errors import InputError
from facesynth.domain.rig.face import Rig


@dataclass
class TakeTruth:
    """One take's truth per frame.

    time_s : (T,) float64 s; emotion : T labels; intensity : (T,) float64;
    rig_weights : (T, 55) float64 in ``shape_names`` order; arkit_weights : (T, 52) float64
    in ``arkit_names`` order.
    """

    time_s: np.ndarray
    emotion: list[str]
    intensity: np.ndarray
    shape_names: tuple[str, ...]
    rig_weights: np.ndarray
    arkit_names: tuple[str, ...]
    arkit_weights: np.ndarray


def _number(v: float) -> str:
    text = f"{v:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("", "-0") else text


def write_truth(path: Path, rig: Rig, fps: float, weights: np.ndarray, emotion: list[str], intensity: np.ndarray) -> None:
    """Write one take's truth. weights : (T, E) rig weights; emotion : T labels; intensity : (T,)."""
    arkit = rig.to_arkit(weights)
    with open(path, "w", newline="", encoding="utf-8") as fh:
        writer = csv.writer(fh)
        writer.writerow(["time_s", "emotion", "intensity"] + [f"rig:{n}" for n in rig.shape_names]
                        + [f"arkit:{n}" for n in rig.arkit_names])
        for t in range(len(weights)):
            writer.writerow([f"{t / fps:.6f}", emotion[t], _number(intensity[t])]
                            + [_number(v) for v in weights[t]] + [_number(v) for v in arkit[t]])


def read_truth(path: Path) -> TakeTruth:
    """Read ``groundtruth/<take>_truth.csv``."""
    path = Path(path)
    if not path.exists():
        raise InputError(f"{path}: truth file not found; generate the corpus with facesynth sample-corpus.")
    with open(path, newline="", encoding="utf-8") as fh:
        reader = csv.reader(fh)
        header = next(reader, None)
        if not header or header[:3] != ["time_s", "emotion", "intensity"]:
            raise InputError(f"{path}: not a sample-corpus truth file (its first columns must be time_s, emotion, intensity).")
        rows = list(reader)
    rig_cols = [i for i, h in enumerate(header) if h.startswith("rig:")]
    arkit_cols = [i for i, h in enumerate(header) if h.startswith("arkit:")]
    values = np.array([[float(r[i]) for i in rig_cols + arkit_cols] for r in rows]).reshape(len(rows), -1)
    return TakeTruth(
        np.array([float(r[0]) for r in rows]), [r[1] for r in rows], np.array([float(r[2]) for r in rows]),
        tuple(header[i][4:] for i in rig_cols), values[:, : len(rig_cols)],
        tuple(header[i][6:] for i in arkit_cols), values[:, len(rig_cols):],
    )
