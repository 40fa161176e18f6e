"""Statistics of blendshape-weight curves, to compare the virtual actress with a real capture.

The comparison is on ARKit weights at 60 frames/s (the rate of an iPhone Live Link Face
capture): for each shape its range (5th and 95th percentiles) and mean absolute velocity
(weight units per second), and the Pearson correlation between the main mouth shapes.
Also measured on the corpus's truth: blinks per minute and their durations, and the
inner-lip gap on the mesh at the centre of every bilabial.
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.domain.rig.face import Rig
from facesynth.domain.rig.markers import mesh_lip_gap

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


@dataclass(frozen=True)
class ShapeStatistics:
    """One shape's curve over a source's frames: ``p5`` and ``p95`` its 5th and 95th percentiles
    (weight, 0..1) and ``mean_abs_velocity`` its mean |velocity| (weight per second)."""

    p5: float
    p95: float
    mean_abs_velocity: float


@dataclass(frozen=True)
class MouthCorrelation:
    """The Pearson correlation of the mouth shapes: ``names`` (:data:`MOUTH_SHAPES`) and ``matrix``
    (len(names) x len(names), rounded to 3 decimals, 0 where a shape does not move)."""

    names: list[str]
    matrix: list[list[float]]


@dataclass(frozen=True)
class CurveStatistics:
    """What :func:`curve_statistics` measured: ``shapes``, shape name (:data:`COMPARED_SHAPES`) -> its
    statistics, and ``mouth_correlation``. ``dataclasses.asdict`` gives the JSON the benchmarks write."""

    shapes: dict[str, ShapeStatistics]
    mouth_correlation: MouthCorrelation


def curve_statistics(takes: list[np.ndarray], names: list[str], fps: float) -> CurveStatistics:
    """Per shape: p5, p95 and mean |velocity| (1/s) over the frames of ``takes`` (each (T, K)
    in ``names`` order), and the correlation matrix of :data:`MOUTH_SHAPES`."""
    frames = np.concatenate(takes)
    speed = np.concatenate([np.abs(np.diff(x, axis=0)) * fps for x in takes])
    per_shape = {}
    for name in COMPARED_SHAPES:
        k = names.index(name)
        per_shape[name] = ShapeStatistics(float(np.percentile(frames[:, k], 5)), float(np.percentile(frames[:, k], 95)),
                                          float(speed[:, k].mean()))
    idx = [names.index(n) for n in MOUTH_SHAPES]
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = np.corrcoef(frames[:, idx].T)
    return CurveStatistics(per_shape, MouthCorrelation(list(MOUTH_SHAPES), np.nan_to_num(corr).round(3).tolist()))


def blink_events(blink: np.ndarray, fps: float, threshold: float = 0.5) -> list[tuple[int, float]]:
    """Blinks in an eyelid curve (T,): (frame of the peak, seconds above half closure)."""
    above = np.concatenate([[False], blink > threshold, [False]])
    edges = np.diff(above.astype(np.int8))
    starts, ends = np.nonzero(edges == 1)[0], np.nonzero(edges == -1)[0]
    return [(int(a + np.argmax(blink[a:b])), (b - a) / fps) for a, b in zip(starts, ends)]


def bilabial_gaps(rig: Rig, weights: np.ndarray, phones, upper: np.ndarray, lower: np.ndarray, fps: float) -> list[float]:
    """The inner-lip gap on the mesh (mm) at the centre of every /p b m/ of a take.
    phones : (start s, end s, label) triples; weights : (T, E) rig weights; upper, lower : the
    lip surfaces' vertices (:func:`facesynth.domain.rig.markers.lip_surfaces`)."""
    centres = [int(round(0.5 * (a + b) * fps)) for a, b, p in phones if p in ("p", "b", "m", "em")]
    centres = [min(c, len(weights) - 1) for c in centres]
    if not centres:
        return []
    return mesh_lip_gap(rig, weights[centres], upper, lower).tolist()


# ---------------------------------------------------------------- articulation statistics
# Comparable across sources whatever their units (mm of lip gap, 0..1 weights): a mouth-opening
# curve is first normalised by its own source's range (:func:`normalise_by_range`), and every
# rate is taken at one frame rate (:data:`ARTICULATION_FPS`, the rate of the FACEGOOD solve).

#: The frame rate (Hz) every articulation statistic is computed at.
ARTICULATION_FPS = 30.0
#: Phone classes (Festival phones) whose mean mouth opening is compared.
PHONE_CLASSES: dict[str, tuple[str, ...]] = {
    "open_vowel": ("aa", "ae", "ah", "ao", "aw", "ay"),
    "mid_vowel": ("eh", "ey", "ow", "oy", "er", "axr", "ax"),
    "close_vowel": ("ih", "iy", "uh", "uw"),
    "bilabial": ("p", "b", "m", "em"),
    "labiodental": ("f", "v"),
    "other_consonant": ("t", "d", "n", "l", "s", "z", "sh", "zh", "ch", "jh", "th", "dh", "k", "g", "ng", "nx",
                        "r", "w", "y", "hh", "el", "en"),
}

#: Phone labels that mean silence.
PAUSE_LABELS = frozenset({"pau", "sil", "sp", ""})
#: Silences at least this long (s) are pauses, left out of the speech statistics.
MIN_PAUSE_S = 0.25


def normalise_by_range(curves: list[np.ndarray], low_pct: float = 5.0, high_pct: float = 95.0):
    """Curves (each (T,)) of one source scaled so that the source's ``low_pct`` percentile (over
    all its frames) is 0 and its ``high_pct`` percentile is 1. Returns (scaled curves, (low, high)
    in the source's units)."""
    frames = np.concatenate(curves)
    low, high = (float(v) for v in np.percentile(frames, [low_pct, high_pct]))
    scale = high - low if high > low else 1.0
    return [(np.asarray(c, np.float64) - low) / scale for c in curves], (low, high)


@dataclass(frozen=True)
class Percentiles:
    """The median (``p50``) and 95th percentile (``p95``) of a quantity, in its unit."""

    p50: float
    p95: float


def _percentiles(values: np.ndarray) -> Percentiles:
    return Percentiles(float(np.percentile(values, 50)), float(np.percentile(values, 95)))


@dataclass(frozen=True)
class MotionStatistics:
    """Speed of range-normalised curves (:func:`motion_statistics`): ``velocity`` (range/s) and
    ``acceleration`` (range/s^2), each in absolute value."""

    velocity: Percentiles
    acceleration: Percentiles


def motion_statistics(curves: list[np.ndarray], fps: float = ARTICULATION_FPS,
                      masks: list[np.ndarray] | None = None) -> MotionStatistics:
    """Speed of range-normalised curves (each (T,), e.g. from :func:`normalise_by_range`) at
    ``fps``: |velocity| (range/s, central differences) and |acceleration| (range/s^2, second
    differences), each as median and 95th percentile over the frames where ``masks`` (each (T,)
    bool; default all) is true."""
    masks = masks if masks is not None else [np.ones(len(c), bool) for c in curves]
    speed = np.concatenate([np.abs(np.gradient(c, 1.0 / fps))[m] for c, m in zip(curves, masks) if len(c) > 2])
    accel = np.concatenate([np.abs(np.gradient(np.gradient(c, 1.0 / fps), 1.0 / fps))[m]
                            for c, m in zip(curves, masks) if len(c) > 2])
    return MotionStatistics(_percentiles(speed), _percentiles(accel))


@dataclass(frozen=True)
class OpeningEvents:
    """Mouth openings (maxima) and closings (minima) per second of speech (:func:`opening_events`)."""

    openings_per_s: float
    closings_per_s: float


def opening_events(curves: list[np.ndarray], fps: float = ARTICULATION_FPS, prominence: float = 0.25,
                   masks: list[np.ndarray] | None = None) -> OpeningEvents:
    """Openings (maxima) and closings (minima) per second of range-normalised mouth-opening
    curves (each (T,)): the extrema that stand out by at least ``prominence`` of the range,
    counted where ``masks`` (each (T,) bool; default all) is true, per second of those frames."""
    from scipy.signal import find_peaks

    masks = masks if masks is not None else [np.ones(len(c), bool) for c in curves]
    seconds = sum(int(m.sum()) for m in masks) / fps
    openings = sum(int(m[find_peaks(c, prominence=prominence)[0]].sum()) for c, m in zip(curves, masks))
    closings = sum(int(m[find_peaks(-c, prominence=prominence)[0]].sum()) for c, m in zip(curves, masks))
    return OpeningEvents(openings / seconds, closings / seconds)


@dataclass(frozen=True)
class AudioLag:
    """The mouth opening's lag behind the audio (:func:`audio_lag`): ``lag_s`` (s; positive: the
    mouth moves after the sound), ``r`` the Pearson r at the best whole-frame lag and ``r_at_0``
    at no lag."""

    lag_s: float
    r: float
    r_at_0: float


def audio_lag(envelopes: list[np.ndarray], openings: list[np.ndarray], fps: float = ARTICULATION_FPS,
              max_lag_s: float = 0.4) -> AudioLag:
    """The lag (s) of the mouth opening behind the audio: the peak of their cross-correlation.

    envelopes, openings : per take, (T,) the audio's loudness envelope and the mouth opening at
    ``fps``. For every lag k (frames, |k| <= ``max_lag_s``) the Pearson r of envelope[t] and
    opening[t + k] over all takes' overlapping frames; the peak is refined by a parabola through
    it and its neighbours. Positive: the mouth moves after the sound; negative: before it.
    """
    max_lag = int(round(max_lag_s * fps))
    lags = np.arange(-max_lag, max_lag + 1)
    r = np.empty(len(lags))
    for i, k in enumerate(lags):
        a, b = [], []
        for env, x in zip(envelopes, openings):
            n = min(len(env), len(x))
            if k >= 0:
                a.append(env[: n - k])
                b.append(x[k:n])
            else:
                a.append(env[-k:n])
                b.append(x[: n + k])
        r[i] = np.corrcoef(np.concatenate(a), np.concatenate(b))[0, 1]
    best = int(np.argmax(r))
    shift = 0.0
    if 0 < best < len(r) - 1:
        left, mid, right = r[best - 1], r[best], r[best + 1]
        curvature = left - 2 * mid + right
        shift = 0.5 * (left - right) / curvature if curvature < 0 else 0.0
    return AudioLag(float((lags[best] + shift) / fps), float(r[best]), float(r[max_lag]))


def autocorrelation_span(curves: list[np.ndarray], fps: float = ARTICULATION_FPS, level: float = 0.5,
                         masks: list[np.ndarray] | None = None) -> float:
    """Coarticulation span (s): the lag at which the autocorrelation of the mouth opening first
    falls to ``level``, interpolated between frames; how long one articulatory gesture keeps the
    curve like itself. Pooled over takes (each (T,)); with ``masks`` (each (T,) bool) only the
    pairs of frames that are both inside the masks count, about the mean of the masked frames."""
    masks = masks if masks is not None else [np.ones(len(c), bool) for c in curves]
    frames = np.concatenate([np.asarray(c, np.float64)[m] for c, m in zip(curves, masks)])
    mean = float(frames.mean())
    n_max = max(len(c) for c in curves)
    num, pairs = np.zeros(n_max), np.zeros(n_max)
    for c, m in zip(curves, masks):
        x = (np.asarray(c, np.float64) - mean) * m
        full = np.correlate(x, x, mode="full")[len(x) - 1:]
        count = np.correlate(m.astype(float), m.astype(float), mode="full")[len(m) - 1:]
        num[: len(full)] += full
        pairs[: len(count)] += count
    with np.errstate(invalid="ignore", divide="ignore"):
        acf = (num / pairs) / (num[0] / pairs[0])
    below = np.flatnonzero(acf <= level)
    if len(below) == 0:
        return float("nan")
    k = int(below[0])
    frac = (acf[k - 1] - level) / (acf[k - 1] - acf[k]) if k > 0 else 0.0
    return float((k - 1 + frac) / fps)


def phone_class_opening(curves: list[np.ndarray], phones: list[list[tuple[float, float, str]]],
                        fps: float = ARTICULATION_FPS) -> dict[str, float | None]:
    """Mean of the range-normalised mouth opening (each take (T,)) over the frames of each phone
    class of :data:`PHONE_CLASSES` and over pauses; phones per take as (start s, end s, Festival
    label). None for a class with no frames."""
    sums = {name: 0.0 for name in (*PHONE_CLASSES, "pause")}
    counts = dict.fromkeys(sums, 0)
    class_of = {p: name for name, members in PHONE_CLASSES.items() for p in members}
    for curve, segs in zip(curves, phones):
        t = np.arange(len(curve)) / fps
        for a, b, label in segs:
            name = class_of.get(label, "pause" if label in PAUSE_LABELS else None)
            if name is None:
                continue
            sel = (t >= a) & (t < b)
            sums[name] += float(curve[sel].sum())
            counts[name] += int(sel.sum())
    return {name: (sums[name] / counts[name] if counts[name] else None) for name in sums}


#: Phones whose mean opening in standard units is reported (:func:`phone_opening_z`): the vowels
#: and consonants whose jaw real speakers and the actress were seen to disagree on, and /p b m/.
Z_PHONES = ("aa", "ae", "ah", "ao", "ey", "eh", "iy", "uw", "f", "v", "r", "jh", "ch", "sh", "p", "b", "m")


def phone_opening_z(curves: list[np.ndarray], phones: list[list[tuple[float, float, str]]], masks: list[np.ndarray],
                    fps: float = ARTICULATION_FPS) -> dict[str, float | None]:
    """Mean of the mouth opening in standard units over each phone of :data:`Z_PHONES`: every take's
    curve (T,) standardized by the mean and standard deviation of its speech frames (``masks``,
    :func:`speech_masks`), then averaged over the frames of every token of the phone (phones per
    take as (start s, end s, Festival label)); None for a phone with no frames."""
    sums = dict.fromkeys(Z_PHONES, 0.0)
    counts = dict.fromkeys(Z_PHONES, 0)
    for curve, segs, mask in zip(curves, phones, masks):
        speech = curve[mask] if mask.any() else curve
        z = (curve - speech.mean()) / max(float(speech.std()), 1e-12)
        t = np.arange(len(curve)) / fps
        for a, b, label in segs:
            if label in sums:
                sel = (t >= a) & (t < b)
                sums[label] += float(z[sel].sum())
                counts[label] += int(sel.sum())
    return {p: (sums[p] / counts[p] if counts[p] else None) for p in Z_PHONES}


def speech_masks(phones: list[list[tuple[float, float, str]]], lengths: list[int], fps: float = ARTICULATION_FPS,
                 min_pause_s: float = MIN_PAUSE_S) -> list[np.ndarray]:
    """Per take, (T,) bool: the frames of speech, i.e. outside every pause (consecutive phones
    labelled ``pau``, ``sil``, ``sp`` or empty, merged) of at least ``min_pause_s``; shorter
    silences (stop closures, recogniser slips) count as speech. Phones per take as (start s,
    end s, label); ``lengths`` the takes' T."""
    masks = []
    for segs, n in zip(phones, lengths):
        t = np.arange(n) / fps
        mask = np.ones(n, bool)
        pauses: list[list[float]] = []
        for a, b, label in segs:
            if label not in PAUSE_LABELS:
                continue
            if pauses and abs(pauses[-1][1] - a) < 1e-6:
                pauses[-1][1] = b
            else:
                pauses.append([a, b])
        for a, b in pauses:
            if b - a >= min_pause_s:
                mask &= ~((t >= a) & (t < b))
        masks.append(mask)
    return masks


@dataclass(frozen=True)
class ArticulationStatistics:
    """All articulation statistics of one source (:func:`articulation_statistics`);
    ``dataclasses.asdict`` gives the JSON the benchmarks write, keys in this order.

    seconds: frames over all takes (s).
    opening_range: percentile name ("p5", "p50", "p95") -> the mouth opening there (source unit).
    jaw_range: the same of the jaw opening (weight).
    speech_seconds: the speech frames (s), outside long pauses; None without phones.
    opening, jaw: :func:`motion_statistics` of the range-normalised curves.
    events: :func:`opening_events` of the range-normalised mouth opening.
    coarticulation_span_s: :func:`autocorrelation_span` of the range-normalised mouth opening (s).
    audio_lag: :func:`audio_lag`; None without the audio envelopes.
    phone_class_opening: :func:`phone_class_opening`; None without phones.
    phone_opening_z: :func:`phone_opening_z`; None without phones.
    """

    seconds: float
    opening_range: dict[str, float]
    jaw_range: dict[str, float]
    speech_seconds: float | None
    opening: MotionStatistics
    jaw: MotionStatistics
    events: OpeningEvents
    coarticulation_span_s: float
    audio_lag: AudioLag | None
    phone_class_opening: dict[str, float | None] | None
    phone_opening_z: dict[str, float | None] | None = None


def articulation_statistics(openings: list[np.ndarray], jaw: list[np.ndarray], fps: float = ARTICULATION_FPS,
                            envelopes: list[np.ndarray] | None = None,
                            phones: list[list[tuple[float, float, str]]] | None = None) -> ArticulationStatistics:
    """All articulation statistics of one source: takes' mouth openings (T,) in the source's
    unit and jaw-opening weights (T,) (ARKit ``jawOpen`` or its counterpart), all at ``fps``;
    optionally the audio envelopes (T,) (for the lag) and the phones (for the per-class opening).
    The speed and event statistics are over the speech frames where the phones are known (all
    frames otherwise).
    """
    normalised, _ = normalise_by_range(openings)
    jaw_normalised, _ = normalise_by_range(jaw)
    masks = speech_masks(phones, [len(c) for c in openings], fps) if phones is not None else None
    all_open, all_jaw = np.concatenate(openings), np.concatenate(jaw)
    return ArticulationStatistics(
        seconds=float(len(all_open) / fps),
        opening_range={f"p{q}": float(np.percentile(all_open, q)) for q in (5, 50, 95)},
        jaw_range={f"p{q}": float(np.percentile(all_jaw, q)) for q in (5, 50, 95)},
        speech_seconds=float(sum(int(m.sum()) for m in masks) / fps) if masks is not None else None,
        opening=motion_statistics(normalised, fps, masks),
        jaw=motion_statistics(jaw_normalised, fps, masks),
        events=opening_events(normalised, fps, masks=masks),
        coarticulation_span_s=autocorrelation_span(normalised, fps, masks=masks),
        audio_lag=audio_lag(envelopes, normalised, fps) if envelopes is not None else None,
        phone_class_opening=phone_class_opening(normalised, phones, fps) if phones is not None else None,
        phone_opening_z=phone_opening_z(openings, phones, masks, fps) if phones is not None and masks is not None
        else None,
    )
