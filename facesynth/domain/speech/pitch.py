"""Pitch of speech and its segments (Chuang & Bregler 2005 §5.1-5.2).

Pitch comes from librosa's probabilistic YIN (pYIN, Mauch & Dixon 2014): it returns a voiced
flag per frame from an HMM over pitch candidates, so the voiceless regions that cut §5.1's
segments come from the tracker itself rather than from a loudness threshold, and it is
maintained, pip-installable and pure Python on top of numpy/scipy (the paper used Praat).
librosa is imported where it is used: it takes a second to import.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


def track(samples: np.ndarray, sample_rate: int, *, fmin: float, fmax: float, hop_s: float,
          resolution: float = 0.1) -> np.ndarray:
    """Raw pitch (P,) float64 Hz every ``hop_s`` seconds, NaN where pYIN finds no voicing.

    samples : (S,) float audio at ``sample_rate`` Hz. Frames are centred at ``k * hop_s``.
    resolution : pYIN's pitch-bin width in semitones.
    """
    import librosa

    y = np.asarray(samples, dtype=np.float32)
    hop = max(1, int(round(hop_s * sample_rate)))
    frame = 1 << int(np.ceil(np.log2(max(4 * sample_rate / fmin, 2 * hop))))  # four periods of the lowest pitch
    if len(y) < frame:
        y = np.pad(y, (0, frame - len(y)))
    f0, voiced, _ = librosa.pyin(y, fmin=fmin, fmax=fmax, sr=sample_rate, frame_length=frame, hop_length=hop,
                                 center=True, resolution=resolution)
    f0 = np.where(voiced, f0, np.nan).astype(np.float64)
    n = int(np.ceil(len(samples) / hop))
    return f0[:max(n, 1)]


def runs(mask: np.ndarray) -> list[tuple[int, int]]:
    """[start, end) index runs where ``mask`` (1-D bool) is True."""
    edges = np.diff(np.concatenate([[0], mask.astype(np.int8), [0]]))
    return list(zip(np.nonzero(edges == 1)[0].tolist(), np.nonzero(edges == -1)[0].tolist()))


def clean(f0: np.ndarray, *, fmin: float, fmax: float, hop_s: float, max_gap_s: float, min_voiced_s: float) -> np.ndarray:
    """§5.1 cleaning: pitch outside [fmin, fmax] Hz is dropped, voiced runs shorter than
    ``min_voiced_s`` are dropped as tracker noise, and gaps up to ``max_gap_s`` between voiced
    frames are filled by linear interpolation. (P,) Hz in, (P,) Hz out (NaN: unvoiced)."""
    p = np.where((f0 >= fmin) & (f0 <= fmax), f0, np.nan)
    for a, b in runs(np.isfinite(p)):
        if (b - a) * hop_s < min_voiced_s:
            p[a:b] = np.nan
    voiced = np.isfinite(p)
    for a, b in runs(~voiced):
        if a > 0 and b < len(p) and (b - a) * hop_s <= max_gap_s:
            p[a:b] = np.interp(np.arange(a, b), [a - 1, b], [p[a - 1], p[b]])
    return p


@dataclass
class Segment:
    """A pitch segment: from one voiced onset to the next (§5.1), times in s.

    start, end : the segment; voiced_end : end of its first voiced run. contour : (n,) the
    voiced run's pitch in semitones re 100 Hz.
    """

    start: float
    end: float
    voiced_end: float
    contour: np.ndarray


def semitones(hz: np.ndarray) -> np.ndarray:
    """Pitch in semitones relative to 100 Hz."""
    return 12.0 * np.log2(hz / 100.0)


def segments(p: np.ndarray, hop_s: float, duration_s: float) -> list[Segment]:
    """§5.1 segments of a cleaned pitch track (P,) Hz: each voiced onset to the next onset
    (the last to ``duration_s``). No voiced frame: no segments."""
    voiced = runs(np.isfinite(p))
    out = []
    for n, (a, b) in enumerate(voiced):
        end = voiced[n + 1][0] * hop_s if n + 1 < len(voiced) else duration_s
        out.append(Segment(a * hop_s, max(end, b * hop_s), b * hop_s, semitones(p[a:b])))
    return out


#: Names of the sentence features of §5.2 (Dellaert et al. 1996).
SENTENCE_FEATURES = ("onsets_per_s", "rhythm_cv", "voiced_fraction", "mean_voiced_s", "mean_voiceless_s",
                     "pitch_min", "pitch_max", "pitch_mean", "pitch_std")


def sentence_features(p: np.ndarray, hop_s: float) -> np.ndarray:
    """§5.2 phrase-level features (9,) of a cleaned pitch track (Hz): speaking rate (voiced
    onsets per second of speech), rhythm (coefficient of variation of onset intervals), voiced
    fraction, mean voiced and voiceless run lengths (s), and pitch min/max/mean/std (semitones)."""
    voiced = np.isfinite(p)
    vr = runs(voiced)
    if not vr:
        return np.zeros(len(SENTENCE_FEATURES))
    span = (vr[-1][1] - vr[0][0]) * hop_s
    onsets = np.array([a for a, _ in vr]) * hop_s
    gaps = np.diff(onsets)
    inner_unvoiced = [(b - a) * hop_s for a, b in runs(~voiced) if a > vr[0][0] and b < vr[-1][1]]
    st = semitones(p[voiced])
    return np.array([len(vr) / max(span, hop_s),
                     float(gaps.std() / gaps.mean()) if len(gaps) > 1 else 0.0,
                     voiced[vr[0][0]:vr[-1][1]].mean(),
                     np.mean([(b - a) * hop_s for a, b in vr]),
                     np.mean(inner_unvoiced) if inner_unvoiced else 0.0,
                     st.min(), st.max(), st.mean(), st.std()])


def geometry(contour: np.ndarray, hop_s: float) -> np.ndarray:
    """§5.2 geometric properties G of a segment's contour (semitones): min, max, range, min
    slope, max slope (semitones/s) and mean curvature (semitones/s^2). (6,)"""
    c = contour
    slope = np.diff(c) / hop_s if len(c) > 1 else np.zeros(1)
    curv = np.diff(c, 2) / hop_s ** 2 if len(c) > 2 else np.zeros(1)
    return np.array([c.min(), c.max(), c.max() - c.min(), slope.min(), slope.max(), curv.mean()])


def resample(contour: np.ndarray, n: int) -> np.ndarray:
    """A contour linearly resampled to ``n`` points (length normalisation of Eq. 10)."""
    if len(contour) == 1:
        return np.full(n, contour[0])
    return np.interp(np.linspace(0, len(contour) - 1, n), np.arange(len(contour)), contour)
