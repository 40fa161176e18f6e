"""Using a fitted expression model (Chuang & Bregler 2005, §3.3) on marker motion: the analysis of
each frame into a style and a content vector, and restyling into another expression (Eq. 7),
towards one emotion or along the spans of an emotion file, blended in and out over
``expression.transition_s``.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.config import ExpressionSettings, IngestSettings
from facesynth.base.errors import InputError
from facesynth.domain.speech.utterance import Utterance, apply_emotions
from facesynth.model.motion import Motion

from . import bilinear


def check_markers(names: list[str], model_names: list[str], motion_path: Path, model_path: Path) -> None:
    """Refuse motion whose markers are not those the model at ``model_path`` was fitted on."""
    if names != model_names:
        raise InputError(f"{motion_path}: its markers differ from those {model_path} was fitted on; "
                         "use motion from the same capture set-up.")


def nearest_emotion(model: bilinear.BilinearModel, styles: np.ndarray) -> list[str]:
    """The fitted emotion whose style vector is nearest each row of ``styles`` (T, I)."""
    d = np.linalg.norm(styles[:, None] - model.styles[None], axis=2)
    return [model.emotions[k] for k in np.argmin(d, axis=1)]


def analysis_lines(model: bilinear.BilinearModel, motion: Motion, settings: ExpressionSettings) -> list[str]:
    """CSV lines, one per frame of ``motion`` (at its output rate): time (s), the nearest
    fitted emotion, the style vector (e0..) and the content vector (c0..) of §3.3's analysis;
    frames with a missing marker (NaN) are skipped."""
    m = motion.markers
    ok = np.isfinite(m.reshape(len(m), -1)).all(axis=1)
    e, c = bilinear.analyze(model, model.coefficients(m[ok]), iterations=settings.analyze_iterations,
                            init=settings.analyze_init)
    nearest = nearest_emotion(model, e)
    header = ["time_s", "emotion"] + [f"e{i}" for i in range(e.shape[1])] + [f"c{j}" for j in range(c.shape[1])]
    lines = [",".join(header)]
    for row, t in enumerate(np.nonzero(ok)[0]):
        lines.append(",".join([f"{t / motion.fps:.4f}", nearest[row]] + [f"{v:.5g}" for v in e[row]]
                              + [f"{v:.5g}" for v in c[row]]))
    return lines


def targets(model: bilinear.BilinearModel, model_path: Path, n: int, fps: float, to: str | None, intensity: float,
            emotions_path: Path | None, ingest: IngestSettings, transition_s: float) -> tuple[np.ndarray, np.ndarray]:
    """Per frame target style (n, I) and intensity (n,): ``to`` everywhere, or each frame's
    span of the emotion file (frames outside every span keep their own expression)."""
    from scipy.ndimage import gaussian_filter1d

    I = model.styles.shape[1]
    if emotions_path is None:
        if to is None:
            raise InputError("give a target emotion (--to) or an emotions file (--emotions).")
        return np.repeat(model.style(to)[None], n, 0), np.full(n, intensity)
    t = np.arange(n) / fps
    utt = Utterance(["x"] * n, t, t + 1.0 / fps, [""] * n)
    apply_emotions(utt, emotions_path, tuple(model.emotions), ingest.emotion_aliases)
    alpha = np.array([intensity if e else 0.0 for e in utt.emotions])
    weighted = np.array([model.style(e) * intensity if e else np.zeros(I) for e in utt.emotions])
    sigma = transition_s * fps
    if sigma > 0 and n > 1:
        alpha = gaussian_filter1d(alpha, sigma, mode="nearest")
        weighted = gaussian_filter1d(weighted, sigma, axis=0, mode="nearest")
    target = np.where(alpha[:, None] > 1e-9, weighted / np.maximum(alpha, 1e-9)[:, None], 0.0)
    return target, alpha


def check_request(model: bilinear.BilinearModel, model_path: Path, to: str | None, intensity: float) -> None:
    """Refuse an emotion the model was not fitted with, or an intensity outside [0, 1]."""
    if to is not None and to not in model.emotions:
        raise InputError(f"{model_path}: the model was fitted with {', '.join(model.emotions)}, not {to!r}; "
                         "restyle to one of those or refit with takes in that emotion.")
    if not (0.0 <= intensity <= 1.0):
        raise InputError(f"--intensity {intensity:g}: give an intensity between 0 and 1 (Eq. 7 interpolates; "
                         "outside it extrapolates to invalid expressions).")


@dataclass(frozen=True)
class Restyled:
    """Marker motion in another expression (Eq. 7).

    markers: (T, M, 3) mm at the motion's output rate.
    capture: (T', M, 3) mm at its capture rate.
    from_emotion: the emotion most output frames were nearest to before ('unknown' when none
        could be analysed).
    """

    markers: np.ndarray
    capture: np.ndarray
    from_emotion: str


def restyled(model: bilinear.BilinearModel, motion: Motion, settings: ExpressionSettings, ingest: IngestSettings,
             model_path: Path, to: str | None, intensity: float, emotions_path: Path | None) -> Restyled:
    """``motion``'s markers in another expression (Eq. 7), at its output and its capture rate:
    towards ``to`` everywhere, or each frame's span of the emotion file ``emotions_path``."""
    results = []
    for frames, fps in ((motion.markers, motion.fps), (motion.markers_capture, motion.capture_fps)):
        target, alpha = targets(model, model_path, len(frames), fps, to, intensity, emotions_path, ingest,
                                settings.transition_s)
        results.append(bilinear.restyle(model, frames, target, alpha, iterations=settings.analyze_iterations,
                                        smooth_frames=settings.style_smoothing_s * fps, init=settings.analyze_init))
    (markers, styles), (capture, _) = results
    ok = np.isfinite(styles).all(axis=1)
    before = nearest_emotion(model, styles[ok]) if ok.any() else []
    return Restyled(markers, capture, max(set(before), key=before.count) if before else "unknown")
