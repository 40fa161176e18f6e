"""The compact key-shape trajectory model and the ``trajectory`` artifact (Huang et al. §5.4):
per phone, and per (phone, emotion) where the training data allow, a Gaussian (mean and diagonal
covariance) of the key-shape weights, with the key-shapes themselves, so that a whole utterance
is synthesized from this file alone (:mod:`facesynth.domain.methods.trajectory`). Written by
``facesynth fit-method trajectory``; read by ``facesynth synthesize --method trajectory``.

Key-shapes: one joint set, the union of every emotion's key-shapes of a ``keyshapes`` artifact;
a frame's weights are its non-negative combination over the whole set (Eq. 5), so the weights of
every emotion live in one space and a change of emotion inside an utterance is a change of
Gaussians on the same path (the smoothness term of Eq. 6 blends it). Everything is float32 except
the counts; a model is a few tens of kilobytes.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import numpy as np

from .artifacts import attr, attr_choice, open_artifact, read, read_strings, write_artifact, write_strings

#: Which frames of a phone token feed its Gaussian.
SAMPLINGS = ("span", "centre")


@dataclass
class TrajectoryModel:
    """Gaussians of key-shape weights per phone and per (phone, emotion).

    marker_names : M names; reference : (M, 3) float32 mm, the rest pose (all weights zero).
    keyshapes : (K, M, 3) float32 mm, the joint key-shape marker poses in the head frame;
        a frame with weights w is ``reference + sum_k w[k] (keyshapes[k] - reference)``.
    keyshape_names : K names (``happy-03``); keyshape_emotion : K, the emotion each came from.
    phones : P phones with a Gaussian (``pau`` included when the training takes have pauses).
    means, variances : (P, K) float32, weight units; tokens : (P,) int64 training tokens;
        samples : (P,) int64 frames that fed each Gaussian.
    pair_phone, pair_emotion : Q (phone, emotion) pairs with their own Gaussian (at least
        ``min_tokens`` tokens); pair_means, pair_variances : (Q, K) float32; pair_tokens,
        pair_samples : (Q,) int64.
    fps : the capture rate of the training frames, frames/s.
    sampling : one of :data:`SAMPLINGS`; min_tokens : tokens a pair needed; variance_floor :
        the floor's fraction of each weight's overall variance; fit_rms : RMS per marker (mm) of
        the training frames' NNLS reconstruction with the joint key-shapes.
    inputs : the file's provenance records ({path, kind, sha256}), as read (empty for a new model).
    """

    marker_names: list[str]
    reference: np.ndarray
    keyshapes: np.ndarray
    keyshape_names: list[str]
    keyshape_emotion: list[str]
    phones: list[str]
    means: np.ndarray
    variances: np.ndarray
    tokens: np.ndarray
    samples: np.ndarray
    pair_phone: list[str]
    pair_emotion: list[str]
    pair_means: np.ndarray
    pair_variances: np.ndarray
    pair_tokens: np.ndarray
    pair_samples: np.ndarray
    fps: float
    sampling: str
    min_tokens: int
    variance_floor: float
    fit_rms: float
    inputs: list[dict] = field(default_factory=list)

    KIND = "trajectory"

    @property
    def count(self) -> int:
        """K, the key-shapes (weight dimensions)."""
        return int(self.keyshapes.shape[0])

    @cached_property
    def deltas(self) -> np.ndarray:
        """(K, 3M) float32 mm: each key-shape minus the reference, flattened (the back-projection basis;
        float32 like the stored poses, whose precision it keeps)."""
        return (self.keyshapes.astype(np.float64) - self.reference.astype(np.float64)).reshape(self.count, -1
                                                                                              ).astype(np.float32)

    def markers(self, weights: np.ndarray) -> np.ndarray:
        """Marker frames (T, M, 3) float32 mm of key-shape weights (T, K)."""
        flat = np.asarray(weights, np.float32) @ self.deltas
        flat += self.reference.reshape(-1)
        return flat.reshape(len(flat), -1, 3)

    @classmethod
    def read(cls, path: Path) -> "TrajectoryModel":
        """The ``trajectory`` artifact at ``path``."""
        with open_artifact(path, cls.KIND) as f:
            sampling = attr_choice(f, "sampling", SAMPLINGS, "train it again with `facesynth fit-method trajectory`")
            return cls(read_strings(f, "marker_names"), read(f, "reference"), read(f, "keyshapes"),
                       read_strings(f, "keyshape_names"), read_strings(f, "keyshape_emotion"),
                       read_strings(f, "phones"), read(f, "means"), read(f, "variances"), read(f, "tokens"),
                       read(f, "samples"), read_strings(f, "pair_phone"), read_strings(f, "pair_emotion"),
                       read(f, "pair_means"), read(f, "pair_variances"), read(f, "pair_tokens"),
                       read(f, "pair_samples"), float(attr(f, "fps")), sampling, int(attr(f, "min_tokens")),
                       float(attr(f, "variance_floor")), float(attr(f, "fit_rms")), stored_records(f))

    def write(self, out: Path, *, config: str, inputs, overwrite: bool = False) -> None:
        """Write a ``trajectory`` artifact to ``out``."""
        with write_artifact(out, self.KIND, config=config, inputs=inputs, overwrite=overwrite) as g:
            g.attrs.update(fps=float(self.fps), sampling=self.sampling, min_tokens=int(self.min_tokens),
                           variance_floor=float(self.variance_floor), fit_rms=float(self.fit_rms),
                           covariance="diagonal")
            write_strings(g, "marker_names", self.marker_names)
            g.create_dataset("reference", data=np.asarray(self.reference, np.float32)).attrs["units"] = "mm"
            g.create_dataset("keyshapes", data=np.asarray(self.keyshapes, np.float32)).attrs["units"] = "mm"
            write_strings(g, "keyshape_names", self.keyshape_names)
            write_strings(g, "keyshape_emotion", self.keyshape_emotion)
            write_strings(g, "phones", self.phones)
            for key in ("means", "variances"):
                g.create_dataset(key, data=np.asarray(getattr(self, key), np.float32)).attrs["units"] = "weight"
            g.create_dataset("tokens", data=np.asarray(self.tokens, np.int64))
            g.create_dataset("samples", data=np.asarray(self.samples, np.int64))
            write_strings(g, "pair_phone", self.pair_phone)
            write_strings(g, "pair_emotion", self.pair_emotion)
            for key in ("pair_means", "pair_variances"):
                g.create_dataset(key, data=np.asarray(getattr(self, key), np.float32).reshape(-1, self.count)
                                 ).attrs["units"] = "weight"
            g.create_dataset("pair_tokens", data=np.asarray(self.pair_tokens, np.int64))
            g.create_dataset("pair_samples", data=np.asarray(self.pair_samples, np.int64))


def stored_records(f) -> list[dict]:
    """The ``inputs`` records of an open artifact; [] when they cannot be parsed."""
    try:
        records = json.loads(str(attr(f, "inputs")))
    except ValueError:
        return []
    return [r for r in records if isinstance(r, dict)] if isinstance(records, list) else []
