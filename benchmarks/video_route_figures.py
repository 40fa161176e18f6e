"""The figures of docs/inputs.md's video route: the virtual actress filmed (her captured take
solved onto the built-in rig and rendered frontally with its sound, standing in for a filmed
face), taken back through the video route as docs/inputs.md runs it (``ingest`` with MediaPipe
Face Mesh, ``normalize``, ``solve`` with the Face Mesh binding that ships), and the rig those curves pose drawn
beside the film at rest and mid-sentence.

    .venv/bin/python benchmarks/video_route_figures.py --work out/figures --out docs/images

(``make figures``; needs ``facesynth[video]``; about a minute on two cores.) Writes
``OUT/video_actress_rest.png`` and ``OUT/video_actress_speaking.png`` (each the film's frame on
the left, the rig posed by the solved curves on the right, 240 x 240 pixels a side) and prints
JSON: the frames shown (rest: the capture's least open jaw in the take's first half second;
mid-sentence: its widest opening), the rig weights solved there that are above 0.05, and the
largest at rest. The work folder keeps every artifact of the chain (reused while it exists).
"""

from __future__ import annotations

import argparse
import csv
import dataclasses
import json
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import numpy as np

from facesynth.base.config import Config
from facesynth.domain.rendering.video import ShadedView
from facesynth.domain.rig.face import load_face_rig
from facesynth.model.curves import RigCurves

#: Pixels of each half of a figure.
SIZE = 240


def _facesynth(*args: str) -> None:
    """Run one facesynth command (quietly), failing loudly."""
    subprocess.run([sys.executable, "-m", "facesynth.cli", *args, "-q"], check=True)


def _made(path: Path, *args: str) -> Path:
    """``path`` made by ``facesynth ARGS -o path`` unless it exists."""
    if not path.exists():
        _facesynth(*args, "-o", str(path))
    return path


def _chain(work: Path) -> tuple[Path, Path, Path, str]:
    """The film (AVI), the capture's curves, the video route's curves and the take's name."""
    corpus = work / "corpus"
    if not (corpus / "manifest.csv").exists():
        _facesynth("sample-corpus", str(corpus), "--preset", "tiny", "--seed", "0")
    with open(corpus / "manifest.csv", encoding="utf-8", newline="") as fh:
        take = next(row["take"] for row in csv.DictReader(fh) if row.get("split") == "test")
    h5 = _made(work / "corpus.h5", "ingest", str(corpus / "manifest.csv"))
    normalized = _made(work / "normalized.h5", "normalize", str(h5))
    pca = _made(work / "pca.h5", "pca", str(normalized))
    db = _made(work / "db.h5", "build-db", str(pca))
    truth = _made(work / "truth.h5", "capture", str(h5), "--db", str(db), "--take", take)
    truth_curves = _made(work / "truth_curves.h5", "solve", str(truth))
    film = work / f"{take}.avi"
    if not film.exists():  # frontal, as a face is filmed
        _facesynth("render", str(truth_curves), "--audio", str(corpus / "audio" / f"{take}.wav"), "-o", str(film),
                   "--set", "render.yaw_deg=0", "--set", "render.pitch_deg=0", "--set", "render.width=480",
                   "--set", "render.height=480")
    manifest = work / "filmed.csv"
    manifest.write_text(f"take,mocap\nfilmed,{film.name}\n", encoding="utf-8")
    filmed = _made(work / "filmed.h5", "ingest", str(manifest))
    filmed_normalized = _made(work / "filmed_normalized.h5", "normalize", str(filmed))
    curves = _made(work / "filmed_curves.h5", "solve", str(filmed_normalized))  # the shipped Face Mesh binding
    return film, truth_curves, curves, take


def _film_frame(film: Path, index: int) -> np.ndarray:
    """Frame ``index`` of the film, (H, W, 3) uint8."""
    import imageio_ffmpeg

    reader = imageio_ffmpeg.read_frames(str(film))
    meta = next(reader)
    width, height = meta["size"]
    for k, raw in enumerate(reader):
        if k == index:
            reader.close()
            return np.frombuffer(raw, np.uint8).reshape(height, width, 3)
    raise ValueError(f"{film} has no frame {index}")


def _figure(film_frame: np.ndarray, rig_frame: np.ndarray, out: Path) -> None:
    from PIL import Image

    halves = [Image.fromarray(img).resize((SIZE, SIZE), Image.Resampling.LANCZOS) for img in (film_frame, rig_frame)]
    figure = Image.new("RGB", (2 * SIZE, SIZE))
    figure.paste(halves[0], (0, 0))
    figure.paste(halves[1], (SIZE, 0))
    figure.save(out, optimize=True)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--work", type=Path, required=True, help="folder for the chain's artifacts (reused)")
    parser.add_argument("--out", type=Path, required=True, help="folder the PNGs go to (docs/images)")
    args = parser.parse_args(argv)
    args.work.mkdir(parents=True, exist_ok=True)
    args.out.mkdir(parents=True, exist_ok=True)
    film, truth_path, curves_path, take = _chain(args.work)
    truth, solved = RigCurves.read(truth_path), RigCurves.read(curves_path)
    jaw = truth.weights[:, truth.shape_names.index("jawOpen")]
    first = max(1, int(round(0.5 * truth.fps)))
    frames = {"rest": int(np.argmin(jaw[:first])), "speaking": int(np.argmax(jaw))}
    rig = load_face_rig()
    settings = dataclasses.replace(Config.load().settings("render"), width=480, height=480, yaw_deg=0.0, pitch_deg=0.0,
                                   use_opencl=False)
    view = ShadedView(SimpleNamespace(rest=rig.neutral, faces=rig.faces, gaze=None), settings, 480)
    names = list(solved.shape_names)
    report: dict = {"take": take, "film": film.name, "frames": {}}
    for label, index in frames.items():
        k = min(index, solved.n_frames - 1)
        weights = np.asarray(solved.weights[k], np.float64)
        _figure(_film_frame(film, index), view.frame(rig.evaluate(weights), k), args.out / f"video_actress_{label}.png")
        on = {names[i]: round(float(weights[i]), 3) for i in np.argsort(-weights) if weights[i] > 0.05}
        report["frames"][label] = {"frame": index, "capture_jawOpen": round(float(jaw[index]), 3), "solved_above_0.05": on,
                                   "largest": round(float(weights.max()), 3)}
    print(json.dumps(report, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
