"""Speech articulation of the virtual actress in the face rig's blendshape weights.

Not one dominance blend, but a small articulatory model with separate, coupled articulators:

* **Targets per phone token** (:data:`VISEME_TARGETS`, over the channels of
  :data:`CHANNELS`: jaw opening and protrusion, lip funnel/pucker, roll, press, stretch,
  upper-lip raise, lower-lip depression, shrugs, spread): scaled by stress and by the
  emotion's articulation amplitude, and jittered per token (a log-normal gain and an
  additive offset per channel), so the same triphone differs from one take to the next.
* **Anticipatory rounding by look-ahead** (Henke's model): a consonant takes the rounding of
  the next rounded vowel up to :data:`ROUNDING_LOOKAHEAD_S` ahead, however many consonants lie
  between, decaying per intervening phone; an unrounded vowel blocks it. Rounding also
  carries over weakly into the consonants after a rounded vowel.
* **Dynamics**: each articulator is a critically damped second-order system driven by the
  piecewise-constant target sequence (leading the phones by ``target_lead_s``), with its own
  stiffness (:data:`STIFFNESS_HZ`; the jaw's and the lips' scale are settings), scaled per
  frame by the emotion. Short phones therefore undershoot their targets, and fast (angry)
  speech with stiffer articulators undershoots less.
* **Bilabial contact**: lip closure is a contact, not a pose. A closure drive aims at a
  virtual target beyond contact (so even a short /p/ reaches it); where the drive reaches
  contact, ``mouthClose`` is solved on the rig (linear in the weights) so that the inner-lip
  line of the lower lip meets the upper lip whatever the jaw, the emotion or the other lip
  shapes do; the drive's excess beyond contact becomes lip press. The jaw keeps its own
  trajectory through the closure. The closure moves the lower lip no faster than
  :data:`MAX_LIP_SPEED_MM_S`: from a wide-open vowel it starts earlier and releases later.
  In pauses the jaw goes to ``pause_jaw_open`` and, where ``pause_lips_closed``, the lips
  close lightly (drive :data:`PAUSE_CLOSURE_TARGET`) as at rest.
* **Left/right asymmetry**: every sided channel (``_L``/``_R``) gets a per-take gain and a
  per-token jitter on each side.

The settings named here are those of ``[sample_corpus]``
(:class:`facesynth.base.config.SampleCorpusSettings`), calibrated on real speech captures
(``benchmarks/articulation_statistics.py``).

Weights are at the capture rate, shape (T, E) in the rig's shape order, 0..1.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from facesynth.base.config import SampleCorpusSettings
from facesynth.base.phonemes import PAU, VOWELS
from facesynth.domain.rig.face import Rig

from .recurrences_numba import damped_response

#: Articulatory channels and the rig shapes each drives (a sided channel drives _L and _R).
CHANNELS: dict[str, tuple[str, ...]] = {
    "jawOpen": ("jawOpen",), "jawForward": ("jawForward",),
    "funnel": ("mouthFunnel",), "pucker": ("mouthPucker",),
    "rollLower": ("mouthRollLower",), "rollUpper": ("mouthRollUpper",),
    "press": ("mouthPress_L", "mouthPress_R"), "stretch": ("mouthStretch_L", "mouthStretch_R"),
    "upperUp": ("mouthUpperUp_L", "mouthUpperUp_R"), "lowerDown": ("mouthLowerDown_L", "mouthLowerDown_R"),
    "shrugLower": ("mouthShrugLower",), "shrugUpper": ("mouthShrugUpper",),
    "spread": ("mouthSmile_L", "mouthSmile_R"),
}
CHANNEL_NAMES = tuple(CHANNELS)
_C = {name: i for i, name in enumerate(CHANNEL_NAMES)}

#: Stiffness of each articulator, as the natural frequency (Hz) of its critically damped system,
#: before the settings: the jaw's is replaced by ``jaw_stiffness_hz``, the lips' (all but the two
#: jaw channels) are multiplied by ``lip_stiffness_scale``.
STIFFNESS_HZ = {"jawOpen": 4.5, "jawForward": 3.5, "funnel": 6.0, "pucker": 5.0, "rollLower": 7.0,
                "rollUpper": 7.0, "press": 7.0, "stretch": 6.0, "upperUp": 6.5, "lowerDown": 6.5,
                "shrugLower": 5.0, "shrugUpper": 5.0, "spread": 5.5}
#: Natural frequency (Hz) of the lip-closure drive, and its virtual target (beyond contact at 1).
#: The lips close at up to ~250 mm/s, so the closing gesture starts well before the acoustic
#: closure (:data:`CLOSURE_ONSET_LEAD_S`) and the release is timed to the phone's end
#: (:data:`CLOSURE_OFFSET_LEAD_S`: the drive needs that long to fall back to contact).
CLOSURE_HZ = 5.0
CLOSURE_VIRTUAL_TARGET = 1.8
CLOSURE_ONSET_LEAD_S = 0.07
CLOSURE_OFFSET_LEAD_S = 0.045
#: The fastest the closure itself moves the lower lip (mm/s); the jaw adds its own motion, and
#: lower-lip speeds in speech stay within a few hundred mm/s. From a wide-open vowel the lips
#: start closing earlier, and open later, rather than faster.
MAX_LIP_SPEED_MM_S = 200.0
#: How far ahead (s) a consonant looks for a rounded vowel, and the decay per phone in between.
ROUNDING_LOOKAHEAD_S = 0.35
ROUNDING_DECAY = 0.85
#: The closure drive in a pause whose lips close (``pause_lips_closed``): just past contact, so
#: the lips meet with little press.
PAUSE_CLOSURE_TARGET = 1.15
#: The articulators that are not the lips' (``lip_stiffness_scale`` leaves them alone).
_JAW_CHANNELS = frozenset({"jawOpen", "jawForward"})

_ROUNDED = {"uw": 0.9, "ow": 0.75, "uh": 0.55, "ao": 0.5, "oy": 0.6, "w": 1.0, "er": 0.45, "axr": 0.4, "aw": 0.35,
            "r": 0.45, "sh": 0.5, "zh": 0.5, "ch": 0.5, "jh": 0.5}
_BILABIALS = frozenset({"p", "b", "m", "em"})


def _t(**kw) -> dict[str, float]:
    return kw


#: Viseme targets per Festival phone (channels not named are 0). Rounding (funnel/pucker)
#: comes from :data:`_ROUNDED` through the look-ahead; here only what the phone itself sets.
#:
#: Revised against real speakers (docs/real-speech.md, "The actress's phones"): the mouth
#: opening per phone in standard units showed English speakers nearly closing /f v/ and /jh/
#: where facesynth opened them, and /aa/ overshooting, /ey/ short; her own truth agreed for
#: /f v/ (-0.1 against FACEGOOD's -0.4 to -0.9), /aa/ (+1.7 against +0.5 to +0.7) and /jh/. So:
#: /f v/ with the jaw nearly closed and the lower lip pushed up and tucked under the upper teeth,
#: the upper lip not raised (labiodentals: the lower lip meets the upper incisors; Ladefoged &
#: Johnson, *A Course in Phonetics*); on the built-in rig mouthRollLower alone parts the inner
#: lips (9 mm at the weight /f/ had, half an /aa/), with mouthShrugLower 0.3 they stay 3 mm apart; /ch jh/ with a high jaw and the lips barely parted (postalveolars have
#: among the highest jaw positions of the consonants; Keating, Lindblom, Lubker & Kreiman 1994);
#: /aa/ less open, /ey/ more. /r/ and /ao/ are left: her truth already opens them no more than
#: the real speakers do (/r/ -0.4, /ao/ +1.3), so what opens them in synthesis is the search.
VISEME_TARGETS: dict[str, dict[str, float]] = {
    "aa": _t(jawOpen=0.36, lowerDown=0.3, upperUp=0.15), "ae": _t(jawOpen=0.36, lowerDown=0.35, upperUp=0.25, spread=0.2, stretch=0.15),
    "ah": _t(jawOpen=0.32, lowerDown=0.3, upperUp=0.12), "ax": _t(jawOpen=0.18, lowerDown=0.15),
    "ao": _t(jawOpen=0.36, lowerDown=0.25), "aw": _t(jawOpen=0.38, lowerDown=0.3), "ay": _t(jawOpen=0.36, lowerDown=0.3, spread=0.12),
    "eh": _t(jawOpen=0.26, lowerDown=0.3, upperUp=0.15, spread=0.18, stretch=0.1), "er": _t(jawOpen=0.16, shrugUpper=0.15),
    "axr": _t(jawOpen=0.16), "ey": _t(jawOpen=0.3, lowerDown=0.3, spread=0.28, stretch=0.12),
    "ih": _t(jawOpen=0.16, lowerDown=0.2, spread=0.25, stretch=0.1), "iy": _t(jawOpen=0.1, lowerDown=0.12, spread=0.4, stretch=0.2),
    "ow": _t(jawOpen=0.26, lowerDown=0.12), "oy": _t(jawOpen=0.26, lowerDown=0.12), "uh": _t(jawOpen=0.17),
    "uw": _t(jawOpen=0.1), "el": _t(jawOpen=0.16, lowerDown=0.1), "en": _t(jawOpen=0.12, lowerDown=0.1),
    "em": _t(jawOpen=0.05), "p": _t(jawOpen=0.06), "b": _t(jawOpen=0.06), "m": _t(jawOpen=0.05),
    "f": _t(jawOpen=0.03, rollLower=0.3, shrugLower=0.3, shrugUpper=0.1), "v": _t(jawOpen=0.03, rollLower=0.28, shrugLower=0.3, shrugUpper=0.1),
    "w": _t(jawOpen=0.08), "r": _t(jawOpen=0.12), "y": _t(jawOpen=0.08, spread=0.3, stretch=0.1),
    "sh": _t(jawOpen=0.08, upperUp=0.25, lowerDown=0.15, jawForward=0.12), "zh": _t(jawOpen=0.08, upperUp=0.25, lowerDown=0.15, jawForward=0.12),
    "ch": _t(jawOpen=0.04, upperUp=0.12, lowerDown=0.05, jawForward=0.1), "jh": _t(jawOpen=0.04, upperUp=0.12, lowerDown=0.05, jawForward=0.1),
    "s": _t(jawOpen=0.05, spread=0.22, stretch=0.15, jawForward=0.08, lowerDown=0.1),
    "z": _t(jawOpen=0.05, spread=0.2, stretch=0.15, jawForward=0.08, lowerDown=0.1),
    "th": _t(jawOpen=0.12, lowerDown=0.2, upperUp=0.1), "dh": _t(jawOpen=0.12, lowerDown=0.2, upperUp=0.1),
    "t": _t(jawOpen=0.11, lowerDown=0.12), "d": _t(jawOpen=0.11, lowerDown=0.12), "n": _t(jawOpen=0.11, lowerDown=0.1),
    "l": _t(jawOpen=0.15, lowerDown=0.12), "nx": _t(jawOpen=0.11), "k": _t(jawOpen=0.16, lowerDown=0.1),
    "g": _t(jawOpen=0.16, lowerDown=0.1), "ng": _t(jawOpen=0.15), "hh": _t(jawOpen=0.2, lowerDown=0.15),
    PAU: _t(jawOpen=0.02),
}


@dataclass(frozen=True)
class TokenVariation:
    """How much one token's targets vary: log-normal gain sigma, additive sigma (weight units),
    per-token left/right gain sigma, and the per-take left/right gain sigma."""

    gain_sigma: float = 0.18
    offset_sigma: float = 0.025
    side_sigma: float = 0.08
    take_side_sigma: float = 0.1


def token_targets(phones: list[str], starts: np.ndarray, ends: np.ndarray, stress: np.ndarray,
                  amplitude: np.ndarray, rng: np.random.Generator, variation: TokenVariation = TokenVariation(),
                  pause_jaw_open: float = VISEME_TARGETS[PAU]["jawOpen"]):
    """Targets of every phone token.

    phones : n Festival phones; starts, ends : (n,) s; stress : (n,) 0/1;
    amplitude : (n,) articulation amplitude of the emotion at each phone; pause_jaw_open : the
    jaw's target (weight) in a pause.
    Returns (targets (n, C) over :data:`CHANNEL_NAMES`, side gains (n, C, 2) for left/right,
    closure (n,) bool, the bilabial tokens).
    """
    n = len(phones)
    targets = np.zeros((n, len(CHANNEL_NAMES)))
    for i, p in enumerate(phones):
        for name, v in VISEME_TARGETS.get(p, {}).items():
            targets[i, _C[name]] = v
        if p == PAU:
            targets[i, _C["jawOpen"]] = pause_jaw_open
    # Anticipatory rounding by look-ahead, carry-over after a rounded vowel.
    centres = 0.5 * (starts + ends)
    rounding = np.array([_ROUNDED.get(p, 0.0) for p in phones])
    for i, p in enumerate(phones):
        if p in VOWELS or p == PAU:
            continue
        reach = 0.0
        for j in range(i + 1, n):
            if phones[j] == PAU or centres[j] - centres[i] > ROUNDING_LOOKAHEAD_S:
                break
            reach = max(reach, rounding[j] * ROUNDING_DECAY ** (j - i))
            if phones[j] in VOWELS:
                break  # the next vowel decides; past it the look-ahead stops
        carry = 0.0
        if i > 0 and phones[i - 1] in VOWELS:
            carry = 0.4 * rounding[i - 1]
        rounding[i] = max(rounding[i], reach, carry)
    targets[:, _C["pucker"]] += 0.55 * rounding
    targets[:, _C["funnel"]] += 0.35 * rounding * np.array([p in VOWELS or p in ("sh", "zh", "ch", "jh", "r") for p in phones])
    targets[:, _C["spread"]] *= 1.0 - np.clip(rounding, 0, 1)
    # Stress and emotion scale the amplitude; per-token jitter makes every token differ.
    scale = (1.0 + 0.2 * stress - 0.12 * (1 - stress) * np.array([p in VOWELS for p in phones])) * amplitude
    targets *= scale[:, None]
    spoken = np.array([p != PAU for p in phones])
    gain = np.exp(rng.normal(0.0, variation.gain_sigma, targets.shape))
    offset = rng.normal(0.0, variation.offset_sigma, targets.shape) * spoken[:, None]
    targets = np.clip(targets * gain + offset, 0.0, 1.0)
    sides = np.exp(rng.normal(0.0, variation.side_sigma, (n, len(CHANNEL_NAMES), 2)))
    closure = np.array([p in _BILABIALS for p in phones])
    return targets, sides, closure


def critically_damped(inputs: np.ndarray, omega: np.ndarray, fps: float, substeps: int = 4) -> np.ndarray:
    """Drive critically damped second-order systems ``x'' = w^2 (u - x) - 2 w x'``.

    inputs : (T, C) piecewise-constant inputs u per frame; omega : (T, C) or (C,) natural
    frequencies (rad/s). Starts at rest at the first input; ``substeps`` semi-implicit Euler
    steps per frame (stable for w * dt << 1). Returns x : (T, C).
    """
    inputs = np.ascontiguousarray(inputs, dtype=np.float64)
    frequencies = np.empty_like(inputs)
    frequencies[...] = omega  # (T, C) or (C,) -> (T, C)
    out = np.empty_like(inputs)
    if len(inputs):
        damped_response(inputs, frequencies, 1.0 / (fps * substeps), substeps, out)
    return out


def target_sequence(values: np.ndarray, starts: np.ndarray, ends: np.ndarray, n_frames: int, fps: float,
                    lead_s: float) -> np.ndarray:
    """Per frame, the target of the phone whose interval, moved ``lead_s`` seconds earlier, holds
    it. values : (n, ...)."""
    t = np.arange(n_frames) / fps + lead_s
    idx = np.clip(np.searchsorted(ends, t, side="right"), 0, len(ends) - 1)
    return values[idx]


@dataclass(frozen=True)
class ContactSolver:
    """Linear lip-contact solve on the rig: the ``mouthClose`` weight that brings the lower
    inner-lip line up to the upper one (vertical gap ``target_gap_mm``) for given other weights.

    lip_pairs : (P, 2) rig vertices (upper, lower) on the inner lip line.
    """

    rig: Rig
    lip_pairs: np.ndarray
    target_gap_mm: float = 0.0

    def closing_mm(self) -> float:
        """How far one unit of ``mouthClose`` moves the lower inner lip toward the upper (mm)."""
        close = self.rig.shape_index("mouthClose")
        up, lo = self.lip_pairs[:, 0], self.lip_pairs[:, 1]
        return float(np.mean(self.rig.deltas[close, lo, 1] - self.rig.deltas[close, up, 1]))

    def needed_close(self, weights: np.ndarray) -> np.ndarray:
        """weights : (T, E) with mouthClose ignored. Returns (T,) the closing weight, >= 0."""
        close = self.rig.shape_index("mouthClose")
        up, lo = self.lip_pairs[:, 0], self.lip_pairs[:, 1]
        gap0 = self.rig.neutral[up, 1] - self.rig.neutral[lo, 1]                     # (P,) upper above lower
        dgap = self.rig.deltas[:, up, 1] - self.rig.deltas[:, lo, 1]                 # (E, P) mm per unit weight
        w = weights.copy()
        w[:, close] = 0.0
        gap = gap0 + w @ dgap - self.target_gap_mm                                    # (T, P)
        per_unit = -dgap[close]                                                       # (P,) closing per unit mouthClose
        # least squares over the pairs: sum_p per_unit_p * (c * per_unit_p - gap_p) = 0
        return np.clip(gap @ per_unit / (per_unit @ per_unit), 0.0, None)


def articulate(phones: list[str], starts: np.ndarray, ends: np.ndarray, stress: np.ndarray, n_frames: int, fps: float,
               amplitude: np.ndarray, stiffness: np.ndarray, take_sides: np.ndarray, rng: np.random.Generator,
               rig: Rig, settings: SampleCorpusSettings, variation: TokenVariation = TokenVariation()):
    """Speech weights of one take before the lip contact is solved.

    amplitude : (n,) per phone; stiffness : (T,) per-frame multiplier of every articulator's
    natural frequency; take_sides : (C, 2) per-take left/right gains; settings : the articulation
    settings (jaw and lip stiffness, target lead, pauses).
    Returns (weights (T, E) rig weights without mouthClose, closure drive (T,) where 1 is contact
    and above 1 presses).
    """
    targets, sides, closure = token_targets(phones, starts, ends, stress, amplitude, rng, variation,
                                            settings.pause_jaw_open)
    omega = 2 * np.pi * np.array([channel_stiffness_hz(c, settings) for c in CHANNEL_NAMES])
    per_frame = target_sequence(targets, starts, ends, n_frames, fps, settings.target_lead_s)
    side_frames = target_sequence(sides, starts, ends, n_frames, fps, settings.target_lead_s) * take_sides[None]
    channels = np.clip(critically_damped(per_frame, stiffness[:, None] * omega[None], fps), 0.0, None)
    weights = np.zeros((n_frames, len(rig.shape_names)))
    for c, name in enumerate(CHANNEL_NAMES):
        shapes = CHANNELS[name]
        if len(shapes) == 2:
            for k, shape in enumerate(shapes):  # _L then _R
                weights[:, rig.shape_index(shape)] = channels[:, c] * side_frames[:, c, k]
        else:
            weights[:, rig.shape_index(shapes[0])] = channels[:, c]
    t = np.arange(n_frames) / fps
    drive_input = np.zeros(n_frames)
    if settings.pause_lips_closed:
        for a, b, p in zip(starts, ends, phones):
            if p == PAU and b - a >= settings.pause_closure_min_s:
                drive_input[(t >= a) & (t < b - CLOSURE_OFFSET_LEAD_S)] = PAUSE_CLOSURE_TARGET
    for a, b in zip(starts[closure], ends[closure]):
        drive_input[(t >= a - CLOSURE_ONSET_LEAD_S) & (t < b - CLOSURE_OFFSET_LEAD_S)] = CLOSURE_VIRTUAL_TARGET
    drive = critically_damped(drive_input[:, None], stiffness[:, None] * 2 * np.pi * CLOSURE_HZ, fps)[:, 0]
    return weights, drive


def channel_stiffness_hz(channel: str, settings: SampleCorpusSettings) -> float:
    """The natural frequency (Hz) of one articulatory channel of :data:`CHANNEL_NAMES` under
    ``settings`` (before the emotion's per-frame multiplier)."""
    if channel == "jawOpen":
        return settings.jaw_stiffness_hz
    return STIFFNESS_HZ[channel] * (1.0 if channel in _JAW_CHANNELS else settings.lip_stiffness_scale)


def slew_limited(values: np.ndarray, max_step: float) -> np.ndarray:
    """The smallest curve at or above ``values`` (T,) that changes by at most ``max_step`` per
    frame: rises start earlier (a backward pass) and falls end later (a forward pass)."""
    out = np.asarray(values, float).copy()
    for t in range(len(out) - 2, -1, -1):
        out[t] = max(out[t], out[t + 1] - max_step)
    for t in range(1, len(out)):
        out[t] = max(out[t], out[t - 1] - max_step)
    return out


def apply_contact(weights: np.ndarray, drive: np.ndarray, solver: ContactSolver, fps: float = 120.0,
                  press_gain: float = 0.35) -> np.ndarray:
    """Put the lip closure into ``weights`` (T, E), in place and returned.

    Where the closure drive is below 1 the lips approach contact in proportion; at 1 and
    above they touch (``mouthClose`` solved on the rig), and the excess presses them together
    (``mouthPress_L/R``) and rolls them in a little. ``mouthClose`` changes no faster than
    :data:`MAX_LIP_SPEED_MM_S` allows (``fps``: frames per second of ``weights``).
    """
    rig = solver.rig
    # the opening shapes give way over at least 60 ms, like the closure itself
    reach = slew_limited(np.clip(drive, 0.0, 1.0), 1.0 / (0.06 * fps))
    excess = np.clip(drive - 1.0, 0.0, None)
    for name, gain in (("mouthPress_L", press_gain), ("mouthPress_R", press_gain),
                       ("mouthRollLower", 0.1), ("mouthRollUpper", 0.08)):
        k = rig.shape_index(name)
        weights[:, k] = weights[:, k] + gain * excess
    # the lip-opening shapes give way as the lips close
    for name in ("mouthUpperUp_L", "mouthUpperUp_R", "mouthLowerDown_L", "mouthLowerDown_R", "mouthFunnel"):
        k = rig.shape_index(name)
        weights[:, k] *= 1.0 - 0.8 * reach
    needed = solver.needed_close(weights)
    max_step = MAX_LIP_SPEED_MM_S / fps / solver.closing_mm()
    weights[:, rig.shape_index("mouthClose")] = np.minimum(slew_limited(reach * needed, max_step), needed)
    return weights
