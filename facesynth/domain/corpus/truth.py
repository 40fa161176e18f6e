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
import re
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


#: The zeros ending a ``%.4f`` number, with its point when nothing is left after it.
_TRAILING_ZEROS = re.compile(r"\.?0+(?=[,\n]|$)")


def _number_rows(values: np.ndarray) -> list[str]:
    """values : (T, K) -> T lines of K comma-separated numbers, each rounded to four decimals
    (``%.4f``, correctly rounded), its trailing zeros and a bare point stripped, ``-0`` as ``0``.

    A ``%.4f`` text has exactly four decimals and a minus sign only in front, so ``-0.0000`` in
    the text is always a whole field (a negative number that rounds to zero); the stripping runs
    on the text of all the rows at once."""
    row_format = ",".join(["%.4f"] * values.shape[1])
    text = "\n".join(row_format % tuple(row) for row in np.asarray(values, np.float64).tolist())
    return _TRAILING_ZEROS.sub("", text.replace("-0.0000", "0.0000")).split("\n")


def write_truth(path: Path, rig: Rig, fps: float, weights: np.ndarray, emotion: list[str], intensity: np.ndarray) -> None:
    """Write one take's truth. weights : (T, E) rig weights; emotion : T labels; intensity : (T,).

    The rows are written as ``csv.writer`` writes them (``\\r\\n`` line ends); no field needs
    quoting (numbers and the emotion names)."""
    arkit = rig.to_arkit(weights)
    numbers = _number_rows(np.column_stack([intensity, weights, arkit]))
    with open(path, "w", newline="", encoding="utf-8") as fh:
        writer = csv.writer(fh)
        writer.writerow(["time_s", "emotion", "intensity"] + [f"rig:{n}" for n in rig.shape_names]
                        + [f"arkit:{n}" for n in rig.arkit_names])
        fh.write("".join(f"{t / fps:.6f},{emotion[t]},{numbers[t]}\r\n" for t in range(len(weights))))


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
