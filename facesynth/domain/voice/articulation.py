"""The voice's articulation (issue 42): frame features of the voice, batch and streaming, and a
linear model from them to the mouth's curves (jaw, opening, rounding), fitted on captures with audio.

**Features.** What the voice says about the mouth, per 10 ms analysis frame, from NumPy and SciPy
only (no librosa: its import costs about a second of ``synthesize``):

=================  =====================================================================  =========
name               what                                                                   unit
=================  =====================================================================  =========
``mel_00..mel_31`` log power in 32 mel bands, 60..7600 Hz (the spectral envelope: F1        log power
                   follows the jaw, F2 the lips' rounding and spreading, the nasal murmur
                   of /m n/, the burst of /p b/, the hiss of /f s/)
``log_rms``        log RMS of the frame (loudness: the jaw's excursion per syllable)        log amplitude
``voicing``        peak of the normalized autocorrelation at 60..400 Hz (vowel vs voiceless 0..1
                   consonant vs silence)
``zcr``            zero crossings per sample (frication, /s f sh/)                         1/sample
``tilt``           slope of the log-mel spectrum per band (breathy/closed vs open vowels)   log power/band
``f1_proxy``       power-weighted mean frequency in 200..900 Hz (a first-formant proxy)     kHz
``f2_proxy``       power-weighted mean frequency in 900..2600 Hz (a second-formant proxy)   kHz
``hf_ratio``       log share of the power above 3.5 kHz (frication)                         log ratio
``lf_ratio``       log share of the power below 1 kHz (voiced low band, nasals)             log ratio
=================  =====================================================================  =========

Frames: audio resampled to 16 kHz; analysis frame ``k`` is a 32 ms Hann window centred on
``k * 10 ms`` (the audio before time 0 and after the end is silence), so frame ``k`` needs the
audio up to ``k * 10 ms + 16 ms``. The model samples these frames at fixed offsets around each
output frame time (:func:`context`), so the look-ahead of a prediction is ``max(offsets) + 16 ms``
(plus the pooling of :func:`context`), independent of the output frame rate.

Two alternatives of the mel bands were measured on held-out speakers and are not what a model
reads (``docs/real-speech.md``: neither beat these): ``envelope`` (the bands of the cepstrally
liftered log envelope, :func:`envelope_of`: no pitch harmonics) and ``warp`` (the bands and
formant proxies read at a vocal-tract warp, :func:`warped_filterbank`,
:mod:`facesynth.domain.voice.tract`), parameters of :func:`frame_features`.

**Normalization** (:class:`Normalizer`): a speaker's voice and a microphone shift every log band by
a constant (gain) and colour it (a filter); the mouth does not care. Each feature is standardized
by a mean and standard deviation that are the training set's (``global``), the whole utterance's
(``utterance``, offline only), or a running estimate (``running``, the default: an exponential
average with time constant ``tau_s``, updated only on frames with speech, started from the
training set's statistics, so it runs frame by frame and adapts to a new voice within seconds).

**Model** (:func:`fit`, :func:`predict`, :class:`StreamingPredictor`): ridge regression from the
normalized features (plus a few loudness hinges, :func:`expand`) read at 10 offsets from -250 ms
to +20 ms around each output frame, to the mouth's curves of a capture (FACEGOOD's ARKit curves,
any performer's curves with their audio). The context is a learned FIR filter over the feature
stream: it reads the onset of the coming sound (look-ahead 46 ms) and the syllable's envelope
behind it. Linear because, held out by take on FACEGOOD, it matched a small MLP; it fits in
seconds on a few minutes of capture and predicts with one matrix product per frame. The fitted
parameters are a :class:`facesynth.model.articulation.ArticulationModel` (the ``articulation``
artifact). On FACEGOOD (fitted on 1114_2_01..03, scored on 1114_2_04, 1114_2_05, 1114_3_15;
``benchmarks/voice_articulation.py``) the predicted mouth opening follows the speaker's with
r 0.73 against 0.68 for the loudness envelope alone.

Streaming (:class:`StreamingFeatures`, :class:`StreamingPredictor`): the same frames and
predictions from chunks of audio of any length, equal to the batch ones to float32 rounding.
Everything is deterministic (no random numbers).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from math import gcd

import numpy as np

from facesynth.base.errors import ArtifactError, InputError
from facesynth.model.articulation import NORMALIZATIONS, ArticulationModel

#: Analysis sample rate (Hz), hop (samples: 10 ms), window (samples: 32 ms) and FFT size.
RATE = 16000
HOP = 160
WIN = 512
NFFT = 1024
N_MELS = 32
FMIN, FMAX = 60.0, 7600.0
#: Seconds between analysis frames.
FRAME_S = HOP / RATE
#: Audio past a frame's centre that the frame reads (s).
HALF_WINDOW_S = WIN / 2 / RATE
#: The floor of the band and frame powers (about -100 dB of a full-scale sine): digital silence is
#: a finite, constant feature.
POWER_FLOOR = 1e-10
#: Pitch lags searched for voicing: 60..400 Hz.
LAG_MIN, LAG_MAX = RATE // 400, RATE // 60

FEATURE_NAMES: tuple[str, ...] = tuple(f"mel_{i:02d}" for i in range(N_MELS)) + (
    "log_rms", "voicing", "zcr", "tilt", "f1_proxy", "f2_proxy", "hf_ratio", "lf_ratio")
N_FEATURES = len(FEATURE_NAMES)
I_LOG_RMS = FEATURE_NAMES.index("log_rms")
I_VOICING = FEATURE_NAMES.index("voicing")


def _hz_to_mel(f):
    return 2595.0 * np.log10(1.0 + np.asarray(f, np.float64) / 700.0)


def _mel_to_hz(m):
    return 700.0 * (10.0 ** (np.asarray(m, np.float64) / 2595.0) - 1.0)


def mel_edges_hz(n_mels: int = N_MELS, fmin: float = FMIN, fmax: float = FMAX) -> np.ndarray:
    """(n_mels + 2,) Hz the edges of the mel bands, HTK mel scale: band i rises from edge i, peaks
    at edge i + 1 (its centre) and falls to edge i + 2."""
    return _mel_to_hz(np.linspace(_hz_to_mel(fmin), _hz_to_mel(fmax), n_mels + 2))


def mel_filterbank(n_mels: int = N_MELS, nfft: int = NFFT, rate: int = RATE, fmin: float = FMIN,
                   fmax: float = FMAX) -> np.ndarray:
    """(n_mels, nfft // 2 + 1) float64 triangular filters, HTK mel scale, each of unit area (so
    a band's value is a mean power density, comparable across band widths)."""
    freqs = np.arange(nfft // 2 + 1) * rate / nfft
    edges = mel_edges_hz(n_mels, fmin, fmax)
    lo, mid, hi = edges[:-2, None], edges[1:-1, None], edges[2:, None]
    up = (freqs[None] - lo) / (mid - lo)
    down = (hi - freqs[None]) / (hi - mid)
    fb = np.clip(np.minimum(up, down), 0.0, None)
    return fb / np.maximum(fb.sum(1, keepdims=True), 1e-12)


_WINDOW = np.hanning(WIN + 2)[1:-1].astype(np.float32)  # symmetric Hann without its zero end points
_WIN_POWER = float(_WINDOW.astype(np.float64) @ _WINDOW)
_MEL_T = mel_filterbank().T.astype(np.float32)  # (NFFT // 2 + 1, N_MELS)
_FREQS = np.arange(NFFT // 2 + 1) * RATE / NFFT
_BAND_F1 = (_FREQS >= 200) & (_FREQS < 900)
_BAND_F2 = (_FREQS >= 900) & (_FREQS < 2600)
# band sums as one matrix product: columns F1 power, F1 power x kHz, F2 power, F2 power x kHz, above
# 3.5 kHz, below 1 kHz, total
_BANDS = np.stack([_BAND_F1, _BAND_F1 * _FREQS / 1000.0, _BAND_F2, _BAND_F2 * _FREQS / 1000.0,
                   _FREQS >= 3500, _FREQS < 1000, np.ones_like(_FREQS)], 1).astype(np.float32)
_TILT = np.arange(N_MELS) - (N_MELS - 1) / 2.0
_TILT = (_TILT / float(_TILT @ _TILT)).astype(np.float32)
# Voicing from the autocorrelation of the frame low-passed to 4 kHz and decimated by 2 (the inverse
# FFT of the power spectrum's lower half: half the cost, pitch lags of 60..400 Hz in steps of 1/8 ms).
_AC_N = NFFT // 2
_LAG_MIN2, _LAG_MAX2 = LAG_MIN // 2, LAG_MAX // 2
_WIN_AC = np.fft.irfft((np.abs(np.fft.rfft(_WINDOW.astype(np.float64), NFFT)) ** 2)[:_AC_N // 2 + 1], _AC_N)
_WIN_AC = (_WIN_AC[:_LAG_MAX2 + 1] / _WIN_AC[0]).astype(np.float32)


def to_analysis_rate(samples: np.ndarray, rate: int) -> np.ndarray:
    """Mono ``samples`` (n,) at ``rate`` Hz as float64 at :data:`RATE` (polyphase resampling)."""
    x = np.asarray(samples, np.float64)
    if x.ndim != 1:
        raise InputError(f"audio samples must be mono (n,), got shape {x.shape}.")
    if int(rate) == RATE:
        return x
    from scipy.signal import resample_poly  # scipy where used: `synthesize` starts without it

    g = gcd(int(rate), RATE)
    return resample_poly(x, RATE // g, int(rate) // g)


def frame_count(n_samples: int) -> int:
    """Analysis frames of ``n_samples`` at :data:`RATE`: every centre k * HOP within the audio."""
    return int(np.ceil(n_samples / HOP)) if n_samples > 0 else 0


#: Quefrency (samples at :data:`RATE`) below which the cepstrum is kept whole by :func:`envelope_of`,
#: and above which it is gone (a half-Hann taper between): 1.25..1.9 ms, below the pitch period of
#: any voice up to 530 Hz, so the log envelope keeps the formants and loses the harmonics.
LIFTER_PASS, LIFTER_STOP = 20, 30
_LIFTER = np.zeros(NFFT // 2 + 1, np.float32)
_LIFTER[:LIFTER_PASS] = 1.0
_LIFTER[LIFTER_PASS:LIFTER_STOP] = 0.5 + 0.5 * np.cos(np.pi * (np.arange(LIFTER_STOP - LIFTER_PASS) + 1)
                                                      / (LIFTER_STOP - LIFTER_PASS + 1))


def envelope_of(log_power: np.ndarray) -> np.ndarray:
    """(K, NFFT // 2 + 1) float32 log spectral envelope of log power spectra (K, NFFT // 2 + 1):
    the real cepstrum liftered to quefrencies below :data:`LIFTER_STOP` samples (the vocal tract's
    smooth envelope; the pitch's harmonics, at the pitch period and beyond, are removed)."""
    import scipy.fft

    cep = scipy.fft.irfft(log_power, NFFT, axis=1)[:, :NFFT // 2 + 1]
    cep *= _LIFTER
    # the cepstrum is even: its spectrum is the cosine series of its first half (a DCT-I)
    return scipy.fft.dct(cep, type=1, axis=1).astype(np.float32)


def warped_filterbank(warp: float) -> np.ndarray:
    """(NFFT // 2 + 1, N_MELS) float32 mel filters read at ``warp`` times their frequencies below
    5.6 kHz / max(warp, 1) and linearly up to :data:`FMAX` above (piecewise-linear vocal-tract-length
    warping): a voice whose formants are ``warp`` times a reference's reads in each band what the
    reference reads in it. ``warp`` 1 is the plain filterbank."""
    if abs(warp - 1.0) < 1e-9:
        return _MEL_T
    cut = 5600.0 / max(warp, 1.0)
    edges = _mel_to_hz(np.linspace(_hz_to_mel(FMIN), _hz_to_mel(FMAX), N_MELS + 2))
    top = FMAX
    warped = np.where(edges <= cut, warp * edges,
                      warp * cut + (edges - cut) * (top - warp * cut) / (top - cut))
    lo, mid, hi = warped[:-2, None], warped[1:-1, None], warped[2:, None]
    up = (_FREQS[None] - lo) / (mid - lo)
    down = (hi - _FREQS[None]) / (hi - mid)
    fb = np.clip(np.minimum(up, down), 0.0, None)
    return (fb / np.maximum(fb.sum(1, keepdims=True), 1e-12)).T.astype(np.float32)


def features_of_frames(frames: np.ndarray, envelope: bool = False, warp: float = 1.0) -> np.ndarray:
    """(K, N_FEATURES) float32 features of (K, WIN) raw (unwindowed) sample frames at :data:`RATE`
    (the columns of :data:`FEATURE_NAMES`). Float32 throughout (the features are far coarser).
    ``envelope``: the mel bands (and the tilt) read the cepstrally liftered log envelope
    (:func:`envelope_of`: no pitch harmonics) instead of the log power; ``warp``: the bands and the
    formant proxies read at ``warp`` times their frequencies (:func:`warped_filterbank`)."""
    import scipy.fft  # scipy where used: `synthesize` starts without it

    k = len(frames)
    out = np.empty((k, N_FEATURES), np.float32)
    if k == 0:
        return out
    x = np.asarray(frames, np.float32)
    x = x - x.mean(1, keepdims=True)
    spec = scipy.fft.rfft(x * _WINDOW, NFFT, axis=1)
    power = spec.real * spec.real
    power += spec.imag * spec.imag
    power *= 1.0 / _WIN_POWER
    fb = warped_filterbank(warp)
    if envelope:
        mel = envelope_of(np.log(power + POWER_FLOOR)) @ fb
    else:
        mel = np.log(power @ fb + POWER_FLOOR)
    out[:, :N_MELS] = mel
    out[:, I_LOG_RMS] = 0.5 * np.log(np.einsum("ij,ij->i", x, x) / WIN + POWER_FLOOR)
    ac = scipy.fft.irfft(power[:, :_AC_N // 2 + 1], _AC_N, axis=1)[:, :_LAG_MAX2 + 1]
    ratio = ac[:, _LAG_MIN2:] / (np.maximum(ac[:, :1], 1e-30) * _WIN_AC[_LAG_MIN2:])
    out[:, I_VOICING] = np.clip(ratio.max(1), 0.0, 1.0) * (ac[:, 0] > 1e-8)
    signs = np.signbit(x)
    out[:, I_VOICING + 1] = np.count_nonzero(signs[:, 1:] != signs[:, :-1], axis=1) / (WIN - 1)
    out[:, I_VOICING + 2] = mel @ _TILT
    b = power @ (_BANDS if abs(warp - 1.0) < 1e-9 else _bands(warp))
    out[:, I_VOICING + 3] = b[:, 1] / (b[:, 0] + POWER_FLOOR)  # 0 in digital silence
    out[:, I_VOICING + 4] = b[:, 3] / (b[:, 2] + POWER_FLOOR)
    b += POWER_FLOOR
    out[:, I_VOICING + 5] = np.log(b[:, 4] / b[:, 6])
    out[:, I_VOICING + 6] = np.log(b[:, 5] / b[:, 6])
    return out


def _bands(warp: float) -> np.ndarray:
    """:data:`_BANDS` with the formant and low/high bands at ``warp`` times their frequencies (kHz
    read back in the reference's scale)."""
    f = _FREQS / warp
    f1, f2 = (f >= 200) & (f < 900), (f >= 900) & (f < 2600)
    return np.stack([f1, f1 * f / 1000.0, f2, f2 * f / 1000.0, f >= 3500, f < 1000, np.ones_like(f)],
                    1).astype(np.float32)


def frame_features(samples: np.ndarray, rate: int, envelope: bool = False, warp: float = 1.0) -> np.ndarray:
    """(K, N_FEATURES) float32 raw features of mono ``samples`` (n,) at ``rate`` Hz: analysis frame
    k centred at k * FRAME_S seconds, K = ceil(duration / FRAME_S) (``envelope``, ``warp``: as
    :func:`features_of_frames`)."""
    x = to_analysis_rate(samples, rate)
    k = frame_count(len(x))
    padded = np.concatenate([np.zeros(WIN // 2, np.float32), x.astype(np.float32), np.zeros(WIN, np.float32)])
    frames = np.lib.stride_tricks.sliding_window_view(padded, WIN)[::HOP][:k]  # a view: no copy
    out = np.empty((k, N_FEATURES), np.float32)
    block = 4096  # bounded memory: (block, NFFT) complex64 at a time, 17 MB
    for a in range(0, k, block):
        out[a:a + block] = features_of_frames(frames[a:a + block], envelope, warp)
    return out


# ---------------------------------------------------------------- normalization

@dataclass
class Normalizer:
    """Standardizes raw features (K, D): ``(x - mean) / std`` per feature.

    mode : "global" (``mean``, ``std`` of the training set), "utterance" (the utterance's own,
        from its frames with speech; offline only), or "running" (exponential averages with time
        constant ``tau_s`` seconds over the frames with speech, started at ``mean``, ``std``).
    mean, std : (D,) float64, the training set's statistics (fitted by :meth:`fit`).
    gate : a frame has speech when its log RMS is within ``gate`` (log amplitude: 4.6 = 40 dB)
        of the loudest frame so far (a peak follower that falls by ``peak_decay`` per second).
    """

    mode: str = "running"
    tau_s: float = 3.0
    gate: float = 4.6
    peak_decay: float = 0.5
    mean: np.ndarray = field(default_factory=lambda: np.zeros(N_FEATURES))
    std: np.ndarray = field(default_factory=lambda: np.ones(N_FEATURES))

    def __post_init__(self):
        if self.mode not in NORMALIZATIONS:
            raise InputError(f"normalization {self.mode!r}: use one of {', '.join(NORMALIZATIONS)}.")

    def speech(self, raw: np.ndarray, peak0: float | None = None) -> tuple[np.ndarray, float]:
        """(K,) bool: the frames of ``raw`` (K, D) with speech, and the peak follower's last value
        (``peak0`` its value before the first frame)."""
        e = raw[:, I_LOG_RMS].astype(np.float64)
        if len(e) == 0:
            return np.zeros(0, bool), (-np.inf if peak0 is None else peak0)
        # p_k = max(e_k, p_{k-1} - step) = max_j (e_j + step j) - step k: a running maximum
        step = self.peak_decay * FRAME_S
        ramp = step * np.arange(1, len(e) + 1)
        start = -np.inf if peak0 is None else peak0
        peak = np.maximum(np.maximum.accumulate(e + ramp), start) - ramp
        return e > peak - self.gate, float(peak[-1])

    def fit(self, raws: list[np.ndarray], weights: list[float] | None = None) -> "Normalizer":
        """Set ``mean``, ``std`` from the speech frames of training utterances (each (K, D)), each
        utterance's frames weighing ``weights`` (one per utterance; all alike without)."""
        chosen = [r[self.speech(r)[0]] for r in raws]
        weights = [1.0] * len(raws) if weights is None else weights
        w = np.concatenate([np.full(len(c), float(wt)) for c, wt in zip(chosen, weights)])
        self.mean, std = weighted_moments(np.concatenate(chosen).astype(np.float64), w)
        self.std = np.maximum(std, 1e-6)
        return self

    def apply(self, raw: np.ndarray) -> np.ndarray:
        """(K, D) float32 standardized features of ``raw`` (K, D) (one whole utterance)."""
        raw = np.asarray(raw, np.float64)
        if self.mode == "global" or len(raw) == 0:
            return ((raw - self.mean) / self.std).astype(np.float32)
        speech, _ = self.speech(raw)
        if self.mode == "utterance":
            rows = raw[speech] if speech.sum() >= 10 else raw
            return ((raw - rows.mean(0)) / np.maximum(rows.std(0), 1e-6)).astype(np.float32)
        state = RunningState.start(self)
        return state.update(self, raw)


@dataclass
class RunningState:
    """The state of a running normalization: means (D,), second moments (D,), peak follower."""

    mean: np.ndarray
    second: np.ndarray
    peak: float

    @classmethod
    def start(cls, norm: Normalizer) -> "RunningState":
        return cls(norm.mean.astype(np.float64).copy(), (norm.std ** 2 + norm.mean ** 2).astype(np.float64),
                   -np.inf)

    def update(self, norm: Normalizer, raw: np.ndarray) -> np.ndarray:
        """Standardize ``raw`` (K, D), frame after frame, each by the statistics of the frames
        before it and itself; advances the state. Returns (K, D) float32."""
        raw = np.asarray(raw, np.float64)
        speech, self.peak = norm.speech(raw, self.peak)
        a = 1.0 - np.exp(-FRAME_S / norm.tau_s)
        # m_k = m_{k-1} + a g_k (x_k - m_{k-1}) in closed form per block (no per-frame Python loop
        # over features): with c_k = prod_{i<=k} (1 - a g_i), m_k = c_k (m_0 + sum_j a g_j x_j / c_j).
        g = a * speech.astype(np.float64)
        out = np.empty(raw.shape, np.float32)
        block = 256  # keeps c_k far from underflow (0.99^256 ~ 0.08)
        for s in range(0, len(raw), block):
            x, gb = raw[s:s + block], g[s:s + block]
            c = np.cumprod(1.0 - gb)
            w = gb / c
            m = c[:, None] * (self.mean[None] + np.cumsum(w[:, None] * x, 0))
            m2 = c[:, None] * (self.second[None] + np.cumsum(w[:, None] * x * x, 0))
            std = np.sqrt(np.maximum(m2 - m * m, 1e-12))
            out[s:s + block] = (x - m) / np.maximum(std, 1e-6 + 0.05 * norm.std)
            self.mean, self.second = m[-1].copy(), m2[-1].copy()
        return out


# ---------------------------------------------------------------- context around a frame time

def context(normed: np.ndarray, times_s: np.ndarray, offsets_s: np.ndarray, pool: int = 3) -> np.ndarray:
    """(T, len(offsets) * D) float32: for each output frame time ``times_s`` (T,), the normalized
    features (K, D) at every offset (s) from it, each the mean of ``pool`` analysis frames centred
    there (so the look-ahead is ``max(offsets) + (pool // 2) * FRAME_S + HALF_WINDOW_S``); frames
    before the first and after the last are the first and last. Offset-major columns."""
    k, d = normed.shape
    if pool > 1:
        c = np.concatenate([np.zeros((1, d)), np.cumsum(normed, 0, dtype=np.float64)])
        lo = np.clip(np.arange(k) - pool // 2, 0, k)
        hi = np.clip(np.arange(k) + pool // 2 + 1, 0, k)
        normed = ((c[hi] - c[lo]) / (hi - lo)[:, None]).astype(np.float32)
    idx = np.rint((np.asarray(times_s)[:, None] + np.asarray(offsets_s)[None]) / FRAME_S).astype(np.int64)
    idx = np.clip(idx, 0, max(k - 1, 0))
    return normed[idx].reshape(len(times_s), -1) if k else np.zeros((len(times_s), len(offsets_s) * d), np.float32)


def look_ahead_s(offsets_s: np.ndarray, pool: int = 3) -> float:
    """Seconds of audio past a frame's time that its context reads, at most (an offset rounds to
    the nearest analysis frame, so a frame may read up to FRAME_S / 2 less)."""
    return float(max(0.0, np.max(offsets_s)) + (pool // 2) * FRAME_S + HALF_WINDOW_S)


# ---------------------------------------------------------------- streaming

class StreamingFeatures:
    """Raw analysis frames from audio chunks at :data:`RATE` (float, mono): ``push(chunk)``
    returns the (k, D) frames completed by it (frame j needs audio up to j * HOP + WIN / 2),
    ``finish()`` the rest (the audio after the end is silence). Equal to :func:`frame_features`
    of the whole audio."""

    def __init__(self):
        self.buffer = np.zeros(WIN // 2)  # silence before time 0
        self.offset = 0  # absolute padded-sample index of buffer[0]
        self.next_frame = 0
        self.samples = 0

    def _take(self, available_frames: int) -> np.ndarray:
        n = available_frames - self.next_frame
        if n <= 0:
            return np.zeros((0, N_FEATURES), np.float32)
        starts = (self.next_frame + np.arange(n)) * HOP - self.offset
        frames = self.buffer[starts[:, None] + np.arange(WIN)[None]]
        self.next_frame += n
        drop = self.next_frame * HOP - self.offset
        self.buffer, self.offset = self.buffer[drop:], self.offset + drop
        return features_of_frames(frames)

    def push(self, chunk: np.ndarray) -> np.ndarray:
        chunk = np.asarray(chunk, np.float64)
        self.buffer = np.concatenate([self.buffer, chunk])
        self.samples += len(chunk)
        end = self.offset + len(self.buffer)  # padded samples available
        ready = (end - WIN) // HOP + 1 if end >= WIN else 0
        return self._take(min(ready, frame_count(self.samples)))

    def finish(self) -> np.ndarray:
        self.buffer = np.concatenate([self.buffer, np.zeros(WIN)])
        return self._take(frame_count(self.samples))


# ---------------------------------------------------------------- the model

#: The default context: offsets (s) from the frame time at which the features are read (-250 ms
#: behind: the syllable's envelope; +20 ms ahead: the coming sound's onset). The look-ahead is
#: 46 ms, short enough for live frames within 80 ms of their sound; reading further ahead (+40,
#: +60 ms: 66 and 86 ms) added 0.002 to the mouth-opening r on FACEGOOD's scored takes (0.732 to
#: 0.734), too little to be worth the latency.
DEFAULT_OFFSETS_S = (-0.25, -0.2, -0.15, -0.12, -0.09, -0.06, -0.04, -0.02, 0.0, 0.02)
#: Knots (standardized log RMS) of the loudness hinges of :func:`expand`.
KNOTS = (-1.5, -0.75, 0.0, 0.75)
#: Columns :func:`expand` adds.
N_EXPANDED = len(KNOTS) + 2


def expand(z: np.ndarray) -> np.ndarray:
    """(K, D + 6) float32: normalized features (K, D) with a few nonlinear columns the jaw needs and
    a linear map cannot make: hinges max(0, e - knot) of the standardized loudness e (the jaw opens
    with loudness above the speech floor, not below it), and voicing times loudness."""
    e = z[:, I_LOG_RMS:I_LOG_RMS + 1]
    v = z[:, I_VOICING:I_VOICING + 1]
    cols = [np.maximum(e - k, 0.0) for k in KNOTS] + [v * e, np.maximum(v, 0.0) * np.maximum(e, 0.0)]
    return np.concatenate([z] + cols, 1).astype(np.float32)


def check_model(model: ArticulationModel, where: str = "the articulation model") -> None:
    """Refuse (ArtifactError) a model fitted on other voice features than this version computes."""
    if tuple(model.feature_names) != FEATURE_NAMES or int(model.analysis_rate) != RATE or int(model.hop) != HOP \
            or int(model.window) != WIN:
        raise ArtifactError(f"{where} was fitted on other voice features than this version computes; fit it again.")
    if model.expand and tuple(np.asarray(model.knots, np.float64).tolist()) != KNOTS:
        raise ArtifactError(f"{where} was fitted with other loudness knots than this version's; fit it again.")
    width = len(model.offsets_s) * (N_FEATURES + (N_EXPANDED if model.expand else 0))
    if np.shape(model.coef) != (width, len(model.target_names)):
        raise ArtifactError(f"{where}: coef has shape {np.shape(model.coef)}, expected "
                            f"({width}, {len(model.target_names)}); fit it again.")
    if not (np.isfinite(model.coef).all() and np.isfinite(model.intercept).all()):
        raise ArtifactError(f"{where}: its coefficients are not all finite numbers; fit it again on frames with "
                            "every target known.")


def normalizer_of(model: ArticulationModel) -> Normalizer:
    """The model's feature :class:`Normalizer`."""
    return Normalizer(mode=model.normalization, tau_s=float(model.tau_s), gate=float(model.gate),
                      peak_decay=float(model.peak_decay), mean=np.asarray(model.feature_mean, np.float64),
                      std=np.asarray(model.feature_std, np.float64))


def model_look_ahead_s(model: ArticulationModel) -> float:
    """Seconds of audio past a frame's time that the model's prediction of it reads."""
    return look_ahead_s(np.asarray(model.offsets_s), model.pool)


def design(model: ArticulationModel, raw: np.ndarray, times_s: np.ndarray) -> np.ndarray:
    """(T, Xa) float32 context of raw features (K, D) (:func:`frame_features`) at output frame times
    (T,) s: normalized, expanded where the model is, pooled and read at its offsets."""
    z = normalizer_of(model).apply(raw)
    if model.expand:
        z = expand(z)
    return context(z, times_s, np.asarray(model.offsets_s, np.float64), model.pool)


def predict_raw(model: ArticulationModel, raw: np.ndarray, times_s: np.ndarray) -> np.ndarray:
    """(T, Y) float64 predicted curves at ``times_s`` (T,) s from raw features (K, D)."""
    # a float32 product: the context is float32, and a float64 copy of it costs more than the product
    coef = np.asarray(model.coef, np.float64).astype(np.float32)
    return (design(model, raw, times_s) @ coef).astype(np.float64) + np.asarray(model.intercept, np.float64)


def predict(model: ArticulationModel, samples: np.ndarray, rate: int, n_frames: int, fps: float) -> np.ndarray:
    """(n_frames, Y) float64 predicted curves (the model's ``target_names``, in their units) at
    frame times f / fps s of mono ``samples`` (n,) at ``rate`` Hz; a frame past the audio's end
    reads the audio's last analysis frames (its context is clipped to them)."""
    check_model(model)
    return predict_raw(model, frame_features(samples, rate), np.arange(n_frames) / float(fps))


# ---------------------------------------------------------------- closure targets of a capture

def closure_frames_of(opening: np.ndarray, depth: float = 0.25, prominence: float = 0.25) -> np.ndarray:
    """Frames (K,) of the closures of a mouth-opening curve (T,): its minima that, with the curve
    scaled so that its 5th percentile is 0 and its 95th is 1, lie below ``depth`` and stand out by
    ``prominence`` (the closures ``benchmarks/real_speech_lipsync.py`` scores)."""
    from scipy.signal import find_peaks

    x = np.asarray(opening, np.float64)
    low, high = np.percentile(x, [5, 95]) if len(x) else (0.0, 0.0)
    if high <= low:
        return np.zeros(0, np.int64)
    frames, _ = find_peaks(-(x - low) / (high - low), height=-depth, prominence=prominence)
    return frames.astype(np.int64)


def match_closures(real: np.ndarray, method: np.ndarray, tolerance: int) -> tuple[int, int]:
    """(real closures with a method closure within +-``tolerance`` frames, method closures with a
    real one that near); ``real``, ``method`` (K,) frames."""
    real, method = np.asarray(real), np.asarray(method)
    if len(real) == 0 or len(method) == 0:
        return 0, 0
    gap = np.abs(real[:, None] - method[None, :])
    return int((gap.min(1) <= tolerance).sum()), int((gap.min(0) <= tolerance).sum())


def closings_of(opening: np.ndarray, frames: np.ndarray, flat: int = 2) -> np.ndarray:
    """(K,) bool: which closures ``frames`` of an opening (T,) are closings within speech (the curve
    stays at its minimum for at most ``flat`` frames) rather than rests (a plateau: the mouth
    closed through a pause)."""
    x = np.asarray(opening, np.float64)
    out = np.zeros(len(frames), bool)
    for i, e in enumerate(frames):
        level = x[e] + 1e-4
        a = b = int(e)
        while a > 0 and x[a - 1] <= level and e - a < flat + 1:
            a -= 1
        while b < len(x) - 1 and x[b + 1] <= level and b - e < flat + 1:
            b += 1
        out[i] = b - a + 1 <= flat
    return out


def closure_target(opening: np.ndarray, fps: float, kind: str = "closure", sigma_s: float = 0.1) -> np.ndarray:
    """(T,) 0..1, a target the model learns to score closures with from a captured opening (T,) at
    ``fps``: a Gaussian bump of ``sigma_s`` around each of its closures (:func:`closure_frames_of`;
    ``kind`` "closing": only the closings within speech, :func:`closings_of`), so that the model
    scores, per frame, how near the lips are to closing. Frames where the opening is unknown (NaN,
    a capture's gap) are NaN: the fit leaves them out."""
    opening = np.asarray(opening, np.float64)
    unknown = ~np.isfinite(opening)
    if unknown.all():
        return np.full(len(opening), np.nan)
    if unknown.any():  # the closures are found on the curve bridged over its gaps
        t = np.arange(len(opening))
        opening = np.interp(t, t[~unknown], opening[~unknown])
    target = _closure_bumps(opening, fps, kind, sigma_s)
    target[unknown] = np.nan
    return target


def _closure_bumps(opening: np.ndarray, fps: float, kind: str, sigma_s: float) -> np.ndarray:
    frames = closure_frames_of(opening)
    if kind == "closing":
        frames = frames[closings_of(opening, frames)]
    if len(frames) == 0:
        return np.zeros(len(opening))
    d = np.abs(np.arange(len(opening))[:, None] - frames[None]).min(1) / (sigma_s * fps)
    return np.exp(-0.5 * d * d)


# ---------------------------------------------------------------- fitting

@dataclass
class Take:
    """One capture with its audio: raw features (K, D) float32 (:func:`frame_features` of its audio),
    the targets (T, Y) at ``fps`` frames/s (frame f at f / fps s of the audio), and ``weight``: how
    much each of its frames counts in the fit, relative to the other takes' (a speaker's takes
    given 1 / the speaker's seconds make every speaker count alike, however long each was heard)."""

    raw: np.ndarray
    targets: np.ndarray
    fps: float
    weight: float = 1.0

    @property
    def times_s(self) -> np.ndarray:
        """(T,) float64 s, the targets' frame times."""
        return np.arange(len(self.targets)) / self.fps


def weighted_moments(values: np.ndarray, weights: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(mean (D,), standard deviation (D,)) float64 of the rows of ``values`` (N, D), each row
    weighing ``weights`` (N,) >= 0 (a row of weight 2 counts as the row twice)."""
    n = weights.sum()
    mean = weights @ values / n
    return mean, np.sqrt(weights @ (values - mean) ** 2 / n)


def ridge(x: np.ndarray, y: np.ndarray, alpha: float, prior: np.ndarray | None = None,
          prior_std: np.ndarray | None = None, strength: float = 0.0,
          weights: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """(coef (P, Y), intercept (Y,)) float64 of ridge regression of ``y`` (N, Y) on ``x`` (N, P): the
    columns of x standardized, penalty ``alpha * N`` on the standardized coefficients (so alpha
    does not depend on how many frames there are), the intercept unpenalized.

    ``weights`` (N,) >= 0: each row's weight in the squared error, the means and the standard
    deviations, N then meaning their sum (a row of weight 2 is the same as the row twice).

    With a ``prior`` (P, Y) (another model's coefficients on the same columns, its targets' standard
    deviations ``prior_std`` (Y,)), a second penalty ``strength * N`` pulls the coefficients toward
    the prior's, both measured per standard deviation of their own targets (a prior fitted in other
    units of the same curves still says which way each column moves them): with little data the
    fit stays near the prior, with much it follows the data."""
    x = np.asarray(x, np.float64)
    y = np.asarray(y, np.float64)
    w = np.ones(len(x)) if weights is None else np.asarray(weights, np.float64)
    n = float(w.sum())
    mx, sx = weighted_moments(x, w)
    my, sy = weighted_moments(y, w)
    sx = np.maximum(sx, 1e-8)
    xs = (x - mx) / sx
    gram = xs.T @ (w[:, None] * xs)
    gram[np.diag_indices_from(gram)] += (alpha + (strength if prior is not None else 0.0)) * n
    rhs = xs.T @ (w[:, None] * (y - my))
    if prior is not None and strength > 0:
        rhs = rhs + _prior_pull(prior, prior_std, sx, sy, strength, n)
    beta = np.linalg.solve(gram, rhs)
    coef = beta / sx[:, None]
    return coef, my - mx @ coef


def _prior_pull(prior: np.ndarray, prior_std: np.ndarray | None, sx: np.ndarray, sy: np.ndarray, strength: float,
                n: float) -> np.ndarray:
    """(P, Y) what :func:`ridge`'s pull toward the ``prior`` coefficients adds to its right-hand side:
    the prior carried into the standardized columns (``sx`` (P,)) and the targets' units (``sy`` (Y,)
    per the prior's ``prior_std`` (Y,)), times ``strength`` and the frames' weight ``n``."""
    scale = np.maximum(sy, 1e-12) / np.maximum(np.asarray(prior_std, np.float64), 1e-12)  # the prior in these units
    return strength * n * (np.asarray(prior, np.float64) * sx[:, None]) * scale[None]


def fit(takes: list[Take], target_names: tuple[str, ...] | list[str], *, offsets_s=DEFAULT_OFFSETS_S,
        pool: int = 3, alpha: float = 1.0, normalization: str = "running", tau_s: float = 3.0,
        expand: bool = True, prior: ArticulationModel | None = None, prior_strength: float = 0.0,
        feature_names: tuple[str, ...] = FEATURE_NAMES) -> ArticulationModel:
    """The model fitted on ``takes`` (their targets' columns named ``target_names``): the
    normalizer's training statistics from the takes' frames with speech, then :func:`ridge` on
    the context, each take's frames weighing its ``weight`` (relative to the others': in the
    statistics, the normalizer's and the targets', and in the squared error). The defaults are the
    settings chosen by leave-one-take-out within FACEGOOD's calibration takes. Deterministic: the
    same takes give the same model, bit for bit.

    With a ``prior`` model (the packaged, general one) and ``prior_strength`` > 0 the fit adapts
    it: the prior's context (offsets, pooling, loudness columns) and its normalization's training
    statistics, and every target the prior predicts pulled toward the prior's coefficients by
    ``prior_strength`` (:func:`ridge`); targets it lacks are fitted as without it.

    ``feature_names``: the columns of the takes' raw features, :data:`FEATURE_NAMES` (what
    :func:`frame_features` computes) or those followed by columns of other features (a benchmark's
    trial: :func:`check_model` refuses such a model wherever facesynth computes the features)."""
    model, prior = _fitting(takes, target_names, offsets_s, pool, alpha, normalization, tau_s, expand, prior,
                            prior_strength, feature_names)
    x = np.concatenate([design(model, t.raw, t.times_s) for t in takes])
    y = np.concatenate([t.targets for t in takes]).astype(np.float64)
    weight = np.concatenate([np.full(len(t.targets), float(t.weight)) for t in takes])
    # frames of a capture's gaps (NaN) are left out; a target some takes lack (a source without a jaw
    # channel) is fitted on the frames that have it, each set of targets with the same frames at once
    known = np.isfinite(y) & np.isfinite(x).all(1)[:, None]
    patterns: dict[bytes, list[int]] = {}
    for j in range(len(target_names)):
        patterns.setdefault(known[:, j].tobytes(), []).append(j)
    for cols in patterns.values():
        rows = known[:, cols[0]]
        _check_known(int(rows.sum()), target_names, cols[0])
        with_prior = [c for c in cols if prior is not None and target_names[c] in prior.target_names]
        plain = [c for c in cols if c not in with_prior]
        w = weight[rows] * (rows.sum() / weight[rows].sum())  # relative: alpha keeps its meaning
        if plain:
            model.coef[:, plain], model.intercept[plain] = ridge(x[rows], y[rows][:, plain], alpha, weights=w)
        if with_prior:
            assert prior is not None
            pc = [prior.target_names.index(target_names[c]) for c in with_prior]
            model.coef[:, with_prior], model.intercept[with_prior] = ridge(
                x[rows], y[rows][:, with_prior], alpha, np.asarray(prior.coef, np.float64)[:, pc],
                np.asarray(prior.target_std, np.float64)[pc], prior_strength, weights=w)
        model.target_mean[cols], model.target_std[cols] = weighted_moments(y[rows][:, cols], w)
    return model


def _fitting(takes, target_names, offsets_s, pool, alpha, normalization, tau_s, expand, prior, prior_strength,
             feature_names) -> tuple[ArticulationModel, ArticulationModel | None]:
    """(the model :func:`fit` fills in: its context, normalization and shapes, coefficients 0; the
    prior it adapts, or None) for :func:`fit`'s arguments, checked."""
    if tuple(feature_names[:N_FEATURES]) != FEATURE_NAMES:
        raise InputError(f"the first {N_FEATURES} feature columns must be those frame_features computes.")
    if prior is not None and prior_strength > 0:
        check_model(prior, "the prior articulation model")
        offsets_s, pool, expand = tuple(np.asarray(prior.offsets_s, np.float64)), int(prior.pool), bool(prior.expand)
    else:
        prior = None
    if not takes:
        raise InputError("fit the articulation model on at least one take.")
    for i, t in enumerate(takes):
        if np.ndim(t.targets) != 2 or np.shape(t.targets)[1] != len(target_names):
            raise InputError(f"take {i}: targets have shape {np.shape(t.targets)}, expected (T, {len(target_names)}) "
                             "for the target names given.")
        if np.ndim(t.raw) != 2 or np.shape(t.raw)[1] != len(feature_names):
            raise InputError(f"take {i}: raw features have shape {np.shape(t.raw)}, expected (K, {len(feature_names)}).")
        if not (np.isfinite(t.weight) and t.weight > 0):
            raise InputError(f"take {i}: weight {t.weight} must be a positive number.")
    norm = Normalizer(mode=normalization, tau_s=tau_s).fit([t.raw for t in takes], [t.weight for t in takes])
    if prior is not None:  # the prior's columns mean what they meant when it was fitted
        norm.mean, norm.std = np.asarray(prior.feature_mean, np.float64), np.asarray(prior.feature_std, np.float64)
    width = len(offsets_s) * (len(feature_names) + (N_EXPANDED if expand else 0))
    model = ArticulationModel(
        list(target_names), np.asarray(offsets_s, np.float64), int(pool), norm.mode, float(norm.tau_s),
        float(norm.gate), float(norm.peak_decay), list(feature_names), norm.mean, norm.std,
        np.zeros((width, len(target_names))), np.zeros(len(target_names)), float(alpha),
        np.zeros(len(target_names)), np.zeros(len(target_names)), bool(expand), np.asarray(KNOTS, np.float64),
        RATE, HOP, WIN)
    return model, prior


def _check_known(frames: int, target_names, column: int) -> None:
    """Refuse a fit of the target ``column`` on fewer frames than twice the targets."""
    if frames < 2 * len(target_names):
        raise InputError(f"only {frames} frames have the target {target_names[column]!r} known; fit "
                         "the articulation model on takes whose lip markers are seen.")


def fit_leaving_each_out(takes: list[Take], target_names: tuple[str, ...] | list[str], *,
                         offsets_s=DEFAULT_OFFSETS_S, pool: int = 3, alpha: float = 1.0, normalization: str = "running",
                         tau_s: float = 3.0, expand: bool = True, prior: ArticulationModel | None = None,
                         prior_strength: float = 0.0, feature_names: tuple[str, ...] = FEATURE_NAMES
                         ) -> list[ArticulationModel]:
    """For each take of ``takes`` (two or more), in order, the model :func:`fit` gives on the
    other takes (the same settings, prior and strength): equal to those fits
    to float rounding (1e-9 of a coefficient).

    Adapting a prior, every fit reads each take's context alike (the normalization's statistics
    are the prior's), so the context is computed once per take and each fit's regression is solved
    from the weighted sums of all the takes' frames less the left-out take's: two passes over the
    frames and one (P, P) solve per take, where fitting anew would read the other takes each time
    (the cost grows with the takes squared). Without a prior each fit is :func:`fit` on the others
    (the normalization's statistics, and so every take's context, change with the takes)."""
    if len(takes) < 2:
        raise InputError("leave one take out of at least two takes.")
    settings = dict(offsets_s=offsets_s, pool=pool, alpha=alpha, normalization=normalization, tau_s=tau_s,
                    expand=expand, feature_names=feature_names)
    if prior is None or prior_strength <= 0:
        return [fit([t for j, t in enumerate(takes) if j != i], target_names, **settings) for i in range(len(takes))]
    model, prior = _fitting(takes, target_names, offsets_s, pool, alpha, normalization, tau_s, expand, prior,
                            prior_strength, feature_names)
    assert prior is not None
    xs = [design(model, t.raw, t.times_s) for t in takes]
    ys = [np.asarray(t.targets, np.float64) for t in takes]
    known = [np.isfinite(y) & np.isfinite(x).all(1)[:, None] for x, y in zip(xs, ys)]
    models = [replace(model, coef=model.coef.copy(), intercept=model.intercept.copy(),
                      target_mean=model.target_mean.copy(), target_std=model.target_std.copy()) for _ in takes]
    patterns: dict[bytes, list[int]] = {}
    for j in range(len(target_names)):
        patterns.setdefault(np.concatenate([k[:, j] for k in known]).tobytes(), []).append(j)
    for cols in patterns.values():
        rows = [k[:, cols[0]] for k in known]
        # the sums about one centre (the first take's mean), so that the moments lose no digits to the means
        centre = (xs[0][rows[0]].mean(0, dtype=np.float64) if rows[0].any() else np.zeros(xs[0].shape[1]),
                  ys[0][rows[0]][:, cols].mean(0) if rows[0].any() else np.zeros(len(cols)))
        sums = [_weighted_sums(x[r], y[r][:, cols], t.weight, centre) for x, y, r, t in zip(xs, ys, rows, takes)]
        total = [sum(parts) for parts in zip(*sums)]
        with_prior = [c for c in cols if target_names[c] in prior.target_names]
        pc = [prior.target_names.index(target_names[c]) for c in with_prior]
        pulled = np.isin(cols, with_prior)
        for i, m in enumerate(models):
            count, s0, sx, sy, sxx, sxy, syy = (a - b for a, b in zip(total, sums[i]))
            _check_known(int(count), target_names, cols[0])
            mx, my = sx / s0, sy / s0  # about the centre
            cxx, cxy = sxx / s0 - np.outer(mx, mx), sxy / s0 - np.outer(mx, my)
            std_x = np.maximum(np.sqrt(np.maximum(np.diag(cxx), 0.0)), 1e-8)
            std_y = np.sqrt(np.maximum(syy / s0 - my * my, 0.0))
            gram = count * cxx / np.outer(std_x, std_x)
            rhs = count * cxy / std_x[:, None]
            beta = np.empty_like(rhs)
            for share, cs, extra in ((~pulled, None, 0.0), (pulled, pc, prior_strength)):
                if not share.any():
                    continue
                g = gram.copy()
                g[np.diag_indices_from(g)] += (alpha + extra) * count
                b = rhs[:, share]
                if cs is not None:
                    b = b + _prior_pull(np.asarray(prior.coef, np.float64)[:, cs], np.asarray(prior.target_std)[cs],
                                        std_x, std_y[share], prior_strength, count)
                beta[:, share] = np.linalg.solve(g, b)
            coef = beta / std_x[:, None]
            m.coef[:, cols], m.intercept[cols] = coef, (my + centre[1]) - (mx + centre[0]) @ coef
            m.target_mean[cols], m.target_std[cols] = my + centre[1], std_y
    return models


def _weighted_sums(x: np.ndarray, y: np.ndarray, weight: float, centre: tuple[np.ndarray, np.ndarray]) -> tuple:
    """(frames, their weight, the weighted sums of the context ``x`` (N, P) and targets ``y`` (N, Y)
    less their ``centre`` (P,) and (Y,), of their outer products and of y's squares) of one take's
    frames, each weighing ``weight``."""
    x, y = np.asarray(x, np.float64) - centre[0], y - centre[1]
    return (len(x), weight * len(x), weight * x.sum(0), weight * y.sum(0), weight * (x.T @ x), weight * (x.T @ y),
            weight * (y * y).sum(0))


# ---------------------------------------------------------------- streaming predictions

class StreamingPredictor:
    """Frame-by-frame predictions from audio chunks, each frame decided from the audio up to its
    time plus :func:`model_look_ahead_s`, never revised.

    ``push(chunk)`` (mono float samples at :data:`RATE`) returns the (k, Y) float64 predictions of
    the output frames (at ``fps``) that the audio so far completes; ``finish()`` the rest, up to
    the audio's end. The frames equal :func:`predict` on the whole audio to float rounding (1e-5),
    with a ``running`` or ``global`` normalization (``utterance`` needs the whole utterance and is
    refused)."""

    def __init__(self, model: ArticulationModel, fps: float, rate: int = RATE):
        check_model(model)
        if model.normalization == "utterance":
            raise InputError("utterance normalization needs the whole audio; stream with a 'running' model.")
        if int(rate) != RATE:
            raise InputError(f"stream audio at {RATE} Hz, not {rate} Hz.")
        self.model, self.fps = model, float(fps)
        self.normalizer = normalizer_of(model)
        self.offsets_s = np.asarray(model.offsets_s, np.float64)
        self.coef = np.asarray(model.coef, np.float64)
        self.intercept = np.asarray(model.intercept, np.float64)
        self.frames = StreamingFeatures()
        self.state = RunningState.start(self.normalizer) if model.normalization == "running" else None
        width = N_FEATURES + (N_EXPANDED if model.expand else 0)
        self.normed = np.zeros((0, width), np.float32)  # normalized frames kept (from first_kept)
        self.first_kept = 0
        self.done = 0  # output frames emitted
        #: (k, D) the raw analysis frames the last push or finish completed
        self.heard = np.zeros((0, N_FEATURES), np.float32)

    def _normalize(self, raw: np.ndarray) -> np.ndarray:
        if self.state is None:
            z = ((raw - self.normalizer.mean) / self.normalizer.std).astype(np.float32)
        else:
            z = self.state.update(self.normalizer, raw)
        return expand(z) if self.model.expand else z

    def _emit(self, final: bool) -> np.ndarray:
        """Predictions of every output frame whose context is complete (every analysis frame it
        pools is in), or of all up to the audio's end when ``final``."""
        half, y = self.model.pool // 2, len(self.model.target_names)
        total = self.first_kept + len(self.normed)  # analysis frames normalized so far
        # output frames within the audio: those whose time lies before its end
        end = int(np.ceil(self.frames.samples / RATE * self.fps - 1e-9))
        if end <= self.done:
            return np.zeros((0, y))
        times = np.arange(self.done, end) / self.fps
        idx = np.rint((times[:, None] + self.offsets_s[None]) / FRAME_S).astype(np.int64)
        if not final:
            ready = idx.max(1) + half < total
            times, idx = times[ready], idx[ready]  # ready frames are a prefix: idx grows with time
        if len(times) == 0:
            return np.zeros((0, y))
        k0 = self.first_kept
        idx = np.clip(idx, 0, total - 1)
        lo = np.clip(idx - half, 0, total) - k0
        hi = np.clip(idx + half + 1, 0, total) - k0
        if lo.min() < 0:
            raise RuntimeError("streaming context fell out of the kept frames")
        c = np.concatenate([np.zeros((1, self.normed.shape[1])), np.cumsum(self.normed, 0, dtype=np.float64)])
        x = ((c[hi] - c[lo]) / (hi - lo)[..., None]).astype(np.float32).reshape(len(times), -1)
        self.done += len(times)
        # drop the frames no later output frame reads
        first_needed = int(np.rint((self.done / self.fps + float(np.min(self.offsets_s))) / FRAME_S)) - half - 1
        drop = min(max(0, first_needed - k0), len(self.normed))
        if drop:
            self.normed, self.first_kept = self.normed[drop:], k0 + drop
        return x.astype(np.float64) @ self.coef + self.intercept

    def push(self, chunk: np.ndarray) -> np.ndarray:
        """(k, Y) float64 predictions of the output frames that ``chunk`` (n,) completes."""
        raw = self.heard = self.frames.push(chunk)
        if len(raw):
            self.normed = np.concatenate([self.normed, self._normalize(raw)])
        return self._emit(final=False)

    def finish(self) -> np.ndarray:
        """(k, Y) float64 predictions of the remaining output frames, up to the audio's end."""
        raw = self.heard = self.frames.finish()
        if len(raw):
            self.normed = np.concatenate([self.normed, self._normalize(raw)])
        return self._emit(final=True)
