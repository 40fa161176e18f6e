"""What each ``facesynth batch`` output costs per line: one line of the sample corpus (its given
alignment, so no recognition) run in this process (as a worker runs it) once per output, the
database already loaded, and once with every rig output together (one solve for all). Prints
JSON (and writes it with ``--out``).

Reported per output: wall seconds of the whole line and of its outputs phase (the motion is
always written; ``anim`` deforms the corpus's plain mesh), the line's seconds of audio, and the
load average before and after (other work on the machine slows the wall-clock figures). The
render size is ``render.width`` x ``render.height`` (640 x 480 by default).

    python benchmarks/batch_outputs.py [--preset tiny] [--take neutral_s001] [--repeats 3]
"""

from __future__ import annotations

import argparse
import csv
import dataclasses
import json
import os
import platform
import shutil
import time
from pathlib import Path

import numpy as np
from batch_throughput import build_db

from facesynth.base.config import Config

OUTPUTS = ("motion", "curves", "arkit-csv", "gltf", "usd", "avi", "anim")


def measure(corpus: Path, db: Path, take: str, work: Path, repeats: int) -> dict:
    from facesynth.domain.batch.job import prepare
    from facesynth.domain.batch.line import run_line
    from facesynth.domain.batch.script import read_script
    from facesynth.formats import usd

    row = next(r for r in csv.DictReader(open(corpus / "manifest.csv", encoding="utf-8")) if r["take"] == take)
    script = work / "script.csv"
    with open(script, "w", newline="", encoding="utf-8") as fh:
        csv.writer(fh).writerows([("id", "audio", "alignment"),
                                  ("line", str(corpus / row["audio"]), str(corpus / row["alignment"]))])
    config = Config.load()
    values = [config.settings(n) for n in ("batch", "synthesize", "ingest", "align", "deform", "render")]
    line = read_script(script)[0]
    kinds = [(k,) for k in OUTPUTS if k != "usd" or usd.available()]
    kinds.append(tuple(k for k in ("curves", "arkit-csv", "gltf", "usd", "avi") if k != "usd" or usd.available()))
    result = {}
    for outputs in [("motion",)] + kinds:  # the first run loads the database
        values[0] = dataclasses.replace(values[0], outputs=outputs)
        walls, phases = [], []
        for _ in range(repeats):
            out = work / "lines"
            shutil.rmtree(out, ignore_errors=True)
            _, job = prepare(script, db, out, *values, mesh=corpus / "face.obj", binding=corpus / "markers.csv")
            started = time.perf_counter()
            r = run_line(line, job)
            walls.append(time.perf_counter() - started)
            if r.status != "ok":
                raise SystemExit(f"{','.join(outputs)}: {r.reason}")
            phases.append(r.outputs_s)
        result[",".join(outputs)] = {"line_s": round(float(np.median(walls)), 3),
                                     "outputs_s": round(float(np.median(phases)), 3), "audio_s": round(r.audio_s, 3)}
    return result


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--preset", default="tiny")
    parser.add_argument("--take", default="neutral_s001")
    parser.add_argument("--repeats", type=int, default=3, help="runs per output; the median is reported")
    parser.add_argument("--work", type=Path, default=Path("out/bench-batch"))
    parser.add_argument("--out", type=Path, default=None)
    args = parser.parse_args()
    folder = args.work / args.preset
    db = build_db(folder, args.preset)
    render = Config.load().settings("render")
    result = {"machine": {"cores": os.cpu_count(), "processor": platform.processor() or platform.machine(),
                          "load_average_at_start": [round(x, 2) for x in os.getloadavg()]},
              "preset": args.preset, "take": args.take, "render_size": [render.width, render.height],
              "repeats": args.repeats, "outputs": measure(folder / "corpus", db, args.take, folder, args.repeats)}
    result["machine"]["load_average_at_end"] = [round(x, 2) for x in os.getloadavg()]
    text = json.dumps(result, indent=2)
    print(text)
    if args.out:
        args.out.write_text(text + "\n")


if __name__ == "__main__":
    main()
