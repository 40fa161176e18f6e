"""Numba versions of the NumPy pair costs of ``facesynth/domain/search/pairs.py`` and of the NumPy scan
of the exact pruned DP (``facesynth/domain/search/pruned.py``): Table I's transition costs computed
with the float32 operations of ``kernels/pair_costs.cl`` in the same order (eight lanes, then
the fixed tree), so bit-identical to ``TransitionCosts.block_numpy`` / ``pairs_numpy``.

Drop-in replacements (``tc`` is a ``pairs.TransitionCosts``):

* :func:`block_numba(tc, rows, cols)` for ``tc.block_numpy(rows, cols)``: (r, c) float32;
* :func:`pairs_numba(tc, rows, cols)` for ``tc.pairs_numpy(rows, cols)``: (K,) float32;
* :func:`dense_numba(tc)` for ``tc.dense()`` without a device: (N, N) float32;
* :func:`column_minima_numba(tc, rows, phi, cols, init, backward=False)` for
  ``pruned._column_minima_numpy``: the same (c,) float32 minima; the second value (pair
  costs computed) is this scan's count, smaller than NumPy's (it only feeds the statistics).

The scan per column (one column per ``prange`` iteration: a column's minimum does not depend on
the thread count): rows come sorted by phi; it stops at the first row with phi >= best
(TC >= 0), skips the rule-1 pair (its value is in ``init``) and any row whose pivot lower bound
(``row_bound`` of the kernel: viseme penalty plus alpha3 and 1 times the largest pivot-distance
gaps, shrunk by 1e-4 relative and the slack absolute) already reaches best, and computes the
others exactly (abandoning a pair as the kernel's ``pair_tc_below`` does once a partial sum's
bound reaches best). Every value it keeps is an exact pair cost plus phi, so the minimum is
the dense one, as for the NumPy and OpenCL scans.
"""

from __future__ import annotations

import numpy as np

from facesynth.base.jit import jit

# -- one pair ---------------------------------------------------------------------------------


@jit(inline="always")
def _lanes(a):
    return ((a[0] + a[1]) + (a[2] + a[3])) + ((a[4] + a[5]) + (a[6] + a[7]))


@jit()
def _gap(last, first, i, j, acc):
    """sum over markers of || first[j, :, k] - last[i, :, k] || in the lanes of ``_gap_lanes``."""
    for l in range(8):
        acc[l] = np.float32(0.0)
    for q in range(last.shape[2]):
        for l in range(8):
            dx = first[j, 0, q, l] - last[i, 0, q, l]
            dy = first[j, 1, q, l] - last[i, 1, q, l]
            dz = first[j, 2, q, l] - last[i, 2, q, l]
            acc[l] = acc[l] + np.sqrt(dx * dx + dy * dy + dz * dz)
    return _lanes(acc)


@jit()
def _dsc(x, y, scale, i, j, acc):
    for l in range(8):
        acc[l] = np.float32(0.0)
    for q in range(x.shape[1]):
        for l in range(8):
            s = x[i, q, l] + y[j, q, l]
            acc[l] = acc[l] + s * s
    return _lanes(acc) * scale[j]


@jit()
def _pair_tc(i, j, x, y, scale, last_pos, first_pos, last_vel, first_vel, vis, pre, pre_vis, a2, a3, pnt, a1pnt, acc):
    """TC(i, j) of Table I: ``_rules`` of the reference (and ``pair_tc`` of the kernel)."""
    p = pre[j]
    if p == i:
        return np.float32(0.0)
    pg = _gap(last_pos, first_pos, i, j, acc)
    vg = _gap(last_vel, first_vel, i, j, acc)
    if p < 0:  # rule 4: (alpha3 PGap + VGap) + alpha1 PNT
        r4 = a3 * pg
        r4 = r4 + vg
        return r4 + a1pnt
    dsc = _dsc(x, y, scale, i, j, acc)
    t = a2 * dsc
    t = t + a3 * pg
    t = t + vg
    t = t + (pnt if vis[i] != pre_vis[j] else np.float32(0.0))
    return t


@jit()
def _pair_tc_below(i, j, limit, slack, x, y, scale, last_pos, first_pos, last_vel, first_vel, vis, pre, pre_vis,
                   a2, a3, pnt, a1pnt, acc):
    """``pair_tc_below`` of the kernel for a rule 2/3/4 pair: +inf once a lower bound of TC from
    partial sums reaches ``limit``, else exactly ``_pair_tc``."""
    shrink = np.float32(0.9999)
    rule4 = pre[j] < 0
    pen = a1pnt if rule4 else (pnt if vis[i] != pre_vis[j] else np.float32(0.0))
    mq = last_pos.shape[2]
    for l in range(8):
        acc[l] = np.float32(0.0)
    for q in range(mq):
        for l in range(8):
            dx = first_pos[j, 0, q, l] - last_pos[i, 0, q, l]
            dy = first_pos[j, 1, q, l] - last_pos[i, 1, q, l]
            dz = first_pos[j, 2, q, l] - last_pos[i, 2, q, l]
            acc[l] = acc[l] + np.sqrt(dx * dx + dy * dy + dz * dz)
        if (q & 3) == 3 and (pen + a3 * _lanes(acc)) * shrink - slack >= limit:
            return np.float32(np.inf)
    pg = _lanes(acc)
    known = pen + a3 * pg
    for l in range(8):
        acc[l] = np.float32(0.0)
    for q in range(mq):
        for l in range(8):
            dx = first_vel[j, 0, q, l] - last_vel[i, 0, q, l]
            dy = first_vel[j, 1, q, l] - last_vel[i, 1, q, l]
            dz = first_vel[j, 2, q, l] - last_vel[i, 2, q, l]
            acc[l] = acc[l] + np.sqrt(dx * dx + dy * dy + dz * dz)
        if (q & 3) == 3 and (known + _lanes(acc)) * shrink - slack >= limit:
            return np.float32(np.inf)
    vg = _lanes(acc)
    if (pen + a3 * pg + vg) * shrink - slack >= limit:
        return np.float32(np.inf)
    if rule4:
        r4 = a3 * pg
        r4 = r4 + vg
        return r4 + a1pnt
    dsc = _dsc(x, y, scale, i, j, acc)
    t = a2 * dsc
    t = t + a3 * pg
    t = t + vg
    t = t + pen
    return t


# -- blocks -----------------------------------------------------------------------------------


@jit()
def _block(rows, cols, paired, out, x, y, scale, last_pos, first_pos, last_vel, first_vel, vis, pre, pre_vis,
           a2, a3, pnt, a1pnt):
    """out (r, c) = TC(rows[a], cols[b]); with ``paired`` out (K, 1) = TC(rows[k], cols[k])."""
    if paired:
        for k in range(rows.shape[0]):
            acc = np.empty(8, np.float32)
            out[k, 0] = _pair_tc(rows[k], cols[k], x, y, scale, last_pos, first_pos, last_vel, first_vel, vis, pre,
                                 pre_vis, a2, a3, pnt, a1pnt, acc)
        return
    for a in range(rows.shape[0]):
        acc = np.empty(8, np.float32)
        for b in range(cols.shape[0]):
            out[a, b] = _pair_tc(rows[a], cols[b], x, y, scale, last_pos, first_pos, last_vel, first_vel, vis, pre,
                                 pre_vis, a2, a3, pnt, a1pnt, acc)


def _features(tc):
    """The arrays and float32 weights the kernels read, made once per TransitionCosts."""
    cached = getattr(tc, "_numba_features", None)
    if cached is not None:
        return cached
    lay = tc.layout
    s = tc.s
    c = np.ascontiguousarray
    feats = (c(lay.x), c(lay.y), c(tc.f.dsc_scale, np.float32), c(lay.last_pos), c(lay.first_pos), c(lay.last_vel),
             c(lay.first_vel), c(tc.f.viseme, np.int64), c(tc.pre, np.int64), c(tc.pre_viseme, np.int64),
             np.float32(s.alpha2), np.float32(s.alpha3), np.float32(s.pnt), np.float32(tc.a1pnt))
    tc._numba_features = feats
    return feats


def block_numba(tc, rows, cols) -> np.ndarray:
    """``tc.block_numpy(rows, cols)``: TC[rows][:, cols], (r, c) float32."""
    rows = np.ascontiguousarray(np.asarray(rows, np.int64).ravel())
    cols = np.ascontiguousarray(np.asarray(cols, np.int64).ravel())
    out = np.empty((len(rows), len(cols)), np.float32)
    if out.size:
        _block(rows, cols, False, out, *_features(tc))
    return out


def pairs_numba(tc, rows, cols) -> np.ndarray:
    """``tc.pairs_numpy(rows, cols)``: TC(rows[k], cols[k]), (K,) float32."""
    rows = np.ascontiguousarray(np.asarray(rows, np.int64).ravel())
    cols = np.ascontiguousarray(np.asarray(cols, np.int64).ravel())
    out = np.empty((len(rows), 1), np.float32)
    if len(rows):
        _block(rows, cols, True, out, *_features(tc))
    return out[:, 0]


def dense_numba(tc) -> np.ndarray:
    """``tc.dense()`` on NumPy: the full (N, N) float32 matrix."""
    n = tc.n
    return block_numba(tc, np.arange(n), np.arange(n))


# -- the pruned DP's column minima --------------------------------------------------------------


@jit(inline="always")
def _row_bound(rp, rv, rvis, mq_p, mq_v, pj, me_vis, a3, pnt, a1pnt, slack):
    lp = np.float32(0.0)
    lv = np.float32(0.0)
    for q in range(rp.shape[0]):
        dp = rp[q] - mq_p[q]
        dv = rv[q] - mq_v[q]
        ap = -dp if dp < np.float32(0.0) else dp
        av = -dv if dv < np.float32(0.0) else dv
        lp = ap if ap > lp else lp
        lv = av if av > lv else lv
    pen = a1pnt if pj < 0 else (pnt if rvis != me_vis else np.float32(0.0))
    return (pen + a3 * lp + lv) * np.float32(0.9999) - slack


@jit()
def _column_minima(rows, phi, cols, init, backward, row_p, row_v, row_vis, row_pre, col_p, col_v, slack, best_out,
                   evals_out, x, y, scale, last_pos, first_pos, last_vel, first_vel, vis, pre, pre_vis,
                   a2, a3, pnt, a1pnt):
    n_rows = rows.shape[0]
    for c in range(cols.shape[0]):
        acc = np.empty(8, np.float32)
        me = cols[c]
        me_pre = pre[me]
        me_vis = vis[me] if backward else pre_vis[me]
        mq_p = col_p[c]
        mq_v = col_v[c]
        best = init[c]
        evals = 0
        # seed: the row with the smallest phi plus its own bound, computed first
        seed = -1
        seed_lb = best
        for r in range(n_rows):
            p = phi[r]
            if p >= seed_lb:
                break
            i = me if backward else rows[r]
            pj = row_pre[r] if backward else me_pre
            if pj == i:
                continue
            lb = p + _row_bound(row_p[r], row_v[r], row_vis[r], mq_p, mq_v, pj, me_vis, a3, pnt, a1pnt, slack)
            if lb < seed_lb:
                seed_lb = lb
                seed = r
        if seed >= 0:
            i = me if backward else rows[seed]
            j = rows[seed] if backward else me
            p = phi[seed]
            v = p + _pair_tc_below(i, j, (best - p) + best * np.float32(2.4e-7), slack, x, y, scale, last_pos,
                                   first_pos, last_vel, first_vel, vis, pre, pre_vis, a2, a3, pnt, a1pnt, acc)
            best = v if v < best else best
            evals += 1
        for r in range(n_rows):
            p = phi[r]
            if p >= best:
                break
            i = me if backward else rows[r]
            pj = row_pre[r] if backward else me_pre
            if pj == i:
                continue  # rule 1 is in init
            if p + _row_bound(row_p[r], row_v[r], row_vis[r], mq_p, mq_v, pj, me_vis, a3, pnt, a1pnt, slack) >= best:
                continue
            j = rows[r] if backward else me
            v = p + _pair_tc_below(i, j, (best - p) + best * np.float32(2.4e-7), slack, x, y, scale, last_pos,
                                   first_pos, last_vel, first_vel, vis, pre, pre_vis, a2, a3, pnt, a1pnt, acc)
            best = v if v < best else best
            evals += 1
        best_out[c] = best
        evals_out[c] = evals


def column_minima_numba(tc, rows: np.ndarray, phi: np.ndarray, cols: np.ndarray, init: np.ndarray,
                        backward: bool = False) -> tuple[np.ndarray, int]:
    """``pruned._column_minima_numpy``: min(init[c], min_r phi[r] + TC(rows[r], cols[c])) (with
    ``backward`` TC(cols[c], rows[r])) for rows sorted by ``phi`` (float32); rule-1 pairs are in
    ``init``. Returns the (c,) float32 minima and the number of pair costs computed."""
    best = np.asarray(init, np.float32).copy()
    if len(rows) == 0 or len(cols) == 0:
        return best, 0
    rows = np.ascontiguousarray(rows, np.int64)
    cols = np.ascontiguousarray(cols, np.int64)
    phi = np.ascontiguousarray(phi, np.float32)
    if backward:
        row_p, row_v, row_vis, row_pre = tc.col_fp[rows], tc.col_fv[rows], tc.pre_viseme[rows], tc.pre[rows]
        col_p, col_v = tc.row_lp[cols], tc.row_lv[cols]
    else:
        row_p, row_v, row_vis, row_pre = tc.row_lp[rows], tc.row_lv[rows], tc.f.viseme[rows], tc.pre[rows]
        col_p, col_v = tc.col_fp[cols], tc.col_fv[cols]
    c = np.ascontiguousarray
    evals = np.zeros(len(cols), np.int64)
    _column_minima(rows, phi, cols, best.copy(), bool(backward), c(row_p, np.float32), c(row_v, np.float32),
                   c(row_vis, np.int64), c(row_pre, np.int64), c(col_p, np.float32), c(col_v, np.float32),
                   np.float32(tc.slack), best, evals, *_features(tc))
    return best, int(evals.sum())
