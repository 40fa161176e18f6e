"""The motion-node database (paper III, VI-B) and the ``motiondb`` artifact.

One motion node per phone occurrence of the training takes, the frames they index (the
phoneme clusters), and per node the features from which the transition terms of Table I
(DSC, PGap, VGap) of any pair are computed on demand (:mod:`facesynth.domain.search.pairs`): the
file grows linearly with the number of nodes. Databases of schema 1 stored (N, N) pair
tables instead; reading one fails with a sentence that says to rebuild it with build-db.
"""

from __future__ import annotations

import contextlib
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import h5py
import numpy as np

from facesynth.base.errors import InputError
from facesynth.base.opencl import HOST_ALIGNMENT
from facesynth.base.phonemes import to_festival

from .artifacts import attr, open_artifact, read, read_strings, stamp, write_artifact, write_strings
from .frames import HeadFrames, relative_to_take, write_head_frames
from .pca import PcaModel
from .tables import Phones, Takes, read_tables, write_tables

BOUNDARY_KEYS = ("first_pos", "last_pos", "first_vel", "last_vel")
DSC_KEYS = ("dsc_out", "dsc_in", "dsc_scale")
PIVOT_KEYS = ("pivot_last_pos", "pivot_first_pos", "pivot_last_vel", "pivot_first_vel")


@dataclass
class Nodes:
    """The motion-node table; row k is node k (N nodes). Frames index the artifact's ``coefficients``.

    phone, emotion : N phone and emotion names.
    viseme : (N,) int64, Table VI class.
    take : (N,) int64, row of ``/takes``.
    frame_start, frame_count : (N,) int64, global frame range.
    start_s, end_s : (N,) float64, seconds from the take's start.
    prev_phone, next_phone : triphone context (``pau`` at sentence edges).
    pre, suc : (N,) int64, captured predecessor / successor node, or -1.
    ipa : N IPA phones pronounced (a take in another language; ``phone`` is then the nearest
        English phone), ``""`` for English phones; None when every take is English.
    """

    phone: list[str]
    viseme: np.ndarray
    emotion: list[str]
    take: np.ndarray
    frame_start: np.ndarray
    frame_count: np.ndarray
    start_s: np.ndarray
    end_s: np.ndarray
    prev_phone: list[str]
    next_phone: list[str]
    pre: np.ndarray
    suc: np.ndarray
    ipa: list[str] | None = None

    def __len__(self) -> int:
        return len(self.phone)

    def frames(self, k: int) -> slice:
        """The global frame range of node ``k``."""
        return slice(int(self.frame_start[k]), int(self.frame_start[k] + self.frame_count[k]))

    def subset(self, keep: np.ndarray) -> "Nodes":
        """The nodes in ``keep`` (sorted indices), links re-indexed; links to dropped nodes become -1."""
        remap = -np.ones(len(self), np.int64)
        remap[keep] = np.arange(len(keep))
        pick = lambda xs: [xs[k] for k in keep]  # noqa: E731
        pre = np.where(self.pre[keep] >= 0, remap[np.maximum(self.pre[keep], 0)], -1)
        suc = np.where(self.suc[keep] >= 0, remap[np.maximum(self.suc[keep], 0)], -1)
        return Nodes(pick(self.phone), self.viseme[keep], pick(self.emotion), self.take[keep],
                     self.frame_start[keep], self.frame_count[keep], self.start_s[keep], self.end_s[keep],
                     pick(self.prev_phone), pick(self.next_phone), pre, suc,
                     None if self.ipa is None else pick(self.ipa))

    _STRINGS = ("phone", "emotion", "prev_phone", "next_phone")
    _ARRAYS = ("viseme", "take", "frame_start", "frame_count", "start_s", "end_s", "pre", "suc")

    def write(self, f: h5py.File) -> None:
        """Write the table as ``/nodes``."""
        g = stamp(f.create_group("nodes"), "nodes")
        for key in self._STRINGS:
            write_strings(g, key, getattr(self, key))
        for key in self._ARRAYS:
            g.create_dataset(key, data=getattr(self, key))
        if self.ipa is not None:
            write_strings(g, "ipa", self.ipa)

    @classmethod
    def read(cls, f: h5py.File) -> "Nodes":
        """The table under ``/nodes`` of an open artifact."""
        values: dict[str, list[str] | np.ndarray] = {k: read_strings(f, f"nodes/{k}") for k in cls._STRINGS}
        values.update({k: read(f, f"nodes/{k}") for k in cls._ARRAYS})
        return cls(**values, ipa=read_strings(f, "nodes/ipa") if "nodes/ipa" in f else None)  # type: ignore[arg-type]


def node_frames(nodes: Nodes, n_frames: int) -> tuple[np.ndarray, np.ndarray]:
    """Per frame: its node ((F,) int64, -1 outside nodes) and relative time in the node
    ((F,) float32, 0 to 1; NaN outside nodes) — the phoneme clusters of paper III."""
    node = -np.ones(n_frames, np.int64)
    relative = np.full(n_frames, np.nan, np.float32)
    for k in range(len(nodes)):
        sl = nodes.frames(k)
        node[sl] = k
        relative[sl] = np.linspace(0.0, 1.0, sl.stop - sl.start)
    return node, relative


@dataclass
class TransitionFeatures:
    """The per-node data from which every pair's Table I terms (DSC, PGap, VGap) are computed,
    as a ``motiondb`` stores it (N nodes, M markers, D DSC terms); the search computes the pair
    terms from it (:mod:`facesynth.domain.search.pairs`).

    first_pos, last_pos : (N, 3M) float32 mm, markers of the node's first / last frame.
    first_vel, last_vel : (N, 3M) float32 mm/frame, velocity at the first / last frame.
    dsc_out : (N, D) float32, x_i: second differences of (1 - s) warp(o_i) (PCA space, mm; Eq. 6).
    dsc_in : (N, D) float32, y_j: second differences of s * pre(o_j) (0 without predecessor).
    dsc_scale : (N,) float32, 1/frame^3 (0 without predecessor).
    viseme : (N,) int64 Table VI class; pre : (N,) int64 captured predecessor or -1.
    pivot_distances : four (N, P) float32 arrays: mixed-norm distances (sum over markers of the
        Euclidean distance) of last_pos, first_pos, last_vel, first_vel from P pivots (mm, mm,
        mm/frame, mm/frame), for the search's bounds; None until computed
        (:func:`facesynth.domain.search.pairs.pivot_distances`), required to write a database.
    device_layout : the search's padded, lane-ordered copies of the arrays
        (:func:`facesynth.domain.search.pairs.layout`), made once on first use; not stored, and
        not carried by ``dataclasses.replace`` (a replaced array needs its own).
    """

    first_pos: np.ndarray
    last_pos: np.ndarray
    first_vel: np.ndarray
    last_vel: np.ndarray
    dsc_out: np.ndarray
    dsc_in: np.ndarray
    dsc_scale: np.ndarray
    viseme: np.ndarray
    pre: np.ndarray
    pivot_distances: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None = None
    device_layout: object = field(default=None, init=False, repr=False, compare=False)

    def __len__(self) -> int:
        return len(self.pre)

    @property
    def pre_viseme(self) -> np.ndarray:
        """(N,) int64: viseme of pre(o_j), -1 without predecessor."""
        return np.where(self.pre >= 0, self.viseme[np.maximum(self.pre, 0)], -1)

    def subset(self, keep: np.ndarray, pre: np.ndarray) -> TransitionFeatures:
        """The nodes ``keep`` with re-indexed links ``pre``; a node whose predecessor is gone
        gets DSC features 0 (Table I rule 4 does not use DSC)."""
        lost = pre < 0
        dsc_in = self.dsc_in[keep].copy()
        scale = self.dsc_scale[keep].copy()
        dsc_in[lost] = 0.0
        scale[lost] = 0.0
        pivots = None if self.pivot_distances is None else tuple(d[keep] for d in self.pivot_distances)
        return TransitionFeatures(self.first_pos[keep], self.last_pos[keep], self.first_vel[keep], self.last_vel[keep],
                                  self.dsc_out[keep], dsc_in, scale, self.viseme[keep], pre,
                                  pivots)


@dataclass
class Pruned:
    """What ``facesynth prune`` removed: each kept node's id in the unpruned database, and
    every removed id (all prunes so far) with its reason."""

    original_id: np.ndarray
    removed_id: np.ndarray
    reason: list[str]


@dataclass
class MotionDatabase:
    """A ``motiondb`` artifact without its transition features (read with :meth:`read_features`;
    :meth:`transition_costs` computes Table I's costs from them on demand).

    takes, phones, marker_names : the corpus tables (M markers).
    model : the PCA model (K components).
    coeffs : (F, K) float32, every frame's PCA coefficients; nodes index these frames.
    frames : the normalized frames and head motion (markers is None unless read with markers).
    nodes : the N motion nodes.
    pruned : what prune removed, or None.
    path : the file (the transition features are read from it).
    source : the file as :meth:`read` opened and validated it, kept open so that every later
        read (the transition features) comes from that same snapshot, even if the path is replaced meanwhile.
    """

    takes: Takes
    phones: Phones
    marker_names: list[str]
    model: PcaModel
    coeffs: np.ndarray
    frames: HeadFrames
    nodes: Nodes
    pruned: Pruned | None = None
    path: Path | None = field(default=None, compare=False)
    source: h5py.File | None = field(default=None, compare=False, repr=False)

    KIND = "motiondb"

    @contextlib.contextmanager
    def _opened(self):
        """The database file: the one :meth:`read` opened, else opened (and validated) now."""
        if self.source is not None and self.source.id.valid:
            yield self.source
        else:
            with open_artifact(self.path, self.KIND) as f:
                yield f

    @property
    def fps(self) -> float:
        """Capture rate of the frames, frames/s."""
        return self.frames.fps

    @property
    def reference(self) -> np.ndarray:
        """(M, 3) float32 mm, the neutral closed-mouth rest pose."""
        return self.frames.reference

    @cached_property
    def head_relative_to_take(self) -> tuple[np.ndarray, np.ndarray]:
        """Per frame, the head pose relative to its take's mean: (F, 3, 3) rotations and (F, 3) mm."""
        return relative_to_take(self.frames.head_rotation, self.frames.head_translation,
                                [self.takes.frames(i) for i in range(len(self.takes))])

    def head_relative(self, frames: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """:attr:`head_relative_to_take` of the frames ``frames`` only ((n,) int indices):
        (n, 3, 3) rotations and (n, 3) mm, the same values, computed for their takes alone."""
        frames = np.asarray(frames, np.int64)
        starts = np.asarray(self.takes.frame_start, np.int64)
        by_start = np.argsort(starts, kind="stable")
        take = by_start[np.searchsorted(starts[by_start], frames, side="right") - 1]
        rot, trans = np.empty((len(frames), 3, 3)), np.empty((len(frames), 3))
        for t in np.unique(take):
            sl = self.takes.frames(int(t))
            r, tr = relative_to_take(self.frames.head_rotation[sl], self.frames.head_translation[sl],
                                     [slice(0, sl.stop - sl.start)])
            sel = take == t
            rot[sel], trans[sel] = r[frames[sel] - sl.start], tr[frames[sel] - sl.start]
        return rot, trans

    @classmethod
    def read(cls, path: Path, *, markers: bool = False) -> "MotionDatabase":
        """Everything but the transition features; the normalized markers only if ``markers``."""
        f = open_artifact(path, cls.KIND)
        try:
            n = len(f["nodes/phone"]) if "nodes/phone" in f else -1
            for key in [f"boundary/{k}" for k in BOUNDARY_KEYS] + [f"transition/{k}" for k in DSC_KEYS + PIVOT_KEYS]:
                if key not in f or len(f[key]) != n:
                    raise InputError(f"{path}: dataset '{key}' is missing or not one row per node; "
                                     "rebuild it with facesynth build-db.")
            takes, phones, names = read_tables(f)
            frames = HeadFrames(read(f, "markers") if markers else None, read(f, "reference"),
                                read(f, "head_rotation"), read(f, "head_translation"),
                                float(attr(f["coefficients"], "fps")), str(f["markers"].attrs.get("origin_marker", "")))
            pruned = Pruned(read(f, "pruned/original_id"), read(f, "pruned/removed_id"),
                            read_strings(f, "pruned/reason")) if "pruned" in f else None
            return cls(takes, phones, names, PcaModel.read(f), read(f, "coefficients"), frames, Nodes.read(f),
                       pruned, Path(path), f)
        except BaseException:
            f.close()
            raise

    def feature_bytes(self) -> int:
        """Bytes of the per-node transition features :meth:`read_features` returns (from the
        datasets' shapes; nothing is read)."""
        with self._opened() as f:
            keys = [f"boundary/{k}" for k in BOUNDARY_KEYS] + [f"transition/{k}" for k in DSC_KEYS + PIVOT_KEYS]
            return int(sum(f[k].size * f[k].dtype.itemsize for k in keys))

    def transition_features(self) -> TransitionFeatures:
        """The per-node transition features as stored, with the nodes' visemes and captured
        predecessors (the search builds its pair terms from them), the arrays page-aligned so
        that an OpenCL CPU device reads them in place."""
        with self._opened() as f:
            first_pos, last_pos, first_vel, last_vel = (read(f, f"boundary/{k}", HOST_ALIGNMENT) for k in BOUNDARY_KEYS)
            dsc_out, dsc_in, dsc_scale = (read(f, f"transition/{k}", HOST_ALIGNMENT) for k in DSC_KEYS)
            pivots = tuple(read(f, f"transition/{k}") for k in PIVOT_KEYS)
            return TransitionFeatures(first_pos, last_pos, first_vel, last_vel, dsc_out, dsc_in, dsc_scale,
                                      self.nodes.viseme, self.nodes.pre, pivots)  # type: ignore[arg-type]

    def write(self, path: Path, features: TransitionFeatures, *, config: str, inputs, overwrite: bool = False) -> None:
        """Write the database with its transition ``features`` (their pivot distances computed;
        the visemes and predecessors are the nodes'); ``frames.markers`` must be loaded."""
        if features.pivot_distances is None:
            raise ValueError("MotionDatabase.write: the features' pivot distances are not computed")
        with write_artifact(path, self.KIND, config=config, inputs=inputs, overwrite=overwrite) as g:
            write_tables(g, self.takes, self.phones, self.marker_names)
            self.model.write(g)
            write_head_frames(g, self.frames)
            c = g.create_dataset("coefficients", data=self.coeffs)
            c.attrs["fps"] = self.fps
            self.nodes.write(g)
            frame_node, relative = node_frames(self.nodes, len(self.coeffs))
            fr = stamp(g.create_group("frames"), "phoneme-clusters")
            fr.create_dataset("node", data=frame_node).attrs["meaning"] = (
                "node of each frame (-1: not in a node); a phoneme cluster is the frames whose node has that phone")
            fr.create_dataset("relative_time", data=relative).attrs["meaning"] = "0 to 1 inside its node (NaN outside nodes)"
            b = stamp(g.create_group("boundary"), "boundary-states")
            for key in BOUNDARY_KEYS:
                b.create_dataset(key, data=np.asarray(getattr(features, key), np.float32))
            tr = stamp(g.create_group("transition"), "transition-features")
            tr.create_dataset("dsc_out", data=np.asarray(features.dsc_out, np.float32)).attrs["units"] = "mm"
            tr.create_dataset("dsc_in", data=np.asarray(features.dsc_in, np.float32)).attrs["units"] = "mm"
            tr.create_dataset("dsc_scale", data=np.asarray(features.dsc_scale, np.float32)).attrs["units"] = "1/frame^3"
            for key, value, units in zip(PIVOT_KEYS, features.pivot_distances, ("mm", "mm", "mm/frame", "mm/frame")):
                tr.create_dataset(key, data=np.asarray(value, np.float32)).attrs["units"] = units
            if self.pruned is not None:
                q = stamp(g.create_group("pruned"), "pruned")
                q.create_dataset("original_id", data=self.pruned.original_id.astype(np.int64))
                q.create_dataset("removed_id", data=self.pruned.removed_id.astype(np.int64))
                write_strings(q, "reason", self.pruned.reason)


def describe(db: MotionDatabase, phone: str | None = None, node: int | None = None) -> list[str]:
    """Lines of ``facesynth db show``: every node (or one phone's) as a table, or one node in detail."""
    nodes, takes = db.nodes, db.takes
    if node is not None:
        if not 0 <= node < len(nodes):
            raise InputError(f"{db.path}: node {node} does not exist (0 to {len(nodes) - 1}).")
        k = node
        lines = [f"node {k}: /{nodes.phone[k]}/ in [{nodes.prev_phone[k]} {nodes.phone[k]} {nodes.next_phone[k]}], {nodes.emotion[k]}",
                 f"  take {takes.name[nodes.take[k]]} ({takes.sentence[nodes.take[k]]}), {nodes.start_s[k]:.3f}-{nodes.end_s[k]:.3f} s, "
                 f"{nodes.frame_count[k]} frames at {db.fps:g} Hz",
                 f"  captured predecessor: {nodes.pre[k] if nodes.pre[k] >= 0 else 'none'}, successor: {nodes.suc[k] if nodes.suc[k] >= 0 else 'none'}"]
        if db.pruned is not None:
            lines.append(f"  id in the unpruned database: {db.pruned.original_id[k]}")
        same = [j for j in range(len(nodes)) if nodes.phone[j] == nodes.phone[k] and j != k
                and nodes.prev_phone[j] == nodes.prev_phone[k] and nodes.next_phone[j] == nodes.next_phone[k]]
        lines.append(f"  same triphone context: {same[:20] if same else 'none'}")
        return lines
    if phone is not None:
        # The same labels as the phone timings take: Festival or CMU (ARPAbet) names, any case.
        asked, phone = phone, to_festival(phone)
        if phone is None:
            raise InputError(f"--phoneme {asked!r}: unknown phone; use Festival or CMU (ARPAbet) phone names.")
        if phone not in nodes.phone:
            raise InputError(f"{db.path}: no node of /{phone}/; phones present: {' '.join(sorted(set(nodes.phone)))}.")
    lines = ["id\tphone\tcontext\temotion\ttake\tframes\tpre\tsuc"]
    for k in range(len(nodes)):
        if phone is not None and nodes.phone[k] != phone:
            continue
        lines.append(f"{k}\t{nodes.phone[k]}\t{nodes.prev_phone[k]}-{nodes.phone[k]}+{nodes.next_phone[k]}\t{nodes.emotion[k]}\t"
                     f"{takes.name[nodes.take[k]]}\t{nodes.frame_start[k]}+{nodes.frame_count[k]}\t{nodes.pre[k]}\t{nodes.suc[k]}")
    return lines
