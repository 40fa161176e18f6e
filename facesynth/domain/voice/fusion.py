"""The voice in the mouth: every method's motion takes what the speech says about the mouth.

The phones say which shape the mouth takes; the voice says how far and how the speaker moved it.
With the utterance's audio given, :func:`apply` moves the motion a method made (the DP's captured
motion above all) toward what the voice says, in one of two ways (``synthesize.voice_recognized``
when the phones were recognised from the audio, ``synthesize.voice_given`` when they were given
or aligned to a transcript):

* ``"articulation"``: the acoustic articulation model (:mod:`facesynth.domain.voice.articulation`,
  the ``articulation`` artifact ``synthesize.articulation_model``; the packaged one, fitted on
  FACEGOOD's and GRID's speakers, by default) predicts the mouth's curves from the voice, and
  :func:`fuse` takes them in (below);
* ``"loudness"``: the voice's loudness alone (:func:`facesynth.domain.speech.loudness.follow`), the
  special case of a "model" whose one prediction is the loudness envelope, mapped by rank, with
  no closure score and no rounding;
* ``"off"``: the phones alone.

**The fusion** (:func:`fuse`), where the voice is clear (its confidence, :func:`confidence`):

1. *Rounding.* The predicted mouthFunnel and mouthPucker, each mapped affinely onto the range of
   that shape's weight in the method's motion (the weights a least-squares fit of the built-in
   rig's mouth shapes gives, :class:`RigShapes`), blended in by ``voice_rounding_weight x
   confidence`` along the shape's own marker displacement (not over a pinned phone that keeps its
   closure, below). A motion whose markers the built-in rig does not bind keeps its rounding.
2. *Opening.* The predicted opening mapped onto the method's inner-lip gaps in this utterance
   (no unit, no gain, the method's own range) and blended with the method's gap by
   ``voice_weight x confidence``. ``voice_opening_map = "rank"`` (the default): each frame takes
   the method's gap at the rank of its prediction (:func:`rank_map`), so the mouth is as often
   closed, half and wide open as the method's, in the voice's order. ``"percentiles"``: the
   prediction's 5th..95th percentiles affinely onto the gaps' (:func:`range_map`), keeping the
   prediction's shape; the prediction dips less between syllables than the speaker's mouth, so
   through speech the mouth stays half open, lips apart (the frozen grimace a database shows when
   a voice drives it). On speakers the packaged model never heard both follow the mouth alike, and
   by rank the lips close where the speaker's do more often (docs/real-speech.md).
3. *Closures* (the voice's own: by default at the model's own threshold, :func:`closure_threshold`;
   the packaged model has none, as on voices a model was not fitted on its closure score fires
   where the lips stay open, and those closures cost more than they get right; a performer's own
   model from ``fit-articulation`` carries the threshold at which they met the performer's
   closures on her held-out takes). Each peak of the
   model's closure score above ``voice_closure_threshold`` takes the gap down to the method's most
   closed gap (a Gaussian dip of :data:`CLOSURE_SIGMA_S`); the
   method's own closings (the phones' /p b m/ and others: deep minima of its gap) are kept where
   the model's closing score confirms them (``voice_closing_threshold``). ``pinned_phones`` keep
   the method's closure (weight 0 over the phone) unless the voice says the lips were open (the
   prediction over the phone above :data:`PINNED_OPEN_QUANTILE` of the utterance's): with the
   phones recognised (``voice_pin_recognized`` false, the default) the phones' /p b m/ are not
   trusted to pin, the voice decides.
4. *Motion.* As the loudness step moves it: every marker along its direction by the step that
   brings the lip gap to its target (:func:`facesynth.domain.speech.loudness.move_to_gaps`).

**Trust** (:func:`trust`): the voice's weight in 1-3 (and its closures) is also scaled by how well
its predicted opening agrees with the method's over ``voice_trust_window_s`` (their local
Pearson r, from ``voice_trust_low`` to ``voice_trust_high``): the loudness says that someone
speaks, the agreement that the model reads this voice. Off by default (``-1`` and ``-1``): it kept
a packaged model fitted on few voices level with the phones alone on speakers it never heard
(``benchmarks/voice_speakers.py``), where the untrusted voice took it 0.09 below them; the model
fitted on more voices reads them well enough that the trust only held it back.

Both paths take the articulation by default (``docs/real-speech.md``): on real speakers the
packaged model never heard it is ahead of the phones alone and of the loudness step with the
phones recognised from the audio and with the phones aligned to a transcript (on the virtual
actress, with her given phones, the loudness step had been ahead). Both are settings, and
``voice_weight = 0`` with ``voice_rounding_weight = 0`` leaves the phones alone.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from facesynth.base.config import SynthesizeSettings
from facesynth.base.errors import InputError
from facesynth.domain.postprocess.concatenation import downsample, frame_ranges
from facesynth.domain.rig.face import Rig
from facesynth.domain.rig.loading import load_rig, marker_map
from facesynth.domain.speech import loudness
from facesynth.domain.speech.loudness import lip_gaps, move_to_gaps, moving_average, opening_direction
from facesynth.domain.voice import activity
from facesynth.domain.voice import articulation as voice_model
from facesynth.model.articulation import ArticulationModel
from facesynth.model.motion import Motion

#: The packaged articulation model (fitted on the speakers whose recordings may ship, FACEGOOD's and
#: GRID's, by ``benchmarks/voice_speakers.py --model-out``; its ``fitted_on`` names every file).
PACKAGED_MODEL = Path(__file__).resolve().parents[2] / "data" / "articulation.h5"
#: The voice's paths (``synthesize.voice_recognized``, ``synthesize.voice_given``).
VOICE_PATHS = ("articulation", "loudness", "off")
#: The frame rate the closure score is fitted at (the captures' 30/s).
CLOSURE_FIT_FPS = 30.0
#: The width (s) of the Gaussian dip a closure makes in the lip gap.
CLOSURE_SIGMA_S = 0.03
#: Closures of the voice at least this far apart (s).
CLOSURE_SPACING_S = 0.15
#: How far (s) from a method's closing the model's closing score may confirm it.
CLOSING_REACH_S = 0.067
#: A pinned phone keeps its closure unless the predicted opening over it ranks above this quantile.
PINNED_OPEN_QUANTILE = 0.75
#: A closure threshold above any closure score (0..1): the voice closes no lips.
NO_CLOSURES = 2.0
#: The rig's mouth shapes fitted to read the motion's rounding (jaw, lips), by ARKit name.
MOUTH_SHAPES = ("jawOpen", "jawForward", "jawLeft", "jawRight", "mouthClose", "mouthFunnel", "mouthPucker",
                "mouthLeft", "mouthRight", "mouthSmile_L", "mouthSmile_R", "mouthStretch_L", "mouthStretch_R",
                "mouthLowerDown_L", "mouthLowerDown_R", "mouthUpperUp_L", "mouthUpperUp_R", "mouthPress_L",
                "mouthPress_R", "mouthRollLower", "mouthRollUpper", "mouthShrugLower", "mouthShrugUpper",
                "mouthFrown_L", "mouthFrown_R", "mouthDimple_L", "mouthDimple_R")
#: The predicted shapes the fusion moves the motion toward.
ROUNDING_SHAPES = ("mouthFunnel", "mouthPucker")


@dataclass(frozen=True)
class VoiceSummary:
    """What the voice did to a motion: ``path`` (one of :data:`VOICE_PATHS`), the closures the voice
    added and the method's closings it kept, the pinned phones kept and vetoed, the mean confidence."""

    path: str
    closures_from_voice: int = 0
    closings_kept: int = 0
    pinned_kept: int = 0
    pinned_vetoed: int = 0
    mean_confidence: float = 0.0
    mean_trust: float = 0.0


@functools.lru_cache(maxsize=4)
def _read_model(path: Path, mtime_ns: int) -> ArticulationModel:
    model = ArticulationModel.read(path)
    voice_model.check_model(model, str(path))
    return model


def closure_threshold(settings: SynthesizeSettings, model: ArticulationModel | None) -> float:
    """The closure score's threshold the voice closes the lips at: ``synthesize.voice_closure_threshold``,
    or where it is negative the model's own (:attr:`~facesynth.model.articulation.ArticulationModel.closure_threshold`,
    chosen by ``fit-articulation`` on the performer's held-out takes), else (none, or no model) none
    (2: above any score)."""
    if settings.voice_closure_threshold >= 0:
        return settings.voice_closure_threshold
    return model.closure_threshold if model is not None and model.closure_threshold is not None else NO_CLOSURES


def articulation_model(setting: str) -> ArticulationModel:
    """The articulation model of ``synthesize.articulation_model``: the file it names, or the packaged
    one when empty (read once per process and file version)."""
    path = Path(setting) if setting else PACKAGED_MODEL
    if not path.is_file():
        raise InputError(f"synthesize.articulation_model: {path} is not a file; give an articulation model "
                         "(benchmarks/voice_articulation.py --model-out), or leave it empty for the packaged one.")
    model = _read_model(path.resolve(), path.stat().st_mtime_ns)
    if "opening" not in model.target_names:
        raise InputError(f"{path}: the articulation model predicts {', '.join(model.target_names)}, not the mouth's "
                         "'opening' the fusion needs; fit it with an 'opening' target.")
    return model


@functools.lru_cache(maxsize=1)
def _builtin_rig() -> Rig:
    return load_rig(None, None)


def apply(motion: Motion, samples: np.ndarray, rate: int, starts: np.ndarray, ends: np.ndarray, phones: list[str],
          settings: SynthesizeSettings, *, recognized: bool) -> tuple[Motion, VoiceSummary, str | None]:
    """``motion`` with what the voice ``samples`` (mono, ``rate`` Hz) says about the mouth, by the
    path ``settings`` choose for phones ``recognized`` from the audio or not (module docstring);
    returns (the motion, what was done, a warning or None)."""
    path = settings.voice_recognized if recognized else settings.voice_given
    if path == "off" or (path == "loudness" and settings.loudness_weight <= 0):
        return motion, VoiceSummary("off"), None
    if path == "loudness":
        moved, warning = loudness.follow(motion, samples, rate, starts, ends, phones, settings)
        return moved, VoiceSummary("loudness" if warning is None else "off"), warning
    if settings.voice_weight <= 0 and settings.voice_rounding_weight <= 0:
        return motion, VoiceSummary("off"), None
    return fuse(motion, samples, rate, starts, ends, phones, articulation_model(settings.articulation_model),
                settings, pinned=recognized is False or settings.voice_pin_recognized)


# ---------------------------------------------------------------- the voice's side

def confidence(raw: np.ndarray, times_s: np.ndarray, snr_none: float, snr_full: float,
               speech: np.ndarray | None = None, admitted: np.ndarray | None = None) -> np.ndarray:
    """(T,) 0..1 how clearly the voice is heard at ``times_s`` (T,) s, from the raw features (K, D)
    of :func:`facesynth.domain.voice.articulation.frame_features` and WebRTC's voice activity
    ``speech`` (K,) 0/1 per 10 ms (none: the level alone): each frame's
    :func:`facesynth.domain.voice.activity.frame_confidence`, the speech band's level above the
    noise floor looking both ways (audio that starts in speech is heard from its start; standing
    on the ``admitted`` (K,) frames, :func:`facesynth.domain.voice.activity.floor_frames`: none
    reading digital silence; all when None), the highest over the speech around it (0.3 s: the jaw
    moves through a syllable's quiet parts too); 0 past the audio's end (a motion may outlast its
    audio by ``ingest.max_audio_mismatch_s``)."""
    if not len(raw):
        return np.zeros(len(times_s))
    level = activity.band_level(activity.band_power(raw))
    c = activity.frame_confidence(level, activity.floor_both_ways(level, admitted),
                                  np.zeros(len(level)) if speech is None else speech, snr_none, snr_full)
    from scipy.ndimage import maximum_filter1d

    c = maximum_filter1d(c, size=int(round(0.3 / voice_model.FRAME_S)) | 1, mode="nearest")
    times_s = np.asarray(times_s, np.float64)
    idx = np.clip(np.rint(times_s / voice_model.FRAME_S).astype(np.int64), 0, len(c) - 1)
    return c[idx] * (times_s <= (len(c) - 0.5) * voice_model.FRAME_S)  # past the audio's end: no voice


def closure_frames(score: np.ndarray, fps: float, threshold: float) -> np.ndarray:
    """Frames (K,) of the peaks of a closure score (T,) at ``fps`` that reach ``threshold``, at least
    :data:`CLOSURE_SPACING_S` apart; the score is averaged over a 1/30 s frame (the rate it was
    fitted at) first, so a fast output rate does not split a peak in two."""
    from scipy.signal import find_peaks

    if len(score) < 3:
        return np.zeros(0, np.int64)
    k = 2 * int(round(fps / CLOSURE_FIT_FPS / 2)) + 1  # odd: centred, so the peak does not shift
    x = moving_average(np.asarray(score, np.float64), k) if k > 1 else np.asarray(score, np.float64)
    peaks, _ = find_peaks(x, height=threshold, distance=max(1, int(round(CLOSURE_SPACING_S * fps))))
    return peaks.astype(np.int64)


# ---------------------------------------------------------------- the fusion on curves

def range_map(predicted: np.ndarray, opening: np.ndarray, low: float = 5.0, high: float = 95.0, *,
              floor: bool = True) -> np.ndarray:
    """(T,) the prediction (T,) mapped affinely so that its ``low``..``high`` percentiles land on the
    method's values' (T,): the method's range, the prediction's shape. With ``floor`` (lip gaps,
    which are positive) a soft floor above 0 below the low percentile (a clipped floor is a plateau,
    and a closure's dip into a plateau is no minimum); without it (rig weights, which may be
    negative against the motion's reference) the map is affine throughout."""
    p, o = np.asarray(predicted, np.float64), np.asarray(opening, np.float64)
    a, b = np.percentile(p, [low, high])
    c, d = np.percentile(o, [low, high])
    if b - a <= 1e-12:
        return o.copy()
    q = c + (p - a) * (d - c) / (b - a)
    if not floor:
        return q
    c = max(c, 0.05 * (d - c), 1e-6)
    return np.where(q < c, c * np.exp(np.minimum(q - c, 0.0) / c), q)


def rank_map(predicted: np.ndarray, opening: np.ndarray) -> np.ndarray:
    """(T,) the method's values ``opening`` (T,) rearranged in the order of ``predicted`` (T,): each
    frame takes the value of ``opening`` at its prediction's rank (ties share their mean rank); a
    flat prediction says nothing (the method's values are returned)."""
    p, o = np.asarray(predicted, np.float64), np.asarray(opening, np.float64)
    if not len(p) or np.ptp(p) <= 1e-12:
        return o.copy()
    return loudness.quantile_map(p, o)


def kept_pinned(pinned: list[tuple[int, int]], predicted: np.ndarray) -> list[tuple[int, int]]:
    """The pinned phones' frame ranges [a, b) (each at least frame a) that keep the method's closure:
    those over which the predicted opening (T,) does not rank above :data:`PINNED_OPEN_QUANTILE` of
    the utterance's (the voice says the lips were open over the others)."""
    rank = (np.argsort(np.argsort(predicted)) + 0.5) / max(len(predicted), 1)
    return [(a, max(b, a + 1)) for a, b in pinned if rank[a:max(b, a + 1)].mean() <= PINNED_OPEN_QUANTILE]


def pinned_free(kept: list[tuple[int, int]], n: int, fps: float, settings: SynthesizeSettings) -> np.ndarray:
    """(n,) 0..1: 0 over the kept pinned phones' frame ranges (:func:`kept_pinned`), 1 elsewhere,
    eased over ``synthesize.loudness_smoothing_s``: how far the voice may move each frame's lips."""
    return loudness.weights(n, kept, 1.0, max(1, int(round(settings.loudness_smoothing_s * fps))))


def method_closings(opening: np.ndarray, closing: np.ndarray | None, fps: float, threshold: float) -> np.ndarray:
    """Frames (K,) of the method's own closures (the deep minima of its gap ``opening`` (T,),
    :func:`facesynth.domain.voice.articulation.closure_frames_of`) that the voice's closing score
    ``closing`` (T,) confirms: it reaches ``threshold`` within :data:`CLOSING_REACH_S`."""
    if closing is None or threshold > 1.0 or len(opening) < 3:
        return np.zeros(0, np.int64)
    frames = voice_model.closure_frames_of(opening)
    reach = max(1, int(round(CLOSING_REACH_S * fps)))
    c = np.asarray(closing, np.float64)
    return np.array([e for e in frames if c[max(0, e - reach):e + reach + 1].max() >= threshold], np.int64)


def local_r(a: np.ndarray, b: np.ndarray, width: int) -> np.ndarray:
    """(T,) Pearson r of two curves (T,) over a centred moving window of ``width`` frames (cut at
    the ends); 0 where either is constant over the window."""
    a, b = np.asarray(a, np.float64), np.asarray(b, np.float64)
    n = len(a)
    if n == 0:
        return np.zeros(0)
    half = max(1, width // 2)
    lo, hi = np.clip(np.arange(n) - half, 0, n), np.clip(np.arange(n) + half + 1, 0, n)
    a, b = a - a.mean(), b - b.mean()  # better conditioned sums

    def window_sum(x):
        c = np.concatenate([[0.0], np.cumsum(x)])
        return c[hi] - c[lo]

    k = (hi - lo).astype(np.float64)
    sa, sb = window_sum(a), window_sum(b)
    cov = window_sum(a * b) - sa * sb / k
    va, vb = window_sum(a * a) - sa * sa / k, window_sum(b * b) - sb * sb / k
    d = np.sqrt(np.maximum(va, 0.0) * np.maximum(vb, 0.0))
    scale = max(float(np.abs(a).max(initial=0.0) * np.abs(b).max(initial=0.0)), 1e-30)
    return np.where(d > 1e-9 * scale * k, cov / np.maximum(d, 1e-300), 0.0)


def trust(predicted: np.ndarray, opening: np.ndarray, fps: float, settings: SynthesizeSettings) -> np.ndarray:
    """(T,) 0..1 how far the voice's predicted opening (T,) is trusted against the method's gap
    ``opening`` (T,) at ``fps``: their local Pearson r over ``voice_trust_window_s`` (:func:`local_r`)
    from ``voice_trust_low`` (0) to ``voice_trust_high`` (1). A voice the model reads well moves
    with the phones' syllables; a voice it was not fitted on, or a noisy one, drifts from them, and
    the phones keep the mouth there. All ones when ``voice_trust_high`` is -1 (always trusted)."""
    n = len(opening)
    low, high = settings.voice_trust_low, settings.voice_trust_high
    if high <= -1.0 or n == 0:
        return np.ones(n)
    r = local_r(predicted, opening, max(3, int(round(settings.voice_trust_window_s * fps))))
    return np.clip((r - low) / max(high - low, 1e-6), 0.0, 1.0)


def target_gap(opening: np.ndarray, predicted: np.ndarray, score: np.ndarray | None, closing: np.ndarray | None,
               conf: np.ndarray, pinned: list[tuple[int, int]], fps: float,
               settings: SynthesizeSettings, trusted: np.ndarray | None = None) -> tuple[np.ndarray, dict]:
    """(T,) target lip gap (mm) from the method's gap ``opening`` (T,) mm, the predicted opening
    ``predicted`` (T,) (any unit), the closure and closing scores (T,) or None, the confidence
    ``conf`` (T,), the pinned phones' frame ranges [a, b) at ``fps`` and the voice's ``trusted``
    share (T,) 0..1 (:func:`trust`; None: computed from the settings) (module docstring, 2-3); and
    what was done. The voice's closures are made only where it is at least half trusted; a
    negative ``voice_closure_threshold`` (the model's own, which :func:`fuse` resolves with
    :func:`closure_threshold`) makes none here."""
    o = np.asarray(opening, np.float64)
    n = len(o)
    q = rank_map(predicted, o) if settings.voice_opening_map == "rank" else range_map(predicted, o)
    tr = trust(predicted, o, fps, settings) if trusted is None else np.asarray(trusted, np.float64)
    w = settings.voice_weight * np.asarray(conf, np.float64) * tr
    kept = kept_pinned(pinned, predicted)
    w = w * pinned_free(kept, n, fps, settings)
    target = (1.0 - w) * o + w * q
    at = closure_threshold(settings, None)
    from_voice = closure_frames(score, fps, at) if score is not None else np.zeros(0, np.int64)
    from_voice = from_voice[tr[from_voice] >= 0.5] if len(from_voice) else from_voice
    kept_closings = method_closings(o, closing, fps, settings.voice_closing_threshold)
    events = np.union1d(from_voice, kept_closings).astype(np.int64)
    if len(events):
        # down to the method's most closed gap; scaling toward it (not clipping at it) keeps each dip
        # a strict minimum, so the lips close there and open on both sides
        closed = float(min(o.min(), target.min()))
        t = np.arange(n)
        sigma = max(CLOSURE_SIGMA_S * fps, 0.5)
        dip = np.zeros(n)
        for e in events:  # sparse: each touches a few frames
            a, b = max(0, e - int(4 * sigma) - 1), min(n, e + int(4 * sigma) + 2)
            dip[a:b] = np.maximum(dip[a:b], np.exp(-0.5 * ((t[a:b] - e) / sigma) ** 2))
        target = closed + (target - closed) * (1.0 - dip)
    return target, {"closures_from_voice": int(len(from_voice)), "closings_kept": int(len(kept_closings)),
                    "pinned_kept": len(kept), "pinned_vetoed": len(pinned) - len(kept),
                    "mean_confidence": float(np.mean(conf)) if n else 0.0,
                    "mean_trust": float(np.mean(tr)) if n else 0.0}


class RigShapes:
    """The built-in rig's mouth shapes as marker motion in a motion's head frame: ``directions``
    (S, M, 3) mm per unit weight of each of ``names`` (zero rows for the markers the rig does not
    bind), and ``solve`` (S, M * 3), the least-squares map from marker displacements (from the
    motion's reference) to those weights (a linear stand-in for ``facesynth solve`` over the
    mouth's shapes)."""

    def __init__(self, rig: Rig, marker_names: list[str], reference: np.ndarray):
        mmap = marker_map(rig, list(marker_names), np.asarray(reference, np.float64), "the motion")
        self.names = tuple(n for n in MOUTH_SHAPES if n in rig.shape_names)
        idx = [rig.shape_names.index(n) for n in self.names]
        deltas = np.asarray(rig.deltas[idx][:, mmap.vertices], np.float64)  # (S, B, 3) rig units and frame
        self.directions = np.zeros((len(idx), len(marker_names), 3))
        self.directions[:, mmap.columns] = deltas @ mmap.rotation / mmap.scale  # the motion's frame, mm
        self.solve = np.linalg.pinv(self.directions.reshape(len(idx), -1).T, rcond=1e-6)
        self.reference = np.asarray(reference, np.float64)

    def weights(self, markers: np.ndarray, names: list[str]) -> np.ndarray:
        """(T, S') the least-squares weights of the shapes ``names`` in marker frames (T, M, 3) mm."""
        rows = [self.names.index(n) for n in names]
        disp = (np.asarray(markers, np.float32) - self.reference.astype(np.float32)).reshape(len(markers), -1)
        return (disp @ self.solve[rows].T.astype(np.float32)).astype(np.float64)


def rig_rounding(markers: np.ndarray, shapes: RigShapes, predicted: dict[str, np.ndarray], blend: np.ndarray) -> np.ndarray:
    """Marker frames (T, M, 3) with the rounding shapes moved toward the predictions: each predicted
    curve (T,) mapped affinely onto the range of that shape's weight in the motion
    (:func:`range_map`), blended by ``blend`` (T,), the difference added along the shape's markers."""
    names = [n for n in predicted if n in shapes.names]
    markers = np.asarray(markers, np.float64)
    if not names:
        return markers
    current = shapes.weights(markers, names)
    steps = np.zeros((len(markers), len(names)))
    for j, name in enumerate(names):
        lo, hi = np.percentile(current[:, j], [5, 95])
        if hi - lo > 1e-6:
            steps[:, j] = blend * (range_map(predicted[name], current[:, j], floor=False) - current[:, j])
    directions = shapes.directions[[shapes.names.index(n) for n in names]].reshape(len(names), -1)
    return markers + (steps.astype(np.float32) @ directions.astype(np.float32)).reshape(markers.shape)


def fuse(motion: Motion, samples: np.ndarray, rate: int, starts: np.ndarray, ends: np.ndarray, phones: list[str],
         model: ArticulationModel, settings: SynthesizeSettings, *, pinned: bool = True,
         rig: Rig | None = None) -> tuple[Motion, VoiceSummary, str | None]:
    """``motion`` (of the utterance with ``phones`` from ``starts`` to ``ends`` s) with the voice's
    articulation predicted by ``model`` from ``samples`` (mono, ``rate`` Hz), as the module docstring
    says; ``pinned``: whether ``synthesize.pinned_phones`` keep their closure; ``rig``: the rig whose
    mouth shapes read the rounding (the built-in one by default). Returns (the motion, what was
    done, a warning or None)."""
    names = list(motion.marker_names)
    lips = tuple(settings.loudness_lip_markers)
    missing = [m for m in lips if m not in names]
    if missing:
        return motion, VoiceSummary("off"), (
            f"the voice's articulation was not applied to the mouth: the motion has no marker {missing[0]!r}; set "
            "synthesize.loudness_lip_markers to its upper and lower inner-lip markers, or synthesize.voice_weight = 0.")
    frames, fps = motion.markers_capture.astype(np.float64), motion.capture_fps
    n = len(frames)
    heard = voice_model.to_analysis_rate(samples, rate)
    raw = voice_model.frame_features(heard, voice_model.RATE)
    times = np.arange(n) / fps
    # predicted at the output rate and interpolated to the capture rate: the model's curves are
    # smoother than 30/s (a 30 ms pooled context), and that is 4 times less work at 120/s
    coarse = np.arange(int(np.floor(times[-1] * motion.fps)) + 2) / motion.fps if n else np.zeros(0)
    at_coarse = voice_model.predict_raw(model, raw, coarse)
    pred = {c: np.interp(times, coarse, at_coarse[:, j]) for j, c in enumerate(model.target_names)}
    speech = activity.speech_frames(heard, settings.voice_activity, len(raw))
    conf = confidence(raw, times, settings.voice_snr_none, settings.voice_snr_full, speech,
                      activity.floor_frames(heard, len(raw)))
    ranges = frame_ranges(np.asarray(starts, float), np.asarray(ends, float), fps)
    pinned_ranges = [r for r, p in zip(ranges, phones) if p in settings.pinned_phones] if pinned else []
    moved = frames
    trusted = trust(pred["opening"], lip_gaps(frames, names, lips), fps, settings)
    rounding = {c: pred[c] for c in ROUNDING_SHAPES if c in pred}
    if settings.voice_rounding_weight > 0 and rounding:
        rig = rig if rig is not None else _builtin_rig()
        if all(m in rig.binding for m in lips) and sum(m in rig.binding for m in names) >= 3:
            # a pinned phone keeps the method's lips whole, its closure and their shape
            free = pinned_free(kept_pinned(pinned_ranges, pred["opening"]), n, fps, settings)
            moved = rig_rounding(frames, RigShapes(rig, names, motion.reference), rounding,
                                 settings.voice_rounding_weight * conf * trusted * free)
    gap = lip_gaps(moved, names, lips)
    target, done = target_gap(gap, pred["opening"], pred.get("closure"), pred.get("closing"), conf, pinned_ranges,
                              fps, replace(settings, voice_closure_threshold=closure_threshold(settings, model)),
                              trusted)
    li, lj = names.index(lips[0]), names.index(lips[1])
    moved = move_to_gaps(moved, opening_direction(moved, gap), (li, lj), target).astype(motion.markers_capture.dtype)
    return (replace(motion, markers_capture=moved, markers=downsample(moved, fps, motion.fps)),
            VoiceSummary("articulation", **done), None)
