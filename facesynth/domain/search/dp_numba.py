"""Numba versions of the NumPy dynamic programs of ``facesynth/domain/search/dp.py`` (paper Algorithm 1):
the same float32 additions, so the same phi, cost and path, bit for bit (check.py).

Drop-in replacements:

* :func:`dp_numba` for ``dp.dp_numpy`` (same signature, a ``dp.DpResult``);
* :func:`dp_bounded_numba` for ``dp.dp_bounded`` (same signature and results);
* :func:`backtrack_dense` for ``dp.backtrack(phi, lambda j: tc[:, j])`` on a dense matrix.

Why identical: ``phi_t(j) = min_i (phi_{t-1}(i) + TC(i, j)) + obs_t(j)``; each sum is one float32
addition, and a minimum does not depend on the order it is taken in, except for NaN, which
NumPy's ``min`` propagates: so does the select below (once NaN, the running minimum stays NaN).
The argmin of the backtracking takes the first NaN if any, else the lowest index of the minimum,
as ``np.argmin`` does.

The minimum runs over rows (i outer, j inner), streaming TC row by row into (N,) running
minima: one pass over TC per step, no temporaries (NumPy builds a (N, 512) sum per block), and
a loop LLVM vectorizes. Serial on purpose: ``parallel=True`` (column blocks over numba's
threads) was slower on the 2-core host (0.40 s against 0.017 s for 29 steps at N = 1,676), as
the steps are short and the cores are shared with pytest-xdist's other worker.
"""

from __future__ import annotations

import numpy as np

from facesynth.base.jit import jit

from .dp import DpResult


@jit()
def _min_plus_step(prev, tc, obs_t, out, rows, acc, exact_nan):
    """out[j] = min over i in rows of (prev[i] + tc[i, j]), plus obs_t[j] (float32). Rows outer,
    columns inner: TC streams once, the running minima ``acc`` (N,) stay in cache, and the
    inner loop vectorizes. With ``exact_nan`` (a NaN in TC or in prev) NaN propagates as in
    np.min (a slower select that does not vectorize)."""
    n = tc.shape[1]
    for j in range(n):
        acc[j] = np.inf
    if exact_nan:
        for k in range(rows.shape[0]):
            i = rows[k]
            p = prev[i]
            for j in range(n):
                v = p + tc[i, j]
                a = acc[j]
                acc[j] = v if (v < a or v != v) else a  # NaN wins and stays
    else:
        for k in range(rows.shape[0]):
            i = rows[k]
            p = prev[i]
            for j in range(n):
                v = p + tc[i, j]
                if v < acc[j]:
                    acc[j] = v
    for j in range(n):
        out[j] = acc[j] + obs_t[j]


@jit()
def _argmin(v):
    """np.argmin of a float32 vector: the first NaN, else the first minimum."""
    best = 0
    for i in range(v.shape[0]):
        if v[i] != v[i]:
            return i
        if v[i] < v[best]:
            best = i
    return best


@jit()
def _backtrack(phi, tc, path):
    t_count = phi.shape[0]
    n = phi.shape[1]
    path[t_count - 1] = _argmin(phi[t_count - 1])
    col = np.empty(n, np.float32)
    for t in range(t_count - 1, 0, -1):
        j = path[t]
        for i in range(n):
            col[i] = phi[t - 1, i] + tc[i, j]
        path[t - 1] = _argmin(col)


def backtrack_dense(phi: np.ndarray, tc: np.ndarray) -> np.ndarray:
    """``dp.backtrack(phi, lambda j: tc[:, j])`` for a dense (N, N) float32 ``tc``: (T,) int64."""
    path = np.empty(len(phi), np.int64)
    _backtrack(np.ascontiguousarray(phi, np.float32), np.ascontiguousarray(tc, np.float32), path)
    return path


def dp_numba(tc: np.ndarray, obs: np.ndarray, column_block: int = 512) -> DpResult:
    """``dp.dp_numpy``: tc (N, N) float32, obs (T, N) float32 -> DpResult (cost, path, phi).
    ``column_block`` is accepted for the signature; the result does not depend on it."""
    tc = np.ascontiguousarray(tc, np.float32)
    obs = np.ascontiguousarray(obs, np.float32)
    t_count, n = obs.shape
    phi = np.empty((t_count, n), np.float32)
    phi[0] = obs[0]
    rows = np.arange(n, dtype=np.int64)
    acc = np.empty(n, np.float32)
    tc_nan = bool(np.isnan(tc).any())
    for t in range(1, t_count):
        _min_plus_step(phi[t - 1], tc, obs[t], phi[t], rows, acc, tc_nan or bool(np.isnan(phi[t - 1]).any()))
    path = backtrack_dense(phi, tc)
    return DpResult(float(phi[-1, path[-1]]), path, phi)


def dp_bounded_numba(tc: np.ndarray, obs: np.ndarray, upper: float) -> tuple[DpResult, np.ndarray]:
    """``dp.dp_bounded``: the DP with states that cannot beat ``upper`` skipped; the same
    result and active fractions."""
    tc = np.ascontiguousarray(tc, np.float32)
    obs = np.ascontiguousarray(obs, np.float32)
    t_count, n = obs.shape
    remaining = np.concatenate([np.cumsum(obs.min(axis=1)[::-1], dtype=np.float64)[::-1][1:], [0.0]])
    phi = np.full((t_count, n), np.inf, np.float32)
    phi[0] = obs[0]
    active_fraction = np.ones(t_count)
    acc = np.empty(n, np.float32)
    tc_nan = bool(np.isnan(tc).any())
    for t in range(1, t_count):
        active = np.nonzero(phi[t - 1].astype(np.float64) + remaining[t - 1] <= upper)[0]
        active_fraction[t - 1] = len(active) / n
        if len(active) == 0:  # NumPy's min of an empty array raises
            raise ValueError("zero-size array to reduction operation minimum which has no identity")
        _min_plus_step(phi[t - 1], tc, obs[t], phi[t], active.astype(np.int64), acc,
                       tc_nan or bool(np.isnan(phi[t - 1][active]).any()))
    path = backtrack_dense(phi, tc)
    return DpResult(float(phi[-1, path[-1]]), path, phi), active_fraction
