"""The search of ``facesynth tune``: the cost weights, PNT, the join smoothing window and the
boundary-fit length by cross-validation on the validation takes (paper VI-D).

The objective is Eq. 12-13 on the validation takes (``split = val``, never in the database):
every sentence is synthesized with candidate settings and compared with its capture; the
score is the mean per-sentence error (mm^2). The search runs in three parts:

1. **Weights** (alpha1..alpha6 and PNT): Nelder-Mead, derivative-free (the objective is
   piecewise constant in the weights), in log space (alpha4 through a logistic, so it stays in
   (0, 1)), from ``starts`` starts: the current values, then random ones drawn log-uniformly
   within ``spread`` of them. PNT is tuned too: the viseme, observation, emotion and rule-4
   penalties scale with it, but PGap, VGap and DSC do not, so it sets their balance.
2. **Boundary-fit length** (``build_db.boundary_fit_frames``): each candidate length's
   boundary velocities are recomputed from the database's coefficients once.
3. **Smoothing window** (``synthesize.smoothing_half_window``): only post-processing
   changes, so the searched paths of the best weights are re-rendered, not searched again.

Reuse: the sentences, their capture and the per-node features are read once. Each weight
setting runs the pruned DP (on OpenCL when there is a device). Without OpenCL, the pair terms
(DSC, PGap, VGap of every ordered pair, which do not depend on the weights) are computed once
as three (N, N) float32 tables when they fit in a quarter of the free memory (VGap once more
per boundary-fit length), and each weight setting only sums them (Table I, bit-identical to
the on-demand costs) for the dense NumPy DP, which gives the pruned DP's path and cost. Searched paths are cached per (weights, fit length) and
re-rendered for other windows; every setting is evaluated once.

Safety: the start settings are the first evaluation and a candidate replaces the best only if
it is strictly better on the validation takes, so the written settings are never worse there
than the start; when nothing beats the start, the start settings are written with a warning
saying so. The test takes, which tuning never sees, give the error before and after with
bootstrap 95% intervals over sentences (and of the paired difference).

A sentence is anything with ``utterance`` (an :class:`~facesynth.domain.speech.utterance.Utterance`)
and ``truth`` (its captured markers, (T, M, 3) mm at the capture rate), such as the held-out
sentences of :func:`facesynth.domain.evaluation.held_out.heldout`.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np
from scipy.optimize import minimize
from scipy.special import expit

from facesynth.base.config import SynthesizeSettings, TuneSettings
from facesynth.base.limits import mem_available
from facesynth.domain.search.pairs import PairTerms, TransitionCosts, boundary_states, node_features, pivot_distances
from facesynth.domain.search.synthesis import render_path, synthesize
from facesynth.model.motiondb import MotionDatabase

ALPHAS = ("alpha1", "alpha2", "alpha3", "alpha4", "alpha5", "alpha6")
WEIGHTS = ALPHAS + ("pnt",)
#: Candidate boundary-fit lengths (frames at the capture rate) and smoothing half-windows (frames).
FIT_LENGTHS = (2, 3, 5, 7, 9, 13)
WINDOWS = (0, 3, 6, 9, 12, 18, 24)


def to_vector(s: SynthesizeSettings) -> np.ndarray:
    """The search vector of the weights: logs, alpha4 as a logit, then log PNT."""
    a4 = min(max(s.alpha4, 1e-6), 1 - 1e-6)
    return np.array([np.log(s.alpha1), np.log(s.alpha2), np.log(s.alpha3), np.log(a4 / (1 - a4)), np.log(s.alpha5),
                     np.log(s.alpha6), np.log(s.pnt)])


def from_vector(v: np.ndarray, s: SynthesizeSettings) -> SynthesizeSettings:
    """Settings with the weights of search vector ``v``."""
    a = np.exp(v)
    return dataclasses.replace(s, alpha1=float(a[0]), alpha2=float(a[1]), alpha3=float(a[2]),
                               alpha4=float(np.clip(expit(v[3]), 1e-6, 1 - 1e-6)), alpha5=float(a[4]),
                               alpha6=float(a[5]), pnt=float(a[6]))


def sentence_error(syn: np.ndarray, truth: np.ndarray) -> float:
    """Eq. 13 of one sentence: mean over frames and markers of the squared distance (mm^2) between
    synthesized and captured markers ((T, M, 3) each, the capture rate; NaN in the capture skipped)."""
    n = min(len(syn), len(truth))
    return float(np.nanmean(np.sum((syn[:n].astype(np.float64) - truth[:n]) ** 2, axis=2)))


def bootstrap_mean(values: np.ndarray, seed: int, draws: int = 2000) -> list[float]:
    """Bootstrap 95% interval of the mean of ``values`` (one per sentence)."""
    if len(values) < 2:
        return [float(np.mean(values))] * 2 if len(values) else [float("nan")] * 2
    rng = np.random.default_rng(seed)
    means = values[rng.integers(0, len(values), (draws, len(values)))].mean(axis=1)
    return [float(np.percentile(means, 2.5)), float(np.percentile(means, 97.5))]


class Objective:
    """Mean Eq. 13 error (mm^2) over ``sentences`` for (weights, fit length, window), with the
    caches that make repeated evaluations cheap."""

    def __init__(self, db: MotionDatabase, synth: SynthesizeSettings, opencl: bool):
        self.db, self.synth, self.opencl = db, synth, opencl
        self.features = {}
        self.terms = {}
        # Without OpenCL, the weight-free pair terms as tables when they fit in a quarter of the
        # free memory (after a few settings the dense NumPy DP on them beats the NumPy pruned DP);
        # with OpenCL the pruned DP is faster from the first setting (measured: 1.4 against 6.3 s
        # of CPU per setting for 6 sentences of the paper preset, 0.8 against 0.8 on the small one).
        free = mem_available()
        fits = PairTerms.bytes_for(len(db.nodes)) < (free if free is not None else 2 << 30) / 4
        self.tables = fits and not opencl
        self.base_features = node_features(db)
        self.paths: dict[tuple, list[np.ndarray]] = {}
        self.scores: dict[tuple, tuple[float, np.ndarray]] = {}

    def features_for(self, fit: int):
        """The database's transition features with boundary velocities fitted over ``fit`` frames,
        their pivot distances computed once (every weight setting's search bounds with them)."""
        if fit not in self.features:
            db = self.db
            states = boundary_states(db.coeffs, db.nodes, db.model, fit)
            fitted = dataclasses.replace(self.base_features, first_vel=states[2], last_vel=states[3],
                                         pivot_distances=None)
            self.features[fit] = dataclasses.replace(fitted, pivot_distances=pivot_distances(fitted))
        return self.features[fit]

    def errors(self, s: SynthesizeSettings, fit: int, sentences, tag: str) -> np.ndarray:
        """Per-sentence errors (mm^2) of ``sentences`` (named ``tag`` in the caches)."""
        weights = tuple(round(getattr(s, k), 12) for k in WEIGHTS)
        key = (tag, weights, fit, s.smoothing_half_window)
        if key in self.scores:
            return self.scores[key][1]
        path_key = (tag, weights, fit)
        out = np.empty(len(sentences))
        if path_key in self.paths:
            for k, (sentence, path) in enumerate(zip(sentences, self.paths[path_key])):
                out[k] = sentence_error(render_path(self.db, sentence.utterance, path, s).markers_capture, sentence.truth)
        else:
            if self.tables:  # the pair terms once per fit length; per weights only the sums (bit-identical)
                if fit not in self.terms:  # DSC and PGap do not depend on the fit: shared
                    self.terms[fit] = PairTerms(self.features_for(fit), next(iter(self.terms.values()), None))
                tc = self.terms[fit].costs(s)
                s = dataclasses.replace(s, dp="dense", use_opencl=False)  # the same path and cost as the pruned DP
            else:
                tc = TransitionCosts(self.features_for(fit), s, self.opencl)
            paths = []
            for k, sentence in enumerate(sentences):
                res = synthesize(self.db, sentence.utterance, {}, s, tc=tc)
                paths.append(res.path)
                out[k] = sentence_error(res.rendered.markers_capture, sentence.truth)
            self.paths[path_key] = paths
        self.scores[key] = (float(out.mean()), out)
        return out


#: Start-simplex steps in log space: a factor e^0.7 (about 2) in every weight, but e^3.5 (about
#: 33) in alpha2, so the search reaches weights where DSC changes the path at all (at the
#: default 0.00123 the results equal those of alpha2 = 0 on the sample corpus).
SIMPLEX_STEPS = np.array([0.7, 3.5, 0.7, 0.7, 0.7, 0.7, 0.7])


def _simplex(v: np.ndarray) -> np.ndarray:
    """The start simplex around ``v`` (:data:`SIMPLEX_STEPS`)."""
    return np.vstack([v] + [v + SIMPLEX_STEPS[i] * np.eye(len(v))[i] for i in range(len(v))])




@dataclasses.dataclass(frozen=True)
class Tuning:
    """What the search found (errors are Eq. 13's, mm^2).

    validation_sentences, test_sentences: sentences tuned on, and held out for the report.
    evaluations: settings evaluated.
    validation_err_before, validation_err_after: the validation error of the start and of the result.
    improved: whether the result beats the start (if not, the result is the start).
    weights: the tuned cost weights (alpha1..alpha6, PNT) by name.
    smoothing_half_window: the tuned join smoothing window (frames).
    boundary_fit_frames: the tuned boundary-fit length (frames).
    boundary_fit_changed: whether that differs from the start (build-db must run again).
    warnings: what the user should know.
    test_err_before, test_err_after: the test error of the start and of the result (None without test takes).
    test_ci_before, test_ci_after, test_ci_difference: their bootstrap 95% intervals, and that of
        the difference (after - before), as [low, high].
    """

    validation_sentences: int
    test_sentences: int
    evaluations: int
    validation_err_before: float
    validation_err_after: float
    improved: bool
    weights: dict[str, float]
    smoothing_half_window: int
    boundary_fit_frames: int
    boundary_fit_changed: bool
    warnings: list[str]
    test_err_before: float | None = None
    test_err_after: float | None = None
    test_ci_before: list[float] | None = None
    test_ci_after: list[float] | None = None
    test_ci_difference: list[float] | None = None


def tune(objective: Objective, validation: Sequence[Any], test: Sequence[Any], settings: TuneSettings,
         fit0: int, progress_fn: Callable[[int, int, float, float], None] | None = None) -> Tuning:
    """Tune the weights of ``objective.synth`` (the start), then the boundary-fit length (from
    ``fit0``, the database's), then the smoothing window on the ``validation`` sentences (see the
    module docstring); the start and the result are then scored on the ``test`` sentences.
    ``progress_fn(done, total, error, best)`` is called after each evaluation."""
    start = objective.synth
    fits = [f for f in FIT_LENGTHS if f != fit0]
    windows = [w for w in WINDOWS if w != start.smoothing_half_window]
    total = settings.max_evaluations + len(fits) + len(windows)
    state = {"done": 0, "best": np.inf}

    def score(s: SynthesizeSettings, fit: int) -> float:
        value = float(objective.errors(s, fit, validation, "val").mean())
        state["done"] += 1
        state["best"] = min(state["best"], value)
        if progress_fn:
            progress_fn(min(int(state["done"]), total), total, value, state["best"])
        return value

    best_s, best_fit = start, fit0
    before_val = best_f = score(start, fit0)

    # 1. the weights, Nelder-Mead from several starts
    rng = np.random.default_rng(settings.seed)
    v0 = to_vector(start)
    starts = [v0] + [v0 + rng.uniform(-np.log(settings.spread), np.log(settings.spread), len(v0))
                     for _ in range(settings.starts - 1)]
    per_start = max(4, (settings.max_evaluations - 1) // max(1, settings.starts))
    seen: dict[tuple, float] = {}

    def weights_objective(v: np.ndarray) -> float:
        key = tuple(np.round(v, 6))
        if key not in seen:
            seen[key] = score(from_vector(v, start), fit0)
        return seen[key]

    seen[tuple(np.round(v0, 6))] = before_val
    for v in starts:
        result = minimize(weights_objective, v, method="Nelder-Mead",
                          options={"maxfev": per_start, "xatol": 1e-2, "fatol": 1e-4, "initial_simplex": _simplex(v)})
        if result.fun < best_f:
            best_s, best_f = from_vector(result.x, start), float(result.fun)
    # 2. the boundary-fit length, 3. the smoothing window (paths reused)
    for fit in fits:
        f = score(best_s, fit)
        if f < best_f:
            best_fit, best_f = fit, f
    for w in windows:
        candidate = dataclasses.replace(best_s, smoothing_half_window=w)
        f = score(candidate, best_fit)
        if f < best_f:
            best_s, best_f = candidate, f
    improved = best_f < before_val
    if not improved:
        best_s, best_fit, best_f = start, fit0, before_val
    found = Tuning(len(validation), len(test), int(state["done"]), before_val, best_f, improved,
                   {k: getattr(best_s, k) for k in WEIGHTS}, best_s.smoothing_half_window, best_fit, best_fit != fit0,
                   [] if improved else [f"no setting tried beat the start on the validation takes ({before_val:.4f} "
                                        "mm^2); the start settings are written unchanged."])
    if test:
        before = objective.errors(start, fit0, test, "test")
        after = objective.errors(best_s, best_fit, test, "test")
        found = dataclasses.replace(found, test_err_before=float(before.mean()), test_err_after=float(after.mean()),
                                    test_ci_before=bootstrap_mean(before, settings.seed),
                                    test_ci_after=bootstrap_mean(after, settings.seed),
                                    test_ci_difference=bootstrap_mean(after - before, settings.seed))
    return found


def config_text(found: Tuning, method: str) -> str:
    """The tuned settings as TOML ``[synthesize]`` and ``[build_db]`` sections that ``--config``
    accepts (``method``: the search tuned; a changed boundary-fit length takes effect when
    ``build-db`` runs again)."""
    lines = ["# Settings tuned by `facesynth tune` (paper VI-D): use with --config.",
             f"# validation error (Eq. 13, mm^2): {found.validation_err_before:.4f} -> {found.validation_err_after:.4f}"]
    if found.test_err_before is not None:
        assert found.test_ci_before is not None and found.test_ci_after is not None
        lo_b, hi_b = found.test_ci_before
        lo_a, hi_a = found.test_ci_after
        lines.append(f"# test error (Eq. 13, mm^2):       {found.test_err_before:.4f} [{lo_b:.4f}, {hi_b:.4f}] -> "
                     f"{found.test_err_after:.4f} [{lo_a:.4f}, {hi_a:.4f}] (bootstrap 95% over sentences)")
    lines += [f"# warning: {w}" for w in found.warnings]
    lines += ["", "[synthesize]"] + [f"{k} = {v!r}" for k, v in found.weights.items()]
    if method != "dp":  # tuned for another search: the file says which
        lines.append(f"method = {method!r}")
    lines.append(f"smoothing_half_window = {found.smoothing_half_window}")
    lines += ["", "# Takes effect when the database is built again: facesynth build-db ... --config this file.",
              "[build_db]", f"boundary_fit_frames = {found.boundary_fit_frames}"]
    return "\n".join(lines) + "\n"
