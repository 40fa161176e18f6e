"""Neutral calibration: the performer's own neutral face becomes the rig's neutral, so that a
capture's weights are its expressions only, for every capture route (video, markers, Live Link
Face, another rig's curves).

A performer's face at rest is not the rig's: a filmed face carries its own shape, the camera's
perspective and the tracker's depth guesses; a Live Link Face or curve take rests where its solver
left it. Measured from the rig's neutral, all of that reads as expression (a frown, a shrug held
through the whole take). Measured from the performer's neutral, it does not.

The neutral is given by a :class:`NeutralChoice` (``--neutral`` on ``solve``, ``solve.neutral``
and ``ingest.neutral``):

* ``auto``: the quietest stretch (:func:`quiet_window`; over every take of a capture of
  several, :func:`quietest_of`: one performer, one neutral face): the window of
  :data:`WINDOW_S` seconds whose frames have the lowest median *quietness score*, the sum of two
  ranks over the take (each in [0, 1]): the frame's motion energy (the RMS speed of its markers,
  mm/s) and its mouth opening (the gap between the inner lips' centres when the markers include
  them, :data:`LIP_PAIRS`; for a take posed from curves, its ``jawOpen`` weight). Still and
  closed, the face is at rest; the median makes a blink or a swallow inside the window harmless.
* ``frame:N``: frame N of the take (0-based); ``time:2.5s``: the frame at 2.5 s.
* ``take:NAME``: the quietest stretch of another take, a neutral take recorded for the purpose
  (as Live Link Face and MetaHuman Animator ask for).
* ``off``: no calibration, the capture's own reference (the rig's neutral for a take posed from
  curves).

A marker take's neutral is the median of its markers over the neutral frames
(:func:`neutral_pose`), which ``solve`` measures displacements from; a take posed from curves has
its neutral weights (the per-channel median, :func:`neutral_weights`) taken off every frame
(:func:`calibrated_weights`) at ``ingest``, before the rig is posed.
"""

from __future__ import annotations

import re
import warnings
from dataclasses import dataclass

import numpy as np

from facesynth.base.errors import InputError

#: The length of the quiet stretch ``auto`` looks for (s): long enough that a median over it
#: is steady (12 frames at 25 frames/s), short enough for a take that is mostly speech.
WINDOW_S = 0.5
#: Marker pairs whose distance is the mouth's opening: MediaPipe's inner-lip centres (a video),
#: the virtual actress's (the built-in rig's marker set).
LIP_PAIRS = (("MP013", "MP014"), ("ULI_C", "LLI_C"))
#: What ``--neutral`` accepts, in words (errors and help).
FORMS = "auto, off, frame:N, time:SECONDSs or take:NAME"


@dataclass(frozen=True)
class NeutralChoice:
    """Where a take's neutral face is: ``kind`` one of ``auto``, ``off``, ``frame``, ``time``,
    ``take``, with ``frame`` (0-based index), ``time_s`` (seconds) or ``take`` (a take's name)."""

    kind: str
    frame: int | None = None
    time_s: float | None = None
    take: str | None = None

    @classmethod
    def parse(cls, text: str, where: str) -> NeutralChoice:
        """``auto``, ``off``, ``frame:120``, ``time:2.5s`` (or ``time:2.5``), ``take:NAME``; one
        sentence naming ``where`` and the forms for anything else."""
        text = text.strip()
        if text in ("auto", "off"):
            return cls(text)
        kind, _, value = text.partition(":")
        value = value.strip()
        if kind == "frame" and re.fullmatch(r"\d+", value):
            return cls("frame", frame=int(value))
        if kind == "time" and re.fullmatch(r"\d+(\.\d*)?s?", value):
            return cls("time", time_s=float(value.rstrip("s")))
        if kind == "take" and value:
            return cls("take", take=value)
        raise InputError(f"{where}: neutral {text!r} is not one of {FORMS}; e.g. --neutral frame:120.")

    def __str__(self) -> str:
        if self.kind == "frame":
            return f"frame:{self.frame}"
        if self.kind == "time":
            return f"time:{self.time_s:g}s"
        if self.kind == "take":
            return f"take:{self.take}"
        return self.kind


def lip_gap(markers: np.ndarray, names: list[str]) -> np.ndarray | None:
    """(T,) distance between the inner lips' centres (markers (T, M, 3), units of the markers),
    by the first of :data:`LIP_PAIRS` the names include; None without one."""
    for upper, lower in LIP_PAIRS:
        if upper in names and lower in names:
            m = np.asarray(markers, np.float64)
            return np.linalg.norm(m[:, names.index(upper)] - m[:, names.index(lower)], axis=1)
    return None


def _ranks(x: np.ndarray) -> np.ndarray:
    """Each finite value's rank in [0, 1] (tied values share their mean rank); NaN stays NaN."""
    out = np.full(len(x), np.nan)
    ok = np.isfinite(x)
    n = int(ok.sum())
    if n > 1:
        values, inverse, counts = np.unique(x[ok], return_inverse=True, return_counts=True)
        first = np.cumsum(counts) - counts  # the lowest rank of each distinct value
        out[ok] = (first + (counts - 1) / 2)[inverse] / (n - 1)
    elif n:
        out[ok] = 0.0
    return out


def quietness(markers: np.ndarray, fps: float, opening: np.ndarray | None) -> np.ndarray:
    """(T,) quietness score of every frame, lower is quieter (see the module docstring).

    markers : (T, M, 3) float, mm (NaN: missing); fps : frames/s; opening : (T,) the mouth's
    opening (mm, or a jawOpen weight), or None (motion energy alone). A frame whose score cannot
    be measured (no marker seen) is NaN."""
    m = np.asarray(markers, np.float64)
    t = len(m)
    speed = np.full(t, np.nan)
    if t > 1:
        step = np.linalg.norm(np.diff(m, axis=0), axis=2) * fps  # (T-1, M) mm/s
        with warnings.catch_warnings():  # a frame with no marker seen has no speed (NaN)
            warnings.simplefilter("ignore", RuntimeWarning)
            per = np.sqrt(np.nanmean(step**2, axis=1))
        # a frame's speed: the mean of its steps in and out (centred, so no lag)
        speed = np.nanmean(np.stack([np.r_[per[:1], per], np.r_[per, per[-1:]]]), axis=0) if len(per) else speed
    elif t == 1:
        speed = np.zeros(1)
    score = _ranks(speed)
    if opening is not None:
        score = score + _ranks(np.asarray(opening, np.float64))
    return score


def quiet_window(score: np.ndarray, fps: float, window_s: float = WINDOW_S) -> slice:
    """The frames (a slice) of the window of ``window_s`` seconds (at least one frame, at most the
    take) whose median score is lowest; among equal medians the lowest mean, then the earliest."""
    t = len(score)
    w = int(np.clip(round(window_s * fps), 1, max(t, 1)))
    if t == 0:
        return slice(0, 0)
    s = np.where(np.isfinite(score), score, np.inf)
    windows = np.lib.stride_tricks.sliding_window_view(s, w)
    medians, means = np.median(windows, axis=1), windows.mean(axis=1)
    start = int(np.lexsort((np.arange(len(medians)), means, medians))[0])
    return slice(start, start + w)


def quietest_of(score: np.ndarray, spans: list[slice], fps: float, window_s: float = WINDOW_S) -> slice:
    """The quietest window (:func:`quiet_window`) over several takes, ``score`` (T,) being the
    scores of all of them one after another (ranked together, so comparable) and ``spans`` each
    take's frames: the window, in ``score``'s frames, with the lowest median, then mean, then the
    earliest; no window crosses from one take into the next."""
    best: tuple[float, float, int] | None = None
    chosen = slice(0, 0)
    for span in spans:
        part = score[span]
        if not len(part):
            continue
        window = quiet_window(part, fps, window_s)
        values = np.where(np.isfinite(part[window]), part[window], np.inf)
        key = (float(np.median(values)), float(values.mean()), span.start + window.start)
        if best is None or key < best:
            best, chosen = key, slice(span.start + window.start, span.start + window.stop)
    return chosen


def chosen_frames(choice: NeutralChoice, score: np.ndarray, fps: float, where: str) -> slice | None:
    """The neutral frames of a take with quietness ``score`` (T,) at ``fps``: a window for
    ``auto``, one frame for ``frame`` and ``time``; None for ``off`` and ``take`` (another
    take's). A frame beyond the take is one sentence naming ``where``."""
    t = len(score)
    if choice.kind == "auto":
        return quiet_window(score, fps)
    if choice.kind in ("frame", "time"):
        frame = choice.frame if choice.kind == "frame" else int(round((choice.time_s or 0.0) * fps))
        if frame is None or not 0 <= frame < t:
            raise InputError(f"{where}: neutral {choice} is beyond the take ({t} frames, {t / fps:.2f} s); name a frame "
                             "or time inside it.")
        return slice(frame, frame + 1)
    return None


def neutral_pose(markers: np.ndarray, frames: slice) -> np.ndarray:
    """(M, 3) float64 the markers' median over ``frames`` (markers (T, M, 3); NaN where a marker is
    unseen in all of them)."""
    with warnings.catch_warnings():  # a marker or channel unseen in every neutral frame is NaN
        warnings.simplefilter("ignore", RuntimeWarning)
        return np.nanmedian(np.asarray(markers, np.float64)[frames], axis=0)


def neutral_weights(weights: np.ndarray, frames: slice) -> np.ndarray:
    """(C,) float64 the per-channel median of ``weights`` (T, C) over ``frames`` (NaN rows, gaps,
    ignored; 0 where every frame is a gap)."""
    with warnings.catch_warnings():  # a marker or channel unseen in every neutral frame is NaN
        warnings.simplefilter("ignore", RuntimeWarning)
        out = np.nanmedian(np.asarray(weights, np.float64)[frames], axis=0)
    return np.nan_to_num(out, nan=0.0)


def calibrated_weights(weights: np.ndarray, neutral: np.ndarray) -> np.ndarray:
    """(T, C) the weights' expressions only: ``clip(weights - neutral, 0, 1)`` per channel (a
    channel below its neutral value is at rest); NaN rows (gaps) stay NaN."""
    return np.clip(np.asarray(weights, np.float64) - np.asarray(neutral, np.float64)[None], 0.0, 1.0)
