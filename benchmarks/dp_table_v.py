"""Paper Table V on this machine: the dense DP (the reference; ``synthesize.dp = "dense"``) for
14, 24, 53 and 63 phones on a paper-size database (about 5,556 nodes), on OpenCL against a
plain read of the same bytes in the same run, the default exact pruned DP beside it (its time,
the fraction of pair costs it computed, and that it found the same path and cost), and on the
NumPy path (what the fallback costs when no OpenCL device builds) on the same
database; the wall time of the whole ``facesynth synthesize`` command for the 63-phone phrase;
and the DP on 20,000 nodes with generated costs (time and peak memory). Prints JSON. Without
an OpenCL device that builds, only the NumPy figures are reported.

    python benchmarks/dp_table_v.py [--db out/bench/db.h5] [--skip-20k]
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from facesynth.base.config import Config
from facesynth.base.opencl import build, choice, context, queue, use_opencl
from facesynth.base.phonemes import PAU, cmudict, to_festival
from facesynth.domain.search.costs import step_costs
from facesynth.domain.search.dp import PANEL, OpenCLDp, PanelMatrix, dp_numpy
from facesynth.domain.search.pairs import transition_costs
from facesynth.domain.search.pruned import dp_pruned
from facesynth.formats.labels import Segment, write_textgrid
from facesynth.model.motiondb import MotionDatabase

PHRASES = {  # paper Table V
    14: "I know you meant it",
    24: "And so you just abandoned them",
    53: "Please go on because Jeff's father has no idea of how things became so horrible",
    63: "It is a fact that long words are difficult to articulate unless you concentrate",
}


def byte_compile() -> None:
    """Byte-compile the facesynth package, as an installed (not editable) copy is: timed
    commands then measure the program, not the compiling of its sources (which is what they
    would do on every run where PYTHONDONTWRITEBYTECODE is set)."""
    import compileall

    import facesynth

    compileall.compile_dir(str(Path(facesynth.__file__).parent), quiet=1)


def build_paper_db(folder: Path) -> Path:
    """Sample corpus 'paper' -> ... -> db.h5 (reused when present)."""
    from facesynth.domain.corpus.generate import generate
    from facesynth.stages import build_db, ingest, normalize, pca

    db = folder / "db.h5"
    if db.exists():
        return db
    folder.mkdir(parents=True, exist_ok=True)
    c = Config.load()
    generate(folder / "corpus", "paper", seed=0, overwrite=True)
    ingest.run(folder / "corpus" / "manifest.csv", folder / "corpus.h5", c.settings("ingest"),
               c.settings("align"), overwrite=True)
    normalize.run(folder / "corpus.h5", folder / "normalized.h5", c.settings("normalize"), overwrite=True)
    pca.run(folder / "normalized.h5", folder / "pca.h5", c.settings("pca"), overwrite=True)
    build_db.run(folder / "pca.h5", db, c.settings("build_db"), overwrite=True)
    return db


def phrase_phones(text: str, length: int) -> list[str]:
    """The phrase's Festival phones (CMU dictionary), framed by pauses, cut or repeated to ``length``."""
    cmu = cmudict()
    phones = [PAU] + [to_festival(p) for w in text.lower().split() for p in cmu[w.strip("?,.")][0]] + [PAU]
    while len(phones) < length:
        phones = phones[:-1] + phones[1:]
    return phones[: length - 1] + [PAU]


def write_phrase(phones: list[str], path: Path) -> None:
    t, segs = 0.0, []
    for p in phones:
        d = 0.25 if p == PAU else 0.09
        segs.append(Segment(round(t, 3), round(t + d, 3), p))
        t += d
    write_textgrid(path, {"phones": segs})


def read_floor(panels: np.ndarray, steps: int, repeats: int = 3) -> float:
    """Seconds to stream the panel-major matrix ``steps`` times (one read per DP step)."""
    import pyopencl as cl

    ctx, q = context(), queue()
    source = (Path(__file__).parent / "kernels" / "read_panels.cl").read_text("utf-8")
    k = build(source, "read_panels.cl", PANEL=PANEL).read_panels
    n = panels.shape[1]
    mf = cl.mem_flags
    buf = cl.Buffer(ctx, mf.READ_ONLY | mf.COPY_HOST_PTR, hostbuf=panels)
    out = cl.Buffer(ctx, mf.WRITE_ONLY, 4 * panels.shape[0])
    best = np.inf
    for _ in range(repeats):
        q.finish()
        t0 = time.perf_counter()
        for _ in range(steps):
            k(q, (panels.shape[0],), None, buf, np.int32(n), np.int32(panels.shape[0]), out)
        q.finish()
        best = min(best, time.perf_counter() - t0)
    return best


def time_dp(run, obs: np.ndarray, repeats: int = 3) -> tuple[float, object]:
    """Best of ``repeats`` wall times of ``run(obs)`` (seconds) and its result."""
    best, result = np.inf, None
    for _ in range(repeats):
        t0 = time.perf_counter()
        result = run(obs)
        best = min(best, time.perf_counter() - t0)
    return best, result


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--db", type=Path, default=None)
    ap.add_argument("--work", type=Path, default=Path("out/bench"))
    ap.add_argument("--skip-20k", action="store_true")
    args = ap.parse_args()
    db_path = args.db or build_paper_db(args.work)
    db = MotionDatabase.read(db_path)
    s = Config.load().settings("synthesize")
    costs = transition_costs(db, s)
    tc = costs.dense()  # the dense DP's matrix, computed once from the per-node features
    on_device = use_opencl(True)
    matrix = PanelMatrix.from_matrix(tc) if on_device else None
    runner = OpenCLDp(matrix) if on_device else None
    n = len(db.nodes)
    report = {"device": choice().description, "device_reason": choice().reason, "nodes": n, "panel": PANEL,
              "matrix_bytes": int(tc.nbytes), "phrases": []}
    for length, text in PHRASES.items():
        phones = phrase_phones(text, length)
        steps = step_costs(phones, ["neutral"] * length, db.nodes.phone, db.nodes.emotion, {}, s)
        numpy_s, ref = time_dp(lambda obs, tc=tc: dp_numpy(tc, obs), steps.total, repeats=2)
        row = {"phones": length, "text": text, "numpy_s": round(numpy_s, 4),
               "paper_gpu_s": {14: 50.828, 24: 90.891, 53: 232.078, 63: 256.484}[length]}
        pruned_s, (pruned, stats) = time_dp(lambda obs: dp_pruned(costs, obs), steps.total)
        row.update(pruned_s=round(pruned_s, 4), pairs_fraction=float(f"{stats.fraction:.3g}"),
                   pruned_identical_to_dense=bool(ref.cost == pruned.cost and (ref.path == pruned.path).all()))
        if on_device:
            dp_s, res = time_dp(runner.run, steps.total)
            floor_s = read_floor(matrix.panels, length - 1)
            row.update(dp_s=round(dp_s, 4), read_floor_s=round(floor_s, 4), ratio_to_read=round(dp_s / floor_s, 3),
                       read_gb_per_s=round(matrix.panels.nbytes * (length - 1) / floor_s / 1e9, 2),
                       numpy_to_opencl=round(numpy_s / dp_s, 2),
                       identical_to_reference=bool(ref.cost == res.cost and (ref.path == res.path).all()))
        report["phrases"].append(row)
    # The whole command, loading included, for the 63-phone phrase.
    tg = args.work / "phrase63.TextGrid"
    args.work.mkdir(parents=True, exist_ok=True)
    write_phrase(phrase_phones(PHRASES[63], 63), tg)
    exe = Path(sys.executable).with_name("facesynth")
    walls = []
    for _ in range(3):
        t0 = time.perf_counter()
        subprocess.run([str(exe), "synthesize", str(db_path), "--phonemes", str(tg), "-o", str(args.work / "m63.h5"),
                        "--overwrite", "-q"], check=True)
        walls.append(time.perf_counter() - t0)
    report["synthesize_command_63_phones_wall_s"] = round(min(walls), 3)
    del runner, matrix, tc
    if not args.skip_20k and on_device:
        report["nodes_20000"] = twenty_thousand()
    print(json.dumps(report, indent=2))


def twenty_thousand(n: int = 20000, steps: int = 63) -> dict:
    """The DP on generated costs for 20,000 nodes: time and this process's peak memory."""
    rng = np.random.default_rng(0)
    tc = np.empty((n, n), np.float32)
    for a in range(0, n, 2000):
        tc[a : a + 2000] = rng.random((min(2000, n - a), n), dtype=np.float32) * 100
    obs = (rng.random((steps, n), dtype=np.float32) * 100).astype(np.float32)
    t0 = time.perf_counter()
    runner = OpenCLDp(tc)
    upload_s = time.perf_counter() - t0
    dp_s, _ = time_dp(runner.run, obs, repeats=1)
    return {"nodes": n, "phones": steps, "matrix_gb": round(tc.nbytes / 1e9, 2), "buffers": len(runner.groups),
            "prepare_s": round(upload_s, 2), "dp_s": round(dp_s, 3),
            "peak_rss_gb": round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1e6, 2)}


if __name__ == "__main__":
    main()
