"""Synthesized motion against ground truth (paper VI-D, VIII), with fair baselines and
bootstrap intervals.

Every held-out take of the corpus (``evaluate.split``) is synthesized from its own phone
timing and emotion, with no constraints, and compared at the capture rate with

* its **capture** (noisy markers), normalized with the database's own reference frame
  (Eq. 1-2), so both are in the same head frame: ``err_mm2`` (Eq. 13), ``total_err_mm2``
  (Eq. 12), ``rms_mm``, ``velocity_rms_mm_s``;
* where the corpus has it (the sample corpus's ``groundtruth/<take>.c3d``, given as the
  ``truth`` folder), its **clean ground truth**: markers without noise, gaps or head motion,
  in the rig's head frame, moved into the database's normalized head frame by one rigid
  transform fitted on the rigid (head-pose) markers of ``markers.csv`` against the
  database's reference (:func:`facesynth.domain.evaluation.baselines.fit_rigid`). Against it:
  ``rms_clean_mm``, ``velocity_rms_clean_mm_s``, the mouth-opening Pearson r (inner-lip gap
  of ``lip_markers``), and lip-closure timing.

Methods, each given the same phone timing (and emotions): the members of the method family
named by ``evaluate.methods`` (:mod:`facesynth.domain.methods`; ``dp`` always), each from its
evaluation source (:meth:`~facesynth.domain.methods.Method.evaluation_source`: the database, a model
given with ``--model`` or one fitted now), synthesized through the shared core
(:func:`facesynth.domain.methods.steps.synthesize`) and scored under its own name, each followed by
the variants it declares (:meth:`~facesynth.domain.methods.Method.ablations`):

* ``dp``: the paper's search; ``greedy``: Cao et al.'s greedy search on the same database and
  cost terms;
* ``trajectory``: Huang et al.'s compact key-shape trajectory model (:mod:`facesynth.domain.methods.trajectory`),
  when a model fitted on the same database is given (``facesynth evaluate --model``): the
  smooth path of Eq. 6-7 through per-(phone, emotion) Gaussians of key-shape weights, scored at
  phone boundaries like the other non-search methods;
* ``coarticulation``: a Cohen-Massaro coarticulation model per (phone, emotion) fitted on the
  database's training takes (``evaluate.dominance_iterations``) or given; ``coarticulation_per_phone``:
  the same per phone (:mod:`facesynth.domain.methods.coarticulation`);
* ``mean``: the mean pose per (phone, emotion) placed at each phone's centre and interpolated
  linearly, the rest pose in pauses; ``mean_per_phone``: the same with the per-phoneme mean pose
  (:mod:`facesynth.domain.methods.mean`);
* ``openfacefx``: the external text-driven system (:mod:`facesynth.domain.evaluation.baselines`), its ARKit
  curves through the corpus's face rig to the markers (only with the ``truth`` folder, which
  holds ``markers.csv``, and when openfacefx is installed; otherwise the report says why not);
* references, not methods: ``capture`` (the normalized noisy capture itself, scored against
  the clean truth) and ``clean`` (the clean truth itself: its closure, join and emotion figures
  are what a perfect method would get).

Figures (:data:`FIGURES`), each with a bootstrap 95% interval over sentences
(:mod:`facesynth.domain.evaluation.bootstrap`), and for every baseline the paired difference ``dp - baseline``:

* lip closure as **timing**: for each /p b m/ token, the first frame inside the phone where
  the inner-lip gap gets below ``closure_mm`` (its onset, s after the phone's start) or none;
  ``closure_rate`` is the fraction of tokens closed, ``closure_delay_ms`` the mean absolute
  difference of onsets from the clean truth's over tokens both close. The rates at 0.5x, 1x,
  2x and 4x ``closure_mm`` are in the JSON (``closure_sweep``) to show where methods separate;
* **join smoothness**: the 99th percentile of the second difference |x[f+1] - 2 x[f] + x[f-1]|
  (mm/frame^2, every marker) at the two frames around each join: the non-captured joins of
  ``dp`` and ``greedy``, the phone boundaries of the other methods and of the clean capture;
  beside it the same percentile at the frames away from joins (``interior_d2_p99``), since the
  noise a method copies from the capture raises both: a pop is a join value well above the
  method's own interior value, and above the clean capture's;
* **emotion recognisability**: a logistic regression on the database's PCA coefficients
  (standardized), trained on captured frames of the training takes with their node's emotion
  (:class:`EmotionClassifier`), applied to every frame of each method's output; the accuracy is
  the fraction of frames classified as the emotion asked for. On the held-out capture it is
  the recognisability of real motion.
* ``emotion_agreement``: the fraction of spoken phones whose node has the asked emotion;
  ``non_captured_joins``: joins of nodes that were not captured together (search methods).

The report ends with one sentence recommending a method for the database (:func:`recommend`),
drawn from the paired bootstrap intervals of the RMS error (against the clean truth where there
is one) between the lowest method and each other.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from facesynth.base.config import EvaluateSettings, NormalizeSettings, SynthesizeSettings
from facesynth.base.errors import InputError
from facesynth.base.phonemes import PAU
from facesynth.base.progress import progress
from facesynth.base.registry import METHODS
from facesynth.domain.geometry.rigid import choose_rigid, fill_gaps, head_pose
from facesynth.domain.methods import Method, MethodSettings, NotEvaluable, names, steps
from facesynth.domain.methods import get as get_method
from facesynth.domain.postprocess.concatenation import frame_ranges
from facesynth.domain.rig.face import load_face_rig
from facesynth.domain.speech.loudness import lip_gaps
from facesynth.domain.speech.utterance import Utterance, utterance
from facesynth.formats.mesh import read_binding, read_rigid_markers
from facesynth.formats.mocap import read_c3d
from facesynth.model.corpus import Corpus
from facesynth.model.motiondb import MotionDatabase

from .baselines import fit_rigid, openfacefx_arkit, openfacefx_missing, rig_markers
from .bootstrap import (
    ResampledStatistic,
    Statistic,
    interval,
    paired_difference,
    pooled_means,
    pooled_percentile,
    resamples,
)

BILABIALS = ("p", "b", "m")


#: Multiples of ``closure_mm`` at which the closure rate is also reported (``closure_sweep``).
CLOSURE_SWEEP = (0.5, 1.0, 2.0, 4.0)
#: The percentile of the second difference at joins (join smoothness).
JOIN_PERCENTILE = 99.0
#: The references scored beside the methods.
REFERENCES = ("capture", "clean")
#: Rows of reports written before each row took its member's name: old name -> name now. A
#: metrics.json of such a report reads with :func:`current_rows`.
OLD_ROWS = {"baseline_emotion": "mean", "baseline": "mean_per_phone", "dominance_emotion": "coarticulation",
            "dominance": "coarticulation_per_phone"}


def current_rows(metrics: dict) -> dict:
    """``metrics`` (a report's metrics.json, by row) with the rows of earlier reports under their
    names now (:data:`OLD_ROWS`); a report of this version comes back as it is."""
    return {OLD_ROWS.get(row, row): value for row, value in metrics.items()}


def searches(name: str) -> bool:
    """Whether the member searches motion nodes (its joins are the non-captured ones)."""
    return bool(METHODS.entry(name).facts.get("searches")) if name in METHODS else False


def simplest_first() -> tuple[str, ...]:
    """Members from the simplest and fastest to the most elaborate (registration's ``simplicity``):
    among tied methods the recommendation prefers the first (no fitting and a closed form; fitted,
    closed form; fitted, a banded solve; searches)."""
    return tuple(e.name for e in sorted(METHODS.entries(), key=lambda e: e.facts.get("simplicity", 99)))


@dataclass
class Sentence:
    """A held-out take: its utterance (phones, times, emotion) and its normalized capture,
    truth : (T, M, 3) float32 mm in the head frame at the capture rate. With a truth folder:
    clean : (T, M, 3) float32 mm, the clean markers in the same normalized head frame, and
    to_reference : (R (3, 3), t (3,) mm) taking the rig's head frame there (x @ R + t)."""

    take: str
    emotion: str
    utterance: Utterance
    truth: np.ndarray
    clean: np.ndarray | None = None
    to_reference: tuple[np.ndarray, np.ndarray] | None = None


def normalized_take(raw: np.ndarray, db: MotionDatabase, settings: NormalizeSettings, corpus_rigid=()):
    """One take's captured markers (T, M, 3) mm, gaps filled and aligned to the database's
    reference frame as ``normalize`` does (weighted Procrustes on the rigid markers:
    the settings', else ``corpus_rigid``, else those found from this take's data). Returns markers
    (T, M, 3), rotations (T, 3, 3), translations (T, 3) mm."""
    names = db.marker_names
    raw = raw.astype(np.float64)
    for m in range(raw.shape[1]):
        raw[:, m], _ = fill_gaps(raw[:, m], settings.max_gap_frames)
    rigid = choose_rigid(names, settings.rigid_markers, [n for n in corpus_rigid if n in names], raw,
                         max_spread_mm=settings.rigid_max_spread_mm, min_markers=settings.rigid_min_markers)
    return head_pose(raw, db.reference.astype(np.float64), rigid.indices)[:3]


@dataclass
class TruthFolder:
    """A corpus folder with clean ground truth (the sample corpus's layout): ``groundtruth/<take>.c3d``
    clean markers in the rig's head frame, ``markers.csv`` the marker-to-vertex binding with its
    ``rigid`` column. rigid : names of the head-pose markers the frame transform is fitted on."""

    folder: Path
    binding: dict[str, int]
    rigid: list[str]

    @classmethod
    def open(cls, folder: Path, names: list[str], normalize_settings: NormalizeSettings) -> "TruthFolder":
        """Check the folder (one sentence naming what is missing) and read its binding."""
        folder = Path(folder)
        if not (folder / "groundtruth").is_dir() or not (folder / "markers.csv").exists():
            raise InputError(f"{folder}: not a corpus folder with ground truth (it needs groundtruth/ and markers.csv); "
                             "pass the folder facesynth sample-corpus wrote.")
        binding = read_binding(folder / "markers.csv")
        missing = [n for n in names if n not in binding]
        if missing:
            raise InputError(f"{folder / 'markers.csv'}: marker {missing[0]!r} of the database is not bound; "
                             "pass the truth folder of the corpus the database was built from.")
        rigid = read_rigid_markers(folder / "markers.csv") or list(normalize_settings.rigid_markers) or list(names)
        return cls(folder, binding, [n for n in rigid if n in names])

    def clean(self, take: str, names: list[str], reference: np.ndarray) -> tuple[np.ndarray, tuple[np.ndarray, np.ndarray]]:
        """A take's clean markers (T, M, 3) float32 mm in the normalized head frame of ``reference``
        (M, 3), and the transform (R, t) from the rig's head frame (fitted on the rigid markers'
        mean position over the take against the reference: the clean head does not move)."""
        path = self.folder / "groundtruth" / f"{take}.c3d"
        if not path.exists():
            raise InputError(f"{path}: no clean ground truth for take {take!r}; pass the truth folder of this corpus.")
        take_markers = read_c3d(path)
        where = {n: i for i, n in enumerate(take_markers.names)}
        if any(n not in where for n in names):
            raise InputError(f"{path}: marker {next(n for n in names if n not in where)!r} is missing; regenerate the corpus.")
        clean = take_markers.positions[:, [where[n] for n in names]].astype(np.float64)
        rigid = [names.index(n) for n in self.rigid]
        r, t = fit_rigid(np.nanmean(clean[:, rigid], axis=0), reference[rigid].astype(np.float64))
        return (clean @ r + t).astype(np.float32), (r, t)

    def vertices(self, names: list[str]) -> np.ndarray:
        """(M,) the rig vertices of the markers ``names``."""
        return np.array([self.binding[n] for n in names])


def heldout(corpus_path: Path, db: MotionDatabase, split: str, normalize_settings: NormalizeSettings,
            truth: TruthFolder | None = None) -> list[Sentence]:
    """The corpus's takes of ``split`` with their phones and normalized capture (and, with
    ``truth``, their clean markers in the same frame)."""
    corpus = Corpus.read(corpus_path, audio=False)
    corpus.check_markers(db.marker_names, corpus_path)
    takes, phones = corpus.takes, corpus.phones
    phone_emotion = phones.emotions(takes)
    rows = [i for i in range(len(takes)) if takes.split[i] == split]
    if not rows:
        raise InputError(f"{corpus_path}: no take has split '{split}'; mark held-out takes in the manifest's split column.")
    out = []
    for i in rows:
        captured, _, _ = normalized_take(corpus.markers[takes.frames(i)], db, normalize_settings, corpus.rigid_markers)
        seg = np.nonzero(phones.take == i)[0]
        utt = utterance([phones.phone[r] for r in seg], phones.start[seg], phones.end[seg], [phone_emotion[r] for r in seg])
        s = Sentence(takes.name[i], takes.emotion[i], utt, captured.astype(np.float32))
        if truth is not None:
            s.clean, s.to_reference = truth.clean(takes.name[i], db.marker_names, db.reference)
        out.append(s)
    return out


def openfacefx_baseline(db: MotionDatabase, utt: Utterance, rig, vertices: np.ndarray,
                        to_reference: tuple[np.ndarray, np.ndarray]) -> np.ndarray:
    """openfacefx from the utterance's phone timing, through the rig to the markers (``vertices``)
    and into the normalized head frame with ``to_reference`` (R, t): (T, M, 3) float32 mm."""
    total = frame_ranges(utt.starts, utt.ends, db.fps)[-1][1]
    arkit = openfacefx_arkit(utt.phones, utt.starts, utt.ends, total, db.fps, rig.arkit_names)
    r, t = to_reference
    return (rig_markers(rig, arkit, vertices) @ r + t).astype(np.float32)


def bilabial_frames(utt: Utterance, fps: float, n: int) -> list[tuple[int, int]]:
    """Frames [a, b) (within the first ``n``) of each /p b m/ token of the utterance, at least one frame each."""
    out = []
    for a, b, p in zip(utt.starts, utt.ends, utt.phones):
        if p in BILABIALS:
            fa = int(round(a * fps))
            fb = min(max(int(round(b * fps)), fa + 1), n)
            if fb > fa:
                out.append((fa, fb))
    return out


def closure_onsets(gap: np.ndarray, tokens: list[tuple[int, int]], fps: float, threshold_mm: float) -> np.ndarray:
    """Closure timing: per token (frames [a, b)), the time (s) from the phone's first frame to the
    first frame whose lip gap ``gap`` (T,) mm is below ``threshold_mm``; NaN when it never is.
    (B,) float64."""
    out = np.full(len(tokens), np.nan)
    for k, (a, b) in enumerate(tokens):
        below = np.nonzero(gap[a:b] < threshold_mm)[0]
        if len(below):
            out[k] = below[0] / fps
    return out


def second_differences(markers: np.ndarray, joins: np.ndarray) -> np.ndarray:
    """|x[f+1] - 2 x[f] + x[f-1]| (mm/frame^2) of every marker at the two frames f = j-1, j around
    each join j (the first frame after it) of ``markers`` (T, M, 3) mm; (n,) float64, flat."""
    x = markers.astype(np.float64)
    frames = np.unique(np.concatenate([np.asarray(joins) - 1, np.asarray(joins)]).astype(int)) if len(joins) else np.zeros(0, int)
    frames = frames[(frames >= 1) & (frames <= len(x) - 2)]
    d2 = x[frames + 1] - 2 * x[frames] + x[frames - 1]
    values = np.linalg.norm(d2, axis=2).ravel()
    return values[np.isfinite(values)]


def away_from(n: int, joins: np.ndarray) -> np.ndarray:
    """The frames 1..n-2 that are not within one frame of a join (the interior frames whose
    second difference measures the motion itself, noise included): (K,) int64."""
    keep = np.ones(n, bool)
    keep[[0, n - 1]] = False
    for j in np.asarray(joins, int):
        keep[max(0, j - 1):j + 1] = False
    return np.nonzero(keep)[0]


def interior_second_differences(markers: np.ndarray, joins: np.ndarray) -> np.ndarray:
    """|x[f+1] - 2 x[f] + x[f-1]| (mm/frame^2) of every marker at the frames :func:`away_from`
    the joins: the level a join's value is compared with. (n,) float64, flat."""
    x = markers.astype(np.float64)
    if len(x) < 3:
        return np.zeros(0)
    f = away_from(len(x), joins)
    values = np.linalg.norm(x[f + 1] - 2 * x[f] + x[f - 1], axis=2).ravel()
    return values[np.isfinite(values)]


def phone_boundaries(utt: Utterance, fps: float) -> np.ndarray:
    """The first frame of every spoken phone that follows a spoken phone: (J,) int64."""
    ranges = frame_ranges(utt.starts, utt.ends, fps)
    return np.array([ranges[t + 1][0] for t in range(len(ranges) - 1)
                     if utt.phones[t] != PAU and utt.phones[t + 1] != PAU], np.int64)


def search_joins(db: MotionDatabase, utt: Utterance, path: np.ndarray) -> np.ndarray:
    """The first frame after each non-captured join of a search's node ``path``: (J,) int64."""
    ranges = frame_ranges(utt.starts, utt.ends, db.fps)
    return np.array([ranges[t + 1][0] for t in range(len(path) - 1)
                     if utt.phones[t] != PAU and utt.phones[t + 1] != PAU and db.nodes.pre[path[t + 1]] != path[t]], np.int64)


def frame_emotions(utt: Utterance, fps: float, n: int) -> np.ndarray:
    """The asked emotion of each of the first ``n`` frames (its phone's): (n,) str."""
    out = np.full(n, utt.emotions[0], dtype=object)
    for (a, b), e in zip(frame_ranges(utt.starts, utt.ends, fps), utt.emotions):
        out[a:min(b, n)] = e
    return out


class EmotionClassifier:
    """Per-frame emotion from a face pose: standardized PCA coefficients of the database's model
    -> multinomial logistic regression, trained on at most ``frames`` captured frames of the
    database's (training) takes, each labelled with its node's emotion."""

    def __init__(self, db: MotionDatabase, frames: int, seed: int):
        from sklearn.linear_model import LogisticRegression
        from sklearn.pipeline import make_pipeline
        from sklearn.preprocessing import StandardScaler

        nodes = db.nodes
        rows = np.concatenate([np.arange(nodes.frame_start[k], nodes.frame_start[k] + nodes.frame_count[k]) for k in range(len(nodes.phone))])
        labels = np.concatenate([[nodes.emotion[k]] * int(nodes.frame_count[k]) for k in range(len(nodes.phone))])
        rows, keep = np.unique(rows, return_index=True)  # overlapping nodes share frames
        labels = labels[keep]
        if len(rows) > frames:
            pick = np.sort(np.random.default_rng(seed).choice(len(rows), frames, replace=False))
            rows, labels = rows[pick], labels[pick]
        self.model = db.model
        self.emotions = sorted(set(labels.tolist()))
        self.pipeline = make_pipeline(StandardScaler(), LogisticRegression(max_iter=2000))
        self.pipeline.fit(db.coeffs[rows].astype(np.float64), labels)

    def predict(self, markers: np.ndarray) -> np.ndarray:
        """The emotion of each frame of ``markers`` (T, M, 3) mm in the normalized head frame: (T,) str."""
        coeffs = self.model.project(markers).astype(np.float64)
        return self.pipeline.predict(np.nan_to_num(coeffs))


@dataclass(frozen=True)
class SentenceMetrics:
    """Metrics of one sentence against its (noisy) capture (:func:`sentence_metrics`).

    frames: frames compared (the shorter of the two, at the capture rate).
    err_mm2: Eq. 13, the mean over frames of the summed squared marker distance (mm^2), over the
        marker samples the capture has.
    rms_mm: its square root (mm).
    velocity_rms_mm_s: RMS of the velocity error (mm/s).
    bilabials: /p b m/ tokens the capture sees the lips in.
    lip_closure_rate, lip_closure_rate_capture: the fraction of those tokens whose smallest lip gap
        is below ``evaluate.closure_mm`` in the synthesis and in the capture; None without tokens.
    min_lip_gap_mm: the synthesis's smallest lip gap on a token, mean over tokens (mm); None
        without tokens.
    """

    frames: int
    err_mm2: float
    rms_mm: float
    velocity_rms_mm_s: float
    bilabials: int
    lip_closure_rate: float | None
    lip_closure_rate_capture: float | None
    min_lip_gap_mm: float | None

    def row(self) -> dict[str, Any]:
        """The fields as a per-sentence row of the report (``metrics.json``'s ``per_sentence``)."""
        return {"frames": self.frames, "err_mm2": self.err_mm2, "rms_mm": self.rms_mm,
                "velocity_rms_mm_s": self.velocity_rms_mm_s, "bilabials": self.bilabials,
                "lip_closure_rate": self.lip_closure_rate, "lip_closure_rate_capture": self.lip_closure_rate_capture,
                "min_lip_gap_mm": self.min_lip_gap_mm}


def sentence_metrics(syn: np.ndarray, truth: np.ndarray, utt: Utterance, fps: float, names: list[str],
                     settings: EvaluateSettings) -> SentenceMetrics:
    """Metrics of one sentence: synthesized ``syn`` against captured ``truth`` (both (T, M, 3) mm at
    ``fps``): Eq. 13 error (mm^2) and its root, velocity RMS (mm/s), and lip closure on /p b m/.
    """
    n = min(len(syn), len(truth))
    syn, truth = syn[:n].astype(np.float64), truth[:n].astype(np.float64)
    # Eq. 13 over the marker samples the capture has (a long gap leaves NaN in the truth).
    err = float(np.nanmean(np.sum((syn - truth) ** 2, axis=2)))
    vel = (np.diff(syn, axis=0) - np.diff(truth, axis=0)) * fps
    gaps_syn = lip_gaps(syn, names, settings.lip_markers)
    gaps_true = lip_gaps(truth, names, settings.lip_markers)
    closures = []
    for fa, fb in bilabial_frames(utt, fps, n):
        if not np.isnan(gaps_true[fa:fb]).all():
            closures.append((gaps_syn[fa:fb].min(), np.nanmin(gaps_true[fa:fb])))
    closures = np.array(closures).reshape(-1, 2)
    return SentenceMetrics(
        n, err, float(np.sqrt(err)), float(np.sqrt(np.nanmean(np.sum(vel**2, axis=2)))), len(closures),
        float((closures[:, 0] < settings.closure_mm).mean()) if len(closures) else None,
        float((closures[:, 1] < settings.closure_mm).mean()) if len(closures) else None,
        float(closures[:, 0].mean()) if len(closures) else None,
    )


@dataclass(frozen=True)
class CleanMetrics:
    """Metrics of one sentence against its clean truth (:func:`clean_metrics`).

    err_clean_mm2: Eq. 13 against the clean truth (mm^2).
    velocity_ms_clean: mean squared velocity error (mm^2/s^2).
    mouth_r: Pearson r of the inner-lip gaps (NaN where either does not move).
    onsets, onsets_clean: (B,) float per /p b m/ token, the closure onset of the method and of the
        truth (s; NaN = no closure).
    sweep: (len(CLOSURE_SWEEP), B) bool, the method's closure flags at each :data:`CLOSURE_SWEEP`
        multiple of ``evaluate.closure_mm``.
    """

    err_clean_mm2: float
    velocity_ms_clean: float
    mouth_r: float
    onsets: np.ndarray
    onsets_clean: np.ndarray
    sweep: np.ndarray

    def row(self) -> dict[str, Any]:
        """The fields as keys of a per-sentence row: the arrays under ``_onsets``, ``_onsets_clean`` and
        ``_sweep`` (a leading '_' keeps a key out of ``metrics.json``)."""
        return {"err_clean_mm2": self.err_clean_mm2, "velocity_ms_clean": self.velocity_ms_clean,
                "mouth_r": self.mouth_r, "_onsets": self.onsets, "_onsets_clean": self.onsets_clean,
                "_sweep": self.sweep}


def clean_metrics(syn: np.ndarray, clean: np.ndarray, utt: Utterance, fps: float, names: list[str],
                  settings: EvaluateSettings) -> CleanMetrics:
    """Metrics of one sentence against its clean truth (both (T, M, 3) mm in the normalized head
    frame at ``fps``): Eq. 13, the velocity error, the inner-lip gaps' correlation and per /p b m/
    token the closure onsets (:class:`CleanMetrics`)."""
    n = min(len(syn), len(clean))
    syn, clean = syn[:n].astype(np.float64), clean[:n].astype(np.float64)
    vel = (np.diff(syn, axis=0) - np.diff(clean, axis=0)) * fps
    gap_syn, gap_clean = lip_gaps(syn, names, settings.lip_markers), lip_gaps(clean, names, settings.lip_markers)
    seen = np.isfinite(gap_syn) & np.isfinite(gap_clean)  # the noisy capture may keep a long gap
    a, b = gap_syn[seen], gap_clean[seen]
    r = float(np.corrcoef(a, b)[0, 1]) if len(a) > 2 and a.std() > 0 and b.std() > 0 else float("nan")
    tokens = bilabial_frames(utt, fps, n)
    return CleanMetrics(
        float(np.nanmean(np.sum((syn - clean) ** 2, axis=2))),
        float(np.nanmean(np.sum(vel**2, axis=2))),
        r,
        closure_onsets(gap_syn, tokens, fps, settings.closure_mm),
        closure_onsets(gap_clean, tokens, fps, settings.closure_mm),
        np.array([np.isfinite(closure_onsets(gap_syn, tokens, fps, k * settings.closure_mm)) for k in CLOSURE_SWEEP]).reshape(len(CLOSURE_SWEEP), len(tokens)),
    )


def aggregate(rows: list[dict]) -> dict:
    """Pool sentence metrics: Eq. 12 sums, frame-weighted means, pooled lip closures."""
    frames = np.array([r["frames"] for r in rows], float)
    out = {"sentences": len(rows), "total_err_mm2": float(sum(r["err_mm2"] for r in rows)),
           "err_mm2": float(np.mean([r["err_mm2"] for r in rows]))}
    out["rms_mm"] = float(np.sqrt(np.average([r["err_mm2"] for r in rows], weights=frames)))
    out["velocity_rms_mm_s"] = float(np.sqrt(np.average([r["velocity_rms_mm_s"] ** 2 for r in rows], weights=frames)))
    lips = [r for r in rows if r["bilabials"]]
    if lips:
        count = sum(r["bilabials"] for r in lips)
        for key in ("lip_closure_rate", "lip_closure_rate_capture", "min_lip_gap_mm"):
            out[key] = float(sum(r[key] * r["bilabials"] for r in lips) / count)
        out["bilabials"] = count
    for key in ("emotion_agreement", "non_captured_joins"):
        if all(key in r for r in rows):
            out[key] = float(np.mean([r[key] for r in rows])) if key == "emotion_agreement" else int(sum(r[key] for r in rows))
    return out


def _field(rows: list[dict], key: str) -> np.ndarray:
    """(n,) float: one per-sentence field of ``rows``."""
    return np.array([r[key] for r in rows], float)


def _weighted_root(key: str) -> Callable[[list[dict], np.ndarray], np.ndarray]:
    def stat(rows: list[dict], idx: np.ndarray) -> np.ndarray:
        w = _field(rows, "frames")[idx]
        return np.sqrt(np.sum(w * _field(rows, key)[idx], axis=-1) / np.sum(w, axis=-1))
    return stat


def _of_rows(stat: Callable[[list[dict], np.ndarray], np.ndarray]) -> Callable[[list[dict]], Statistic]:
    """A figure ``stat(rows, idx)`` as :data:`FIGURES` holds it: rows -> (idx -> float), computed on
    all resamples at once (:class:`~facesynth.domain.evaluation.bootstrap.ResampledStatistic`).
    ``stat`` takes a method's rows (one per sentence) and the sentence indices ``idx`` (..., n) of
    resamples, and returns the figure of each resample, shape (...) (NaN where undefined)."""
    return lambda rows: ResampledStatistic(lambda index: stat(rows, index))


def _mean_r(rows: list[dict], idx: np.ndarray) -> np.ndarray:
    values = _field(rows, "mouth_r")[idx]
    missing = np.isnan(values)
    count = np.sum(~missing, axis=-1)
    total = np.sum(np.where(missing, 0.0, values), axis=-1)  # np.nanmean's sum
    defined = np.isfinite(values).any(axis=-1)
    return np.divide(total, count, out=np.full(total.shape, np.nan), where=defined)


def _closure_rate(rows: list[dict], idx: np.ndarray) -> np.ndarray:
    return pooled_means([np.isfinite(r["_onsets"]).astype(float) for r in rows], idx)


def _closure_delay(rows: list[dict], idx: np.ndarray) -> np.ndarray:
    delays = []
    for r in rows:
        a, b = np.asarray(r["_onsets"], float), np.asarray(r["_onsets_clean"], float)
        both = np.isfinite(a) & np.isfinite(b)
        delays.append(np.abs(a[both] - b[both]))
    return 1000.0 * pooled_means(delays, idx)


def _join_p99(rows: list[dict]) -> Statistic:
    return pooled_percentile([r["_d2"] for r in rows], JOIN_PERCENTILE)


def _interior_p99(rows: list[dict]) -> Statistic:
    return pooled_percentile([r["_d2_interior"] for r in rows], JOIN_PERCENTILE)


def _emotion_accuracy(rows: list[dict], idx: np.ndarray) -> np.ndarray:
    correct = np.array([r["emotion_correct"] for r in rows], np.int64)[idx].sum(axis=-1)
    frames = np.array([r["frames"] for r in rows], np.int64)[idx].sum(axis=-1)
    return correct / np.maximum(1, frames)


#: key -> (label, statistic, needs the clean truth, lower is better). The statistic takes a
#: method's rows (one per sentence) and returns the figure of the sentences ``idx`` of a resample
#: (:data:`facesynth.domain.evaluation.bootstrap.Statistic`), prepared once for the thousands of resamples.
FIGURES: dict[str, tuple[str, Callable[[list[dict]], Statistic], bool, bool]] = {
    "rms_clean_mm": ("RMS vs clean truth (mm)", _of_rows(_weighted_root("err_clean_mm2")), True, True),
    "rms_mm": ("RMS vs noisy capture (mm)", _of_rows(_weighted_root("err_mm2")), False, True),
    "velocity_rms_clean_mm_s": ("velocity RMS error vs clean (mm/s)", _of_rows(_weighted_root("velocity_ms_clean")),
                                True, True),
    "mouth_r": ("mouth-opening Pearson r", _of_rows(_mean_r), True, False),
    "closure_rate": ("/p b m/ closed within the phone", _of_rows(_closure_rate), True, False),
    "closure_delay_ms": ("|closure onset - truth's| (ms)", _of_rows(_closure_delay), True, True),
    "join_d2_p99": ("join 2nd difference, 99th pct (mm/frame²)", _join_p99, False, True),
    "interior_d2_p99": ("2nd difference away from joins, 99th pct (mm/frame²)", _interior_p99, False, True),
    "emotion_accuracy": ("emotion recognised (frames)", _of_rows(_emotion_accuracy), False, False),
}


def figures(per_method: dict[str, list[dict]], settings: EvaluateSettings, with_clean: bool) -> dict:
    """Every :data:`FIGURES` entry per method with its bootstrap interval, the paired difference
    ``dp - method`` for every other method, and the closure sweep. Rows of all methods are the
    same sentences in the same order."""
    n = len(per_method["dp"])
    index = resamples(n, settings.bootstrap_resamples, settings.seed)
    out: dict = {}
    dp_statistics: dict[str, Statistic] = {}  # prepared once for every paired difference
    for method, rows in per_method.items():
        entry = {}
        for key, (_, figure, clean, _) in FIGURES.items():
            if (clean and not with_clean) or any(_needed(key) not in r for r in rows):
                continue
            stat = figure(rows)
            entry[key] = interval(stat, n, index)
            if method == "dp":
                dp_statistics[key] = stat
            elif method not in REFERENCES and key in out.get("dp", {}):
                entry[f"dp_minus.{key}"] = paired_difference(dp_statistics[key], stat, n, index)
        if with_clean and all("_sweep" in r for r in rows):
            sweep = np.concatenate([r["_sweep"] for r in rows], axis=1)
            entry["closure_sweep"] = {f"{k * settings.closure_mm:g}": (float(sweep[j].mean()) if sweep.shape[1] else None)
                                      for j, k in enumerate(CLOSURE_SWEEP)}
        out[method] = entry
    return out


def _needed(key: str) -> str:
    """The per-sentence field a figure is computed from."""
    return {"rms_clean_mm": "err_clean_mm2", "rms_mm": "err_mm2", "velocity_rms_clean_mm_s": "velocity_ms_clean",
            "mouth_r": "mouth_r", "closure_rate": "_onsets", "closure_delay_ms": "_onsets",
            "join_d2_p99": "_d2", "interior_d2_p99": "_d2_interior", "emotion_accuracy": "emotion_correct"}[key]


@dataclass
class Member:
    """A member of the method family as ``evaluate`` runs it: the method, its source (the
    database, or its model), the settings it runs with and the work prepared once for every sentence."""

    method: Method
    source: Any
    settings: MethodSettings
    prepared: Any = None


def method_outputs(db: MotionDatabase, s: Sentence, members: dict[str, Member],
                   ablations: Mapping[str, Callable[[Utterance], np.ndarray]], rig=None, vertices=None,
                   source_where: str = "the database") -> tuple[dict, dict]:
    """Every row's markers (T, M, 3) mm at the capture rate for one sentence, and per row its extra
    fields (search methods: emotion agreement, joins). ``members``: by name (the row), run through
    the shared core; ``ablations``: the members' variants, row -> utterance -> markers."""
    outputs, extra = {}, {}
    for name, m in members.items():
        result = steps.synthesize(m.method, m.source, s.utterance, m.settings, prepared=m.prepared,
                                  source_where=source_where, where=s.take)
        motion = result.motion
        outputs[name] = motion.markers_capture
        if searches(name):
            spoken = [k for k, p in enumerate(s.utterance.phones) if p != PAU]
            extra[name] = {"emotion_agreement": float(np.mean([motion.path.node_emotion[k] == s.utterance.emotions[k]
                                                               for k in spoken])),
                           "non_captured_joins": motion.path.non_captured_joins,
                           "joins": search_joins(db, s.utterance, motion.path.node)}
    for row, markers in ablations.items():
        outputs[row] = markers(s.utterance)
    if rig is not None:
        if s.to_reference is None:  # evaluate() passes the rig only with every sentence's clean truth
            raise ValueError(f"{s.take}: the openfacefx baseline needs the clean truth's head frame")
        outputs["openfacefx"] = openfacefx_baseline(db, s.utterance, rig, vertices, s.to_reference)
    return outputs, extra


@dataclass(frozen=True)
class Recommendation:
    """The method :func:`recommend` chose (a member's name; '' when no figure was computed), the
    figure it compared and the sentence that says why."""

    method: str
    figure: str
    sentence: str


def recommend(figures: dict[str, dict], row_of: dict[str, str] | None = None, difference=None) -> Recommendation:
    """One sentence recommending a method from the report's own bootstrap intervals.

    ``figures``: per row, its :data:`FIGURES` entries ({value, low, high}); ``row_of``: member ->
    row (default: every member under its name; members absent from ``figures`` ignored). The figure is the
    RMS error against the clean truth where computed, else against the noisy capture.
    ``difference(key, other_row, best_row)``: the paired bootstrap interval of ``other - best``
    on the same resamples ({value, low, high}); without it the methods' own intervals are compared.

    The method of the lowest value is recommended when it is lower than every other method beyond
    doubt: the paired interval of each other method minus it lies above 0 (or, without pairs, its
    own interval lies entirely below every other's). Otherwise the methods not told apart from it
    (a paired interval holding 0, an overlapping interval) are tied with it, and the simplest and
    fastest of them (:func:`simplest_first`) is recommended."""
    row_of = row_of if row_of is not None else {m: m for m in names()}
    present = {m: r for m, r in row_of.items() if r in figures}
    for key in ("rms_clean_mm", "rms_mm"):
        scored = {m: figures[r][key] for m, r in present.items()
                  if figures[r].get(key, {}).get("value") is not None and np.isfinite(figures[r][key]["value"])}
        if scored:
            break
    else:
        return Recommendation("", "", "No method could be recommended: no RMS figure was computed.")
    label = FIGURES[key][0].replace(" (mm)", "")
    order = sorted(scored, key=lambda m: scored[m]["value"])
    best = order[0]

    def bound(m: str, side: str) -> float:
        return scored[m][side] if scored[m].get(side) is not None else scored[m]["value"]

    def cell(m: str) -> str:
        return f"{scored[m]['value']:.3f} mm [{bound(m, 'low'):.3f}, {bound(m, 'high'):.3f}]"

    if len(order) == 1:
        return Recommendation(best, key, f"Recommended for this database: {best}, the only method scored "
                                         f"({label} {cell(best)}).")
    if difference is not None:
        paired = {m: difference(key, present[m], present[best]) for m in order[1:]}

        def apart(m: str) -> bool:
            return paired[m].get("low") is not None and paired[m]["low"] > 0

        def gap(m: str) -> str:
            d = paired[m]
            return f"{m} {d['value']:+.3f} mm [{d['low']:+.3f}, {d['high']:+.3f}]" if d.get("low") is not None else m
        how = "the paired 95% interval"
    else:
        def apart(m: str) -> bool:
            return bound(m, "low") > bound(best, "high")

        def gap(m: str) -> str:
            return f"{m} {cell(m)}"
        how = "its 95% interval"
    tied = [best] + [m for m in order[1:] if not apart(m)]
    if len(tied) == 1:
        return Recommendation(best, key, f"Recommended for this database: {best}, the lowest {label} "
                                         f"({cell(best)}); every other method is higher beyond {how} "
                                         f"(next: {gap(order[1])}).")
    rank = {m: k for k, m in enumerate(simplest_first())}
    choice = min(tied, key=lambda m: rank.get(m, len(rank)))
    others = ", ".join(gap(m) for m in tied if m != best)
    lowest = f"{best} has the lowest {label} ({cell(best)}), but {how} does not tell it from {others}"
    if choice == best:
        return Recommendation(choice, key, f"Recommended for this database: {choice}; {lowest}, and it is the "
                                           "simplest and fastest of these.")
    return Recommendation(choice, key, f"Recommended for this database: {choice}, the simplest and fastest of the "
                                       f"tied methods ({label} {cell(choice)}); {lowest}.")


def evaluate(db_path: Path, corpus: Path, settings: EvaluateSettings, synth: SynthesizeSettings | MethodSettings,
             normalize_settings: NormalizeSettings, sentences: list[Sentence] | None = None,
             db: MotionDatabase | None = None, tc=None, with_baseline: bool = True,
             truth: Path | None = None, models: Mapping[str, Any] | None = None) -> tuple[dict, list[dict]]:
    """Returns (metrics per row, per-sentence records with the curves to plot).

    The members of ``settings.methods`` (``dp`` always) are scored, each with the variants it
    declares (:meth:`~facesynth.domain.methods.Method.ablations`). ``synth``: the
    :class:`MethodSettings` (or ``[synthesize]`` alone: the packaged defaults for the members'
    sections). ``models``: member -> its model given for this database (read; the members'
    :meth:`~facesynth.domain.methods.Method.evaluation_source` fit one where none is given and
    they can). ``with_baseline=False`` evaluates
    the DP alone against the noisy capture (tune leaves the other methods and figures out of its
    many evaluations). ``truth``: a corpus folder with clean ground truth (:class:`TruthFolder`),
    which adds the clean-truth figures, the ``openfacefx`` baseline and the ``capture`` / ``clean``
    references. Metrics per row: ``overall``, ``per_emotion``, ``per_sentence``, and ``figures``
    (with intervals); under ``"_figures"`` the table's meta (labels, skipped methods and why, the
    :class:`Recommendation` as ``recommendation``)."""
    db = db or MotionDatabase.read(db_path)
    for name in tuple(settings.lip_markers) + (settings.plot_marker,):
        if name not in db.marker_names:
            raise InputError(f"evaluate: marker {name!r} is not in the database; set evaluate.lip_markers / evaluate.plot_marker to markers it has.")
    folder = TruthFolder.open(truth, db.marker_names, normalize_settings) if truth is not None else None
    sentences = sentences if sentences is not None else heldout(corpus, db, settings.split, normalize_settings, folder)
    with_clean = folder is not None and all(s.clean is not None for s in sentences)
    method_settings = synth if isinstance(synth, MethodSettings) else MethodSettings.packaged(synthesize=synth)
    wanted = ("dp",) + tuple(m for m in settings.methods if m != "dp") if with_baseline else ("dp",)
    skipped = {}
    members: dict[str, Member] = {}
    ablations: dict[str, Callable[[Utterance], np.ndarray]] = {}
    order: list[str] = []  # the rows: each member, then its variants
    for name in names():  # the report's order
        if name not in wanted:
            continue
        method = get_method(name)
        own = method.for_evaluation(method_settings, settings)
        try:
            source = method.evaluation_source(db, own, models or {}, str(db_path))
        except NotEvaluable as reason:
            skipped[name] = str(reason)
            continue
        shared = tc if tc is not None and searches(name) else None  # the caller's transition costs, for both searches
        members[name] = Member(method, source, own, shared if shared is not None else method.prepare(source, own))
        variants = method.ablations(db, own) if with_baseline else {}
        ablations.update(variants)
        order += [name, *variants]
    rig = vertices = None
    if with_baseline:
        missing = "it needs the clean truth folder (--truth), which holds the rig's marker binding" if not with_clean else openfacefx_missing()
        if missing is not None:
            skipped["openfacefx"] = missing
        elif folder is not None:  # with_clean: there is one
            rig, vertices = load_face_rig(), folder.vertices(db.marker_names)
    order += ["openfacefx"] if rig is not None else []
    references = (REFERENCES if with_clean else ("capture",)) if with_baseline else ()
    per_method: dict[str, list[dict]] = {m: [] for m in order + list(references)}
    classifier = EmotionClassifier(db, settings.classifier_frames, settings.seed) if with_baseline else None
    k = db.marker_names.index(settings.plot_marker)
    records = []
    for s in progress(sentences, "evaluate"):
        outputs, extra = method_outputs(db, s, members, ablations, rig, vertices, str(db_path))
        if "capture" in references:
            outputs["capture"] = s.truth
        clean = s.clean if with_clean else None  # with_clean: every sentence has it
        if "clean" in references:
            outputs["clean"] = s.clean
        record = {"take": s.take, "emotion": s.emotion, "fps": db.fps, "truth": (clean if clean is not None else s.truth)[:, k]}
        boundaries = phone_boundaries(s.utterance, db.fps)
        for method in per_method:
            markers = outputs[method]
            m = sentence_metrics(markers, s.truth, s.utterance, db.fps, db.marker_names, settings).row()
            m.update(take=s.take, emotion=s.emotion)
            m.update({key: v for key, v in extra.get(method, {}).items() if key != "joins"})
            if classifier is not None:  # with_baseline
                n = m["frames"]
                if clean is not None:
                    m.update(clean_metrics(markers, clean, s.utterance, db.fps, db.marker_names, settings).row())
                joins = extra[method]["joins"] if "joins" in extra.get(method, {}) else boundaries
                m["_d2"] = second_differences(markers[:n], joins)
                m["_d2_interior"] = interior_second_differences(markers[:n], joins)
                asked = frame_emotions(s.utterance, db.fps, n)
                m["emotion_correct"] = int(np.sum(classifier.predict(markers[:n]) == asked))
            per_method[method].append(m)
            if method not in REFERENCES:
                record[method] = markers[:, k]
        records.append(record)
    metrics: dict[str, dict] = {}
    for method, rows_of in per_method.items():
        emotions = sorted({r["emotion"] for r in rows_of})
        public = [{key: v for key, v in r.items() if not key.startswith("_")} for r in rows_of]
        metrics[method] = {"overall": aggregate(rows_of),
                           "per_emotion": {e: aggregate([r for r in rows_of if r["emotion"] == e]) for e in emotions},
                           "per_sentence": public}
    if classifier is not None:  # with_baseline
        for method, entry in figures(per_method, settings, with_clean).items():
            metrics[method]["figures"] = entry
        index = resamples(len(sentences), settings.bootstrap_resamples, settings.seed)  # the figures' resamples

        def difference(key: str, other: str, best: str) -> dict:
            stat = FIGURES[key][1]
            return paired_difference(stat(per_method[other]), stat(per_method[best]), len(sentences), index)

        choice = recommend({r: metrics[r]["figures"] for r in metrics if "figures" in metrics[r]},
                           {m: m for m in members}, difference)
        metrics["_figures"] = {"labels": {key: label for key, (label, _, _, _) in FIGURES.items()},
                               "lower_is_better": {key: lower for key, (_, _, _, lower) in FIGURES.items()},
                               "clean_truth": with_clean, "skipped": skipped,
                               "classifier_emotions": classifier.emotions,
                               "recommendation": dataclasses.asdict(choice)}
    return metrics, records
