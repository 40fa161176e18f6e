"""``facesynth evaluate``: synthesized motion against captured ground truth (paper VI-D, VIII).

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

The baseline is the per-phoneme mean pose (mean PCA frame of all the database's frames of
that phone) placed at each phone's centre and interpolated linearly, the rest pose in pauses.
"""

from __future__ import annotations

import html
import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..artifacts import open_artifact, read_strings
from ..config import EvaluateSettings, NormalizeSettings, SynthesizeSettings
from ..errors import InputError
from ..opencl import use_opencl
from ..motion.postprocess import frame_ranges
from ..phonemes import PAU, viseme
from ..progress import progress
from ..search.inputs import Utterance, utterance
from ..tables import Phones, Takes
from .normalize import fill_gaps, rigid_align
from .synthesize import Database, load_database, synthesize

BILABIALS = ("p", "b", "m")


@dataclass
class Sentence:
    take: str
    emotion: str
    utterance: Utterance
    truth: np.ndarray  # (T, M, 3) mm, head frame, capture rate


def normalized_take(f, i: int, takes: Takes, db: Database, settings: NormalizeSettings):
    """Take i of an open corpus, gaps filled and aligned to the database's reference frame
    (Eq. 1-2). Returns markers (T, M, 3), rotations (T, 3, 3), translations (T, 3)."""
    names = db.marker_names
    origin = int(np.argmin(np.linalg.norm(db.reference, axis=1)))
    rigid = np.array([names.index(n) for n in settings.rigid_markers]) if settings.rigid_markers else np.arange(len(names))
    raw = f["markers"][takes.frames(i)].astype(np.float64)
    for m in range(raw.shape[1]):
        raw[:, m], _ = fill_gaps(raw[:, m], settings.max_gap_frames)
    return rigid_align(raw, db.reference.astype(np.float64), origin, rigid)


def _check_markers(corpus: Path, f, db: Database) -> None:
    if read_strings(f, "marker_names") != db.marker_names:
        raise InputError(f"{corpus}: its markers differ from the database's; use the corpus the database was built from.")


def heldout(corpus: Path, db: Database, split: str, normalize_settings: NormalizeSettings) -> list[Sentence]:
    """The corpus's held-out takes with their phones and normalized capture."""
    with open_artifact(corpus, "corpus") as f:
        takes, phones = Takes.read(f), Phones.read(f)
        _check_markers(corpus, f, db)
        rows = [i for i in range(len(takes)) if takes.split[i] == split]
        if not rows:
            raise InputError(f"{corpus}: no take has split '{split}'; mark held-out takes in the manifest's split column.")
        out = []
        for i in rows:
            truth, _, _ = normalized_take(f, i, takes, db, normalize_settings)
            seg = np.nonzero(phones.take == i)[0]
            utt = utterance([phones.phone[r] for r in seg], phones.start[seg], phones.end[seg], [takes.emotion[i]] * len(seg))
            out.append(Sentence(takes.name[i], takes.emotion[i], utt, truth.astype(np.float32)))
    return out


def baseline(db: Database, utt: Utterance) -> np.ndarray:
    """Per-phoneme mean pose at phone centres, linearly interpolated. (T, M, 3) at capture rate."""
    phones = np.array(db.nodes.phone)
    means: dict[str, np.ndarray] = {}
    rest = db.model.project(db.reference[None])[0].astype(np.float64)

    def mean_pose(p: str) -> np.ndarray:
        if p not in means:
            sel = np.nonzero(phones == p)[0]
            if len(sel) == 0:  # an unseen phone: its viseme's nodes, else every node
                sel = np.nonzero(db.nodes.viseme == viseme(p))[0]
                sel = sel if len(sel) else np.arange(len(phones))
            rows = np.concatenate([np.arange(db.nodes.frame_start[k], db.nodes.frame_start[k] + db.nodes.frame_count[k]) for k in sel])
            means[p] = db.coeffs[rows].astype(np.float64).mean(0)
        return means[p]

    ranges = frame_ranges(utt.starts, utt.ends, db.fps)
    total = ranges[-1][1]
    centres = np.array([(a + b - 1) / 2.0 for a, b in ranges])
    poses = np.stack([rest if p == PAU else mean_pose(p) for p in utt.phones])
    frames = np.arange(total)
    coeffs = np.stack([np.interp(frames, centres, poses[:, k]) for k in range(poses.shape[1])], 1)
    return db.model.reconstruct(coeffs)


def lip_gaps(markers: np.ndarray, names: list[str], lip_markers: tuple[str, ...]) -> np.ndarray:
    i, j = (names.index(n) for n in lip_markers)
    return np.linalg.norm(markers[:, i] - markers[:, j], axis=1)


def sentence_metrics(syn: np.ndarray, truth: np.ndarray, utt: Utterance, fps: float, names: list[str],
                     settings: EvaluateSettings) -> dict:
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
             db: Database | None = None, tc=None, with_baseline: bool = True) -> tuple[dict, list[dict]]:
    """Returns (metrics per method, per-sentence records with the curves to plot).
    ``with_baseline=False`` skips the baseline, which does not depend on the search
    settings (tune leaves it out of its many evaluations)."""
    db = db or load_database(db_path)
    for name in tuple(settings.lip_markers) + (settings.plot_marker,):
        if name not in db.marker_names:
            raise InputError(f"evaluate: marker {name!r} is not in the database; set evaluate.lip_markers / evaluate.plot_marker to markers it has.")
    sentences = sentences if sentences is not None else heldout(corpus, db, settings.split, normalize_settings)
    if tc is None:
        tc = db.transition_panels(synth) if use_opencl(synth.use_opencl) else db.transition(synth)
    per_method: dict[str, list[dict]] = {"dp": [], "baseline": []} if with_baseline else {"dp": []}
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
        if with_baseline:
            base = baseline(db, s.utterance)
            m_base = sentence_metrics(base, s.truth, s.utterance, db.fps, db.marker_names, settings)
            m_base.update(take=s.take, emotion=s.emotion)
            per_method["baseline"].append(m_base)
            record["baseline"] = base[:, k]
        records.append(record)
    metrics = {}
    for method, rows in per_method.items():
        emotions = sorted({r["emotion"] for r in rows})
        metrics[method] = {"overall": aggregate(rows),
                           "per_emotion": {e: aggregate([r for r in rows if r["emotion"] == e]) for e in emotions},
                           "per_sentence": rows}
    return metrics, records


def plot(records: list[dict], folder: Path, marker: str) -> list[str]:
    """Figs. 15-16 for each sentence: the marker's vertical trajectory and speed over time."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = []
    for r in records:
        fig, axes = plt.subplots(2, 1, figsize=(9, 5.5), sharex=True)
        n = min(len(r["truth"]), len(r["dp"]), len(r["baseline"]))
        t = np.arange(n) / r["fps"]
        for key, style, label in (("truth", "--", "ground truth"), ("dp", "-", "synthesized (DP)"), ("baseline", ":", "baseline")):
            y = r[key][:n].astype(np.float64)
            axes[0].plot(t, y[:, 1], style, label=label, lw=1.4)
            speed = np.linalg.norm(np.gradient(y, axis=0), axis=1) * r["fps"]
            axes[1].plot(t, speed, style, label=label, lw=1.4)
        axes[0].set_ylabel(f"{marker} height (mm)")
        axes[1].set_ylabel(f"{marker} speed (mm/s)")
        axes[1].set_xlabel("time (s)")
        axes[0].legend(loc="upper right", fontsize=8)
        axes[0].set_title(f"{r['take']} ({r['emotion']})")
        fig.tight_layout()
        name = f"{r['take']}_{marker}.png"
        fig.savefig(folder / name, dpi=90, metadata={"Software": None})
        plt.close(fig)
        names.append(name)
    return names


def write_report(folder: Path, metrics: dict, images: list[str], meta: dict) -> None:
    (folder / "metrics.json").write_text(json.dumps({**metrics, "meta": meta}, indent=2, sort_keys=True), encoding="utf-8")
    keys = [("rms_mm", "RMS error (mm)"), ("err_mm2", "Eq. 13 error (mm²)"), ("total_err_mm2", "Eq. 12 total (mm²)"),
            ("velocity_rms_mm_s", "velocity RMS error (mm/s)"), ("lip_closure_rate", "bilabials closed"),
            ("lip_closure_rate_capture", "bilabials closed in the capture"), ("min_lip_gap_mm", "mean smallest lip gap on /p b m/ (mm)"),
            ("emotion_agreement", "emotion agreement"), ("non_captured_joins", "non-captured joins")]

    def table(select) -> str:
        head = "<tr><th></th>" + "".join(f"<th>{m}</th>" for m in metrics) + "</tr>"
        body = ""
        for key, label in keys:
            cells = []
            for m in metrics:
                v = select(metrics[m]).get(key)
                cells.append("—" if v is None else (f"{v:.3f}" if isinstance(v, float) else str(v)))
            body += f"<tr><td>{html.escape(label)}</td>" + "".join(f"<td>{c}</td>" for c in cells) + "</tr>"
        return f"<table>{head}{body}</table>"

    parts = ["<!doctype html><meta charset='utf-8'><title>facesynth evaluation</title>",
             "<style>body{font-family:sans-serif} table{border-collapse:collapse;margin:8px 0} td,th{border:1px solid #ccc;padding:3px 8px;text-align:right} td:first-child{text-align:left}</style>",
             f"<h1>Evaluation on {meta['sentences']} held-out sentences</h1>",
             f"<p>Database {html.escape(meta['db'])}; ground truth {html.escape(meta['heldout'])} (split '{meta['split']}'). "
             "The baseline is the per-phoneme mean pose, linearly interpolated.</p><h2>Overall</h2>", table(lambda m: m["overall"])]
    emotions = sorted(next(iter(metrics.values()))["per_emotion"])
    for e in emotions:
        parts += [f"<h2>{html.escape(e)}</h2>", table(lambda m, e=e: m["per_emotion"][e])]
    parts.append(f"<h2>Lower-lip marker {html.escape(meta['plot_marker'])} (paper Figs. 15-16)</h2>")
    parts += [f"<p><img src='{html.escape(name)}'></p>" for name in images]
    (folder / "index.html").write_text("\n".join(parts), encoding="utf-8")


def capture(db_path: Path, corpus: Path, take: str, out: Path, normalize_settings: NormalizeSettings,
            output_fps: float, overwrite: bool = False) -> dict:
    """Write a captured take as a ``motion`` artifact in the database's head frame (attribute
    ``source = "capture"``, no search path): ground truth to deform and render beside a synthesis."""
    from ..artifacts import check_output, write_artifact
    from ..motion.head import relative_to_take
    from ..motion.postprocess import downsample
    from .synthesize import write_head_and_markers

    check_output(out, overwrite)
    db = load_database(db_path)
    with open_artifact(corpus, "corpus") as f:
        takes = Takes.read(f)
        _check_markers(corpus, f, db)
        if take not in takes.name:
            raise InputError(f"{corpus}: no take {take!r}; it has {', '.join(takes.name[:5])}...")
        i = takes.index(take)
        markers, rotations, translations = normalized_take(f, i, takes, db, normalize_settings)
    rel_r, rel_t = relative_to_take(rotations, translations, [slice(0, len(markers))])
    with write_artifact(out, "motion", config="{}", inputs=[db_path, corpus], overwrite=overwrite) as g:
        g.attrs["source"] = "capture"
        g.attrs["take"] = take
        m = g.create_dataset("markers", data=downsample(markers.astype(np.float32), db.fps, output_fps))
        m.attrs.update(units="mm", fps=output_fps)
        mc = g.create_dataset("markers_capture", data=markers.astype(np.float32))
        mc.attrs.update(units="mm", fps=db.fps)
        write_head_and_markers(g, db.marker_names, db.reference, downsample(rel_r, db.fps, output_fps),
                               downsample(rel_t, db.fps, output_fps), output_fps)
    return {"frames": int(np.ceil(len(markers) * output_fps / db.fps)), "take": take}


def run(db_path: Path, corpus: Path, out_dir: Path, settings: EvaluateSettings, synth: SynthesizeSettings,
        normalize_settings: NormalizeSettings, overwrite: bool = False) -> dict:
    if out_dir.exists() and (out_dir / "metrics.json").exists() and not overwrite:
        raise InputError(f"{out_dir}: already holds a report; pass --overwrite or choose another folder.")
    metrics, records = evaluate(db_path, corpus, settings, synth, normalize_settings)
    out_dir.mkdir(parents=True, exist_ok=True)
    images = plot(records, out_dir, settings.plot_marker)
    meta = {"db": str(db_path), "heldout": str(corpus), "split": settings.split, "sentences": len(records),
            "plot_marker": settings.plot_marker, "closure_mm": settings.closure_mm}
    write_report(out_dir, metrics, images, meta)
    return {m: v["overall"] for m, v in metrics.items()}
