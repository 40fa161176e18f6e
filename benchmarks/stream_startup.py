"""The whole ``facesynth stream DB --audio WAV`` command, start to last frame, against another
checkout's in the same run. Prints JSON.

A stream of audio whose frames come from its voice (``stream.voice = "articulation"``, the
default) needs no search; a stream that takes the phones' path (``--set stream.voice=off``) does.
Each repetition runs both checkouts' commands in fresh processes, alternated, so that the shared
machine's drift falls on both alike. Reported per checkout and voice setting: wall seconds (min,
median) and the frames written (which must agree), and the ratio of the medians.

    facesynth sample-corpus corpus --preset small --seed 0
    facesynth ingest corpus/manifest.csv -o corpus.h5 && facesynth normalize corpus.h5 -o normalized.h5
    facesynth pca normalized.h5 -o pca.h5 && facesynth build-db pca.h5 -o db.h5
    python benchmarks/stream_startup.py --db db.h5 --audio corpus/audio/neutral_s016.wav \\
        --facesynth OTHER_CHECKOUT/.venv/bin/facesynth [--repeats 5]
"""

from __future__ import annotations

import argparse
import hashlib
import json
import shutil
import statistics
import subprocess
import time
from pathlib import Path


def run_once(facesynth: str, db: Path, audio: Path, voice: str) -> tuple[float, int, str]:
    """(wall s, frames written, sha256 of the output) of one command in a fresh process."""
    start = time.perf_counter()
    out = subprocess.run([facesynth, "stream", str(db), "--audio", str(audio), "--set", f"stream.voice={voice}"],
                         capture_output=True, check=True).stdout
    wall = time.perf_counter() - start
    return wall, sum(b'"type": "frame"' in line for line in out.splitlines()), hashlib.sha256(out).hexdigest()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--db", type=Path, required=True)
    parser.add_argument("--audio", type=Path, required=True)
    parser.add_argument("--facesynth", required=True, help="the other checkout's facesynth")
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    commands = {"this": shutil.which("facesynth") or "facesynth", "other": args.facesynth}
    out: dict = {"db": str(args.db), "audio": str(args.audio), "repeats": args.repeats}
    for voice in ("articulation", "off"):
        walls: dict[str, list[float]] = {k: [] for k in commands}
        outputs: dict[str, set] = {k: set() for k in commands}
        for _ in range(args.repeats):
            for name, command in commands.items():
                wall, frames, digest = run_once(command, args.db, args.audio, voice)
                walls[name].append(wall)
                outputs[name].add((frames, digest))
        out[voice] = {name: {"wall_s_min": round(min(w), 2), "wall_s_median": round(statistics.median(w), 2),
                             "frames": sorted(outputs[name])[0][0], "same_output_every_run": len(outputs[name]) == 1}
                      for name, w in walls.items()}
        out[voice]["same_output_as_other"] = outputs["this"] == outputs["other"]
        out[voice]["ratio_of_medians"] = round(out[voice]["other"]["wall_s_median"] / out[voice]["this"]["wall_s_median"], 2)
    print(json.dumps(out, indent=2))


if __name__ == "__main__":
    main()
