"""Head motion for new speech with the ``[head_motion]`` settings (``facesynth head-motion``):
the library of captured takes, their cleaned pitch and head motion, and the head motion chosen
for a new pitch track (Chuang & Bregler 2005 §5; the search and the blend are :mod:`.synthesis`).

The database holds every take's head motion (normalize keeps it); the takes' audio comes
from the corpus artifact the database was built from, which stores every take's samples.
Only the database's training takes are matched.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from facesynth.base.config import HeadMotionSettings
from facesynth.base.errors import InputError
from facesynth.domain.head_motion import synthesis as headsynth
from facesynth.domain.speech import pitch as P
from facesynth.model.corpus import Corpus
from facesynth.model.head_motion import HeadMotion
from facesynth.model.motiondb import MotionDatabase

#: Below these spreads (degrees, mm) over all frames a database has no head motion to reuse.
STILL_DEG, STILL_MM = 1e-3, 1e-3


def check_settings(s: HeadMotionSettings) -> None:
    """Refuse settings that bound nothing: a pitch range that is empty, and Eq. 12's weights
    ``b + c`` above 1 (the length term is weighed by ``1 - b - c``)."""
    if s.pitch_min_hz >= s.pitch_max_hz:
        raise InputError(f"head_motion.pitch_min_hz {s.pitch_min_hz:g} must be below pitch_max_hz "
                         f"{s.pitch_max_hz:g}.")
    if s.b + s.c > 1:
        raise InputError(f"head_motion.b + head_motion.c = {s.b + s.c:g}: Eq. 12 weighs the length term "
                         "by 1 - b - c, so keep b + c at most 1.")


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


def artifact(res: headsynth.Result, lib: list[headsynth.LibraryTake], p: np.ndarray,
             s: HeadMotionSettings) -> HeadMotion:
    """The ``headmotion`` artifact of ``res``: the head poses at ``s.fps``, the new speech's
    pitch ``p`` (Hz every ``s.hop_s``) and segments, and the captured segment each was given."""
    rotation, translation = head_poses(res.head)
    chosen = [lib[c.take] for c in res.choices]
    segs = [t.segments[c.index] for t, c in zip(chosen, res.choices)]
    return HeadMotion(rotation, translation, s.fps, p, 1.0 / s.hop_s,
                      np.array([g.start for g in res.segments]), np.array([g.end for g in res.segments]),
                      [t.name for t in chosen], np.array([c.index for c in res.choices], np.int64),
                      np.array([c.cost for c in res.choices]), np.array([g.start for g in segs]),
                      np.array([g.end for g in segs]))


def consecutive(choices: list[headsynth.Choice]) -> int:
    """Joins where the next captured segment follows the previous one in its take."""
    return sum(1 for a, b in zip(choices, choices[1:]) if a.take == b.take and b.index == a.index + 1)
