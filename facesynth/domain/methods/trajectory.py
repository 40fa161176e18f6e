"""Compact key-shape trajectory synthesis (Huang, Chen & Chuang §5.4, Eq. 6-7): arrays in, arrays out.

Training. Every training frame (the PCA reconstruction of the database's frame, as a displacement
from the reference) is a non-negative combination of the joint key-shapes (Eq. 5, NNLS); per phone
the weights' mean and variance, and per (phone, emotion) where there are at least ``min_tokens``
tokens. Which frames: ``span`` (the paper: every frame tagged with the phone) or ``centre`` (the
centre frame of each token: sharper targets, fewer samples). Frames of pruned nodes are left out;
pauses are a phone like the others. The covariance is diagonal, as in the paper ("diagonal phoneme
covariance, assuming independent in each dimension"); each variance is floored at
``variance_floor`` times that weight's variance over all training frames, so that a key-shape a
phone never used (variance 0) gets a large but finite precision and a pair with few tokens cannot
pin a weight harder than the data justify.

Synthesis. Each frame t of the utterance (on the solve grid at ``fps``) takes the Gaussian of its
phone: the (phone, emotion) one when the model has it, else the phone's, else (a phone the model
never saw) the pooled Gaussian of the phones of its viseme class (Table VI) with a warning, or an
error when the model has none of them. Eq. 6,

    E = (x - mu)^T D^T Sigma^-1 D (x - mu) + lambda x^T W^T W x,

with D the duration normalization (each frame's data term times ``1 - D_ph / T``, D_ph the frames
of its phone, T the utterance's; floored at ``1 / T`` so a one-phone utterance still has a data
term) and W the first difference, is minimized by Eq. 7,

    (D^T Sigma^-1 D + lambda W^T W) x = D^T Sigma^-1 D mu.

With a diagonal Sigma the system separates into one tridiagonal T x T system per key-shape
weight; ordered weight-major they form one symmetric positive definite band matrix of half
bandwidth 1, solved in O(K T) by LAPACK's ``ptsv`` (``scipy.linalg.solveh_banded``). Lambda is
given per frame at ``smoothness_fps`` (the paper's 30 frames/s video); solved at another rate it is
scaled by ``(fps / smoothness_fps)^2``, which keeps the same time constant (the data term grows
with the frames per second, the squared first difference shrinks with their square). The matrix
is a Stieltjes matrix and the means are non-negative, so the solved weights are non-negative too.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np

from facesynth.base.config import SynthesizeSettings, TrajectorySettings
from facesynth.base.errors import InputError, UsageError
from facesynth.base.phonemes import PAU, VISEME_GROUPS, viseme
from facesynth.domain.postprocess.concatenation import downsample, downsample_sources, frame_ranges
from facesynth.domain.retarget.solve import nnls_weights
from facesynth.domain.speech.utterance import stand_in_phones
from facesynth.model.motion import Motion, Provenance, SearchPath
from facesynth.model.trajectory import TrajectoryModel

from . import FitSummary, Method, MethodSettings, NotEvaluable, Synthesis, SynthesisSummary
from .live import LiveSource, LiveStepper, Track, wrong_source

log = logging.getLogger(__name__)


# ---------------------------------------------------------------- training

@dataclass
class Samples:
    """Training frames of the trajectory model: rows (N,) int64 of the database's frames, and
    per row its phone, emotion and token (a running index of phone occurrences)."""

    rows: np.ndarray
    phone: np.ndarray
    emotion: np.ndarray
    token: np.ndarray


def training_samples(db, sampling: str) -> Samples:
    """The frames of ``db``'s training takes that feed the Gaussians. db : a MotionDatabase.
    ``sampling``: ``span`` (every frame of each phone) or ``centre`` (each token's centre frame).
    Frames of pruned nodes are left out (pauses, which are no node, are kept)."""
    takes, phones, nodes = db.takes, db.phones, db.nodes
    phone_emotion = phones.emotions(takes)
    kept = np.zeros(len(db.coeffs), bool)
    for k in range(len(nodes)):
        kept[nodes.frames(k)] = True
    rows, labels, emotions, tokens = [], [], [], []
    token = 0
    for i in range(len(takes)):
        if takes.split[i] != "train":
            continue
        sl = takes.frames(i)
        seg = np.nonzero(phones.take == i)[0]
        if not len(seg):
            continue
        ranges = frame_ranges(phones.start[seg], phones.end[seg], db.fps)
        for r, (a, b) in zip(seg, ranges):
            a, b = min(a, sl.stop - sl.start), min(b, sl.stop - sl.start)
            if b <= a:
                continue
            frames = np.arange(a, b) if sampling == "span" else np.array([(a + b - 1) // 2])
            frames = frames + sl.start
            if phones.phone[r] != PAU:
                frames = frames[kept[frames]]
            if not len(frames):
                continue
            rows.append(frames)
            labels += [phones.phone[r]] * len(frames)
            emotions += [phone_emotion[r]] * len(frames)
            tokens.append(np.full(len(frames), token))
            token += 1
    if not rows:
        raise InputError("the database has no training frames for the trajectory model; it needs takes with split 'train'.")
    return Samples(np.concatenate(rows), np.array(labels), np.array(emotions), np.concatenate(tokens))


@dataclass
class Gaussians:
    """Per-group means and variances of weights: labels (G,), means / variances (G, K) float64,
    tokens / samples (G,) int64."""

    labels: list
    means: np.ndarray
    variances: np.ndarray
    tokens: np.ndarray
    samples: np.ndarray


def group_gaussians(weights: np.ndarray, groups: np.ndarray, tokens: np.ndarray, floor: np.ndarray) -> Gaussians:
    """Mean and variance (the paper's 1/N estimate) of ``weights`` (N, K) per value of ``groups``
    (N,), variances at least ``floor`` (K,); labels in sorted order."""
    labels, inverse = np.unique(groups, return_inverse=True)
    k = weights.shape[1]
    counts = np.bincount(inverse, minlength=len(labels)).astype(np.float64)
    sums = np.zeros((len(labels), k))
    squares = np.zeros((len(labels), k))
    np.add.at(sums, inverse, weights)
    means = sums / counts[:, None]
    np.add.at(squares, inverse, (weights - means[inverse]) ** 2)
    variances = np.maximum(squares / counts[:, None], floor[None])
    ntok = np.array([len(np.unique(tokens[inverse == g])) for g in range(len(labels))], np.int64)
    return Gaussians([str(v) for v in labels], means, variances, ntok, counts.astype(np.int64))


def variance_floor(weights: np.ndarray, fraction: float) -> np.ndarray:
    """(K,) the variance floor: ``fraction`` times each weight's variance over ``weights`` (N, K),
    itself at least 1e-8 (a key-shape no training frame uses)."""
    return fraction * np.maximum(weights.var(0), 1e-8)


def fit_gaussians(weights: np.ndarray, samples: Samples, min_tokens: int, floor_fraction: float
                  ) -> tuple[Gaussians, Gaussians]:
    """Per phone and per (phone, emotion) Gaussians of ``weights`` (N, K), one row per sample; the
    pairs with fewer than ``min_tokens`` tokens are dropped (their phone's Gaussian stands in).
    Pair labels are 'phone|emotion'."""
    floor = variance_floor(weights, floor_fraction)
    phones = group_gaussians(weights, samples.phone, samples.token, floor)
    pairs = group_gaussians(weights, np.char.add(np.char.add(samples.phone.astype(str), "|"), samples.emotion.astype(str)),
                            samples.token, floor)
    keep = np.nonzero(pairs.tokens >= min_tokens)[0]
    pairs = Gaussians([pairs.labels[i] for i in keep], pairs.means[keep], pairs.variances[keep], pairs.tokens[keep],
                      pairs.samples[keep])
    return phones, pairs


# ---------------------------------------------------------------- synthesis

def pooled(means: np.ndarray, variances: np.ndarray, weights: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The mean and variance (K,) of the mixture of Gaussians ``means``, ``variances`` (G, K) with
    mixing ``weights`` (G,) (e.g. their sample counts): the moments of the pooled samples."""
    w = np.asarray(weights, np.float64) / np.sum(weights)
    mean = w @ means
    return mean, np.maximum(w @ (variances + means**2) - mean**2, variances.min(0))


@dataclass
class FrameTargets:
    """The Gaussian each solve-grid frame is pulled toward: means, variances (T, K) float64;
    ranges [a, b) of each phone on the grid; used (per phone) the label of the Gaussian used
    ('aa|happy', 'aa', or 'viseme:...'); fallbacks: phone -> the viseme pooling used for it."""

    means: np.ndarray
    variances: np.ndarray
    ranges: list[tuple[int, int]]
    used: list[str]
    fallbacks: dict[str, str]


def frame_targets(model, phones: list[str], emotions: list[str], starts: np.ndarray, ends: np.ndarray, fps: float,
                  where: str = "the utterance") -> FrameTargets:
    """Each frame's Gaussian for an utterance (phones, emotions, starts / ends in s) on the grid at
    ``fps``. model : a :class:`~facesynth.model.trajectory.TrajectoryModel`. A phone with no
    duration is an error naming it; an unseen phone falls back to its viseme class (warned once per
    phone), or is an error when the model has no phone of that class."""
    for t, (p, a, b) in enumerate(zip(phones, starts, ends)):
        if not b > a:
            raise InputError(f"{where}: phone {t + 1} /{p}/ at {a:.3f} s has no duration (end {b:.3f} s); "
                             "give every phone an end after its start.")
    ranges = frame_ranges(np.asarray(starts, float), np.asarray(ends, float), fps)
    index = {p: i for i, p in enumerate(model.phones)}
    pair_index = {(p, e): i for i, (p, e) in enumerate(zip(model.pair_phone, model.pair_emotion))}
    # each phone -> a row of the stacked table: the pairs, then the phones, then pooled visemes
    row_of: dict[tuple[str, str], int] = {}
    pooled_rows: list[tuple[np.ndarray, np.ndarray]] = []
    labels: list[str] = [f"{p}|{e}" for p, e in zip(model.pair_phone, model.pair_emotion)] + list(model.phones)
    fallbacks: dict[str, str] = {}
    rows = []
    for p, e in zip(phones, emotions):
        key = (p, e)
        if key not in row_of:
            if key in pair_index:
                row_of[key] = pair_index[key]
            elif p in index:
                row_of[key] = len(model.pair_phone) + index[p]
            else:
                group = [q for q in VISEME_GROUPS[viseme(p)] if q in index]
                if not group:
                    raise InputError(f"{where}: phone /{p}/ is not in the trajectory model and neither is any phone of "
                                     f"its viseme class ({' '.join(VISEME_GROUPS[viseme(p)])}); train the model on "
                                     "takes that have one of them.")
                if p not in fallbacks:
                    fallbacks[p] = " ".join(group)
                    log.warning("%s: phone /%s/ is not in the trajectory model; using the pooled Gaussian of its "
                                "viseme class (%s).", where, p, " ".join(group))
                members = [index[q] for q in group]
                pooled_rows.append(pooled(model.means[members].astype(np.float64),
                                          model.variances[members].astype(np.float64), model.samples[members]))
                labels.append("viseme:" + " ".join(group))
                row_of[key] = len(labels) - 1
        rows.append(row_of[key])
    means = np.concatenate([model.pair_means, model.means] + [m[None] for m, _ in pooled_rows]).astype(np.float64)
    variances = np.concatenate([model.pair_variances, model.variances] + [v[None] for _, v in pooled_rows]
                               ).astype(np.float64)
    rows = np.asarray(rows, np.int64)
    per_frame = np.repeat(rows, [b - a for a, b in ranges])
    used = [labels[r] for r in rows]
    return FrameTargets(means[per_frame], variances[per_frame], ranges, used, fallbacks)


def duration_weights(ranges: list[tuple[int, int]], total: int, normalize: bool = True) -> np.ndarray:
    """(T,) each frame's data-term weight, the square of Eq. 6's D: ``1 - D_ph / T`` with D_ph the
    frames of its phone and T = ``total``, floored at ``1 / T``; all ones without ``normalize``."""
    out = np.ones(total)
    if normalize and total > 0:
        for a, b in ranges:
            out[a:b] = max(1.0 - (b - a) / total, 1.0 / total)
    return out


def effective_lambda(smoothness: float, fps: float, smoothness_fps: float) -> float:
    """Lambda per frame at ``fps`` for ``smoothness`` given per frame at ``smoothness_fps``."""
    return smoothness * (fps / smoothness_fps) ** 2


def solve(means: np.ndarray, precisions: np.ndarray, lam: float, before: np.ndarray | None = None) -> np.ndarray:
    """Eq. 7 for a diagonal Sigma: x (T, K) float64 minimizing
    ``sum_t,k precisions[t,k] (x[t,k] - means[t,k])^2 + lam sum_t,k (x[t,k] - x[t-1,k])^2``.

    means, precisions : (T, K), precisions = D^T Sigma^-1 D's diagonal (> 0). One banded solve of
    the K tridiagonal systems stacked weight-major (half bandwidth 1). ``before`` (K,): the frame
    before the first, fixed (live synthesis continues a path already sent): its smoothness term
    ``lam (x[0] - before)^2`` joins the sum. The path is a Gauss-Markov chain, so this is the
    exact minimizer of the whole path's Eq. 6 given the frames up to ``before``."""
    mu = np.asarray(means, np.float64)
    p = np.asarray(precisions, np.float64)
    t, k = mu.shape
    if t == 0:
        return np.zeros((0, k))
    ab = np.empty((2, k, t))
    ww = np.zeros(t)  # diagonal of W^T W: 1, 2, ..., 2, 1 (0 for one frame), +1 at the start after `before`
    ww[1:] += 1.0
    ww[:-1] += 1.0
    if before is not None:
        ww[0] += 1.0
    ab[1] = p.T + lam * ww[None]
    ab[0] = -lam
    ab[0, :, 0] = 0.0  # no coupling across weights (and ab[0, 0, 0] is unused)
    weighted = p * mu
    if before is not None:
        weighted[0] += lam * np.asarray(before, np.float64)
    rhs = weighted.T.ravel()
    from scipy.linalg import solveh_banded  # here: `synthesize` of the DP method never loads SciPy

    x = solveh_banded(ab.reshape(2, k * t), rhs, overwrite_ab=True, overwrite_b=True, check_finite=False)
    return x.reshape(k, t).T


def dense_system(means: np.ndarray, variances: np.ndarray, d: np.ndarray, lam: float) -> tuple[np.ndarray, np.ndarray]:
    """Eq. 7 written out as in the paper, for testing: (A, b) with x time-major (alpha_1 .. alpha_T
    stacked). means, variances : (T, K); d : (T,) the squared diagonal of D."""
    t, k = means.shape
    dm = np.kron(np.diag(np.sqrt(d)), np.eye(k))
    sigma_inv = np.diag(1.0 / variances.ravel())
    w = np.kron(np.eye(t - 1, t, 1) - np.eye(t - 1, t), np.eye(k)) if t > 1 else np.zeros((0, k))
    data = dm.T @ sigma_inv @ dm
    return data + lam * w.T @ w, data @ means.ravel()


@dataclass
class Path:
    """A synthesized trajectory: weights (T, K) float64 on the solve grid at ``fps``; the targets;
    per phone the data and smoothness terms of Eq. 6 over its frames (``data``, ``smooth``: (U,))
    and their total ``energy``; lam, the lambda per frame used."""

    weights: np.ndarray
    fps: float
    targets: FrameTargets
    data: np.ndarray
    smooth: np.ndarray
    energy: float
    lam: float


def synthesize_path(model, phones: list[str], emotions: list[str], starts: np.ndarray, ends: np.ndarray, *,
                    smoothness: float, smoothness_fps: float, fps: float, duration_normalization: bool = True,
                    where: str = "the utterance") -> Path:
    """Eq. 6-7 for an utterance: the key-shape weight path on the grid at ``fps`` (0: the model's)."""
    fps = fps or model.fps
    targets = frame_targets(model, phones, emotions, starts, ends, fps, where)
    total = len(targets.means)
    d = duration_weights(targets.ranges, total, duration_normalization)
    precisions = d[:, None] / targets.variances
    lam = effective_lambda(smoothness, fps, smoothness_fps)
    x = solve(targets.means, precisions, lam)
    per_frame = (precisions * (x - targets.means) ** 2).sum(1)
    steps = np.zeros(total)
    if total > 1:
        steps[1:] = lam * ((x[1:] - x[:-1]) ** 2).sum(1)
    data, smooth = per_phone(per_frame, targets.ranges), per_phone(steps, targets.ranges)
    return Path(x, fps, targets, data, smooth, float(per_frame.sum() + steps.sum()), lam)


def per_phone(values: np.ndarray, ranges: list[tuple[int, int]]) -> np.ndarray:
    """(U,) the sums of per-frame ``values`` (T,) over each phone's frames [a, b) (0 for none)."""
    cumulative = np.concatenate([[0.0], np.cumsum(values)])
    edges = np.asarray(ranges, np.int64).reshape(-1, 2)
    return cumulative[edges[:, 1]] - cumulative[edges[:, 0]]


def resample(weights: np.ndarray, fps_in: float, n_out: int, fps_out: float) -> np.ndarray:
    """Weights (T, K) on the grid at ``fps_in`` linearly interpolated to ``n_out`` frames at
    ``fps_out`` (frame f at time f / fps); the same array when the grids agree."""
    if fps_in == fps_out and len(weights) == n_out:
        return weights
    t_in = np.arange(len(weights)) / fps_in
    t_out = np.arange(n_out) / fps_out
    return np.stack([np.interp(t_out, t_in, weights[:, j]) for j in range(weights.shape[1])], 1) \
        if len(weights) else np.zeros((n_out, weights.shape[1]))


# ---------------------------------------------------------------- the model and the motion artifact

def joint_keyshapes(keyshapes) -> tuple[np.ndarray, list[str], list[str]]:
    """The union of every emotion's key-shapes of a :class:`~facesynth.model.keyshapes.KeyShapes`:
    marker poses (K, M, 3) float32 mm, names and the emotion each came from, emotions in file order."""
    poses, names, emotions = [], [], []
    for emotion, e in keyshapes.emotions.items():
        poses.append(np.asarray(e.markers, np.float32))
        names += list(e.names)
        emotions += [emotion] * e.count
    return np.concatenate(poses), names, emotions


def train_model(db, keyshapes, settings, where: str = "the database"):
    """The trajectory model of a motion database's training takes over the joint key-shapes.

    db : a MotionDatabase; keyshapes : a KeyShapes of the same markers; settings : a
    :class:`~facesynth.base.config.TrajectorySettings`. Returns (TrajectoryModel, Samples)."""
    if list(keyshapes.marker_names) != list(db.marker_names):
        raise InputError(f"{where}: the key-shapes' markers are not the database's; choose the key-shapes from this "
                         "database with `facesynth keyshapes`.")
    poses, names, emotions = joint_keyshapes(keyshapes)
    reference = np.asarray(db.reference, np.float64)
    deltas = (poses.astype(np.float64) - reference).reshape(len(poses), -1)
    samples = training_samples(db, settings.frames)
    disp = (db.model.reconstruct(db.coeffs[samples.rows]).astype(np.float64) - reference).reshape(len(samples.rows), -1)
    weights, rms = nnls_weights(disp, deltas)
    phones, pairs = fit_gaussians(weights, samples, settings.min_tokens, settings.variance_floor)
    split = [label.split("|", 1) for label in pairs.labels]
    k = len(poses)
    model = TrajectoryModel(
        list(db.marker_names), reference.astype(np.float32), poses, names, emotions, phones.labels,
        phones.means.astype(np.float32), phones.variances.astype(np.float32), phones.tokens, phones.samples,
        [s[0] for s in split], [s[1] for s in split], pairs.means.astype(np.float32).reshape(-1, k),
        pairs.variances.astype(np.float32).reshape(-1, k), pairs.tokens, pairs.samples, float(db.fps), settings.frames,
        int(settings.min_tokens), float(settings.variance_floor), float(np.sqrt(np.mean(rms**2))))
    return model, samples


def synthesize_motion(model, utt, settings, output_fps: float, where: str = "the utterance", phone_match: str = "unseen"):
    """The ``motion`` artifact's contents (source ``trajectory``) for an utterance.

    model : a TrajectoryModel; utt : a :class:`~facesynth.domain.speech.utterance.Utterance`; settings :
    TrajectorySettings. The path is solved on its grid, interpolated to the model's capture rate
    (``markers_capture``), back-projected and down-sampled to ``output_fps`` as the DP's output is.
    Fields of the search that do not apply are filled so that every reader of a synthesized motion
    reads them: ``path/node`` -1 (no motion node), ``node_phone`` / ``node_emotion`` the phone and
    emotion of the Gaussian used (``viseme:s z`` for a viseme's pooled Gaussian; emotion '' for an
    all-emotion Gaussian),
    ``cost_oc`` / ``cost_tc`` the data and smoothness terms of Eq. 6 over each phone's frames,
    ``cost_emp`` and ``cost_block`` zero, ``total_cost`` Eq. 6; provenance node, take and source frame
    -1 (no source frame), ``smoothed`` False. The head does not move (identity rotation, zero
    translation): the model has no head motion. A phone of another language the model lacks takes
    its phone nearest in features (``phone_match``: ``synthesize.phone_match``). Returns (Motion, Path)."""
    path = synthesize_path(model, stand_in_phones(utt, set(model.phones), phone_match), list(utt.emotions),
                           utt.starts, utt.ends,
                           smoothness=settings.smoothness, smoothness_fps=settings.smoothness_fps, fps=settings.fps,
                           duration_normalization=settings.duration_normalization, where=where)
    ranges = frame_ranges(utt.starts, utt.ends, model.fps)
    n_capture = ranges[-1][1]
    weights = resample(path.weights, path.fps, n_capture, model.fps)
    markers_capture = model.markers(weights)
    markers = downsample(markers_capture, model.fps, output_fps)
    step = np.zeros(n_capture, np.int64)
    for t, (a, b) in enumerate(ranges):
        step[a:b] = t
    node_phone = [u.split("|")[0] for u in path.targets.used]
    node_emotion = [u.split("|")[1] if "|" in u else "" for u in path.targets.used]
    u = len(utt.phones)
    search = SearchPath(np.full(u, -1, np.int64), list(utt.phones), list(utt.emotions), node_phone, node_emotion,
                        np.asarray(utt.starts, float), np.asarray(utt.ends, float),
                        {"tc": path.smooth.astype(np.float32), "oc": path.data.astype(np.float32),
                         "emp": np.zeros(u, np.float32), "block": np.zeros(u, np.float32)},
                        path.energy, 0, "trajectory", "cpu (scipy.linalg.solveh_banded)",
                        "the trajectory method solves Eq. 7 on the host")
    none = np.full(n_capture, -1, np.int64)
    provenance = Provenance(none, none.copy(), [], none.copy(), step, np.zeros(n_capture, bool), model.fps)
    n_out = len(markers)
    rotation = np.repeat(np.eye(3, dtype=np.float32)[None], n_out, axis=0)
    motion = Motion(markers, output_fps, markers_capture, model.fps, list(model.marker_names),
                    np.asarray(model.reference, np.float32), rotation, np.zeros((n_out, 3), np.float32), None, search,
                    provenance, keyshape_weights=weights.astype(np.float32),
                    keyshape_names=list(model.keyshape_names))
    return motion, path


class TrajectoryMethod(Method):
    """Huang et al.'s key-shape trajectory; source: a ``trajectory`` artifact (fitted with the
    key-shapes of a ``keyshapes`` artifact)."""

    name = "trajectory"

    def read(self, path):

        return TrajectoryModel.read(path)

    def recorded_settings(self, settings: MethodSettings):
        return settings.trajectory

    def live(self, source, settings: MethodSettings) -> "TrajectoryLive":
        """Eq. 7 solved on ``source`` (a TrajectoryModel) as phones arrive, the sent frames fixed."""
        return TrajectoryLive(source, settings.synthesize, settings.trajectory)

    def evaluation_source(self, db, settings: MethodSettings, given, where: str):
        """The model given for this database (its fit needs key-shapes, which ``evaluate`` does not make)."""
        model = given.get(self.name)
        if model is None:
            raise NotEvaluable("give a model fitted on this database with --model (facesynth fit-method trajectory)")
        if model.fps != db.fps or list(model.marker_names) != list(db.marker_names):
            raise InputError("evaluate: the trajectory model's markers or capture rate are not the database's; "
                             "fit it on this database with `facesynth fit-method trajectory`.")
        return model

    def fit(self, db, settings: MethodSettings, *, keyshapes=None, where: str = "the database"):
        """The model of ``db``'s training takes over the joint key-shapes of ``keyshapes`` (a
        KeyShapes, needed); returns (TrajectoryModel, :class:`~facesynth.domain.methods.FitSummary` with
        ``keyshapes``, ``phones``, ``pairs``, ``samples``)."""
        if keyshapes is None:
            raise UsageError("the trajectory method is fitted over key-shapes; give them with --keyshapes "
                             "(facesynth keyshapes).")
        model, samples = train_model(db, keyshapes, settings.trajectory, where)
        return model, FitSummary(model.fit_rms, keyshapes=model.count, phones=len(model.phones),
                                 pairs=len(model.pair_phone), samples=len(samples.rows))

    def synthesize(self, source, utt, settings: MethodSettings, constraints=None, *, prepared=None,
                   where: str = "the utterance") -> Synthesis:
        """The path of Eq. 6-7 (:func:`synthesize_motion`); the summary holds the Eq. 6 ``energy``,
        ``lam`` (lambda) and the ``fallbacks`` (unseen phones and the viseme class that covered each)."""
        self.refuse_constraints(constraints)
        motion, path = synthesize_motion(source, utt, settings.trajectory, settings.synthesize.output_fps, where,
                                         settings.synthesize.phone_match)
        return Synthesis(motion, SynthesisSummary(len(utt), len(motion.markers), energy=path.energy, lam=path.lam,
                                                  fallbacks=path.targets.fallbacks))


class TrajectoryLive(LiveSource):
    """The trajectory member live on its fitted model (``settings``: its smoothness and duration
    normalization)."""

    what = "the trajectory model"

    def __init__(self, model, synth: SynthesizeSettings, settings: TrajectorySettings):
        if not isinstance(model, TrajectoryModel):
            raise wrong_source("trajectory", "a trajectory model", "`facesynth fit-method trajectory` in place of the "
                                "database")
        self.model, self.synth, self.settings = model, synth, settings
        self.fps = float(synth.output_fps)
        self.marker_names, self.reference = list(model.marker_names), np.asarray(model.reference, np.float32)
        #: the model's capture rate, as batch synthesis solves it (``trajectory.fps`` 0); output
        #: frames are down-sampled from it
        self.grid_fps = float(model.fps)
        self.emotions = sorted(set(model.keyshape_emotion) | set(model.pair_emotion))
        self.rest_markers = self.reference.copy()  # all key-shape weights 0

    def stepper(self) -> LiveStepper:
        return _TrajectoryStepper(self)


class _TrajectoryStepper(LiveStepper):
    def __init__(self, live: TrajectoryLive):
        self.live = live
        self.solved: tuple[int, np.ndarray] | None = None  # the last capture frame a sent frame used, (index, (K,) weights)

    def decide(self, track: Track, upto: int) -> list[int]:
        return [-1] * (upto - len(track.committed))  # no nodes: a committed phone's frames may be sent

    def final_limit(self, track: Track) -> int:
        return int(round(track.ends[len(track.committed) - 1] * self.live.grid_fps))  # the solve reaches every frame

    def render(self, track: Track, first: int, stop: int) -> np.ndarray:
        """Eq. 7 solved over the frames after the last one a sent frame used, up to the end of the
        known phones, that frame fixed (the frames between, used only by frames sent while a pause
        waited, are solved again), down-sampled as batch synthesis down-samples."""
        live = self.live
        model, settings, grid = live.model, live.settings, live.grid_fps
        ratio = grid / live.fps
        begin, before = (0, None) if self.solved is None else (self.solved[0] + 1, self.solved[1])
        k = max(0, int(np.searchsorted(np.array(track.starts), begin / grid + 1e-9, side="right")) - 1)
        while k > 0 and int(round(track.starts[k] * grid)) > begin:
            k -= 1
        targets = frame_targets(model, track.phones[k:], track.emotions[k:],
                                                  np.array(track.starts[k:]), np.array(track.ends[k:]), grid,
                                                  "the stream")
        ranges = targets.ranges  # on the capture grid: the targets start at frame ranges[0][0]
        offset, known = ranges[0][0], ranges[-1][1]
        # Eq. 6's D with T the frames known so far (the utterance's length is not known yet)
        d = duration_weights(ranges, known, settings.duration_normalization)[offset:]
        skip = begin - offset  # the targets' frames before the window
        precisions = d[skip:, None] / targets.variances[skip:]
        lam = effective_lambda(settings.smoothness, grid, settings.smoothness_fps)
        x = solve(targets.means[skip:], precisions, lam, before)
        # the capture frames batch's down-sampling takes output frames [first, stop) from
        below, above, w = downsample_sources(np.arange(first, stop), ratio, known)
        if below[0] < begin or above[-1] >= known:
            raise AssertionError(f"solve window [{begin}, {known}) does not hold frames [{first}, {stop})")  # a bug
        last = int(above[-1] if w[-1] > 0 else below[-1])  # the last capture frame a sent frame uses
        capture = model.markers(x[below[0] - begin: last + 1 - begin])
        lo, w3 = capture[below - below[0]], w[:, None, None]
        markers = lo if not w.any() else (lo * (1 - w3) + capture[np.minimum(above, last) - below[0]] * w3
                                          ).astype(capture.dtype)
        self.solved = (last, x[last - begin])
        return markers
