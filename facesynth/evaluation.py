"""Synthesized motion against captured ground truth (paper VI-D, VIII).

Every held-out take of the corpus (``evaluate.split``) is synthesized from its own phone
timing and emotion, with no constraints, and compared at the capture rate with its
capture, normalized with the database's own reference frame (Eq. 1-2) so both are in the
same head frame. Numbers, per method (``dp`` and ``baseline``), per emotion and overall:

* ``err_mm2``: Eq. 13, the mean over frames and markers of the squared marker distance;
  ``total_err_mm2``: Eq. 12, its sum over sentences; ``rms_mm``: the root of Eq. 13;
* ``velocity_rms_mm_s``: the same for marker velocities;
* lip closure on /p b m/: the fraction of bilabials whose lip gap gets below
  ``closure_mm`` within the phone (the capture's own fraction beside it), and the mean of
  the smallest gap;
* ``emotion_agreement``: the fraction of spoken phones whose node has the asked emotion;
* ``non_captured_joins``: joins of nodes that were not captured together.

Baselines, each given the same phone timing (and emotions):

* ``baseline``: the per-phoneme mean pose (mean PCA frame of all the database's frames of
  that phone) placed at each phone's centre and interpolated linearly, the rest pose in pauses;
* ``baseline_emotion``: the same with the mean pose per (phone, emotion), the phone's mean
  where the database has no node of that phone in that emotion;
* ``dominance``: a Cohen-Massaro coarticulation model (:mod:`facesynth.motion.dominance`)
  fitted on the database's training takes (targets, dominance magnitudes and rates per phone);
* ``dominance_emotion``: the same per (phone, emotion), given each phone's emotion.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .config import EvaluateSettings, NormalizeSettings, SynthesizeSettings
from .errors import InputError
from .model.corpus import Corpus
from .model.motiondb import MotionDatabase
from .motion.dominance import DominanceModel, emotion_labels, fit_dominance, training_sentences
from .motion.postprocess import frame_ranges
from .motion.rigid import fill_gaps, head_pose, rigid_indices
from .opencl import use_opencl
from .phonemes import PAU, viseme
from .progress import progress
from .search.inputs import Utterance, utterance
from .search.synthesis import synthesize


BILABIALS = ("p", "b", "m")


@dataclass
class Sentence:
    """A held-out take: its utterance (phones, times, emotion) and its normalized capture,
    truth : (T, M, 3) float32 mm in the head frame at the capture rate."""

    take: str
    emotion: str
    utterance: Utterance
    truth: np.ndarray


def normalized_take(raw: np.ndarray, db: MotionDatabase, settings: NormalizeSettings, corpus_rigid=()):
    """One take's captured markers (T, M, 3) mm, gaps filled and aligned to the database's
    reference frame as ``normalize`` does (weighted Procrustes on the rigid markers:
    the settings', else ``corpus_rigid``, else all). Returns markers (T, M, 3), rotations (T, 3, 3), translations (T, 3) mm."""
    names = db.marker_names
    rigid, _ = rigid_indices(names, settings.rigid_markers, [n for n in corpus_rigid if n in names])
    raw = raw.astype(np.float64)
    for m in range(raw.shape[1]):
        raw[:, m], _ = fill_gaps(raw[:, m], settings.max_gap_frames)
    return head_pose(raw, db.reference.astype(np.float64), rigid)[:3]


def heldout(corpus_path: Path, db: MotionDatabase, split: str, normalize_settings: NormalizeSettings) -> list[Sentence]:
    """The corpus's takes of ``split`` with their phones and normalized capture."""
    corpus = Corpus.read(corpus_path, audio=False)
    corpus.check_markers(db.marker_names, corpus_path)
    takes, phones = corpus.takes, corpus.phones
    phone_emotion = phones.emotions(takes)
    rows = [i for i in range(len(takes)) if takes.split[i] == split]
    if not rows:
        raise InputError(f"{corpus_path}: no take has split '{split}'; mark held-out takes in the manifest's split column.")
    out = []
    for i in rows:
        truth, _, _ = normalized_take(corpus.markers[takes.frames(i)], db, normalize_settings, corpus.rigid_markers)
        seg = np.nonzero(phones.take == i)[0]
        utt = utterance([phones.phone[r] for r in seg], phones.start[seg], phones.end[seg], [phone_emotion[r] for r in seg])
        out.append(Sentence(takes.name[i], takes.emotion[i], utt, truth.astype(np.float32)))
    return out


def baseline(db: MotionDatabase, utt: Utterance, by_emotion: bool = False) -> np.ndarray:
    """Per-phoneme (or, with ``by_emotion``, per (phone, emotion)) mean pose at phone centres,
    linearly interpolated. (T, M, 3) at capture rate."""
    phones = np.array(db.nodes.phone)
    emotions = np.array(db.nodes.emotion)
    means: dict[tuple[str, str], np.ndarray] = {}
    rest = db.model.project(db.reference[None])[0].astype(np.float64)

    def mean_pose(p: str, emotion: str) -> np.ndarray:
        key = (p, emotion if by_emotion else "")
        if key not in means:
            sel = np.nonzero(phones == p)[0]
            if by_emotion and (emotions[sel] == emotion).any():
                sel = sel[emotions[sel] == emotion]
            if len(sel) == 0:  # an unseen phone: its viseme's nodes, else every node
                sel = np.nonzero(db.nodes.viseme == viseme(p))[0]
                sel = sel if len(sel) else np.arange(len(phones))
            rows = np.concatenate([np.arange(db.nodes.frame_start[k], db.nodes.frame_start[k] + db.nodes.frame_count[k]) for k in sel])
            means[key] = db.coeffs[rows].astype(np.float64).mean(0)
        return means[key]

    ranges = frame_ranges(utt.starts, utt.ends, db.fps)
    total = ranges[-1][1]
    centres = np.array([(a + b - 1) / 2.0 for a, b in ranges])
    poses = np.stack([rest if p == PAU else mean_pose(p, e) for p, e in zip(utt.phones, utt.emotions)])
    frames = np.arange(total)
    coeffs = np.stack([np.interp(frames, centres, poses[:, k]) for k in range(poses.shape[1])], 1)
    return db.model.reconstruct(coeffs)


def dominance_baseline(db: MotionDatabase, model: DominanceModel, utt: Utterance, by_emotion: bool = False) -> np.ndarray:
    """The fitted Cohen-Massaro model's markers (T, M, 3) mm at the capture rate (``by_emotion``:
    a model fitted per (phone, emotion))."""
    total = frame_ranges(utt.starts, utt.ends, db.fps)[-1][1]
    labels = emotion_labels(utt.phones, utt.emotions) if by_emotion else utt.phones
    return db.model.reconstruct(model.predict(labels, utt.starts, utt.ends, total, db.fps))


def lip_gaps(markers: np.ndarray, names: list[str], lip_markers: tuple[str, ...]) -> np.ndarray:
    """Per frame, the distance (mm) between the two ``lip_markers`` of marker frames (T, M, 3) mm."""
    i, j = (names.index(n) for n in lip_markers)
    return np.linalg.norm(markers[:, i] - markers[:, j], axis=1)


def sentence_metrics(syn: np.ndarray, truth: np.ndarray, utt: Utterance, fps: float, names: list[str],
                     settings: EvaluateSettings) -> dict:
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
    for a, b, p in zip(utt.starts, utt.ends, utt.phones):
        if p in BILABIALS:
            fa, fb = int(round(a * fps)), min(int(round(b * fps)) + 1, n)
            if fb > fa and not np.isnan(gaps_true[fa:fb]).all():
                closures.append((gaps_syn[fa:fb].min(), np.nanmin(gaps_true[fa:fb])))
    closures = np.array(closures).reshape(-1, 2)
    return {
        "frames": n, "err_mm2": err, "rms_mm": float(np.sqrt(err)),
        "velocity_rms_mm_s": float(np.sqrt(np.nanmean(np.sum(vel**2, axis=2)))),
        "bilabials": len(closures),
        "lip_closure_rate": float((closures[:, 0] < settings.closure_mm).mean()) if len(closures) else None,
        "lip_closure_rate_capture": float((closures[:, 1] < settings.closure_mm).mean()) if len(closures) else None,
        "min_lip_gap_mm": float(closures[:, 0].mean()) if len(closures) else None,
    }


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


def evaluate(db_path: Path, corpus: Path, settings: EvaluateSettings, synth: SynthesizeSettings,
             normalize_settings: NormalizeSettings, sentences: list[Sentence] | None = None,
             db: MotionDatabase | None = None, tc=None, with_baseline: bool = True) -> tuple[dict, list[dict]]:
    """Returns (metrics per method, per-sentence records with the curves to plot).
    ``with_baseline=False`` skips the baseline, which does not depend on the search
    settings (tune leaves it out of its many evaluations)."""
    db = db or MotionDatabase.read(db_path)
    for name in tuple(settings.lip_markers) + (settings.plot_marker,):
        if name not in db.marker_names:
            raise InputError(f"evaluate: marker {name!r} is not in the database; set evaluate.lip_markers / evaluate.plot_marker to markers it has.")
    sentences = sentences if sentences is not None else heldout(corpus, db, settings.split, normalize_settings)
    if tc is None:
        tc = db.transition_costs(synth, use_opencl(synth.use_opencl))
    baselines = ("baseline", "baseline_emotion", "dominance", "dominance_emotion") if with_baseline else ()
    per_method: dict[str, list[dict]] = {"dp": [], **{b: [] for b in baselines}}
    dominance = {by: fit_dominance(training_sentences(db, by_emotion=by), db.fps, settings.dominance_iterations)
                 for by in (False, True)} if with_baseline else {}
    records = []
    for s in progress(sentences, "evaluate"):
        res = synthesize(db, s.utterance, {}, synth, tc=tc)
        spoken = [k for k, p in enumerate(s.utterance.phones) if p != PAU]
        agreement = float(np.mean([db.nodes.emotion[res["path"][k]] == s.utterance.emotions[k] for k in spoken]))
        m_dp = sentence_metrics(res["markers_capture"], s.truth, s.utterance, db.fps, db.marker_names, settings)
        m_dp.update(emotion_agreement=agreement, non_captured_joins=res["non_captured_joins"], take=s.take, emotion=s.emotion)
        per_method["dp"].append(m_dp)
        k = db.marker_names.index(settings.plot_marker)
        record = {"take": s.take, "emotion": s.emotion, "fps": db.fps, "truth": s.truth[:, k], "dp": res["markers_capture"][:, k]}
        for method in baselines:
            if method.startswith("dominance"):
                by = method == "dominance_emotion"
                base = dominance_baseline(db, dominance[by], s.utterance, by_emotion=by)
            else:
                base = baseline(db, s.utterance, by_emotion=(method == "baseline_emotion"))
            m_base = sentence_metrics(base, s.truth, s.utterance, db.fps, db.marker_names, settings)
            m_base.update(take=s.take, emotion=s.emotion)
            per_method[method].append(m_base)
            record[method] = base[:, k]
        records.append(record)
    metrics = {}
    for method, rows in per_method.items():
        emotions = sorted({r["emotion"] for r in rows})
        metrics[method] = {"overall": aggregate(rows),
                           "per_emotion": {e: aggregate([r for r in rows if r["emotion"] == e]) for e in emotions},
                           "per_sentence": rows}
    return metrics, records
