"""Key-shapes and the ``keyshapes`` artifact (Chuang & Bregler 2005 §4.1, Huang et al. §5.2):
per emotion, a few marker poses chosen from the motion database whose non-negative combinations
reconstruct that emotion's frames (Eq. 8), with the keymorph of each key-shape on the built-in rig.
Written by ``facesynth keyshapes``; read by ``facesynth retarget`` and the trajectory model."""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .artifacts import attr, attr_choice, open_artifact, read, read_strings, stamp, write_artifact, write_strings

#: The ways key-shapes are chosen.
METHODS = ("pca", "affinity")


@dataclass
class EmotionKeyShapes:
    """The key-shapes of one emotion.

    markers : (K, M, 3) float32 mm, the key-shape marker poses in the head frame (same frame and
        marker order as the database's frames).
    coefficients : (K, C) float32, the key-shapes' PCA coordinates in the database's PCA model.
    source_frame : (K,) int64, the database frame each key-shape was taken from.
    names : K key-shape names (``happy-03``); keymorph files and CSV rows are matched by them.
    keymorphs : (K, E) float32 in [0, 1], each key-shape's rig weights on the built-in rig, fitted
        by bounded least squares at the rig's marker vertices (None when not fitted).
    counts, errors : (n,) int64 and (n,) float32 mm, the frames' NNLS reconstruction RMS (Eq. 8)
        with the first ``counts[i]`` key-shapes of the selection order, the curve whose knee
        chose K (affinity) or that reports the choice (pca).
    rms : the reconstruction RMS in mm of the emotion's frames with all K key-shapes.
    """

    markers: np.ndarray
    coefficients: np.ndarray
    source_frame: np.ndarray
    names: list[str]
    keymorphs: np.ndarray | None
    counts: np.ndarray
    errors: np.ndarray
    rms: float

    @property
    def count(self) -> int:
        return int(self.markers.shape[0])


@dataclass
class KeyShapes:
    """Key-shapes of every emotion of a database.

    emotions : emotion name -> :class:`EmotionKeyShapes`.
    marker_names : M names; reference : (M, 3) float32 mm, the database's rest pose.
    method : one of :data:`METHODS`; requested_count : the ``--count`` asked for (0: automatic).
    solver : the settings of the frames' weights solve (JSON-able dict: ``solver``, ``max_iter``,
        ``tolerance``), so a reader solves weights the same way.
    rig_name, rig_sha256 : the rig the keymorphs were fitted on ('' when none).
    rig_shape_names : the rig's E shape names (empty when no keymorphs).
    """

    emotions: dict[str, EmotionKeyShapes]
    marker_names: list[str]
    reference: np.ndarray
    method: str
    requested_count: int
    solver: dict = field(default_factory=dict)
    rig_name: str = ""
    rig_sha256: str = ""
    rig_shape_names: list[str] = field(default_factory=list)

    KIND = "keyshapes"

    @classmethod
    def read(cls, path: Path) -> "KeyShapes":
        """The ``keyshapes`` artifact at ``path``."""
        with open_artifact(path, cls.KIND) as f:
            method = attr_choice(f, "method", METHODS, "rebuild it with `facesynth keyshapes`")
            emotions = {}
            for name in read_strings(f, "emotion_names"):
                g = f[f"emotions/{name}"]
                emotions[name] = EmotionKeyShapes(
                    read(f, f"emotions/{name}/markers"), read(f, f"emotions/{name}/coefficients"),
                    read(f, f"emotions/{name}/source_frame"), read_strings(f, f"emotions/{name}/names"),
                    read(f, f"emotions/{name}/keymorphs") if "keymorphs" in g else None,
                    read(f, f"emotions/{name}/counts"), read(f, f"emotions/{name}/errors"), float(attr(g, "rms")))
            return cls(emotions, read_strings(f, "marker_names"), read(f, "reference"), method,
                       int(attr(f, "requested_count")), json.loads(str(attr(f, "solver"))),
                       str(f.attrs.get("rig_name", "")), str(f.attrs.get("rig_sha256", "")),
                       read_strings(f, "rig_shape_names") if "rig_shape_names" in f else [])

    def write(self, out: Path, *, config: str, inputs, overwrite: bool = False) -> None:
        """Write a ``keyshapes`` artifact to ``out``."""
        with write_artifact(out, self.KIND, config=config, inputs=inputs, overwrite=overwrite) as g:
            g.attrs.update(method=self.method, requested_count=int(self.requested_count),
                           solver=json.dumps(self.solver, sort_keys=True))
            write_strings(g, "marker_names", self.marker_names)
            g.create_dataset("reference", data=np.asarray(self.reference, np.float32)).attrs["units"] = "mm"
            write_strings(g, "emotion_names", list(self.emotions))
            has_keymorphs = any(e.keymorphs is not None for e in self.emotions.values())
            if has_keymorphs:
                g.attrs.update(rig_name=self.rig_name, rig_sha256=self.rig_sha256)
                write_strings(g, "rig_shape_names", self.rig_shape_names)
            top = stamp(g.create_group("emotions"), "keyshape-emotions")
            for name, e in self.emotions.items():
                eg = stamp(top.create_group(name), "keyshape-set")
                eg.attrs["rms"] = float(e.rms)
                eg.create_dataset("markers", data=np.asarray(e.markers, np.float32)).attrs["units"] = "mm"
                eg.create_dataset("coefficients", data=np.asarray(e.coefficients, np.float32)).attrs["units"] = "mm"
                eg.create_dataset("source_frame", data=np.asarray(e.source_frame, np.int64))
                write_strings(eg, "names", e.names)
                if e.keymorphs is not None:
                    k = eg.create_dataset("keymorphs", data=np.clip(e.keymorphs, 0, 1).astype(np.float32))
                    k.attrs["units"] = "weight"
                eg.create_dataset("counts", data=np.asarray(e.counts, np.int64))
                eg.create_dataset("errors", data=np.asarray(e.errors, np.float32)).attrs["units"] = "mm"
