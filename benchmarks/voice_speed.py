"""What the voice's articulation adds to ``facesynth synthesize --audio``: the whole command on a
real take of about 2 minutes (audio alone: the phones recognised), with the voice's articulation
(``synthesize.voice_recognized = "articulation"``, the default) and without it (``"off"``),
alternating, in fresh processes, in the same run; and the command's own ``the voice`` phase
(its ``-v`` line). With ``--against CHECKOUT`` (another checkout of facesynth, e.g. ``git worktree
add`` of an earlier commit) its default command runs too, with the same interpreter and the other
checkout's code first on ``PYTHONPATH``, alternated with this one's. Prints JSON.

    python benchmarks/voice_speed.py --audio FACEGOOD_DIR/wav/1114_2_04.wav --db out/bench/db.h5 [--repeats 3] \
        [--against OTHER_CHECKOUT]

The issue's bound: the step adds at most 10% to the command, and the command stays within 10% of
its time when the issue was filed.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from facesynth.formats.audio import read_audio

VOICE_PHASE = re.compile(r"the voice (\d+\.\d+) s\b")


def run(db: Path, audio: Path, out: Path, voice: str | None, checkout: Path | None = None) -> tuple[float, float | None]:
    """(wall seconds of ``facesynth synthesize DB --audio AUDIO``, its voice phase in seconds or None):
    with ``synthesize.voice_recognized = voice`` (None: the checkout's default), the code of
    ``checkout`` (None: this one's)."""
    env = dict(os.environ, PYTHONPATH=str(checkout)) if checkout is not None else None
    given = ["--set", f"synthesize.voice_recognized={voice}"] if voice is not None else []
    t0 = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "facesynth.cli", "synthesize", str(db), "--audio", str(audio), "-o",
                           str(out), "--overwrite", "-v", *given], capture_output=True, text=True, check=False,
                          cwd=tempfile.gettempdir() if checkout is not None else None, env=env)
    wall = time.perf_counter() - t0
    if done.returncode:
        raise SystemExit(f"synthesize failed: {done.stderr.strip()}")
    found = VOICE_PHASE.search(done.stdout + done.stderr)
    return wall, float(found.group(1)) if found else None


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--audio", type=Path, required=True)
    ap.add_argument("--db", type=Path, required=True)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--against", type=Path, default=None, help="another checkout whose default command runs too")
    args = ap.parse_args()
    samples, rate = read_audio(args.audio)
    walls: dict[str, list[float]] = {"articulation": [], "off": []}
    if args.against is not None:
        walls["other"] = []
    phases: list[float] = []
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(args.repeats):
            for voice in walls:
                other = voice == "other"
                wall, phase = run(args.db.resolve(), args.audio.resolve(), Path(tmp) / f"{voice}.h5",
                                  None if other else voice, args.against.resolve() if other else None)
                walls[voice].append(wall)
                if voice == "articulation" and phase is not None:
                    phases.append(phase)
    on, off = statistics.median(walls["articulation"]), statistics.median(walls["off"])
    out = {"audio": args.audio.name, "audio_s": round(len(samples) / rate, 1), "repeats": args.repeats,
           "command_s_with_voice": round(on, 2), "command_s_without": round(off, 2),
           "voice_phase_s": round(statistics.median(phases), 3) if phases else None,
           "added_fraction": round(on / off - 1, 3),
           "voice_phase_fraction": round(statistics.median(phases) / on, 3) if phases else None,
           "walls": {k: [round(x, 2) for x in v] for k, v in walls.items()}}
    if args.against is not None:  # this default (the voice on) against the other checkout's, run by run
        out["against"] = {"checkout": commit_of(args.against),
                          "ratio_of_medians": round(on / statistics.median(walls["other"]), 3),
                          "ratio_per_run": [round(a / b, 3) for a, b in zip(walls["articulation"], walls["other"])]}
    print(json.dumps(out, indent=1))


def commit_of(checkout: Path) -> str | None:
    """The commit ``checkout`` is at (None where git cannot say)."""
    done = subprocess.run(["git", "-C", str(checkout), "rev-parse", "HEAD"], capture_output=True, text=True, check=False)
    return done.stdout.strip() or None


if __name__ == "__main__":
    main()
