"""``facesynth evaluate``: synthesized motion against captured ground truth (paper VI-D, VIII),
written as ``metrics.json``, plots, an HTML report and a Markdown table ``table.md`` (the
metrics, baselines and intervals: :mod:`facesynth.domain.evaluation.held_out`)."""

from __future__ import annotations

import html
import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.config import EvaluateSettings, NormalizeSettings, SynthesizeSettings, TrajectorySettings
from facesynth.base.errors import InputError, OutputExistsError
from facesynth.domain.evaluation.held_out import FIGURES, REFERENCES, evaluate, member_rows
from facesynth.model.artifacts import atomic_folder, check_output_folder, sha256_of
from facesynth.model.trajectory import TrajectoryModel


def plot(records: list[dict], folder: Path, marker: str) -> list[str]:
    """Figs. 15-16 for each sentence: the marker's vertical trajectory and speed over time."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = []
    for r in records:
        fig, axes = plt.subplots(2, 1, figsize=(9, 5.5), sharex=True)
        curves = [c for c in (("truth", "--", "ground truth"), ("dp", "-", "synthesized (DP)"), ("baseline", ":", "per-phone mean"),
                              ("dominance", "-.", "Cohen-Massaro (fitted)"), ("openfacefx", (0, (1, 3)), "openfacefx")) if c[0] in r]
        n = min(len(r[key]) for key, _, _ in curves)
        t = np.arange(n) / r["fps"]
        for key, style, label in curves:
            y = r[key][:n].astype(np.float64)
            axes[0].plot(t, y[:, 1], linestyle=style, label=label, lw=1.4)
            speed = np.linalg.norm(np.gradient(y, axis=0), axis=1) * r["fps"]
            axes[1].plot(t, speed, linestyle=style, label=label, lw=1.4)
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


def _cell(f: dict | None, decimals: int = 3) -> str:
    """A figure with its interval: '1.234 [1.100, 1.400]'; '—' when undefined."""
    if not f or f.get("value") is None:
        return "—"
    if f.get("low") is None:
        return f"{f['value']:.{decimals}f}"
    return f"{f['value']:.{decimals}f} [{f['low']:.{decimals}f}, {f['high']:.{decimals}f}]"


def row_label(row: str) -> str:
    """A row's name in the tables: the member of the method family it scores, where the row keeps
    an older name ('baseline_emotion (mean)')."""
    member = next((m for m, r in member_rows().items() if r == row and m != r), None)
    return f"{row} ({member})" if member else row


def figure_rows(metrics: dict) -> tuple[list[str], list[str], list[list[str]], list[list[str]]]:
    """The table of figures: (figure keys shown, their labels, a row of cells per method with
    intervals, a row per baseline of paired differences dp - baseline). Methods in ``metrics``
    order; references (capture, clean) last."""
    methods = [m for m in metrics if "figures" in metrics[m]]
    methods = [m for m in methods if m not in REFERENCES] + [m for m in methods if m in REFERENCES]
    keys = [k for k in FIGURES if any(k in metrics[m]["figures"] for m in methods)]
    labels = [FIGURES[k][0] for k in keys]
    rows = [[row_label(m)] + [_cell(metrics[m]["figures"].get(k)) for k in keys] for m in methods]
    diffs = [[f"dp − {m}"] + [_cell(metrics[m]["figures"].get(f"dp_minus.{k}")) for k in keys]
             for m in methods if m != "dp" and m not in REFERENCES]
    return keys, labels, rows, diffs


def markdown_table(metrics: dict, meta: dict) -> str:
    """The figures as Markdown: methods x figures with bootstrap 95% intervals, then the paired
    differences DP - baseline (an interval that excludes 0 decides)."""
    keys, labels, rows, diffs = figure_rows(metrics)
    if not keys:
        return ""
    head = "| method | " + " | ".join(labels) + " |\n|---|" + "---|" * len(labels) + "\n"
    body = "".join("| " + " | ".join(r) + " |\n" for r in rows)
    dbody = "".join("| " + " | ".join(r) + " |\n" for r in diffs)
    skipped = "".join(f"\n*{m} not run:* {why}.\n" for m, why in meta.get("skipped", {}).items())
    recommendation = f"\n{meta['recommendation']}\n" if meta.get("recommendation") else ""
    return (f"Held-out sentences: {meta['sentences']} (split '{meta['split']}'); value [bootstrap 95% interval over "
            f"sentences, {meta['bootstrap_resamples']} resamples]. Closure threshold {meta['closure_mm']:g} mm.\n\n"
            + head + body + "\nPaired differences (DP minus each baseline, same resamples):\n\n" + head.replace("| method |", "| difference |")
            + dbody + skipped + recommendation)


def write_report(folder: Path, metrics: dict, images: list[str], meta: dict) -> None:
    """Write ``metrics.json``, ``table.md`` and ``index.html`` (the table of figures with
    intervals, tables per method and emotion, the plots) to ``folder``."""
    extra = metrics.get("_figures", {})
    meta = {**meta, "skipped": extra.get("skipped", {}),
            "recommendation": extra.get("recommendation", {}).get("sentence", "")}
    methods = {m: v for m, v in metrics.items() if not m.startswith("_")}
    (folder / "metrics.json").write_text(json.dumps({**methods, "figures_meta": extra, "meta": meta}, indent=2, sort_keys=True),
                                         encoding="utf-8")
    (folder / "table.md").write_text(markdown_table(methods, meta), encoding="utf-8")
    metrics = methods
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
             "Methods (<code>facesynth synthesize --method NAME</code>): <i>dp</i>, the paper's search; <i>baseline_emotion</i> "
             "(<i>mean</i>), the mean pose per (phone, emotion), linearly interpolated; <i>baseline</i>, the same per phone; "
             "<i>dominance_emotion</i> (<i>coarticulation</i>), a Cohen-Massaro coarticulation model per (phone, emotion) "
             "fitted on the training takes; <i>dominance</i>, the same per phone; "
             "<i>greedy</i>, Cao et al.'s greedy search on the same database; <i>trajectory</i>, Huang et "
             "al.'s smooth path through per-(phone, emotion) Gaussians of key-shape weights (Eq. 6-7), trained on the same "
             "takes; <i>openfacefx</i>, the external "
             "text-driven lip-sync from the same phone timing through the face rig to the markers. References: <i>capture</i>, the "
             "normalized noisy capture; <i>clean</i>, the clean ground truth itself.</p>"]
    shown, labels, rows, diffs = figure_rows(metrics)
    if shown:
        head = "<tr><th></th>" + "".join(f"<th>{html.escape(label)}</th>" for label in labels) + "</tr>"
        parts += ["<h2>Figures with bootstrap 95% intervals over sentences</h2>",
                  "<table>" + head + "".join("<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in r) + "</tr>" for r in rows) + "</table>",
                  "<p>Paired differences, DP minus each baseline (same resamples; an interval that excludes 0 decides):</p>",
                  "<table>" + head + "".join("<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in r) + "</tr>" for r in diffs) + "</table>"]
        parts += [f"<p><i>{html.escape(m)}</i> not run: {html.escape(why)}.</p>" for m, why in meta["skipped"].items()]
    parts += ["<h2>Overall (against the noisy capture)</h2>", table(lambda m: m["overall"])]

    emotions = sorted(next(iter(metrics.values()))["per_emotion"])
    for e in emotions:
        parts += [f"<h2>{html.escape(e)}</h2>", table(lambda m, e=e: m["per_emotion"][e])]
    parts.append(f"<h2>Lower-lip marker {html.escape(meta['plot_marker'])} (paper Figs. 15-16)</h2>")
    parts += [f"<p><img src='{html.escape(name)}'></p>" for name in images]
    if meta.get("recommendation"):
        parts += ["<h2>Recommendation</h2>", f"<p><b>{html.escape(meta['recommendation'])}</b></p>"]
    (folder / "index.html").write_text("\n".join(parts), encoding="utf-8")


def check_report_folder(out_dir: Path, overwrite: bool) -> None:
    """Refuse a report folder that is a file, or that already holds files unless ``overwrite``
    (an empty folder is fine). The report is written into a temporary folder beside it and renamed
    into place; with ``overwrite`` the old folder is replaced as a whole."""
    check_output_folder(out_dir, "the report")
    if out_dir.is_dir() and any(out_dir.iterdir()) and not overwrite:
        what = "already holds a report" if (out_dir / "metrics.json").exists() else "is not empty"
        raise OutputExistsError(f"{out_dir}: {what}; pass --overwrite to write the report into it or choose another folder.")


def trained_on(model: TrajectoryModel, model_path: Path, db_path: Path) -> None:
    """Refuse a trajectory model whose recorded training database is not ``db_path`` (by sha256):
    the methods must learn from the same takes, and the held-out ones must stay unseen."""
    dbs = [r for r in model.inputs if r.get("kind") == "motiondb"]
    if not any(r.get("sha256") == sha256_of(db_path) for r in dbs):
        was = f" ({dbs[0].get('path')})" if dbs else ""
        raise InputError(f"{model_path}: was trained on another database{was}, not {db_path}; train it on {db_path} "
                         "with `facesynth fit-method trajectory` so that every method learns from the same takes.")


@dataclass(frozen=True)
class EvaluateResult:
    """What ``facesynth evaluate`` measured.

    methods: per method, its overall metrics as metrics.json holds them (``rms_mm`` and
        ``velocity_rms_mm_s`` in mm and mm/s, ...), with ``figures`` (each a value and its
        bootstrap interval) where computed.
    recommendation: the report's last sentence, recommending a method for this database from
        the paired bootstrap intervals ('' when there is nothing to compare).
    """

    methods: dict[str, dict]
    recommendation: str = ""


def run(db_path: Path, corpus: Path, out_dir: Path, settings: EvaluateSettings, synth: SynthesizeSettings,
        normalize_settings: NormalizeSettings, overwrite: bool = False, truth: Path | None = None,
        trajectory: Path | None = None, trajectory_settings: TrajectorySettings | None = None) -> EvaluateResult:
    """Evaluate the database on the corpus's held-out takes and write the report to ``out_dir``.
    ``truth``: the
    corpus folder with clean ground truth (``groundtruth/``, ``markers.csv``). ``trajectory``: a
    trajectory model trained on ``db_path`` (``facesynth fit-method trajectory``), synthesized with
    ``trajectory_settings``, adds the trajectory method.
    """
    check_report_folder(out_dir, overwrite)
    model = None
    if trajectory is not None:
        model = TrajectoryModel.read(trajectory)
        trained_on(model, trajectory, db_path)
    metrics, records = evaluate(db_path, corpus, settings, synth, normalize_settings, truth=truth, trajectory=model,
                                trajectory_settings=trajectory_settings)
    with atomic_folder(out_dir, "the report", overwrite) as tmp:
        images = plot(records, tmp, settings.plot_marker)
        meta = {"db": str(db_path), "heldout": str(corpus), "split": settings.split, "sentences": len(records),
                "trajectory": None if trajectory is None else str(trajectory),
                "plot_marker": settings.plot_marker, "closure_mm": settings.closure_mm, "truth": None if truth is None else str(truth),
                "bootstrap_resamples": settings.bootstrap_resamples}
        write_report(tmp, metrics, images, meta)
    return EvaluateResult({m: {**v["overall"], **({"figures": v["figures"]} if "figures" in v else {})}
                           for m, v in metrics.items() if not m.startswith("_")},
                          metrics.get("_figures", {}).get("recommendation", {}).get("sentence", ""))

