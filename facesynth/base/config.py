"""Typed, per-stage settings, validated when they are loaded.

``configs/default.toml`` is the single source of default values. Each setting is declared
once, as a field of its section's frozen dataclass: its Python type, and through
:func:`setting` its allowed range or choices, unit and source. :meth:`Config.load` checks
the defaults, a ``--config`` file and every ``--set section.key=value`` against these
declarations before any work is done: an unknown section or key, a wrong type, a value out
of range (NaN and infinity included) or an unknown choice is refused with one sentence that
names where it came from, the key, the value given and what is allowed (a ``--set``
problem is an :class:`~facesynth.base.errors.OverrideError`, bad usage). A stage asks for
its own section as a frozen dataclass; the resolved section is stored in the artifact the
stage writes (root attribute ``config``). Precedence: defaults < ``--config`` file <
``--set`` overrides.

``python -m facesynth.base.config`` prints the settings reference, ``docs/configuration.md``.
"""

from __future__ import annotations

import dataclasses
import json
import math
import sys
import typing
from collections.abc import Mapping
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any, TypeVar

from .errors import ConfigError, OverrideError
from .phonemes import PAU, PHONES
from .registry import EXPORT_FORMATS, METHODS, Registry

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

DEFAULTS_NAME = "configs/default.toml"

#: Presets of ``facesynth sample-corpus --preset``: the virtual actress's sizes
#: (:mod:`facesynth.domain.corpus.generate`) and a real performer's takes shipped with facesynth
#: (``facegood``: :mod:`facesynth.domain.capture.facegood`).
SAMPLE_CORPUS_PRESETS: tuple[str, ...] = ("tiny", "small", "paper", "facegood")

#: Phones a Table IV list may name: the Festival set without the pause.
_SPOKEN_PHONES: tuple[str, ...] = tuple(p for p in PHONES if p != PAU)


@dataclass(frozen=True)
class Declaration:
    """What one setting may hold, beyond its Python type (stored in its field's metadata).

    ``ge``/``gt``/``le``/``lt`` bound a number (inclusive/exclusive); ``choices`` lists the
    allowed strings (for a list: of each element), or names the members of a registry
    (:class:`Members`: read when a value is checked, so a member registered later counts); ``min_items``/``max_items`` bound a list's
    length; ``finite`` refuses NaN and infinity for floats. ``unit`` and ``source`` are for
    people: the unit of a number and where its value or meaning comes from."""

    source: str
    unit: str = ""
    ge: float | None = None
    gt: float | None = None
    le: float | None = None
    lt: float | None = None
    members: Members | None = None
    min_items: int = 0
    max_items: int | None = None
    finite: bool = True
    fixed_choices: tuple[str, ...] | None = None

    @property
    def choices(self) -> tuple[str, ...] | None:
        """The allowed strings now (a registry's members as registered so far)."""
        return self.members.names() if self.members is not None else self.fixed_choices


@dataclass(frozen=True)
class Members:
    """The members of ``registry`` (a :class:`facesynth.base.registry.Registry`) that have the
    fact ``having`` (all of them when ''), as a setting's choices, plus ``extra`` values."""

    registry: Registry
    having: str = ""
    extra: tuple[str, ...] = ()

    def names(self) -> tuple[str, ...]:
        return tuple(e.name for e in self.registry.entries() if not self.having or e.facts.get(self.having)) + self.extra


def setting(source: str, *, unit: str = "", ge: float | None = None, gt: float | None = None,
            le: float | None = None, lt: float | None = None, choices: tuple[str, ...] | Members | None = None,
            min_items: int = 0, max_items: int | None = None, finite: bool = True) -> Any:
    """A settings-dataclass field carrying its :class:`Declaration`. It has no default: the
    default value lives in ``configs/default.toml`` only."""
    members = choices if isinstance(choices, Members) else None
    fixed = None if members is not None or not choices else tuple(choices)  # type: ignore[arg-type]
    decl = Declaration(source, unit, ge, gt, le, lt, members, min_items, max_items, finite, fixed)
    return dataclasses.field(metadata={"setting": decl})


@dataclass(frozen=True)
class IngestSettings:
    """``[ingest]``: emotion labels and their aliases, audio/motion length check, phone tiers."""

    emotions: tuple[str, ...] = setting("paper III (four expressions)", min_items=1)
    emotion_aliases: Mapping[str, str] = setting("not in the paper: other spellings in manifests and emotion files")
    max_audio_mismatch_s: float = setting("not in the paper: input check", unit="s", ge=0)
    phone_tiers: tuple[str, ...] = setting("not in the paper: TextGrid tier names", min_items=1)
    emotion_tiers: tuple[str, ...] = setting("not in the paper: TextGrid tier names of per-phone emotion")
    recognize_phones: bool = setting("not in the paper: a take with audio but neither alignment nor transcript gets "
                                     "its phones recognised from the audio (align.recognition); false: no phones")
    curves_mapping: str = setting("not in the paper: another rig's curves -> ARKit (CSV source,arkit,weight) for takes "
                                  "whose manifest row names none (relative to the working folder); empty: none")
    curves_fps: float = setting("not in the paper: frame rate of curve takes without time (.npy) whose manifest row "
                                "gives none; 0: none", unit="frames/s", ge=0, le=2000)
    live_link_max_gap_s: float = setting("not in the paper: Live Link Face rows further apart leave a gap instead of "
                                         "being interpolated", unit="s", gt=0, le=10)
    video_eye_corners_mm: float = setting("not in the paper: a video take's scale, the distance between the outer eye "
                                          "corners (adult biocular width 87-91 mm)", unit="mm", gt=0, le=1000)
    neutral: str = setting("not in the paper: the performer's neutral face in another rig's curves, taken off "
                           "their weights: auto, off, frame:N or time:SECONDSs")
    live_link_neutral: str = setting("not in the paper: the same for a Live Link Face take (ARKit measures from the "
                                     "performer's face already): auto, off, frame:N or time:SECONDSs")


@dataclass(frozen=True)
class AlignSettings:
    """``[align]``: pocketsphinx's front end (frame rate, frames/s) and model sample rate (Hz); the
    fallback methods, voice activity and the transcript-mismatch check (:mod:`facesynth.domain.speech.alignment`)."""

    frame_rate: int = setting("pocketsphinx's acoustic front end (its default)", unit="frames/s", ge=1)
    sample_rate: int = setting("pocketsphinx's English acoustic model", unit="Hz", ge=8000)
    methods: tuple[str, ...] = setting("not in the paper: alignment methods tried in order until one places every word",
                                       choices=("pocketsphinx", "wide-beam", "chunks", "duration"), min_items=1)
    wide_beam: float = setting("not in the paper: pocketsphinx beam of the wide-beam method (its default 1e-48)",
                               gt=0, lt=1)
    min_silence_s: float = setting("not in the paper: silences the chunks method cuts at", unit="s", gt=0)
    max_voiced_pause_s: float = setting("not in the paper: speech aligned as pause above this is a transcript mismatch",
                                        unit="s", gt=0)
    max_rate_ratio: float = setting("not in the paper: speech this many times longer or shorter than its text's typical "
                                    "duration is a transcript mismatch", unit="factor", gt=1)
    min_phone_s: float = setting("not in the paper: shortest speech per phone of the text", unit="s", ge=0)
    activity_range_db: float = setting("not in the paper: voice activity, below the loudest frames", unit="dB", gt=0)
    activity_floor_db: float = setting("not in the paper: voice activity, above the noise floor", unit="dB", ge=0)
    recognition: str = setting("not in the paper: how audio without a text is turned into phones (recognised words "
                               "then aligned, or a phone loop)", choices=("words", "phones"))
    language: str = setting("not in the paper: the language of the text (a BCP-47 tag: en, de, fr, es, cmn, ...); "
                            "another than English is read by a G2P backend and its phones mapped to the nearest "
                            "English phones by articulation")
    dictionary: str = setting("not in the paper: the user's pronunciations, lines 'word  IPA phones', read before the "
                              "dictionary or G2P backend; {language} in the path is the language's tag; empty: none")


@dataclass(frozen=True)
class NormalizeSettings:
    """``[normalize]``: origin and rigid markers, gap filling, the reference frame of Eq. 1-2."""

    origin_marker: str = setting("paper III ('a specific marker'); empty: the marker nearest the centroid")
    rigid_markers: tuple[str, ...] = setting("Eq. 1-2; empty: the corpus's rigid markers, else all markers as in the paper")
    max_gap_frames: int = setting("not in the paper: gap filling", unit="frames", ge=0)
    reference_take: str = setting("Eq. 1-2 reference frame; empty: leading silences of neutral takes (or the first "
                                  "take when reference_frame is set)")
    reference_frame: int = setting("Eq. 1-2 reference frame; -1: automatic", unit="frame index", ge=-1)
    reference_silence_s: float = setting("Eq. 1-2 automatic reference", unit="s", gt=0)
    rigid_max_spread_mm: float = setting("not in the paper: rigid markers found from the data when none are named; "
                                         "the most a pair's distance may vary (standard deviation)", unit="mm", gt=0)
    rigid_min_markers: int = setting("not in the paper: fewest rigid markers found from the data", ge=3, le=1000)
    known_pose: bool = setting("not in the paper: a corpus whose takes were all posed from curves is normalized with "
                               "their known rest pose as the reference and their known head pose (no fit); false: "
                               "as any capture")


@dataclass(frozen=True)
class PcaSettings:
    """``[pca]``: number of components (paper III: 25) or a variance target."""

    n_components: int = setting("paper III (25 components)", ge=1)
    variance_target: float = setting("paper III (98.53% of the variance); 0: use n_components", unit="fraction", ge=0, le=1)


@dataclass(frozen=True)
class BuildDbSettings:
    """``[build_db]``: DSC time-warp samples (Eq. 6), the boundary-velocity fit (Eq. 9)."""

    dsc_samples: int = setting("Eq. 6 (time-warp before the blend)", unit="samples", ge=3)
    boundary_fit_frames: int = setting("not in the paper: Eq. 9's velocities as end slopes of a local polynomial fit; "
                                       "2: one-frame differences", unit="frames at the capture rate", ge=2, le=60)


@dataclass(frozen=True)
class IsomapSettings:
    """``[isomap]``: neighbours (paper IV: 12), landmark size, the Eq. 3 image size and kernel."""

    n_neighbors: int = setting("paper IV (12 neighbours)", ge=2)
    max_exact_frames: int = setting("not in the paper: landmark Isomap; 0: every frame exactly", unit="frames", ge=0)
    image_size: int = setting("Eq. 3 image", unit="px", ge=16)
    kernel_sigma_px: float = setting("Eq. 3 (Gaussian width)", unit="px", gt=0)
    rho: float = setting("Eq. 3 (0 < rho < 1)", gt=0, lt=1)


@dataclass(frozen=True)
class PruneSettings:
    """``[prune]``: the thresholds of ``prune --auto`` (jump and outlier robust z-scores, excursion length)."""

    jump_z: float = setting("paper V (chosen on the sample corpus)", unit="robust z-score", gt=0)
    max_excursion_s: float = setting("paper V (chosen on the sample corpus)", unit="s", gt=0)
    outlier_z: float = setting("paper V (chosen on the sample corpus)", unit="robust z-score", gt=0)


@dataclass(frozen=True)
class SynthesizeSettings:
    """``[synthesize]``: search, cost weights (Tables I-II, Eq. 4-10: PNT, alpha1..alpha6), smoothing
    (Eq. 16, Table IV), silence and output rate.
    """

    method: str = setting("paper VI-B, Algorithm 1 (dp); the other members of the method family (docs/methods.md)",
                          choices=Members(METHODS))
    search: str = setting("deprecated, now synthesize.method (which it follows when that is dp): paper VI-B, "
                          "Algorithm 1 (dp); Cao et al. 2004 (greedy)", choices=("dp", "greedy"))
    greedy_clusters: int = setting("Cao et al. 5.3; 0: unclustered Anime Graph", unit="clusters", ge=0)
    postprocess: str = setting("paper VII-B, Eq. 16 (deng); Cao et al. 6.3 (cao)", choices=("deng", "cao"))
    use_opencl: bool = setting("not in the paper: compute device")
    dp: str = setting("not in the paper: the exact pruned DP (pruned) or the dense reference (dense)",
                      choices=("pruned", "dense"))
    pnt: float = setting("Tables I-II, Eq. 5 (PNT)", unit="cost", gt=0)
    alpha1: float = setting("Table I, rule 4", ge=0)
    alpha2: float = setting("Table I, rules 2-3 (weight of DSC, Eq. 6)", ge=0)
    alpha3: float = setting("Eq. 7", ge=0)
    alpha4: float = setting("Table II, rule 2 (0 < alpha4 < 1)", gt=0, lt=1)
    alpha5: float = setting("Table II", ge=0)
    alpha6: float = setting("Eq. 5", ge=0)
    huge_penalty: float = setting("Eq. 10 (HugePenalty)", unit="cost", gt=0)
    phone_match: str = setting("not in the paper: Table II's phone matching for a phone of another language (viseme: "
                               "by its nearest English phone, the paper's rule; unseen: one the database lacks by "
                               "articulatory features, its nearest phone's nodes 0 and the others by how much "
                               "further they are, facesynth.base.ipa; features: every phone so, English too)",
                               choices=("viseme", "unseen", "features"))
    phone_match_scale: float = setting("not in the paper: how much further in features (facesynth.base.ipa.WEIGHTS) "
                                       "than the nearest phone a node's phone costs what Table II's rule 3 charges "
                                       "(another viseme); nearer, from alpha4 times that up", unit="feature distance",
                                       gt=0)
    join_smoothing: str = setting("paper VII-B, Eq. 16 (eq16, free-ended); not in the paper: a displacement blend "
                                  "continuous in position and velocity (blend)", choices=("blend", "eq16"))
    smoothing_half_window: int = setting("Eq. 16 (s = 3); the blend's reach on each side of a join",
                                         unit="frames at the capture rate", ge=0, le=600)
    smoothing_lambda: float = setting("Eq. 16 (weight of the smoothness term)", ge=0)
    weight_high: float = setting("Table IV (2)", gt=0)
    weight_low: float = setting("Table IV (0.5)", gt=0)
    weight_intermediate: float = setting("Table IV (1.0)", gt=0)
    high_phones: tuple[str, ...] = setting("Table IV", choices=_SPOKEN_PHONES)
    low_phones: tuple[str, ...] = setting("Table IV", choices=_SPOKEN_PHONES)
    pinned_phones: tuple[str, ...] = setting("not in the paper: phones the join blend leaves unchanged against "
                                             "an unpinned neighbour, and whose lip gap the voice's loudness leaves "
                                             "as the method made it (lip closures stay closed)", choices=_SPOKEN_PHONES)
    output_fps: float = setting("paper VII-B (30 frames/s)", unit="frames/s", gt=0, le=1000)
    silence_interpolation: str = setting("paper VII-B (linear); hermite: velocities matched on both sides",
                                         choices=("linear", "cubic", "cosine", "hermite"))
    pause_rest_min_s: float = setting("not in the paper: a pause at least this long passes through the rest pose "
                                      "(the mouth relaxes and closes) instead of one interpolation between its "
                                      "neighbours; 3600: never", unit="s", gt=0, le=3600)
    pause_rest_ramp_s: float = setting("not in the paper: time such a pause takes to ease from the last phone to "
                                       "rest, and from rest into the next phone", unit="s", gt=0, le=2)
    loudness_weight: float = setting("not in the paper (JALI, Edwards et al. 2016: the jaw follows the voice's "
                                     "loudness): with the audio given, the share of the mouth opening taken from "
                                     "its loudness; 0: the phones alone", ge=0, le=1)
    loudness_smoothing_s: float = setting("not in the paper: moving average of the audio's loudness envelope, "
                                          "and the ease of its weight around pinned_phones", unit="s", gt=0, le=1)
    loudness_lip_markers: tuple[str, ...] = setting("not in the paper: upper and lower inner-lip markers whose "
                                                    "gap the loudness moves", min_items=2, max_items=2)
    voice_recognized: str = setting("not in the paper: with the phones recognised from the audio (audio alone), what "
                                    "the voice does to the mouth: its articulation (the acoustic articulation model), "
                                    "its loudness alone, or nothing", choices=("articulation", "loudness", "off"))
    voice_given: str = setting("not in the paper: the same with the phones given or aligned to a transcript",
                               choices=("articulation", "loudness", "off"))
    articulation_model: str = setting("not in the paper: the articulation artifact the voice's articulation comes "
                                      "from; empty: the packaged model (fitted on FACEGOOD and GRID's speakers)")
    articulation_prior: float = setting("not in the paper: fit-articulation adapts the articulation_model (the "
                                        "general one) to a performer: how strongly each coefficient is pulled "
                                        "toward it (a ridge penalty per frame, as the fit's own); 0: the "
                                        "performer's capture alone", ge=0)
    voice_weight: float = setting("not in the paper: the share of the mouth opening the voice's articulation takes "
                                  "where the voice is clear; 0: the phones' opening", ge=0, le=1)
    voice_opening_map: str = setting("not in the paper: how the articulation's predicted opening becomes lip gaps: "
                                     "by rank onto the method's own gaps (their distribution: as often closed, half "
                                     "and wide open as the method's mouth) or affinely, its 5th..95th percentiles "
                                     "onto theirs", choices=("percentiles", "rank"))
    voice_rounding_weight: float = setting("not in the paper: the share of the lips' rounding (mouthFunnel, "
                                           "mouthPucker) the voice's articulation takes; 0: the phones' rounding",
                                           ge=0, le=1)
    voice_closure_threshold: float = setting("not in the paper: a peak of the articulation model's closure score "
                                             "at least this high closes the lips; above 1: never; -1: the "
                                             "model's own (a performer's model from fit-articulation carries the "
                                             "threshold its held-out takes chose; a model without one, the "
                                             "packaged, closes none)", ge=-1)
    voice_closing_threshold: float = setting("not in the paper: a closing of the method's own motion is kept where "
                                             "the model's closing score reaches this near it; above 1: none kept",
                                             ge=0)
    voice_trust_window_s: float = setting("not in the paper: the window over which the voice's predicted opening "
                                          "and the phones' opening are compared (their local agreement, how far "
                                          "the voice is trusted)", unit="s", gt=0, le=60)
    voice_trust_low: float = setting("not in the paper: at or below this local Pearson r between the voice's and the "
                                     "phones' opening the voice is not trusted (the phones keep their opening and "
                                     "closures); -1 with voice_trust_high -1: always trusted", ge=-1, le=1)
    voice_trust_high: float = setting("not in the paper: at or above this local Pearson r the voice is fully "
                                      "trusted (linear between)", ge=-1, le=1)
    voice_snr_none: float = setting("not in the paper: the speech band's loudness above its running noise floor at or "
                                    "below which it is not heard (no confidence: the method's mouth in batch, rest "
                                    "live)", unit="natural log of an amplitude ratio", ge=0, le=10)
    voice_snr_full: float = setting("not in the paper: the speech band's loudness above its running noise floor from which "
                                    "it is heard fully (linear from voice_snr_none)",
                                    unit="natural log of an amplitude ratio", ge=0, le=10)
    voice_activity: int = setting("not in the paper: WebRTC's voice activity detector, whose speech frames are "
                                  "heard fully whatever their level (aggressiveness 0..3: higher calls more noise, "
                                  "and more quiet speech, not speech; -1: the level alone)", ge=-1, le=3)
    voice_pin_recognized: bool = setting("not in the paper: with the phones recognised, whether pinned_phones keep "
                                         "their closure against the voice's articulation (recognised /p b m/ are "
                                         "often wrong)")


@dataclass(frozen=True)
class EvaluateSettings:
    """``[evaluate]``: which takes, the lip markers and closure threshold (mm), the plotted marker,
    the fitting effort of the Cohen-Massaro baseline, the bootstrap and the emotion classifier."""

    split: str = setting("paper VIII (test sentences); val: the tuning sentences", choices=("test", "val"))
    lip_markers: tuple[str, ...] = setting("not in the paper: upper and lower inner-lip markers", min_items=2, max_items=2)
    closure_mm: float = setting("not in the paper: bilabial closure", unit="mm", gt=0)
    plot_marker: str = setting("paper Figs. 15-16 (marker #79)")
    dominance_iterations: int = setting("not in the paper: L-BFGS-B iterations fitting the Cohen-Massaro baseline", ge=1)
    methods: tuple[str, ...] = setting("not in the paper: the synthesis methods scored (dp always: the paired "
                                       "differences are dp minus each); trajectory also needs --model",
                                       choices=Members(METHODS))
    bootstrap_resamples: int = setting("not in the paper: resamples of the sentences for every 95% interval", ge=100)
    classifier_frames: int = setting("not in the paper: training frames of the emotion classifier", unit="frames", ge=100)
    seed: int = setting("not in the paper: seeds the bootstrap and the classifier's frame sample", ge=0)


@dataclass(frozen=True)
class TuneSettings:
    """``[tune]``: the multi-start Nelder-Mead search of the cost weights and PNT (paper VI-D),
    then the boundary-fit length and the join window."""

    starts: int = setting("paper VI-D (random restarts)", ge=1)
    max_evaluations: int = setting("paper VI-D; split evenly across the starts", unit="evaluations in all", ge=1)
    seed: int = setting("not in the paper: random starts", ge=0)
    spread: float = setting("paper VI-D (random starts)", unit="factor", ge=1)


@dataclass(frozen=True)
class DeformSettings:
    """``[deform]``: Eq. 14 Gaussian width and mesh-distance threshold (mesh units), head motion."""

    sigma: float = setting("Eq. 14 (the paper's 1.5 on its model)", unit="mesh units", gt=0)
    distance_threshold: float = setting("paper VII-A (mesh-distance threshold)", unit="mesh units", gt=0)
    apply_head_motion: bool = setting("Eq. 1-2 (the removed head motion)")


@dataclass(frozen=True)
class RenderSettings:
    """``[render]``: video size (px), frame rate, view, camera (field of view, yaw, pitch; degrees),
    anti-aliasing, compute device, head motion of rig curves."""

    width: int = setting("not in the paper: video size", unit="px", ge=16)
    height: int = setting("not in the paper: video size", unit="px", ge=16)
    fps: float = setting("paper VII-B (30 frames/s)", unit="frames/s", gt=0, le=1000)
    view: str = setting("not in the paper: what is drawn", choices=("shaded", "markers", "side-by-side"))
    labels: tuple[str, ...] = setting("not in the paper: the side-by-side view's labels, left (the animation) and "
                                      "right (--compare)", min_items=2, max_items=2)
    fov_deg: float = setting("not in the paper: vertical field of view", unit="degrees", gt=0, lt=180)
    yaw_deg: float = setting("not in the paper: camera turned toward the subject's left (+x); 0 is frontal",
                             unit="degrees", ge=-90, le=90)
    pitch_deg: float = setting("not in the paper: camera raised above the face (negative: below)",
                               unit="degrees", ge=-60, le=60)
    supersample: int = setting("not in the paper: anti-aliasing, samples per pixel along each axis (1: none)",
                               ge=1, le=4)
    use_opencl: bool = setting("not in the paper: rasterize on OpenCL (NumPy without a device that builds)")
    head_motion: bool = setting("not in the paper: move the face by the head motion rig curves carry (a mesh "
                                "animation's is in its vertices where deform put it)")


@dataclass(frozen=True)
class LimitsSettings:
    """``[limits]``: physical bounds on what an input may hold, read by every command. A value
    past a bound is refused with a sentence naming the setting that raises it; the defaults sit
    far above any real face capture (the paper: 79 markers, 5,556 nodes, 120 Hz)."""

    max_markers: int = setting("not in the paper: input bound (a face capture has tens to a few hundred)",
                               unit="markers", ge=1)
    max_nodes: int = setting("not in the paper: input bound (hours of capture: about 130,000)", unit="nodes", ge=1)
    max_frames: int = setting("not in the paper: input bound on the frames of one artifact", unit="frames", ge=1)
    max_vertices: int = setting("not in the paper: input bound on a face mesh", unit="vertices", ge=3)
    max_fps: float = setting("not in the paper: input bound on capture and output frame rates", unit="frames/s", gt=0)
    max_phone_s: float = setting("not in the paper: longest phone segment (pauses included)", unit="s", gt=0)
    max_utterance_s: float = setting("not in the paper: longest utterance or take", unit="s", gt=0)
    max_dataset_mb: float = setting("not in the paper: largest dataset an artifact may declare", unit="MB", gt=0)


@dataclass(frozen=True)
class BatchSettings:
    """``[batch]``: what each line of ``facesynth batch`` writes and how many Dask workers run them."""

    outputs: tuple[str, ...] = setting("not in the paper: per-line outputs: the motion, the rig curves, the video, "
                                       "the mesh animation and the export formats (arkit: deprecated, now arkit-csv)",
                                       choices=Members(EXPORT_FORMATS, "batch", ("motion", "curves", "avi", "anim",
                                                                                 "arkit")), min_items=1)
    workers: int = setting("not in the paper: local Dask worker processes; 0: one per core", unit="processes", ge=0)


@dataclass(frozen=True)
class ExpressionSettings:
    """``[expression]``: the bilinear style/content model (Chuang & Bregler 2005 §3, Eq. 4-7)."""

    splits: tuple[str, ...] = setting("not in the paper: the takes fitted (held-out takes stay out)",
                                      choices=("train", "val", "test"), min_items=1)
    components: int = setting("Eq. 1 (PCA of the facial vector); not given in the paper", unit="components", ge=1)
    content_dim: int = setting("Eq. 4 (content vector size); not given in the paper", ge=1)
    frame_step: int = setting("not in the paper: every n-th aligned frame is fitted", unit="frames", ge=1)
    max_iterations: int = setting("Eq. 4-6 fit: 'iterate until convergence'", ge=1)
    tolerance: float = setting("Eq. 4-6 fit: stop when an iteration lowers the error by less than this fraction",
                               unit="fraction", ge=0, lt=1)
    analyze_iterations: int = setting("Eq. 5-6 ('iterate over these two equations until convergence')", ge=1)
    analyze_init: str = setting("§3.3 (mean_content: the mean content vector, as the paper); best_style: the fitted "
                                "style that explains each frame best", choices=("mean_content", "best_style"))
    transition_s: float = setting("not in the paper: Gaussian sigma easing the style between emotion spans",
                                  unit="s", ge=0)
    style_smoothing_s: float = setting("not in the paper (its §7 notes per-frame jitter): Gaussian sigma smoothing "
                                       "the analysed style over time; 0: per frame as in the paper", unit="s", ge=0)


@dataclass(frozen=True)
class HeadMotionSettings:
    """``[head_motion]``: pitch-driven head motion (Chuang & Bregler 2005 §5, Eq. 10-15)."""

    pitch_min_hz: float = setting("§5.1 'normal human range' (pYIN search range)", unit="Hz", gt=0)
    pitch_max_hz: float = setting("§5.1 'normal human range' (pYIN search range)", unit="Hz", gt=0)
    hop_s: float = setting("not in the paper: pitch frame hop", unit="s", gt=0, le=0.1)
    pitch_resolution: float = setting("not in the paper: pYIN pitch-bin width (librosa's default 0.1; coarser is faster)",
                                      unit="semitones", gt=0, le=1)
    max_gap_s: float = setting("§5.1 'interpolate ... very short periods of missing data'", unit="s", ge=0)
    min_voiced_s: float = setting("not in the paper: voiced runs shorter than this are pitch-tracker noise", unit="s", ge=0)
    top_sentences: int = setting("§5.2 M (top sentences by phrase features); not given in the paper", ge=1)
    top_segments: int = setting("§5.2 K (candidates per segment); not given in the paper", ge=1)
    b: float = setting("Eq. 12 (b = 0.05, weight of the geometric distance G_d)", ge=0, le=1)
    c: float = setting("Eq. 12 (c = 0.3, weight of the pitch distance P_d)", ge=0, le=1)
    omega_h: float = setting("Eq. 15 (omega_1, set equal to omega_2 in the paper)", ge=0)
    omega_r: float = setting("Eq. 15 (omega_2)", ge=0)
    breath_s: float = setting("§5.4 subsentence breaks 'where the speaker takes a breath' (unvoiced pause)", unit="s", gt=0)
    join_smooth_s: float = setting("§5.4 'end positions ... are smoothed' (Gaussian sigma at joins)", unit="s", ge=0)
    fps: float = setting("not in the paper: rate of the written head motion (the output rate)", unit="frames/s", gt=0, le=1000)


@dataclass(frozen=True)
class KeyshapesSettings:
    """``[keyshapes]``: key-shape selection per emotion (Chuang & Bregler 2005 §4.1, Huang et al. §5.2),
    the NNLS weights (Eq. 8) and the keymorph fit on the built-in rig."""

    method: str = setting("Chuang & Bregler §4.1 (pca) or Huang et al. §5.2 (affinity)", choices=("pca", "affinity"))
    count: int = setting("Chuang & Bregler §6 (about 20 per emotion); 0: the error knee (affinity) or 20 (pca)", ge=0,
                         le=200)
    duplicate_mm: float = setting("Chuang & Bregler §4.1 (near-duplicate threshold): RMS per marker", unit="mm", ge=0)
    affinity_frames: int = setting("not in the papers: frames sampled for affinity propagation (memory grows with "
                                   "its square)", ge=10, le=20000)
    curve_frames: int = setting("not in the papers: frames sampled for the reconstruction-error curve", ge=10)
    keymorph_ridge: float = setting("not in the papers: tie-break between rig shapes in the keymorph fit, relative to "
                                    "a shape's squared norm", ge=0)
    seed: int = setting("not in the papers: frame sampling", ge=0)


@dataclass(frozen=True)
class TrajectorySettings:
    """``[trajectory]``: the compact key-shape trajectory model (Huang et al. §5.4): per phone (and per
    (phone, emotion)) Gaussians of key-shape weights, and the smooth path of Eq. 6-7 through them."""

    frames: str = setting("Huang §5.4 (span: every frame tagged with the phone); centre: each token's centre frame",
                          choices=("span", "centre"))
    min_tokens: int = setting("not in the paper: training tokens a (phone, emotion) model needs, else the phone's "
                              "model is used", unit="tokens", ge=1)
    variance_floor: float = setting("not in the paper: each variance is at least this fraction of that key-shape "
                                    "weight's variance over all training frames", gt=0, le=1)
    smoothness: float = setting("Huang §5.4, Eq. 6 (lambda = 10), per frame at smoothness_fps", ge=0)
    smoothness_fps: float = setting("Huang §5.4 (18000 frames of 10 minutes of video: 30 frames/s); at another solve "
                                    "rate lambda is scaled by (fps / smoothness_fps)^2", unit="frames/s", gt=0, le=1000)
    fps: float = setting("not in the paper: the rate Eq. 7 is solved at; 0: the model's capture rate",
                         unit="frames/s", ge=0, le=1000)
    duration_normalization: bool = setting("Huang §5.4, Eq. 6 (D: each frame's data term times 1 - D_ph / T)")


@dataclass(frozen=True)
class CoarticulationSettings:
    """``[coarticulation]``: fitting the Cohen-Massaro coarticulation method (``facesynth fit-method
    coarticulation``): a target pose, dominance magnitude and rate per (phone, emotion)."""

    iterations: int = setting("not in the paper: L-BFGS-B iterations of the fit (variable projection)", ge=1)


@dataclass(frozen=True)
class SolveSettings:
    """``[solve]``: the direct facial solve, rig weights in [0, 1] per frame (a production facial solve)."""

    smooth: float = setting("not in the papers: weight of the frame-to-frame change, relative to a shape's squared "
                            "norm", ge=0)
    ridge: float = setting("not in the papers: weight of the squared weights, relative to a shape's squared norm", ge=0)
    iterations: int = setting("not in the papers: most iterations of the projected-gradient solve", ge=1, le=100000)
    tolerance: float = setting("not in the papers: stop when no weight moves by more than this in one iteration",
                               unit="weight", gt=0)
    output_fps: float = setting("not in the papers: rate of the curves solved from a normalized capture (render's rate)",
                                unit="frames/s", gt=0, le=1000)
    posed_captures: str = setting("not in the papers: a normalized capture posed from curves (noise-free markers, rest "
                                  "and head pose known) is solved 'exact' (no smoothing, no ridge, exact_iterations "
                                  "and exact_tolerance) or 'regularized' (the settings above)",
                                  choices=("exact", "regularized"))
    exact_iterations: int = setting("not in the papers: most iterations of the exact solve", ge=1, le=1000000)
    exact_tolerance: float = setting("not in the papers: the exact solve's stopping step", unit="weight", gt=0)
    neutral: str = setting("not in the papers: the performer's neutral face the weights of a normalized capture's "
                           "take are measured from: auto, off, frame:N, time:SECONDSs or take:NAME")
    sparsity: float = setting("not in the papers: weight of the sum of the weights (L1), relative to a shape's "
                              "squared norm", ge=0)
    antagonist: float = setting("not in the papers: weight of the product of opposing channels (jawLeft and "
                                "jawRight...), relative to a shape's squared norm", ge=0)
    symmetry: float = setting("not in the papers: weight of the squared difference of mirrored channels, relative "
                              "to a shape's squared norm", ge=0)


@dataclass(frozen=True)
class BindSettings:
    """``[bind]``: placing a capture's markers on a rig (``facesynth bind``)."""

    frame: int = setting("not in the papers: the capture frame fitted to the rig; -1: the most typical frame",
                         unit="frame index", ge=-1)
    max_residual_mm: float = setting("not in the papers: markers farther than this from their rig vertex are "
                                     "flagged", unit="mm", gt=0)
    keep: float = setting("not in the papers: fraction of the markers each fitting step uses (the rest are taken "
                          "as off the face)", unit="fraction", gt=0, le=1)
    iterations: int = setting("not in the papers: most closest-point iterations per start", ge=1, le=10000)


@dataclass(frozen=True)
class RetargetSettings:
    """``[retarget]``: key-shape retargeting (Chuang & Bregler Eq. 9) and mesh blending (Huang et al. §3),
    compute device."""

    blend: str = setting("Huang et al. §3 (deformation gradients) or linear keymorph blending",
                         choices=("linear", "gradient"))
    emotion_scale_mm: float = setting("not in the papers: per-frame emotion weights are exp(-(r_e / scale)^2) of each "
                                      "emotion's NNLS residual r_e, normalized", unit="mm", gt=0)
    emotion_smooth_s: float = setting("not in the papers: moving-average window of the emotion weights", unit="s",
                                      ge=0)
    anchor: float = setting("Sumner et al. 2005 (soft constraint): pull toward the linear blend, relative to the "
                            "mean squared edge", gt=0)
    use_opencl: bool = setting("not in the papers: gradient blending's rotated edges and back-substitutions on "
                               "OpenCL (NumPy and SuperLU without a device that builds)")


@dataclass(frozen=True)
class ExportSettings:
    """``[export]``: ``facesynth export``'s defaults (the other formats keep the animation's rate
    unless ``--fps``)."""

    arkit_fps: float = setting("not in the paper: Live Link Face records at 60 frames/s", unit="frames/s",
                               gt=0, le=1000)


@dataclass(frozen=True)
class StreamSettings:
    """``[stream]``: live synthesis (``facesynth stream``): decisions with a bounded look-ahead,
    incremental phones, the transports' bounds (docs/live.md)."""

    method: str = setting("paper Algorithm 1 on a sliding window (dp, fixed-lag), Cao et al.'s greedy tiling, or "
                          "Huang et al.'s key-shape trajectory solved with the sent frames fixed (trajectory: streams "
                          "from a trajectory model)", choices=Members(METHODS, "streams"))
    lookahead_phones: int = setting("not in the papers: phones known past a step before it is committed (the "
                                    "fixed lag); more: closer to the whole-utterance DP, later frames", unit="phones",
                                    ge=0, le=64)
    fps: float = setting("not in the papers: output frames per second (30 as batch, 60 as Live Link Face)",
                         unit="frames/s", gt=0, le=120)
    recognition_hold: int = setting("not in the papers: the recogniser's last phones that are still provisional "
                                    "(its partial hypothesis revises them)", unit="phones", ge=1, le=16)
    recognition_restart_s: float = setting("not in the papers: the live recogniser starts a new utterance in the first "
                                           "silence after this long (its work per step grows with the utterance)",
                                           unit="s", gt=0, le=3600)
    pause_wait_s: float = setting("not in the papers: a pause whose next phone is not decided yet has its frames "
                                  "sent this long after their audio, easing toward rest as batch does (in given-phones mode, "
                                  "audio with no phone for this long is taken as a pause)", unit="s", gt=0, le=3600)
    chunk_s: float = setting("not in the papers: audio read per step from standard input", unit="s", gt=0, le=1)
    queue_messages: int = setting("not in the papers: messages waiting for one WebSocket client at most; a client "
                                  "that falls further behind is disconnected", unit="messages", ge=1, le=100000)
    max_message_bytes: int = setting("not in the papers: largest WebSocket message a client may send",
                                     unit="bytes", ge=1024, le=1 << 26)
    voice: str = setting("not in the papers: with the phones recognised from the audio, frames from the voice's "
                         "articulation as soon as its audio (and the model's look-ahead) arrives (articulation), "
                         "or from the phones once the recogniser settles them (off: the DP's captured motion, "
                         "about a second later)", choices=("articulation", "off"))
    voice_jaw: str = setting("not in the papers: with stream.voice = articulation, the jaw from the model's "
                             "predicted mouth opening in the jaw's units (opening) or from its predicted jawOpen "
                             "(jawOpen)", choices=("opening", "jawOpen"))
    voice_anticipation_s: float = setting("not in the papers: with stream.voice = articulation, how far the mouth may "
                                          "move ahead of its sound, as a real mouth opens before its first syllable: "
                                          "each frame waits this much more audio, so the latency grows by it and a "
                                          "player delays its audio to match (0: the model's look-ahead alone)",
                                          unit="s", ge=0, le=1)


@dataclass(frozen=True)
class SampleCorpusSettings:
    """``[sample_corpus]``: the virtual actress's articulation (``facesynth sample-corpus``),
    calibrated on real speech captures (docs/real-speech.md, benchmarks/articulation_statistics.py)."""

    jaw_stiffness_hz: float = setting("calibrated on real speech: natural frequency of the jaw's critically damped "
                                      "motion (higher: a faster jaw that undershoots less)", unit="Hz", gt=0, le=30)
    lip_stiffness_scale: float = setting("calibrated on real speech: multiplier of the lip articulators' natural "
                                         "frequencies (funnel, pucker, roll, press, stretch, raise, lower, shrug, spread)",
                                         gt=0, le=5)
    target_lead_s: float = setting("calibrated on real speech: the articulators' targets lead the phone boundaries "
                                   "(and the sound) by this much", unit="s", ge=0, le=0.2)
    pause_jaw_open: float = setting("calibrated on real speech: the jaw's target in a pause", unit="weight", ge=0, le=1)
    pause_lips_closed: bool = setting("calibrated on real speech: the lips close in pauses of at least "
                                      "pause_closure_min_s (as at rest), rather than staying apart")
    pause_closure_min_s: float = setting("not measured: the shortest pause in which the lips close", unit="s",
                                         ge=0, le=10)


SECTIONS: dict[str, type] = {
    "ingest": IngestSettings,
    "align": AlignSettings,
    "normalize": NormalizeSettings,
    "pca": PcaSettings,
    "build_db": BuildDbSettings,
    "isomap": IsomapSettings,
    "prune": PruneSettings,
    "synthesize": SynthesizeSettings,
    "evaluate": EvaluateSettings,
    "tune": TuneSettings,
    "deform": DeformSettings,
    "keyshapes": KeyshapesSettings,
    "trajectory": TrajectorySettings,
    "coarticulation": CoarticulationSettings,
    "solve": SolveSettings,
    "bind": BindSettings,
    "retarget": RetargetSettings,
    "render": RenderSettings,
    "limits": LimitsSettings,
    "batch": BatchSettings,
    "expression": ExpressionSettings,
    "head_motion": HeadMotionSettings,
    "export": ExportSettings,
    "stream": StreamSettings,
    "sample_corpus": SampleCorpusSettings,
}

S = TypeVar("S")


@dataclass(frozen=True)
class Declared:
    """One declared setting: ``section.name``, its Python type and its :class:`Declaration`."""

    section: str
    name: str
    type: Any
    decl: Declaration

    @property
    def key(self) -> str:
        """``section.key`` of this setting."""
        return f"{self.section}.{self.name}"

    def type_name(self) -> str:
        """The kind of value, in words: 'integer', 'number', 'list of strings'..."""
        origin = typing.get_origin(self.type)
        if origin is tuple:
            return "list of strings" if typing.get_args(self.type)[0] is str else "list of numbers"
        if origin is not None:  # Mapping[str, str]
            return "table of strings"
        return {bool: "boolean", str: "string", int: "integer", float: "number"}[self.type]

    def limits(self) -> str:
        """The allowed range, choices or length in words ('' when any value of the type will do)."""
        d = self.decl
        if self.type is bool:
            return "true or false"
        if typing.get_origin(self.type) is tuple:
            parts = []
            if d.choices:
                parts.append(f"each one of {', '.join(d.choices)}")
            if d.min_items and d.max_items == d.min_items:
                parts.append(f"exactly {d.min_items}")
            else:
                if d.min_items:
                    parts.append(f"at least {d.min_items}")
                if d.max_items is not None:
                    parts.append(f"at most {d.max_items}")
            return ", ".join(parts)
        if d.choices:
            return f"one of {', '.join(d.choices)}"
        bounds = [f"{op} {_number(v)}" for op, v in ((">=", d.ge), (">", d.gt), ("<=", d.le), ("<", d.lt)) if v is not None]
        return " and ".join(bounds)

    def allowed(self) -> str:
        """What the setting may hold, in one phrase: 'a number > 0 (mm)', 'one of dp, greedy'."""
        if self.type is bool or (self.decl.choices and typing.get_origin(self.type) is not tuple):
            return self.limits()
        text = f"{'an' if self.type is int else 'a'} {self.type_name()}"
        if self.type is float and not self.decl.finite:
            text += ", inf or nan"
        limits = self.limits()
        if limits:
            text += (", " if typing.get_origin(self.type) is tuple else " ") + limits
        return text + (f" ({self.decl.unit})" if self.decl.unit else "")

    def check(self, value: Any, origin: str) -> Any:
        """``value`` as stored (ints given for floats become floats), or ConfigError."""
        ok, stored = self._convert(value)
        if not ok:
            raise ConfigError(f"{origin}: '{self.key}' must be {self.allowed()}; got {_literal(value)}.")
        return stored

    def _convert(self, value: Any) -> tuple[bool, Any]:
        d = self.decl
        origin = typing.get_origin(self.type)
        if origin is tuple:
            element = typing.get_args(self.type)[0]
            if not isinstance(value, list) or not all(_is(x, element) for x in value):
                return False, value
            if d.choices and any(x not in d.choices for x in value):
                return False, value
            if len(value) < d.min_items or (d.max_items is not None and len(value) > d.max_items):
                return False, value
            return True, [float(x) if element is float else x for x in value]
        if origin is not None:  # Mapping[str, str]
            ok = isinstance(value, dict) and all(isinstance(v, str) for v in value.values())
            return ok, value
        if not _is(value, self.type):
            return False, value
        if self.type is float:
            value = float(value)
            if not math.isfinite(value):
                return not d.finite, value
        if self.type in (int, float):
            if ((d.ge is not None and not value >= d.ge) or (d.gt is not None and not value > d.gt)
                    or (d.le is not None and not value <= d.le) or (d.lt is not None and not value < d.lt)):
                return False, value
        if d.choices and value not in d.choices:
            return False, value
        return True, value


def _is(value: Any, kind: type) -> bool:
    """Whether a TOML value has the Python type ``kind`` (an integer is also a float; a bool is no number)."""
    if isinstance(value, bool):
        return kind is bool
    if kind is float:
        return isinstance(value, (int, float))
    return isinstance(value, kind)


def _number(v: float) -> str:
    return str(int(v)) if float(v).is_integer() else repr(v)


def _literal(value: Any) -> str:
    """``value`` written as in TOML, for messages."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            return str(value)  # nan, inf, -inf: as TOML writes them
        text = repr(value)
        whole = text.lstrip("-")[:-2]
        if text.endswith(".0") and len(whole) > 6:  # 1000000000.0 -> 1.0e9
            digits = whole.rstrip("0")
            text = f"{'-' if value < 0 else ''}{digits[0]}.{digits[1:] or '0'}e{len(whole) - 1}"
        return text
    if isinstance(value, list):
        return "[" + ", ".join(_literal(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{k} = {_literal(v)}" for k, v in value.items()) + " }"
    return str(value)


def member_sections() -> dict[str, tuple[type, Mapping[str, Any]]]:
    """The settings sections members of the method family bring that facesynth does not declare
    above: {section: (its settings dataclass, its default values)}, from the registrations' facts
    ``settings`` (the section's name), ``settings_type`` and ``settings_defaults`` (a member
    outside facesynth: a plug-in's, a test's toy). A member whose section is one of
    :data:`SECTIONS` names it alone."""
    out: dict[str, tuple[type, Mapping[str, Any]]] = {}
    for e in METHODS.entries():
        section = e.facts.get("settings")
        if section and section not in SECTIONS:
            out[section] = (e.facts["settings_type"], e.facts.get("settings_defaults", {}))
    return out


def sections() -> dict[str, type]:
    """Every settings section, :data:`SECTIONS` then the members' own (:func:`member_sections`)."""
    return {**SECTIONS, **{name: cls for name, (cls, _) in member_sections().items()}}


def _declared(section: str, cls: type) -> dict[str, Declared]:
    hints = typing.get_type_hints(cls)
    return {f.name: Declared(section, f.name, hints[f.name], f.metadata["setting"]) for f in dataclasses.fields(cls)}


class _Declarations(Mapping):
    """Every setting's declaration, by section and key: :data:`SECTIONS`' built once, the members'
    own sections (:func:`member_sections`) as registered when asked."""

    def __init__(self) -> None:
        self._fixed = {section: _declared(section, cls) for section, cls in SECTIONS.items()}

    def _all(self) -> dict[str, dict[str, Declared]]:
        extra = {name: _declared(name, cls) for name, (cls, _) in member_sections().items()}
        return {**self._fixed, **extra} if extra else self._fixed

    def __getitem__(self, section: str) -> dict[str, Declared]:
        if section in self._fixed:
            return self._fixed[section]
        return self._all()[section]

    def __iter__(self):
        return iter(self._all())

    def __len__(self) -> int:
        return len(self._all())


#: Every setting's declaration, by section and key (from the dataclasses above and the members' sections).
DECLARATIONS: Mapping[str, Mapping[str, Declared]] = _Declarations()


def choices(section: str, name: str) -> tuple[str, ...]:
    """The allowed values of a choice setting, e.g. for a click option's ``click.Choice``."""
    found = DECLARATIONS[section][name].decl.choices
    if not found:
        raise KeyError(f"{section}.{name} is not a choice setting")
    return found


def _read_toml(path: Path) -> dict[str, Any]:
    try:
        with open(path, "rb") as fh:
            return tomllib.load(fh)
    except FileNotFoundError:
        raise ConfigError(f"{path}: configuration file not found; check the --config path.") from None
    except tomllib.TOMLDecodeError as exc:
        raise ConfigError(f"{path}: not valid TOML ({exc}); fix the file.") from None
    except UnicodeDecodeError as exc:
        raise ConfigError(f"{path}: byte {exc.start} is not UTF-8 text; save the file as UTF-8.") from None
    except IsADirectoryError:
        raise ConfigError(f"{path}: is a folder; give a TOML file to --config.") from None


def default_config() -> dict[str, dict[str, Any]]:
    """The packaged defaults, ``configs/default.toml``, as nested dicts (not yet checked)."""
    text = resources.files("facesynth").joinpath(DEFAULTS_NAME).read_text("utf-8")
    data = tomllib.loads(text)
    for section, (_, defaults) in member_sections().items():
        data.setdefault(section, dict(defaults))
    return data


def parse_override(item: str) -> tuple[str, str, Any]:
    """``(section, key, value)`` of one ``--set section.key=value``; a bare word is a string.
    Raises OverrideError when ``item`` has no ``section.key=`` part."""
    if "=" not in item or "." not in item.split("=", 1)[0]:
        raise OverrideError(f"--set {item!r}: expected section.key=value, e.g. --set pca.n_components=20.")
    key, raw = item.split("=", 1)
    section, name = key.strip().split(".", 1)
    try:
        value = tomllib.loads(f"v = {raw}")["v"]
    except tomllib.TOMLDecodeError:
        value = raw  # a bare word is a string: --set synthesize.method=greedy
    return section, name, value


def _apply(data: dict[str, dict[str, Any]], layer: dict[str, Any], origin: str) -> None:
    """Check every value of ``layer`` against its declaration and put it into ``data``."""
    for section, values in layer.items():
        if section not in DECLARATIONS:
            known = ", ".join(DECLARATIONS)
            raise ConfigError(f"{origin}: unknown section [{section}]; the sections are {known}.")
        if not isinstance(values, dict):
            raise ConfigError(f"{origin}: [{section}] must be a table of settings; got {_literal(values)}.")
        declared = DECLARATIONS[section]
        for name, value in values.items():
            if name not in declared:
                raise ConfigError(f"{origin}: unknown key '{section}.{name}'; the keys of [{section}] are "
                                  f"{', '.join(declared)}.")
            data.setdefault(section, {})[name] = declared[name].check(value, origin)


class Config:
    """The resolved, checked configuration: defaults, then a file, then ``--set`` overrides."""

    def __init__(self, data: dict[str, dict[str, Any]], reads: tuple[str, ...] | None = None,
                 given: frozenset[str] = frozenset()):
        self._data = data
        self._reads = reads
        self._given = given

    def only(self, reads: tuple[str, ...]) -> "Config":
        """The same values, of which :meth:`settings` hands out only the sections ``reads``
        (the command line's declaration of what a command reads, kept true by this guard)."""
        return Config(self._data, tuple(reads), self._given)

    def given(self, key: str) -> bool:
        """Whether ``section.key`` was given by a ``--config`` file or a ``--set`` (not the default):
        a deprecated name warns only then."""
        return key in self._given

    @classmethod
    def load(cls, path: Path | None = None, overrides: tuple[str, ...] = ()) -> "Config":
        """Read and check the defaults, the file at ``path`` and each ``section.key=value`` of
        ``overrides``, in that order. Raises ConfigError naming the origin, key and allowed values
        (OverrideError, bad usage, for an override)."""
        data: dict[str, dict[str, Any]] = {}
        _apply(data, default_config(), DEFAULTS_NAME)
        for section, declared in DECLARATIONS.items():
            lacking = [name for name in declared if name not in data.get(section, {})]
            if lacking:
                raise ConfigError(f"{DEFAULTS_NAME}: no default for '{section}.{lacking[0]}'; every setting needs one.")
        given: set[str] = set()
        if path is not None:
            layer = _read_toml(Path(path))
            _apply(data, layer, str(path))
            given |= {f"{section}.{name}" for section, values in layer.items() for name in values}
        for item in overrides:
            section, name, value = parse_override(item)
            try:
                _apply(data, {section: {name: value}}, f"--set {item}")
            except ConfigError as exc:
                raise OverrideError(str(exc)) from None
            given.add(f"{section}.{name}")
        return cls(data, given=frozenset(given))

    def settings(self, section: str, cls: type[S] | None = None) -> S:
        """The section as its frozen dataclass (lists become tuples)."""
        if self._reads is not None and section not in self._reads:
            # A programming error, not the user's: the command reads a section it does not declare.
            raise RuntimeError(f"[{section}] is not among the sections this command declares ({', '.join(self._reads)}); "
                               "add it to the reads of its Stage in facesynth/base/pipeline.py")
        cls = cls or sections()[section]
        values = {}
        for field in dataclasses.fields(cls):
            value = self._data[section][field.name]
            values[field.name] = tuple(value) if isinstance(value, list) else value
        return cls(**values)


def settings_json(settings: Any) -> str:
    """JSON of a settings dataclass, stored as the ``config`` attribute of artifacts."""
    def plain(v):
        if isinstance(v, tuple):
            return [plain(x) for x in v]
        if isinstance(v, Mapping):
            return {k: plain(x) for k, x in v.items()}
        return v
    return json.dumps({k: plain(v) for k, v in dataclasses.asdict(settings).items()}, sort_keys=True)


def reference_markdown() -> str:
    """The settings reference (``docs/configuration.md``), made from the declarations and the defaults."""
    defaults = default_config()
    lines = [
        "# Configuration reference",
        "",
        "<!-- Made by `python -m facesynth.base.config > docs/configuration.md` from the declarations in",
        "facesynth/base/config.py and the defaults in configs/default.toml; a test checks it is current. -->",
        "",
        "Every setting, with its type and allowed values, unit, default and source. \"Paper\" is",
        "Deng & Neumann (2008); equation, table and section numbers refer to it. The comments in",
        "[`configs/default.toml`](../configs/default.toml) say what each setting does. Precedence:",
        "defaults < `--config FILE` < `--set section.key=value`. Every value, the defaults included,",
        "is checked when the configuration is loaded: an unknown section or key, a wrong type, a",
        "number out of range (NaN and infinity included) or an unknown choice stops the command",
        "with one sentence naming the key and what is allowed: exit status 1 for the defaults or a",
        "`--config` file, 2 (bad usage) for a `--set`. A `--set` must name a section the command",
        "reads (the message names the commands that read it); a `--config` file may hold sections",
        "of other commands, so one file can serve the whole pipeline, and those are checked too.",
    ]
    for section, declared in DECLARATIONS.items():
        lines += ["", f"## [{section}]", "", "| key | type | allowed | unit | default | source |",
                  "|---|---|---|---|---|---|"]
        for name, d in declared.items():
            cells = [f"`{name}`", d.type_name(), d.limits() or "any", d.decl.unit or "—",
                     f"`{_literal(defaults[section][name])}`", d.decl.source]
            lines.append("| " + " | ".join(c.replace("|", "\\|") for c in cells) + " |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":  # pragma: no cover
    print(reference_markdown(), end="")
