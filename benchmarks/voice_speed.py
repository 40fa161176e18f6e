"""What the voice's articulation adds to ``facesynth synthesize --audio``: the whole command on a
real take of about 2 minutes (audio alone: the phones recognised), with the voice's articulation
(``synthesize.voice_recognized = "articulation"``, the default) and without it (``"off"``),
alternating, in fresh processes, in the same run; and the command's own ``the voice`` phase
(its ``-v`` line). Prints JSON.

    python benchmarks/voice_speed.py --audio FACEGOOD_DIR/wav/1114_2_04.wav --db out/bench/db.h5 [--repeats 3]

The issue's bound: the step adds at most 10% to the command.
"""

from __future__ import annotations

import argparse
import json
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from facesynth.formats.audio import read_audio

VOICE_PHASE = re.compile(r"the voice (\d+\.\d+) s\b")


def run(db: Path, audio: Path, out: Path, voice: str) -> tuple[float, float | None]:
    """(wall seconds of ``facesynth synthesize DB --audio AUDIO``, its voice phase in seconds or None)."""
    t0 = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "facesynth.cli", "synthesize", str(db), "--audio", str(audio), "-o",
                           str(out), "--overwrite", "-v", "--set", f"synthesize.voice_recognized={voice}"],
                          capture_output=True, text=True, check=False)
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
    args = ap.parse_args()
    samples, rate = read_audio(args.audio)
    walls: dict[str, list[float]] = {"articulation": [], "off": []}
    phases: list[float] = []
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(args.repeats):
            for voice in walls:
                wall, phase = run(args.db, args.audio, Path(tmp) / f"{voice}.h5", voice)
                walls[voice].append(wall)
                if voice == "articulation" and phase is not None:
                    phases.append(phase)
    on, off = statistics.median(walls["articulation"]), statistics.median(walls["off"])
    print(json.dumps({"audio": args.audio.name, "audio_s": round(len(samples) / rate, 1), "repeats": args.repeats,
                      "command_s_with_voice": round(on, 2), "command_s_without": round(off, 2),
                      "voice_phase_s": round(statistics.median(phases), 3) if phases else None,
                      "added_fraction": round(on / off - 1, 3),
                      "voice_phase_fraction": round(statistics.median(phases) / on, 3) if phases else None,
                      "walls": {k: [round(x, 2) for x in v] for k, v in walls.items()}}, indent=1))


if __name__ == "__main__":
    main()
