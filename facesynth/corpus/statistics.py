"""Statistics of blendshape-weight curves, to compare the virtual actress with a real capture.

The comparison is on ARKit weights at 60 frames/s (the rate of an iPhone Live Link Face
capture): for each shape its range (5th and 95th percentiles) and mean absolute velocity
(weight units per second), and the Pearson correlation between the main mouth shapes.
Also measured on the corpus's truth: blinks per minute and their durations, and the
inner-lip gap on the mesh at the centre of every bilabial.
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np

from ..facerig import Rig

#: The mouth shapes whose correlations are compared (ARKit names).
MOUTH_SHAPES = ("jawOpen", "mouthClose", "mouthFunnel", "mouthPucker", "mouthSmileLeft", "mouthSmileRight",
                "mouthLowerDownLeft", "mouthUpperUpLeft", "mouthStretchLeft", "mouthPressLeft", "mouthRollLower")
#: Shapes whose range and velocity are compared (ARKit names).
COMPARED_SHAPES = MOUTH_SHAPES + ("jawForward", "mouthShrugUpper", "mouthShrugLower", "mouthFrownLeft",
                                  "eyeBlinkLeft", "eyeLookDownLeft", "browInnerUp", "browDownLeft",
                                  "cheekSquintLeft", "noseSneerLeft")
LLF_FPS = 60.0


def arkit_label(name: str) -> str:
    """ARKit name as in :attr:`Rig.arkit_names` ('eyeBlinkLeft')."""
    return name[0].lower() + name[1:]


def read_live_link_face(path: Path) -> tuple[list[str], np.ndarray]:
    """A Live Link Face CSV: (the 52 ARKit names, lower-camel, weights (T, 52)), rotations left out."""
    with open(path, newline="", encoding="utf-8") as fh:
        reader = csv.DictReader(fh)
        columns = [c for c in reader.fieldnames or [] if c not in ("Timecode", "BlendShapeCount")
                   and not c.startswith(("Head", "LeftEye", "RightEye"))]
        rows = [[float(r[c]) for c in columns] for r in reader]
    return [arkit_label(c) for c in columns], np.array(rows)


def resample(weights: np.ndarray, fps: float, new_fps: float) -> np.ndarray:
    """Linear resampling of (T, K) curves from ``fps`` to ``new_fps``."""
    t = np.arange(len(weights)) / fps
    new_t = np.arange(0.0, t[-1] + 1e-9, 1.0 / new_fps)
    return np.stack([np.interp(new_t, t, weights[:, k]) for k in range(weights.shape[1])], 1)


def curve_statistics(takes: list[np.ndarray], names: list[str], fps: float) -> dict:
    """Per shape: p5, p95 and mean |velocity| (1/s) over the frames of ``takes`` (each (T, K)
    in ``names`` order), and the correlation matrix of :data:`MOUTH_SHAPES`."""
    frames = np.concatenate(takes)
    speed = np.concatenate([np.abs(np.diff(x, axis=0)) * fps for x in takes])
    per_shape = {}
    for name in COMPARED_SHAPES:
        k = names.index(name)
        per_shape[name] = {"p5": float(np.percentile(frames[:, k], 5)), "p95": float(np.percentile(frames[:, k], 95)),
                           "mean_abs_velocity": float(speed[:, k].mean())}
    idx = [names.index(n) for n in MOUTH_SHAPES]
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = np.corrcoef(frames[:, idx].T)
    return {"shapes": per_shape, "mouth_correlation": {"names": list(MOUTH_SHAPES), "matrix": np.nan_to_num(corr).round(3).tolist()}}


def blink_events(blink: np.ndarray, fps: float, threshold: float = 0.5) -> list[tuple[int, float]]:
    """Blinks in an eyelid curve (T,): (frame of the peak, seconds above half closure)."""
    above = np.concatenate([[False], blink > threshold, [False]])
    edges = np.diff(above.astype(np.int8))
    starts, ends = np.nonzero(edges == 1)[0], np.nonzero(edges == -1)[0]
    return [(int(a + np.argmax(blink[a:b])), (b - a) / fps) for a, b in zip(starts, ends)]


def bilabial_gaps(rig: Rig, weights: np.ndarray, phones, upper: np.ndarray, lower: np.ndarray, fps: float) -> list[float]:
    """The inner-lip gap on the mesh (mm) at the centre of every /p b m/ of a take.
    phones : (start s, end s, label) triples; weights : (T, E) rig weights; upper, lower : the
    lip surfaces' vertices (:func:`facesynth.corpus.markers.lip_surfaces`)."""
    from .markers import mesh_lip_gap

    centres = [int(round(0.5 * (a + b) * fps)) for a, b, p in phones if p in ("p", "b", "m", "em")]
    centres = [min(c, len(weights) - 1) for c in centres]
    if not centres:
        return []
    return mesh_lip_gap(rig, weights[centres], upper, lower).tolist()
