"""``facesynth tune``: alpha1..alpha6 by cross-validation (paper VI-D).

The objective is Eq. 12-13 on the validation takes (``split = val``): every sentence is
synthesized with candidate weights and compared with its capture. A discrete search has no
gradient (the objective is piecewise constant in the weights), so instead of the paper's
gradient descent the weights are searched with Nelder-Mead — derivative-free — in log space
(alpha4 through a logistic, so it stays in (0, 1)), from ``starts`` random starts drawn
log-uniformly within ``spread`` of the current values (the first start is the current
values themselves). PNT stays fixed: it only sets the scale the alphas are measured in.
The best weights are written as a configuration ``synthesize`` accepts, and the error
before and after is reported on the test takes, which tuning never sees.
"""

from __future__ import annotations

import dataclasses
import time
from pathlib import Path

import numpy as np
from scipy.optimize import minimize
from scipy.special import expit

from ..artifacts import atomic_path, check_output
from ..config import EvaluateSettings, NormalizeSettings, SynthesizeSettings, TuneSettings
from ..errors import InputError
from ..evaluation import evaluate, heldout
from ..model.motiondb import MotionDatabase

ALPHAS = ("alpha1", "alpha2", "alpha3", "alpha4", "alpha5", "alpha6")


def to_vector(s: SynthesizeSettings) -> np.ndarray:
    """The search vector of the alphas: logs, alpha4 as a logit."""
    a4 = min(max(s.alpha4, 1e-6), 1 - 1e-6)
    return np.array([np.log(s.alpha1), np.log(s.alpha2), np.log(s.alpha3), np.log(a4 / (1 - a4)), np.log(s.alpha5), np.log(s.alpha6)])


def from_vector(v: np.ndarray, s: SynthesizeSettings) -> SynthesizeSettings:
    """Settings with the alphas of search vector ``v``."""
    a = np.exp(v)
    return dataclasses.replace(s, alpha1=float(a[0]), alpha2=float(a[1]), alpha3=float(a[2]),
                               alpha4=float(np.clip(expit(v[3]), 1e-6, 1 - 1e-6)), alpha5=float(a[4]), alpha6=float(a[5]))


def tune(db_path: Path, corpus: Path, settings: TuneSettings, synth: SynthesizeSettings, evaluate_settings: EvaluateSettings,
         normalize_settings: NormalizeSettings, progress_fn=None) -> dict:
    """Tune alpha1..alpha6 on the validation takes of ``corpus``; returns the weights and the
    errors (mm^2) before and after on the validation and test takes.
    """
    for name in ALPHAS:
        if getattr(synth, name) <= 0:
            raise InputError(f"synthesize.{name} must be positive to tune it (got {getattr(synth, name)}).")
    db = MotionDatabase.read(db_path)
    validation = heldout(corpus, db, "val", normalize_settings)
    test = heldout(corpus, db, "test", normalize_settings)
    cache: dict[tuple, float] = {}

    def error(v: np.ndarray, sentences) -> float:
        s = from_vector(v, synth)
        metrics, _ = evaluate(db_path, corpus, evaluate_settings, s, normalize_settings, sentences=sentences, db=db,
                              with_baseline=False)
        return metrics["dp"]["overall"]["err_mm2"]  # mean Eq. 13 over the sentences (Eq. 12 / K)

    def objective(v: np.ndarray) -> float:
        key = tuple(np.round(v, 6))
        if key not in cache:
            cache[key] = error(v, validation)
            if progress_fn:
                progress_fn(len(cache), cache[key])
        return cache[key]

    rng = np.random.default_rng(settings.seed)
    v0 = to_vector(synth)
    starts = [v0] + [v0 + rng.uniform(-np.log(settings.spread), np.log(settings.spread), len(v0)) for _ in range(settings.starts - 1)]
    t0 = time.perf_counter()
    best_v, best_f = v0, objective(v0)
    before_val = best_f
    per_start = max(4, settings.max_evaluations // max(1, settings.starts))
    for start in starts:
        result = minimize(objective, start, method="Nelder-Mead",
                          options={"maxfev": per_start, "xatol": 1e-2, "fatol": 1e-4, "initial_simplex": _simplex(start)})
        if result.fun < best_f:
            best_v, best_f = result.x, float(result.fun)
    tuned = from_vector(best_v, synth)
    summary = {"validation_sentences": len(validation), "test_sentences": len(test), "evaluations": len(cache),
               "seconds": time.perf_counter() - t0, "validation_err_before": before_val, "validation_err_after": best_f,
               "alphas": {k: getattr(tuned, k) for k in ALPHAS}}
    if test:
        summary["test_err_before"] = error(v0, test)
        summary["test_err_after"] = error(best_v, test)
    return summary


def _simplex(v: np.ndarray, step: float = 0.7) -> np.ndarray:
    """A start simplex a factor e^0.7 (about 2) wide in every weight."""
    return np.vstack([v] + [v + step * np.eye(len(v))[i] for i in range(len(v))])


def write_config(path: Path, summary: dict, overwrite: bool) -> None:
    """Write the tuned weights as a TOML ``[synthesize]`` section ``synthesize --config`` accepts."""
    lines = ["# Cost weights tuned by `facesynth tune` (paper VI-D): use with --config.",
             f"# validation error (Eq. 13, mm^2): {summary['validation_err_before']:.4f} -> {summary['validation_err_after']:.4f}"]
    if "test_err_before" in summary:
        lines.append(f"# test error (Eq. 13, mm^2):       {summary['test_err_before']:.4f} -> {summary['test_err_after']:.4f}")
    lines += ["", "[synthesize]"] + [f"{k} = {v!r}" for k, v in summary["alphas"].items()]
    with atomic_path(path, overwrite) as tmp:
        tmp.write_text("\n".join(lines) + "\n", encoding="utf-8")


def run(db_path: Path, corpus: Path, out: Path, settings: TuneSettings, synth: SynthesizeSettings,
        evaluate_settings: EvaluateSettings, normalize_settings: NormalizeSettings, overwrite: bool = False,
        progress_fn=None) -> dict:
    """Tune and write ``out``; returns the summary."""
    check_output(out, overwrite)
    summary = tune(db_path, corpus, settings, synth, evaluate_settings, normalize_settings, progress_fn)
    write_config(out, summary, overwrite)
    return summary
