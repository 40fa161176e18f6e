"""The whole ``facesynth synthesize`` command against the read floor, measured in the same run.
Prints JSON.

For the 63-phone phrase of paper Table V and the paper preset, each repetition runs the
command in a fresh process (``-v``) and then the read floor in this process: the panel-major
N x N matrix streamed once per DP step (62 reads for 63 phones) by the OpenCL read kernel of
``dp_table_v.py``: the floor of the dense DP, which the default (pruned) search is not bound by. Reported: the command's time from process start to output file
written (min and median), to process exit, the floor (min and median), their ratio, and the
command's own per-phase breakdown (its ``-v`` line) with start-up, the time it does not
itself report (interpreter, imports, settings, reading the utterance), as the remainder.

    python benchmarks/synthesize_startup.py --db out/bench/db.h5 [--repeats 7]
    python benchmarks/synthesize_startup.py --build-paper [--work out/bench]
    python benchmarks/synthesize_startup.py --db DB --facesynth OTHER_CHECKOUT/.venv/bin/facesynth

"File written" is the output's status-change time, which the final rename sets (file system
clock, a few milliseconds coarse).
"""

from __future__ import annotations

import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
from dp_table_v import PHRASES, build_paper_db, byte_compile, phrase_phones, read_floor, write_phrase

from facesynth.base.opencl import device_name
from facesynth.model.motiondb import MotionDatabase

PHONES = 63
PHASE = re.compile(r"([A-Za-z][A-Za-z -]*?) (\d+\.\d+) s\b")


def run_command(exe: Path, db: Path, phrase: Path, out: Path) -> dict:
    """One fresh ``facesynth synthesize -v``: seconds to the output written and to exit, and its phases."""
    out.unlink(missing_ok=True)
    start = time.time_ns()
    done = subprocess.run([str(exe), "synthesize", str(db), "--phonemes", str(phrase), "-o", str(out), "-v"],
                          capture_output=True, text=True)
    exit_s = (time.time_ns() - start) / 1e9
    if done.returncode != 0:
        raise SystemExit(f"facesynth synthesize failed:\n{done.stderr}")
    written_s = (out.stat().st_ctime_ns - start) / 1e9
    line = next((ln for ln in done.stderr.splitlines() if ln.startswith(("phases:", "load "))), "")
    phases = {name.strip(): float(value) for name, value in PHASE.findall(line.split(";")[0])}
    return {"written_s": written_s, "exit_s": exit_s, "phases": phases}


def summary(values: list[float]) -> dict:
    return {"min": round(min(values), 3), "median": round(statistics.median(values), 3)}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--db", type=Path, default=None, help="A paper-size motiondb (default: --build-paper).")
    ap.add_argument("--build-paper", action="store_true", help="Build the paper preset database in --work (reused).")
    ap.add_argument("--work", type=Path, default=Path("out/bench"))
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--facesynth", type=Path, default=Path(sys.executable).with_name("facesynth"),
                    help="The command to time (e.g. another checkout's).")
    args = ap.parse_args()
    if args.db is None and not args.build_paper:
        ap.error("give --db or --build-paper")
    byte_compile()
    db_path = args.db or build_paper_db(args.work)
    args.work.mkdir(parents=True, exist_ok=True)
    phrase, out = args.work / f"phrase{PHONES}.TextGrid", args.work / f"m{PHONES}_startup.h5"
    write_phrase(phrase_phones(PHRASES[PHONES], PHONES), phrase)

    db = MotionDatabase.read(db_path)
    # The dense DP's floor: N x N float32 in the panel-major layout, streamed once per step (the
    # values do not matter to a read, so the matrix is not computed).
    from facesynth.base.opencl import aligned_empty
    from facesynth.domain.search.dp import PANEL

    n = len(db.nodes)
    panels = aligned_empty((-(-n // PANEL), n, PANEL), np.float32)
    panels.fill(1.0)
    read_floor(panels, 1, repeats=1)  # build the read kernel before timing
    runs, floors = [], []
    for _ in range(args.repeats):
        runs.append(run_command(args.facesynth, db_path, phrase, out))
        floors.append(read_floor(panels, PHONES - 1, repeats=1))
    best = min(runs, key=lambda r: r["written_s"])
    written = [r["written_s"] for r in runs]
    phase_names = list(best["phases"])
    reported = {name: summary([r["phases"][name] for r in runs]) for name in phase_names}
    startup = [r["written_s"] - sum(r["phases"].values()) for r in runs]
    report = {
        "command": f"facesynth synthesize ({PHONES} phones of paper Table V) -v",
        "facesynth": "this environment's" if args.facesynth == Path(sys.executable).with_name("facesynth")
        else str(args.facesynth), "device": device_name(), "nodes": len(db.nodes),
        "cpus": os.cpu_count(), "repeats": args.repeats,
        "command_to_file_written_s": summary(written),
        "command_to_exit_s": summary([r["exit_s"] for r in runs]),
        "read_floor_s": summary(floors),
        "ratio_to_read_floor": {"min": round(min(written) / min(floors), 2),
                                "median": round(statistics.median(written) / statistics.median(floors), 2)},
        "phases_s": {"start-up (interpreter, imports, settings, utterance)": summary(startup), **reported,
                     "exit (after the file is written)": summary([r["exit_s"] - r["written_s"] for r in runs])},
        "fastest_run_phases_s": {"start-up": round(best["written_s"] - sum(best["phases"].values()), 3),
                                 **{k: round(v, 3) for k, v in best["phases"].items()}},
    }
    print(json.dumps(report, indent=2))


if __name__ == "__main__":
    os.environ.setdefault("PYOPENCL_CTX", "0")
    main()
