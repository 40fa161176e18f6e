"""The ``expression`` artifact: a fitted expression model (the bilinear style/content model of
Chuang & Bregler §3, :mod:`facesynth.domain.expression`), written by ``facesynth expression fit``."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .artifacts import open_artifact, read, read_strings, write_artifact, write_strings


@dataclass
class BilinearModel:
    """A fitted symmetric bilinear model over PCA coefficients of marker frames.

    mean : (3M,) float64 mm, the mean marker frame (flattened x, y, z per marker).
    basis : (K, 3M) float64, orthonormal PCA modes (Eq. 1's ``P_s``, rows).
    emotions : S emotion names; styles : (S, I) float64 style vectors (Eq. 4's ``e_s``).
    W : (K, I, J) float64 bilinear basis (Eq. 4's ``W_k``).
    content_mean : (J,) float64, the mean training content vector (Eq. 5's initial guess).
    errors : (n_iter,) float64 mean squared error per ALS iteration, mm^2 per component.
    """

    mean: np.ndarray
    basis: np.ndarray
    emotions: list[str]
    styles: np.ndarray
    W: np.ndarray
    content_mean: np.ndarray
    errors: np.ndarray

    def coefficients(self, frames: np.ndarray) -> np.ndarray:
        """(T, M, 3) mm frames -> (T, K) PCA coefficients (Eq. 1)."""
        return (frames.reshape(len(frames), -1).astype(np.float64) - self.mean) @ self.basis.T

    def frames(self, coeffs: np.ndarray) -> np.ndarray:
        """(T, K) coefficients -> (T, M, 3) mm frames."""
        return (self.mean + coeffs @ self.basis).reshape(len(coeffs), -1, 3)

    def style(self, emotion: str) -> np.ndarray:
        """(I,) the style vector of ``emotion`` (a fitted one)."""
        return self.styles[self.emotions.index(emotion)]


class ExpressionModel:
    """Reader and writer of the ``expression`` kind; the model itself is a
    :class:`BilinearModel` with its marker names (fitted and used by :mod:`facesynth.domain.expression.bilinear`)."""

    KIND = "expression"

    @classmethod
    def read(cls, path: Path) -> tuple[BilinearModel, list[str]]:
        """The model and its marker names (M)."""
        with open_artifact(path, cls.KIND) as f:
            names = read_strings(f, "marker_names")
            mean = read(f, "mean").astype(np.float64).reshape(-1)
            basis = read(f, "basis").astype(np.float64)
            model = BilinearModel(mean, basis.reshape(len(basis), -1), read_strings(f, "emotions"), read(f, "styles"),
                                  read(f, "W"), read(f, "content_mean"), read(f, "errors"))
            return model, names

    @classmethod
    def write(cls, path: Path, model: BilinearModel, marker_names: list[str], *, config: str, inputs,
              aligned_frames: int, sentences: list[str], overwrite: bool = False) -> None:
        """Write the model to ``path`` with how much aligned data it was fitted on."""
        with write_artifact(path, cls.KIND, config=config, inputs=inputs, overwrite=overwrite) as g:
            write_strings(g, "marker_names", marker_names)
            g.create_dataset("mean", data=model.mean.reshape(-1, 3).astype(np.float32)).attrs["units"] = "mm"
            g.create_dataset("basis", data=model.basis.reshape(len(model.basis), -1, 3).astype(np.float32))
            write_strings(g, "emotions", model.emotions)
            g.create_dataset("styles", data=model.styles.astype(np.float64))
            g.create_dataset("W", data=model.W.astype(np.float64))
            g.create_dataset("content_mean", data=model.content_mean.astype(np.float64))
            g.create_dataset("errors", data=model.errors.astype(np.float64)).attrs["units"] = "mm^2"
            write_strings(g, "sentences", sentences)
            g.attrs["aligned_frames"] = int(aligned_frames)
