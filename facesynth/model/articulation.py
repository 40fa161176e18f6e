"""The fitted acoustic articulation model and the ``articulation`` artifact: a linear map (ridge
regression) from the voice's frame features, read at fixed offsets around each output frame, to
the mouth's curves of a capture (jawOpen, the mouth opening, funnel, pucker, ...), with the
features' normalization, so that the mouth is predicted from audio with this file alone
(:mod:`facesynth.domain.voice.articulation` holds the features, the fit and the prediction).
Written by ``facesynth fit-articulation`` (a performer's capture) and by
``benchmarks/voice_articulation.py --model-out`` (FACEGOOD: the packaged model); read by
``synthesize.articulation_model`` (:func:`facesynth.domain.voice.fusion.articulation_model`).
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .artifacts import attr, open_artifact, read, read_strings, write_artifact, write_strings
from .trajectory import stored_records

#: The normalizations of the voice features (see :class:`facesynth.domain.voice.articulation.Normalizer`).
NORMALIZATIONS = ("global", "utterance", "running")


@dataclass
class ArticulationModel:
    """A fitted map from voice features to mouth curves; ``prediction = context @ coef + intercept``.

    target_names : Y names of the predicted curves (in the units of the curves it was fitted on,
    0..1 for ARKit weights). offsets_s : (C,) float64 s, the offsets from an output frame's time at
    which the features are read; pool : analysis frames averaged around each offset.
    normalization : one of :data:`NORMALIZATIONS`; tau_s : s, the running normalization's time
    constant; gate : log amplitude, how far below the loudest frame a frame still has speech;
    peak_decay : log amplitude/s, how fast that loudest level falls.
    feature_names : D names of the voice features; feature_mean, feature_std : (D,) float64, their
    statistics on the training frames with speech.
    coef : (C * D', Y) float64 (D' = D plus the loudness columns where ``expand``), offset-major;
    intercept : (Y,) float64; alpha : the ridge penalty (per standardized column, times the frames).
    target_mean, target_std : (Y,) float64 of the training targets.
    expand : whether the loudness hinges at ``knots`` (Kn,) float64 (standardized log RMS) are
    columns of the context. analysis_rate : Hz, hop and window : samples, of the analysis frames.
    inputs : the file's provenance records ({path, kind, sha256}), as read (empty for a new model).
    fitted_on : what the model was fitted on, by name: one record per file of speech or curves
    ({"name": "<source>/<speaker>/<file>", "sha256": ..., "seconds": audio s or null}), so that a
    packaged model says which recordings it learned from without naming any folder; [] when unknown
    (a model of an earlier release, or a performer's model, whose ``inputs`` say it).
    closure_threshold : the threshold of the closure score at which the voice's own closures met
    the performer's on takes the model did not see (``fit-articulation``,
    :func:`facesynth.domain.voice.fitting.held_out_takes`), which ``synthesize.voice_closure_threshold
    = -1`` takes; None where none was chosen (a general model, or too few takes).
    """

    target_names: list[str]
    offsets_s: np.ndarray
    pool: int
    normalization: str
    tau_s: float
    gate: float
    peak_decay: float
    feature_names: list[str]
    feature_mean: np.ndarray
    feature_std: np.ndarray
    coef: np.ndarray
    intercept: np.ndarray
    alpha: float
    target_mean: np.ndarray
    target_std: np.ndarray
    expand: bool
    knots: np.ndarray
    analysis_rate: int
    hop: int
    window: int
    inputs: list[dict] = field(default_factory=list)
    fitted_on: list[dict] = field(default_factory=list)
    closure_threshold: float | None = None

    KIND = "articulation"

    def column(self, name: str) -> int:
        """The column of the target ``name`` in the predictions."""
        return self.target_names.index(name)

    @classmethod
    def read(cls, path: Path) -> "ArticulationModel":
        """The ``articulation`` artifact at ``path``."""
        with open_artifact(path, cls.KIND) as f:
            return cls(read_strings(f, "target_names"), read(f, "offsets_s"), int(attr(f, "pool")),
                       str(attr(f, "normalization")), float(attr(f, "tau_s")), float(attr(f, "gate")),
                       float(attr(f, "peak_decay")), read_strings(f, "feature_names"), read(f, "feature_mean"),
                       read(f, "feature_std"), read(f, "coef"), read(f, "intercept"), float(attr(f, "alpha")),
                       read(f, "target_mean"), read(f, "target_std"), bool(int(attr(f, "expand"))), read(f, "knots"),
                       int(attr(f, "analysis_rate")), int(attr(f, "hop")), int(attr(f, "window")), stored_records(f),
                       _fitted_on(f),
                       float(f.attrs["closure_threshold"]) if "closure_threshold" in f.attrs else None)

    def write(self, out: Path, *, config: str, inputs, overwrite: bool = False) -> None:
        """Write an ``articulation`` artifact to ``out``."""
        with write_artifact(out, self.KIND, config=config, inputs=inputs, overwrite=overwrite) as g:
            g.attrs.update(pool=int(self.pool), normalization=str(self.normalization), tau_s=float(self.tau_s),
                           gate=float(self.gate), peak_decay=float(self.peak_decay), alpha=float(self.alpha),
                           expand=int(bool(self.expand)), analysis_rate=int(self.analysis_rate), hop=int(self.hop),
                           window=int(self.window), fitted_on=json.dumps(self.fitted_on, sort_keys=True))
            if self.closure_threshold is not None:
                g.attrs["closure_threshold"] = float(self.closure_threshold)
            write_strings(g, "target_names", self.target_names)
            g.create_dataset("offsets_s", data=np.asarray(self.offsets_s, np.float64)).attrs["units"] = "s"
            write_strings(g, "feature_names", self.feature_names)
            g.create_dataset("feature_mean", data=np.asarray(self.feature_mean, np.float64))
            g.create_dataset("feature_std", data=np.asarray(self.feature_std, np.float64))
            g.create_dataset("coef", data=np.asarray(self.coef, np.float64))
            g.create_dataset("intercept", data=np.asarray(self.intercept, np.float64))
            g.create_dataset("target_mean", data=np.asarray(self.target_mean, np.float64))
            g.create_dataset("target_std", data=np.asarray(self.target_std, np.float64))
            g.create_dataset("knots", data=np.asarray(self.knots, np.float64))


def _fitted_on(f) -> list[dict]:
    """The ``fitted_on`` records of an open artifact; [] when absent (an earlier release's) or unparsable."""
    if "fitted_on" not in f.attrs:
        return []
    try:
        records = json.loads(str(f.attrs["fitted_on"]))
    except ValueError:
        return []
    return [r for r in records if isinstance(r, dict)] if isinstance(records, list) else []
