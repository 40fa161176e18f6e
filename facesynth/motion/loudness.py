"""The speech's loudness in the lips (not in the four papers): when the audio of the utterance is
given, the mouth opens with its loudness as well as with its phones.

The phones say which shape the mouth takes, not how far a speaker opens it on each syllable; the
loudness of the voice says much of that (a louder syllable is spoken with the jaw further down).
JALI (Edwards et al., SIGGRAPH 2016) drives its jaw from the speech's volume for this reason. On
real speech the audio's loudness envelope follows the speaker's mouth opening better than any
phone-driven method facesynth has (docs/real-speech.md), so with the audio at hand facesynth uses
both:

1. **Opening.** The inner-lip gap ``o`` (T,) mm of the method's motion, between the two
   ``synthesize.loudness_lip_markers``.
2. **Loudness.** The audio's log-RMS around each frame (:func:`envelope`), smoothed over
   ``synthesize.loudness_smoothing_s``.
3. **Target.** The loudness mapped onto the distribution of ``o`` in this utterance by rank
   (quantile mapping: the loudest frame gets the widest opening the method made, the quietest its
   narrowest, whatever the microphone's gain), blended with ``o``: ``(1 - w) o + w q``, ``w`` =
   ``synthesize.loudness_weight``. The range of openings is the method's own; only when the mouth
   opens wide changes. Within the phones of ``synthesize.pinned_phones`` (/p b m/) ``w`` falls to 0
   (eased over the smoothing window), so a bilabial still closes the lips.
4. **Motion.** Every marker moves along the direction in which this utterance's frames move as the
   mouth opens (the least-squares slope of the markers on ``o``: jaw, lips and chin together), by
   the amount that brings the gap to the target (:func:`move_to_gaps`). The frames at the capture
   rate change; the output frames are down-sampled from them again.

Choices: the quantile mapping instead of a fitted linear map (no unit, no gain, no fitting on the
speaker); the weight 0.6 chosen on three real takes (FACEGOOD 1114_2_01..03, the actress's
calibration takes; ``benchmarks/real_speech_lipsync.py --loudness-weights``), none of those
scored in docs/real-speech.md's fair test.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..config import SynthesizeSettings
from .postprocess import downsample, frame_ranges

#: Iterations of :func:`move_to_gaps` (each one a Newton step of every frame's gap along the direction).
GAP_ITERATIONS = 3


def envelope(samples: np.ndarray, rate: int, n: int, fps: float, smooth_s: float) -> np.ndarray:
    """(n,) log-RMS of mono ``samples`` at ``rate`` Hz around each frame time f / fps (windows of
    2 / fps s), smoothed by a centred moving average of ``smooth_s`` seconds; silence (and frames
    after the audio's end) floored at 1e-4 of the loudest frame's RMS."""
    x = np.asarray(samples, np.float64)
    half = int(round(rate / fps))
    centres = (np.arange(n) * rate / fps).round().astype(np.int64)
    c2 = np.concatenate([[0.0], np.cumsum(x * x)])
    a, b = np.clip(centres - half, 0, len(x)), np.clip(centres + half, 0, len(x))
    rms = np.sqrt((c2[b] - c2[a]) / np.maximum(b - a, 1))
    env = np.log(np.maximum(rms, 1e-4 * max(float(rms.max(initial=0.0)), 1e-12)))
    return moving_average(env, max(1, int(round(smooth_s * fps))))


def lip_gaps(markers: np.ndarray, names: list[str], lip_markers: tuple[str, ...]) -> np.ndarray:
    """(T,) distance (mm) between the two ``lip_markers`` in marker frames (T, M, 3) mm."""
    i, j = (names.index(n) for n in lip_markers)
    return np.linalg.norm(markers[:, i] - markers[:, j], axis=-1)


def mean_ranks(values: np.ndarray) -> np.ndarray:
    """(T,) float64 ranks 1..T of ``values`` (T,), ties sharing their mean rank (as
    ``scipy.stats.rankdata``, without importing scipy.stats, which takes half a second)."""
    values = np.asarray(values)
    order = np.argsort(values, kind="stable")
    ordered = values[order]
    first = np.concatenate([[True], ordered[1:] != ordered[:-1]]) if len(values) else np.zeros(0, bool)
    starts = np.flatnonzero(first)
    counts = np.diff(np.append(starts, len(values)))
    ranks = np.empty(len(values))
    ranks[order] = np.repeat(starts + (counts + 1) / 2.0, counts)
    return ranks


def quantile_map(loudness: np.ndarray, opening: np.ndarray) -> np.ndarray:
    """(T,) the opening at the quantile of each frame's ``loudness`` rank in the distribution of
    ``opening`` (T,) (ties share their mean rank)."""
    q = (mean_ranks(loudness) - 0.5) / len(loudness)
    return np.quantile(np.asarray(opening, np.float64), q)


def moving_average(x: np.ndarray, k: int) -> np.ndarray:
    """(n,) centred moving average of ``x`` (n,) over ``k`` samples (the window [i - k // 2,
    i + (k - 1) // 2]), the ends repeated beyond the edges."""
    return np.convolve(np.pad(x, (k // 2, k - 1 - k // 2), mode="edge"), np.ones(k) / k, mode="valid")


def weights(n: int, pinned: list[tuple[int, int]], weight: float, ease: int) -> np.ndarray:
    """(n,) the loudness's share of the opening per frame: ``weight``, 0 within the frame ranges
    ``pinned`` ([a, b) each), eased between over ``ease`` frames outside them."""
    mask = np.zeros(n)
    for a, b in pinned:
        mask[a:b] = 1.0
    if ease > 1 and mask.any():
        reach = ease // 2  # dilate by the moving average's reach, so that the pinned frames stay at 0
        mask = moving_average((np.convolve(mask, np.ones(2 * reach + 1), mode="same") > 0).astype(float), ease)
    return weight * (1.0 - np.clip(mask, 0.0, 1.0))


def opening_direction(markers: np.ndarray, opening: np.ndarray) -> np.ndarray:
    """(M, 3) the least-squares slope of the marker frames (T, M, 3) mm on ``opening`` (T,) mm:
    how every marker moves per mm of lip gap in these frames; zeros when the opening never changes."""
    o = np.asarray(opening, np.float64) - np.mean(opening)
    var = float(o @ o)
    if var <= 1e-12 * max(len(o), 1):
        return np.zeros(markers.shape[1:])
    x = np.asarray(markers, np.float64)
    return np.tensordot(o, x - x.mean(0), axes=(0, 0)) / var


def move_to_gaps(markers: np.ndarray, direction: np.ndarray, lips: tuple[int, int], target: np.ndarray) -> np.ndarray:
    """Marker frames (T, M, 3) mm moved along ``direction`` (M, 3) so that the distance between
    markers ``lips`` (indices) is ``target`` (T,) mm: a few Newton steps of each frame's step
    length along the direction (frames where the gap does not change along it stay)."""
    x = np.asarray(markers, np.float64)
    du = direction[lips[0]] - direction[lips[1]]
    step = np.zeros(len(x))
    for _ in range(GAP_ITERATIONS):
        v = x[:, lips[0]] - x[:, lips[1]] + step[:, None] * du
        gap = np.linalg.norm(v, axis=-1)
        slope = (v @ du) / np.maximum(gap, 1e-9)
        ok = np.abs(slope) > 1e-6
        step[ok] += (target[ok] - gap[ok]) / slope[ok]
    return (x + step[:, None, None] * direction[None]).astype(np.asarray(markers).dtype)


def follow(motion, samples: np.ndarray, rate: int, starts: np.ndarray, ends: np.ndarray, phones: list[str],
           settings: SynthesizeSettings):
    """``motion`` (a :class:`~facesynth.model.motion.Motion` of an utterance with ``phones`` from
    ``starts`` to ``ends`` s) with its mouth opening following the loudness of ``samples`` (mono,
    ``rate`` Hz) as the module docstring says; returns (the motion, a warning or None). The
    motion is returned unchanged, with a warning, when it lacks the lip markers."""
    names = list(motion.marker_names)
    missing = [m for m in settings.loudness_lip_markers if m not in names]
    if missing:
        return motion, (f"the audio's loudness was not applied to the mouth: the motion has no marker "
                        f"{missing[0]!r}; set synthesize.loudness_lip_markers to its upper and lower inner-lip "
                        "markers, or synthesize.loudness_weight = 0.")
    lips = (names.index(settings.loudness_lip_markers[0]), names.index(settings.loudness_lip_markers[1]))
    frames, fps = motion.markers_capture, motion.capture_fps
    opening = lip_gaps(frames, names, settings.loudness_lip_markers).astype(np.float64)
    loud = envelope(samples, rate, len(frames), fps, settings.loudness_smoothing_s)
    ranges = frame_ranges(np.asarray(starts, float), np.asarray(ends, float), fps)
    pinned = [r for r, p in zip(ranges, phones) if p in settings.pinned_phones]
    w = weights(len(frames), pinned, settings.loudness_weight, max(1, int(round(settings.loudness_smoothing_s * fps))))
    target = (1.0 - w) * opening + w * quantile_map(loud, opening)
    moved = move_to_gaps(frames, opening_direction(frames, opening), lips, target)
    return replace(motion, markers_capture=moved, markers=downsample(moved, fps, motion.fps)), None
