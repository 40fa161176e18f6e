"""``facesynth sample-corpus``: write the virtual actress's corpus in the formats a real user has.

The actress lives on the production face rig (:mod:`facesynth.domain.rig.face`): her speech is
articulated in the rig's blendshape weights (:mod:`facesynth.domain.corpus.actress_mouth`), her face
blinks, raises the brows, looks around and shows four emotions, sometimes changing emotion
inside a sentence (:mod:`facesynth.domain.corpus.nonspeech`), and her head moves with pitch and
phrasing (:mod:`facesynth.domain.corpus.speech`). About 90 markers glued to rig vertices
(:mod:`facesynth.domain.rig.markers`) are captured with noise, gaps and contamination.

Layout of OUT_DIR::

    manifest.csv            take, mocap, audio, alignment, transcript, emotion, sentence, split
                            (emotion: the take's emotion at its start)
    mocap/<take>.c3d        markers, mm, 120 Hz, head motion, noise, gaps, contamination
    audio/<take>.wav        16 kHz mono speech whose pitch and spectrum follow the phones
    labels/<take>.TextGrid  tiers 'phones' (Festival set), 'words' and 'emotion' (the emotion
                            of each stretch of the take; ingest gives every phone the emotion
                            at its centre)
    face.obj                the rig's neutral mesh, mm (+y up, +z forward, +x the subject's left)
    markers.csv             marker,vertex,rigid: the marker-to-vertex binding on face.obj and
                            the rigid (head-pose) markers
    contamination.csv       ground truth of the injected spikes and marker swaps
    groundtruth/<take>.c3d  every take: clean markers in the head frame (no noise, no head motion)
    groundtruth/<take>_head.csv   per-frame head rotation (row-major 3x3) and translation (mm)
    groundtruth/<take>_truth.csv  per-frame rig weights (55), ARKit weights (52), emotion and
                            intensity (:mod:`facesynth.domain.corpus.truth`)
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.config import Config, SampleCorpusSettings
from facesynth.base.errors import InputError
from facesynth.base.phonemes import PAU
from facesynth.base.progress import progress
from facesynth.domain.rig.face import Rig, load_face_rig
from facesynth.domain.rig.markers import build_marker_set
from facesynth.formats.audio import write_wav
from facesynth.formats.labels import Segment, write_textgrid
from facesynth.formats.mesh import write_binding, write_obj
from facesynth.formats.mocap import MarkerTake, write_c3d
from facesynth.model.artifacts import check_output_folder

from .actress_mouth import CHANNEL_NAMES, ContactSolver, TokenVariation, apply_contact, articulate
from .nonspeech import (
    EMOTIONS,
    EmotionTrack,
    blink_times,
    blink_weights,
    brow_weights,
    couple_cheeks_and_nose,
    emotion_track,
    emotion_weights,
    gaze_weights,
)
from .speech import STYLES, ReadSentence, design_sentences, head_motion, pitch, synthesize_audio, time_utterance
from .truth import write_truth

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
#: Fraction of takes whose emotion changes inside the sentence.
EMOTION_CHANGE_PROBABILITY = 0.25


@dataclass
class Performance:
    """One take as performed: its timing, emotion, rig weights (T, E), head motion and audio pitch.

    weights : (T, E) rig weights at the capture rate; rotations : (T, 3, 3); translations : (T, 3) mm;
    f0 : (T,) Hz.
    """

    utterance: ReadSentence
    emotion: EmotionTrack
    weights: np.ndarray
    rotations: np.ndarray
    translations: np.ndarray
    f0: np.ndarray


def perform(words: list[str], emotion: str, rng: np.random.Generator, rig: Rig, solver: ContactSolver,
            pause_prob: float, fps: float = 120.0, change_probability: float = EMOTION_CHANGE_PROBABILITY,
            settings: SampleCorpusSettings | None = None) -> Performance:
    """The actress reads ``words`` in ``emotion`` (sometimes changing to another at a word boundary),
    articulating with ``settings`` (default: ``[sample_corpus]`` of configs/default.toml)."""
    settings = settings or default_settings()
    change_at: tuple[str, int] | None = None  # (the second emotion, the word it starts on)
    if len(words) >= 3 and rng.random() < change_probability:
        second = str(rng.choice([e for e in EMOTIONS if e != emotion]))
        change_at = (second, int(rng.integers(1, len(words))))
    styles = [STYLES[change_at[0] if change_at is not None and k >= change_at[1] else emotion] for k in range(len(words))]
    utt = time_utterance(words, styles, rng, pause_prob)
    n_frames = int(np.floor(utt.duration * fps)) + 1
    change = (change_at[0], utt.word_spans[change_at[1]][1]) if change_at is not None else None  # (second, switch_s)
    track = emotion_track(emotion, change, n_frames, fps, rng)
    style_rows = [STYLES[e] for e in EMOTIONS]
    stiffness = track.blend @ np.array([s.stiffness for s in style_rows])
    amplitude = track.at(0.5 * (utt.starts + utt.ends), fps) @ np.array([s.amplitude for s in style_rows])

    f0, accents = pitch(utt, STYLES[emotion], fps, rng)
    if change is not None:
        second, switch_s = change
        f0_second, accents_second = pitch(utt, STYLES[second], fps, rng)
        x = track.blend[:, EMOTIONS.index(second)]
        f0 = (1 - x) * f0 + x * f0_second
        accents = [a for a in accents if a[0] < switch_s] + [a for a in accents_second if a[0] >= switch_s]

    take_sides = np.exp(rng.normal(0.0, TokenVariation().take_side_sigma, (len(CHANNEL_NAMES), 2)))
    weights, drive = articulate(utt.phones, utt.starts, utt.ends, utt.stress, n_frames, fps, amplitude, stiffness,
                                take_sides, rng, rig, settings)
    weights += emotion_weights(rig, track, fps, rng)
    pauses = [(float(a), float(b)) for a, b, p in zip(utt.starts, utt.ends, utt.phones) if p == PAU]
    blink_scale = float(np.mean(track.blend @ np.array([s.blink_duration for s in style_rows])))
    weights += blink_weights(rig, blink_times(utt.duration, pauses, rng), n_frames, fps, rng, blink_scale)
    weights += brow_weights(rig, accents, n_frames, fps, rng)
    weights += gaze_weights(rig, n_frames, fps, rng)
    jaw_side = rig.shape_index(str(rng.choice(["jawLeft", "jawRight"])))
    weights[:, jaw_side] += rng.uniform(0.0, 0.12) * weights[:, rig.shape_index("jawOpen")]
    couple_cheeks_and_nose(rig, weights)
    np.clip(weights, 0.0, 1.0, out=weights)
    apply_contact(weights, drive, solver, fps)
    np.clip(weights, 0.0, 1.0, out=weights)

    phrase_ends = [a for a, b, p in zip(utt.starts[1:], utt.ends[1:], utt.phones[1:]) if p == PAU]
    rotations, translations = head_motion(f0, STYLES[emotion], fps, rng, phrase_ends)
    return Performance(utt, track, weights, rotations, translations, f0)


def emotion_segments(track: EmotionTrack, fps: float, duration: float) -> list[Segment]:
    """The 'emotion' tier: stretches of one dominant emotion (boundaries at the cross-fade's middle)."""
    labels = track.labels()
    segs, start = [], 0
    for t in range(1, len(labels) + 1):
        if t == len(labels) or labels[t] != labels[start]:
            end = duration if t == len(labels) else t / fps
            segs.append(Segment(start / fps, end, labels[start]))
            start = t
    return segs


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


def _capture(clean: np.ndarray, rotations: np.ndarray, translations: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Clean head-frame markers (T, M, 3) mm -> as captured: head motion about a centre behind
    the face, placement in the capture volume, and per-marker noise."""
    centre = np.array([0.0, 0.0, -60.0])
    moved = np.einsum("tij,tmj->tmi", rotations, clean - centre) + centre + translations[:, None, :]
    yaw = np.deg2rad(rng.uniform(-8, 8))
    world_r = np.array([[np.cos(yaw), 0, np.sin(yaw)], [0, 1, 0], [-np.sin(yaw), 0, np.cos(yaw)]])
    world_t = np.array([250.0, 1550.0, -120.0]) + rng.uniform(-20, 20, 3)
    captured = moved @ world_r.T + world_t
    return captured + rng.normal(0.0, MARKER_NOISE_MM, captured.shape)


def _write_head(path: Path, rotations: np.ndarray, translations: np.ndarray) -> None:
    """``groundtruth/<take>_head.csv``: per frame the head rotation (T, 3, 3), row-major with 8
    decimals, and translation (T, 3) mm with 5, as ``csv.writer`` writes the rows (``\\r\\n``)."""
    row_format = ",".join(["%.8f"] * 9 + ["%.5f"] * 3) + "\r\n"
    rows = np.concatenate([rotations.reshape(len(rotations), 9), translations], axis=1)
    with open(path, "w", newline="") as fh:
        csv.writer(fh).writerow([f"r{i}{j}" for i in range(3) for j in range(3)] + ["tx", "ty", "tz"])
        fh.write("".join(row_format % tuple(row) for row in rows.tolist()))


def default_settings() -> SampleCorpusSettings:
    """The ``[sample_corpus]`` settings of configs/default.toml."""
    return Config.load().settings("sample_corpus")


@dataclass(frozen=True)
class GeneratedCorpus:
    """What :func:`generate` wrote.

    takes: takes (one C3D, WAV and TextGrid each).
    frames: capture frames over all takes.
    train_phones: phone segments of the training takes.
    contamination_events: marker spikes and swaps put into the capture (for prune to find).
    seconds: capture length over all takes (s).
    """

    takes: int
    frames: int
    train_phones: int
    contamination_events: int
    seconds: float


def generate(out_dir: Path, preset: str = "small", seed: int = 0, overwrite: bool = False,
             settings: SampleCorpusSettings | None = None) -> GeneratedCorpus:
    """Write the sample corpus into ``out_dir``, the actress articulating with ``settings``
    (default: :func:`default_settings`)."""
    settings = settings or default_settings()
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

    rig = load_face_rig()
    markers = build_marker_set(rig)
    solver = ContactSolver(rig, markers.lip_pairs)
    write_obj(out_dir / "face.obj", rig.neutral, rig.faces, "facesynth sample corpus face (ICT-FaceKit rig, MIT), millimetres, +y up, +z forward")
    write_binding(out_dir / "markers.csv", markers.binding(), {n for n, r in zip(markers.names, markers.rigid) if r})

    jobs = [(e, s) for e in EMOTIONS for s in range(n_sentences)]
    take_seeds = root.spawn(len(jobs) + 1)[1:]
    manifest_rows, contamination, n_frames_total, n_phones_train = [], [], 0, 0
    for (emotion, s), take_seed in progress(list(zip(jobs, take_seeds)), "sample-corpus"):
        rng = np.random.default_rng(take_seed)
        take = f"{emotion}_s{s:03d}"
        perf = perform(sentences[s], emotion, rng, rig, solver, spec.pause_prob, CAPTURE_FPS, settings=settings)
        utt = perf.utterance
        clean = rig.evaluate(perf.weights, vertices=markers.vertices)  # (T, M, 3) head frame, mm
        captured = _capture(clean, perf.rotations, perf.translations, rng)
        speech = [i for i, p in enumerate(utt.phones) if p != PAU]
        speech_frames = (int(utt.starts[speech[0]] * CAPTURE_FPS), int(utt.ends[speech[-1]] * CAPTURE_FPS))
        if split_of[s] == "train":
            contamination += _inject_contamination(captured, markers.names, rng, spec.contamination_rate, take, speech_frames)
            n_phones_train += len(speech)
        _add_gaps(captured, rng, long_gap=(preset == "paper" and rng.random() < 0.05))

        write_c3d(out_dir / "mocap" / f"{take}.c3d", MarkerTake(captured.astype(np.float32), markers.names, CAPTURE_FPS))
        audio = synthesize_audio(utt, perf.f0, CAPTURE_FPS, STYLES[emotion], AUDIO_RATE, rng)
        write_wav(out_dir / "audio" / f"{take}.wav", audio, AUDIO_RATE)
        phones = [Segment(float(a), float(b), p) for a, b, p in zip(utt.starts, utt.ends, utt.phones)]
        words = [Segment(a, b, w) for w, a, b in utt.word_spans]
        write_textgrid(out_dir / "labels" / f"{take}.TextGrid",
                       {"phones": phones, "words": words, "emotion": emotion_segments(perf.emotion, CAPTURE_FPS, utt.duration)},
                       utt.duration)
        write_c3d(out_dir / "groundtruth" / f"{take}.c3d", MarkerTake(clean.astype(np.float32), markers.names, CAPTURE_FPS))
        _write_head(out_dir / "groundtruth" / f"{take}_head.csv", perf.rotations, perf.translations)
        write_truth(out_dir / "groundtruth" / f"{take}_truth.csv", rig, CAPTURE_FPS, perf.weights,
                    perf.emotion.labels(), perf.emotion.frame_intensity())
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
    return GeneratedCorpus(len(manifest_rows), n_frames_total, n_phones_train, len(contamination),
                           n_frames_total / CAPTURE_FPS)
