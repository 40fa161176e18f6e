"""Normalized marker frames (paper III, Eq. 1-2) and the ``normalized`` artifact.

Every artifact from ``normalized`` on carries the same four datasets, written by
:func:`write_head_frames` and read by :func:`read_head_frames`: the normalized markers, the
rest pose they were aligned to, and the per-frame rigid head motion that was removed
(:func:`relative_to_take`: that motion relative to each take's mean pose).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import h5py
import numpy as np

from .artifacts import attr, open_artifact, read, write_artifact
from .tables import Phones, Takes, read_tables, write_tables


@dataclass
class HeadFrames:
    """Normalized frames and the head motion removed from them.

    markers : (F, M, 3) float32 mm, head motion removed (NaN where a long gap stayed); None where
        they were not read (a motion database read without them, ``MotionDatabase.read``).
    reference : (M, 3) float32 mm, the closed-mouth rest pose of Eq. 1-2.
    head_rotation : (F, 3, 3) float32; captured = head_rotation @ normalized + head_translation.
    head_translation : (F, 3) float32 mm.
    fps : frames/s; origin_marker : the marker placed at the origin.
    """

    markers: np.ndarray | None
    reference: np.ndarray
    head_rotation: np.ndarray
    head_translation: np.ndarray
    fps: float
    origin_marker: str

    def loaded_markers(self) -> np.ndarray:
        """:attr:`markers`, refused where they were not read (``MotionDatabase.read(markers=False)``;
        a ``normalized`` artifact always has them)."""
        if self.markers is None:
            raise ValueError("the normalized markers were not read; read the motion database with markers=True")
        return self.markers


def read_head_frames(f: h5py.File) -> HeadFrames:
    """The normalized markers, rest pose and head motion of an open artifact."""
    return HeadFrames(read(f, "markers"), read(f, "reference"), read(f, "head_rotation"), read(f, "head_translation"),
                      float(attr(f["markers"], "fps")), str(attr(f["markers"], "origin_marker")))


def write_head_frames(g: h5py.File, frames: HeadFrames) -> None:
    """Write ``markers``, ``head_rotation``, ``head_translation`` and ``reference`` with units and rates."""
    m = frames.loaded_markers()
    d = g.create_dataset("markers", data=m, chunks=(max(1, min(len(m), 1024)), m.shape[1], 3))
    d.attrs["units"] = "mm"
    d.attrs["fps"] = frames.fps
    d.attrs["origin_marker"] = frames.origin_marker
    r = g.create_dataset("head_rotation", data=frames.head_rotation.astype(np.float32))
    r.attrs["fps"] = frames.fps
    r.attrs["convention"] = "captured = head_rotation @ normalized + head_translation"
    t = g.create_dataset("head_translation", data=frames.head_translation.astype(np.float32))
    t.attrs["units"] = "mm"
    t.attrs["fps"] = frames.fps
    ref = g.create_dataset("reference", data=frames.reference.astype(np.float32))
    ref.attrs["units"] = "mm"


@dataclass
class NormalizedFrames:
    """A ``normalized`` artifact: the corpus tables and its frames with head motion removed.

    posed : every take was posed from curves, its known rest pose the reference and its known
    head pose removed: the markers carry no measurement noise (root attribute ``capture`` =
    ``posed``; see ``solve.posed_captures``)."""

    takes: Takes
    phones: Phones
    marker_names: list[str]
    frames: HeadFrames
    posed: bool = False

    KIND = "normalized"

    @classmethod
    def read(cls, path: Path) -> "NormalizedFrames":
        """The ``normalized`` artifact at ``path``."""
        with open_artifact(path, cls.KIND) as f:
            posed = "capture" in f.attrs and attr(f, "capture") == "posed"
            return cls(*read_tables(f), read_head_frames(f), posed)

    @classmethod
    def read_posed(cls, path: Path) -> bool:
        """Whether the ``normalized`` artifact at ``path`` is of a capture posed from curves (its
        root attribute alone is read)."""
        with open_artifact(path, cls.KIND) as f:
            return "capture" in f.attrs and attr(f, "capture") == "posed"

    def write(self, path: Path, *, config: str, inputs, overwrite: bool = False) -> None:
        """Write a ``normalized`` artifact to ``path``."""
        with write_artifact(path, self.KIND, config=config, inputs=inputs, overwrite=overwrite) as g:
            write_tables(g, self.takes, self.phones, self.marker_names)
            write_head_frames(g, self.frames)
            g.attrs["capture"] = "posed" if self.posed else "markers"


def relative_to_take(rotations: np.ndarray, translations: np.ndarray, take_ranges: list[slice]) -> tuple[np.ndarray, np.ndarray]:
    """Per frame head motion relative to its take's mean pose: ``R_rel = Rbar^T R_t``,
    ``t_rel = Rbar^T (t_t - tbar)`` (Rbar the rotation nearest the take's mean, tbar its mean
    translation), for (F, 3, 3) rotations and (F, 3) mm translations and the frame ranges of
    the takes; returns (F, 3, 3) and (F, 3) mm."""
    rel_r = rotations.astype(np.float64).copy()
    rel_t = translations.astype(np.float64).copy()
    for sl in take_ranges:
        r = rotations[sl].astype(np.float64)
        if len(r) == 0:
            continue
        u, _, vt = np.linalg.svd(r.mean(axis=0))
        mean_r = u @ np.diag([1.0, 1.0, np.linalg.det(u @ vt)]) @ vt
        rel_r[sl] = mean_r.T @ r
        rel_t[sl] = (translations[sl] - translations[sl].mean(axis=0)) @ mean_r
    return rel_r, rel_t
