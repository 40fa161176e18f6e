"""Audio: WAV/FLAC through ``soundfile``; mono float32 in [-1, 1]."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import soundfile as sf

from facesynth.base import limits
from facesynth.base.errors import InputError


def read_audio(path: Path) -> tuple[np.ndarray, int]:
    """Read audio as mono. Returns (samples (n,) float32, sample rate Hz)."""
    path = Path(path)
    if not path.exists():
        raise InputError(f"{path}: audio file not found; check the path.")
    try:
        data, rate = sf.read(str(path), dtype="float32", always_2d=True)
    except (sf.LibsndfileError, RuntimeError, TypeError) as exc:
        raise InputError(f"{path}: unreadable audio ({exc}); use WAV or FLAC.") from None
    if data.shape[0] == 0:
        raise InputError(f"{path}: the audio file has no samples.")
    if rate <= 0:
        raise InputError(f"{path}: the header gives a sample rate of {rate} Hz; re-export the audio.")
    finite = np.isfinite(data).all(axis=1)
    if not finite.all():
        first = int(np.argmin(finite))
        raise InputError(f"{path}, {first / rate:.3f} s: a sample is NaN or infinite; re-export the audio.")
    limits.bound(data.shape[0] / rate, "max_utterance_s", "the audio's length (s)", str(path))
    return data.mean(axis=1).astype(np.float32), int(rate)


def write_wav(path: Path, samples: np.ndarray, rate: int) -> None:
    """Write mono 16-bit PCM WAV."""
    sf.write(str(path), np.clip(samples, -1.0, 1.0), int(rate), subtype="PCM_16")


def resample(samples: np.ndarray, rate: int, target: int) -> np.ndarray:
    """Polyphase resampling to ``target`` Hz."""
    if rate == target:
        return samples
    from math import gcd

    from scipy.signal import resample_poly

    g = gcd(int(rate), int(target))
    return resample_poly(samples, target // g, rate // g).astype(np.float32)
