"""A voice's vocal-tract length against a reference's (vocal-tract-length normalization): the
warp ``w`` such that the voice's formants lie at ``w`` times the reference's, from the long-term
spectral envelope of its voiced frames. A warp changes the frequencies every formant lies at by
one factor, a shift on a log-frequency axis; a microphone's tilt is a line on that axis. So the
voice's long-term log envelope, less its line, is slid along the log-frequency axis against the
reference's, and the shift of best correlation is the warp's logarithm. The features then read
the voice's spectrum at ``w`` times their frequencies
(:func:`facesynth.domain.voice.articulation.warped_filterbank`).

A second estimate reads the warp from the voice's median pitch (:func:`median_pitch`,
:func:`pitch_warp`): across speakers, formants scale with about the 0.27th power of the pitch.

Neither helped the articulation model on real speakers held out (``docs/real-speech.md``,
``benchmarks/voice_features.json``): the envelope's warp follows the recording more than the
speaker, and the pitch's, though it tells women from men, leaves the r level or lower. Both are
kept for the benchmark that measured them (``benchmarks/voice_speakers.py --features``); the
packaged model reads unwarped features.
"""

from __future__ import annotations

import numpy as np

from . import articulation as A

#: The log-frequency grid (ln Hz, steps of 0.01) on which a voice's long-term envelope is compared
#: with a reference's: 300..4500 Hz (the formants), and how far a voice's may shift (ln of the warp).
WARP_GRID = np.arange(np.log(300.0), np.log(4500.0), 0.01)
MAX_LOG_WARP = 0.25


def long_term_envelope(samples: np.ndarray, rate: int) -> np.ndarray | None:
    """(G,) float64 long-term log envelope of a voice on ``WARP_GRID`` widened by ``MAX_LOG_WARP``
    both ways (G = len(WARP_GRID) + 2 * 25): the mean liftered log envelope (:func:`envelope_of`)
    of its voiced frames within 30 dB of its loudest, read at log-spaced frequencies. None when the
    audio has fewer than 20 such frames."""
    import scipy.fft

    x = A.to_analysis_rate(samples, rate)
    k = A.frame_count(len(x))
    padded = np.concatenate([np.zeros(A.WIN // 2, np.float32), x.astype(np.float32), np.zeros(A.WIN, np.float32)])
    frames = np.lib.stride_tricks.sliding_window_view(padded, A.WIN)[::A.HOP][:k]
    total, count = np.zeros(A.NFFT // 2 + 1), 0
    raw = A.frame_features(samples, rate)
    loud = (raw[:, A.I_VOICING] > 0.6) & (raw[:, A.I_LOG_RMS] > raw[:, A.I_LOG_RMS].max() - 3.45)
    picked = np.flatnonzero(loud)
    for a in range(0, len(picked), 4096):
        f = frames[picked[a:a + 4096]].astype(np.float32)
        f = f - f.mean(1, keepdims=True)
        spec = scipy.fft.rfft(f * A._WINDOW, A.NFFT, axis=1)
        total += A.envelope_of(np.log(np.abs(spec) ** 2 / A._WIN_POWER + A.POWER_FLOOR)).sum(0)
        count += len(f)
    if count < 20:
        return None
    step = int(round(MAX_LOG_WARP / 0.01))
    grid = np.concatenate([WARP_GRID[0] - 0.01 * np.arange(step, 0, -1), WARP_GRID,
                           WARP_GRID[-1] + 0.01 * np.arange(1, step + 1)])
    return np.interp(np.exp(grid), A._FREQS, total / count)


def _detrended(v: np.ndarray) -> np.ndarray:
    """``v`` (G,) less its least-squares line (a channel's tilt, linear in log frequency), unit norm."""
    t = np.arange(len(v), dtype=np.float64)
    t -= t.mean()
    r = v - v.mean() - t * (t @ (v - v.mean())) / (t @ t)
    return r / max(float(np.linalg.norm(r)), 1e-12)


def estimate_warp(lte: np.ndarray | None, reference: np.ndarray) -> float:
    """The vocal-tract warp of a voice against a reference: the factor ``w`` (exp(-0.25)..exp(0.25))
    such that the voice's long-term envelope ``lte`` (:func:`long_term_envelope`) at ``w`` times a
    frequency best matches ``reference`` (G,) (the reference's, read on ``WARP_GRID``) at that
    frequency, each less its tilt (correlation over shifts on the log-frequency axis, refined by a
    parabola). 1.0 when ``lte`` is None."""
    if lte is None:
        return 1.0
    step = int(round(MAX_LOG_WARP / 0.01))
    ref = _detrended(np.asarray(reference, np.float64))
    g = len(ref)
    scores = np.array([_detrended(lte[step + s:step + s + g]) @ ref for s in range(-step, step + 1)])
    i = int(np.argmax(scores))
    shift = float(i - step)
    if 0 < i < len(scores) - 1:
        a, b, c = scores[i - 1], scores[i], scores[i + 1]
        if a - 2 * b + c < 0:
            shift += 0.5 * (a - c) / (a - 2 * b + c)
    return float(np.exp(0.01 * shift))


#: How a voice's formants scale with its pitch across speakers: women's pitch is about 1.8 times
#: men's and their formants about 1.17 times (Peterson and Barney 1952), 1.17 = 1.8 ** 0.27.
PITCH_TO_WARP = 0.27


def median_pitch(samples: np.ndarray, rate: int) -> float | None:
    """The median pitch (Hz, 60..400) of a voice's voiced frames within 30 dB of its loudest (the
    lag of the peak of each frame's normalized autocorrelation); None with fewer than 20 of them."""
    import scipy.fft

    x = A.to_analysis_rate(samples, rate)
    k = A.frame_count(len(x))
    padded = np.concatenate([np.zeros(A.WIN // 2, np.float32), x.astype(np.float32), np.zeros(A.WIN, np.float32)])
    frames = np.lib.stride_tricks.sliding_window_view(padded, A.WIN)[::A.HOP][:k]
    raw = A.frame_features(samples, rate)
    picked = np.flatnonzero((raw[:, A.I_VOICING] > 0.6) & (raw[:, A.I_LOG_RMS] > raw[:, A.I_LOG_RMS].max() - 3.45))
    if len(picked) < 20:
        return None
    pitches = []
    for a in range(0, len(picked), 4096):
        f = frames[picked[a:a + 4096]].astype(np.float64)
        f = (f - f.mean(1, keepdims=True)) * A._WINDOW
        power = np.abs(scipy.fft.rfft(f, A.NFFT, axis=1)) ** 2
        ac = scipy.fft.irfft(power, A.NFFT, axis=1)[:, :A.LAG_MAX + 1]
        lags = A.LAG_MIN + np.argmax(ac[:, A.LAG_MIN:], axis=1)
        pitches.append(A.RATE / lags)
    return float(np.median(np.concatenate(pitches)))


def pitch_warp(pitch: float | None, reference_pitch: float) -> float:
    """The vocal-tract warp a voice's median ``pitch`` (Hz) implies against a reference's:
    ``(pitch / reference_pitch) ** PITCH_TO_WARP``, within exp(+-MAX_LOG_WARP); 1.0 for None."""
    if pitch is None or reference_pitch <= 0:
        return 1.0
    return float(np.exp(np.clip(PITCH_TO_WARP * np.log(pitch / reference_pitch), -MAX_LOG_WARP, MAX_LOG_WARP)))
