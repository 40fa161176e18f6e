"""Synthetic speakers: a recorded voice made into another speaker's and another microphone's, so that
an articulation model fitted on a few real voices learns what does not depend on them (training
only: a synthetic voice is no evidence of how the model does on a real one).

A :class:`Voice` changes, in this order:

* the **vocal tract's length**: the short-time spectrum's frequency axis scaled by ``warp``
  (formants and harmonics move together, as between a longer and a shorter tract and its larynx:
  0.85 a larger speaker, 1.2 a smaller one), on 32 ms frames with the original phases;
* the **microphone and channel**: a first-order high-pass at ``low_hz``, a low-pass at
  ``high_hz`` (8th order; a telephone band at 3.4 kHz), a spectral tilt of ``tilt_db`` per octave around
  1 kHz and a gain of ``gain_db``;
* **noise**: white noise ``snr_db`` below the voice's RMS over its loud frames.

Deterministic: the same voice and samples give the same audio (the noise is seeded by ``seed``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Voice:
    """One synthetic speaker and channel (module docstring): warp (frequency-axis factor), low_hz and
    high_hz (Hz, the band), tilt_db (dB/octave around 1 kHz), gain_db, snr_db (dB), seed (noise)."""

    warp: float = 1.0
    low_hz: float = 60.0
    high_hz: float = 7800.0
    tilt_db: float = 0.0
    gain_db: float = 0.0
    snr_db: float = 60.0
    seed: int = 0


def random_voice(rng: np.random.Generator) -> Voice:
    """A voice drawn from the ranges of real speakers and consumer microphones: warp 0.82..1.22
    (men to children around the training voice), band 50..300 Hz to 3.4..8 kHz, tilt -4..+4
    dB/octave, gain -20..+6 dB, noise 15..50 dB below the voice."""
    return Voice(warp=float(np.exp(rng.uniform(np.log(0.82), np.log(1.22)))),
                 low_hz=float(rng.uniform(50.0, 300.0)), high_hz=float(rng.choice([3400.0, 5000.0, 7000.0, 8000.0])),
                 tilt_db=float(rng.uniform(-4.0, 4.0)), gain_db=float(rng.uniform(-20.0, 6.0)),
                 snr_db=float(rng.uniform(15.0, 50.0)), seed=int(rng.integers(0, 2 ** 31 - 1)))


def warp_spectrum(samples: np.ndarray, rate: int, warp: float, nperseg: int | None = None) -> np.ndarray:
    """(n,) float64 ``samples`` (n,) at ``rate`` Hz with the short-time spectrum's frequency axis
    scaled by ``warp`` (the magnitude at f moves to warp x f; phases kept), overlap-added back."""
    from scipy.signal import istft, stft

    x = np.asarray(samples, np.float64)
    if abs(warp - 1.0) < 1e-6 or len(x) == 0:
        return x.copy()
    nperseg = nperseg or int(2 ** np.ceil(np.log2(0.032 * rate)))
    _, _, z = stft(x, rate, nperseg=nperseg, noverlap=3 * nperseg // 4, boundary="even")
    k = np.arange(z.shape[0], dtype=np.float64)
    src = k / warp  # the bin whose magnitude lands at bin k
    mag = np.abs(z)
    lo = np.clip(np.floor(src).astype(np.int64), 0, z.shape[0] - 1)
    hi = np.clip(lo + 1, 0, z.shape[0] - 1)
    frac = (src - lo)[:, None]
    warped = (1.0 - frac) * mag[lo] + frac * mag[hi]
    warped[src > z.shape[0] - 1] = 0.0
    out = warped * np.exp(1j * np.angle(z))
    _, y = istft(out, rate, nperseg=nperseg, noverlap=3 * nperseg // 4, boundary=True)
    return fit_to(y, len(x))


def fit_to(x: np.ndarray, n: int) -> np.ndarray:
    """(n,) ``x`` cut or padded with zeros."""
    return x[:n] if len(x) >= n else np.concatenate([x, np.zeros(n - len(x))])


def channel(samples: np.ndarray, rate: int, voice: Voice) -> np.ndarray:
    """(n,) ``samples`` through the voice's band, tilt and gain (frequency domain, zero phase)."""
    x = np.asarray(samples, np.float64)
    n = len(x)
    if n == 0:
        return x.copy()
    spec = np.fft.rfft(x)
    f = np.fft.rfftfreq(n, 1.0 / rate)
    high_pass = 1.0 / np.sqrt(1.0 + (voice.low_hz / np.maximum(f, 1e-3)) ** 2)
    low_pass = 1.0 / np.sqrt(1.0 + (f / min(voice.high_hz, rate / 2)) ** 16)  # 8th order
    tilt = 10.0 ** (voice.tilt_db * np.log2(np.maximum(f, 20.0) / 1000.0) / 20.0)
    gain = 10.0 ** (voice.gain_db / 20.0)
    return np.fft.irfft(spec * high_pass * low_pass * tilt * gain, n)


def transform(samples: np.ndarray, rate: int, voice: Voice) -> np.ndarray:
    """(n,) float64: mono ``samples`` (n,) at ``rate`` Hz as ``voice`` speaks them (module docstring)."""
    y = channel(warp_spectrum(samples, rate, voice.warp), rate, voice)
    if voice.snr_db < 60.0 and len(y):
        hop = max(1, rate // 100)
        frames = y[:len(y) // hop * hop].reshape(-1, hop)
        rms = np.sqrt((frames * frames).mean(1)) if len(frames) else np.zeros(1)
        loud = float(np.sqrt(np.mean(np.square(rms[rms >= np.percentile(rms, 70)])))) if len(rms) else 0.0
        noise = np.random.default_rng(voice.seed).standard_normal(len(y))
        y = y + noise * loud * 10.0 ** (-voice.snr_db / 20.0)
    return y
