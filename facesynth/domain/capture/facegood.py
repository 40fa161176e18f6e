"""A real performer one command away: FACEGOOD's seven takes, shipped compressed with facesynth
and written as a capture corpus by ``facesynth sample-corpus DIR --preset facegood``.

What it is: one performer (FACEGOOD's "shirley"), speaking presumably Mandarin (not checked by
listening), neutral, in seven takes of 656 s (11 minutes) in all, with the face solved from video
(in Maya, by FACEGOOD) into 116 blendshape curves at 30 frames/s: FACEGOOD-Audio2Face's training
data (github.com/FACEGOOD/FACEGOOD-Audio2Face, ``code/train/wav`` and ``code/train/bs_value``), MIT
licence (``facesynth/data/FACEGOOD.LICENSE``, copied beside the corpus). No transcript, no phone
timing: ``ingest`` recognises the phones from the audio, as for any take without a transcript
(pocketsphinx's English models on this speech: the phones are the English ones nearest what it
hears).

Shipped (``facesynth/data``): ``facegood.npz`` (the curves as float16, within 2.5e-4 of FACEGOOD's
float64; the channel names; the takes' names, frame and sample counts), ``facegood_audio.ogg``
(the seven takes' 16 kHz speech, one after another, as Opus at about 23 kbit/s) and
``facegood_arkit.csv`` (FACEGOOD's own table from its channels to ARKit, with one row added:
``mouth_oh_c -> jawOpen``; see the file's comments). :func:`pack` makes the first two from
FACEGOOD's files.

The corpus written (:func:`write_corpus`): ``manifest.csv`` (columns ``take, mocap, names, fps,
mapping, audio, emotion, sentence, split``; every take neutral and ``train``), ``curves/<take>.npy``
(frames x 116, float32), ``curves/channels.txt``, ``audio/<take>.wav`` (16 kHz, 16 bit),
``facegood_arkit.csv``, ``FACEGOOD.LICENSE`` and a ``README.md`` saying what it is.
"""

from __future__ import annotations

import csv
import io
import sys
import warnings
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

import numpy as np
import soundfile as sf

from facesynth.base.errors import InputError
from facesynth.formats.audio import write_wav

#: The package data files of the preset (in ``facesynth/data``).
CURVES_FILE = "facegood.npz"
AUDIO_FILE = "facegood_audio.ogg"
MAPPING_FILE = "facegood_arkit.csv"
LICENSE_FILE = "FACEGOOD.LICENSE"
#: Opus's compression level (soundfile: 0 best quality .. 1 smallest) of the shipped audio: about
#: 23 kbit/s of 16 kHz speech.
OPUS_LEVEL = 0.9

README = """# FACEGOOD's takes: a real performer as a capture corpus

Written by `facesynth sample-corpus DIR --preset facegood`. One performer (FACEGOOD's "shirley"),
speaking presumably Mandarin (not checked by listening), neutral, {takes} takes, {seconds:.0f} s
(about 11 minutes) in all, with the face solved from video into FACEGOOD's 116 blendshape curves at
30 frames/s. From FACEGOOD-Audio2Face's training data (github.com/FACEGOOD/FACEGOOD-Audio2Face),
MIT licence (`FACEGOOD.LICENSE`). The audio was shipped as Opus (about 23 kbit/s) and is written
here as 16 kHz WAV; the curves were shipped as float16.

There is no transcript and no phone timing: `facesynth ingest manifest.csv -o corpus.h5` recognises
the phones from the audio (English models), poses the built-in rig with the curves mapped to ARKit
by `facegood_arkit.csv` and records the virtual actress's markers on it. Then `normalize`, `pca`
and `build-db` make a database of this performer's motion.
"""


@dataclass(frozen=True)
class FacegoodSummary:
    """What :func:`write_corpus` wrote: takes, frames (at 30 frames/s) and seconds of speech."""

    takes: int
    frames: int
    seconds: float


def _data(name: str) -> bytes:
    return resources.files("facesynth").joinpath(f"data/{name}").read_bytes()


def shipped() -> tuple[dict[str, np.ndarray], np.ndarray, int]:
    """(the arrays of ``facegood.npz``, all takes' audio (S,) float32, its sample rate)."""
    with np.load(io.BytesIO(_data(CURVES_FILE)), allow_pickle=False) as npz:
        arrays = {k: npz[k] for k in npz.files}
    audio, rate = sf.read(io.BytesIO(_data(AUDIO_FILE)), dtype="float32")
    return arrays, np.asarray(audio, np.float32).reshape(len(audio), -1).mean(axis=1), int(rate)


def write_corpus(folder: Path) -> FacegoodSummary:
    """Write FACEGOOD's takes into ``folder`` as a capture corpus (see the module docstring)."""
    folder = Path(folder)
    arrays, audio, rate = shipped()
    takes = [str(t) for t in arrays["takes"]]
    frames, samples = arrays["frames"].astype(np.int64), arrays["samples"].astype(np.int64)
    if len(audio) != samples.sum():
        raise InputError(f"facesynth/data/{AUDIO_FILE}: {len(audio)} samples where {int(samples.sum())} were shipped; "
                         "reinstall facesynth.")
    (folder / "curves").mkdir(parents=True, exist_ok=True)
    (folder / "audio").mkdir(exist_ok=True)
    (folder / "curves" / "channels.txt").write_text("".join(f"{n}\n" for n in arrays["names"]), encoding="utf-8")
    curves = arrays["curves"].astype(np.float32)
    fps = float(arrays["fps"])
    f0 = s0 = 0
    rows = []
    for take, n, m in zip(takes, frames, samples):
        np.save(folder / "curves" / f"{take}.npy", curves[f0:f0 + n])
        write_wav(folder / "audio" / f"{take}.wav", audio[s0:s0 + m], rate)
        rows.append([take, f"curves/{take}.npy", "curves/channels.txt", f"{fps:g}", MAPPING_FILE, f"audio/{take}.wav",
                     "neutral", take, "train"])
        f0, s0 = f0 + n, s0 + m
    with open(folder / "manifest.csv", "w", encoding="utf-8", newline="") as fh:
        writer = csv.writer(fh, lineterminator="\n")
        writer.writerow(["take", "mocap", "names", "fps", "mapping", "audio", "emotion", "sentence", "split"])
        writer.writerows(rows)
    (folder / MAPPING_FILE).write_bytes(_data(MAPPING_FILE))
    (folder / LICENSE_FILE).write_bytes(_data(LICENSE_FILE))
    seconds = float(samples.sum() / rate)
    (folder / "README.md").write_text(README.format(takes=len(takes), seconds=seconds), encoding="utf-8")
    return FacegoodSummary(len(takes), int(frames.sum()), seconds)


def pack(source: Path, data: Path) -> dict[str, float]:
    """Make the shipped files (``facegood.npz``, ``facegood_audio.ogg``) in ``data`` from FACEGOOD's
    folder ``source`` (``wav/<take>.wav``, ``bs_value_npy/bs_value_<take>.npy``,
    ``shirley_1015_bs_name.npy``): ``python -m facesynth.domain.capture.facegood SOURCE DATA``.
    Returns the files' sizes (bytes) and the curves' largest rounding error."""
    source, data = Path(source), Path(data)
    with warnings.catch_warnings():  # FACEGOOD's arrays were written by Python 2, which NumPy warns about
        warnings.simplefilter("ignore", UserWarning)
        names = np.array([str(n) for n in np.load(source / "shirley_1015_bs_name.npy", allow_pickle=False)])
        takes = sorted(p.stem.removeprefix("bs_value_") for p in (source / "bs_value_npy").glob("bs_value_*.npy"))
        curves = [np.load(source / "bs_value_npy" / f"bs_value_{t}.npy", allow_pickle=False) for t in takes]
    sounds = [sf.read(source / "wav" / f"{t}.wav", dtype="float32") for t in takes]
    rate = sounds[0][1]
    if any(r != rate for _, r in sounds):
        raise InputError(f"{source}/wav: the takes' sample rates differ; FACEGOOD's are all 16 kHz.")
    values = np.concatenate(curves)
    half = values.astype(np.float16)
    np.savez_compressed(data / CURVES_FILE, curves=half, names=names, takes=np.array(takes),
                        frames=np.array([len(c) for c in curves], np.int64),
                        samples=np.array([len(x) for x, _ in sounds], np.int64), fps=np.float64(30.0))
    audio = np.concatenate([x.reshape(len(x), -1).mean(axis=1) for x, _ in sounds])
    sf.write(data / AUDIO_FILE, audio, rate, format="OGG", subtype="OPUS", compression_level=OPUS_LEVEL)
    return {"curves_bytes": (data / CURVES_FILE).stat().st_size, "audio_bytes": (data / AUDIO_FILE).stat().st_size,
            "curves_max_error": float(np.abs(half.astype(np.float64) - values).max())}


def main(argv: list[str]) -> int:
    """``python -m facesynth.domain.capture.facegood SOURCE DATA``: :func:`pack`."""
    if len(argv) != 2:
        print("usage: python -m facesynth.domain.capture.facegood FACEGOOD_FOLDER facesynth/data", file=sys.stderr)
        return 2
    print(pack(Path(argv[0]), Path(argv[1])))
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main(sys.argv[1:]))
