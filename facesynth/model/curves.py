"""Rig animation curves and the ``curves`` artifact: per-frame blendshape weights of a named rig,
written by ``facesynth solve`` (a direct facial solve of marker motion), ``facesynth retarget``
(key-shape weights applied to keymorphs, Chuang & Bregler 2005 Eq. 9) and by the scoring code
for a take's true weights, and by ``facesynth openfacefx`` (openfacefx's lip sync of the same phones).
``facesynth render``, the exporters (ARKit CSV, glTF), ``facesynth player`` and ``facesynth rig-mesh`` read it."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from facesynth.base.errors import InputError

from .artifacts import attr, open_artifact, read, read_strings, write_artifact, write_strings
from .provenance import FrameProvenance

#: What made the curves: a direct solve, key-shape retargeting, a take's true weights, a file
#: of weights given by the user, or openfacefx's lip sync of a synthesized motion's phones.
SOURCES = ("solve", "retarget", "truth", "import", "openfacefx")


@dataclass
class RigCurves:
    """Blendshape weight curves of one rig.

    weights : (T, E) float32 in [0, 1] at ``fps`` frames/s, one column per rig shape.
    shape_names : the E shape names in the rig's own spelling (ICT-FaceKit's, e.g. ``jawOpen``,
        ``mouthSmile_L``, for the built-in rig).
    rig_name : the rig's name (``ict-facekit`` for the built-in rig, else the user's folder or file
        name); rig_sha256 : hex sha256 identifying the rig's data (the package data for the
        built-in rig, the sorted file names and bytes of a user's rig folder, or a glTF's bytes).
    source : one of :data:`SOURCES`.
    head_rotation : optional (T, 3, 3) float32, head_translation : optional (T, 3) float32 mm, the
        head pose carried from the motion (``x -> R @ x + t``).
    emotion : optional T per-frame emotion names; intensity : optional (T,) float32 in [0, 1].
    residual : optional (T,) float32 mm, the per-frame RMS marker residual of the fit that made
        the weights (NaN where a frame had no markers).
    method : free text saying how (e.g. ``deformation-gradient``, ``linear``, the key-shape
        selection), empty when nothing more is to say.
    provenance : optional, where each of the T frames came from (phone, emotion, node, take).
    """

    weights: np.ndarray
    fps: float
    shape_names: list[str]
    rig_name: str
    rig_sha256: str
    source: str
    head_rotation: np.ndarray | None = None
    head_translation: np.ndarray | None = None
    emotion: list[str] | None = None
    intensity: np.ndarray | None = None
    residual: np.ndarray | None = None
    method: str = ""
    provenance: FrameProvenance | None = None

    KIND = "curves"

    def __post_init__(self) -> None:
        self.weights = np.asarray(self.weights, dtype=np.float32)
        if self.weights.ndim != 2 or self.weights.shape[1] != len(self.shape_names):
            raise ValueError(f"weights {self.weights.shape} do not match {len(self.shape_names)} shape names")
        if self.source not in SOURCES:
            raise ValueError(f"unknown curves source {self.source!r}")

    @property
    def n_frames(self) -> int:
        return int(self.weights.shape[0])

    @classmethod
    def read(cls, path: Path) -> "RigCurves":
        """The ``curves`` artifact at ``path``; weights outside [0, 1] are refused."""
        with open_artifact(path, cls.KIND) as f:
            weights = read(f, "weights")
            bad = np.argwhere((weights < 0) | (weights > 1))
            if len(bad):
                t, e = bad[0]
                raise InputError(f"{path}: /weights frame {t}, column {e}: {weights[t, e]:g} is outside [0, 1]; "
                                 f"rewrite the curves with this version of facesynth.")
            names = read_strings(f, "shape_names")
            has_head = "head_rotation" in f
            return cls(weights, float(attr(f["weights"], "fps")), names, str(attr(f, "rig_name")),
                       str(attr(f, "rig_sha256")), str(attr(f, "source")),
                       read(f, "head_rotation") if has_head else None,
                       read(f, "head_translation") if has_head else None,
                       read_strings(f, "emotion") if "emotion" in f else None,
                       read(f, "intensity") if "intensity" in f else None,
                       read(f, "residual") if "residual" in f else None,
                       str(f.attrs.get("method", "")), FrameProvenance.read(f))

    def write(self, out: Path, *, config: str, inputs, overwrite: bool = False) -> None:
        """Write a ``curves`` artifact to ``out``."""
        with write_artifact(out, self.KIND, config=config, inputs=inputs, overwrite=overwrite) as g:
            g.attrs.update(rig_name=self.rig_name, rig_sha256=self.rig_sha256, source=self.source, method=self.method)
            w = g.create_dataset("weights", data=np.clip(self.weights, 0.0, 1.0).astype(np.float32))
            w.attrs.update(fps=self.fps, units="weight")
            write_strings(g, "shape_names", self.shape_names)
            if self.head_rotation is not None:
                hr = g.create_dataset("head_rotation", data=np.asarray(self.head_rotation, np.float32))
                hr.attrs.update(fps=self.fps, convention="x -> head_rotation @ x + head_translation")
                ht = g.create_dataset("head_translation", data=np.asarray(self.head_translation, np.float32))
                ht.attrs.update(fps=self.fps, units="mm")
            if self.emotion is not None:
                write_strings(g, "emotion", self.emotion)
                g.create_dataset("intensity", data=np.asarray(self.intensity, np.float32))
            if self.residual is not None:
                r = g.create_dataset("residual", data=np.asarray(self.residual, np.float32))
                r.attrs["units"] = "mm"
            if self.provenance is not None:
                self.provenance.fitted(self.n_frames).write(g)
