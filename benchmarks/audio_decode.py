"""How long :func:`facesynth.formats.audio.read_audio` takes on 10 s of speech-like sound as a
WAV (libsndfile) and as M4A (AAC), MP3 and Opus (the bundled ffmpeg, whose start is included).

    .venv/bin/python benchmarks/audio_decode.py [--seconds 10] [--repeats 7] > audio_decode.json

The sound is a seeded mix of a 140 Hz voice-like harmonic series under a 4 Hz syllable envelope
and noise, 16 kHz mono, written as a 16-bit WAV and encoded with the bundled ffmpeg (AAC and MP3
at 96 kb/s, Opus at 48 kb/s; a format whose encoder the build lacks is left out). Prints one JSON
object: per format the median and the fastest of ``--repeats`` reads (ms), the decoded rate and
samples, and the file's size.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import imageio_ffmpeg
import numpy as np

from facesynth.formats.audio import read_audio, write_wav

ENCODINGS = {"m4a": ["-c:a", "aac", "-b:a", "96k"], "mp3": ["-c:a", "libmp3lame", "-b:a", "96k"],
             "opus": ["-c:a", "libopus", "-b:a", "48k"]}


def speech_like(seconds: float, rate: int = 16000, seed: int = 0) -> np.ndarray:
    """(n,) float32: harmonics of 140 Hz under a 4 Hz envelope, with a little noise."""
    t = np.arange(int(seconds * rate)) / rate
    voice = sum(np.sin(2 * np.pi * 140 * k * t) / k for k in range(1, 12))
    envelope = 0.5 * (1 + np.sin(2 * np.pi * 4 * t)) ** 2
    noise = np.random.default_rng(seed).normal(0, 0.02, len(t))
    return (0.2 * voice * envelope / 4 + noise).astype(np.float32)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seconds", type=float, default=10.0)
    ap.add_argument("--repeats", type=int, default=7)
    args = ap.parse_args(argv)
    ffmpeg = imageio_ffmpeg.get_ffmpeg_exe()
    out: dict = {"seconds": args.seconds, "repeats": args.repeats, "formats": {}}
    with tempfile.TemporaryDirectory() as tmp:
        wav = Path(tmp) / "speech.wav"
        write_wav(wav, speech_like(args.seconds), 16000)
        files = {"wav": wav}
        for name, options in ENCODINGS.items():
            path = Path(tmp) / f"speech.{name}"
            done = subprocess.run([ffmpeg, "-hide_banner", "-nostdin", "-v", "error", "-y", "-i", str(wav), *options,
                                   str(path)], capture_output=True, check=False)
            if done.returncode == 0:
                files[name] = path
        for name, path in files.items():
            times = []
            for _ in range(args.repeats):
                t0 = time.perf_counter()
                samples, rate = read_audio(path)
                times.append(time.perf_counter() - t0)
            out["formats"][name] = {"median_ms": round(1000 * float(np.median(times)), 1),
                                    "fastest_ms": round(1000 * min(times), 1), "rate": rate,
                                    "samples": len(samples), "bytes": path.stat().st_size}
    json.dump(out, sys.stdout, indent=1)
    print()
    return 0


if __name__ == "__main__":
    sys.exit(main())
