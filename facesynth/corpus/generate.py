"""``facesynth sample-corpus``: write the virtual actress's corpus in the formats a real user has.

Layout of OUT_DIR::

    manifest.csv            take, mocap, audio, alignment, transcript, emotion, sentence, split
    mocap/<take>.c3d        markers, mm, 120 Hz, head motion, noise, gaps, contamination
    audio/<take>.wav        16 kHz mono speech whose pitch and spectrum follow the phones
    labels/<take>.TextGrid  tiers 'phones' (Festival set) and 'words'
    face.obj, markers.csv   the face mesh (mm) and the marker-to-vertex binding
    contamination.csv       ground truth of the injected spikes and marker swaps
    groundtruth/<take>.c3d  held-out takes: clean markers in the head frame (no noise, no head motion)
    groundtruth/<take>_head.csv   per-frame head rotation (row-major 3x3) and translation (mm)
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..artifacts import check_output_folder
from ..errors import InputError
from ..formats.audio import write_wav
from ..formats.labels import Segment, write_textgrid
from ..formats.mesh import write_binding, write_obj
from ..formats.mocap import MarkerTake, write_c3d
from ..progress import progress
from .face import Rig, build_face_model
from .speech import EMOTIONS, STYLES, articulation, design_sentences, head_motion, pitch, synthesize_audio, time_utterance

CAPTURE_FPS = 120.0
AUDIO_RATE = 16000


@dataclass(frozen=True)
class Preset:
    """Sentences per emotion by split, sentence length (phones), contamination events per train take."""

    train: int
    val: int
    test: int
    min_phones: int
    max_phones: int
    pause_prob: float
    contamination_rate: float


PRESETS = {
    # seconds, for tests
    "tiny": Preset(train=3, val=1, test=1, min_phones=10, max_phones=16, pause_prob=0.5, contamination_rate=0.7),
    # a few minutes of speech, for the demo
    "small": Preset(train=14, val=2, test=2, min_phones=22, max_phones=32, pause_prob=0.35, contamination_rate=0.5),
    # about 5,556 motion nodes, the size of the paper's database (6 validation and 3 test
    # sentences per emotion, the paper's 24 + 12)
    "paper": Preset(train=43, val=6, test=3, min_phones=25, max_phones=35, pause_prob=0.35, contamination_rate=0.3),
}

MARKER_NOISE_MM = 0.2


def _inject_contamination(positions: np.ndarray, names: list[str], rng: np.random.Generator, rate: float,
                          take: str, speech_frames: tuple[int, int]) -> list[dict]:
    """Add marker spikes and label swaps to speech frames; return their ground truth."""
    events = []
    n_frames, n_markers, _ = positions.shape
    lo, hi = speech_frames
    n_events = rng.poisson(rate)
    for _ in range(n_events):
        kind = "spike" if rng.random() < 0.6 else "swap"
        if kind == "spike":
            length = int(rng.integers(1, 5))
            start = int(rng.integers(lo, max(lo + 1, hi - length)))
            m = int(rng.integers(n_markers))
            direction = rng.normal(size=3)
            direction /= np.linalg.norm(direction)
            positions[start : start + length, m] += direction * rng.uniform(15.0, 40.0)
            markers = names[m]
        else:
            length = int(rng.integers(15, 60))
            start = int(rng.integers(lo, max(lo + 1, hi - length)))
            m = int(rng.integers(n_markers))
            d = np.linalg.norm(positions[start] - positions[start, m], axis=1)
            d[m] = np.inf
            candidates = np.argsort(d)[1:4]  # the 2nd to 4th nearest marker: a near one, as a labelling error would pick
            k = int(candidates[rng.integers(len(candidates))])
            sl = slice(start, start + length)
            positions[sl, [m, k]] = positions[sl, [k, m]]
            markers = f"{names[m]}+{names[k]}"
        end = min(start + length, n_frames) - 1
        events.append({"take": take, "type": kind, "markers": markers, "start_frame": start, "end_frame": end,
                       "start_s": f"{start / CAPTURE_FPS:.4f}", "end_s": f"{(end + 1) / CAPTURE_FPS:.4f}"})
    return events


def _add_gaps(positions: np.ndarray, rng: np.random.Generator, long_gap: bool) -> None:
    n_frames, n_markers, _ = positions.shape
    for _ in range(rng.poisson(2.0)):
        length = int(rng.integers(2, 11))
        start = int(rng.integers(0, max(1, n_frames - length)))
        positions[start : start + length, int(rng.integers(n_markers))] = np.nan
    if long_gap:
        start = int(rng.integers(0, max(1, n_frames - 60)))
        positions[start : start + 40, int(rng.integers(n_markers))] = np.nan


def generate(out_dir: Path, preset: str = "small", seed: int = 0, overwrite: bool = False) -> dict:
    """Write the sample corpus into ``out_dir``. Returns a summary (takes, frames, nodes...)."""
    if preset not in PRESETS:
        raise InputError(f"unknown preset {preset!r}; choose tiny, small or paper.")
    out_dir = Path(out_dir)
    check_output_folder(out_dir, "the corpus")
    if (out_dir / "manifest.csv").exists() and not overwrite:
        raise InputError(f"{out_dir}: already holds a corpus (manifest.csv); pass --overwrite or choose another folder.")
    spec = PRESETS[preset]
    for sub in ("mocap", "audio", "labels", "groundtruth"):
        (out_dir / sub).mkdir(parents=True, exist_ok=True)

    root = np.random.SeedSequence([seed, 20080420])
    design_rng, *_ = [np.random.default_rng(s) for s in root.spawn(1)]
    n_sentences = spec.train + spec.val + spec.test
    sentences = design_sentences(n_sentences, design_rng, spec.min_phones, spec.max_phones)
    split_of = ["train"] * spec.train + ["val"] * spec.val + ["test"] * spec.test

    face = build_face_model()
    marker_rest = face.vertices[face.marker_vertices]
    rig = Rig(marker_rest, face.lower[face.marker_vertices])
    write_obj(out_dir / "face.obj", face.vertices, face.faces, "facesynth sample corpus face, millimetres, +y up, +z forward")
    write_binding(out_dir / "markers.csv", dict(zip(face.marker_names, face.marker_vertices.tolist())))

    jobs = [(e, s) for e in EMOTIONS for s in range(n_sentences)]
    take_seeds = root.spawn(len(jobs) + 1)[1:]
    manifest_rows, contamination, n_frames_total, n_phones_train = [], [], 0, 0
    for (emotion, s), take_seed in progress(list(zip(jobs, take_seeds)), "sample-corpus"):
        rng = np.random.default_rng(take_seed)
        style = STYLES[emotion]
        take = f"{emotion}_s{s:03d}"
        utt = time_utterance(sentences[s], style, rng, spec.pause_prob)
        params = articulation(utt, style, CAPTURE_FPS, rng)
        f0 = pitch(utt, style, CAPTURE_FPS, rng)
        rotations, translations = head_motion(f0, style, CAPTURE_FPS, rng)
        clean = rig.evaluate(params)  # (T, M, 3) head frame
        # Head motion about a centre behind the face, then placement in the capture volume.
        centre = np.array([0.0, 0.0, -60.0])
        moved = np.einsum("tij,tmj->tmi", rotations, clean - centre) + centre + translations[:, None, :]
        yaw = np.deg2rad(rng.uniform(-8, 8))
        world_r = np.array([[np.cos(yaw), 0, np.sin(yaw)], [0, 1, 0], [-np.sin(yaw), 0, np.cos(yaw)]])
        world_t = np.array([250.0, 1550.0, -120.0]) + rng.uniform(-20, 20, 3)
        captured = moved @ world_r.T + world_t
        captured += rng.normal(0.0, MARKER_NOISE_MM, captured.shape)
        speech = [i for i, p in enumerate(utt.phones) if p != "pau"]
        speech_frames = (int(utt.starts[speech[0]] * CAPTURE_FPS), int(utt.ends[speech[-1]] * CAPTURE_FPS))
        if split_of[s] == "train":
            contamination += _inject_contamination(captured, face.marker_names, rng, spec.contamination_rate, take, speech_frames)
            n_phones_train += len(speech)
        _add_gaps(captured, rng, long_gap=(preset == "paper" and rng.random() < 0.05))

        write_c3d(out_dir / "mocap" / f"{take}.c3d", MarkerTake(captured.astype(np.float32), face.marker_names, CAPTURE_FPS))
        audio = synthesize_audio(utt, f0, CAPTURE_FPS, style, AUDIO_RATE, rng)
        write_wav(out_dir / "audio" / f"{take}.wav", audio, AUDIO_RATE)
        phones = [Segment(float(a), float(b), p) for a, b, p in zip(utt.starts, utt.ends, utt.phones)]
        words = [Segment(a, b, w) for w, a, b in utt.word_spans]
        write_textgrid(out_dir / "labels" / f"{take}.TextGrid", {"phones": phones, "words": words}, utt.duration)
        if split_of[s] != "train":
            write_c3d(out_dir / "groundtruth" / f"{take}.c3d", MarkerTake(clean.astype(np.float32), face.marker_names, CAPTURE_FPS))
        with open(out_dir / "groundtruth" / f"{take}_head.csv", "w", newline="") as fh:
            writer = csv.writer(fh)
            writer.writerow([f"r{i}{j}" for i in range(3) for j in range(3)] + ["tx", "ty", "tz"])
            for r, tr in zip(rotations, translations):
                writer.writerow([f"{v:.8f}" for v in r.reshape(-1)] + [f"{v:.5f}" for v in tr])
        n_frames_total += len(captured)
        manifest_rows.append({
            "take": take, "mocap": f"mocap/{take}.c3d", "audio": f"audio/{take}.wav",
            "alignment": f"labels/{take}.TextGrid", "transcript": " ".join(utt.words),
            "emotion": emotion, "sentence": f"s{s:03d}", "split": split_of[s],
        })

    with open(out_dir / "contamination.csv", "w", newline="") as fh:
        fields = ["take", "type", "markers", "start_frame", "end_frame", "start_s", "end_s"]
        writer = csv.DictWriter(fh, fieldnames=fields)
        writer.writeheader()
        writer.writerows(contamination)
    with open(out_dir / "manifest.csv", "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=list(manifest_rows[0]))
        writer.writeheader()
        writer.writerows(manifest_rows)
    return {"takes": len(manifest_rows), "frames": n_frames_total, "train_phones": n_phones_train,
            "contamination_events": len(contamination), "seconds": n_frames_total / CAPTURE_FPS}
