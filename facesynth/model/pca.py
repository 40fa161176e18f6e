"""The PCA model of marker frames (paper III, Eq. 11) and the ``pca`` artifact."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import h5py
import numpy as np

from .artifacts import open_artifact, read, stamp, write_artifact
from .frames import HeadFrames, read_head_frames, write_head_frames
from .tables import Phones, Takes, read_tables, write_tables


@dataclass
class PcaModel:
    """A PCA basis of marker frames. Each frame's M markers are packed into a 3M vector
    (x, y, z per marker, marker-major: vector index = 3 * marker + axis).

    mean : (3M,) float64, mm.
    basis : (3M, K) float64, orthonormal columns.
    variances : (K,) float64, mm^2.
    explained : fraction of the total variance covered by the K components.
    """

    mean: np.ndarray
    basis: np.ndarray
    variances: np.ndarray
    explained: float

    def project(self, frames: np.ndarray) -> np.ndarray:
        """Coefficients (n, K) float32 of frames (n, M, 3) or (n, 3M) mm; NaN coordinates are skipped."""
        x = frames.reshape(len(frames), -1).astype(np.float64) - self.mean
        coeffs = x @ self.basis
        missing = np.isnan(x).any(axis=1)
        for i in np.nonzero(missing)[0]:
            seen = ~np.isnan(x[i])
            coeffs[i] = np.linalg.lstsq(self.basis[seen], x[i, seen], rcond=None)[0]
        return coeffs.astype(np.float32)

    def reconstruct(self, coeffs: np.ndarray) -> np.ndarray:
        """Eq. 11: MrkMotion = MeanMotion + EigMx . PcaCoef. (n, K) -> (n, M, 3) float32 mm."""
        x = self.mean + np.asarray(coeffs, np.float64) @ self.basis.T
        return x.reshape(len(x), -1, 3).astype(np.float32)

    @classmethod
    def read(cls, f: h5py.File) -> "PcaModel":
        """The model stored under ``/pca`` of a ``pca`` or later artifact."""
        return cls(read(f, "pca/mean"), read(f, "pca/basis"), read(f, "pca/variances"), float(f["pca"].attrs["explained"]))

    def write(self, f: h5py.File) -> None:
        """Write the model under ``/pca``."""
        p = stamp(f.create_group("pca"), "pca-model")
        p.create_dataset("mean", data=self.mean)
        p.create_dataset("basis", data=self.basis)
        p.create_dataset("variances", data=self.variances)
        p.attrs["explained"] = self.explained
        p.attrs["layout"] = "vector index = 3 * marker + axis"


@dataclass
class PcaFrames:
    """A ``pca`` artifact: the normalized frames with their PCA coefficients.

    takes, phones, marker_names : the corpus tables.
    model : the fitted :class:`PcaModel` (K components).
    coefficients : (F, K) float32, per frame (F: all frames of all takes).
    frames : the normalized frames and head motion (:class:`HeadFrames`, F frames at ``frames.fps``).
    """

    takes: Takes
    phones: Phones
    marker_names: list[str]
    model: PcaModel
    coefficients: np.ndarray
    frames: HeadFrames

    KIND = "pca"

    @classmethod
    def read(cls, path: Path) -> "PcaFrames":
        """The ``pca`` artifact at ``path``."""
        with open_artifact(path, cls.KIND) as f:
            takes, phones, names = read_tables(f)
            return cls(takes, phones, names, PcaModel.read(f), read(f, "coefficients"), read_head_frames(f))

    def write(self, path: Path, *, config: str, inputs, overwrite: bool = False) -> None:
        """Write a ``pca`` artifact to ``path``."""
        with write_artifact(path, self.KIND, config=config, inputs=inputs, overwrite=overwrite) as g:
            write_tables(g, self.takes, self.phones, self.marker_names)
            self.model.write(g)
            c = g.create_dataset("coefficients", data=self.coefficients)
            c.attrs["fps"] = self.frames.fps
            c.attrs["units"] = "mm"
            write_head_frames(g, self.frames)
