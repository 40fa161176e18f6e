"""The ingested capture (paper III) and the ``corpus`` artifact."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from facesynth.base.errors import InputError

from .artifacts import attr, open_artifact, read, stamp, write_artifact
from .tables import Phones, Takes, read_tables, write_tables


@dataclass
class Corpus:
    """Every take of a capture, concatenated.

    takes, phones, marker_names : the tables (M markers, F frames in all).
    markers : (F, M, 3) float32 mm, as captured (head motion in; NaN in gaps).
    fps : capture rate, frames/s.
    audio : (S,) float32 samples of all takes at ``sample_rate`` Hz; take i's are
        ``audio[audio_start[i] : audio_start[i] + audio_count[i]]``.
    rigid_markers : the markers that move only with the head (the binding's ``rigid`` column,
        :func:`facesynth.formats.mesh.read_rigid_markers`), the set ``normalize`` fits the head
        pose on; [] when the corpus names none.
    rest_pose : (M, 3) float32 mm, the markers of the face at rest (every weight 0, no head
        motion), or None. Known when every take was posed from curves (Live Link Face, another
        rig's curves: :mod:`facesynth.domain.capture.posing`), whose markers are then exact:
        ``markers = known_head_rotation @ (posed markers) + known_head_translation``.
    known_head_rotation, known_head_translation : (F, 3, 3) and (F, 3) float32 (mm), the head
        pose each frame was posed with, given with ``rest_pose`` (else None); ``normalize`` takes
        them instead of fitting a pose.
    """

    takes: Takes
    phones: Phones
    marker_names: list[str]
    markers: np.ndarray
    fps: float
    audio: np.ndarray
    audio_start: np.ndarray
    audio_count: np.ndarray
    sample_rate: int
    rigid_markers: list[str] = field(default_factory=list)
    rest_pose: np.ndarray | None = None
    known_head_rotation: np.ndarray | None = None
    known_head_translation: np.ndarray | None = None

    KIND = "corpus"

    @property
    def posed(self) -> bool:
        """Whether every take was posed from curves (its rest pose and head pose known)."""
        return self.rest_pose is not None and self.known_head_rotation is not None

    @classmethod
    def read(cls, path: Path, *, audio: bool = True) -> "Corpus":
        """The corpus at ``path``; ``audio=False`` leaves the samples out (an empty array)."""
        with open_artifact(path, cls.KIND) as f:
            takes, phones, names = read_tables(f)
            samples = read(f, "audio/samples") if audio else np.zeros(0, np.float32)
            flags = read(f, "rigid") if "rigid" in f else np.zeros(len(names), bool)
            posed = "rest_pose" in f
            return cls(takes, phones, names, read(f, "markers"), float(attr(f["markers"], "fps")), samples,
                       read(f, "audio/start"), read(f, "audio/count"), int(attr(f["audio"], "sample_rate")),
                       [n for n, r in zip(names, flags) if r], read(f, "rest_pose") if posed else None,
                       read(f, "known_head_rotation") if posed else None,
                       read(f, "known_head_translation") if posed else None)

    def write(self, path: Path, *, config: str, inputs, overwrite: bool = False) -> None:
        """Write the corpus to ``path`` (an atomic, stamped ``corpus`` artifact)."""
        with write_artifact(path, self.KIND, config=config, inputs=inputs, overwrite=overwrite) as f:
            m = self.markers
            d = f.create_dataset("markers", data=m, chunks=(max(1, min(len(m), 1024)), m.shape[1], 3))
            d.attrs["units"] = "mm"
            d.attrs["fps"] = self.fps
            write_tables(f, self.takes, self.phones, self.marker_names)
            rigid = set(self.rigid_markers)
            f.create_dataset("rigid", data=np.array([n in rigid for n in self.marker_names], bool))
            if self.rest_pose is not None and self.known_head_rotation is not None \
                    and self.known_head_translation is not None:
                f.create_dataset("rest_pose", data=np.asarray(self.rest_pose, np.float32)).attrs["units"] = "mm"
                f.create_dataset("known_head_rotation", data=np.asarray(self.known_head_rotation, np.float32),
                                 chunks=(max(1, min(len(m), 4096)), 3, 3))
                t = f.create_dataset("known_head_translation", data=np.asarray(self.known_head_translation, np.float32),
                                     chunks=(max(1, min(len(m), 4096)), 3))
                t.attrs["units"] = "mm"
            a = stamp(f.create_group("audio"), "audio")
            a.create_dataset("samples", data=self.audio.astype(np.float32))
            a.create_dataset("start", data=self.audio_start.astype(np.int64))
            a.create_dataset("count", data=self.audio_count.astype(np.int64))
            a.attrs["sample_rate"] = self.sample_rate

    def take_index(self, name: str, path: Path) -> int:
        """Row of take ``name``; a clear error naming ``path`` when there is none."""
        if name not in self.takes.name:
            raise InputError(f"{path}: no take {name!r}; it has {', '.join(self.takes.name[:5])}...")
        return self.takes.index(name)

    def check_markers(self, names: list[str], path: Path) -> None:
        """Refuse a corpus whose markers are not ``names`` (e.g. a database's)."""
        if self.marker_names != names:
            raise InputError(f"{path}: its markers differ from the database's; use the corpus the database was built from.")
