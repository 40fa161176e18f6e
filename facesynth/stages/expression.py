"""``facesynth expression fit|analyze|restyle``: the bilinear style/content model of Chuang &
Bregler (2005) §3 on marker motion. Fitting (the takes warped onto one timeline, PCA, Eq. 4-6)
is :mod:`facesynth.domain.expression.training`, analysis and restyling (Eq. 7)
:mod:`facesynth.domain.expression.analysis`, the maths :mod:`facesynth.domain.expression.bilinear`.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.config import ExpressionSettings, IngestSettings, settings_json
from facesynth.domain.expression.analysis import analysis_lines, check_markers, check_request, restyled
from facesynth.domain.expression.training import aligned_data, fit_model
from facesynth.model.artifacts import check_output
from facesynth.model.expression import ExpressionModel
from facesynth.model.frames import NormalizedFrames
from facesynth.model.motion import Motion


@dataclass(frozen=True)
class ExpressionFitResult:
    """What ``facesynth expression fit`` fitted.

    emotions: the styles (emotions) of the model.
    sentences: sentences spoken in every one of them, aligned phone by phone.
    frames: aligned frames per emotion.
    errors: the mean squared error after each alternating least-squares iteration (mm^2).
    skipped: sentences left out, and why.
    components: the PCA components the model works in.
    content_dim: the size of a content vector.
    """

    emotions: list[str]
    sentences: int
    frames: int
    errors: list[float]
    skipped: list[str]
    components: int
    content_dim: int


@dataclass(frozen=True)
class RestyleResult:
    """What ``facesynth expression restyle`` did.

    frames: frames restyled (at the motion's output rate).
    from_emotion: the emotion most frames were nearest to before ('unknown' when none could be analysed).
    change_mm: RMS marker change (mm).
    """

    frames: int
    from_emotion: str
    change_mm: float


def fit(norm_path: Path, out: Path, settings: ExpressionSettings, overwrite: bool = False) -> ExpressionFitResult:
    """``expression fit``: read a ``normalized`` artifact, fit, write an ``expression`` artifact."""
    check_output(out, overwrite)
    norm = NormalizedFrames.read(norm_path)
    X, emotions, used, notes = aligned_data(norm, settings.splits, settings.frame_step)
    model = fit_model(X, emotions, settings)
    ExpressionModel.write(out, model, norm.marker_names, config=settings_json(settings),
                          inputs=[norm_path], aligned_frames=X.shape[1], sentences=used,
                          overwrite=overwrite)
    return ExpressionFitResult(emotions, len(used), X.shape[1], model.errors.tolist(), notes, model.basis.shape[0],
                               model.W.shape[2])


def analyze(model_path: Path, motion_path: Path, settings: ExpressionSettings) -> list[str]:
    """``expression analyze``: CSV lines, one per output frame: time (s), the nearest fitted
    emotion, the style vector (e0..) and the content vector (c0..); NaN frames are skipped."""
    model, names = ExpressionModel.read(model_path)
    motion = Motion.read(motion_path)
    check_markers(motion.marker_names, names, motion_path, model_path)
    return analysis_lines(model, motion, settings)


def restyle(model_path: Path, motion_path: Path, out: Path, settings: ExpressionSettings, ingest: IngestSettings, *,
            to: str | None, intensity: float, emotions_path: Path | None, overwrite: bool = False) -> RestyleResult:
    """``expression restyle``: the motion in another expression (Eq. 7), at the output and
    the capture rate, head motion kept; writes a ``motion`` artifact (``source = restyle``)."""
    check_output(out, overwrite)
    model, names = ExpressionModel.read(model_path)
    check_request(model, model_path, to, intensity)
    motion = Motion.read(motion_path)
    check_markers(motion.marker_names, names, motion_path, model_path)
    done = restyled(model, motion, settings, ingest, model_path, to, intensity, emotions_path)
    Motion(done.markers, motion.fps, done.capture, motion.capture_fps, motion.marker_names, motion.reference,
           motion.head_rotation, motion.head_translation, source="restyle").write(out, config=settings_json(settings),
                                   inputs=[p for p in (model_path, motion_path, emotions_path) if p is not None],
                                   overwrite=overwrite)
    return RestyleResult(len(done.markers), done.from_emotion,
                         float(np.sqrt(np.nanmean((done.markers - motion.markers) ** 2)) * np.sqrt(3)))
