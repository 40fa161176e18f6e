"""Transition costs of paper Table I computed on demand from per-node boundary features.

No (N, N) table is stored: ``build-db`` keeps, per node, what the pair terms of any ordered
pair (i, j) are made of, and a pair's DSC, PGap and VGap are computed when a search needs it.

* DSC (Eq. 6). With both nodes resampled to S samples (build_db.dsc_samples) and the blend
  ``(1 - s) warp(o_i) + s pre(o_j)``, the second differences of the blend are
  ``x_i + y_j`` where ``x_i`` are the second differences of ``(1 - s) warp(o_i)`` and ``y_j``
  those of ``s pre(o_j)``, both ((S - 2) K,) in PCA space (mm). So
  ``DSC(i, j) = scale_j * sum_d (x_i[d] + y_j[d])^2`` with ``scale_j`` = 1 / (frames between
  samples of pre(o_j))^3 (0 when o_j has no predecessor): mm^2/frame^3.
* PGap, VGap (Eq. 8-9): sums over markers of the distances between o_i's last frame and o_j's
  first frame, positions (mm) and velocities (mm/frame).

Every sum runs in float32 in eight lanes (term d in lane d % 8, front to back) that are then
added in a fixed tree, here and in ``kernels/pair_costs.cl``, so both give bit-identical values. Against the stored float32 tables of schema 1 (DSC expanded as
``|x|^2 + |y|^2 + 2 x.y`` in float64 and rounded once) the float32 sums differ by at most
``(D + 2) 2^-24`` of the sum of the squares' magnitudes for DSC (D = (S - 2) K terms;
measured: below 2e-6 relative to the largest DSC of a database) and by at most
``(M + 2) 2^-24`` of the PGap/VGap sum for M markers (measured: below 2e-6 relative);
``tests/search/test_pairs.py`` checks both bounds against the schema-1 formulas.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from facesynth.base.config import SynthesizeSettings
from facesynth.base.jit import worth
from facesynth.base.opencl import context, kernel, queue, use_opencl
from facesynth.domain.postprocess.concatenation import end_slope_weights
from facesynth.model.motiondb import MotionDatabase, TransitionFeatures

from .costs import transition_matrix
from .dp import PanelMatrix
from .pairs_numba import block_numba

#: Pivots of the cheap lower and upper bounds (triangle inequality of the mixed norm) that
#: ``build-db`` stores; a search uses as many as the database holds. More pivots give tighter
#: bounds for more work per bound: on 100,000 nodes, 16 computed 2.5x fewer pair costs than 4
#: (benchmarks/scale_search.py).
PIVOTS = 16
#: Work-group size of ``pruned_columns``, the same at every launch: PoCL compiles a kernel
#: once per work-group size, so a size that followed the column count (min(64, columns))
#: cost a compile at the first launch of every new size, about 1 s in a fresh process.
LOCAL_SIZE = 16


@dataclass
class DeviceLayout:
    """The features as the pair sums read them: x, y (N, Q, 8) float32 zero-padded to a
    multiple of 8; boundary states (N, 3, Mq, 8) float32, coordinate planes with marker k in
    lane k % 8 of group k // 8, zero-padded."""

    x: np.ndarray
    y: np.ndarray
    last_pos: np.ndarray
    first_pos: np.ndarray
    last_vel: np.ndarray
    first_vel: np.ndarray

    @classmethod
    def of(cls, f: TransitionFeatures) -> "DeviceLayout":
        return cls(_lanes8(f.dsc_out), _lanes8(f.dsc_in), _planes(f.last_pos), _planes(f.first_pos),
                   _planes(f.last_vel), _planes(f.first_vel))


def layout(f: TransitionFeatures) -> DeviceLayout:
    """The padded, lane-ordered copies of ``f`` the pair sums run on (made once, kept in
    ``f.device_layout``)."""
    if f.device_layout is None:
        f.device_layout = DeviceLayout.of(f)
    return f.device_layout  # type: ignore[return-value]


def pair_terms(f: TransitionFeatures, rows: np.ndarray, cols: np.ndarray,
               paired: bool = False) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """DSC, PGap and VGap of every (rows[a], cols[b]), each (r, c) float32, or with ``paired``
    of each (rows[k], cols[k]), each (K,) float32; summed in eight lanes and then across them
    (the reference of ``kernels/pair_costs.cl``, bit-identical)."""
    rows, cols = np.asarray(rows), np.asarray(cols)
    if f.device_layout is not None or len(rows) + len(cols) >= len(f) // 4:
        lay = layout(f)
        x, y = lay.x[rows], lay.y[cols]  # (r, Q, 8), (c, Q, 8)
        last_pos, first_pos = lay.last_pos[rows], lay.first_pos[cols]
        last_vel, first_vel = lay.last_vel[rows], lay.first_vel[cols]
    else:  # a few nodes (backtracking, a pruned scan): lay out only those, the same values
        x, y = _lanes8(f.dsc_out[rows]), _lanes8(f.dsc_in[cols])
        last_pos, first_pos = _planes(f.last_pos[rows]), _planes(f.first_pos[cols])
        last_vel, first_vel = _planes(f.last_vel[rows]), _planes(f.first_vel[cols])
    scale = f.dsc_scale[cols]
    if not paired:  # rows along the first axis, columns along the second
        x, last_pos, last_vel = x[:, None], last_pos[:, None], last_vel[:, None]
        y, first_pos, first_vel, scale = y[None], first_pos[None], first_vel[None], scale[None]
    acc = np.zeros(np.broadcast_shapes(x.shape[:-2], y.shape[:-2]) + (8,), np.float32)
    s = np.empty_like(acc)
    for q in range(x.shape[-2]):
        np.add(x[..., q, :], y[..., q, :], out=s)
        s *= s
        acc += s
    dsc = _lanes(acc)
    dsc *= scale
    return dsc, _gap_lanes(last_pos, first_pos), _gap_lanes(last_vel, first_vel)


def _lanes8(a: np.ndarray) -> np.ndarray:
    """(n, d) -> (n, ceil(d / 8), 8) float32, zero-padded: term d in lane d % 8."""
    n, d = a.shape
    out = np.zeros((n, -(-d // 8) * 8), np.float32)
    out[:, :d] = a
    return out.reshape(n, -1, 8)


def _planes(a: np.ndarray) -> np.ndarray:
    """(n, 3M) marker coordinates -> (n, 3, ceil(M / 8), 8) float32 coordinate planes, marker k
    in lane k % 8 of group k // 8, zero-padded."""
    n, m3 = a.shape
    m = m3 // 3
    out = np.zeros((n, 3, -(-m // 8) * 8), np.float32)
    out[:, :, :m] = a.reshape(n, m, 3).transpose(0, 2, 1)
    return out.reshape(n, 3, -1, 8)


def _lanes(a: np.ndarray) -> np.ndarray:
    """((l0 + l1) + (l2 + l3)) + ((l4 + l5) + (l6 + l7)) over the last axis (float32)."""
    return ((a[..., 0] + a[..., 1]) + (a[..., 2] + a[..., 3])) + ((a[..., 4] + a[..., 5]) + (a[..., 6] + a[..., 7]))


def _gap_lanes(last: np.ndarray, first: np.ndarray) -> np.ndarray:
    """sum over markers of || first[..., k] - last[..., k] ||, float32, in the lane order of the
    kernel; last (..., 3, Mq, 8) and first (..., 3, Mq, 8) broadcast against each other."""
    acc = np.zeros(np.broadcast_shapes(last.shape[:-3], first.shape[:-3]) + (8,), np.float32)
    d = np.empty_like(acc)
    sq = np.empty_like(acc)
    for q in range(last.shape[-2]):
        np.subtract(first[..., 0, q, :], last[..., 0, q, :], out=sq)
        sq *= sq
        for c in (1, 2):
            np.subtract(first[..., c, q, :], last[..., c, q, :], out=d)
            d *= d
            sq += d
        np.sqrt(sq, out=sq)
        acc += sq
    return _lanes(acc)


def mixed_norms(a: np.ndarray, pivots: np.ndarray) -> np.ndarray:
    """sum_k || a[n, k] - pivots[q, k] || over 3-vectors k: (N, Q) float32 (a: (N, 3M), pivots (Q, 3M))."""
    out = np.empty((len(a), len(pivots)), np.float32)
    a = np.asarray(a, np.float32)
    step = 4096
    for q, p in enumerate(np.asarray(pivots, np.float32)):
        for s in range(0, len(a), step):  # float32 differences and norms, float64 sums: 1e-6 relative
            d = (a[s : s + step] - p[None]).reshape(min(step, len(a) - s), -1, 3)
            out[s : s + step, q] = np.sqrt(np.einsum("nmk,nmk->nm", d, d)).sum(-1, dtype=np.float64)
    return out


def _pivots(a: np.ndarray, b: np.ndarray, count: int) -> np.ndarray:
    """``count`` pivots for the rows of a and b: their mean, then farthest-first picks (deterministic)."""
    both = np.concatenate([a, b]) if len(b) else a
    picks = [both.mean(axis=0)]
    dist = mixed_norms(both, np.array(picks))[:, 0]
    while len(picks) < count and len(both):
        k = int(np.argmax(dist))
        picks.append(both[k].astype(np.float64))
        dist = np.minimum(dist, mixed_norms(both, both[k : k + 1])[:, 0])
    return np.array(picks, np.float32)


def pivot_distances(f: TransitionFeatures) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Distances of every node's last/first positions and last/first velocities from
    :data:`PIVOTS` pivots each ((N, PIVOTS) float32; positions and velocities have their own
    pivots: the mean, then farthest-first picks). Only bounds use them, so any pivots are
    valid; ``build-db`` stores them so a search need not compute them."""
    pos = _pivots(f.last_pos, f.first_pos, PIVOTS)
    vel = _pivots(f.last_vel, f.first_vel, PIVOTS)
    return mixed_norms(f.last_pos, pos), mixed_norms(f.first_pos, pos), mixed_norms(f.last_vel, vel), mixed_norms(f.first_vel, vel)


def boundary_states(coeffs: np.ndarray, nodes, model, fit_frames: int = 2) -> tuple[np.ndarray, ...]:
    """First/last frame positions (mm) and velocities (mm/frame) in marker space, each (N, 3M)
    float32, of the motion nodes ``nodes`` (a :class:`~facesynth.model.motiondb.Nodes`) over the
    PCA coefficients ``coeffs`` ((F, K) mm) of ``model`` (a :class:`~facesynth.model.pca.PcaModel`).

    The velocities are the slopes at the node's ends of a least-squares polynomial
    (:func:`facesynth.domain.postprocess.concatenation.end_slope_weights`: a Savitzky-Golay derivative
    taken at the end point) through the node's first/last ``fit_frames`` frames (fewer in a
    shorter node); ``fit_frames = 2`` is the one-frame finite difference. A single frame's
    difference is mostly marker noise; a fit over several frames measures the motion.
    """
    first = coeffs[nodes.frame_start].astype(np.float64)
    last = coeffs[nodes.frame_start + nodes.frame_count - 1].astype(np.float64)
    to_markers = lambda c: model.reconstruct(c).reshape(len(c), -1)  # noqa: E731
    first_pos, last_pos = to_markers(first), to_markers(last)
    first_d = np.zeros_like(first)
    last_d = np.zeros_like(last)
    lengths = np.minimum(nodes.frame_count, max(fit_frames, 2))
    for length in np.unique(lengths):
        k = np.nonzero(lengths == length)[0]
        w = end_slope_weights(int(length))  # (L,): slope at frame 0 of frames 0..L-1
        head = nodes.frame_start[k][:, None] + np.arange(length)[None, :]
        tail = (nodes.frame_start[k] + nodes.frame_count[k] - 1)[:, None] - np.arange(length)[None, :]
        first_d[k] = np.einsum("l,nlk->nk", w, coeffs[head].astype(np.float64))
        last_d[k] = -np.einsum("l,nlk->nk", w, coeffs[tail].astype(np.float64))  # time runs backwards there
    zero = to_markers(np.zeros((1, coeffs.shape[1])))
    first_vel = (to_markers(first_d) - zero).astype(np.float32)  # the linear part only: velocities
    last_vel = (to_markers(last_d) - zero).astype(np.float32)
    return first_pos.astype(np.float32), last_pos.astype(np.float32), first_vel, last_vel


#: Most row groups per pruned step (``MAX_GROUPS`` of ``kernels/pair_costs.cl``).
MAX_GROUPS = 256
#: Fewest rows per group: smaller groups bound tighter, but each costs its own bound per column.
MIN_GROUP = 16


def row_groups(rows: np.ndarray, phi: np.ndarray, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Groups of rows close together in ``points`` ((n, d) float32, e.g. each row's pivot
    distances) for the pruned scan: k-d splits at the median of the widest coordinate until a
    group has at most max(MIN_GROUP, n / MAX_GROUPS) rows. ``rows`` must be sorted by ``phi``.

    Returns ``order`` ((n,) indices into rows: the groups one after the other, numbered by
    their smallest phi, rows by phi inside; a stable sort, so ties keep their order) and
    ``start`` ((groups + 1,) int32 offsets into ``order``). Any grouping is valid: the
    kernel's bounds hold for whatever rows a group holds; close rows make them tight.
    """
    n = len(rows)
    if n == 0:
        return np.zeros(0, np.int64), np.zeros(1, np.int32)
    size = max(MIN_GROUP, -(-n // MAX_GROUPS))
    # level by level: every group larger than size is split at its median of its widest
    # coordinate, all groups of a level at once (a stable sort within groups)
    order, starts = np.arange(n), np.array([0, n])
    while True:
        lengths = np.diff(starts)
        split = lengths > size
        if not split.any():
            break
        seg = np.repeat(np.arange(len(lengths)), lengths)
        pts = points[order]
        widest = np.argmax(np.maximum.reduceat(pts, starts[:-1]) - np.minimum.reduceat(pts, starts[:-1]), axis=1)
        key = np.where(split[seg], pts[np.arange(n), widest[seg]], 0.0)
        order = order[np.lexsort((key, seg))]
        starts = np.unique(np.concatenate([starts, (starts[:-1] + lengths // 2)[split]]))
    count = len(starts) - 1
    label = np.empty(n, np.int64)
    label[order] = np.repeat(np.arange(count), np.diff(starts))
    # number the groups by their smallest phi: rows are phi-sorted, so by their first row
    first = np.full(count, n, np.int64)
    np.minimum.at(first, label, np.arange(n))
    rank = np.empty(count, np.int64)
    rank[np.argsort(first, kind="stable")] = np.arange(count)
    label = rank[label]
    order = np.argsort(label, kind="stable")
    start = np.searchsorted(label[order], np.arange(count + 1)).astype(np.int32)
    return order, start


@dataclass
class TransitionCosts:
    """TC(i, j) of Table I for settings ``s``, computed on demand (rows i = the node before).

    Usable wherever an (N, N) matrix was: ``tc[i, j]``, :meth:`column`, :meth:`values`,
    :meth:`block`, :meth:`dense`. ``opencl`` chooses the device for blocks (bit-identical).
    The pivot distances (``row_lp`` ... , (N, PIVOTS) float32) give cheap bounds:
    ``|row_lp[i, q] - col_fp[j, q]| <= PGap(i, j) <= row_lp[i, q] + col_fp[j, q]`` (triangle
    inequality of the mixed norm sum_k ||.||), likewise for velocities.
    """

    f: TransitionFeatures
    s: SynthesizeSettings
    opencl: bool = False
    _device: object = field(default=None, repr=False)

    def __post_init__(self):
        f = self.f
        self.n = len(f)
        self.pre = f.pre.astype(np.int64)
        self.pre_viseme = f.pre_viseme
        self.a1pnt = np.float32(self.s.alpha1 * self.s.pnt)
        distances = f.pivot_distances if f.pivot_distances is not None else pivot_distances(f)
        self.row_lp, self.col_fp, self.row_lv, self.col_fv = (np.asarray(d, np.float32) for d in distances)
        # float32 norms: 1e-6 relative at most, far inside the margins the bounds are used with
        xn = np.sqrt(np.einsum("ij,ij->i", f.dsc_out, f.dsc_out)).astype(np.float64)
        yn = np.sqrt(np.einsum("ij,ij->i", f.dsc_in, f.dsc_in)).astype(np.float64)
        scale = f.dsc_scale.astype(np.float64)
        # a2 DSC(i, k) <= a2 scale_k (|x_i| + |y_k|)^2 <= dsc_row_max[i] for every k
        self.dsc_row_max = self.s.alpha2 * (scale.max(initial=0.0) * xn ** 2 + 2 * xn * (scale * yn).max(initial=0.0)
                                            + (scale * yn ** 2).max(initial=0.0))

        # advantage(r, j) <= reach_row[r] + reach_col[j] (pivot 0), for the cheap first test
        a3 = self.s.alpha3
        self.reach_row = self.dsc_row_max + a3 * self.row_lp[:, 0] + self.row_lv[:, 0] + self.s.pnt
        suc = self._suc
        via = np.where(suc >= 0, a3 * self.col_fp[np.maximum(suc, 0), 0] + self.col_fv[np.maximum(suc, 0), 0], 0.0)
        self.reach_col = np.maximum(a3 * self.row_lp[:, 0].astype(np.float64) + self.row_lv[:, 0], via)
        # Absolute slack of the cheap lower bound (:meth:`lower`, the kernel's): float32 rounding of
        # the stored pivot distances and of the computed sums, far below any cost that matters.
        self.slack = 1e-4 * (a3 * (float(self.row_lp.max(initial=0)) + float(self.col_fp.max(initial=0)))
                             + float(self.row_lv.max(initial=0)) + float(self.col_fv.max(initial=0))) + 1e-3

    # --- values ----------------------------------------------------------------------------
    def block(self, rows, cols) -> np.ndarray:
        """TC[rows][:, cols], (r, c) float32."""
        rows = np.asarray(rows, np.int64).ravel()
        cols = np.asarray(cols, np.int64).ravel()
        if len(rows) == 0 or len(cols) == 0:
            return np.zeros((len(rows), len(cols)), np.float32)
        if self.opencl:
            return self.device.block(rows, cols)
        if not worth(1.6e-6 * len(rows) * len(cols)):  # NumPy's time per pair here
            return self.block_numpy(rows, cols)

        return block_numba(self, rows, cols)

    def block_numpy(self, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
        """The NumPy reference of :meth:`block`: Table I's rules on the pair terms, in the
        order of ``kernels/pair_costs.cl``."""
        out = np.empty((len(rows), len(cols)), np.float32)
        step = max(1, (1 << 21) // max(len(cols), 1))
        for a in range(0, len(rows), step):
            r = rows[a : a + step]
            out[a : a + step] = self._rules(*pair_terms(self.f, r, cols), r[:, None], cols[None, :])
        return out

    def pairs_numpy(self, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
        """TC(rows[k], cols[k]) for each k, (K,) float32: the values of :meth:`block_numpy`."""
        rows, cols = np.asarray(rows, np.int64), np.asarray(cols, np.int64)
        out = np.empty(len(rows), np.float32)
        step = 1 << 16
        for a in range(0, len(rows), step):
            r, c = rows[a : a + step], cols[a : a + step]
            out[a : a + step] = self._rules(*pair_terms(self.f, r, c, paired=True), r, c)
        return out

    def _rules(self, dsc: np.ndarray, pgap: np.ndarray, vgap: np.ndarray, r: np.ndarray, c: np.ndarray) -> np.ndarray:
        """Table I on the pair terms of nodes ``r`` before ``c`` (index arrays that broadcast to
        the terms' shape), in the float32 operations of ``kernels/pair_costs.cl``."""
        s = self.s
        rule4 = np.float32(s.alpha3) * pgap  # rule 4: (alpha3 PGap + VGap) + alpha1 PNT
        rule4 += vgap
        rule4 += self.a1pnt
        t = np.float32(s.alpha2) * dsc
        t += np.float32(s.alpha3) * pgap
        t += vgap
        t += np.float32(s.pnt) * (self.f.viseme[r] != self.pre_viseme[c])
        pre = self.pre[c]
        return np.where(pre == r, np.float32(0.0), np.where(pre < 0, rule4, t))

    def column(self, j: int, rows: np.ndarray | None = None) -> np.ndarray:
        """TC[:, j] ((N,) float32), or TC[rows, j] when ``rows`` is given."""
        rows = np.arange(self.n) if rows is None else rows
        return self.block(rows, [j])[:, 0]

    def values(self, i: int, js: np.ndarray) -> np.ndarray:
        """TC[i, js], (len(js),) float32."""
        return self.block([i], js)[0]

    def __getitem__(self, ij: tuple[int, int]) -> np.float32:
        i, j = ij
        return self.block([int(i)], [int(j)])[0, 0]

    def dense(self) -> np.ndarray:
        """The full (N, N) float32 matrix (for small databases and the dense reference DP)."""
        out = np.empty((self.n, self.n), np.float32)
        cols = np.arange(self.n)
        step = max(1, (64 << 20) // (4 * max(self.n, 1)))
        for a in range(0, self.n, step):
            out[a : a + step] = self.block(np.arange(a, min(self.n, a + step)), cols)
        return out

    def panels(self):
        """The full matrix in the panel-major layout of the dense OpenCL DP (a PanelMatrix)."""
        out = PanelMatrix(self.n)
        cols = np.arange(self.n)
        step = max(1, (32 << 20) // (4 * max(self.n, 1)))
        for a in range(0, self.n, step):
            rows = slice(a, min(self.n, a + step))
            out.set_rows(rows, self.block(np.arange(rows.start, rows.stop), cols))
        return out

    # --- bounds ----------------------------------------------------------------------------
    def upper(self, r: np.ndarray, k: np.ndarray) -> np.ndarray:
        """Upper bounds of TC(r, k) (broadcast shapes), float64, from the pivots."""
        pg = np.min(self.row_lp[r] + self.col_fp[k], axis=-1)
        vg = np.min(self.row_lv[r] + self.col_fv[k], axis=-1)
        pvc = self.s.alpha3 * pg.astype(np.float64) + vg
        tc = self.dsc_row_max[r] + pvc + self.s.pnt * (self.f.viseme[r] != self.pre_viseme[k])
        return np.where(self.pre[k] < 0, float(self.a1pnt) + pvc, np.where(self.pre[k] == r, 0.0, tc))

    def lower(self, r: np.ndarray, k: np.ndarray | int, pivots: int | None = None) -> np.ndarray:
        """Lower bounds of TC(r, k) for nodes ``r`` before ``k`` (index arrays or scalars that
        broadcast), float64: the viseme penalty (alpha1 PNT for rule 4) plus the pivot bounds
        of alpha3 PGap and VGap (the first ``pivots`` pivots: fewer is cheaper and looser),
        shrunk against rounding as in ``kernels/pair_costs.cl``; 0 for rule 1."""
        r, k = np.asarray(r), np.asarray(k)
        q = slice(0, pivots)
        lp = np.max(np.abs(self.row_lp[r, q] - self.col_fp[k, q]), axis=-1).astype(np.float64)
        lv = np.max(np.abs(self.row_lv[r, q] - self.col_fv[k, q]), axis=-1).astype(np.float64)
        pre = self.pre[k]
        pen = np.where(pre < 0, float(self.a1pnt), self.s.pnt * (self.f.viseme[r] != self.pre_viseme[k]))
        bound = (pen + self.s.alpha3 * lp + lv) * 0.9999 - self.slack
        return np.where(pre == r, 0.0, np.maximum(bound, 0.0))

    def advantage(self, r: np.ndarray, j: np.ndarray) -> np.ndarray:
        """Upper bounds of max_k (TC(r, k) - TC(j, k)) over every node k, float64 (r, j broadcast):
        how much more a continuation from r can cost than the same continuation from j.

        k = suc(j) costs 0 from j (rule 1) and at most ``upper(r, k)`` from r; k without a
        predecessor costs alpha1 PNT + PVC from both, so differs by at most alpha3 |LP_r - LP_j|
        + |LV_r - LV_j| (within the general bound); k = suc(r) costs 0 from r; every other k
        differs by at most a2 max DSC(r, .) + alpha3 |LP_r - LP_j| + |LV_r - LV_j| + PNT [viseme
        differs], the distances bounded through the pivots.
        """
        r, j = np.asarray(r), np.asarray(j)  # broadcast by the operations: a scalar r is read once
        lp = np.min(self.row_lp[r] + self.row_lp[j], axis=-1).astype(np.float64)
        lv = np.min(self.row_lv[r] + self.row_lv[j], axis=-1).astype(np.float64)
        general = self.dsc_row_max[r] + self.s.alpha3 * lp + lv + self.s.pnt * (self.f.viseme[r] != self.f.viseme[j])
        suc_j = self._suc[j]
        via_suc = np.where(suc_j >= 0, self.upper(r, np.maximum(suc_j, 0)), 0.0)
        return np.maximum(np.maximum(general, via_suc), 0.0)

    @property
    def _suc(self) -> np.ndarray:
        if not hasattr(self, "_suc_cache"):
            suc = -np.ones(self.n, np.int64)
            has = self.pre >= 0
            suc[self.pre[has]] = np.nonzero(has)[0]
            self._suc_cache = suc
        return self._suc_cache

    @property
    def layout(self) -> DeviceLayout:
        """The features' padded, lane-ordered copies (:func:`layout`, made once)."""
        return layout(self.f)

    @property
    def device(self):
        """The OpenCL side (features uploaded once)."""
        if self._device is None:
            self._device = OpenCLPairs(self)
        return self._device


class OpenCLPairs:
    """The features on the OpenCL device, and the kernels of ``kernels/pair_costs.cl``.

    On a CPU device the page-aligned features are used in place (:meth:`upload`), everything
    else is copied into device-owned buffers (COPY_HOST_PTR): a misaligned or short-lived host
    array is never handed over.
    """

    def __init__(self, tc: TransitionCosts):
        import pyopencl as cl

        self.cl, self.ctx, self.queue, self.tc = cl, context(), queue(), tc
        device = self.ctx.devices[0]
        # the alignment a host array needs to be used in place, or 0: only a CPU device reads
        # host memory as fast as its own
        self.in_place = max(128, device.mem_base_addr_align // 8) if device.type & cl.device_type.CPU else 0
        f = tc.f
        dims8, markers = -(-f.dsc_out.shape[1] // 8), f.first_pos.shape[1] // 3
        defines = dict(DIMS8=dims8, MQ=-(-markers // 8), PIVOTS=tc.row_lp.shape[1])
        defines["MAX_GROUPS"] = MAX_GROUPS
        self.block_kernel = kernel("pair_costs", "tc_block", **defines)
        self.pruned_kernel = kernel("pair_costs", "pruned_columns", **defines)
        up = self.upload
        # The lane layout of DeviceLayout, made on the device: no host copy of the features.
        planes = kernel("pair_costs", "to_planes", **defines)

        sources = []  # held until the layout kernels have run: a buffer may use its array in place

        def as_planes(a):
            src = up(a, kept=True)
            sources.append(src)
            out = cl.Buffer(self.ctx, cl.mem_flags.READ_WRITE, max(4, 4 * len(a) * 3 * defines["MQ"] * 8))
            if len(a):
                planes(self.queue, (-(-len(a) // 64) * 64,), (64,), src, np.int32(len(a)), np.int32(markers), out)
            return out

        def as_lanes(a):
            if a.shape[1] % 8 == 0:
                return up(a, kept=True)
            padded = np.zeros((len(a), dims8 * 8), np.float32)
            padded[:, : a.shape[1]] = a
            return up(padded)

        self.features = [as_lanes(f.dsc_out), as_lanes(f.dsc_in), up(f.dsc_scale), as_planes(f.last_pos),
                         as_planes(f.first_pos), as_planes(f.last_vel), as_planes(f.first_vel),
                         up(f.viseme.astype(np.int32)), up(tc.pre.astype(np.int32)),
                         up(tc.pre_viseme.astype(np.int32)),
                         np.float32(tc.s.alpha2), np.float32(tc.s.alpha3), np.float32(tc.s.pnt), tc.a1pnt]
        self.queue.finish()
        self.slack = tc.slack

    def upload(self, a: np.ndarray, kept: bool = False):
        """A read-only device buffer of ``a`` (float32 or int32, C order), a copy; with ``kept``
        (the buffer outlives every kernel that reads it, and the buffer holds its array) on a
        CPU device ``a`` itself when it starts on the device's base alignment (USE_HOST_PTR:
        no copy of hundreds of MB at 100,000 nodes). A buffer dropped while a kernel still
        reads it must be a copy: the array it used in place would be freed under the kernel."""
        a = np.ascontiguousarray(a, np.int32 if a.dtype.kind in "iu" else np.float32)
        mf = self.cl.mem_flags
        if a.nbytes == 0:
            a = np.zeros(1, a.dtype)
        if kept and self.in_place and a.ctypes.data % self.in_place == 0:
            return self.cl.Buffer(self.ctx, mf.READ_ONLY | mf.USE_HOST_PTR, hostbuf=a)
        return self.cl.Buffer(self.ctx, mf.READ_ONLY | mf.COPY_HOST_PTR, hostbuf=a)

    def block(self, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
        """TC[rows][:, cols] on the device, (r, c) float32."""
        cl = self.cl
        out = np.empty((len(rows), len(cols)), np.float32)
        step = max(1, (64 << 20) // (4 * len(cols)))
        cols_buf = self.upload(cols)
        for a in range(0, len(rows), step):
            r = rows[a : a + step]
            buf = cl.Buffer(self.ctx, cl.mem_flags.WRITE_ONLY, 4 * len(r) * len(cols))
            local = (LOCAL_SIZE, 1)
            size = (-(-len(cols) // local[0]) * local[0], len(r))
            self.block_kernel(self.queue, size, local, *self.features, self.upload(r), cols_buf,
                              np.int32(len(r)), np.int32(len(cols)), buf)
            cl.enqueue_copy(self.queue, out[a : a + len(r)], buf)
        return out

    def _rows(self, rows: np.ndarray, phi: np.ndarray, backward: bool) -> list[np.ndarray]:
        """What ``pruned_columns`` reads of the rows (its comment), grouped by :func:`row_groups`:
        rows, phi, visemes, predecessors, pivot distances (positions, velocities), group
        starts, pivot ranges (lo/hi of positions, lo/hi of velocities) and viseme sets.
        The same rows come twice per step (probes, then the other columns): made once."""
        key = (backward, len(rows), rows.tobytes(), phi.tobytes())
        if getattr(self, "_rows_key", None) == key:
            return self._rows_data  # type: ignore[has-type]
        tc = self.tc
        rows = np.asarray(rows, np.int64)
        if backward:
            row_p, row_v, row_vis, row_pre = tc.col_fp[rows], tc.col_fv[rows], tc.pre_viseme[rows], tc.pre[rows]
        else:
            row_p, row_v, row_vis, row_pre = tc.row_lp[rows], tc.row_lv[rows], tc.f.viseme[rows], tc.pre[rows]
        order, start = row_groups(rows, phi, np.concatenate([tc.s.alpha3 * row_p, row_v], axis=1))
        rows, phi, row_p, row_v, row_vis, row_pre = (a[order] for a in (rows, phi, row_p, row_v, row_vis, row_pre))
        heads = start[:-1]
        bits = np.where((row_vis >= 0) & (row_vis < 32), np.left_shift(1, np.clip(row_vis, 0, 31)).astype(np.uint32),
                        np.where(row_vis >= 32, np.uint32(0xFFFFFFFF), np.uint32(0)))
        if len(heads):
            lo_p, hi_p = np.minimum.reduceat(row_p, heads), np.maximum.reduceat(row_p, heads)
            lo_v, hi_v = np.minimum.reduceat(row_v, heads), np.maximum.reduceat(row_v, heads)
            group_vis = np.bitwise_or.reduceat(bits, heads).astype(np.uint32)
        else:
            lo_p = hi_p = lo_v = hi_v = np.zeros((0, row_p.shape[1]), np.float32)
            group_vis = np.zeros(0, np.uint32)
        f32 = lambda a: np.ascontiguousarray(a, np.float32)  # noqa: E731
        self._rows_key = key
        self._rows_data = [rows.astype(np.int32), f32(phi), row_vis.astype(np.int32), row_pre.astype(np.int32),
                           f32(row_p), f32(row_v), start, f32(lo_p), f32(hi_p), f32(lo_v), f32(hi_v), group_vis]
        return self._rows_data

    def _cols(self, cols: np.ndarray, init: np.ndarray, backward: bool) -> list[np.ndarray]:
        """What ``pruned_columns`` reads of the columns: cols, init, pivot distances."""
        tc = self.tc
        cols = np.asarray(cols, np.int64)
        col_p, col_v = (tc.row_lp[cols], tc.row_lv[cols]) if backward else (tc.col_fp[cols], tc.col_fv[cols])
        return [cols.astype(np.int32), np.ascontiguousarray(init, np.float32),
                np.ascontiguousarray(col_p, np.float32), np.ascontiguousarray(col_v, np.float32)]

    def _buffer(self, name: str, nbytes: int):
        """A device buffer ``name`` of at least ``nbytes``, reused between launches (grown by
        doubling), and whether it is new."""
        have = getattr(self, "_buffers", {})
        self._buffers = have
        if name in have and have[name].size >= nbytes:
            return have[name], False
        size = max(nbytes, 2 * have[name].size if name in have else 1 << 16)
        have[name] = self.cl.Buffer(self.ctx, self.cl.mem_flags.READ_WRITE, size)
        return have[name], True

    def column_minima(self, rows: np.ndarray, phi: np.ndarray, cols: np.ndarray, init: np.ndarray,
                      backward: bool = False) -> tuple[np.ndarray, int]:
        """min(init[c], min_r phi[r] + TC(rows[r], cols[c])) for rows sorted by ``phi`` (float32),
        or with ``backward`` TC(cols[c], rows[r]); pairs of Table I rules 1 and 4 are left to
        ``init``. Returns the (c,) float32 minima and the number of pair costs computed."""
        cl = self.cl
        n_cols = len(cols)
        if n_cols == 0:
            return np.zeros(0, np.float32), 0
        parts = self._rows(rows, phi, backward) + self._cols(cols, init, backward)
        step = pack_words(parts, [len(parts[6]) - 1, n_cols, int(bool(backward))])
        step_buf, new_step = self._buffer("step", step.nbytes)
        out_buf, new_out = self._buffer("out", 8 * n_cols)
        kernel = self.pruned_kernel
        if new_step or new_out:  # the arguments stay the same between launches otherwise
            kernel.set_args(*self.features, np.float32(self.slack), step_buf, out_buf)
        cl.enqueue_copy(self.queue, step_buf, step, is_blocking=False)
        local = LOCAL_SIZE
        cl.enqueue_nd_range_kernel(self.queue, kernel, (-(-n_cols // local) * local,), (local,))
        out = np.empty(2 * n_cols, np.uint32)
        cl.enqueue_copy(self.queue, out, out_buf, is_blocking=True)
        return out[:n_cols].view(np.float32), int(out[n_cols:].astype(np.int64).sum())


def pack_words(parts: list[np.ndarray], scalars: list[int]) -> np.ndarray:
    """One uint32 buffer holding the 4-byte arrays ``parts`` (float32, int32 or uint32, any
    shape, C order) and ``scalars``: the word offset of each part, then the scalars, then
    the parts, each starting on a 32-byte boundary (the layout ``pruned_columns`` reads)."""
    head = -(-(len(parts) + len(scalars)) // 8) * 8
    offsets, at = [], head
    for a in parts:
        offsets.append(at)
        at += -(-max(a.size, 1) // 8) * 8
    out = np.zeros(at, np.uint32)
    out[: len(parts)] = offsets
    out[len(parts) : len(parts) + len(scalars)] = scalars
    for start, a in zip(offsets, parts):
        if a.dtype.itemsize != 4:
            raise TypeError(f"pack_words: parts must have 4-byte elements, not {a.dtype}")
        out[start : start + a.size] = np.ascontiguousarray(a).reshape(-1).view(np.uint32)
    return out


class PairTerms:
    """The weight-free pair terms of every ordered pair, kept for a search that tries many
    weights on one database (``tune``): DSC, PGap and VGap as (N, N) float32 each (row i = the
    node before), 12 N^2 bytes. :meth:`costs` assembles Table I for settings ``s`` from them
    with :func:`facesynth.domain.search.costs.transition_matrix`, the same float32 operations as
    :meth:`TransitionCosts.block_numpy`, so the matrix is bit-identical to the on-demand one."""

    def __init__(self, f: TransitionFeatures, like: "PairTerms | None" = None):
        """The tables of ``f``; with ``like`` (the tables of features that differ from ``f`` in
        the boundary velocities only) DSC and PGap are shared and only VGap is computed."""
        n = len(f)
        self.f = f
        cols = np.arange(n)
        step = max(1, (1 << 21) // max(n, 1))
        if like is not None:
            self.dsc, self.pgap = like.dsc, like.pgap  # type: ignore[has-type]
            self.vgap = np.empty((n, n), np.float32)
            lay = layout(f)
            for a in range(0, n, step):
                rows = np.arange(a, min(n, a + step))
                self.vgap[rows] = _gap_lanes(lay.last_vel[rows][:, None], lay.first_vel[cols][None])
            return
        self.dsc, self.pgap, self.vgap = (np.empty((n, n), np.float32) for _ in range(3))
        for a in range(0, n, step):
            rows = np.arange(a, min(n, a + step))
            self.dsc[rows], self.pgap[rows], self.vgap[rows] = pair_terms(f, rows, cols)

    @staticmethod
    def bytes_for(n: int) -> int:
        """Memory the three (n, n) float32 tables take."""
        return 12 * n * n

    def costs(self, s: SynthesizeSettings) -> "DenseCosts":
        """TC of Table I for settings ``s`` as a :class:`DenseCosts`."""
        return DenseCosts(transition_matrix(self.dsc, self.pgap, self.vgap, self.f.viseme, self.f.pre.astype(np.int64), s))


@dataclass
class DenseCosts:
    """A full (N, N) float32 TC matrix usable where a :class:`TransitionCosts` is (NumPy only):
    ``tc[i, j]``, :meth:`block`, :meth:`column`, :meth:`values`, :meth:`dense`."""

    matrix: np.ndarray
    opencl: bool = False

    def __post_init__(self):
        self.n = len(self.matrix)

    def block(self, rows, cols) -> np.ndarray:
        """TC[rows][:, cols], (r, c) float32."""
        return self.matrix[np.ix_(np.asarray(rows, np.int64).ravel(), np.asarray(cols, np.int64).ravel())]

    def column(self, j: int, rows: np.ndarray | None = None) -> np.ndarray:
        """TC[:, j], or TC[rows, j]."""
        return self.matrix[:, j] if rows is None else self.matrix[rows, j]

    def values(self, i: int, js: np.ndarray) -> np.ndarray:
        """TC[i, js]."""
        return self.matrix[i, js]

    def __getitem__(self, ij: tuple[int, int]) -> np.float32:
        return self.matrix[int(ij[0]), int(ij[1])]

    def dense(self) -> np.ndarray:
        """The (N, N) matrix itself."""
        return self.matrix


def node_features(db: MotionDatabase) -> TransitionFeatures:
    """The per-node features ``db`` stores, with its nodes' visemes and captured predecessors."""
    return db.transition_features()


def transition_costs(db: MotionDatabase, settings: SynthesizeSettings, opencl: bool | None = None) -> TransitionCosts:
    """Table I's costs of ``db`` for ``settings``, computed on demand; on OpenCL when ``opencl``
    (default: ``settings.use_opencl`` and a device that builds). ``.dense()`` is the full (N, N)
    float32 matrix (N^2 memory: small databases and the dense reference DP), ``.panels()`` the
    same in the panel-major layout of the dense OpenCL DP."""
    if opencl is None:
        opencl = use_opencl(settings.use_opencl)
    return TransitionCosts(node_features(db), settings, opencl)
