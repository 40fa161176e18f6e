"""Bounded least squares for rig weights.

* :func:`nnls_weights`: frames as non-negative combinations of key-shapes (Chuang & Bregler
  Eq. 8, Huang Eq. 5), every frame solved exactly with scipy's NNLS on the K x K Cholesky factor of
  the key-shapes' Gram matrix instead of the D x K system (the same minimizer, D/K times less work).
* :func:`fit_rig_weights`: rig weights in [0, 1] that best reproduce target displacements at some
  vertices (keymorph fitting), exactly with ``scipy.optimize.lsq_linear``.
* :func:`solve_curves`: the direct facial solve, all frames at once: weights in [0, 1] minimizing
  the marker misfit plus ``smooth`` times the squared frame-to-frame change plus ``ridge`` times
  the squared weights, by accelerated projected gradient (FISTA with restart) on the whole (T, E)
  array; missing markers (NaN) drop out of their frame's misfit.
"""

from __future__ import annotations

import numpy as np
from scipy.linalg import solve_triangular
from scipy.optimize import lsq_linear, nnls


def nnls_weights(frames: np.ndarray, shapes: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Non-negative weights of every frame over the key-shapes.

    frames : (N, D) float, e.g. marker displacements flattened (mm); shapes : (K, D) key-shapes.
    Returns weights (N, K) float64 >= 0 and the per-frame RMS residual per point (N,) in the
    frames' units, ``sqrt(|x - w B|^2 / (D / 3))`` (per marker when D = 3M).
    """
    x = np.asarray(frames, np.float64)
    b = np.asarray(shapes, np.float64)
    gram = b @ b.T
    gram[np.diag_indices_from(gram)] += 1e-9 * max(np.trace(gram), 1e-12) / len(gram)
    upper = np.linalg.cholesky(gram).T  # gram = U^T U
    # |x - B^T w|^2 = |U w - U^-T B x|^2 + const: an NNLS on the K x K factor.
    rhs = solve_triangular(upper, b @ np.nan_to_num(x).T, trans="T").T  # (N, K)
    w = np.empty((len(x), len(b)))
    holes = ~np.isfinite(x)
    for i in range(len(x)):
        if holes[i].any():  # a frame with missing markers: fit the coordinates it has
            seen = ~holes[i]
            w[i] = nnls(b[:, seen].T, x[i, seen], maxiter=50 * len(b))[0] if seen.any() else 0.0
        else:
            w[i] = nnls(upper, rhs[i], maxiter=50 * len(b))[0]
    resid = np.where(holes, 0.0, x - w @ b)
    n_points = np.maximum((~holes).sum(1) / 3, 1)
    rms = np.sqrt((resid**2).sum(1) / n_points)
    return w, rms


def fit_rig_weights(targets: np.ndarray, basis: np.ndarray, ridge: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Rig weights in [0, 1] reproducing each target.

    targets : (K, D) displacements at the fitted vertices, flattened; basis : (E, D) the rig's
    shape displacements there. ridge : weight of ``|w|^2`` relative to the mean squared norm of a
    basis row (a tie-break between shapes that move the fitted vertices alike).
    Returns (K, E) weights and the (K,) RMS residual per vertex.
    """
    a = np.asarray(basis, np.float64).T  # (D, E)
    lam = ridge * float((a**2).sum(0).mean())
    if lam > 0:
        a = np.vstack([a, np.sqrt(lam) * np.eye(a.shape[1])])
    out = np.empty((len(targets), a.shape[1]))
    for k, t in enumerate(np.asarray(targets, np.float64)):
        rhs = np.concatenate([t, np.zeros(a.shape[0] - len(t))])
        out[k] = lsq_linear(a, rhs, bounds=(0.0, 1.0), method="bvls").x
    resid = np.asarray(targets) - out @ np.asarray(basis, np.float64)
    return out, np.sqrt((resid**2).sum(1) / max(resid.shape[1] / 3, 1))


def solve_curves(frames: np.ndarray, basis: np.ndarray, *, smooth: float, ridge: float, iterations: int,
                 tolerance: float) -> tuple[np.ndarray, np.ndarray, int]:
    """The direct facial solve; see :func:`_solve_curves`. Runs with one BLAS thread: its products
    are small (T x E by E x 3M), and a threaded BLAS spends more on waking threads than on them
    (25 times slower on a busy two-core machine)."""
    from threadpoolctl import threadpool_limits

    with threadpool_limits(1):
        return _solve_curves(frames, basis, smooth=smooth, ridge=ridge, iterations=iterations, tolerance=tolerance)


def _solve_curves(frames: np.ndarray, basis: np.ndarray, *, smooth: float, ridge: float, iterations: int,
                  tolerance: float) -> tuple[np.ndarray, np.ndarray, int]:
    """The direct facial solve.

    frames : (T, M, 3) marker displacements in rig units (NaN: missing); basis : (E, M, 3) the rig's
    shape displacements at the markers' vertices. smooth : weight of ``sum_t |w_t - w_{t-1}|^2``,
    ridge : of ``|w|^2``, both relative to the mean squared norm of a basis row. Stops when no
    weight moved by more than ``tolerance`` in an iteration, or after ``iterations``.
    Returns weights (T, E) float64 in [0, 1], the per-frame RMS marker residual (T,) (NaN where no
    marker was seen) and the iterations run.
    """
    d = np.asarray(frames, np.float64).reshape(len(frames), -1)
    a = np.asarray(basis, np.float64).reshape(len(basis), -1)  # (E, D)
    seen = np.isfinite(d)
    d = np.where(seen, d, 0.0)
    mask = seen.astype(np.float64)
    scale = float((a**2).sum(1).mean())
    lam_s, lam_r = smooth * scale, ridge * scale
    t_count = len(d)
    # Lipschitz constant of the gradient: |A|^2 (masks only shrink it) + 4 smooth (path Laplacian) + ridge.
    lip = np.linalg.norm(a, 2) ** 2 + 4 * lam_s + lam_r
    step = 1.0 / lip
    w = np.zeros((t_count, len(a)))
    y, theta, prev_obj = w.copy(), 1.0, np.inf
    it = 0
    for it in range(1, iterations + 1):
        r = (y @ a - d) * mask
        grad = r @ a.T + lam_r * y
        if t_count > 1 and lam_s > 0:
            diff = np.diff(y, axis=0)
            grad[1:] += lam_s * diff
            grad[:-1] -= lam_s * diff
        w_new = np.clip(y - step * grad, 0.0, 1.0)
        moved = float(np.abs(w_new - w).max()) if t_count else 0.0
        # Restart the momentum when the step went uphill (O'Donoghue & Candes's gradient restart).
        if np.sum(grad * (w_new - w)) > 0:
            theta_new, y = 1.0, w_new.copy()
        else:
            theta_new = 0.5 * (1 + np.sqrt(1 + 4 * theta * theta))
            y = w_new + ((theta - 1) / theta_new) * (w_new - w)
        w, theta = w_new, theta_new
        if moved < tolerance:
            break
    r = (w @ a - d) * mask
    counts = seen.reshape(t_count, -1, 3)[:, :, 0].sum(1)
    with np.errstate(invalid="ignore", divide="ignore"):
        rms = np.where(counts > 0, np.sqrt((r**2).sum(1) / np.maximum(counts, 1)), np.nan)
    return w, rms, it
