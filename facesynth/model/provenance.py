"""Where every frame of an animation came from, carried from ``synthesize`` to the end of the
pipeline: the ``provenance`` group of ``curves`` and ``meshanim`` artifacts (written by
``solve``, ``retarget``, ``rig-mesh`` and ``deform``), the glTF ``extras`` and USD
``customData`` of ``export`` and the player's timeline.

A synthesized ``motion`` keeps its provenance per capture-rate frame (its ``provenance`` group)
and its phones in ``path``; :func:`of_motion` turns them into one row per output frame. Frames
made at another rate than their source (the output rate of a synthesis, ``export --fps``) take
the provenance of the nearest source frame (:meth:`FrameProvenance.resampled`). A captured take
carries its name and no phones (none are known); a restyled motion carries nothing.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .artifacts import read, read_strings, stamp, write_strings

#: What made the frames the provenance describes (the motion's ``source``; a synthesis names its
#: method in ``method``).
ORIGINS = ("synthesis", "capture")

#: The rule by which frames made at another rate take their provenance, as stored in the files.
RESAMPLING = "a frame made at another rate than its source has the provenance of the nearest source frame"


@dataclass
class SearchPath:
    """The search's choice, one row per input phone (T phones).

    node : (T,) int64 chosen node; phone, emotion : asked; node_phone, node_emotion : chosen.
    start, end : (T,) float64 s. costs : per term ("tc", "oc", "emp", "block"), (T,) float32.
    total_cost : Eq. 4; non_captured_joins : joins without a captured link; method : the member of
    the method family that made the motion ("dp", "greedy", "trajectory", ...); device : where the
    search ran, device_reason : why there.
    """

    node: np.ndarray
    phone: list[str]
    emotion: list[str]
    node_phone: list[str]
    node_emotion: list[str]
    start: np.ndarray
    end: np.ndarray
    costs: dict[str, np.ndarray]
    total_cost: float
    non_captured_joins: int
    method: str
    device: str
    device_reason: str = ""


@dataclass
class Provenance:
    """Per capture-rate frame (F frames at ``fps``): node, take row, source frame in the
    database (-1: regenerated silence), input phone index, smoothed flag; and the take names."""

    node: np.ndarray
    take: np.ndarray
    take_names: list[str]
    source_frame: np.ndarray
    step: np.ndarray
    smoothed: np.ndarray
    fps: float


@dataclass
class PhoneSegment:
    """One phone of a synthesized utterance: the phone and emotion asked for, ``start``/``end`` s,
    the database node chosen for it (-1: none) and the take most of its frames came from ('')."""

    phone: str
    emotion: str
    start: float
    end: float
    node: int = -1
    take: str = ""


@dataclass
class FrameProvenance:
    """Per frame of an animation (T frames at its own rate):

    phone, emotion : T names, the input phone and emotion the frame belongs to ('' where not known);
    node : (T,) int64 source database node (-1: regenerated silence, a trajectory or a capture);
    take : T source take names ('' for regenerated silence);
    source_frame : (T,) int64 source frame (a synthesis: row of the database's frames; a capture:
        frame of the take at its capture rate; -1 where none);
    step : (T,) int64 the frame's row of ``segments`` (-1 without phones);
    segments : the utterance's phones (empty for a capture); origin : one of :data:`ORIGINS`;
    method : the member of the method family that made a synthesis ('' for a capture).
    """

    phone: list[str]
    emotion: list[str]
    node: np.ndarray
    take: list[str]
    source_frame: np.ndarray
    step: np.ndarray
    segments: list[PhoneSegment]
    origin: str
    method: str = ""

    def __post_init__(self) -> None:
        self.node = np.asarray(self.node, np.int64)
        self.source_frame = np.asarray(self.source_frame, np.int64)
        self.step = np.asarray(self.step, np.int64)
        n = len(self.node)
        if not all(len(x) == n for x in (self.phone, self.emotion, self.take, self.source_frame, self.step)):
            raise ValueError("every per-frame provenance field needs one entry per frame")
        if self.origin not in ORIGINS:
            raise ValueError(f"unknown provenance origin {self.origin!r}")

    @property
    def n_frames(self) -> int:
        return int(len(self.node))

    def take_frames(self, rows: np.ndarray) -> "FrameProvenance":
        """The provenance of frames ``rows`` (n,) int of this one (same segments)."""
        rows = np.asarray(rows, np.int64)
        return FrameProvenance([self.phone[i] for i in rows], [self.emotion[i] for i in rows], self.node[rows],
                               [self.take[i] for i in rows], self.source_frame[rows], self.step[rows],
                               list(self.segments), self.origin, self.method)

    def resampled(self, n_frames: int, fps_from: float, fps_to: float) -> "FrameProvenance":
        """The provenance of ``n_frames`` frames at ``fps_to`` made from these at ``fps_from``: each
        the nearest source frame's (frame i at i / fps_to s)."""
        return self.take_frames(nearest_frames(n_frames, fps_to, self.n_frames, fps_from))

    def fitted(self, n_frames: int) -> "FrameProvenance":
        """This provenance for an animation of ``n_frames`` frames at the same rate (a rounding
        difference of a frame or so: the last row repeats, or the extra rows go)."""
        if n_frames == self.n_frames:
            return self
        return self.take_frames(np.minimum(np.arange(n_frames), self.n_frames - 1))

    def to_json(self) -> dict:
        """Plain lists for JSON (glTF ``extras``, the player): per-frame lists and the phones."""
        return {"origin": self.origin, "method": self.method, "resampling": RESAMPLING,
                "frames": {"phone": list(self.phone), "emotion": list(self.emotion), "node": self.node.tolist(),
                           "take": list(self.take), "source_frame": self.source_frame.tolist(),
                           "step": self.step.tolist()},
                "phones": [{"phone": s.phone, "emotion": s.emotion, "start": s.start, "end": s.end, "node": s.node,
                            "take": s.take} for s in self.segments]}

    def write(self, g) -> None:
        """Write the ``provenance`` group (``frame-provenance``) into the open artifact ``g``."""
        p = stamp(g.create_group("provenance"), "frame-provenance")
        p.attrs.update(origin=self.origin, resampling=RESAMPLING)
        if self.method:
            p.attrs["method"] = self.method
        write_strings(p, "phone", self.phone)
        write_strings(p, "emotion", self.emotion)
        p.create_dataset("node", data=self.node)
        write_strings(p, "take", self.take)
        p.create_dataset("source_frame", data=self.source_frame)
        p.create_dataset("step", data=self.step)
        if self.segments:
            s = stamp(p.create_group("segments"), "phone-segments")
            write_strings(s, "phone", [x.phone for x in self.segments])
            write_strings(s, "emotion", [x.emotion for x in self.segments])
            s.create_dataset("start", data=np.array([x.start for x in self.segments], np.float64)).attrs["units"] = "s"
            s.create_dataset("end", data=np.array([x.end for x in self.segments], np.float64)).attrs["units"] = "s"
            s.create_dataset("node", data=np.array([x.node for x in self.segments], np.int64))
            write_strings(s, "take", [x.take for x in self.segments])

    @classmethod
    def read(cls, f) -> "FrameProvenance | None":
        """The ``provenance`` group of an open ``curves`` or ``meshanim`` artifact; None without one."""
        if "provenance" not in f:
            return None
        segments = []
        if "provenance/segments" in f:
            k = "provenance/segments/"
            segments = [PhoneSegment(p, e, float(a), float(b), int(n), t) for p, e, a, b, n, t in zip(
                read_strings(f, k + "phone"), read_strings(f, k + "emotion"), read(f, k + "start"), read(f, k + "end"),
                read(f, k + "node"), read_strings(f, k + "take"))]
        attrs = f["provenance"].attrs
        origin, method = str(attrs.get("origin", "synthesis")), str(attrs.get("method", ""))
        if origin == "trajectory":  # written before motion schema 2 named the method
            origin, method = "synthesis", "trajectory"
        return cls(read_strings(f, "provenance/phone"), read_strings(f, "provenance/emotion"),
                   read(f, "provenance/node"), read_strings(f, "provenance/take"), read(f, "provenance/source_frame"),
                   read(f, "provenance/step"), segments, origin, method)


def nearest_frames(n_out: int, fps_out: float, n_in: int, fps_in: float) -> np.ndarray:
    """(n_out,) int64: for frame i at i / fps_out s, the nearest of ``n_in`` frames at ``fps_in``."""
    return np.clip(np.floor(np.arange(n_out) * (fps_in / fps_out) + 0.5), 0, max(n_in - 1, 0)).astype(np.int64)


def of_motion(search: SearchPath | None, prov: Provenance | None, n_frames: int, fps: float, source: str,
              take: str = "", capture_frames: int = 0, capture_fps: float = 0.0) -> FrameProvenance | None:
    """The provenance of a motion's ``n_frames`` output frames at ``fps``.

    A synthesis (``source`` "synthesis", by any method) takes its search path and capture-rate
    provenance (``search``, ``prov``), and its method from the path; a capture (``source`` "capture") its take name, and the
    source frame from the take's ``capture_frames`` frames at ``capture_fps``. None for any other
    motion (a restyle)."""
    if source == "capture":
        return of_take(take, n_frames, fps, capture_frames, capture_fps)
    if source != "synthesis" or search is None or prov is None:
        return None
    rows = nearest_frames(n_frames, fps, len(prov.node), prov.fps)
    step = prov.step[rows]
    takes = [prov.take_names[t] if t >= 0 else "" for t in prov.take[rows]]
    segments = []
    for i in range(len(search.phone)):
        mine = prov.take[(prov.step == i) & (prov.take >= 0)]
        majority = prov.take_names[int(np.bincount(mine).argmax())] if len(mine) else ""
        segments.append(PhoneSegment(search.phone[i], search.emotion[i], float(search.start[i]), float(search.end[i]),
                                     int(search.node[i]), majority))
    ok = (step >= 0) & (step < len(search.phone))
    return FrameProvenance([search.phone[s] if o else "" for s, o in zip(step, ok)],
                           [search.emotion[s] if o else "" for s, o in zip(step, ok)],
                           prov.node[rows], takes, prov.source_frame[rows], np.where(ok, step, -1), segments, source,
                           search.method)


def of_take(take: str, n_frames: int, fps: float, capture_frames: int, capture_fps: float) -> FrameProvenance:
    """A captured take's provenance: its name on every frame, the nearest of its ``capture_frames``
    frames at ``capture_fps`` as source frame, and no phones, emotions or nodes (none are known)."""
    source = (nearest_frames(n_frames, fps, capture_frames, capture_fps) if capture_frames > 0
              else np.full(n_frames, -1, np.int64))
    return FrameProvenance([""] * n_frames, [""] * n_frames, np.full(n_frames, -1, np.int64), [take] * n_frames,
                           source, np.full(n_frames, -1, np.int64), [], "capture")
