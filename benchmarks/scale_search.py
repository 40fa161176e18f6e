"""The exact pruned search at scale: databases of hours of capture made by replicating the
paper preset's training takes with variation, and for each size N the build-db time, peak
memory and file size, the whole ``facesynth synthesize`` command for paper Table V's 14, 24,
53 and 63-phone phrases (time and peak memory), the fraction of the dense DP's pair costs the
search computed, and, where N x N float32 fits in memory, the dense DP's floor measured in the
same run: one plain read of the panel-major N x N matrix per step. Prints JSON.

Replication (:func:`replicate`): copy c of every training take is time-warped by a factor
drawn from [0.92, 1.08] (coefficients linearly interpolated, head motion by nearest frame,
phone times scaled) and gets Gaussian noise of 2% of each PCA component's standard deviation
per frame plus a per-copy offset of 5%; its markers are the PCA reconstruction. Held-out
takes are kept once. Deterministic for a seed.

Commands run in child processes; each child reports its own peak resident memory (VmHWM of
/proc/self/status) and the parent times it.

    python benchmarks/scale_search.py [--pca out/scale/pca.h5] [--copies 1 4 18] [--work out/scale] [--out docs]

With ``--out`` it also writes ``scale.json`` (the JSON below) and ``scale.md`` (its tables) there.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from facesynth.domain.search.pairs import transition_costs

HERE = Path(__file__).resolve().parent
LENGTHS = (14, 24, 53, 63)


def vm_hwm_gb() -> float:
    """This process's peak resident memory (VmHWM), GB."""
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith("VmHWM:"):
            return int(line.split()[1]) * 1024 / 1e9
    return float("nan")


def replicate(pca_in: Path, pca_out: Path, copies: int, seed: int = 0) -> dict:
    """Write ``pca_out``: ``pca_in`` with every training take present ``copies`` times (copy 0
    unchanged, the others time-warped and noisy, see the module docstring)."""
    from facesynth.model.frames import HeadFrames
    from facesynth.model.pca import PcaFrames
    from facesynth.model.tables import Phones, Takes

    src = PcaFrames.read(pca_in)
    rng = np.random.default_rng(seed)
    coeffs, model, takes, phones = src.coefficients, src.model, src.takes, src.phones
    std = coeffs.std(axis=0).astype(np.float32)
    out_takes = {k: [] for k in ("name", "emotion", "sentence", "split", "transcript", "frame_start", "frame_count")}
    out_phones = {k: [] for k in ("take", "start", "end", "phone")}
    parts, heads_r, heads_t, markers = [], [], [], []
    start = 0
    for c in range(copies):
        for t in range(len(takes)):
            if c > 0 and takes.split[t] != "train":
                continue
            frames = takes.frames(t)
            count = frames.stop - frames.start
            factor = 1.0 if c == 0 else float(rng.uniform(0.92, 1.08))
            new_count = max(2, int(round(count * factor)))
            x = np.linspace(0.0, count - 1, new_count)
            lo = np.floor(x).astype(int)
            hi = np.minimum(lo + 1, count - 1)
            w = (x - lo)[:, None].astype(np.float32)
            block = coeffs[frames][lo] * (1 - w) + coeffs[frames][hi] * w
            if c > 0:
                block = block + std * (0.05 * rng.standard_normal(len(std)).astype(np.float32)
                                       + 0.02 * rng.standard_normal(block.shape).astype(np.float32))
            nearest = frames.start + np.rint(x).astype(int)
            parts.append(block.astype(np.float32))
            markers.append(model.reconstruct(block) if c > 0 else src.frames.markers[frames])
            heads_r.append(src.frames.head_rotation[nearest])
            heads_t.append(src.frames.head_translation[nearest])
            for key in ("emotion", "sentence", "split", "transcript"):
                out_takes[key].append(getattr(takes, key)[t])
            out_takes["name"].append(takes.name[t] if c == 0 else f"{takes.name[t]}~{c}")
            out_takes["frame_start"].append(start)
            out_takes["frame_count"].append(new_count)
            scale = (new_count - 1) / max(count - 1, 1)
            for r in np.nonzero(phones.take == t)[0]:
                out_phones["take"].append(len(out_takes["name"]) - 1)
                out_phones["start"].append(phones.start[r] * scale)
                out_phones["end"].append(phones.end[r] * scale)
                out_phones["phone"].append(phones.phone[r])
            start += new_count
    new_takes = Takes(*(out_takes[k] for k in ("name", "emotion", "sentence", "split", "transcript")),
                      np.array(out_takes["frame_start"], np.int64), np.array(out_takes["frame_count"], np.int64))
    new_phones = Phones(np.array(out_phones["take"], np.int64), np.array(out_phones["start"]), np.array(out_phones["end"]),
                        out_phones["phone"])
    frames = HeadFrames(np.concatenate(markers).astype(np.float32), src.frames.reference, np.concatenate(heads_r),
                        np.concatenate(heads_t), src.frames.fps, src.frames.origin_marker)
    out = PcaFrames(new_takes, new_phones, src.marker_names, model, np.concatenate(parts), frames)
    out.write(pca_out, config="{}", inputs=[pca_in], overwrite=True)
    return {"takes": len(new_takes), "frames": int(start)}


def paper_pca(work: Path) -> Path:
    """The paper preset's pca.h5 (seed 0), made once."""
    from facesynth.base.config import Config
    from facesynth.domain.corpus.generate import generate
    from facesynth.stages import ingest, normalize, pca

    out = work / "pca.h5"
    if out.exists():
        return out
    work.mkdir(parents=True, exist_ok=True)
    c = Config.load()
    generate(work / "corpus", "paper", seed=0, overwrite=True)
    ingest.run(work / "corpus" / "manifest.csv", work / "corpus.h5", c.settings("ingest"), c.settings("align"), overwrite=True)
    normalize.run(work / "corpus.h5", work / "normalized.h5", c.settings("normalize"), overwrite=True)
    pca.run(work / "normalized.h5", out, c.settings("pca"), overwrite=True)
    return out


def child(args: list[str]) -> dict:
    """Run ``python scale_search.py --child ARGS`` and return its JSON line with the wall time."""
    t0 = time.perf_counter()
    done = subprocess.run([sys.executable, str(Path(__file__).resolve()), "--child", *args], check=True,
                          capture_output=True, text=True)
    wall = time.perf_counter() - t0
    record = json.loads(done.stdout.strip().splitlines()[-1])
    record["wall_s"] = round(wall, 3)
    return record


def child_main(args: list[str]) -> None:
    """In the child: ``cli ...`` runs a facesynth command; ``search DB WORK`` measures the search."""
    if args[0] == "cli":
        from facesynth.cli import main

        try:
            main(args[1:], standalone_mode=False)
        finally:
            print(json.dumps({"peak_gb": round(vm_hwm_gb(), 3)}))
    elif args[0] == "search":
        print(json.dumps(search_figures(Path(args[1]), Path(args[2]), args[3:])))


def search_figures(db_path: Path, work: Path, overrides: list[str]) -> dict:
    """The pruned DP alone on each Table V phrase: seconds (best of 2), fraction of pair costs,
    columns evaluated; and the dense floor (one plain read of N x N float32 per step) where it fits."""
    from dp_table_v import PHRASES, phrase_phones

    from facesynth.base.config import Config
    from facesynth.base.opencl import use_opencl
    from facesynth.domain.search.costs import step_costs
    from facesynth.domain.search.pruned import dp_pruned
    from facesynth.model.motiondb import MotionDatabase

    s = Config.load(None, tuple(overrides)).settings("synthesize")
    db = MotionDatabase.read(db_path)
    n = len(db.nodes)
    tc = transition_costs(db, s, use_opencl(s.use_opencl))
    rows = []
    for length in LENGTHS:
        phones = phrase_phones(PHRASES[length], length)
        obs = step_costs(phones, ["neutral"] * length, db.nodes.phone, db.nodes.emotion, {}, s).total
        best = np.inf
        for _ in range(2):
            t0 = time.perf_counter()
            res, stats = dp_pruned(tc, obs)
            best = min(best, time.perf_counter() - t0)
        rows.append({"phones": length, "dp_s": round(best, 4), "pairs_fraction": float(f"{stats.fraction:.3g}"),
                     "pairs": stats.pairs, "columns_evaluated": int(sum(stats.columns)), "cost": res.cost})
    out = {"nodes": n, "settings": overrides, "phrases": rows}
    if 4 * n * n <= FLOOR_MAX_BYTES and use_opencl(True):
        out["dense_read_floor_s"] = {str(length): round(read_floor(n, length - 1), 4) for length in LENGTHS}
    out["peak_gb"] = round(vm_hwm_gb(), 3)
    return out


#: The dense floor is measured only where an N x N float32 matrix takes at most this.
FLOOR_MAX_BYTES = 6 << 30


def read_floor(n: int, steps: int, repeats: int = 2) -> float:
    """Seconds to stream an N x N panel-major float32 matrix ``steps`` times with
    ``kernels/read_panels.cl`` (the dense DP's floor), from page-aligned host memory."""
    import pyopencl as cl

    from facesynth.base.opencl import aligned_empty, build, context, queue
    from facesynth.domain.search.dp import PANEL

    ctx, q = context(), queue()
    n_panels = -(-n // PANEL)
    panels = aligned_empty((n_panels, n, PANEL), np.float32)
    panels.fill(1.0)
    k = build((HERE / "kernels" / "read_panels.cl").read_text("utf-8"), "read_panels.cl", PANEL=PANEL).read_panels
    buf = cl.Buffer(ctx, cl.mem_flags.READ_ONLY | cl.mem_flags.USE_HOST_PTR, hostbuf=panels)
    out = cl.Buffer(ctx, cl.mem_flags.WRITE_ONLY, 4 * n_panels)
    best = np.inf
    for _ in range(repeats):
        q.finish()
        t0 = time.perf_counter()
        for _ in range(steps):
            k(q, (n_panels,), None, buf, np.int32(n), np.int32(n_panels), out)
        q.finish()
        best = min(best, time.perf_counter() - t0)
    return best


def main() -> None:
    if len(sys.argv) > 1 and sys.argv[1] == "--child":
        sys.path.insert(0, str(HERE))
        child_main(sys.argv[2:])
        return
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pca", type=Path, default=None, help="a pca.h5 to replicate (default: the paper preset's, made in --work)")
    ap.add_argument("--copies", type=int, nargs="+", default=[1, 4, 18])
    ap.add_argument("--work", type=Path, default=Path("out/scale"))
    ap.add_argument("--weak", nargs="*", default=["synthesize.pnt=1e-6"],
                    help="settings that weaken the bounds, measured at the smallest size")
    ap.add_argument("--out", type=Path, default=None, help="folder for scale.json and scale.md")
    args = ap.parse_args()
    sys.path.insert(0, str(HERE))
    from dp_table_v import PHRASES, byte_compile, phrase_phones, write_phrase

    byte_compile()

    args.work.mkdir(parents=True, exist_ok=True)
    pca = args.pca or paper_pca(args.work)
    for length in LENGTHS:
        write_phrase(phrase_phones(PHRASES[length], length), args.work / f"phrase{length}.TextGrid")
    report = {"host": host(), "sizes": []}
    for copies in args.copies:
        folder = args.work / f"x{copies}"
        folder.mkdir(exist_ok=True)
        big = folder / "pca.h5"
        if copies == 1:
            big = pca
        elif not big.exists():
            replicate(pca, big, copies)
        db = folder / "db.h5"
        build = child(["cli", "build-db", str(big), "-o", str(db), "--overwrite", "-q"])
        row = {"copies": copies, "build_db_s": build["wall_s"], "build_db_peak_gb": build["peak_gb"],
               "db_mb": round(db.stat().st_size / 1e6, 1), "synthesize": []}
        for length in LENGTHS:
            runs = [child(["cli", "synthesize", str(db), "--phonemes", str(args.work / f"phrase{length}.TextGrid"),
                           "-o", str(folder / f"m{length}.h5"), "--overwrite", "-q"]) for _ in range(2)]
            fastest = min(runs, key=lambda r: r["wall_s"])
            row["synthesize"].append({"phones": length, "command_s": fastest["wall_s"], "peak_gb": fastest["peak_gb"]})
        row["search"] = child(["search", str(db), str(args.work)])
        row["nodes"] = row["search"]["nodes"]
        if copies == min(args.copies) and args.weak:
            row["search_weak"] = child(["search", str(db), str(args.work), *args.weak])
        report["sizes"].append(row)
        print(json.dumps(row), file=sys.stderr, flush=True)
    print(json.dumps(report, indent=1))
    if args.out is not None:
        args.out.mkdir(parents=True, exist_ok=True)
        (args.out / "scale.json").write_text(json.dumps(report, indent=1) + "\n", encoding="utf-8")
        (args.out / "scale.md").write_text(markdown(report), encoding="utf-8")


def host() -> dict:
    """The processor count, memory and load average of the machine, and the OpenCL device."""
    import os

    from facesynth.base.opencl import choice

    mem = next((int(line.split()[1]) for line in Path("/proc/meminfo").read_text().splitlines()
                if line.startswith("MemTotal:")), 0)
    return {"cpus": os.cpu_count(), "memory_gb": round(mem * 1024 / 1e9, 1),
            "load_average_at_start": [round(x, 2) for x in os.getloadavg()], "device": choice().description}


def markdown(report: dict) -> str:
    """``docs/scale.md``: the tables of a :func:`main` report."""
    h = report["host"]
    lines = ["# The exact search at scale", "",
             "Written by `benchmarks/scale_search.py --out docs` (do not edit); every number is in `scale.json`. "
             f"Host: {h['cpus']} processors, {h['memory_gb']} GB, {h['device']}; load average when the run started "
             f"{h['load_average_at_start'][0]} (other work on a shared machine slows every figure).", "",
             "Databases: the paper preset's training takes replicated with time-warp and noise (the script's docstring). "
             "Times are wall-clock seconds of fresh processes (start-up included), peaks are each process's VmHWM.", "",
             "| nodes | build-db (s) | build-db peak (GB) | db.h5 (MB) | synthesize 14 / 24 / 53 / 63 phones (s) "
             "| synthesize peak (GB) | search alone, 63 phones (s) | pair costs computed (63 phones) | dense read floor, 63 phones (s) |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in report["sizes"]:
        syn = " / ".join(f"{x['command_s']:.2f}" for x in r["synthesize"])
        peak = max(x["peak_gb"] for x in r["synthesize"])
        last = r["search"]["phrases"][-1]
        floor = r["search"].get("dense_read_floor_s", {}).get("63")
        lines.append(f"| {r['nodes']:,} | {r['build_db_s']:.1f} | {r['build_db_peak_gb']:.2f} | {r['db_mb']:.0f} | {syn} | "
                     f"{peak:.2f} | {last['dp_s']:.2f} | {last['pairs_fraction']:.2g} | "
                     f"{'does not fit' if floor is None else f'{floor:.2f}'} |")
    weak = [r for r in report["sizes"] if "search_weak" in r]
    if weak:
        r = weak[0]
        lines += ["", f"Weights that make the bounds weak ({', '.join(r['search_weak']['settings'])}; {r['nodes']:,} nodes): "
                  "the search stays exact and gets slower.", "",
                  "| phones | search, default weights (s) | search, weak bounds (s) | slowdown | pair costs computed (weak) |",
                  "|---|---|---|---|---|"]
        for a, b in zip(r["search"]["phrases"], r["search_weak"]["phrases"]):
            lines.append(f"| {a['phones']} | {a['dp_s']:.3f} | {b['dp_s']:.3f} | {b['dp_s'] / a['dp_s']:.0f}x | "
                         f"{b['pairs_fraction']:.2g} |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()
