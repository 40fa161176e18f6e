"""The fitted Cohen-Massaro coarticulation model and the ``coarticulation`` artifact: per phone type
(a ``phone|emotion`` label, or ``pau``) a target pose in the database's PCA coefficients, a dominance
magnitude and a rate, with the PCA model and the rest pose, so that an utterance is synthesized from
this file alone (:mod:`facesynth.domain.methods.coarticulation`). Written by ``facesynth fit-method
coarticulation``; read by ``facesynth synthesize --method coarticulation``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .artifacts import attr, open_artifact, read, read_strings, write_artifact, write_strings
from .pca import PcaModel
from .trajectory import stored_records


@dataclass
class CoarticulationModel:
    """Cohen-Massaro parameters per phone type, in the PCA space of the database it was fitted on.

    labels : P phone types (``aa|happy``; ``pau`` one type for every emotion).
    targets : (P, K) float64 target poses in PCA coefficients; magnitude : (P,) float64 alpha;
    rate : (P,) float64 theta, 1/s.
    pca : the database's :class:`~facesynth.model.pca.PcaModel` (K components); marker_names : M
    names; reference : (M, 3) float32 mm, the rest pose; fps : the capture rate of the training
    frames, frames/s; iterations : the L-BFGS-B iterations allowed; fit_rms : RMS per marker (mm) of
    the fit on the training frames (PCA space, before truncation).
    inputs : the file's provenance records ({path, kind, sha256}), as read (empty for a new model).
    """

    labels: list[str]
    targets: np.ndarray
    magnitude: np.ndarray
    rate: np.ndarray
    pca: PcaModel
    marker_names: list[str]
    reference: np.ndarray
    fps: float
    iterations: int
    fit_rms: float
    inputs: list[dict] = field(default_factory=list)

    KIND = "coarticulation"

    @classmethod
    def read(cls, path: Path) -> "CoarticulationModel":
        """The ``coarticulation`` artifact at ``path``."""
        with open_artifact(path, cls.KIND) as f:
            return cls(read_strings(f, "labels"), read(f, "targets"), read(f, "magnitude"), read(f, "rate"),
                       PcaModel.read(f), read_strings(f, "marker_names"), read(f, "reference"),
                       float(attr(f, "fps")), int(attr(f, "iterations")), float(attr(f, "fit_rms")), stored_records(f))

    def write(self, out: Path, *, config: str, inputs, overwrite: bool = False) -> None:
        """Write a ``coarticulation`` artifact to ``out``."""
        with write_artifact(out, self.KIND, config=config, inputs=inputs, overwrite=overwrite) as g:
            g.attrs.update(fps=float(self.fps), iterations=int(self.iterations), fit_rms=float(self.fit_rms))
            write_strings(g, "labels", self.labels)
            g.create_dataset("targets", data=np.asarray(self.targets, np.float64))
            g.create_dataset("magnitude", data=np.asarray(self.magnitude, np.float64))
            g.create_dataset("rate", data=np.asarray(self.rate, np.float64)).attrs["units"] = "1/s"
            self.pca.write(g)
            write_strings(g, "marker_names", self.marker_names)
            g.create_dataset("reference", data=np.asarray(self.reference, np.float32)).attrs["units"] = "mm"

