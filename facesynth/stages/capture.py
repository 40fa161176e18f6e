"""``facesynth capture``: a captured take exported as a ``motion`` artifact in the database's
head frame (attribute ``source = "capture"``, no search path): ground truth to deform and
render beside a synthesis."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.config import NormalizeSettings
from facesynth.domain.evaluation.held_out import normalized_take
from facesynth.domain.postprocess.concatenation import downsample
from facesynth.model.artifacts import check_output
from facesynth.model.corpus import Corpus
from facesynth.model.frames import relative_to_take
from facesynth.model.motion import Motion
from facesynth.model.motiondb import MotionDatabase


@dataclass(frozen=True)
class CaptureResult:
    """What ``facesynth capture`` exported.

    take: the captured take's name.
    frames: frames of the motion at the output rate.
    """

    take: str
    frames: int


def run(db_path: Path, corpus_path: Path, take: str, out: Path, normalize_settings: NormalizeSettings,
        output_fps: float, overwrite: bool = False) -> CaptureResult:
    """Write take ``take`` of ``corpus_path`` to ``out`` at ``output_fps`` (and the capture rate)."""
    check_output(out, overwrite)
    db = MotionDatabase.read(db_path)
    corpus = Corpus.read(corpus_path, audio=False)
    corpus.check_markers(db.marker_names, corpus_path)
    i = corpus.take_index(take, corpus_path)
    markers, rotations, translations = normalized_take(corpus.markers[corpus.takes.frames(i)], db, normalize_settings,
                                                       corpus.rigid_markers)
    rel_r, rel_t = relative_to_take(rotations, translations, [slice(0, len(markers))])
    motion = Motion(downsample(markers.astype(np.float32), db.fps, output_fps), output_fps, markers.astype(np.float32),
                    db.fps, db.marker_names, db.reference, downsample(rel_r, db.fps, output_fps),
                    downsample(rel_t, db.fps, output_fps), source="capture", take=take)
    motion.write(out, config="{}", inputs=[db_path, corpus_path], overwrite=overwrite)
    return CaptureResult(take, int(np.ceil(len(markers) * output_fps / db.fps)))

