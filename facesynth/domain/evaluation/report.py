"""The report of ``facesynth evaluate``: the figures of :mod:`facesynth.domain.evaluation.held_out`
written as ``metrics.json``, a Markdown table ``table.md``, an HTML page ``index.html`` and the
plots of the marker's trajectory and speed (paper Figs. 15-16). Rows are named by the member of
the method family they score (``mean``, ``coarticulation``; their per-phone variants
``mean_per_phone``, ``coarticulation_per_phone``); reports written before read through
:func:`facesynth.domain.evaluation.held_out.current_rows`."""

from __future__ import annotations

import html
import json
from pathlib import Path

import numpy as np

from facesynth.base.registry import METHODS

from .held_out import FIGURES, REFERENCES


def members_described() -> list[tuple[str, str]]:
    """(name, summary) of every registered member of the method family, in report order."""
    return [(e.name, e.summary) for e in METHODS.entries()]


def plot(records: list[dict], folder: Path, marker: str) -> list[str]:
    """Figs. 15-16 for each sentence: the marker's vertical trajectory and speed over time."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = []
    for r in records:
        fig, axes = plt.subplots(2, 1, figsize=(9, 5.5), sharex=True)
        curves = [c for c in (("truth", "--", "ground truth"), ("dp", "-", "synthesized (DP)"),
                              ("mean_per_phone", ":", "per-phone mean"), ("coarticulation_per_phone", "-.", "Cohen-Massaro (fitted)"),
                              ("openfacefx", (0, (1, 3)), "openfacefx")) if c[0] in r]
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


def figure_rows(metrics: dict) -> tuple[list[str], list[str], list[list[str]], list[list[str]]]:
    """The table of figures: (figure keys shown, their labels, a row of cells per method with
    intervals, a row per baseline of paired differences dp - baseline). Methods in ``metrics``
    order; references (capture, clean) last."""
    methods = [m for m in metrics if "figures" in metrics[m]]
    methods = [m for m in methods if m not in REFERENCES] + [m for m in methods if m in REFERENCES]
    keys = [k for k in FIGURES if any(k in metrics[m]["figures"] for m in methods)]
    labels = [FIGURES[k][0] for k in keys]
    rows = [[m] + [_cell(metrics[m]["figures"].get(k)) for k in keys] for m in methods]
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
             "Methods (<code>facesynth synthesize --method NAME</code>): "
             + "; ".join(f"<i>{html.escape(name)}</i>, {html.escape(what)}" for name, what in members_described())
             + "; each <i>NAME_per_phone</i>, the same method per phone (every emotion pooled); <i>openfacefx</i>, "
             "the external text-driven lip-sync from the same phone timing through the face rig to the markers. "
             "References: <i>capture</i>, the normalized noisy capture; <i>clean</i>, the clean ground truth itself.</p>"]
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
