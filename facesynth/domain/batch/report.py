"""The batch summary: ``summary.csv`` and ``summary.html``, one row per line of the script."""

from __future__ import annotations

import csv
import html
import io
from pathlib import Path

from facesynth.model.artifacts import atomic_path

from .line import LineResult

COLUMNS = ("id", "row", "status", "reason", "method", "recognized", "phones", "audio_s", "align_s", "synthesize_s",
           "outputs_s", "load_s", "total_s", "cpu_s", "outputs", "warnings")


def rows(results: list[LineResult]) -> list[dict]:
    """The summary rows: times in seconds rounded to milliseconds, lists joined by ';'."""
    out = []
    for r in results:
        row = {c: getattr(r, c) for c in COLUMNS}
        for c in ("audio_s", "align_s", "synthesize_s", "outputs_s", "load_s", "total_s", "cpu_s"):
            row[c] = f"{row[c]:.3f}"
        row["outputs"] = ";".join(r.outputs)
        row["warnings"] = " ".join(r.warnings)
        out.append(row)
    return out


def write_summary(out_dir: Path, results: list[LineResult], title: str) -> tuple[Path, Path]:
    """Write ``summary.csv`` and ``summary.html`` into ``out_dir`` (replacing those of an earlier
    run); returns their paths."""
    table = rows(results)
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, COLUMNS, lineterminator="\n")
    writer.writeheader()
    writer.writerows(table)
    csv_path, html_path = out_dir / "summary.csv", out_dir / "summary.html"
    with atomic_path(csv_path, overwrite=True) as tmp:
        tmp.write_text(buffer.getvalue(), encoding="utf-8")
    with atomic_path(html_path, overwrite=True) as tmp:
        tmp.write_text(summary_html(table, title), encoding="utf-8")
    return csv_path, html_path


def summary_html(table: list[dict], title: str) -> str:
    """A self-contained HTML page of the summary rows, failures first."""
    counts = {s: sum(r["status"] == s for r in table) for s in ("ok", "skipped", "failed")}
    colours = {"ok": "#e6f4ea", "skipped": "#eef2f7", "failed": "#fdecea"}
    ordered = sorted(table, key=lambda r: (r["status"] != "failed", int(r["row"])))
    head = "".join(f"<th>{html.escape(c)}</th>" for c in COLUMNS)
    body = "\n".join(
        f'<tr style="background:{colours.get(r["status"], "#fff")}">'
        + "".join(f"<td>{html.escape(str(r[c]))}</td>" for c in COLUMNS) + "</tr>" for r in ordered)
    return (f"<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>{html.escape(title)}</title>"
            "<style>body{font:14px sans-serif;margin:2em}table{border-collapse:collapse}"
            "td,th{border:1px solid #ccc;padding:3px 6px;text-align:left;vertical-align:top}</style></head><body>"
            f"<h1>{html.escape(title)}</h1><p>{counts['ok']} done, {counts['skipped']} up to date (skipped), "
            f"{counts['failed']} failed, of {len(table)} lines.</p>"
            f"<table><thead><tr>{head}</tr></thead><tbody>\n{body}\n</tbody></table></body></html>\n")
