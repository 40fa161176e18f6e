"""The motion-node database (paper III, VI-B) and the ``motiondb`` artifact.

One motion node per phone occurrence of the training takes, the frames they index (the
phoneme clusters), and the pairwise transition terms of Table I (DSC, PGap, VGap) as
(N, N) float32 tables, row = predecessor candidate i, column = node j. The pair tables are
streamed from the file when the search needs them, never held twice.
"""

from __future__ import annotations

import contextlib
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import h5py
import numpy as np

from ..artifacts import RowReader, attr, open_artifact, read, read_strings, stamp, write_artifact, write_strings
from ..errors import InputError
from ..phonemes import to_festival
from .frames import HeadFrames, write_head_frames
from .pca import PcaModel
from .tables import Phones, Takes, read_tables, write_tables

PAIR_KEYS = ("dsc", "pgap", "vgap")
PAIR_UNITS = {"dsc": "mm^2/frame^3", "pgap": "mm", "vgap": "mm/frame"}
BOUNDARY_KEYS = ("first_pos", "last_pos", "first_vel", "last_vel")


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
                     pick(self.prev_phone), pick(self.next_phone), pre, suc)

    _STRINGS = ("phone", "emotion", "prev_phone", "next_phone")
    _ARRAYS = ("viseme", "take", "frame_start", "frame_count", "start_s", "end_s", "pre", "suc")

    def write(self, f: h5py.File) -> None:
        """Write the table as ``/nodes``."""
        g = stamp(f.create_group("nodes"), "nodes")
        for key in self._STRINGS:
            write_strings(g, key, getattr(self, key))
        for key in self._ARRAYS:
            g.create_dataset(key, data=getattr(self, key))

    @classmethod
    def read(cls, f: h5py.File) -> "Nodes":
        """The table under ``/nodes`` of an open artifact."""
        values = {k: read_strings(f, f"nodes/{k}") for k in cls._STRINGS}
        values.update({k: read(f, f"nodes/{k}") for k in cls._ARRAYS})
        return cls(**values)


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
class PairTerms:
    """The pairwise transition terms of Table I and what they were computed from.

    dsc : (N, N) float32 mm^2/frame^3, Eq. 6 (0 where node j has no captured predecessor).
    pgap, vgap : (N, N) float32, Eq. 8-9 in mm and mm/frame.
    boundary : first_pos, last_pos, first_vel, last_vel, each (N, 3M) float32 (mm, mm/frame).
    device : where PGap/VGap were computed ("OpenCL: ..." or "NumPy"); device_reason : why there.
    """

    dsc: np.ndarray
    pgap: np.ndarray
    vgap: np.ndarray
    boundary: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]
    device: str
    device_reason: str = ""

    def subset(self, keep: np.ndarray) -> "PairTerms":
        """Rows and columns ``keep`` of every table, in row blocks."""
        tables = []
        for m in (self.dsc, self.pgap, self.vgap):
            out = np.empty((len(keep), len(keep)), np.float32)
            for a in range(0, len(keep), 512):
                out[a : a + 512] = m[keep[a : a + 512]][:, keep]
            tables.append(out)
        return PairTerms(*tables, tuple(b[keep] for b in self.boundary), self.device, self.device_reason)


@dataclass
class Pruned:
    """What ``facesynth prune`` removed: each kept node's id in the unpruned database, and
    every removed id (all prunes so far) with its reason."""

    original_id: np.ndarray
    removed_id: np.ndarray
    reason: list[str]


@dataclass
class MotionDatabase:
    """A ``motiondb`` artifact without its pair tables (read with :meth:`read_pairs` or
    streamed by :meth:`transition` / :meth:`transition_panels`).

    takes, phones, marker_names : the corpus tables (M markers).
    model : the PCA model (K components).
    coeffs : (F, K) float32, every frame's PCA coefficients; nodes index these frames.
    frames : the normalized frames and head motion (markers is None unless read with markers).
    nodes : the N motion nodes.
    pruned : what prune removed, or None.
    path : the file (pair tables are read from it).
    source : the file as :meth:`read` opened and validated it, kept open so that every later
        read (the pair tables) comes from that same snapshot, even if the path is replaced meanwhile.
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
        from ..motion.head import relative_to_take

        return relative_to_take(self.frames.head_rotation, self.frames.head_translation,
                                [self.takes.frames(i) for i in range(len(self.takes))])

    @classmethod
    def read(cls, path: Path, *, markers: bool = False) -> "MotionDatabase":
        """Everything but the pair tables; the normalized markers only if ``markers``."""
        f = open_artifact(path, cls.KIND)
        try:
            n = len(f["nodes/phone"]) if "nodes/phone" in f else -1
            for key in PAIR_KEYS:
                shape = f[f"pairs/{key}"].shape if f"pairs/{key}" in f else None
                if shape != (n, n):
                    raise InputError(f"{path}: dataset 'pairs/{key}' is missing or not (nodes x nodes); "
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

    def read_pairs(self) -> PairTerms:
        """The full pair tables and boundary states."""
        with self._opened() as f:
            return PairTerms(*(read(f, f"pairs/{k}") for k in PAIR_KEYS),
                             tuple(read(f, f"boundary/{k}") for k in BOUNDARY_KEYS),
                             str(f["pairs"].attrs.get("device", "")), str(f["pairs"].attrs.get("device_reason", "")))

    def transition(self, settings) -> np.ndarray:
        """The full (N, N) float32 TC matrix of Table I for ``settings`` (SynthesizeSettings),
        streaming the pair terms in row blocks."""
        from ..search.costs import transition_rows

        n = len(self.nodes)
        tc = np.empty((n, n), np.float32)
        block = min(256, n)
        with self._opened() as f, contextlib.ExitStack() as stack:
            terms = [stack.enter_context(RowReader(f[f"pairs/{key}"], block)) for key in PAIR_KEYS]
            for a in range(0, n, block):
                rows = slice(a, min(n, a + block))
                tc[rows] = transition_rows(rows, *(t.rows(rows) for t in terms), self.nodes.viseme, self.nodes.pre, settings)
        return tc

    def transition_panels(self, settings):
        """TC assembled straight into the panel-major layout of the OpenCL DP (a PanelMatrix),
        streaming the pair terms in row blocks read in place from the file."""
        from ..search.costs import transition_panel_rows
        from ..search.dp import PanelMatrix

        n = len(self.nodes)
        out = PanelMatrix(n)
        block = min(128, n)  # half a chunk of build-db: the block's sums stay in cache
        scratch = np.empty((2, block, n), np.float32)
        with self._opened() as f, contextlib.ExitStack() as stack:
            terms = [stack.enter_context(RowReader(f[f"pairs/{key}"], block)) for key in PAIR_KEYS]
            for a in range(0, n, block):
                rows = slice(a, min(n, a + block))
                dsc, pgap, vgap = (t.rows(rows) for t in terms)
                transition_panel_rows(out.panels, rows, dsc, pgap, vgap, self.nodes.viseme, self.nodes.pre, settings,
                                      scratch=scratch)
                del dsc, pgap, vgap  # views of the file's map, which closes with the readers
        return out

    def write(self, path: Path, pairs: PairTerms, *, config: str, inputs, overwrite: bool = False) -> None:
        """Write the database with ``pairs``; ``frames.markers`` must be loaded."""
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
            n = len(self.nodes)
            p = stamp(g.create_group("pairs"), "pair-terms")
            for key in PAIR_KEYS:
                d = p.create_dataset(key, data=getattr(pairs, key), chunks=(max(1, min(n, 256)), max(n, 1)))
                d.attrs["units"] = PAIR_UNITS[key]
                d.attrs["layout"] = "row = predecessor candidate i, column = node j"
            p.attrs["device"] = pairs.device
            p.attrs["device_reason"] = pairs.device_reason
            b = stamp(g.create_group("boundary"), "boundary-states")
            for key, value in zip(BOUNDARY_KEYS, pairs.boundary):
                b.create_dataset(key, data=value.astype(np.float32))
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
