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
   (quantile mapping: louder frames get wider openings of those the method made, quieter ones
   narrower, whatever the microphone's gain), blended with ``o``: ``(1 - w) o + w q``, ``w`` =
   ``synthesize.loudness_weight``. The targets stay within the method's own range of openings;
   only when the mouth opens wide changes. Within the phones of ``synthesize.pinned_phones``
   (/p b m/, each at least one frame) ``w`` falls to 0, eased over the smoothing window, so a
   bilabial still closes the lips.
4. **Motion.** Each marker moves along the direction in which it moves as the mouth opens in this
   utterance (its least-squares slope on ``o``, scaled by the share of its motion that ``o``
   explains, so that the jaw, lips and chin move and markers the opening does not drive, such as
   the brows, nearly stay), by the amount that brings the gap to the target (:func:`move_to_gaps`;
   where the target cannot be reached along that direction, as far toward it as the direction
   allows). The frames at the capture rate change; the output frames are down-sampled from them
   again.

Audio whose loudness hardly varies (the 5th..95th percentile spread of the log-RMS envelope below
:data:`MIN_SPREAD`: silence, a placeholder file, a tone) says nothing about the mouth; the step is
then skipped with a warning instead of flattening the opening toward its median.

Choices: the quantile mapping instead of a fitted linear map (no unit, no gain, no fitting on the
speaker); the weight 0.6 chosen on three real takes (FACEGOOD 1114_2_01..03, the actress's
calibration takes; ``benchmarks/real_speech_lipsync.py --loudness-weights``), none of those
scored in docs/real-speech.md's fair test.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from facesynth.base.config import SynthesizeSettings
from facesynth.domain.postprocess.concatenation import downsample, frame_ranges

#: The least 5th..95th percentile spread (nats of log-RMS; 1 is a factor e in loudness) of an
#: audio's envelope for the loudness to move the mouth; speech spans several.
MIN_SPREAD = 1.0


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
    ``pinned`` ([a, b) each, at least frame a), eased between over ``ease`` frames outside them."""
    mask = np.zeros(n)
    for a, b in pinned:
        mask[a:max(b, a + 1)] = 1.0
    if ease > 1 and mask.any():
        reach = ease // 2  # dilate by the moving average's reach, so that the pinned frames stay at 0
        dilated = np.convolve(mask, np.ones(2 * reach + 1), mode="full")[reach:reach + n] > 0
        mask = moving_average(dilated.astype(float), ease)
    return weight * (1.0 - np.clip(mask, 0.0, 1.0))


def opening_direction(markers: np.ndarray, opening: np.ndarray) -> np.ndarray:
    """(M, 3) how every marker moves per mm of lip gap in the marker frames (T, M, 3) mm: its
    least-squares slope on ``opening`` (T,) mm, scaled by the share of the marker's variance that
    the opening explains (R², 0..1: a marker the opening does not drive nearly stays); zeros when
    the opening never changes."""
    o = np.asarray(opening, np.float64) - np.mean(opening)
    var = float(o @ o)
    if var <= 1e-12 * max(len(o), 1):
        return np.zeros(markers.shape[1:])
    x = np.asarray(markers, np.float64)
    x = x - x.mean(0)
    slope = np.tensordot(o, x, axes=(0, 0)) / var
    explained = np.sum(slope * slope, axis=-1) * var / np.maximum(np.sum(x * x, axis=(0, 2)), 1e-12)
    return slope * np.clip(explained, 0.0, 1.0)[:, None]


def move_to_gaps(markers: np.ndarray, direction: np.ndarray, lips: tuple[int, int], target: np.ndarray) -> np.ndarray:
    """Marker frames (T, M, 3) mm moved along ``direction`` (M, 3) by the step s (per frame) that
    makes the distance between markers ``lips`` (indices) ``target`` (T,) mm: the root of
    |v + s du|² = target² nearest 0 (v the lip vector, du the lips' relative direction). Where no
    step reaches the target (the part of the gap off that line is wider: lips apart front to
    back, as in /f v/), the step that brings the gap closest to it; where the gap does not change
    along the direction, none."""
    x = np.asarray(markers, np.float64)
    du = direction[lips[0]] - direction[lips[1]]
    a = float(du @ du)
    if a <= 1e-18:
        return np.asarray(markers).copy()
    v = x[:, lips[0]] - x[:, lips[1]]
    b = v @ du
    c = np.sum(v * v, axis=-1) - np.asarray(target, np.float64) ** 2
    disc = b * b - a * c
    root = np.sqrt(np.maximum(disc, 0.0))
    near = np.where(np.abs(-b + root) <= np.abs(-b - root), -b + root, -b - root) / a
    step = np.where(disc >= 0, near, -b / a)
    return (x + step[:, None, None] * direction[None]).astype(np.asarray(markers).dtype)


def follow(motion, samples: np.ndarray, rate: int, starts: np.ndarray, ends: np.ndarray, phones: list[str],
           settings: SynthesizeSettings):
    """``motion`` (a :class:`~facesynth.model.motion.Motion` of an utterance with ``phones`` from
    ``starts`` to ``ends`` s) with its mouth opening following the loudness of ``samples`` (mono,
    ``rate`` Hz) as the module docstring says; returns (the motion, a warning or None). The
    motion is returned unchanged, with a warning, when it lacks the lip markers or the audio's
    loudness hardly varies."""
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
    spread = float(np.subtract(*np.percentile(loud, [95, 5]))) if len(loud) else 0.0
    if spread < MIN_SPREAD:
        return motion, (f"the audio's loudness was not applied to the mouth: it hardly varies (its log-RMS spans "
                        f"{spread:.2f} between the 5th and 95th percentiles, under {MIN_SPREAD:g}); give the "
                        "utterance's speech, or set synthesize.loudness_weight = 0.")
    ranges = frame_ranges(np.asarray(starts, float), np.asarray(ends, float), fps)
    pinned = [r for r, p in zip(ranges, phones) if p in settings.pinned_phones]
    w = weights(len(frames), pinned, settings.loudness_weight, max(1, int(round(settings.loudness_smoothing_s * fps))))
    target = (1.0 - w) * opening + w * quantile_map(loud, opening)
    moved = move_to_gaps(frames, opening_direction(frames, opening), lips, target)
    return replace(motion, markers_capture=moved, markers=downsample(moved, fps, motion.fps)), None
