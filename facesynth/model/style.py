"""The ``expression`` artifact: a fitted style model (the bilinear style/content model of
Chuang & Bregler §3, :mod:`facesynth.style`), written by ``facesynth expression fit``."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..artifacts import open_artifact, read, read_strings, write_artifact, write_strings
from ..style.bilinear import BilinearModel


class StyleModel:
    """Reader and writer of the ``expression`` kind; the model itself is a
    :class:`~facesynth.style.bilinear.BilinearModel` with its marker names."""

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
