"""Whether someone speaks: how clearly the voice is heard, per 10 ms, batch and live.

The voice's mouth is trusted where someone speaks and rests where nobody does. Two signs of
speech, each per 10 ms analysis frame, and a frame is heard as clearly as the stronger says:

* **Level.** The loudness of the speech band (the mel bands of :data:`SPEECH_BAND_HZ`, the
  articulation features' own, averaged over :data:`LEVEL_FRAMES` frames, 30 ms) above a running
  noise floor (the quietest level within reach, rising by :data:`FLOOR_RISE_PER_S` a second),
  from ``snr_none`` (nothing) to ``snr_full`` (fully) (:func:`snr_share`). The band leaves out the
  rumble below 300 Hz (ventilation, traffic), whose loudness jitters from frame to frame and was
  taken for syllables, and the hiss above 3.4 kHz. Batch's floor looks both ways (audio that starts
  in speech is heard from its start); a stream's looks back only. Digital silence (exact zeros: a
  muted line, a device's first buffers, an editor's cut, a synthesized voice's pauses) says nothing
  about the room, so the floor does not stand on it: a frame whose level reads any of it
  (:class:`FloorFrames`) is left out of the floor, or the room's noise after a stretch of zeros
  would stand far above a floor on the zeros and be heard as a voice for seconds. The first sound
  after digital silence is taken for the room until something quieter comes; where nothing but a
  voice and digital silence is heard, the voice's quietest moments are the floor and the detector
  hears the rest.
* **Voice activity.** WebRTC's voice activity detector (``webrtcvad``: a Gaussian mixture of speech
  and noise spectra, six bands, adapting to the noise as it goes; ``aggressiveness`` 0..3, higher
  rejects more noise and more quiet speech; -1 leaves it out) says speech or not per 10 ms. It
  needs no floor: a stream that starts in speech, or a recording whose speech stands only a few
  dB above its room's noise (where the level's share stays low), is heard from its first
  syllable. Steady noise at -40 dBFS, white, brown or a 60 Hz hum, it leaves unheard at
  aggressiveness 2 (tests); louder noise with speech's spectrum (pink noise at -26 dBFS) it hears.
  Its first 100 ms, at the audio's start and after digital silence, are not taken
  (:data:`VAD_WARMUP_FRAMES`): there it calls any sound speech.

Why WebRTC's and not a hand-written detector: the voicing feature (the autocorrelation's peak) is
fooled by rumble (brown noise reads as voiced), and a level detector cannot tell a loud noisy
room from speech. WebRTC's detector is small (C, no model files), costs microseconds per 10 ms
and is the one WebRTC's real-time calls run on.
"""

from __future__ import annotations

import numpy as np

from facesynth.domain.voice import articulation as voice_model

#: The speech band whose loudness is the level's (Hz): the telephone band.
SPEECH_BAND_HZ = (300.0, 3400.0)
#: Analysis frames (10 ms each) the band's loudness is averaged over (causal: the frame and those before).
LEVEL_FRAMES = 3
#: How fast the noise floor rises away from a quiet frame (natural log of amplitude a second): a
#: noisy recording's floor follows its noise up, and a syllable's peak is not taken for it.
FLOOR_RISE_PER_S = 0.2
#: The detector's first frames, and its first after digital silence, are not taken: its noise
#: model starts from its defaults (and learns nothing from zeros) and takes the first 70 ms of any
#: sound, steady noise included, for speech.
VAD_WARMUP_FRAMES = 10
#: Digital silence: samples below half a 16-bit step (full scale 1), in whole blocks of
#: :data:`SILENCE_BLOCK` samples (2 ms at 16 kHz), at least :data:`SILENCE_MIN_BLOCKS` in a row.
#: A decoder's or resampler's ringing about a cut of zeros stays below the step. The few ms of
#: zeros a decoder leaves at a file's start (2 to 6 ms in every GRID clip) or a quiet 16-bit
#: studio between syllables (FACEGOOD's takes) are not a silenced line: they lower a frame's level
#: no more than the analysis's own zeros before the audio's start do, and are left alone.
SILENCE_AMPLITUDE = 2.0 ** -16
SILENCE_BLOCK = 32
SILENCE_MIN_BLOCKS = 5


_CENTRES_HZ = voice_model.mel_edges_hz()[1:-1]
#: The mel bands (columns of the raw features) whose centres lie in the speech band.
_BAND = np.flatnonzero((_CENTRES_HZ >= SPEECH_BAND_HZ[0]) & (_CENTRES_HZ <= SPEECH_BAND_HZ[1]))


def band_power(raw: np.ndarray) -> np.ndarray:
    """(K,) float64 the speech band's power (the sum of its mel bands' mean power densities, no unit)
    of raw features (K, D) (:func:`facesynth.domain.voice.articulation.frame_features`)."""
    return np.exp(np.asarray(raw, np.float64)[:, _BAND]).sum(1)


def band_level(power: np.ndarray, before: np.ndarray | None = None) -> np.ndarray:
    """(K,) the speech band's loudness (natural log of an amplitude) of frames whose band powers are
    ``power`` (K,): the log of the mean power over each frame and the ``LEVEL_FRAMES - 1`` before it,
    halved; ``before``: the powers of the frames before the first (a stream's last), none at an
    audio's start (the first frames average what there is)."""
    before = np.zeros(0) if before is None else np.asarray(before, np.float64)[-(LEVEL_FRAMES - 1):]
    x = np.concatenate([before, np.asarray(power, np.float64)])
    c = np.concatenate([[0.0], np.cumsum(x)])
    end = np.arange(len(before), len(x)) + 1
    start = np.maximum(end - LEVEL_FRAMES, 0)
    return 0.5 * np.log((c[end] - c[start]) / (end - start) + voice_model.POWER_FLOOR)


def snr_share(above_floor: np.ndarray | float, snr_none: float, snr_full: float) -> np.ndarray:
    """0..1 how clearly a level ``above_floor`` the noise floor is heard: 0 at or below ``snr_none``,
    1 at or above ``snr_full``, linear between (a step at ``snr_none`` where the two meet)."""
    return np.clip((np.asarray(above_floor, np.float64) - snr_none) / max(snr_full - snr_none, 1e-6), 0.0, 1.0)


def _candidates(level: np.ndarray, admitted: np.ndarray | None) -> np.ndarray:
    """(K,) float64 the levels the floor may stand on: ``level``, +inf where not ``admitted``."""
    e = np.asarray(level, np.float64)
    return e if admitted is None else np.where(admitted, e, np.inf)


def floor_after(level: np.ndarray, first: int = 0, carried: float = np.inf,
                admitted: np.ndarray | None = None) -> tuple[np.ndarray, float]:
    """The noise floor (K,) under ``level`` (K,), the 10 ms frames ``first``.. of an audio, looking
    back only: f_k = min(e_k, f_{k-1} + rise), rising by :data:`FLOOR_RISE_PER_S` a second away from
    each quiet frame; with what it carries to the next frames (the running minimum of e_k - rise k,
    ``carried`` in from the frames before ``first``: a stream's floor, chunk by chunk, is exactly
    the whole audio's). ``admitted`` (K,) bool: the frames the floor may stand on (all by default;
    :class:`FloorFrames`); +inf until the first."""
    ramp = FLOOR_RISE_PER_S * voice_model.FRAME_S * np.arange(first, first + len(level), dtype=np.float64)
    lowest = np.minimum.accumulate(np.concatenate([[carried], _candidates(level, admitted) - ramp]))[1:]
    return lowest + ramp, float(lowest[-1]) if len(lowest) else carried


def floor_both_ways(level: np.ndarray, admitted: np.ndarray | None = None) -> np.ndarray:
    """(K,) the noise floor under ``level`` (K,) 10 ms frames: the quietest level within reach, rising
    by :data:`FLOOR_RISE_PER_S` a second away from each quiet frame, before and after it; only the
    ``admitted`` (K,) frames count (all by default); +inf where none does."""
    e = _candidates(level, admitted)
    ramp = FLOOR_RISE_PER_S * voice_model.FRAME_S * np.arange(len(e))
    before = np.minimum.accumulate((e + ramp)[::-1])[::-1] - ramp  # b_k = min(e_k, b_{k+1} + rise)
    return np.minimum(floor_after(e)[0], before)


class FloorFrames:
    """Which 10 ms analysis frames the noise floor may stand on: those whose level
    (:func:`band_level`: frames k - 2..k, each reading WIN samples about its centre) reads no
    digital silence of the audio: a block of :data:`SILENCE_BLOCK` samples below
    :data:`SILENCE_AMPLITUDE` that ends a run of at least :data:`SILENCE_MIN_BLOCKS` such blocks
    (looking back only, so the first blocks of a run do not count: a frame reading only those
    reads at most 8 ms of zeros). The analysis's own zeros before the audio's start and after its
    end do not count. Fed mono audio at 16 kHz in chunks of any length (:meth:`push`);
    :meth:`admitted` answers for frames whose samples have all arrived (a frame past the audio's
    end: at its end), so a stream's answer, chunk by chunk, is the whole audio's."""

    #: The level's reach in blocks: frame k reads blocks k * STEP - BACK .. k * STEP + AHEAD.
    STEP = voice_model.HOP // SILENCE_BLOCK
    BACK = ((LEVEL_FRAMES - 1) * voice_model.HOP + voice_model.WIN // 2) // SILENCE_BLOCK
    AHEAD = voice_model.WIN // 2 // SILENCE_BLOCK - 1

    def __init__(self):
        assert voice_model.HOP % SILENCE_BLOCK == 0 and voice_model.WIN // 2 % SILENCE_BLOCK == 0
        self.pending = np.zeros(0)
        self.silent = np.zeros(0, bool)  # blocks from ``base`` on
        self.base = 0
        self.blocks = 0  # whole blocks read so far
        self.run = 0  # quiet blocks in a row up to the last read

    def push(self, samples: np.ndarray) -> None:
        x = np.concatenate([self.pending, np.asarray(samples, np.float64)])
        k = len(x) // SILENCE_BLOCK
        self.pending = x[k * SILENCE_BLOCK:]
        quiet = np.abs(x[:k * SILENCE_BLOCK]).reshape(k, SILENCE_BLOCK).max(1, initial=0.0) < SILENCE_AMPLITUDE
        index = np.arange(k)
        loud = np.maximum.accumulate(np.where(quiet, -1, index)) if k else index  # the last loud block
        run = np.where(loud >= 0, index - loud, index + 1 + self.run)  # quiet blocks in a row to each
        self.run = int(run[-1]) if k else self.run
        self.silent = np.concatenate([self.silent, run >= SILENCE_MIN_BLOCKS])
        self.blocks += k

    def admitted(self, first: int, count: int) -> np.ndarray:
        """(count,) bool for frames ``first``.. (each at most once, in order: the blocks no later
        frame reads are let go). Blocks before the audio or not yet read (past its end) are not
        silent."""
        lo = np.arange(first, first + count) * self.STEP - self.BACK
        hi = np.arange(first, first + count) * self.STEP + self.AHEAD
        c = np.concatenate([[0], np.cumsum(self.silent)])
        a, b = np.clip(lo - self.base, 0, len(self.silent)), np.clip(hi + 1 - self.base, 0, len(self.silent))
        out = c[b] == c[a]
        drop = min(max((first + count) * self.STEP - self.BACK - self.base, 0), len(self.silent))
        self.silent, self.base = self.silent[drop:], self.base + drop
        return out


def floor_frames(samples: np.ndarray, count: int) -> np.ndarray:
    """(count,) bool the analysis frames of mono ``samples`` (n,) at 16 kHz the noise floor may
    stand on (:class:`FloorFrames`)."""
    frames = FloorFrames()
    frames.push(samples)
    return frames.admitted(0, count)


class SpeechFrames:
    """WebRTC's speech-or-not per 10 ms of mono audio at 16 kHz, fed in chunks of any length:
    :meth:`push` returns (k,) float 0/1 for the 10 ms frames the chunk completes; frame j covers
    samples [160 j, 160 (j + 1)); the first :data:`VAD_WARMUP_FRAMES` of the audio, and those after
    a frame of digital silence (all zero at 16 bits), are 0: the detector's noise model does not
    learn from zeros, so after them it takes any sound for speech until it settles again.
    ``aggressiveness`` -1: no detector, every frame 0."""

    def __init__(self, aggressiveness: int):
        self.vad = None
        if aggressiveness >= 0:
            import webrtcvad

            self.vad = webrtcvad.Vad(aggressiveness)
        self.pending = np.zeros(0, np.int16)
        self.frames = 0  # frames read so far
        self.last_silent = -1  # the last frame of digital silence (the audio's start: frame -1)

    def push(self, samples: np.ndarray) -> np.ndarray:
        pcm = np.clip(np.rint(np.asarray(samples, np.float64) * 32767.0), -32768, 32767).astype("<i2")
        x = np.concatenate([self.pending, pcm])
        hop = voice_model.HOP
        k = len(x) // hop
        self.pending = x[k * hop:]
        first, self.frames = self.frames, self.frames + k
        if self.vad is None:
            return np.zeros(k)
        frames = x[:k * hop].reshape(k, hop)
        flags = np.array([self.vad.is_speech(f.tobytes(), voice_model.RATE) for f in frames], np.float64)
        index = np.arange(first, first + k)
        silent = np.abs(frames.astype(np.int32)).max(1, initial=0) == 0  # zero at 16 bits
        last = np.maximum.accumulate(np.concatenate([[self.last_silent], np.where(silent, index, -1)]))[1:]
        if k:
            self.last_silent = int(last[-1])
        flags[index - last <= VAD_WARMUP_FRAMES] = 0.0
        return flags


def speech_frames(samples: np.ndarray, aggressiveness: int, count: int) -> np.ndarray:
    """(count,) float 0/1 WebRTC's speech-or-not of mono ``samples`` (n,) at 16 kHz per 10 ms frame,
    the frames past the audio's last whole 10 ms 0."""
    flags = SpeechFrames(aggressiveness).push(samples)[:count]
    return np.concatenate([flags, np.zeros(count - len(flags))])


def frame_confidence(level: np.ndarray, floor: np.ndarray, speech: np.ndarray, snr_none: float,
                     snr_full: float) -> np.ndarray:
    """(K,) 0..1 how clearly each 10 ms frame is heard: the larger of its level's share above the
    floor (:func:`snr_share`) and its voice activity ``speech`` (K,) 0/1."""
    return np.maximum(snr_share(np.asarray(level) - np.asarray(floor), snr_none, snr_full), speech)
