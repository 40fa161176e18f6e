"""The ``coarticulation`` method: a fitted Cohen-Massaro coarticulation model per (phone, emotion).

Cohen & Massaro (1993): every phone type p has a target pose ``T_p`` and a dominance
function ``D_i(t) = alpha_p * exp(-theta_p * |t - c_i|)`` around the centre ``c_i`` of each of
its tokens; the pose at time t is the dominance-weighted mean of the targets of all tokens
of the sentence::

    F(t) = sum_i D_i(t) T_{p(i)} / sum_i D_i(t)

(their exponent c is 1 here). Poses are vectors of any feature space; facesynth fits in the
database's PCA coefficients (K components), so the squared error of the fit is the marker
error of Eq. 13 up to the truncation of PCA.

Fitting (:func:`fit_dominance`) on training sentences: for given magnitudes ``alpha`` and
rates ``theta`` the targets enter linearly, so they are solved exactly by (ridge) least
squares (with a small ridge, :data:`RELATIVE_RIDGE`), and the 2P log-parameters are optimized on the remaining residual (variable
projection) with L-BFGS-B, whose gradient is exact at the solved targets (Golub & Pereyra).

As a member of the family (:class:`CoarticulationMethod`) the model is fitted per (phone, emotion)
(:func:`emotion_labels`) on a database's training takes and written as a ``coarticulation``
artifact (:class:`~facesynth.model.coarticulation.CoarticulationModel`, ``facesynth fit-method
coarticulation``); synthesis reads that file alone. A label the fit never saw takes the mean target
of that phone's other emotions, else of every type, with the median magnitude and rate.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.optimize import minimize

from facesynth.base.blas import one_blas_thread
from facesynth.base.config import EvaluateSettings
from facesynth.base.errors import InputError
from facesynth.base.phonemes import PAU
from facesynth.domain.postprocess.concatenation import frame_ranges
from facesynth.domain.speech.utterance import stand_in_phones
from facesynth.model.coarticulation import CoarticulationModel

from . import FitSummary, Method, MethodSettings, Synthesis, SynthesisSummary
from .steps import frame_motion

#: Ridge on the targets, relative to the mean diagonal of the design's Gram matrix at the
#: start: without it a type with a tiny magnitude gets a huge target that only fits the
#: training frames (on the tiny sample corpus the held-out error doubles).
RELATIVE_RIDGE = 1e-4
_LOG_ALPHA_BOUNDS = (np.log(1e-3), np.log(1e3))
_LOG_THETA_BOUNDS = (np.log(1.0), np.log(200.0))  # 1/s: dominance half-widths from 0.7 s to 3.5 ms


@dataclass(frozen=True)
class DominanceModel:
    """Cohen-Massaro parameters per phone type.

    phones : the P phone types (phones, or phone|emotion labels, :func:`emotion_labels`);
    targets : (P, K) poses; magnitude : (P,) alpha; rate : (P,) theta in 1/s. A label not
    seen in fitting takes the mean target with the median magnitude and rate (an unseen
    phone|emotion first the mean of that phone's other emotions).
    """

    phones: tuple[str, ...]
    targets: np.ndarray
    magnitude: np.ndarray
    rate: np.ndarray

    def _lookup(self, phones: list[str]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        index = {p: k for k, p in enumerate(self.phones)}
        rows = []
        for p in phones:
            if p in index:
                rows.append([index[p]])
            else:  # phone|emotion unseen: the phone in the other emotions; else everything
                same = [k for k, q in enumerate(self.phones) if q.split("|")[0] == p.split("|")[0]]
                rows.append(same or list(range(len(self.phones))))
        targets = np.stack([self.targets[r].mean(axis=0) for r in rows])
        alpha = np.array([np.median(self.magnitude[r]) for r in rows])
        theta = np.array([np.median(self.rate[r]) for r in rows])
        return targets, alpha, theta

    def predict(self, phones: list[str], starts: np.ndarray, ends: np.ndarray, n_frames: int, fps: float) -> np.ndarray:
        """Poses (n_frames, K) at ``fps`` for the phone sequence (times in s)."""
        targets, alpha, theta = self._lookup(phones)
        return token_weights(starts, ends, alpha, theta, n_frames, fps) @ targets


def token_weights(starts: np.ndarray, ends: np.ndarray, alpha: np.ndarray, theta: np.ndarray, n_frames: int,
                  fps: float) -> np.ndarray:
    """Normalized dominances (n_frames, n) of n tokens: row t sums to 1."""
    return normalized_dominances(centre_distances(np.arange(n_frames), starts, ends, fps), alpha, theta)


def centre_distances(frames: np.ndarray, starts: np.ndarray, ends: np.ndarray, fps: float) -> np.ndarray:
    """|t - c_i| (T, n) in s from the times of ``frames`` (T,) at ``fps`` to the centres of n tokens
    (``starts``, ``ends`` (n,) s)."""
    t = np.asarray(frames)[:, None] / fps
    centres = 0.5 * (np.asarray(starts) + np.asarray(ends))[None, :]
    return np.abs(t - centres)


def normalized_dominances(distances: np.ndarray, alpha: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """Dominances (T, n) of n tokens (magnitudes ``alpha`` (n,), rates ``theta`` (n,) 1/s) at
    ``distances`` (T, n) s from their centres, normalized so that row t sums to 1."""
    log_d = np.log(alpha)[None, :] - theta[None, :] * distances
    log_d -= log_d.max(axis=1, keepdims=True)  # no underflow far from every centre
    d = np.exp(log_d)
    return d / d.sum(axis=1, keepdims=True)


@dataclass
class _Sequence:
    token_type: np.ndarray  # (n,) index into the phone types
    distances: np.ndarray   # (T_kept, n) s, |t - c_i| from the kept frames to the token centres
    poses: np.ndarray       # (T_kept, K)
    type_pairs: np.ndarray  # (n * n,) flat index p(i) * P + p(j) into the (P, P) Gram matrix, row-major over (i, j)


def fit_dominance(sentences: list[tuple[list[str], np.ndarray, np.ndarray, np.ndarray, np.ndarray]], fps: float,
                  max_iterations: int = 40) -> DominanceModel:
    """Fit a :class:`DominanceModel` on training sentences.

    sentences : (phones, starts s, ends s, poses (T, K) at ``fps``, mask (T,) bool of the frames
    to fit: False for frames known to be bad, e.g. contaminated nodes). ``max_iterations``
    bounds the L-BFGS-B iterations.
    """
    types = sorted({p for s in sentences for p in s[0]})
    index = {p: k for k, p in enumerate(types)}
    n_types = len(types)
    seqs = []
    for phones, starts, ends, poses, mask in sentences:
        keep = np.nonzero(mask & np.isfinite(poses).all(axis=1))[0]
        token_type = np.array([index[p] for p in phones], dtype=np.int64)
        seqs.append(_Sequence(token_type, centre_distances(keep, np.asarray(starts, float), np.asarray(ends, float), fps),
                              poses[keep].astype(np.float64), (token_type[:, None] * n_types + token_type[None, :]).ravel()))
    total = np.concatenate([s.poses for s in seqs])
    y_norm = float((total**2).sum())
    type_pairs = np.concatenate([sq.type_pairs for sq in seqs])
    all_token_types = np.concatenate([sq.token_type for sq in seqs])

    def weights_of(x: np.ndarray) -> list[np.ndarray]:
        """Per sequence, the normalized token dominances (T_kept, n)."""
        alpha, theta = np.exp(x[:n_types]), np.exp(x[n_types:])
        return [normalized_dominances(sq.distances, alpha[sq.token_type], theta[sq.token_type]) for sq in seqs]

    ridge = [0.0]

    def solve(x: np.ndarray, with_gradient: bool = False):
        # The design of a sequence is W E, W (T_kept, n) its dominances and E (n, P) its tokens' one-hot
        # types, so the normal equations are assembled from the small token products: E^T (W^T W) E scatters
        # the (n, n) Gram matrix of the tokens onto their types' pairs, E^T (W^T Y) sums its rows by type.
        weights = weights_of(x)
        gram = np.bincount(type_pairs, weights=np.concatenate([(w.T @ w).ravel() for w in weights]),
                           minlength=n_types * n_types).reshape(n_types, n_types)
        if not ridge[0]:
            ridge[0] = RELATIVE_RIDGE * max(float(np.trace(gram)) / n_types, 1e-12)
        gram = gram + ridge[0] * np.eye(n_types)
        rhs = np.zeros((n_types, total.shape[1]))
        np.add.at(rhs, all_token_types, np.concatenate([w.T @ sq.poses for w, sq in zip(weights, seqs)]))
        targets = np.linalg.solve(gram, rhs)
        residual = ridge[0] * float((targets**2).sum())  # the ridge belongs to the objective, so the gradient below is exact
        gradient = np.zeros(2 * n_types)
        theta = np.exp(x[n_types:])
        for w, sq in zip(weights, seqs):
            token_targets = targets[sq.token_type]                                        # (n, K)
            fitted = w @ token_targets
            error = fitted - sq.poses
            residual += float((error**2).sum())
            if with_gradient:
                # variable projection: d residual / dx = 2 sum_t error_t . dF_t/dx at the solved targets, with
                # dF_t/dx = sum_i w_ti g_ti (T_p(i) - F_t), g = d log D_i / dx (1 for log alpha, -theta |tau| for log theta)
                h = w * (error @ token_targets.T - (error * fitted).sum(axis=1, keepdims=True))  # (T_kept, n)
                np.add.at(gradient, sq.token_type, 2.0 * h.sum(axis=0))
                np.add.at(gradient, n_types + sq.token_type, 2.0 * (h * (-theta[sq.token_type] * sq.distances)).sum(axis=0))
        return targets, residual, gradient

    # start: equal magnitudes, a 60 ms dominance decay (theta = 1/0.06 s); the ridge is fixed there
    x0 = np.concatenate([np.zeros(n_types), np.full(n_types, np.log(1 / 0.06))])
    solve(x0)
    bounds = [_LOG_ALPHA_BOUNDS] * n_types + [_LOG_THETA_BOUNDS] * n_types
    def objective(x: np.ndarray) -> tuple[float, np.ndarray]:
        _, residual, gradient = solve(x, with_gradient=True)
        return residual / y_norm, gradient / y_norm

    with one_blas_thread():  # products of tens of rows
        result = minimize(objective, x0, jac=True, method="L-BFGS-B", bounds=bounds, options={"maxiter": max_iterations})
        targets, _, _ = solve(result.x)
    return DominanceModel(tuple(types), targets, np.exp(result.x[:n_types]), np.exp(result.x[n_types:]))


def emotion_labels(phones: list[str], emotions: list[str]) -> list[str]:
    """Phone labels that carry the emotion ('aa|happy'): a model fitted on them has a target,
    magnitude and rate per (phone, emotion); a pause stays one type."""
    return [p if p == PAU else f"{p}|{e}" for p, e in zip(phones, emotions)]


def training_sentences(db, by_emotion: bool = False) -> list[tuple[list[str], np.ndarray, np.ndarray, np.ndarray, np.ndarray]]:
    """The training takes of a motion database as :func:`fit_dominance` sentences in PCA
    coefficients, frames of pruned (removed) nodes masked out. db : a MotionDatabase.
    ``by_emotion``: phone labels per (phone, emotion) (:func:`emotion_labels`)."""
    takes, phones, nodes = db.takes, db.phones, db.nodes
    phone_emotion = phones.emotions(takes)
    kept = np.zeros(len(db.coeffs), bool)
    for k in range(len(nodes)):
        kept[nodes.frames(k)] = True
    out = []
    for i in range(len(takes)):
        if takes.split[i] != "train":
            continue
        sl = takes.frames(i)
        rows = np.nonzero(phones.take == i)[0]
        labels = [phones.phone[r] for r in rows]
        mask = kept[sl].copy()
        if by_emotion:
            labels = emotion_labels(labels, [phone_emotion[r] for r in rows])
        for r, p in zip(rows, labels):  # pauses are no node but belong to the fit
            if p == PAU:
                a, b = int(round(phones.start[r] * db.fps)), int(round(phones.end[r] * db.fps))
                mask[a:b] = True
        out.append((labels, phones.start[rows], phones.end[rows], db.coeffs[sl], mask))
    return out


def fit_rms(model: DominanceModel, sentences, fps: float, basis: np.ndarray) -> float:
    """RMS per marker (mm) of ``model`` on the fitted frames of ``sentences`` (as for
    :func:`fit_dominance`); ``basis`` (3M, K) orthonormal, so coefficient errors are marker errors."""
    total, count = 0.0, 0
    for phones, starts, ends, poses, mask in sentences:
        keep = np.nonzero(mask & np.isfinite(poses).all(axis=1))[0]
        if not len(keep):
            continue
        fitted = model.predict(phones, starts, ends, int(keep.max()) + 1, fps)[keep]
        total += float(((fitted - poses[keep]) ** 2).sum())
        count += len(keep)
    markers = basis.shape[0] // 3
    return float(np.sqrt(total / max(count * markers, 1)))


class CoarticulationMethod(Method):
    """The fitted Cohen-Massaro model per (phone, emotion); source: a ``coarticulation`` artifact."""

    name = "coarticulation"
    not_live = ("each frame depends on the dominance of phones after it, up to the end of the utterance "
                "(a live form would need a look-ahead the model does not bound)")

    def read(self, path):

        return CoarticulationModel.read(path)

    def for_evaluation(self, settings: MethodSettings, evaluate: EvaluateSettings) -> MethodSettings:
        """Fitted with ``evaluate.dominance_iterations`` L-BFGS-B iterations."""
        return settings.replace(coarticulation=dataclasses.replace(settings.coarticulation,
                                                                   iterations=evaluate.dominance_iterations))

    def ablations(self, db, settings: MethodSettings) -> dict[str, Callable[[Any], np.ndarray]]:
        """``coarticulation_per_phone``: the same model per phone (every emotion pooled), fitted on
        ``db``'s training takes."""
        model = fit_dominance(training_sentences(db, by_emotion=False), db.fps, settings.coarticulation.iterations)

        def markers(utt) -> np.ndarray:
            total = frame_ranges(utt.starts, utt.ends, db.fps)[-1][1]
            return db.model.reconstruct(model.predict(utt.phones, utt.starts, utt.ends, total, db.fps))
        return {"coarticulation_per_phone": markers}

    def fit(self, db, settings: MethodSettings, *, keyshapes=None, where: str = "the database"):
        """The model of ``db``'s training takes (``coarticulation.iterations`` L-BFGS-B iterations);
        returns (CoarticulationModel, :class:`~facesynth.domain.methods.FitSummary` with ``labels``)."""
        sentences = training_sentences(db, by_emotion=True)
        if not sentences:

            raise InputError(f"{where}: no take has split 'train'; the coarticulation model is fitted on the "
                             "training takes.")
        model = fit_dominance(sentences, db.fps, settings.coarticulation.iterations)
        rms = fit_rms(model, sentences, db.fps, db.model.basis)
        out = CoarticulationModel(list(model.phones), model.targets, model.magnitude, model.rate, db.model,
                                  list(db.marker_names), np.asarray(db.reference, np.float32), float(db.fps),
                                  int(settings.coarticulation.iterations), rms)
        return out, FitSummary(rms, labels=len(model.phones))

    def synthesize(self, source, utt, settings: MethodSettings, constraints=None, *, prepared=None,
                   where: str = "the utterance") -> Synthesis:
        """The model's poses at the capture rate (Eq. 11 through its PCA model), down-sampled to
        ``synthesize.output_fps``; the summary's ``unseen`` names the (phone, emotion) pairs the fit never
        saw ('/aa/ in sad', or '/zh/' for a phone it never saw in any emotion) and what covers each."""
        self.refuse_constraints(constraints)
        model = DominanceModel(tuple(source.labels), source.targets, source.magnitude, source.rate)
        fitted = {label.split("|")[0] for label in source.labels}
        labels = emotion_labels(stand_in_phones(utt, fitted, settings.synthesize.phone_match), list(utt.emotions))
        total = frame_ranges(utt.starts, utt.ends, source.fps)[-1][1]
        coeffs = model.predict(labels, utt.starts, utt.ends, total, source.fps)
        markers = source.pca.reconstruct(coeffs)
        known = set(source.labels)
        seen_phones = {k.split("|")[0] for k in known}
        unseen = {}
        for label in dict.fromkeys(labels):
            if label not in known:
                phone, _, emotion = label.partition("|")
                if phone in seen_phones:
                    unseen[f"/{phone}/ in {emotion}"] = "the mean of that phone's other emotions"
                else:
                    unseen[f"/{phone}/"] = "the mean of every phone type"
        motion = frame_motion(self.name, utt, markers, coeffs, source.fps, settings.synthesize.output_fps,
                              source.marker_names, source.reference, list(utt.phones),
                              [e if p != PAU else "" for p, e in zip(utt.phones, utt.emotions)], "cpu (NumPy)")
        return Synthesis(motion, SynthesisSummary(len(utt), len(motion.markers), unseen))
