"""Throughput of ``facesynth batch``: lines per minute with 1 and 2 local Dask workers on the
small and paper sample databases, and the fixed cost per line. Prints JSON (and writes it
with ``--out``).

The lines are the sample corpus's recordings (2 to 6 s of speech each, every emotion)
with their transcripts, cycled to ``--lines`` lines with distinct ids and emotions, so every
line runs the whole per-line pipeline: alignment (pocketsphinx with its fallbacks),
synthesis on the database and the motion output. The databases are built once into
``--work`` (``sample-corpus`` -> ``ingest`` -> ``normalize`` -> ``pca`` -> ``build-db``) and reused.

Reported per database and worker count: wall time with and without starting the cluster,
lines per minute (steady: the cluster already up), the mean seconds per line of each phase
(align, synthesize, outputs: wall seconds inside the worker), the CPU seconds per line
(the worker process's CPU time, which a busy shared machine does not inflate), the load
average before and after (other work on the machine slows the wall-clock figures), the
database load (once per worker), the fixed cost per line (the intercept
of a least-squares line of per-line seconds against seconds of audio, over the lines
pocketsphinx aligned at once; the same for CPU seconds) and the dispatch cost per line (worker time outside the
lines' own work).

    python benchmarks/batch_throughput.py [--lines 1000] [--presets small,paper] [--workers 1,2]
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import platform
import shutil
import time
from pathlib import Path

import numpy as np

from facesynth.base.config import Config

EMOTIONS = ("neutral", "happy", "angry", "sad")


def build_db(folder: Path, preset: str) -> Path:
    """Sample corpus ``preset`` -> ... -> db.h5 (reused when present)."""
    from facesynth.domain.corpus.generate import generate
    from facesynth.stages import build_db, ingest, normalize, pca

    db = folder / "db.h5"
    if db.exists():
        return db
    folder.mkdir(parents=True, exist_ok=True)
    c = Config.load()
    generate(folder / "corpus", preset, seed=0, overwrite=True)
    ingest.run(folder / "corpus" / "manifest.csv", folder / "corpus.h5", c.settings("ingest"), c.settings("align"),
               overwrite=True)
    normalize.run(folder / "corpus.h5", folder / "normalized.h5", c.settings("normalize"), overwrite=True)
    pca.run(folder / "normalized.h5", folder / "pca.h5", c.settings("pca"), overwrite=True)
    build_db.run(folder / "pca.h5", db, c.settings("build_db"), overwrite=True)
    return db


def write_script(corpus: Path, n: int, path: Path) -> Path:
    """A script of ``n`` lines cycling through the corpus's recordings of 2 to 6 s."""
    import soundfile as sf

    takes = [r for r in csv.DictReader(open(corpus / "manifest.csv", encoding="utf-8"))
             if 2.0 <= sf.info(str(corpus / r["audio"])).duration <= 6.0]
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(("id", "audio", "text", "emotion"))
        for k in range(n):
            take = takes[k % len(takes)]
            w.writerow((f"line{k:05d}", str(corpus / take["audio"]), take["transcript"], EMOTIONS[k % 4]))
    return path


def measure(script: Path, db: Path, out: Path, workers: int) -> dict:
    """One batch run on a fresh local cluster of ``workers`` processes."""
    from distributed import Client, LocalCluster

    from facesynth.stages import batch

    c = Config.load()
    settings = [c.settings(s) for s in ("batch", "synthesize", "ingest", "align", "deform", "render")]
    shutil.rmtree(out, ignore_errors=True)
    started = time.perf_counter()
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster, \
            Client(cluster) as client:
        client.wait_for_workers(workers)
        up = time.perf_counter()
        s = batch.run(script, db, out, *settings, client=client)
    wall = time.perf_counter() - started
    ok = [r for r in s.results if r.status == "ok"]
    audio = np.array([r.audio_s for r in ok])
    total = np.array([r.total_s - r.load_s for r in ok])
    # the fixed cost: per-line seconds against seconds of audio, on the lines pocketsphinx
    # aligned at once (a fallback line also pays for the methods that failed before it)
    first = np.array([r.method == "pocketsphinx" for r in ok])
    slope, intercept = (np.polyfit(audio[first], total[first], 1) if first.sum() > 2
                        else (float("nan"), float("nan")))
    cpu = np.array([r.cpu_s for r in ok])
    cpu_slope, cpu_intercept = (np.polyfit(audio[first], cpu[first], 1) if first.sum() > 2
                                else (float("nan"), float("nan")))
    inside = float(sum(r.total_s for r in s.results))
    methods: dict[str, int] = {}
    for r in ok:
        methods[r.method] = methods.get(r.method, 0) + 1
    return {
        "workers": workers, "lines": s.lines, "ok": s.ok, "failed": s.failed,
        "failures": sorted({r.reason for r in s.results if r.status == "failed"})[:5],
        "cluster_start_s": round(up - started, 2), "batch_s": round(s.seconds, 2), "wall_s": round(wall, 2),
        "lines_per_min": round(60 * s.lines / s.seconds, 1),
        "lines_per_min_with_start": round(60 * s.lines / wall, 1),
        "mean_line_s": round(float(total.mean()), 3),
        "mean_line_cpu_s": round(float(np.mean([r.cpu_s for r in ok])), 3),
        "mean_line_cpu_s_by_method": {m: round(float(np.mean([r.cpu_s for r in ok if r.method == m])), 3)
                                      for m in sorted({r.method for r in ok})}, "mean_align_s": round(float(np.mean([r.align_s for r in ok])), 3),
        "mean_synthesize_s": round(float(np.mean([r.synthesize_s for r in ok])), 3),
        "mean_outputs_s": round(float(np.mean([r.outputs_s for r in ok])), 3),
        "db_load_s_per_worker": round(float(sum(r.load_s for r in ok)) / workers, 2),
        "mean_audio_s": round(float(audio.mean()), 2),
        "fixed_cost_per_line_s": round(float(intercept), 3), "cost_per_audio_second_s": round(float(slope), 3),
        "fixed_cpu_per_line_s": round(float(cpu_intercept), 3), "cpu_per_audio_second_s": round(float(cpu_slope), 3),
        "median_line_cpu_s": round(float(np.median(cpu)), 3),
        # worker time per line outside the line's own work: task dispatch, results, summary
        "dispatch_per_line_s": round((s["seconds"] * workers - inside) / s["lines"], 3),
        "mean_line_s_by_method": {m: round(float(np.mean([r.total_s - r.load_s for r in ok if r.method == m])), 3)
                                  for m in sorted({r.method for r in ok})},
        "alignment_methods": methods,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lines", type=int, default=1000)
    parser.add_argument("--presets", default="small,paper")
    parser.add_argument("--workers", default="1,2")
    parser.add_argument("--work", type=Path, default=Path("out/bench-batch"))
    parser.add_argument("--out", type=Path, default=None)
    args = parser.parse_args()
    result = {"machine": {"cores": os.cpu_count(), "processor": platform.processor() or platform.machine(),
                          "load_average_at_start": [round(x, 2) for x in os.getloadavg()]},
              "lines": args.lines, "runs": {}}
    for preset in args.presets.split(","):
        folder = args.work / preset
        started = time.perf_counter()
        db = build_db(folder, preset)
        script = write_script(folder / "corpus", args.lines, folder / f"script-{args.lines}.csv")
        runs = result["runs"][preset] = {"db_bytes": db.stat().st_size,
                                         "db_build_s": round(time.perf_counter() - started, 1)}
        for workers in (int(w) for w in args.workers.split(",")):
            runs[f"{workers}_workers"] = measure(script, db, folder / f"lines-{workers}", workers)
            print(json.dumps({preset: {f"{workers}_workers": runs[f"{workers}_workers"]}}), flush=True)
    result["machine"]["load_average_at_end"] = [round(x, 2) for x in os.getloadavg()]
    text = json.dumps(result, indent=2)
    print(text)
    if args.out:
        args.out.write_text(text + "\n")


if __name__ == "__main__":
    main()
