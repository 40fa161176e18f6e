"""Reading any take a capture manifest's ``mocap`` column may name: the registered capture
formats (:data:`facesynth.base.registry.CAPTURE_READERS`, registered in
:mod:`facesynth.domain.capture`) and the one entry ``ingest`` and ``bind`` call,
:func:`read_capture`.

A member of the registry is either a plain reader ``read(path) -> MarkerTake`` (a marker file,
told by its file name: :mod:`facesynth.formats.mocap`), or a :class:`CaptureReader`, whose
``read`` takes the take's :class:`CaptureOptions` (the rig a curve take poses, a mapping, a
frame rate...) and whose ``recognizes`` tells from the file (and the options) whether a file
with one of its suffixes is of this format. Among the formats sharing a suffix (``.csv``: Live
Link Face, another rig's curves, markers) the first registered that recognizes the file reads it.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from facesynth.base.errors import InputError
from facesynth.base.registry import CAPTURE_READERS
from facesynth.domain.rig.face import Rig
from facesynth.domain.rig.neutral import NeutralChoice
from facesynth.formats.mocap import MarkerTake, checked

#: The scale of a video take when nothing else is said (mm between the outer eye corners).
EYE_CORNERS_MM = 90.0
#: Rows of a Live Link Face take further apart than this (s) leave a gap.
MAX_INTERPOLATED_S = 0.05


@dataclass(frozen=True)
class CaptureOptions:
    """What a take may need beyond its file (from the manifest's optional columns, else
    ``[ingest]``, and ``ingest --rig/--binding``).

    rig : the rig a curve take poses; None: the built-in rig bound to the virtual actress's markers.
    mapping : another rig's curves: the mapping CSV to ARKit. names : a ``.npy`` curve take's
    channel names. fps : the rate of curves without time, or a Live Link Face take's timecode
    rate (None: from the file). face_width_mm : a video's scale (outer eye corners).
    max_interpolated_s : a Live Link Face take's longest stretch between rows that is
    interpolated. need_audio : a video must carry sound (False when the manifest gives the
    take's audio). neutral : another rig's curves have the performer's neutral weights taken
    off (:mod:`facesynth.domain.rig.neutral`; None: not); live_link_neutral : a Live Link Face
    take likewise."""

    rig: Rig | None = None
    mapping: Path | None = None
    names: Path | None = None
    fps: float | None = None
    face_width_mm: float = EYE_CORNERS_MM
    max_interpolated_s: float = MAX_INTERPOLATED_S
    need_audio: bool = True
    neutral: NeutralChoice | None = None
    live_link_neutral: NeutralChoice | None = None


@dataclass(frozen=True)
class CaptureReader:
    """A capture format that needs the take's options or tells its files by their contents
    (see the module docstring): ``read(path, options)`` returns the take as markers;
    ``recognizes(path, options)`` whether a file with one of the format's suffixes is of this
    format (None: the suffix says it)."""

    read: Callable[[Path, CaptureOptions], MarkerTake]
    recognizes: Callable[[Path, CaptureOptions], bool] | None = None


def _as_reader(member: Any) -> CaptureReader:
    """A registered member as a :class:`CaptureReader` (a plain marker reader takes no options)."""
    if isinstance(member, CaptureReader):
        return member
    return CaptureReader(lambda path, options: member(path))


def capture_reader(path: Path, options: CaptureOptions) -> tuple[str, CaptureReader]:
    """(name, reader) of the registered format of ``path``: by its suffix, then its contents; one
    sentence naming the formats read for a file of none of them."""
    suffix = Path(path).suffix.lower()
    known = [e for e in CAPTURE_READERS.entries() if suffix in e.facts["suffixes"]]
    for entry in known:
        reader = _as_reader(entry.load())
        if reader.recognizes is None or reader.recognizes(path, options):
            return entry.name, reader
    if known:
        raise InputError(f"{path}: not a capture file facesynth reads ({'; '.join(e.summary for e in known)}); check "
                         "the manifest's mocap column.")
    suffixes = list(dict.fromkeys(x for e in CAPTURE_READERS.entries() for x in e.facts["suffixes"]))
    raise InputError(f"{path}: unsupported mocap format {suffix!r}; use {', '.join(suffixes[:-1])} or {suffixes[-1]}.")


def read_capture(path: Path, options: CaptureOptions | None = None) -> MarkerTake:
    """The take at ``path`` as markers, read by its registered format (:func:`capture_reader`)
    and checked as every take is (:func:`facesynth.formats.mocap.check_take`): a
    :class:`~facesynth.formats.mocap.MarkerTake`, or for curves and video its subclass
    :class:`~facesynth.domain.capture.posing.CaptureTake`."""
    path = Path(path)
    options = options or CaptureOptions()
    if not path.exists():
        raise InputError(f"{path}: mocap file not found; check the manifest's mocap column.")
    _, reader = capture_reader(path, options)
    return checked(reader.read(path, options), path)
