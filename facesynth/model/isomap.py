"""Phoneme-Isomaps (paper IV, Eq. 3, Fig. 7) and the ``isomap`` artifact."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from facesynth.base.errors import InputError

from .artifacts import open_artifact, read, read_strings, stamp, write_artifact, write_strings
from .pca import PcaModel

MAP_KINDS = ("isomap", "pca_map")


@dataclass
class Cluster:
    """One phoneme cluster (n frames) and its 2D maps.

    frames : (n,) int64 rows of the database's coefficients; node : (n,) int64 their node;
    relative_time : (n,) float64 in [0, 1]; emotion : n names.
    isomap, pca_map : (n, 2) float64 embeddings; triangles : per map, (t, 3) int32 Delaunay
    triangles (0 rows when the points are degenerate); coefficients : (n, K) float32.
    neighbors : the Isomap neighbour count used; exact : frames embedded exactly (the rest
    by the out-of-sample extension); note : why fewer neighbours were used, or "".
    """

    phone: str
    frames: np.ndarray
    node: np.ndarray
    relative_time: np.ndarray
    emotion: list[str]
    isomap: np.ndarray
    pca_map: np.ndarray
    neighbors: int
    exact: int
    note: str
    coefficients: np.ndarray
    triangles: dict[str, np.ndarray] = field(default_factory=dict)


@dataclass
class PhonemeMaps:
    """An ``isomap`` artifact: every phoneme cluster's maps, with the PCA model and marker
    names needed to turn a picked point back into markers (Eq. 11)."""

    model: PcaModel
    marker_names: list[str]
    clusters: dict[str, Cluster]

    KIND = "isomap"

    def cluster(self, phone: str, path: Path) -> Cluster:
        """The cluster of ``phone``; a clear error naming ``path`` when there is none."""
        if phone not in self.clusters:
            raise InputError(f"{path}: no phoneme cluster /{phone}/; it has {', '.join(sorted(self.clusters))}.")
        return self.clusters[phone]

    @classmethod
    def read(cls, path: Path) -> "PhonemeMaps":
        """Every cluster of the ``isomap`` artifact at ``path``."""
        with open_artifact(path, cls.KIND) as f:
            clusters = {}
            for phone in f["clusters"]:
                h = f["clusters"][phone]
                key = f"clusters/{phone}"
                clusters[phone] = Cluster(
                    phone, read(f, f"{key}/frames"), read(f, f"{key}/node"), read(f, f"{key}/relative_time"),
                    read_strings(f, f"{key}/emotion"), read(f, f"{key}/isomap"), read(f, f"{key}/pca_map"),
                    int(h.attrs.get("n_neighbors", 0)), int(h.attrs.get("exact_frames", 0)), str(h.attrs.get("note", "")),
                    read(f, f"{key}/coefficients"), {k: read(f, f"{key}/{k}_triangles") for k in MAP_KINDS})
            return cls(PcaModel.read(f), read_strings(f, "marker_names"), clusters)

    def write(self, path: Path, *, config: str, inputs, overwrite: bool = False) -> None:
        """Write an ``isomap`` artifact to ``path``."""
        with write_artifact(path, self.KIND, config=config, inputs=inputs, overwrite=overwrite) as g:
            self.model.write(g)
            write_strings(g, "marker_names", self.marker_names)
            root = stamp(g.create_group("clusters"), "phoneme-maps")
            for c in self.clusters.values():
                h = stamp(root.create_group(c.phone), "phoneme-map")
                h.create_dataset("frames", data=c.frames)
                h.create_dataset("node", data=c.node)
                h.create_dataset("relative_time", data=c.relative_time)
                write_strings(h, "emotion", c.emotion)
                h.create_dataset("coefficients", data=c.coefficients)
                for kind in MAP_KINDS:
                    h.create_dataset(kind, data=getattr(c, kind))
                    h.create_dataset(f"{kind}_triangles", data=c.triangles[kind])
                h.attrs.update(n_neighbors=c.neighbors, exact_frames=c.exact, note=c.note)
