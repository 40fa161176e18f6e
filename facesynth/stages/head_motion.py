"""``facesynth head-motion``: head motion for new speech, chosen from the captured takes by
pitch (Chuang & Bregler 2005 §5; the method is :mod:`facesynth.domain.head_motion.synthesis`,
with the ``[head_motion]`` settings :mod:`facesynth.domain.head_motion.from_pitch`).

The database holds every take's head motion (normalize keeps it); the takes' audio comes
from the corpus artifact the database was built from (``--corpus corpus.h5``, written by
``facesynth ingest``, which stores every take's samples), so no path outside the artifacts
is needed. Only the database's training takes are matched.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path

from facesynth.base.config import HeadMotionSettings, settings_json
from facesynth.domain.head_motion import from_pitch
from facesynth.domain.head_motion.synthesis import LibraryTake
from facesynth.domain.speech import pitch as P
from facesynth.formats.audio import read_audio
from facesynth.model.artifacts import check_output
from facesynth.model.corpus import Corpus
from facesynth.model.motiondb import MotionDatabase


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
    from_pitch.check_settings(settings)
    samples, rate = read_audio(audio_path)
    if samples.ndim > 1:
        samples = samples.mean(axis=1)
    db = MotionDatabase.read(db_path)
    from_pitch.database_head(db, db_path)
    t0 = time.perf_counter()
    p = from_pitch.clean_pitch(samples, rate, settings)
    lib: list[LibraryTake] = []
    if P.segments(p, settings.hop_s, len(samples) / rate):     # no voiced speech: rest, no library needed
        lib = from_pitch.library(db, Corpus.read(corpus_path), db_path, corpus_path, settings)
    pitch_s = time.perf_counter() - t0
    res, warnings = from_pitch.synthesize(lib, p, len(samples) / rate, settings)
    from_pitch.artifact(res, lib, p, settings).write(out, config=settings_json(settings),
                                                     inputs=[db_path, corpus_path, audio_path], overwrite=overwrite)
    return HeadMotionResult(len(samples) / rate, len(res.segments), from_pitch.consecutive(res.choices), len(lib),
                            pitch_s, warnings)
