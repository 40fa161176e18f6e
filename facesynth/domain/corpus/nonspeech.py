"""The rest of the virtual actress's face: emotion, blinks, brows, gaze, cheeks and nose.

All in the face rig's blendshape weights at the capture rate (arrays (T, E) in the rig's
shape order, 0..1):

* **Emotion** as a per-frame blend over :data:`EMOTIONS` (rows sum to 1) times an intensity.
  Each emotion has a shape offset (:data:`EMOTION_OFFSETS`: happy smiles and squints the
  cheeks, angry lowers the brows, sneers and presses the lips, sad raises the inner brows
  and pulls the corners down) that breathes slowly, and dynamics (tempo, articulator
  stiffness, articulation amplitude) in :mod:`facesynth.domain.corpus.speech`. Some takes change
  emotion inside the sentence, at a word boundary, with a cross-fade (onset of the new one,
  offset of the old) of :data:`SWITCH_RAMP_S`.
* **Blinks**: an inhomogeneous Poisson process, :data:`BLINK_RATE_PER_MIN` while speaking and
  several times that in pauses and at the sentence's end, with a refractory time; each blink
  closes fast and opens slowly over 100-300 ms, both eyes nearly together.
* **Brows** rise on pitch accents (``browInnerUp``/``browOuterUp``), a pulse that follows the accent.
* **Gaze**: fixations held for a log-normal time, joined by fast saccades (``eyeLook*``); the
  upper lid follows a downward gaze a little.
* **Cheeks and nose** are coupled to the mouth: ``cheekSquint`` follows the smile,
  ``noseSneer`` the upper-lip raise, ``cheekPuff`` the lip press.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from facesynth.domain.rig.face import Rig

from .actress_mouth import critically_damped

EMOTIONS = ("neutral", "happy", "angry", "sad")

#: Shape offsets of each emotion at intensity 1 (rig weights; a name without side drives both sides).
EMOTION_OFFSETS: dict[str, dict[str, float]] = {
    "neutral": {},
    "happy": {"mouthSmile": 0.5, "mouthUpperUp": 0.15, "cheekSquint": 0.35, "eyeSquint": 0.2, "mouthDimple": 0.15, "browOuterUp": 0.1},
    "angry": {"browDown": 0.6, "noseSneer": 0.35, "mouthPress": 0.25, "eyeSquint": 0.25, "mouthStretch": 0.1,
              "jawForward": 0.08, "mouthFrown": 0.1, "eyeWide": 0.05},
    "sad": {"browInnerUp": 0.55, "mouthFrown": 0.4, "mouthShrugLower": 0.2, "eyeBlink": 0.12, "eyeLookDown": 0.12,
            "browDown": 0.1},
}
#: Range of the cross-fade of an emotion change inside a sentence (s).
SWITCH_RAMP_S = (0.2, 0.5)
#: Blinks per minute while speaking; pauses and the sentence's end multiply the rate.
BLINK_RATE_PER_MIN = 13.0
BLINK_PAUSE_FACTOR = 3.5
BLINK_REFRACTORY_S = 0.5
BLINK_DURATION_S = (0.1, 0.3)


def _sided(rig: Rig, name: str) -> list[int]:
    """Rig shape indices of ``name``: itself, or its _L and _R shapes."""
    if name in rig.shape_names:
        return [rig.shape_index(name)]
    return [rig.shape_index(f"{name}_L"), rig.shape_index(f"{name}_R")]


@dataclass
class EmotionTrack:
    """The emotion of every frame.

    blend : (T, 4) weights over :data:`EMOTIONS`, rows sum to 1.
    intensity : (4,) intensity of each emotion in this take (0..1).
    switch_s : time (s) of the middle of an emotion change, or None.
    """

    blend: np.ndarray
    intensity: np.ndarray
    switch_s: float | None

    def labels(self) -> list[str]:
        """Per frame, the dominant emotion."""
        return [EMOTIONS[k] for k in np.argmax(self.blend, axis=1)]

    def frame_intensity(self) -> np.ndarray:
        """(T,) per frame, the dominant emotion's weight times its intensity."""
        k = np.argmax(self.blend, axis=1)
        return self.blend[np.arange(len(k)), k] * self.intensity[k]

    def at(self, times: np.ndarray, fps: float) -> np.ndarray:
        """The blend (n, 4) at ``times`` (s)."""
        idx = np.clip(np.round(np.asarray(times) * fps).astype(int), 0, len(self.blend) - 1)
        return self.blend[idx]


def emotion_track(first: str, change: tuple[str, float] | None, n_frames: int, fps: float,
                  rng: np.random.Generator) -> EmotionTrack:
    """A take's emotion: ``first`` throughout, or with ``change`` = (``second``, ``switch_s``)
    ``first`` then ``second`` cross-faded around ``switch_s``."""
    t = np.arange(n_frames) / fps
    blend = np.zeros((n_frames, len(EMOTIONS)))
    a = EMOTIONS.index(first)
    switch_s: float | None = None
    if change is None:
        blend[:, a] = 1.0
    else:
        second, switch_s = change
        ramp = rng.uniform(*SWITCH_RAMP_S)
        x = np.clip((t - switch_s) / ramp + 0.5, 0.0, 1.0)
        x = x * x * (3 - 2 * x)  # smooth onset/offset
        blend[:, a] = 1.0 - x
        blend[:, EMOTIONS.index(second)] = x
    intensity = np.array([0.0 if e == "neutral" else rng.uniform(0.5, 1.0) for e in EMOTIONS])
    return EmotionTrack(blend, intensity, switch_s)


def emotion_weights(rig: Rig, track: EmotionTrack, fps: float, rng: np.random.Generator) -> np.ndarray:
    """The emotion's shape offsets per frame, breathing slowly (+-15%). Returns (T, E)."""
    n = len(track.blend)
    t = np.arange(n) / fps
    out = np.zeros((n, len(rig.shape_names)))
    for k, emotion in enumerate(EMOTIONS):
        if not EMOTION_OFFSETS[emotion] or not track.blend[:, k].any():
            continue
        wobble = 1.0 + 0.15 * np.sin(2 * np.pi * rng.uniform(0.15, 0.5) * t + rng.uniform(0, 2 * np.pi))
        level = track.blend[:, k] * track.intensity[k] * wobble
        for name, value in EMOTION_OFFSETS[emotion].items():
            for s in _sided(rig, name):
                out[:, s] += value * level * rng.uniform(0.85, 1.15)
    return out


def blink_times(duration: float, pauses: list[tuple[float, float]], rng: np.random.Generator) -> list[float]:
    """Blink onsets (s) over ``duration``: Poisson at :data:`BLINK_RATE_PER_MIN`, raised
    :data:`BLINK_PAUSE_FACTOR`-fold inside pauses, thinned by a refractory time."""
    dt = 0.01
    t = np.arange(0.0, duration, dt)
    rate = np.full(len(t), BLINK_RATE_PER_MIN / 60.0)
    for a, b in pauses:
        rate[(t >= a) & (t < b)] *= BLINK_PAUSE_FACTOR
    events = t[rng.random(len(t)) < rate * dt]
    out: list[float] = []
    for e in events:
        if not out or e - out[-1] > BLINK_REFRACTORY_S:
            out.append(float(e))
    return out


def blink_weights(rig: Rig, onsets: list[float], n_frames: int, fps: float, rng: np.random.Generator,
                  duration_scale: float = 1.0) -> np.ndarray:
    """Blinks as eyelid weights (T, E): fast closing (a third), slower opening."""
    out = np.zeros((n_frames, len(rig.shape_names)))
    t = np.arange(n_frames) / fps
    left, right = rig.shape_index("eyeBlink_L"), rig.shape_index("eyeBlink_R")
    for onset in onsets:
        length = rng.uniform(*BLINK_DURATION_S) * duration_scale
        close = length / 3.0
        depth = rng.uniform(0.85, 1.0)
        x = np.where(t < onset + close, (t - onset) / close, 1.0 - (t - onset - close) / (length - close))
        shape = np.clip(x, 0.0, 1.0)
        shape = np.sin(0.5 * np.pi * shape) ** 2 * depth
        lag = rng.normal(0.0, 0.004)  # the eyes blink nearly together
        out[:, left] = np.maximum(out[:, left], shape)
        out[:, right] = np.maximum(out[:, right], np.interp(t - lag, t, shape) * rng.uniform(0.92, 1.0))
    return out


def brow_weights(rig: Rig, accents: list[tuple[float, float]], n_frames: int, fps: float,
                 rng: np.random.Generator) -> np.ndarray:
    """Brow raises on pitch accents. accents : (time s, strength 0..1). Returns (T, E)."""
    out = np.zeros((n_frames, len(rig.shape_names)))
    t = np.arange(n_frames) / fps
    inner, outer = _sided(rig, "browInnerUp"), _sided(rig, "browOuterUp")
    for centre, strength in accents:
        if rng.random() > 0.7:  # not every accent moves the brows
            continue
        peak = centre + rng.normal(0.02, 0.03)
        rise, fall = rng.uniform(0.08, 0.14), rng.uniform(0.2, 0.35)
        pulse = np.where(t < peak, np.exp(-((t - peak) / rise) ** 2), np.exp(-((t - peak) / fall) ** 2))
        amp = strength * rng.uniform(0.25, 0.55)
        side = np.exp(rng.normal(0.0, 0.1, 2))
        for k, s in enumerate(inner):
            out[:, s] += 0.7 * amp * side[k] * pulse
        for k, s in enumerate(outer):
            out[:, s] += amp * side[k] * pulse
    return out


def gaze_weights(rig: Rig, n_frames: int, fps: float, rng: np.random.Generator) -> np.ndarray:
    """Fixations and saccades as eyeLook weights, with the lids following a downward gaze. Returns (T, E)."""
    duration = n_frames / fps
    horizontal = np.zeros(n_frames)  # + toward the subject's left
    vertical = np.zeros(n_frames)    # + up
    t0, h, v = 0.0, rng.normal(0.0, 0.06), rng.normal(-0.03, 0.05)
    while t0 < duration:
        a = int(t0 * fps)
        hold = float(np.exp(rng.normal(np.log(0.7), 0.5)))
        horizontal[a:], vertical[a:] = h, v
        t0 += hold
        h = float(np.clip(0.6 * h + rng.normal(0.0, 0.1), -0.35, 0.35))
        v = float(np.clip(0.5 * v + rng.normal(-0.02, 0.07), -0.3, 0.25))
    # saccades: a fast second-order response (natural frequency 25 Hz, ~40 ms)
    gaze = critically_damped(np.stack([horizontal, vertical], 1), 2 * np.pi * np.array([25.0, 25.0]), fps)
    out = np.zeros((n_frames, len(rig.shape_names)))
    hz, vt = gaze[:, 0], gaze[:, 1]
    out[:, rig.shape_index("eyeLookOut_L")] = np.clip(hz, 0, None)
    out[:, rig.shape_index("eyeLookIn_R")] = np.clip(hz, 0, None)
    out[:, rig.shape_index("eyeLookIn_L")] = np.clip(-hz, 0, None)
    out[:, rig.shape_index("eyeLookOut_R")] = np.clip(-hz, 0, None)
    for s in _sided(rig, "eyeLookUp"):
        out[:, s] = np.clip(vt, 0, None)
    for s in _sided(rig, "eyeLookDown"):
        out[:, s] = np.clip(-vt, 0, None)
    for s in _sided(rig, "eyeBlink"):
        out[:, s] = 0.3 * np.clip(-vt, 0, None)  # the upper lid follows the eye down
    return out


def couple_cheeks_and_nose(rig: Rig, weights: np.ndarray) -> np.ndarray:
    """Add the cheek and nose motion that follows the mouth, in place; returns ``weights``."""
    for side in ("_L", "_R"):
        smile = weights[:, rig.shape_index("mouthSmile" + side)]
        upper = weights[:, rig.shape_index("mouthUpperUp" + side)]
        weights[:, rig.shape_index("cheekSquint" + side)] += 0.45 * smile
        weights[:, rig.shape_index("eyeSquint" + side)] += 0.15 * smile
        weights[:, rig.shape_index("noseSneer" + side)] += 0.25 * upper + 0.1 * smile
        press = weights[:, rig.shape_index("mouthPress" + side)]
        weights[:, rig.shape_index("cheekPuff" + side)] += 0.15 * press
    return weights
