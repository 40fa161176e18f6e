"""Another rig's blendshape curves (FACEGOOD, Faceware, MetaHuman exports...) as a capture take:
the curves and their mapping to ARKit are read by :mod:`facesynth.formats.blendshape_curves`,
``ARKit = clip(curves @ mapping, 0, 1)`` poses the rig and its surface is recorded, as for a Live
Link Face take (:func:`facesynth.domain.capture.posing.pose_markers`). The take has no head motion.

A ``.npy`` is always curves; a ``.csv`` is curves when a mapping is given for the take (the
manifest's ``mapping`` column, or ``ingest.curves_mapping``) and its header is not a marker
CSV's (``time`` and ``<marker>_x/_y/_z`` columns). Channels that move (standard deviation over
:data:`MOVING_SD`) but that the mapping leaves out are named in a warning.
"""

from __future__ import annotations

import csv
import logging
from pathlib import Path

import numpy as np

from facesynth.base.errors import InputError
from facesynth.domain.rig.face import load_face_rig
from facesynth.formats.blendshape_curves import read_curves, read_mapping

from .posing import CaptureTake, posed_take
from .readers import CaptureOptions, CaptureReader

log = logging.getLogger(__name__)

#: A source channel whose standard deviation exceeds this (weight units) and that the mapping
#: leaves out is named in a warning.
MOVING_SD = 0.01


def arkit_weights(values: np.ndarray, matrix: np.ndarray) -> np.ndarray:
    """(T, 52) ARKit weights of curves ``values`` (T, C) through a mapping ``matrix`` (C, 52):
    clipped to [0, 1]; a frame with a NaN channel is a gap (NaN)."""
    gap = np.isnan(values).any(axis=1)
    arkit = np.clip(np.where(gap[:, None], 0.0, values) @ matrix, 0.0, 1.0)
    arkit[gap] = np.nan
    return arkit


def read_curve_take(path: Path, options: CaptureOptions) -> CaptureTake:
    """Another rig's curves at ``path`` as markers of ``options.rig`` (None: the built-in rig),
    mapped to ARKit by ``options.mapping``, at the file's rate or ``options.fps``."""
    path = Path(path)
    if options.mapping is None:
        raise InputError(f"{path}: another rig's curves need a mapping to ARKit; give a CSV of source,arkit,weight "
                         "in the manifest's mapping column or with --set ingest.curves_mapping=FILE.")
    values, channels, rate = read_curves(path, options.names, options.fps)
    if len(values) == 0:
        raise InputError(f"{path}: the take has no frames; export it again or drop it from the manifest.")
    matrix = read_mapping(options.mapping, channels, load_face_rig().arkit_names, str(path))
    arkit = arkit_weights(values, matrix)
    notes = []
    with np.errstate(invalid="ignore"):
        spread = np.nanstd(values, axis=0) if (~np.isnan(values)).any() else np.zeros(len(channels))
    unmapped = [(channels[k], float(spread[k])) for k in np.argsort(-spread) if spread[k] > MOVING_SD
                and not matrix[k].any()]
    if unmapped:
        listed = ", ".join(f"{n} (sd {s:.2f})" for n, s in unmapped[:4])
        notes.append(f"{len(unmapped)} moving channel(s) drive no ARKit shape in {Path(options.mapping).name}: {listed}")
    gaps = int(np.isnan(arkit).any(axis=1).sum())
    if gaps:
        notes.append(f"{gaps} of {len(arkit)} frames are gaps (an empty or NaN cell)")
    for note in notes:
        log.warning("%s: %s.", path, note)
    return posed_take(arkit, rate, options.rig, None, "curves", notes, options.neutral, str(path))


def _recognizes(path: Path, options: CaptureOptions) -> bool:
    """A ``.npy``, or a CSV given a mapping whose header is not a marker CSV's."""
    if path.suffix.lower() == ".npy":
        return True
    if options.mapping is None:
        return False
    with open(path, encoding="utf-8-sig", errors="replace", newline="") as fh:
        lines = [line for line in (fh.readline(1 << 16), fh.readline(1 << 16)) if line and not line.startswith("#")]
    header = [h.strip() for h in next(csv.reader(lines[:1]), [])]
    return not ("time" in header and any(h.endswith("_x") and h[:-2] + "_y" in header for h in header))


#: The registered reader (:mod:`facesynth.domain.capture`).
READER = CaptureReader(read_curve_take, _recognizes)
