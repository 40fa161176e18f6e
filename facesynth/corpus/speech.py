"""Speech of the virtual actress: sentences, phone timing, articulation, pitch and audio.

Articulation follows the Cohen-Massaro dominance model: every phone has a target and a
dominance for each rig parameter, and the parameter at time t is the dominance-weighted
mean of the targets of all phones, so the same phone looks different in different
contexts (coarticulation). Bilabials have an overwhelming lip-closure dominance, so the
lips close on /p b m/ whatever surrounds them. Emotions change pose (expression
parameters), dynamics (tempo, articulation sharpness, jaw amplitude), pitch and loudness.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import numpy as np
from scipy.signal import butter, lfilter, sosfilt

from ..phonemes import PAU, VOWELS, pronunciations, to_festival
from .face import P, PARAMS

EMOTIONS = ("neutral", "happy", "angry", "sad")


@dataclass(frozen=True)
class EmotionStyle:
    """How one emotion shapes speech: tempo (duration multiplier), articulation sharpness and
    jaw gain (multipliers), lip spread bias, F0 base and range (Hz), loudness, head-motion gain,
    and the mean intensity of each rig expression parameter.
    """

    tempo: float        # duration multiplier
    sharpness: float    # dominance rate multiplier (higher: crisper articulation)
    jaw_gain: float     # jaw amplitude multiplier
    spread_bias: float  # constant lip spread added
    f0_base: float      # Hz
    f0_range: float     # Hz
    loudness: float
    head_gain: float    # head motion amplitude multiplier
    expression: dict    # rig expression parameter -> mean intensity


STYLES = {
    "neutral": EmotionStyle(1.00, 1.00, 1.00, 0.00, 195.0, 25.0, 1.0, 1.0, {}),
    "happy": EmotionStyle(0.93, 1.05, 1.08, 0.18, 235.0, 45.0, 1.1, 1.2, {"smile": 0.8}),
    "angry": EmotionStyle(0.88, 1.35, 1.20, 0.05, 220.0, 40.0, 1.35, 1.5, {"angry": 0.85}),
    "sad": EmotionStyle(1.22, 0.75, 0.70, 0.00, 180.0, 12.0, 0.7, 0.6, {"sad": 0.8}),
}

# Articulation targets (rig parameters) and the dominance of each phone class.
_T = {
    "aa": dict(jaw=0.85, spread=0.1, raise_=0.4), "ae": dict(jaw=0.70, spread=0.45, raise_=0.4),
    "ah": dict(jaw=0.60, raise_=0.25), "ax": dict(jaw=0.35, raise_=0.1), "ao": dict(jaw=0.70, round=0.45),
    "aw": dict(jaw=0.75, round=0.3), "ay": dict(jaw=0.70, spread=0.3), "eh": dict(jaw=0.50, spread=0.4),
    "er": dict(jaw=0.35, round=0.35), "axr": dict(jaw=0.35, round=0.35), "ey": dict(jaw=0.45, spread=0.5),
    "ih": dict(jaw=0.30, spread=0.45), "iy": dict(jaw=0.20, spread=0.7), "ow": dict(jaw=0.50, round=0.7),
    "oy": dict(jaw=0.50, round=0.55), "uh": dict(jaw=0.35, round=0.5), "uw": dict(jaw=0.25, round=0.95),
    "el": dict(jaw=0.3), "em": dict(jaw=0.1, close=1.0), "en": dict(jaw=0.25),
    "p": dict(jaw=0.10, close=1.0), "b": dict(jaw=0.10, close=1.0), "m": dict(jaw=0.10, close=1.0),
    "f": dict(jaw=0.15, tuck=1.0), "v": dict(jaw=0.15, tuck=1.0), "w": dict(jaw=0.2, round=1.0),
    "r": dict(jaw=0.25, round=0.5), "sh": dict(jaw=0.2, round=0.55, raise_=0.3), "ch": dict(jaw=0.2, round=0.55, raise_=0.3),
    "jh": dict(jaw=0.2, round=0.55, raise_=0.3), "zh": dict(jaw=0.2, round=0.55, raise_=0.3),
    "s": dict(jaw=0.12, spread=0.5), "z": dict(jaw=0.12, spread=0.5), "th": dict(jaw=0.25), "dh": dict(jaw=0.25),
    "t": dict(jaw=0.25), "d": dict(jaw=0.25), "n": dict(jaw=0.25), "l": dict(jaw=0.3), "nx": dict(jaw=0.25),
    "k": dict(jaw=0.35), "g": dict(jaw=0.35), "ng": dict(jaw=0.35), "y": dict(jaw=0.2, spread=0.55),
    "hh": dict(jaw=0.45), "pau": dict(jaw=0.0, close=0.5),
}
_STRONG = {"p": {"close": 20.0}, "b": {"close": 20.0}, "m": {"close": 20.0}, "em": {"close": 20.0},
           "f": {"tuck": 20.0}, "v": {"tuck": 20.0}, "w": {"round": 8.0}, "uw": {"round": 3.0},
           "sh": {"round": 3.0}, "ch": {"round": 3.0}, "jh": {"round": 3.0}, "zh": {"round": 3.0}}
_WEAK = {"k", "g", "ng", "hh", "t", "d", "n", "l", "y", "th", "dh"}
# Dominance decay rate per parameter (1/s): lip closure and the labiodental tuck are brief
# gestures; lip rounding is anticipated over long spans (classic anticipatory coarticulation).
_RATE = {"jaw": 18.0, "round": 12.0, "spread": 18.0, "close": 70.0, "tuck": 60.0, "raise": 20.0}

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


def _base_duration(phone: str) -> float:
    if phone in ("aw", "ay", "oy", "ey", "ow"):
        return 0.150
    if phone == "ax":
        return 0.060
    if phone in VOWELS:
        return 0.105
    if phone in _STOPS:
        return 0.075
    if phone in ("s", "sh", "z", "zh", "ch", "jh"):
        return 0.100
    if phone in _FRICATION:
        return 0.085
    if phone in _NASALS:
        return 0.065
    return 0.060


@lru_cache(maxsize=1)
def lexicon() -> dict[str, tuple[tuple[str, ...], tuple[int, ...]]]:
    """Word -> (Festival phones, stress per phone: 1 stressed vowel, 0 otherwise)."""
    text = resources.files("facesynth.corpus").joinpath("words.txt").read_text("utf-8")
    words = [w for line in text.splitlines() if not line.startswith("#") for w in line.split()]
    cmu = pronunciations(words)
    out = {}
    for word in words:
        if word not in cmu:
            continue
        arpabet = cmu[word][0]
        phones = tuple(to_festival(p) for p in arpabet)
        stress = tuple(1 if p[-1] in "12" else 0 for p in arpabet)
        out[word] = (phones, stress)
    return out


def design_sentences(n: int, rng: np.random.Generator, min_phones: int, max_phones: int) -> list[list[str]]:
    """Phoneme-balanced sentences: each one, of ``min_phones``..``max_phones`` phones, is the
    candidate (of several random word sequences) covering the most diphones not yet covered."""
    lex = lexicon()
    words = sorted(lex)
    covered: set[tuple[str, str]] = set()
    sentences = []
    for _ in range(n):
        best, best_score = None, -1
        for _ in range(40):
            target = int(rng.integers(min_phones, max_phones + 1))
            sent, count = [], 0
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


def time_utterance(words: list[str], style: EmotionStyle, rng: np.random.Generator, pause_prob: float) -> ReadSentence:
    """Phone durations with variation: class base x emotion tempo x stress x log-normal noise;
    leading/trailing silence and sometimes a mid-sentence pause between words."""
    lex = lexicon()
    pause_after = -1
    if len(words) >= 6 and rng.random() < pause_prob:
        pause_after = int(rng.integers(2, len(words) - 2))
    phones, stress, durations, word_index = [PAU], [0], [rng.uniform(0.25, 0.40)], [-1]
    for k, w in enumerate(words):
        ph, st = lex[w]
        for p, s in zip(ph, st):
            d = _base_duration(p) * style.tempo * (1.25 if s else 1.0) * float(np.exp(rng.normal(0.0, 0.18)))
            if p in VOWELS and k == len(words) - 1:
                d *= 1.3  # phrase-final lengthening
            phones.append(p)
            stress.append(s)
            durations.append(max(d, 0.03))
            word_index.append(k)
        if k == pause_after:
            phones.append(PAU)
            stress.append(0)
            durations.append(rng.uniform(0.15, 0.30) * style.tempo)
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


def articulation(utt: ReadSentence, style: EmotionStyle, fps: float, rng: np.random.Generator) -> np.ndarray:
    """Rig parameters over time by dominance blending. Returns (T, len(PARAMS)) at ``fps``."""
    n_frames = int(np.floor(utt.duration * fps)) + 1
    t = np.arange(n_frames) / fps
    centers = 0.5 * (utt.starts + utt.ends)
    half = 0.35 * (utt.ends - utt.starts)
    speech_params = ("jaw", "round", "spread", "close", "tuck", "raise")
    out = np.zeros((n_frames, len(PARAMS)))
    tau = np.clip(np.abs(t[:, None] - centers[None, :]) - half[None, :], 0.0, None)  # (T, n)
    for name in speech_params:
        key = "raise_" if name == "raise" else name
        targets = np.array([_T[p].get(key, 0.0) for p in utt.phones])
        alpha = np.array([
            _STRONG.get(p, {}).get(name, 0.3 if p in _WEAK else (0.5 if p == PAU else 1.0)) for p in utt.phones
        ])
        if name == "close":  # only bilabials and silence care about closure
            alpha = np.where(targets > 0, alpha, 0.6)
        dominance = alpha[None, :] * np.exp(-_RATE[name] * style.sharpness * tau)
        out[:, P[name]] = (dominance * targets[None, :]).sum(1) / dominance.sum(1)
    out[:, P["jaw"]] *= style.jaw_gain * (1.0 + 0.15 * np.interp(t, centers, utt.stress.astype(float)))
    out[:, P["spread"]] += style.spread_bias
    for name in ("smile", "sad", "angry"):
        mean = style.expression.get(name, 0.03)
        wobble = sum(0.08 * np.sin(2 * np.pi * rng.uniform(0.1, 0.5) * t + rng.uniform(0, 2 * np.pi)) for _ in range(2))
        out[:, P[name]] = np.clip(mean * (1.0 + rng.normal(0.0, 0.08)) + mean * wobble, 0.0, None)
    return out


def pitch(utt: ReadSentence, style: EmotionStyle, fps: float, rng: np.random.Generator) -> np.ndarray:
    """F0 contour (Hz) at ``fps``: declination, accents on stressed vowels, final fall, jitter."""
    n_frames = int(np.floor(utt.duration * fps)) + 1
    t = np.arange(n_frames) / fps
    speech = [i for i, p in enumerate(utt.phones) if p != PAU]
    t0, t1 = utt.starts[speech[0]], utt.ends[speech[-1]]
    x = np.clip((t - t0) / max(t1 - t0, 1e-3), 0, 1)
    f0 = style.f0_base + style.f0_range * (0.3 - 0.7 * x)
    for i in speech:
        if utt.stress[i] and rng.random() < 0.45:
            c = 0.5 * (utt.starts[i] + utt.ends[i])
            f0 += style.f0_range * rng.uniform(0.5, 1.0) * np.exp(-((t - c) ** 2) / (2 * 0.08**2))
    f0 += style.f0_range * 0.08 * np.convolve(rng.normal(size=n_frames), np.ones(15) / 15, mode="same")
    return f0


def head_motion(f0: np.ndarray, style: EmotionStyle, fps: float, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """Rigid head motion correlated with pitch. Returns rotations (T,3,3) and translations (T,3) mm."""
    n = len(f0)

    def smooth_noise(scale: float, width: int) -> np.ndarray:
        k = np.hanning(width)
        k /= k.sum()
        return scale * np.convolve(rng.normal(size=n + width), k, mode="same")[:n] * np.sqrt(width / 3)

    lag = int(0.1 * fps)  # the nod follows the pitch by ~100 ms
    f0_delayed = np.concatenate([np.full(lag, f0[0]), f0[:-lag]]) if lag else f0
    nod = style.head_gain * (np.deg2rad(2.5) * (f0_delayed - style.f0_base) / max(style.f0_range, 1.0) + smooth_noise(np.deg2rad(0.6), 90))
    yaw = style.head_gain * smooth_noise(np.deg2rad(1.5), 150)
    roll = style.head_gain * smooth_noise(np.deg2rad(0.8), 150)
    rotations = np.stack([_euler(a, b, c) for a, b, c in zip(nod, yaw, roll)])
    translations = np.stack([smooth_noise(1.5, 200), smooth_noise(1.5, 200), smooth_noise(2.0, 200)], 1)
    return rotations, translations


def _euler(pitch_x: float, yaw_y: float, roll_z: float) -> np.ndarray:
    cx, sx, cy, sy, cz, sz = np.cos(pitch_x), np.sin(pitch_x), np.cos(yaw_y), np.sin(yaw_y), np.cos(roll_z), np.sin(roll_z)
    rx = np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]])
    ry = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    rz = np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]])
    return rz @ ry @ rx


def _resonator(freq: float, bandwidth: float, rate: int) -> tuple[np.ndarray, np.ndarray]:
    r = np.exp(-np.pi * bandwidth / rate)
    theta = 2 * np.pi * freq / rate
    a = np.array([1.0, -2 * r * np.cos(theta), r * r])
    return np.array([a.sum()]), a  # unit gain at DC


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
    b_glot, a_glot = butter(2, 800 / (rate / 2))
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
    states = [np.zeros(2) for _ in range(3)]
    for s in range(0, n, block):
        e = min(s + block, n)
        tc = ts[(s + e) // 2]
        y = excitation[s:e]
        for k in range(3):
            fk = float(np.interp(tc, centers, formants[:, k]))
            b, a = _resonator(fk, 60.0 + 40.0 * k, rate)
            y, states[k] = lfilter(b, a, y, zi=states[k])
        out[s:e] = y
    # Frication and bursts.
    for i, p in enumerate(phones):
        s, e = int(utt.starts[i] * rate), int(utt.ends[i] * rate)
        if e <= s:
            continue
        if p in _FRICATION:
            lo, hi, amp = _FRICATION[p]
            sos = butter(4, [lo / (rate / 2), min(hi, 0.45 * rate) / (rate / 2)], btype="band", output="sos")
            env = np.sin(np.linspace(0, np.pi, e - s)) ** 0.5
            out[s:e] += amp * 6.0 * sosfilt(sos, rng.normal(size=e - s)) * env
        elif p in _STOPS:
            b0 = s + int(0.6 * (e - s))
            length = e - b0
            sos = butter(2, [1500 / (rate / 2), 0.45], btype="band", output="sos")
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
