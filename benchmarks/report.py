"""The report of docs/results.md (the virtual actress's figures the README quotes), rebuilt
from fresh sample corpora over several seeds; writes it between the report markers of
``results.md`` (the hand-written text around them stays) and ``results.json`` (every number,
with the host).

For each corpus seed the real pipeline runs through the installed ``facesynth`` command
(sample-corpus, ingest, normalize, pca, build-db, prune --auto, evaluate), then
``benchmarks/prune_auto.py``, ``benchmarks/search_comparison.py`` and ``facesynth tune``
with a bounded budget (its weights evaluated on the test takes with ``facesynth
evaluate``). Once, on the first seed's paper-preset database: ``benchmarks/dp_table_v.py``
(the DP against a plain read of the same bytes, measured in the same run), the
phoneme-Isomaps, ``make demo`` and the renderer's speed against real time, and the host's
memory bandwidth.

Quality figures are deterministic (the same seeds give the same numbers); timings depend
on the host, so they are given as ratios to a floor measured in the same run where one
exists, and in seconds only beside the host's description.

    python benchmarks/report.py [--seeds 0 1 2] [--preset paper] [--work out/report] [--out docs]

Exit status: 0 ok, 1 a pipeline command failed (its command and last error line are
printed), 2 bad usage.
"""

from __future__ import annotations

import argparse
import datetime
import json
import os
import platform
import re
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
BENCH = Path(__file__).resolve().parent
SEARCHES = ("GreedyMatching", "PQ-Matching(3)", "PQ-Matching(4)", "PQ-Matching(5)", "DP (Algorithm 1, OpenCL)")
EMOTIONS = ("neutral", "happy", "angry", "sad")
STAGES = ("sample-corpus", "ingest", "normalize", "pca", "build-db", "prune", "evaluate")


class ReportError(Exception):
    """A command of the report failed; the message names it and its last error line."""


# --------------------------------------------------------------------------- statistics

def summarize(values: list[float], confidence: float = 0.95) -> dict:
    """Mean, sample standard deviation, min, max and a Student-t confidence interval of the
    mean over ``values`` (one per seed); ``ci`` is None for fewer than two values."""
    from scipy import stats

    v = np.asarray(values, dtype=np.float64)
    out = {"n": int(len(v)), "mean": float(v.mean()), "min": float(v.min()), "max": float(v.max()),
           "std": float(v.std(ddof=1)) if len(v) > 1 else None, "ci": None}
    if len(v) > 1:
        half = float(stats.t.ppf(0.5 + confidence / 2, len(v) - 1) * v.std(ddof=1) / np.sqrt(len(v)))
        out["ci"] = [out["mean"] - half, out["mean"] + half]
    return out


def pooled_rms(err_mm2: np.ndarray, frames: np.ndarray) -> float:
    """RMS marker error (mm) of sentences pooled as ``facesynth evaluate`` pools them: the
    root of the frame-weighted mean of the per-sentence Eq. 13 errors (mm²)."""
    return float(np.sqrt(np.average(err_mm2, weights=frames)))


def bootstrap_sentences(rows: list[dict], resamples: int = 2000, seed: int = 0, confidence: float = 0.95) -> dict:
    """95% bootstrap intervals over held-out sentences for the method's and the baseline's
    pooled RMS error (mm) and their difference (baseline minus method, mm).

    rows : one dict per sentence with ``frames``, ``dp_err_mm2`` and ``baseline_err_mm2``.
    Sentences are resampled with replacement (paired: both methods on the same draw) with a
    fixed generator seed, so the interval is deterministic."""
    frames = np.array([r["frames"] for r in rows], np.float64)
    dp = np.array([r["dp_err_mm2"] for r in rows], np.float64)
    base = np.array([r["baseline_err_mm2"] for r in rows], np.float64)
    rng = np.random.default_rng(seed)
    draws = rng.integers(0, len(rows), size=(resamples, len(rows)))
    w = frames[draws]
    dp_rms = np.sqrt((dp[draws] * w).sum(1) / w.sum(1))
    base_rms = np.sqrt((base[draws] * w).sum(1) / w.sum(1))
    lo, hi = 50 * (1 - confidence), 50 * (1 + confidence)

    def interval(sample: np.ndarray, point: float) -> dict:
        return {"value": point, "ci": [float(np.percentile(sample, lo)), float(np.percentile(sample, hi))]}

    dp_point, base_point = pooled_rms(dp, frames), pooled_rms(base, frames)
    return {"sentences": len(rows), "resamples": resamples,
            "dp_rms_mm": interval(dp_rms, dp_point), "baseline_rms_mm": interval(base_rms, base_point),
            "difference_mm": interval(base_rms - dp_rms, base_point - dp_point)}


# --------------------------------------------------------------------------- figures

# (key, label, unit, decimals): the quality figures of one seed, in table order.
QUALITY = [
    ("eval.dp.rms_mm", "RMS marker error, DP (default weights)", "mm", 3),
    ("eval.baseline.rms_mm", "RMS marker error, per-phoneme-mean baseline", "mm", 3),
    ("eval.gain_mm", "baseline minus DP (RMS)", "mm", 3),
    ("eval.dp.err_mm2", "Eq. 13 error, DP", "mm²", 4),
    ("eval.baseline.err_mm2", "Eq. 13 error, baseline", "mm²", 4),
    ("eval.dp.velocity_rms_mm_s", "velocity RMS error, DP", "mm/s", 1),
    ("eval.baseline.velocity_rms_mm_s", "velocity RMS error, baseline", "mm/s", 1),
    ("eval.dp.lip_closure_rate", "/p b m/ that close the lips, DP", "fraction", 3),
    ("eval.baseline.lip_closure_rate", "/p b m/ that close the lips, baseline", "fraction", 3),
    ("eval.capture.lip_closure_rate", "/p b m/ that close the lips, capture", "fraction", 3),
    ("eval.dp.min_lip_gap_mm", "mean smallest lip gap on /p b m/, DP", "mm", 3),
    ("eval.dp.emotion_agreement", "phones whose node has the asked emotion, DP", "fraction", 3),
    ("eval.dp.non_captured_joins", "non-captured joins, DP (all test sentences)", "count", 0),
] + [(f"eval.{m}.{e}.rms_mm", f"RMS error, {e}, {name}", "mm", 3)
     for e in EMOTIONS for m, name in (("dp", "DP"), ("baseline", "baseline"))] + [
    ("prune.precision", "prune --auto precision (nodes)", "fraction", 3),
    ("prune.recall", "prune --auto recall (nodes)", "fraction", 3),
    ("pca.explained_pct", "variance covered by the PCA components", "%", 2),
    ("search.dp_lowest_cost", "sentences where the DP has the lowest Eq. 4 cost", "fraction", 3),
    ("search.dp_lowest_rms", "sentences where the DP has the lowest RMS error", "fraction", 3),
] + [(f"search.rms_mm.{s}", f"RMS error, {s} (search comparison)", "mm", 3) for s in SEARCHES] + [
    ("tune.validation_before", "tune: validation Eq. 13 error before", "mm²", 4),
    ("tune.validation_after", "tune: validation Eq. 13 error after", "mm²", 4),
    ("tune.test_before", "tune: test Eq. 13 error before", "mm²", 4),
    ("tune.test_after", "tune: test Eq. 13 error after", "mm²", 4),
    ("tune.test_rms_after_mm", "RMS marker error, DP with the tuned weights", "mm", 3),
    ("corpus.test_sentences", "held-out (test) sentences", "count", 0),
    ("corpus.megabytes", "corpus written by sample-corpus", "MB", 1),
    ("db.nodes", "motion nodes", "count", 0),
    ("db.nodes_kept", "motion nodes kept by prune --auto", "count", 0),
]


def _baseline(ev: dict) -> dict:
    """The per-phoneme mean pose's row of an ``evaluate`` metrics.json: ``mean_per_phone`` (the
    ``mean`` method's per-phone variant), ``baseline`` in reports written before rows took their
    method's name."""
    return ev["mean_per_phone"] if "mean_per_phone" in ev else ev["baseline"]


def seed_figures(raw: dict) -> dict:
    """The quality figures of one seed (keys of QUALITY) from its raw outputs: the
    ``evaluate`` metrics.json, prune_auto.py and search_comparison.py JSON, the tune
    summary, the PCA's explained variance fraction and the corpus and database sizes."""
    ev = {**raw["evaluate"], "baseline": _baseline(raw["evaluate"])}
    f = {}
    for m in ("dp", "baseline"):
        o = ev[m]["overall"]
        for key in ("rms_mm", "err_mm2", "velocity_rms_mm_s", "lip_closure_rate"):
            f[f"eval.{m}.{key}"] = o.get(key)
        for e in EMOTIONS:
            if e in ev[m]["per_emotion"]:
                f[f"eval.{m}.{e}.rms_mm"] = ev[m]["per_emotion"][e]["rms_mm"]
    dp = ev["dp"]["overall"]
    f["eval.gain_mm"] = ev["baseline"]["overall"]["rms_mm"] - dp["rms_mm"]
    f["eval.capture.lip_closure_rate"] = dp.get("lip_closure_rate_capture")
    f["eval.dp.min_lip_gap_mm"] = dp.get("min_lip_gap_mm")
    f["eval.dp.emotion_agreement"] = dp.get("emotion_agreement")
    f["eval.dp.non_captured_joins"] = dp.get("non_captured_joins")
    f["prune.precision"], f["prune.recall"] = raw["prune"]["precision"], raw["prune"]["recall"]
    f["pca.explained_pct"] = 100 * raw["pca_explained"]
    tables = raw["search"]["tables"]
    lowest_cost = lowest_rms = 0
    for t in tables:
        rows = {r["search"]: r for r in t["rows"]}
        dp_row = rows[SEARCHES[-1]]
        lowest_cost += all(dp_row["eq4_cost"] <= r["eq4_cost"] + 1e-3 for r in rows.values())
        lowest_rms += all(dp_row["rms_mm"] <= r["rms_mm"] for r in rows.values())
    f["search.dp_lowest_cost"] = lowest_cost / len(tables)
    f["search.dp_lowest_rms"] = lowest_rms / len(tables)
    for s in SEARCHES:
        f[f"search.rms_mm.{s}"] = float(np.mean([next(r["rms_mm"] for r in t["rows"] if r["search"] == s) for t in tables]))
    tune = raw["tune"]
    f["tune.validation_before"], f["tune.validation_after"] = tune["validation_before"], tune["validation_after"]
    f["tune.test_before"] = dp["err_mm2"]
    f["tune.test_after"] = raw["evaluate_tuned"]["dp"]["overall"]["err_mm2"]
    f["tune.test_rms_after_mm"] = raw["evaluate_tuned"]["dp"]["overall"]["rms_mm"]
    f["corpus.test_sentences"] = dp["sentences"]
    f["corpus.megabytes"] = raw["corpus"]["bytes"] / 1e6
    f["db.nodes"], f["db.nodes_kept"] = raw["nodes"], raw["nodes_kept"]
    return f


def sentence_rows(raw: dict) -> list[dict]:
    """One row per held-out sentence of a seed: frames and both methods' Eq. 13 error (mm²)."""
    dp, base = raw["evaluate"]["dp"]["per_sentence"], _baseline(raw["evaluate"])["per_sentence"]
    return [{"seed": raw["seed"], "take": a["take"], "frames": a["frames"], "dp_err_mm2": a["err_mm2"],
             "baseline_err_mm2": b["err_mm2"]} for a, b in zip(dp, base)]


def method_figures(raws: list[dict]) -> list[dict]:
    """Per seed, ``facesynth evaluate``'s figures of every method and reference with their
    bootstrap intervals over that seed's sentences (and the paired DP - baseline differences),
    as its metrics.json has them; [] for seeds evaluated without them."""
    out = []
    for r in raws:
        ev = r["evaluate"]
        figures = {m: v["figures"] for m, v in ev.items() if isinstance(v, dict) and "figures" in v}
        if figures:
            out.append({"seed": r["seed"], "sentences": ev["dp"]["overall"]["sentences"], "figures": figures,
                        "skipped": ev.get("figures_meta", {}).get("skipped", {})})
    return out


def method_tables(methods: list[dict]) -> list[str]:
    """Markdown lines: for each seed, methods x figures with intervals and the paired differences."""
    from facesynth.domain.evaluation.report import figure_rows

    lines = []
    for entry in methods:
        keys, labels, rows, diffs = figure_rows({m: {"figures": f} for m, f in entry["figures"].items()})
        head = ["| method | " + " | ".join(labels) + " |", "|---|" + "---|" * len(labels)]
        lines += ["", f"Seed {entry['seed']}, {entry['sentences']} held-out sentences:", "", *head,
                  *("| " + " | ".join(r) + " |" for r in rows), "",
                  "Paired differences, DP minus each baseline (an interval that excludes 0 decides):", "",
                  head[0].replace("| method |", "| difference |"), head[1], *("| " + " | ".join(r) + " |" for r in diffs)]
        lines += ["", *(f"*{m} not run:* {why}." for m, why in entry["skipped"].items())]
    return lines


def seed_timings(raw: dict) -> dict:
    """Seconds (wall, this host) of one seed's commands and searches: each stage command
    including interpreter start-up, and the median search time per search method."""
    t = {f"stage.{k}": v for k, v in raw["seconds"].items()}
    for s in SEARCHES:
        t[f"search.{s}"] = float(np.median([next(r["seconds"] for r in x["rows"] if r["search"] == s)
                                            for x in raw["search"]["tables"]]))
    return t


# A t interval assumes an unbounded, roughly normal quantity: none for rates and counts.
NO_INTERVAL = ("fraction", "count", "MB")


def aggregate(raws: list[dict]) -> dict:
    """Per-seed figures and their summaries (``summarize``) for every quality figure and
    timing, and the sentence bootstrap over all seeds' held-out sentences."""
    per_seed = [seed_figures(r) for r in raws]
    quality = {}
    for key, _, unit, _ in QUALITY:
        values = [f.get(key) for f in per_seed]
        if any(v is None for v in values):
            continue
        quality[key] = {"per_seed": values, **summarize(values)}
        if unit in NO_INTERVAL:
            quality[key]["ci"] = None
    timings = [seed_timings(r) for r in raws]
    speed = {k: {"per_seed": [t[k] for t in timings], **summarize([t[k] for t in timings])} for k in timings[0]}
    rows = [row for r in raws for row in sentence_rows(r)]
    return {"seeds": [r["seed"] for r in raws], "quality": quality, "sentences": bootstrap_sentences(rows),
            "methods": method_figures(raws),
            "tune": [{"seed": r["seed"], **r["tune"], "test_before": r["evaluate"]["dp"]["overall"]["err_mm2"],
                      "test_after": r["evaluate_tuned"]["dp"]["overall"]["err_mm2"]} for r in raws],
            "seed_timings_s": speed}


# --------------------------------------------------------------------------- host

def host_info() -> dict:
    """Processor model, logical cores (all, and usable by this process), memory (GB,
    1e9 bytes), system, Python and NumPy versions, and the 1-minute load average."""
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as fh:
            cpu = next((line.split(":", 1)[1].strip() for line in fh if line.startswith("model name")), cpu)
    except OSError:
        pass
    try:
        memory = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 1e9
    except (ValueError, OSError, AttributeError):
        memory = None
    usable = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    return {"processor": cpu, "cores": os.cpu_count(), "usable_cores": usable,
            "memory_gb": round(memory, 1) if memory else None,
            "system": f"{platform.system()} {platform.release()} {platform.machine()}",
            "python": platform.python_version(), "numpy": np.__version__,
            "load_average_1min": round(os.getloadavg()[0], 2) if hasattr(os, "getloadavg") else None}


def copy_bandwidth(n_bytes: int = 512 * 2**20, repeats: int = 5) -> float:
    """Host memory bandwidth in GB/s (1e9 bytes/s): bytes read plus bytes written per
    second by a NumPy copy of an ``n_bytes`` array into another, best of ``repeats``."""
    src = np.ones(n_bytes // 8)
    dst = np.empty_like(src)
    np.copyto(dst, src)  # first touch maps the pages; not timed
    best = np.inf
    for _ in range(repeats):
        t0 = time.perf_counter()
        np.copyto(dst, src)
        best = min(best, time.perf_counter() - t0)
    return 2 * src.nbytes / best / 1e9


def opencl_device() -> dict:
    """The OpenCL device facesynth uses here (``facesynth devices``), with its platform and why."""
    from facesynth.base.opencl import OpenCLUnavailable, choice

    try:
        chosen = choice()
    except OpenCLUnavailable as exc:
        return {"device": None, "note": str(exc)}
    if chosen.device is None:
        return {"device": None, "note": chosen.reason}
    return {"device": chosen.device.name, "platform": chosen.device.platform, "reason": chosen.reason}


# --------------------------------------------------------------------------- running

def facesynth_exe() -> str:
    """The ``facesynth`` console script of the interpreter running this script."""
    exe = Path(sys.executable).with_name("facesynth")
    if not exe.exists():
        raise ReportError(f"no facesynth command beside {sys.executable}; install the package (pip install -e .).")
    return str(exe)


def run(cmd: list[str], cwd: Path) -> tuple[float, str]:
    """Run one command in ``cwd``; returns (wall seconds, stdout). A failure raises
    ReportError with the command and its last line of error output."""
    t0 = time.perf_counter()
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    seconds = time.perf_counter() - t0
    if p.returncode != 0:
        last = (p.stderr.strip().splitlines() or ["(no error output)"])[-1]
        raise ReportError(f"`{' '.join(Path(c).name if os.sep in c else c for c in cmd)}` failed "
                          f"(exit {p.returncode}): {last}")
    return seconds, p.stdout


def say(message: str) -> None:
    print(message, file=sys.stderr, flush=True)


def build_chain(fs: str, folder: Path, preset: str, seed: int, seconds: dict) -> None:
    """sample-corpus -> ingest -> normalize -> pca -> build-db -> prune --auto in ``folder``."""
    steps = [("sample-corpus", ["sample-corpus", "corpus", "--preset", preset, "--seed", str(seed)]),
             ("ingest", ["ingest", "corpus/manifest.csv", "-o", "corpus.h5"]),
             ("normalize", ["normalize", "corpus.h5", "-o", "normalized.h5"]),
             ("pca", ["pca", "normalized.h5", "-o", "pca.h5"]),
             ("build-db", ["build-db", "pca.h5", "-o", "db.h5"]),
             ("prune", ["prune", "db.h5", "--auto", "-o", "db_clean.h5"])]
    for name, args in steps:
        seconds[name], _ = run([fs, *args, "--overwrite", "-q"], folder)


def parse_tuned(path: Path) -> dict:
    """The validation errors (mm²) and weights from the configuration ``facesynth tune`` wrote."""
    try:
        import tomllib
    except ModuleNotFoundError:  # Python 3.10
        import tomli as tomllib
    text = path.read_text("utf-8")
    m = re.search(r"validation error \(Eq\. 13, mm\^2\): ([0-9.]+) -> ([0-9.]+)", text)
    if not m:
        raise ReportError(f"{path.name}: no validation error line; the tune output format changed.")
    return {"validation_before": float(m.group(1)), "validation_after": float(m.group(2)),
            "alphas": tomllib.loads(text)["synthesize"]}


def read_artifact_facts(folder: Path) -> dict:
    """The PCA's explained variance fraction and the node counts before and after pruning."""
    from facesynth.model.motiondb import MotionDatabase

    counts = [len(MotionDatabase.read(folder / name).nodes) for name in ("db.h5", "db_clean.h5")]
    explained = MotionDatabase.read(folder / "db.h5").model.explained
    return {"pca_explained": explained, "nodes": counts[0], "nodes_kept": counts[1]}


def run_seed(fs: str, work: Path, preset: str, seed: int, tune_evaluations: int) -> dict:
    """The whole pipeline for one corpus seed; returns its raw outputs (see seed_figures)."""
    folder = work / f"seed{seed}"
    folder.mkdir(parents=True, exist_ok=True)
    seconds: dict[str, float] = {}
    build_chain(fs, folder, preset, seed, seconds)
    seconds["evaluate"], _ = run([fs, "evaluate", "db_clean.h5", "--heldout", "corpus.h5", "--truth", "corpus",
                                  "-o", "evaluate", "--overwrite", "-q"], folder)
    py = sys.executable
    _, out = run([py, str(BENCH / "prune_auto.py"), "--db", "db.h5", "--truth", "corpus/contamination.csv"], folder)
    prune = json.loads(out)
    _, out = run([py, str(BENCH / "search_comparison.py"), "--db", "db_clean.h5", "--corpus", "corpus.h5"], folder)
    search = json.loads(out)
    seconds["tune"], _ = run([fs, "tune", "db_clean.h5", "--validation", "corpus.h5", "-o", "tuned.toml",
                              "--set", "tune.starts=1", "--set", f"tune.max_evaluations={tune_evaluations}",
                              "--overwrite", "-q"], folder)
    run([fs, "evaluate", "db_clean.h5", "--heldout", "corpus.h5", "-o", "evaluate_tuned", "--config", "tuned.toml",
         "--overwrite", "-q"], folder)
    corpus_bytes = sum(p.stat().st_size for p in (folder / "corpus").rglob("*") if p.is_file())
    metrics = {k: json.loads((folder / k / "metrics.json").read_text("utf-8")) for k in ("evaluate", "evaluate_tuned")}
    for m in metrics.values():
        m.pop("meta", None)
    return {"seed": seed, "preset": preset, "seconds": seconds, "corpus": {"bytes": corpus_bytes},
            "evaluate": metrics["evaluate"], "evaluate_tuned": metrics["evaluate_tuned"], "prune": prune,
            "search": search, "tune": {**parse_tuned(folder / "tuned.toml"), "budget": tune_evaluations},
            **read_artifact_facts(folder)}


def run_speed(fs: str, work: Path, paper_folder: Path) -> dict:
    """Once per report: the DP benchmark (paper Table V) and the phoneme-Isomaps on the
    paper-preset database, ``make demo`` in a fresh folder and the renderer on its
    animations. Seconds are this host's wall time; ratios are to floors of the same run."""
    out = {}
    _, text = run([sys.executable, str(BENCH / "dp_table_v.py"), "--db", "db.h5", "--work", "bench"], paper_folder)
    out["dp_table_v"] = json.loads(text)
    _, text = run([sys.executable, str(BENCH / "synthesize_startup.py"), "--db", "db.h5", "--repeats", "5"], paper_folder)
    out["synthesize_startup"] = json.loads(text)
    out["isomap_s"], _ = run([fs, "isomap", "db_clean.h5", "-o", "isomap.h5", "--images", "isomaps",
                              "--overwrite", "-q"], paper_folder)
    demo = work / "demo"
    if demo.exists():
        import shutil

        shutil.rmtree(demo)
    out["make_demo_s"], _ = run(["make", "-s", "-C", str(ROOT), "demo", f"OUT={demo}"], ROOT)
    out["render"] = time_render(fs, demo)
    return out


def time_render(fs: str, demo: Path) -> dict:
    """Render the demo's rig curves again (posed through the built-in rig, as ``make demo``
    renders them) and time the whole command: frames per second (wall time, start-up included)
    and that as a multiple of real time (the video's rate)."""
    from facesynth.domain.rig.face import load_face_rig
    from facesynth.model.curves import RigCurves

    clips = sorted(demo.glob("*.curves.h5"))
    frames, fps = 0, None
    for c in clips:
        curves = RigCurves.read(c)
        frames += len(curves.weights)
        fps = curves.fps
    triangles = len(load_face_rig().faces)
    audio = [x for c in clips for x in ("--audio", str(demo / "corpus" / "audio" / (c.name.split(".")[0] + ".wav")))]
    seconds, _ = run([fs, "render", *map(str, clips), *audio, "-o", "render_timed.avi", "--overwrite", "-q"], demo)
    return {"frames": frames, "video_fps": fps, "triangles": triangles, "wall_s": seconds,
            "frames_per_s": frames / seconds, "times_real_time": frames / seconds / fps}


# --------------------------------------------------------------------------- writing

def _fmt(v, decimals: int) -> str:
    if v is None:
        return "—"
    return f"{v:,.{decimals}f}" if decimals else f"{round(v):,d}"


#: The lines around the report in results.md; the text before and after them is written by hand.
REPORT_BEGIN = "<!-- report:begin: written by `make report` (benchmarks/report.py); edit above this line -->"
REPORT_END = "<!-- report:end -->"


def publish(path: Path, report_markdown: str) -> None:
    """Put the report into ``path`` between :data:`REPORT_BEGIN` and :data:`REPORT_END`, keeping
    the hand-written text before and after them; a file without them (or no file) gets a title
    and the report, between the markers."""
    text = path.read_text(encoding="utf-8") if path.exists() else ""
    if REPORT_BEGIN in text and REPORT_END in text.split(REPORT_BEGIN, 1)[1]:
        before, rest = text.split(REPORT_BEGIN, 1)
        after = rest.split(REPORT_END, 1)[1]
    else:
        before, after = "# Results\n\n", "\n"
    path.write_text(f"{before}{REPORT_BEGIN}\n{report_markdown.rstrip()}\n{REPORT_END}{after}", encoding="utf-8")


def markdown(results: dict) -> str:
    """results.md from the report's JSON: host, quality over seeds, sentence bootstrap,
    tuning, searches and speed."""
    h, q, s = results["host"], results["quality"], results["speed"]
    seeds = ", ".join(map(str, results["seeds"]))
    n = len(results["seeds"])
    lines = [
        "## The report: fresh corpora over several seeds",
        "",
        f"Rebuilt by `make report` (`benchmarks/report.py`) from fresh sample corpora: preset "
        f"`{results['preset']}`, seeds {seeds}; tuning budget {results['tune_evaluations']} evaluations. "
        f"The whole report took {results['report_s'] / 60:.1f} min"
        + (f" (seeds {', '.join(map(str, results['reused_seeds']))} read from an earlier run's raw.json)"
           if results.get("reused_seeds") else "") + ". Every number below is in `results.json`.",
        "",
        "Quality figures are deterministic: the same code and seeds give the same numbers (a second run "
        "of the report reproduces them exactly; another processor or OpenCL device may differ in the last "
        "digits). Timings are this host's; speed is given as a ratio to a floor measured in the same run "
        "where one exists.",
        "",
        "### Host",
        "",
        "| processor | logical cores (usable) | memory | copy bandwidth | OpenCL device | load (1 min, at start) |",
        "|---|---|---|---|---|---|",
        f"| {h['processor']} | {h['cores']} ({h['usable_cores']}) | {h['memory_gb']} GB | "
        f"{h['copy_bandwidth_gb_s']:.1f} GB/s | {h['opencl']['device']} ({h['opencl'].get('platform', '')}) | "
        f"{h['load_average_1min']} |",
        "",
        "Copy bandwidth: bytes read plus bytes written per second by a NumPy copy of a 512 MiB array.",
        "",
        f"### Quality over {n} seed{'s' if n > 1 else ''}",
        "",
        "`facesynth evaluate` on each seed's held-out (test) sentences, the database cleaned by "
        "`prune --auto`. Spread: sample standard deviation and min–max over seeds; 95% CI: "
        "Student-t interval of the mean over seeds (none for rates and counts).",
        "",
        "| figure | unit | mean | std | min – max | 95% CI | per seed |",
        "|---|---|---|---|---|---|---|",
    ]
    for key, label, unit, d in QUALITY:
        if key not in q:
            continue
        x = q[key]
        ci = f"{_fmt(x['ci'][0], d)} – {_fmt(x['ci'][1], d)}" if x["ci"] else "—"
        mean_d = d or 1  # a mean of counts need not be whole
        lines.append(f"| {label} | {unit} | {_fmt(x['mean'], mean_d)} | {_fmt(x['std'], mean_d)} | "
                     f"{_fmt(x['min'], d)} – {_fmt(x['max'], d)} | {ci} | {' / '.join(_fmt(v, d) for v in x['per_seed'])} |")
    b = results["sentences"]
    lines += [
        "",
        f"Over sentences ({b['sentences']} held-out sentences of all seeds pooled, {b['resamples']} paired "
        "bootstrap resamples of sentences, 95% percentile intervals):",
        "",
        "| | RMS (mm) | 95% CI |",
        "|---|---|---|",
    ]
    for key, label in (("dp_rms_mm", "DP"), ("baseline_rms_mm", "baseline"), ("difference_mm", "baseline minus DP")):
        lines.append(f"| {label} | {b[key]['value']:.3f} | {b[key]['ci'][0]:.3f} – {b[key]['ci'][1]:.3f} |")
    if results.get("methods"):
        lines += [
            "",
            "### Methods against baselines, with intervals",
            "",
            "`facesynth evaluate --truth` on each seed's held-out sentences: errors against the clean ground truth "
            "and the noisy capture (both in the database's normalized head frame), velocity error, mouth-opening "
            "Pearson r, /p b m/ closure and its onset against the truth's, the second difference at joins and away "
            "from them, and the fraction of frames a classifier trained on captured training frames recognises as "
            "the asked emotion. Value [bootstrap 95% interval over sentences]; `capture` and `clean` are "
            "references (the noisy capture and the clean truth themselves), not methods.",
            *method_tables(results["methods"]),
        ]
    lines += [
        "",
        "### Tuning",
        "",
        f"`facesynth tune --set tune.starts=1 --set tune.max_evaluations={results['tune_evaluations']}`: "
        "Nelder-Mead from the default weights on the validation sentences; the tuned weights are then "
        "scored by `facesynth evaluate` on the test sentences, which tuning never sees (Eq. 13, mm²).",
        "",
        "| seed | validation before → after | test before → after |",
        "|---|---|---|",
    ]
    for t in results["tune"]:
        lines.append(f"| {t['seed']} | {t['validation_before']:.4f} → {t['validation_after']:.4f} | "
                     f"{t['test_before']:.4f} → {t['test_after']:.4f} |")
    lines += [
        "",
        "### Searches compared",
        "",
        "`benchmarks/search_comparison.py` on each seed's cleaned database and three of its held-out sentences "
        "(the script's choice: spoken length closest to 22 phones). RMS error against the capture and Eq. 4 cost are deterministic; "
        "seconds are this host's (median over sentences, then mean over seeds), also as a multiple of the DP's time.",
        "",
        "| search | RMS (mm), mean | seconds | × DP |",
        "|---|---|---|---|",
    ]
    dp_s = results["seed_timings_s"][f"search.{SEARCHES[-1]}"]["mean"]
    for name in SEARCHES:
        t = results["seed_timings_s"][f"search.{name}"]["mean"]
        lines.append(f"| {name} | {q[f'search.rms_mm.{name}']['mean']:.3f} | {t:.4g} | {t / dp_s:.3g} |")
    dpt = s["dp_table_v"]
    lines += [
        "",
        f"The DP has the lowest Eq. 4 cost in {q['search.dp_lowest_cost']['mean']:.0%} of the compared sentences "
        f"and the lowest RMS error in {q['search.dp_lowest_rms']['mean']:.0%}.",
        "",
        "### Speed",
        "",
        f"On the host above. The dense DP (`benchmarks/dp_table_v.py`; the reference, `synthesize.dp = \"dense\"`) on "
        f"seed {results['seeds'][0]}'s paper-preset database ({dpt['nodes']:,} nodes, transition matrix "
        f"{dpt['matrix_bytes'] / 1e6:.0f} MB), against a plain read of the same bytes once per step measured in the "
        "same run (best of 3 each), and the default exact pruned DP (same path and cost, no N x N matrix; "
        "`benchmarks/scale_search.py` measures it up to hours of capture):",
        "",
        "| phones (paper Table V) | dense DP (s) | read floor (s) | dense / read floor | read GB/s | NumPy dense DP (s) "
        "| NumPy / OpenCL | pruned DP (s) | pair costs computed | paper's GPU (s) |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in dpt["phrases"]:
        pruned = (f"{r['pruned_s']:.3f} | {r['pairs_fraction']:.2g}" if "pruned_s" in r else "– | –")
        lines.append(f"| {r['phones']} | {r['dp_s']:.3f} | {r['read_floor_s']:.3f} | {r['ratio_to_read']:.2f} | "
                     f"{r['read_gb_per_s']:.1f} | {r['numpy_s']:.3f} | {r['numpy_to_opencl']:.1f} | {pruned} | "
                     f"{r['paper_gpu_s']:.0f} |")
    st = s["synthesize_startup"]
    r = s["render"]
    lines += [
        "",
        f"* The DP's 14-phone path and cost are identical to the NumPy reference's: "
        f"{'yes' if dpt['phrases'][0].get('identical_to_reference') else 'NO'}; the pruned DP's to the dense DP's "
        f"on every phrase: {'yes' if all(r.get('pruned_identical_to_dense', False) for r in dpt['phrases']) else 'NO'}.",
        "* The NumPy DP is what a machine without a working OpenCL device runs (the fallback); same path and cost.",
        f"* The whole `facesynth synthesize` command for 63 phones (`benchmarks/synthesize_startup.py`, fresh "
        f"processes, {st['repeats']} runs), process start to file written: {st['command_to_file_written_s']['min']:.2f} s "
        f"(median {st['command_to_file_written_s']['median']:.2f}), {st['ratio_to_read_floor']['min']:.2f} times "
        f"(median {st['ratio_to_read_floor']['median']:.2f}) the read floor of the same run "
        f"({st['read_floor_s']['min']:.3f} s).",
    ]
    if "nodes_20000" in dpt:
        k = dpt["nodes_20000"]
        lines.append(f"* 20,000 nodes (generated costs, {k['matrix_gb']} GB matrix): preparation {k['prepare_s']:.1f} s, "
                     f"DP {k['dp_s']:.2f} s for {k['phones']} phones, peak memory {k['peak_rss_gb']:.1f} GB.")
    lines += [
        f"* Rendering (`facesynth render`, {r['triangles']:,}-triangle face, the command's wall time with start-up): "
        f"{r['frames']} frames in {r['wall_s']:.1f} s = {r['frames_per_s']:.1f} frames/s, "
        f"{r['times_real_time']:.2f} × real time ({r['video_fps']:g} frames/s).",
        f"* Phoneme-Isomaps of the paper-preset database: {s['isomap_s']:.1f} s. "
        f"`make demo` (small preset, environment already set up): {s['make_demo_s']:.1f} s.",
        "",
        "Each stage command, wall time with interpreter start-up (s, mean and min – max over seeds):",
        "",
        "| " + " | ".join(STAGES + ("tune",)) + " |",
        "|" + "---|" * (len(STAGES) + 1),
        "| " + " | ".join(f"{results['seed_timings_s'][f'stage.{k}']['mean']:.1f} "
                          f"({results['seed_timings_s'][f'stage.{k}']['min']:.1f} – {results['seed_timings_s'][f'stage.{k}']['max']:.1f})"
                          for k in STAGES + ("tune",)) + " |",
        "",
    ]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", nargs="+", type=int, default=[0, 1, 2], help="corpus seeds (default: 0 1 2)")
    ap.add_argument("--preset", choices=["tiny", "small", "paper"], default="paper",
                    help="sample-corpus preset of the per-seed pipeline (default: paper, the README's)")
    ap.add_argument("--tune-evaluations", type=int, default=12, help="tune.max_evaluations per seed (default: 12)")
    ap.add_argument("--work", type=Path, default=ROOT / "out" / "report", help="folder for the artifacts")
    ap.add_argument("--out", type=Path, default=ROOT / "docs", help="folder for results.md and results.json")
    ap.add_argument("--reuse-seeds", action="store_true",
                    help="read a seed's figures from its raw.json in --work when an earlier run of the same "
                         "commit and preset left one, instead of running it again")
    args = ap.parse_args(argv)
    if len(set(args.seeds)) != len(args.seeds):
        ap.error("--seeds: each seed once.")
    if args.tune_evaluations < 1:
        ap.error("--tune-evaluations must be at least 1.")
    os.environ.setdefault("PYOPENCL_CTX", "0")
    args.work, args.out = args.work.resolve(), args.out.resolve()  # commands run in other folders
    started = time.perf_counter()
    try:
        fs = facesynth_exe()
        host = host_info()
        host["copy_bandwidth_gb_s"] = copy_bandwidth()
        host["opencl"] = opencl_device()
        raws, reused = [], []
        for seed in args.seeds:
            raw = args.work / f"seed{seed}" / "raw.json"
            if args.reuse_seeds and raw.exists():
                say(f"seed {seed}: figures read from {raw}")
                raws.append(json.loads(raw.read_text(encoding="utf-8")))
                reused.append(seed)
                continue
            say(f"seed {seed}: pipeline ({args.preset} preset), evaluate, prune, searches, tune ...")
            raws.append(run_seed(fs, args.work, args.preset, seed, args.tune_evaluations))
            raw.write_text(json.dumps(raws[-1]), encoding="utf-8")
        paper = args.work / f"seed{args.seeds[0]}"
        if args.preset != "paper":
            paper = args.work / "paper"
            paper.mkdir(parents=True, exist_ok=True)
            build_chain(fs, paper, "paper", args.seeds[0], {})
        say("speed: DP benchmark, isomaps, make demo, rendering ...")
        speed = run_speed(fs, args.work, paper)
    except ReportError as exc:
        say(f"error: {exc}")
        return 1
    results = {"generated": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d"),
               "commit": _commit(), "preset": args.preset, "tune_evaluations": args.tune_evaluations,
               "host": host, **aggregate(raws), "speed": speed, "report_s": time.perf_counter() - started,
               "reused_seeds": reused}
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "results.json").write_text(json.dumps(results, indent=2) + "\n", encoding="utf-8")
    publish(args.out / "results.md", markdown(results))
    say(f"wrote {args.out / 'results.md'} and results.json in {results['report_s'] / 60:.1f} min")
    return 0


def _commit() -> str | None:
    """The repository's commit, with ``-dirty`` when the work tree has changes; None outside git."""
    try:
        head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"], cwd=ROOT, capture_output=True, text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return None
    return head + ("-dirty" if dirty else "")


if __name__ == "__main__":
    sys.exit(main())
