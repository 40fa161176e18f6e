"""``facesynth batch``: a script of dialogue lines -> per-line motion (and what pipelines import:
rig curves, ARKit CSV, glTF with the audio, USD, a video; or a plain mesh's animation) on Dask,
with a summary of every line (see :mod:`facesynth.domain.batch`).

Every line is synthesized by one member of the method family (``method``: default
``synthesize.method``, i.e. the DP) through the same shared core as ``facesynth synthesize``
(:mod:`facesynth.domain.methods.steps`), under the command's ``[limits]``, which the job carries to the
workers. The script is checked first: a file without the required columns is refused before any work
(and before a cluster is started). Each line then runs as one task; the summary
(``summary.csv``, ``summary.html``) lists status, the alignment method, phone count, timings
and the reason of every failure.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from facesynth.base.config import (
    AlignSettings,
    BatchSettings,
    DeformSettings,
    ExportSettings,
    IngestSettings,
    RenderSettings,
    SolveSettings,
    SynthesizeSettings,
)
from facesynth.base.progress import progress
from facesynth.domain.batch.job import prepare
from facesynth.domain.batch.line import LineResult
from facesynth.domain.batch.report import write_summary
from facesynth.domain.batch.runner import dask_client, run_lines
from facesynth.domain.methods import MethodSettings


@dataclass(frozen=True)
class BatchResult:
    """What ``facesynth batch`` did.

    ok, skipped, failed: lines by status (skipped: up to date from an earlier run).
    lines: lines of the script.
    results: every line's result, in script order.
    csv, html: the summary's paths.
    seconds: wall time (s).
    """

    ok: int
    skipped: int
    failed: int
    lines: int
    results: list[LineResult]
    csv: Path
    html: Path
    seconds: float


def run(script: Path, db: Path, out_dir: Path, settings: BatchSettings, synthesize: SynthesizeSettings | MethodSettings,
        ingest: IngestSettings, align: AlignSettings, deform: DeformSettings, render: RenderSettings, *,
        method: str | None = None, mesh: Path | None = None, binding: Path | None = None, scheduler: str | None = None,
        overwrite: bool = False, on_result: Callable[[LineResult], None] | None = None, client=None,
        solve: SolveSettings | None = None, export: ExportSettings | None = None, rig: Path | None = None,
        rig_binding: Path | None = None) -> BatchResult:
    """Run every line of ``script`` and write the summary into ``out_dir``. ``client``: an open
    ``distributed.Client`` to use instead of creating one (tests, notebooks); the rest as
    :func:`facesynth.domain.batch.job.prepare`, which checks the request before any work."""
    lines, job = prepare(script, db, out_dir, settings, synthesize, ingest, align, deform, render, method=method,
                         mesh=mesh, binding=binding, overwrite=overwrite, solve=solve, export=export, rig=rig,
                         rig_binding=rig_binding)
    started = time.perf_counter()
    counts = {"ok": 0, "skipped": 0, "failed": 0}

    def show(_) -> str:
        return f"{counts['ok'] + counts['skipped']} done, {counts['failed']} failed"

    def gather(active) -> list[LineResult]:
        results = []
        for result in progress(run_lines(lines, job, active), "lines", length=len(lines), show=show):
            counts[result.status] += 1
            results.append(result)
            if on_result is not None:
                on_result(result)
        return sorted(results, key=lambda r: r.row)

    if client is not None:
        results = gather(client)
    else:
        with dask_client(scheduler, settings.workers) as new_client:
            results = gather(new_client)
    csv_path, html_path = write_summary(job.out_dir, results, f"facesynth batch {script.name}")
    counts = {s: sum(r.status == s for r in results) for s in ("ok", "skipped", "failed")}
    return BatchResult(counts["ok"], counts["skipped"], counts["failed"], len(results), results, csv_path, html_path,
                       time.perf_counter() - started)

