"""Mesh animation (paper VII-A) and the ``meshanim`` artifact: the face mesh moved by marker
motion, with the deformation weights that did it."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from .artifacts import attr, open_artifact, read, read_strings, stamp, write_artifact, write_strings
from .provenance import FrameProvenance

if TYPE_CHECKING:
    from scipy import sparse


@dataclass
class MeshAnimation:
    """vertices : (T, V, 3) float32 in mesh units at ``fps``; rest : (V, 3) float32;
    faces : (F, 3) int (triangles); markers : (T, M, 3) float32 mm, the motion that drove it;
    marker_names : M names; weights : (V, K) sparse Gaussian weights of Eq. 14-15 over the K bound
    markers ``bound_markers`` at vertices ``vertex_of`` ((K,) int); fit_rms : residual of the
    marker-to-mesh similarity fit, mesh units; gaze : optional (T, 2, 2) float32 radians, per
    frame (yaw, pitch) of the eye at +x (the subject's left) and of the eye at -x, yaw turning
    the gaze toward +x and pitch up; NaN (or None) where the gaze is not known, e.g. from
    marker motion, and the renderer's eyes then look straight ahead; provenance : optional,
    where each frame came from (phone, emotion, node, take)."""

    vertices: np.ndarray
    fps: float
    rest: np.ndarray
    faces: np.ndarray
    markers: np.ndarray
    marker_names: list[str]
    weights: sparse.csr_matrix | None = None
    bound_markers: list[str] | None = None
    vertex_of: np.ndarray | None = None
    fit_rms: float = float("nan")
    gaze: np.ndarray | None = None
    provenance: FrameProvenance | None = None

    KIND = "meshanim"

    @classmethod
    def read(cls, path: Path) -> "MeshAnimation":
        """Vertices, faces, markers and the gaze track if any (the weights are not read)."""
        with open_artifact(path, cls.KIND) as f:
            return cls(read(f, "vertices"), float(attr(f["vertices"], "fps")), read(f, "rest"),
                       read(f, "faces").astype(np.int64), read(f, "markers"), read_strings(f, "marker_names"),
                       fit_rms=float(f.attrs.get("fit_rms", np.nan)),
                       gaze=read(f, "gaze") if "gaze" in f else None, provenance=FrameProvenance.read(f))

    def write(self, out: Path, *, config: str, inputs, overwrite: bool = False) -> None:
        """Write a ``meshanim`` artifact (with its deformation weights) to ``out``."""
        if self.weights is None or self.bound_markers is None or self.vertex_of is None:
            raise ValueError("a mesh animation is written with the deformation weights that made it "
                             "(weights, bound_markers, vertex_of); one read from a file has none")
        with write_artifact(out, self.KIND, config=config, inputs=inputs, overwrite=overwrite) as g:
            v = g.create_dataset("vertices", data=self.vertices, chunks=(1,) + self.vertices.shape[1:])
            v.attrs.update(fps=self.fps, units="mesh units")
            g.create_dataset("rest", data=self.rest.astype(np.float32))
            g.create_dataset("faces", data=self.faces.astype(np.int32))
            w = stamp(g.create_group("weights"), "csr-matrix")
            w.create_dataset("data", data=self.weights.data.astype(np.float32))
            w.create_dataset("indices", data=self.weights.indices)
            w.create_dataset("indptr", data=self.weights.indptr)
            w.attrs["shape"] = self.weights.shape
            write_strings(w, "markers", self.bound_markers)
            w.create_dataset("vertex_of", data=self.vertex_of)
            m = g.create_dataset("markers", data=self.markers)
            m.attrs.update(fps=self.fps, units="mm")
            write_strings(g, "marker_names", self.marker_names)
            g.attrs["fit_rms"] = self.fit_rms
            if self.gaze is not None:
                gz = g.create_dataset("gaze", data=np.asarray(self.gaze, np.float32))
                gz.attrs.update(fps=self.fps, units="radians")
            if self.provenance is not None:
                self.provenance.fitted(len(self.vertices)).write(g)
