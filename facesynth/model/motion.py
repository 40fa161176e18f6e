"""Marker motion (paper VI-VII) and the ``motion`` artifact, written by ``synthesize`` (with
its search path and per-frame provenance) and by ``capture`` (a captured take as ground truth)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .artifacts import attr, open_artifact, read, read_strings, stamp, write_artifact, write_strings
from .provenance import Provenance, SearchPath, of_motion


@dataclass
class Motion:
    """Marker motion in the head frame (head motion removed), with the head motion beside it.

    markers : (T, M, 3) float32 mm at ``fps`` (the output rate).
    markers_capture : (F, M, 3) float32 mm at ``capture_fps``.
    marker_names : M names; reference : (M, 3) float32 mm rest pose.
    head_rotation : (T, 3, 3) float32, head_translation : (T, 3) float32 mm, at ``fps``: the head
        pose relative to the source take's mean (x -> head_rotation @ x + head_translation).
    coefficients : (F, K) float32 PCA coefficients at ``capture_fps`` (a synthesis by a method in the
        database's PCA space; as the method made them: the voice's loudness moves the markers only).
    path, provenance : the search and where each frame came from (synthesis only; ``path.method``
        names the method).
    source : "synthesis", "capture" or "restyle"; take : the captured take (capture only).
    keyshape_weights : (F, Kt) float32 key-shape weights at ``capture_fps``, keyshape_names : Kt
        names (a synthesis by a method in key-shapes, the trajectory: the path of Eq. 7 the markers
        were back-projected from, before the voice's loudness moved them).
    """

    markers: np.ndarray
    fps: float
    markers_capture: np.ndarray
    capture_fps: float
    marker_names: list[str]
    reference: np.ndarray
    head_rotation: np.ndarray
    head_translation: np.ndarray
    coefficients: np.ndarray | None = None
    path: SearchPath | None = None
    provenance: Provenance | None = None
    source: str = "synthesis"
    take: str = ""
    keyshape_weights: np.ndarray | None = None
    keyshape_names: list[str] | None = None

    KIND = "motion"

    @classmethod
    def read(cls, path: Path, *, search: bool = False) -> "Motion":
        """The marker motion and head motion; with ``search``, also the search path and per-frame
        provenance (:meth:`read_search`), so :meth:`frame_provenance` needs no file."""
        with open_artifact(path, cls.KIND) as f:  # the head motion is required: checked at the door
            motion = cls(read(f, "markers"), float(attr(f["markers"], "fps")), read(f, "markers_capture"),
                         float(attr(f["markers_capture"], "fps")), read_strings(f, "marker_names"), read(f, "reference"),
                         read(f, "head_rotation"), read(f, "head_translation"),
                         source=str(f.attrs.get("source", "synthesis")), take=str(f.attrs.get("take", "")))
        if search:
            motion.path, motion.provenance = cls.read_search(path)
        return motion

    @staticmethod
    def read_search(path: Path) -> tuple[SearchPath | None, Provenance | None]:
        """The search path and per-frame provenance of a synthesized motion; (None, None) for a
        captured take (which has neither)."""
        with open_artifact(path, Motion.KIND) as f:
            if "path" not in f or "provenance" not in f:
                return None, None
            p, v = f["path"], f["provenance"]
            costs = {k[len("cost_"):]: read(f, f"path/{k}") for k in p if k.startswith("cost_")}
            search = SearchPath(read(f, "path/node").astype(np.int64), read_strings(f, "path/phone"),
                                read_strings(f, "path/emotion"), read_strings(f, "path/node_phone"),
                                read_strings(f, "path/node_emotion"), read(f, "path/start"), read(f, "path/end"), costs,
                                float(p.attrs.get("total_cost", np.nan)), int(p.attrs.get("non_captured_joins", 0)),
                                str(p.attrs.get("method", "")), str(p.attrs.get("device", "")),
                                str(p.attrs.get("device_reason", "")))
            provenance = Provenance(read(f, "provenance/node").astype(np.int64),
                                    read(f, "provenance/take").astype(np.int64), read_strings(f, "provenance/take_names"),
                                    read(f, "provenance/source_frame").astype(np.int64),
                                    read(f, "provenance/step").astype(np.int64),
                                    read(f, "provenance/smoothed").astype(bool), float(attr(v, "fps")))
            return search, provenance

    def frame_provenance(self, path: Path | None = None):
        """Where each output frame came from (a :class:`~facesynth.model.provenance.FrameProvenance`,
        read from the motion at ``path``, or with ``path`` None from the search path and provenance
        this object holds: a motion just synthesized, or read with ``search``); None for a restyled
        motion, which records nothing."""
        if path is None:
            search, prov = self.path, self.provenance
        else:
            search, prov = self.read_search(path) if self.source == "synthesis" else (None, None)
        return of_motion(search, prov, len(self.markers), self.fps, self.source, self.take, len(self.markers_capture),
                         self.capture_fps)

    def head(self) -> tuple[np.ndarray, np.ndarray]:
        """(rotations, translations) at the output rate (every motion has them: the artifact
        requires them)."""
        return self.head_rotation, self.head_translation

    def write(self, out: Path, *, config: str, inputs=(), records=None, overwrite: bool = False) -> None:
        """Write a ``motion`` artifact to ``out`` (provenance from ``inputs`` or precomputed ``records``)."""
        with write_artifact(out, self.KIND, config=config, inputs=inputs, records=records, overwrite=overwrite) as g:
            g.attrs["source"] = self.source
            if self.source == "capture":
                g.attrs["take"] = self.take
            m = g.create_dataset("markers", data=self.markers)
            m.attrs.update(units="mm", fps=self.fps)
            mc = g.create_dataset("markers_capture", data=self.markers_capture)
            mc.attrs.update(units="mm", fps=self.capture_fps)
            if self.coefficients is not None:
                c = g.create_dataset("coefficients", data=self.coefficients)
                c.attrs["fps"] = self.capture_fps
            if self.keyshape_weights is not None and self.keyshape_names is not None:  # a pair (a method in key-shapes)
                w = g.create_dataset("keyshape_weights", data=np.asarray(self.keyshape_weights, np.float32))
                w.attrs.update(units="weight", fps=self.capture_fps)
                write_strings(g, "keyshape_names", self.keyshape_names)
            write_strings(g, "marker_names", self.marker_names)
            r = g.create_dataset("reference", data=self.reference)
            r.attrs["units"] = "mm"
            hr = g.create_dataset("head_rotation", data=self.head_rotation.astype(np.float32))
            hr.attrs.update(fps=self.fps, convention="head pose relative to the source take's mean: x -> head_rotation @ x + head_translation")
            ht = g.create_dataset("head_translation", data=self.head_translation.astype(np.float32))
            ht.attrs.update(fps=self.fps, units="mm")
            if self.path is not None:
                _write_path(g, self.path)
            if self.provenance is not None:
                _write_provenance(g, self.provenance)


def _write_path(g, s: SearchPath) -> None:
    p = stamp(g.create_group("path"), "search-path")
    p.create_dataset("node", data=s.node)
    write_strings(p, "phone", s.phone)
    write_strings(p, "emotion", s.emotion)
    write_strings(p, "node_phone", s.node_phone)
    write_strings(p, "node_emotion", s.node_emotion)
    p.create_dataset("start", data=s.start).attrs["units"] = "s"
    p.create_dataset("end", data=s.end).attrs["units"] = "s"
    for key, value in s.costs.items():
        p.create_dataset(f"cost_{key}", data=value)
    p.attrs.update(total_cost=s.total_cost, non_captured_joins=s.non_captured_joins, method=s.method, device=s.device,
                   device_reason=s.device_reason)


def _write_provenance(g, v: Provenance) -> None:
    p = stamp(g.create_group("provenance"), "provenance")
    p.attrs["fps"] = v.fps
    p.attrs["meaning"] = "per capture-rate frame: node, take row, source frame in the database (-1: regenerated silence)"
    p.create_dataset("node", data=v.node)
    p.create_dataset("take", data=v.take)
    write_strings(p, "take_names", v.take_names)
    p.create_dataset("source_frame", data=v.source_frame)
    p.create_dataset("step", data=v.step)
    p.create_dataset("smoothed", data=v.smoothed)
