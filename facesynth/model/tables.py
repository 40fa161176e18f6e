"""Tables shared by the corpus-side artifacts: the takes, their phone segments and the markers.

Stored as column datasets under ``/takes`` and ``/phones`` (and ``/marker_names``) and
written forward by each stage, so every artifact downstream of ``ingest`` knows which
frames belong to which take.
"""

from __future__ import annotations

from dataclasses import dataclass

import h5py
import numpy as np

from .artifacts import read, read_strings, stamp, write_strings


@dataclass
class Takes:
    """One row per take. Frames of take i are ``frame_start[i] : frame_start[i] + frame_count[i]``."""

    name: list[str]
    emotion: list[str]
    sentence: list[str]
    split: list[str]
    transcript: list[str]
    frame_start: np.ndarray  # (n,) int64
    frame_count: np.ndarray  # (n,) int64

    def __len__(self) -> int:
        return len(self.name)

    def frames(self, i: int) -> slice:
        """The global frame range of take ``i``."""
        return slice(int(self.frame_start[i]), int(self.frame_start[i] + self.frame_count[i]))

    def index(self, name: str) -> int:
        """Row of the take named ``name``."""
        return self.name.index(name)

    def write(self, f: h5py.File) -> None:
        """Write the table as ``/takes``."""
        g = stamp(f.create_group("takes"), "takes")
        for key in ("name", "emotion", "sentence", "split", "transcript"):
            write_strings(g, key, getattr(self, key))
        g.create_dataset("frame_start", data=self.frame_start.astype(np.int64))
        g.create_dataset("frame_count", data=self.frame_count.astype(np.int64))

    @classmethod
    def read(cls, f: h5py.File) -> "Takes":
        """The table under ``/takes`` of an open artifact."""
        return cls(  # type: ignore[call-arg]
            *(read_strings(f, f"takes/{k}") for k in ("name", "emotion", "sentence", "split", "transcript")),  # type: ignore[arg-type]
            read(f, "takes/frame_start"), read(f, "takes/frame_count"),
        )


@dataclass
class Phones:
    """One row per phone segment: its take (row index into :class:`Takes`), times (s), phone,
    and its emotion (``None``: every phone has its take's emotion, as in files written
    before per-phone emotion existed; see :meth:`emotions`). ``ipa``: for takes spoken in
    another language than English, the IPA phone each segment pronounces (``phone`` is then its
    nearest English phone), ``""`` for English phones and pauses; None when every take is
    English (and in files written before it existed)."""

    take: np.ndarray   # (n,) int64
    start: np.ndarray  # (n,) float64, seconds from the take's start
    end: np.ndarray    # (n,) float64
    phone: list[str]
    emotion: list[str] | None = None
    ipa: list[str] | None = None

    def emotions(self, takes: "Takes") -> list[str]:
        """The emotion of every phone: its own, or its take's when the table has none."""
        if self.emotion is not None:
            return list(self.emotion)
        return [takes.emotion[int(t)] for t in self.take]

    def __len__(self) -> int:
        return len(self.phone)

    def write(self, f: h5py.File) -> None:
        """Write the table as ``/phones`` (times in s)."""
        g = stamp(f.create_group("phones"), "phones")
        g.create_dataset("take", data=self.take.astype(np.int64))
        g.create_dataset("start", data=self.start.astype(np.float64))
        g.create_dataset("end", data=self.end.astype(np.float64))
        write_strings(g, "phone", self.phone)
        if self.emotion is not None:
            write_strings(g, "emotion", self.emotion)
        if self.ipa is not None:
            write_strings(g, "ipa", self.ipa)
        g["start"].attrs["units"] = "s"
        g["end"].attrs["units"] = "s"

    @classmethod
    def read(cls, f: h5py.File) -> "Phones":
        """The table under ``/phones`` of an open artifact."""
        emotion = read_strings(f, "phones/emotion") if "phones/emotion" in f else None
        ipa = read_strings(f, "phones/ipa") if "phones/ipa" in f else None
        return cls(read(f, "phones/take"), read(f, "phones/start"), read(f, "phones/end"), read_strings(f, "phones/phone"),
                   emotion, ipa)


def read_tables(f: h5py.File) -> tuple[Takes, Phones, list[str]]:
    """The takes, phones and marker names every corpus-side artifact carries."""
    return Takes.read(f), Phones.read(f), read_strings(f, "marker_names")


def write_tables(f: h5py.File, takes: Takes, phones: Phones, marker_names: list[str]) -> None:
    """Write ``/takes``, ``/phones`` and ``/marker_names``."""
    takes.write(f)
    phones.write(f)
    write_strings(f, "marker_names", marker_names)
