"""The exact pruned dynamic program of paper Algorithm 1: the same path and cost as the dense
DP (:func:`facesynth.domain.search.dp.dp_numpy`), with pair costs computed only where bounds cannot
rule them out and no (N, N) matrix anywhere.

Per step t, with ``phi_{t-1}`` exact on the live states (dead states are +inf):

1. **Rule 1 for free.** A node whose captured predecessor is live starts from
   ``phi_{t-1}(pre(j))`` (rule 1, cost 0). A node without a captured predecessor (rule 4:
   alpha1 PNT + PVC) is searched like any other, its scan bounded below by alpha1 PNT.
2. **Dominance before evaluation.** Every cost term is non-negative, so
   ``phi_t(j) >= min phi_{t-1} + obs_t(j)``; a state j is useless if some state r has
   ``phi_t(r) + TC(r, k) < phi_t(j) + TC(j, k)`` for every next node k, i.e. if
   ``phi_t(j) > phi_t(r) + max_k (TC(r, k) - TC(j, k))``. That maximum is bounded from the
   boundary features (:meth:`TransitionCosts.advantage`: triangle inequality of the PGap/VGap
   norm through pivots, the viseme penalty, the captured successor of j) and is 0 at the last
   step. The references r are the few states with the smallest upper bounds (the rule 1/4
   values, and the exact values of a few probe columns evaluated first: those with the
   smallest lower bounds). Before evaluation only the cheap form of the test runs
   (``advantage(r, j) <= reach_row[r] + reach_col[j]``), the full one at the last step.
   The observation cost's large constants (Table II) put the nodes of other phones far
   above, so they die here without a single pair cost.
3. **Sorted rows.** For each surviving column, the live rows are scanned by increasing
   ``phi_{t-1}``; the scan stops at the first row with ``phi_{t-1}(i) >= best`` (TC >= 0) and
   skips rows whose cheap lower bound (viseme penalty + pivot bounds) already reaches ``best``.
   The minimum is the same float32 value the dense min over all rows gives (rounding is
   monotone), so ``phi_t(j)`` is exact.
4. **Dominance after evaluation**, as in 2 with exact values, shrinks the next step's rows.

Every kill is strict by a margin of 1e-4 relative plus 1e-3 absolute, far above float32
rounding, so a state that ties on the dense DP's optimal paths is never removed; ties then
resolve as in the dense DP (lowest index, in the final argmin and in the backtracking, which
recomputes TC along the path over the rows that can attain the minimum, on the host). Weights that weaken the bounds (a zero
PNT, say) leave more states alive: slower, never inexact.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from facesynth.base.jit import worth

from .dp import DpResult
from .pairs import TransitionCosts
from .pairs_numba import column_minima_numba

#: States used as dominance references per step.
REFERENCES = 4
#: Columns evaluated first at each step to give the references exact values.
PROBES = 32
#: Pivots of the NumPy scan's first bound (all pivots bound the pairs it leaves).
NUMPY_FIRST_PIVOTS = 4
#: Elements (rows x columns x first pivots) per block of the NumPy scan's bounds.
NUMPY_BOUND_ELEMENTS = 1 << 22


@dataclass
class PruneStats:
    """What the pruned DP computed: pair costs evaluated (forward and backtracking), the dense
    DP's count ((T - 1) N^2) and per step the columns evaluated and the states kept."""

    pairs: int = 0
    dense_pairs: int = 0
    columns: list[int] = field(default_factory=list)
    live: list[int] = field(default_factory=list)

    @property
    def fraction(self) -> float:
        """Pair costs computed over the dense DP's (N^2 per step)."""
        return self.pairs / self.dense_pairs if self.dense_pairs else 0.0


def _margin(a, b):
    """Slack of a strict kill ``a > b + margin``: 1e-4 relative plus 1e-3 absolute."""
    return 1e-4 * (np.abs(a) + np.abs(b)) + 1e-3


def _dominated(tc: TransitionCosts, cand: np.ndarray, lower: np.ndarray, refs: np.ndarray, ref_upper: np.ndarray,
               last: bool, cheap: bool = False) -> np.ndarray:
    """Mask of ``cand`` (indices, with lower bounds ``lower`` of their phi) that some reference
    state (``refs`` with upper bounds ``ref_upper`` of their phi) dominates strictly; with
    ``cheap`` by the first, cheap test only (fewer kills, never a wrong one)."""
    if len(cand) == 0 or len(refs) == 0:
        return np.zeros(len(cand), bool)
    lower = lower.astype(np.float64)
    if last:
        bound = float(np.min(ref_upper))
        return lower > bound + _margin(lower, bound)
    # Cheap first: advantage(r, j) <= tc.reach_row[r] + tc.reach_col[j] for all r, j.
    bound = float(np.min(ref_upper + tc.reach_row[refs]))
    killed = lower - tc.reach_col[cand] > bound + _margin(lower, bound)
    if cheap:
        return killed
    open_ = np.nonzero(~killed)[0]
    # One reference at a time, smallest upper bound first, each on the states still open: the
    # same kills as against the minimum over the references (b + margin(lower, b) grows with
    # b >= 0), with most states settled by the first reference.
    for k in np.argsort(ref_upper, kind="stable"):
        if not len(open_):
            break
        bound = ref_upper[k] + tc.advantage(refs[k], cand[open_])
        dead = lower[open_] > bound + _margin(lower[open_], bound)
        killed[open_[dead]] = True
        open_ = open_[~dead]
    return killed


def _references(idx: np.ndarray, upper: np.ndarray, count: int = REFERENCES) -> tuple[np.ndarray, np.ndarray]:
    """The ``count`` entries of ``idx`` with the smallest finite ``upper``."""
    finite = np.isfinite(upper)
    idx, upper = idx[finite], upper[finite]
    if len(upper) > count:
        keep = np.argpartition(upper, count - 1)[:count]
        idx, upper = idx[keep], upper[keep]
    return idx, upper.astype(np.float64)


def _column_minima_numpy(tc: TransitionCosts, rows: np.ndarray, phi: np.ndarray, cols: np.ndarray,
                         init: np.ndarray, backward: bool = False) -> tuple[np.ndarray, int]:
    """The NumPy side of ``pruned_columns`` in ``kernels/pair_costs.cl``: the same minima
    (``backward``: of the costs TC(cols, rows)) with the same cheap bounds, vectorized.

    Per column: the pair with the smallest ``phi`` plus lower bound (a seed, bounded through
    :data:`NUMPY_FIRST_PIVOTS` pivots) is computed first; then every row whose ``phi`` plus
    lower bound, first through those pivots and then through all, stays below the best value
    so far. Every other row's value is at least its bound, so at least that best value, and
    the minimum is the dense one.
    """
    best = init.astype(np.float32).copy()
    evals = 0
    if len(rows) == 0 or len(cols) == 0:
        return best, 0

    def evaluate(r, k, c):
        nonlocal evals
        i, j = (c[k], rows[r]) if backward else (rows[r], c[k])
        evals += len(r)
        return phi[r] + tc.pairs_numpy(i, j)

    step = max(1, NUMPY_BOUND_ELEMENTS // (len(rows) * NUMPY_FIRST_PIVOTS))
    for a in range(0, len(cols), step):
        c, at = cols[a : a + step], np.arange(a, min(a + step, len(cols)))
        i, j = (c[None, :], rows[:, None]) if backward else (rows[:, None], c[None, :])
        bound = phi[:, None] + tc.lower(i, j, NUMPY_FIRST_PIVOTS)  # (rows, columns), float64
        bound[tc.pre[j] == i] = np.inf  # rule 1 is in init
        seed = np.argmin(bound, axis=0)
        go = np.nonzero(bound[seed, at - a] < best[at])[0]
        np.minimum.at(best, at[go], evaluate(seed[go], go, c))
        r, k = np.nonzero(bound < best[at][None, :])
        r, k = r[r != seed[k]], k[r != seed[k]]
        i, j = (c[k], rows[r]) if backward else (rows[r], c[k])
        tight = phi[r] + tc.lower(i, j) < best[at[k]]
        r, k = r[tight], k[tight]
        np.minimum.at(best, at[k], evaluate(r, k, c))
    return best, evals


def _host_minima(tc: TransitionCosts, t_count: int):
    """The column scan without a device: numba's (the same minima as :func:`_column_minima_numpy`)
    where it pays for its start-up (about 2 us of NumPy per node and step here), else NumPy's."""
    if not worth(2e-6 * tc.n * t_count):
        return lambda *a, **k: _column_minima_numpy(tc, *a, **k)

    return lambda *a, **k: column_minima_numba(tc, *a, **k)


def dp_pruned(tc: TransitionCosts, obs: np.ndarray, keep_last: bool = False) -> tuple[DpResult, PruneStats]:
    """Algorithm 1 for observation costs ``obs`` ((T, N) float32: OC + EMP + B per step) over the
    transition costs ``tc`` (computed on demand; on OpenCL when ``tc.opencl``). Returns the
    result (cost, (T,) path, (T, N) float32 phi with +inf on pruned states) and the counts.
    The cost and path equal :func:`facesynth.domain.search.dp.dp_numpy` on ``tc.dense()``, and so does
    phi on every state kept; with ``keep_last`` no state of the last step is pruned, so its
    phi is the dense DP's for every node."""
    obs = np.asarray(obs, np.float32)
    t_count, n = obs.shape
    stats = PruneStats(dense_pairs=(t_count - 1) * n * n)
    phi = np.full((t_count, n), np.inf, np.float32)
    phi[0] = obs[0]
    no_pre = tc.pre < 0
    with_pre = ~no_pre
    all_nodes = np.arange(n)
    live = all_nodes
    if t_count > 1:
        live = _after(tc, live, phi[0], last=False)
        dead = np.ones(n, bool)
        dead[live] = False
        phi[0, dead] = np.inf
    stats.live.append(len(live))
    minima = tc.device.column_minima if tc.opencl else _host_minima(tc, t_count)
    for t in range(1, t_count):
        last = t == t_count - 1
        prev = phi[t - 1]
        order = live[np.argsort(prev[live], kind="stable")]
        m = prev[order[0]]
        # Upper bounds: phi(pre) + obs for rule 1 (none for rule 4); lower bound m + obs.
        upper = np.full(n, np.inf, np.float32)
        pre_val = np.where(with_pre, prev[np.maximum(tc.pre, 0)], np.float32(np.inf)).astype(np.float32)
        upper[with_pre] = (pre_val + obs[t])[with_pre]
        lower = m.astype(np.float64) + obs[t] + np.where(no_pre, float(tc.a1pnt), 0.0)
        rows_sorted, phi_sorted = order.astype(np.int32), prev[order]
        # Probes: a few columns evaluated first, so the references have tight values.
        candidates = all_nodes
        if len(candidates) > 4 * PROBES:  # the few smallest lower bounds, without sorting all N
            candidates = candidates[np.argpartition(lower[candidates], 4 * PROBES - 1)[: 4 * PROBES]]
        probes = candidates[np.lexsort((candidates, upper[candidates], lower[candidates]))[:PROBES]]
        best, evals = minima(rows_sorted, phi_sorted, probes.astype(np.int32), pre_val[probes])
        stats.pairs += evals
        upper[probes] = best + obs[t, probes]
        phi[t, probes] = upper[probes]
        refs, ref_upper = _references(all_nodes, upper)
        # before evaluation only the cheap test: the per-reference bounds cost more than the
        # few columns they would spare (at 100,000 nodes they killed 2% of the survivors)
        killed = (np.zeros(n, bool) if last and keep_last
                  else _dominated(tc, all_nodes, lower, refs, ref_upper, last, cheap=not last))
        cols = np.nonzero(~killed)[0]
        cols = cols[np.isinf(phi[t, cols])]  # the probes are done
        stats.columns.append(len(cols) + len(probes))
        best, evals = minima(rows_sorted, phi_sorted, cols.astype(np.int32), pre_val[cols])
        stats.pairs += evals
        phi[t, cols] = best + obs[t, cols]
        phi[t, probes[killed[probes]]] = np.inf
        live = np.nonzero(np.isfinite(phi[t]))[0]
        if not last:
            live = _after(tc, live, phi[t], last=False)
            dead = np.ones(n, bool)
            dead[live] = False
            phi[t, dead] = np.inf
        stats.live.append(len(live))
    path = np.empty(t_count, np.int64)
    path[-1] = int(np.argmin(phi[-1]))
    for t in range(t_count - 1, 0, -1):
        j = int(path[t])
        path[t - 1] = _argmin_predecessor(tc, phi[t - 1], j, phi[t, j], obs[t, j], stats)
    return DpResult(float(phi[-1, path[-1]]), path, phi), stats


def _argmin_predecessor(tc: TransitionCosts, prev: np.ndarray, j: int, phi_j: np.float32, obs_j: np.float32,
                        stats: PruneStats) -> int:
    """argmin_i (prev[i] + TC(i, j)), lowest index on ties (``prev``: (N,) float32 phi of the
    step before, +inf on pruned states; ``phi_j`` = phi_t(j), ``obs_j`` = obs_t(j): the minimum
    is phi_j - obs_j up to one float32 rounding of phi_j). Only rows whose ``prev[i]`` plus the
    cheap lower bound of TC(i, j) (:meth:`TransitionCosts.lower`) stays within a margin far
    above that rounding can attain the minimum (TC >= 0 and rounding is monotone). So few rows
    are left, and their costs are computed on the host (bit-identical to the kernel),
    without a device round trip per step."""
    limit = float(phi_j) - float(obs_j) + _margin(float(phi_j), float(obs_j))
    rows = np.nonzero(prev <= limit)[0]
    rows = rows[prev[rows] + tc.lower(rows, j) <= limit]
    stats.pairs += len(rows)
    values = prev[rows] + tc.block_numpy(rows, np.array([j]))[:, 0]
    return int(rows[np.argmin(values)])


def _after(tc: TransitionCosts, live: np.ndarray, values: np.ndarray, last: bool) -> np.ndarray:
    """The states of ``live`` (exact ``values``) that no reference dominates."""
    refs, ref_upper = _references(live, values[live])
    killed = _dominated(tc, live, values[live], refs, ref_upper, last)
    return live[~killed]


def backward_pruned(tc: TransitionCosts, obs: np.ndarray, stop: int = 0) -> tuple[np.ndarray, PruneStats]:
    """The dense DP run backwards, exactly: ``beta[t](i) = min_k (beta[t+1](k) + TC(i, k)) + obs[t](i)``
    for t from T - 1 down to ``stop`` (beta[T-1] = obs[T-1]); the same float32 values as
    :func:`facesynth.domain.search.dp.dp_numpy` on ``tc.dense().T`` with ``obs[::-1]``. Returns
    ``beta[stop]`` ((N,) float32) and the counts. No state is pruned (every node's value is
    wanted); the sorted scan with its cheap bounds still skips most pairs."""
    obs = np.asarray(obs, np.float32)
    t_count, n = obs.shape
    stats = PruneStats(dense_pairs=(t_count - 1 - stop) * n * n)
    minima = tc.device.column_minima if tc.opencl else _host_minima(tc, t_count)
    beta = obs[-1].copy()
    suc = tc._suc
    nodes = np.arange(n, dtype=np.int32)
    for t in range(t_count - 2, stop - 1, -1):
        order = np.argsort(beta, kind="stable")
        # rule 1: k = suc(i) costs 0; every other k (rule 4 too) is scanned
        init = np.where(suc >= 0, beta[np.maximum(suc, 0)], np.float32(np.inf)).astype(np.float32)
        best, evals = minima(order.astype(np.int32), beta[order], nodes, init, backward=True)
        stats.pairs += evals
        beta = best + obs[t]
    return beta, stats
