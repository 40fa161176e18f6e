"""Speech of the virtual actress: sentences, phone timing, pitch, head motion and audio.

Phone durations follow the phone class, stress, phrase-final lengthening and the emotion's
tempo (word by word, so a take that changes emotion changes tempo with it); pitch has
declination, accents on some stressed vowels (which also raise the brows, see
:mod:`facesynth.domain.corpus.nonspeech`) and a final fall; the head nods with the pitch. The
articulation itself is in :mod:`facesynth.domain.corpus.actress_mouth`.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import cache, lru_cache
from importlib import resources

import numpy as np
from scipy.signal import butter, lfilter, sosfilt

from facesynth.base.phonemes import PAU, VOWELS, pronunciations, to_festival, typical_duration

from .recurrences_numba import section_cascade


@dataclass(frozen=True)
class EmotionStyle:
    """How one emotion shapes speech: tempo (duration multiplier), articulator stiffness and
    articulation amplitude (multipliers), F0 base and range (Hz), loudness, head-motion gain
    and a blink-duration multiplier. Its shape offsets are in
    :data:`facesynth.domain.corpus.nonspeech.EMOTION_OFFSETS`.
    """

    tempo: float        # duration multiplier
    stiffness: float    # multiplier of every articulator's natural frequency
    amplitude: float    # articulation target multiplier
    f0_base: float      # Hz
    f0_range: float     # Hz
    loudness: float
    head_gain: float    # head motion amplitude multiplier
    blink_duration: float


#: One style per emotion of :data:`facesynth.domain.corpus.nonspeech.EMOTIONS`.
STYLES = {
    "neutral": EmotionStyle(1.00, 1.00, 1.00, 195.0, 25.0, 1.0, 1.0, 1.0),
    "happy": EmotionStyle(0.93, 1.05, 1.08, 235.0, 45.0, 1.1, 1.2, 0.9),
    "angry": EmotionStyle(0.88, 1.25, 1.2, 220.0, 40.0, 1.35, 1.5, 0.85),
    "sad": EmotionStyle(1.22, 0.78, 0.72, 180.0, 12.0, 0.7, 0.6, 1.35),
}

# Formants (Hz) for the source-filter audio; consonants borrow a neutral tract.
_FORMANTS = {
    "iy": (270, 2290, 3010), "ih": (390, 1990, 2550), "eh": (530, 1840, 2480), "ae": (660, 1720, 2410),
    "aa": (730, 1090, 2440), "ao": (570, 840, 2410), "uh": (440, 1020, 2240), "uw": (300, 870, 2240),
    "ah": (520, 1190, 2390), "ax": (500, 1500, 2500), "er": (490, 1350, 1690), "axr": (490, 1350, 1690),
    "ey": (480, 2100, 2600), "ay": (660, 1500, 2500), "aw": (660, 1100, 2400), "ow": (500, 900, 2400),
    "oy": (550, 1100, 2400), "l": (360, 1300, 2700), "el": (400, 1200, 2600), "r": (330, 1060, 1380),
    "w": (300, 700, 2200), "y": (280, 2200, 3000), "m": (280, 1000, 2200), "em": (280, 1000, 2200),
    "n": (280, 1600, 2600), "en": (300, 1600, 2600), "ng": (280, 2000, 2600), "nx": (300, 1600, 2600),
}
_NEUTRAL_TRACT = (500, 1500, 2500)
_FRICATION = {"s": (4000, 7500, 0.30), "z": (4000, 7500, 0.18), "sh": (2000, 6000, 0.30), "zh": (2000, 6000, 0.16),
              "ch": (2000, 6000, 0.28), "jh": (2000, 6000, 0.18), "f": (1200, 7500, 0.10), "v": (1200, 7500, 0.07),
              "th": (1500, 7500, 0.08), "dh": (1500, 7500, 0.06)}
_STOPS = {"p": 0.10, "b": 0.08, "t": 0.14, "d": 0.10, "k": 0.12, "g": 0.09}
_VOICED_CONSONANTS = {"b", "d", "g", "v", "dh", "z", "zh", "jh", "m", "n", "ng", "l", "r", "w", "y", "em", "en", "el", "nx"}
_NASALS = {"m", "n", "ng", "em", "en"}


@lru_cache(maxsize=1)
def lexicon() -> dict[str, tuple[tuple[str, ...], tuple[int, ...]]]:
    """Word -> (Festival phones, stress per phone: 1 stressed vowel, 0 otherwise)."""
    text = resources.files("facesynth.domain.corpus").joinpath("words.txt").read_text("utf-8")
    words = [w for line in text.splitlines() if not line.startswith("#") for w in line.split()]
    cmu = pronunciations(words)
    out = {}
    for word in words:
        if word not in cmu:
            continue
        arpabet = cmu[word][0]
        phones = tuple(f for p in arpabet if (f := to_festival(p)) is not None)
        if len(phones) != len(arpabet):  # a phone with no Festival name: not a word to speak
            continue
        stress = tuple(1 if p[-1] in "12" else 0 for p in arpabet)
        out[word] = (phones, stress)
    return out


def design_sentences(n: int, rng: np.random.Generator, min_phones: int, max_phones: int) -> list[list[str]]:
    """Phoneme-balanced sentences: each one, of ``min_phones``..``max_phones`` phones, is the
    candidate (of several random word sequences) covering the most diphones not yet covered."""
    lex = lexicon()
    words = sorted(lex)
    covered: set[tuple[str, str]] = set()
    sentences: list[list[str]] = []
    for _ in range(n):
        best: list[str] = []  # the first candidate replaces it (a score is >= 0)
        best_score = -1
        for _ in range(40):
            target = int(rng.integers(min_phones, max_phones + 1))
            sent: list[str] = []
            count = 0
            while count < target:
                w = words[int(rng.integers(len(words)))]
                if count + len(lex[w][0]) > max_phones and count >= min_phones:
                    break
                if count + len(lex[w][0]) > max_phones:
                    continue
                sent.append(w)
                count += len(lex[w][0])
            phones = [PAU] + [p for w in sent for p in lex[w][0]] + [PAU]
            score = len(set(zip(phones[:-1], phones[1:])) - covered)
            if score > best_score:
                best, best_score = sent, score
        phones = [PAU] + [p for w in best for p in lex[w][0]] + [PAU]
        covered |= set(zip(phones[:-1], phones[1:]))
        sentences.append(best)
    return sentences


@dataclass
class ReadSentence:
    """One read sentence: words, phones with times (s), and stress per phone."""

    words: list[str]
    phones: list[str]
    starts: np.ndarray  # (n,) s
    ends: np.ndarray    # (n,) s
    stress: np.ndarray  # (n,) int
    word_spans: list[tuple[str, float, float]]

    @property
    def duration(self) -> float:
        """Seconds from the sentence's start to its last phone's end."""
        return float(self.ends[-1])


def time_utterance(words: list[str], style: EmotionStyle | Sequence[EmotionStyle], rng: np.random.Generator,
                   pause_prob: float) -> ReadSentence:
    """Phone durations with variation: class base x emotion tempo x stress x log-normal noise;
    leading/trailing silence and sometimes a mid-sentence pause between words. ``style`` is
    one style, or one per word (a take whose emotion changes)."""
    lex = lexicon()
    styles = [style] * len(words) if isinstance(style, EmotionStyle) else list(style)
    pause_after = -1
    if len(words) >= 6 and rng.random() < pause_prob:
        pause_after = int(rng.integers(2, len(words) - 2))
    phones, stress, durations, word_index = [PAU], [0], [rng.uniform(0.25, 0.40)], [-1]
    for k, w in enumerate(words):
        ph, st = lex[w]
        for p, s in zip(ph, st):
            d = typical_duration(p) * styles[k].tempo * (1.25 if s else 1.0) * float(np.exp(rng.normal(0.0, 0.18)))
            if p in VOWELS and k == len(words) - 1:
                d *= 1.3  # phrase-final lengthening
            phones.append(p)
            stress.append(s)
            durations.append(max(d, 0.03))
            word_index.append(k)
        if k == pause_after:
            phones.append(PAU)
            stress.append(0)
            durations.append(rng.uniform(0.15, 0.30) * styles[k].tempo)
            word_index.append(-1)
    phones.append(PAU)
    stress.append(0)
    durations.append(rng.uniform(0.30, 0.45))
    word_index.append(-1)
    ends = np.round(np.cumsum(durations), 3)
    starts = np.concatenate([[0.0], ends[:-1]])
    spans = []
    for k, w in enumerate(words):
        idx = [i for i, wi in enumerate(word_index) if wi == k]
        spans.append((w, float(starts[idx[0]]), float(ends[idx[-1]])))
    return ReadSentence(list(words), phones, starts, ends, np.array(stress), spans)


def pitch(utt: ReadSentence, style: EmotionStyle, fps: float, rng: np.random.Generator) -> tuple[np.ndarray, list[tuple[float, float]]]:
    """F0 contour (Hz) at ``fps``: declination, accents on stressed vowels, final fall, jitter.
    Returns (f0 (T,) Hz, the accents as (centre s, strength 0.5..1))."""
    n_frames = int(np.floor(utt.duration * fps)) + 1
    t = np.arange(n_frames) / fps
    speech = [i for i, p in enumerate(utt.phones) if p != PAU]
    t0, t1 = utt.starts[speech[0]], utt.ends[speech[-1]]
    x = np.clip((t - t0) / max(t1 - t0, 1e-3), 0, 1)
    f0 = style.f0_base + style.f0_range * (0.3 - 0.7 * x)
    accents = []
    for i in speech:
        if utt.stress[i] and rng.random() < 0.45:
            c = 0.5 * (utt.starts[i] + utt.ends[i])
            strength = rng.uniform(0.5, 1.0)
            f0 += style.f0_range * strength * np.exp(-((t - c) ** 2) / (2 * 0.08**2))
            accents.append((float(c), float(strength)))
    f0 += style.f0_range * 0.08 * np.convolve(rng.normal(size=n_frames), np.ones(15) / 15, mode="same")
    return f0, accents


def head_motion(f0: np.ndarray, style: EmotionStyle, fps: float, rng: np.random.Generator,
                phrase_ends: Sequence[float] = ()) -> tuple[np.ndarray, np.ndarray]:
    """Rigid head motion correlated with pitch, with a small downward nod closing each phrase
    (``phrase_ends``, s). Returns rotations (T,3,3) and translations (T,3) mm."""
    n = len(f0)
    t = np.arange(n) / fps

    def smooth_noise(scale: float, width: int) -> np.ndarray:
        k = np.hanning(width)
        k /= k.sum()
        return scale * np.convolve(rng.normal(size=n + width), k, mode="same")[:n] * np.sqrt(width / 3)

    lag = int(0.1 * fps)  # the nod follows the pitch by ~100 ms
    f0_delayed = np.concatenate([np.full(lag, f0[0]), f0[:-lag]]) if lag else f0
    nod = style.head_gain * (np.deg2rad(2.5) * (f0_delayed - style.f0_base) / max(style.f0_range, 1.0) + smooth_noise(np.deg2rad(0.6), 90))
    for end in phrase_ends:
        nod -= style.head_gain * np.deg2rad(rng.uniform(0.5, 1.5)) * np.exp(-((t - end - 0.1) ** 2) / (2 * 0.12**2))
    yaw = style.head_gain * smooth_noise(np.deg2rad(1.5), 150)
    roll = style.head_gain * smooth_noise(np.deg2rad(0.8), 150)
    rotations = _euler(nod, yaw, roll)
    translations = np.stack([smooth_noise(1.5, 200), smooth_noise(1.5, 200), smooth_noise(2.0, 200)], 1)
    return rotations, translations


def _euler(pitch_x: np.ndarray, yaw_y: np.ndarray, roll_z: np.ndarray) -> np.ndarray:
    """Rotations (T, 3, 3) ``Rz @ Ry @ Rx`` for the angles (T,) rad about x, y and z."""
    cx, sx, cy, sy, cz, sz = np.cos(pitch_x), np.sin(pitch_x), np.cos(yaw_y), np.sin(yaw_y), np.cos(roll_z), np.sin(roll_z)
    one, zero = np.ones_like(cx), np.zeros_like(cx)

    def matrices(*entries: np.ndarray) -> np.ndarray:  # nine (T,) entries, row by row -> (T, 3, 3)
        return np.stack(entries, axis=-1).reshape(-1, 3, 3)

    rx = matrices(one, zero, zero, zero, cx, -sx, zero, sx, cx)
    ry = matrices(cy, zero, sy, zero, one, zero, -sy, zero, cy)
    rz = matrices(cz, -sz, zero, sz, cz, zero, zero, zero, one)
    return rz @ ry @ rx


def _resonators(freqs: np.ndarray, bandwidth: float, rate: int) -> tuple[np.ndarray, np.ndarray]:
    """Second-order resonators of unit gain at DC, one per centre frequency.

    freqs : (n,) Hz; bandwidth : Hz. Returns (numerators (n, 3), denominators (n, 3)), the
    numerators zero past their first coefficient and the denominators starting with 1.
    """
    r = np.exp(-np.pi * bandwidth / rate)
    theta = 2 * np.pi * freqs / rate
    denominators = np.stack([np.ones_like(theta), -2 * r * np.cos(theta), np.full_like(theta, r * r)], axis=1)
    numerators = np.zeros_like(denominators)
    numerators[:, 0] = denominators.sum(axis=1)  # unit gain at DC
    return numerators, denominators


@cache
def _butter_low_pass(order: int, cutoff: float) -> tuple[np.ndarray, np.ndarray]:
    """Butterworth low-pass ``(b, a)``, ``cutoff`` a fraction of the Nyquist rate; shared, so
    read-only."""
    b, a = butter(order, cutoff)
    b.flags.writeable = a.flags.writeable = False
    return b, a


@cache
def _butter_band_pass(order: int, low: float, high: float) -> np.ndarray:
    """Butterworth band-pass second-order sections (``sos``), the edges fractions of the Nyquist
    rate; shared, so read-only: give ``sosfilt`` a copy (it needs a writable array)."""
    sos = butter(order, [low, high], btype="band", output="sos")
    sos.flags.writeable = False
    return sos


def synthesize_audio(utt: ReadSentence, f0_frames: np.ndarray, fps: float, style: EmotionStyle,
                     rate: int, rng: np.random.Generator) -> np.ndarray:
    """Source-filter speech: a glottal pulse train at the F0 contour through time-varying
    formant resonators (blocks of 5 ms), plus shaped noise for fricatives and stop bursts.
    Returns (n,) float32 in [-1, 1] at ``rate`` Hz, as long as the utterance."""
    n = int(round(utt.duration * rate))
    ts = np.arange(n) / rate
    f0 = np.interp(ts, np.arange(len(f0_frames)) / fps, f0_frames)
    phase = np.cumsum(f0 / rate)
    pulses = np.diff(np.floor(phase), prepend=0.0)
    b_glot, a_glot = _butter_low_pass(2, 800 / (rate / 2))
    source = lfilter(b_glot, a_glot, pulses) * 20.0 + 0.02 * rng.normal(size=n)

    idx = np.clip(np.searchsorted(utt.ends, ts, side="right"), 0, len(utt.phones) - 1)
    phones = utt.phones
    voicing = np.array([1.0 if p in VOWELS else 0.6 if p in _VOICED_CONSONANTS and p not in _NASALS else 0.45 if p in _NASALS else 0.0 for p in phones])
    for i, p in enumerate(phones):  # voiced stops: murmur only
        if p in ("b", "d", "g"):
            voicing[i] = 0.15
    voice_env = _smooth(voicing[idx], int(0.012 * rate))
    formants = np.array([_FORMANTS.get(p, _NEUTRAL_TRACT) for p in phones], float)
    # Formant targets at phone centres, linearly interpolated: smooth transitions.
    centers = 0.5 * (utt.starts + utt.ends)
    block = int(0.005 * rate)
    out = np.zeros(n)
    excitation = source * voice_env
    hh = np.array([p == "hh" for p in phones])[idx]
    excitation += 0.25 * rng.normal(size=n) * _smooth(hh.astype(float), int(0.01 * rate))
    # Three resonators in series, their formants those at the middle sample of each block.
    block_starts = np.arange(0, n, block)
    block_middles = ts[(block_starts + np.minimum(block_starts + block, n)) // 2]
    resonators = [_resonators(np.interp(block_middles, centers, formants[:, k]), 60.0 + 40.0 * k, rate) for k in range(3)]
    numerators = np.stack([b for b, _ in resonators], axis=1)    # (n_blocks, 3, 3)
    denominators = np.stack([a for _, a in resonators], axis=1)  # (n_blocks, 3, 3)
    section_cascade(excitation, block, numerators, denominators, out)
    # Frication and bursts.
    for i, p in enumerate(phones):
        s, e = int(utt.starts[i] * rate), int(utt.ends[i] * rate)
        if e <= s:
            continue
        if p in _FRICATION:
            lo, hi, amp = _FRICATION[p]
            sos = _butter_band_pass(4, lo / (rate / 2), min(hi, 0.45 * rate) / (rate / 2)).copy()
            env = np.sin(np.linspace(0, np.pi, e - s)) ** 0.5
            out[s:e] += amp * 6.0 * sosfilt(sos, rng.normal(size=e - s)) * env
        elif p in _STOPS:
            b0 = s + int(0.6 * (e - s))
            length = e - b0
            sos = _butter_band_pass(2, 1500 / (rate / 2), 0.45).copy()
            out[b0:e] += _STOPS[p] * 8.0 * sosfilt(sos, rng.normal(size=length)) * np.exp(-np.arange(length) / (0.008 * rate))
    out *= style.loudness
    peak = np.max(np.abs(out)) + 1e-9
    out = 0.5 * out / peak * min(1.0, style.loudness)
    return out.astype(np.float32)


def _smooth(x: np.ndarray, width: int) -> np.ndarray:
    if width < 2:
        return x
    k = np.ones(width) / width
    return np.convolve(x, k, mode="same")
