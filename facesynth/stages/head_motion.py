"""``facesynth head-motion``: head motion for new speech, chosen from the captured takes by
pitch (Chuang & Bregler 2005 §5; the method is :mod:`facesynth.domain.head_motion.synthesis`).

The database holds every take's head motion (normalize keeps it); the takes' audio comes
from the corpus artifact the database was built from (``--corpus corpus.h5``, written by
``facesynth ingest``, which stores every take's samples), so no path outside the artifacts
is needed. Only the database's training takes are matched.
"""

from __future__ import annotations

import logging
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.config import HeadMotionSettings, settings_json
from facesynth.base.errors import InputError
from facesynth.domain.head_motion import synthesis as headsynth
from facesynth.domain.speech import pitch as P
from facesynth.formats.audio import read_audio
from facesynth.model.artifacts import check_output
from facesynth.model.corpus import Corpus
from facesynth.model.head_motion import HeadMotion
from facesynth.model.motiondb import MotionDatabase

log = logging.getLogger(__name__)

#: Below these spreads (degrees, mm) over all frames a database has no head motion to reuse.
STILL_DEG, STILL_MM = 1e-3, 1e-3


def clean_pitch(samples: np.ndarray, rate: int, s: HeadMotionSettings) -> np.ndarray:
    """§5.1: pYIN pitch of ``samples``, cleaned. (P,) Hz every ``s.hop_s``, NaN unvoiced."""
    raw = P.track(samples, rate, fmin=s.pitch_min_hz, fmax=s.pitch_max_hz, hop_s=s.hop_s,
                  resolution=s.pitch_resolution)
    return P.clean(raw, fmin=s.pitch_min_hz, fmax=s.pitch_max_hz, hop_s=s.hop_s, max_gap_s=s.max_gap_s,
                   min_voiced_s=s.min_voiced_s)


def head_channels(rotation: np.ndarray, translation: np.ndarray) -> np.ndarray:
    """(F, 3, 3) rotations and (F, 3) mm -> (F, 6): rotation vector in degrees, translation in mm."""
    from scipy.spatial.transform import Rotation

    return np.concatenate([np.degrees(Rotation.from_matrix(rotation.astype(np.float64)).as_rotvec()), translation], 1)


def head_poses(channels: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Inverse of :func:`head_channels`: (F, 6) -> (F, 3, 3), (F, 3) mm."""
    from scipy.spatial.transform import Rotation

    return Rotation.from_rotvec(np.radians(channels[:, :3])).as_matrix(), channels[:, 3:].copy()


def database_head(db: MotionDatabase, db_path: Path) -> np.ndarray:
    """(F, 6) every frame's head pose relative to its take's mean; refuses a database whose
    head never moves (nothing to reuse)."""
    rot, trans = db.head_relative_to_take
    channels = head_channels(rot, trans)
    if channels[:, :3].std(axis=0).max() < STILL_DEG and channels[:, 3:].std(axis=0).max() < STILL_MM:
        raise InputError(f"{db_path}: the database has no head motion (every frame has the same head pose); "
                         "build it from a capture whose rigid head markers move, or leave the head still.")
    return channels


def library(db: MotionDatabase, corpus: Corpus, db_path: Path, corpus_path: Path, s: HeadMotionSettings,
            splits=("train",)) -> list[headsynth.LibraryTake]:
    """The database's takes in ``splits`` with their cleaned pitch (from the corpus audio),
    segments and head motion relative to the take's mean pose."""
    channels = database_head(db, db_path)
    out = []
    for i, name in enumerate(db.takes.name):
        if db.takes.split[i] not in splits:
            continue
        if name not in corpus.takes.name:
            raise InputError(f"{corpus_path}: no take {name!r} of {db_path}; pass the corpus the database was built from.")
        k = corpus.takes.index(name)
        a = int(corpus.audio_start[k])
        samples = corpus.audio[a:a + int(corpus.audio_count[k])]
        p = clean_pitch(samples, corpus.sample_rate, s)
        segs = P.segments(p, s.hop_s, len(samples) / corpus.sample_rate)
        out.append(headsynth.LibraryTake(name, db.takes.sentence[i], p, segs, channels[db.takes.frames(i)], db.fps,
                                         s.hop_s))
    if not any(t.segments for t in out):
        raise InputError(f"{corpus_path}: no voiced speech in the training takes' audio; head motion needs the speech "
                         "that was captured with it.")
    return out


def synthesize(lib: list[headsynth.LibraryTake], p: np.ndarray, duration_s: float, s: HeadMotionSettings, *,
               exclude: frozenset[str] | set[str] = frozenset(), random: np.random.Generator | None = None
               ) -> tuple[headsynth.Result, list[str]]:
    """Head motion (T, 6) for a cleaned pitch track; ``random`` draws segments instead of
    matching them (a baseline). Returns the result and warnings (no voiced frame: rest)."""
    segs = P.segments(p, s.hop_s, duration_s)
    if not segs:
        T = max(1, int(np.ceil(duration_s * s.fps)))
        return headsynth.Result(np.zeros((T, 6)), s.fps, [], []), [
            "the audio has no voiced frame (no pitch between head_motion.pitch_min_hz and pitch_max_hz), so the head "
            "stays at rest."]
    if random is not None:
        choices = headsynth.random_choices(lib, len(segs), random, exclude)
    else:
        choices = headsynth.search(lib, segs, P.sentence_features(p, s.hop_s), m=s.top_sentences, k=s.top_segments,
                                   b=s.b, c=s.c, omega_h=s.omega_h, omega_r=s.omega_r, breath_s=s.breath_s,
                                   exclude=exclude)
    head = headsynth.blend(lib, segs, choices, duration_s, s.fps, breath_s=s.breath_s, join_smooth_s=s.join_smooth_s)
    return headsynth.Result(head, s.fps, segs, choices), []


@dataclass(frozen=True)
class HeadMotionResult:
    """What ``facesynth head-motion`` made.

    seconds: the new speech's length (s).
    segments: its pitch segments, each given a captured segment.
    consecutive: joins where the next captured segment follows the previous one in its take.
    library_takes: captured takes whose pitch was searched.
    pitch_s: seconds spent on pitch (the speech's and the takes').
    warnings: e.g. speech without voiced segments (the head keeps its rest pose).
    """

    seconds: float
    segments: int
    consecutive: int
    library_takes: int
    pitch_s: float
    warnings: list[str]


def run(db_path: Path, corpus_path: Path, audio_path: Path, out: Path, settings: HeadMotionSettings,
        overwrite: bool = False) -> HeadMotionResult:
    """Read the database, the corpus audio and the new speech; write a ``headmotion`` artifact."""
    check_output(out, overwrite)
    if settings.pitch_min_hz >= settings.pitch_max_hz:
        raise InputError(f"head_motion.pitch_min_hz {settings.pitch_min_hz:g} must be below pitch_max_hz "
                         f"{settings.pitch_max_hz:g}.")
    if settings.b + settings.c > 1:
        raise InputError(f"head_motion.b + head_motion.c = {settings.b + settings.c:g}: Eq. 12 weighs the length term "
                         "by 1 - b - c, so keep b + c at most 1.")
    samples, rate = read_audio(audio_path)
    if samples.ndim > 1:
        samples = samples.mean(axis=1)
    db = MotionDatabase.read(db_path)
    database_head(db, db_path)
    t0 = time.perf_counter()
    p = clean_pitch(samples, rate, settings)
    lib: list[headsynth.LibraryTake] = []
    if P.segments(p, settings.hop_s, len(samples) / rate):     # no voiced speech: rest, no library needed
        lib = library(db, Corpus.read(corpus_path), db_path, corpus_path, settings)
    pitch_s = time.perf_counter() - t0
    res, warnings = synthesize(lib, p, len(samples) / rate, settings)
    rotation, translation = head_poses(res.head)
    chosen = [lib[c.take] for c in res.choices]
    segs = [t.segments[c.index] for t, c in zip(chosen, res.choices)]
    HeadMotion(rotation, translation, settings.fps, p, 1.0 / settings.hop_s,
               np.array([g.start for g in res.segments]), np.array([g.end for g in res.segments]),
               [t.name for t in chosen], np.array([c.index for c in res.choices], np.int64),
               np.array([c.cost for c in res.choices]), np.array([g.start for g in segs]),
               np.array([g.end for g in segs])).write(out, config=settings_json(settings),
                                                      inputs=[db_path, corpus_path, audio_path], overwrite=overwrite)
    consecutive = sum(1 for a, b in zip(res.choices, res.choices[1:]) if a.take == b.take and b.index == a.index + 1)
    return HeadMotionResult(len(samples) / rate, len(res.segments), consecutive, len(lib), pitch_s, warnings)

