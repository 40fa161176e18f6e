"""``facesynth expression fit|analyze|restyle``: the bilinear style/content model of Chuang &
Bregler (2005) §3 on marker motion (the math is :mod:`facesynth.domain.expression.bilinear`).

fit: the takes of each sentence in every emotion are time-warped phone by phone onto one
timeline (the neutral take's when there is one; pauses placed differently are warped over), so
that frame c is the same speech in every emotion; the aligned frames are projected on their PCA (Eq. 1) and factored by Eq. 4-6.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.config import ExpressionSettings, IngestSettings, settings_json
from facesynth.base.errors import InputError
from facesynth.base.phonemes import PAU
from facesynth.domain.expression import bilinear
from facesynth.domain.speech.utterance import Utterance, apply_emotions
from facesynth.model.artifacts import check_output
from facesynth.model.expression import ExpressionModel
from facesynth.model.frames import NormalizedFrames
from facesynth.model.motion import Motion

log = logging.getLogger(__name__)


def aligned_data(norm: NormalizedFrames, splits, frame_step: int) -> tuple[np.ndarray, list[str], list[str], list[str]]:
    """Every sentence's takes warped onto one timeline.

    Returns X (S, C, M, 3) mm (style, aligned frame), the S emotions, the sentences used and
    notes on the sentences skipped (not in every emotion, or different spoken phones).
    """
    blocks, emotions, used, notes = aligned_blocks(norm, splits, frame_step)
    return np.concatenate(blocks, axis=1), emotions, used, notes


def aligned_blocks(norm: NormalizedFrames, splits, frame_step: int
                   ) -> tuple[list[np.ndarray], list[str], list[str], list[str]]:
    """As :func:`aligned_data`, one (S, n, M, 3) block per sentence used."""
    takes, phones, fr = norm.takes, norm.phones, norm.frames
    use = [i for i in range(len(takes)) if takes.split[i] in splits]
    if not use:
        raise InputError(f"no takes in the splits {', '.join(splits)}; set expression.splits to splits the corpus has.")
    emotions = sorted({takes.emotion[i] for i in use}, key=lambda e: (e != "neutral", e))
    by_sentence: dict[str, dict[str, int]] = {}
    for i in use:
        by_sentence.setdefault(takes.sentence[i], {})[takes.emotion[i]] = i
    spoken = np.array([p != PAU for p in phones.phone])
    rows_of = {i: np.nonzero((phones.take == i) & spoken)[0] for i in use}
    blocks, used, notes = [], [], []
    for sentence, takes_of in sorted(by_sentence.items()):
        missing = [e for e in emotions if e not in takes_of]
        if missing:
            notes.append(f"sentence {sentence}: no take in {', '.join(missing)}")
            continue
        seqs = {e: [phones.phone[r] for r in rows_of[takes_of[e]]] for e in emotions}
        ref = takes_of[emotions[0]]
        if any(seqs[e] != seqs[emotions[0]] for e in emotions):
            notes.append(f"sentence {sentence}: the spoken phones differ between emotions")
            continue
        rr = rows_of[ref]
        t0, t1 = float(phones.start[rr[0]]), float(phones.end[rr[-1]])
        times = np.arange(int(np.ceil(t0 * fr.fps)), int(np.floor(t1 * fr.fps)), frame_step) / fr.fps
        warped = []
        for e in emotions:
            i = takes_of[e]
            r = rows_of[i]
            warped.append(bilinear.warp_take(fr.loaded_markers()[takes.frames(i)], fr.fps, (phones.start[r], phones.end[r]),
                                             (phones.start[rr], phones.end[rr]), times))
        block = np.stack(warped)                                   # (S, n, M, 3)
        ok = np.isfinite(block).all(axis=(0, 2, 3))
        blocks.append(block[:, ok])
        used.append(sentence)
    if not blocks:
        raise InputError("no sentence has takes in every emotion with the same phones ("
                         + "; ".join(notes[:3]) + "); the bilinear fit needs the same sentences in each emotion.")
    return blocks, emotions, used, notes


def fit_model(X: np.ndarray, emotions: list[str], settings: ExpressionSettings) -> bilinear.BilinearModel:
    """PCA of the aligned frames (Eq. 1), then the bilinear fit (Eq. 4-6). X : (S, C, M, 3) mm."""
    S, C = X.shape[:2]
    flat = X.reshape(S * C, -1).astype(np.float64)
    mean = flat.mean(axis=0)
    centred = flat - mean
    values, vectors = np.linalg.eigh(centred.T @ centred)    # the PCA of Eq. 1 from the (3M, 3M) scatter
    basis = vectors[:, ::-1][:, :min(settings.components, len(values))].T
    Y = ((flat - mean) @ basis.T).reshape(S, C, -1)
    return bilinear.fit(Y, emotions, mean, basis, content_dim=settings.content_dim,
                        max_iterations=settings.max_iterations, tolerance=settings.tolerance)


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


def _check_markers(names: list[str], model_names: list[str], motion_path: Path, model_path: Path) -> None:
    if names != model_names:
        raise InputError(f"{motion_path}: its markers differ from those {model_path} was fitted on; "
                         "use motion from the same capture set-up.")


def nearest_emotion(model: bilinear.BilinearModel, styles: np.ndarray) -> list[str]:
    """The fitted emotion whose style vector is nearest each row of ``styles`` (T, I)."""
    d = np.linalg.norm(styles[:, None] - model.styles[None], axis=2)
    return [model.emotions[k] for k in np.argmin(d, axis=1)]


def analyze(model_path: Path, motion_path: Path, settings: ExpressionSettings) -> list[str]:
    """``expression analyze``: CSV lines, one per output frame: time (s), the nearest fitted
    emotion, the style vector (e0..) and the content vector (c0..); NaN frames are skipped."""
    model, names = ExpressionModel.read(model_path)
    motion = Motion.read(motion_path)
    _check_markers(motion.marker_names, names, motion_path, model_path)
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


def restyle(model_path: Path, motion_path: Path, out: Path, settings: ExpressionSettings, ingest: IngestSettings, *,
            to: str | None, intensity: float, emotions_path: Path | None, overwrite: bool = False) -> RestyleResult:
    """``expression restyle``: the motion in another expression (Eq. 7), at the output and
    the capture rate, head motion kept; writes a ``motion`` artifact (``source = restyle``)."""
    check_output(out, overwrite)
    model, names = ExpressionModel.read(model_path)
    check_request(model, model_path, to, intensity)
    motion = Motion.read(motion_path)
    _check_markers(motion.marker_names, names, motion_path, model_path)
    results = []
    for frames, fps in ((motion.markers, motion.fps), (motion.markers_capture, motion.capture_fps)):
        target, alpha = targets(model, model_path, len(frames), fps, to, intensity, emotions_path, ingest,
                                settings.transition_s)
        results.append(bilinear.restyle(model, frames, target, alpha, iterations=settings.analyze_iterations,
                                        smooth_frames=settings.style_smoothing_s * fps, init=settings.analyze_init))
    (markers, styles), (capture, _) = results
    Motion(markers, motion.fps, capture, motion.capture_fps, motion.marker_names, motion.reference,
           motion.head_rotation, motion.head_translation, source="restyle").write(out, config=settings_json(settings),
                                   inputs=[p for p in (model_path, motion_path, emotions_path) if p is not None],
                                   overwrite=overwrite)
    ok = np.isfinite(styles).all(axis=1)
    before = nearest_emotion(model, styles[ok]) if ok.any() else []
    return RestyleResult(len(markers), max(set(before), key=before.count) if before else "unknown",
                         float(np.sqrt(np.nanmean((markers - motion.markers) ** 2)) * np.sqrt(3)))

