"""Bounded least squares for rig weights.

* :func:`nnls_weights`: frames as non-negative combinations of key-shapes (Chuang & Bregler
  Eq. 8, Huang Eq. 5), every frame solved exactly on the key-shapes' K x K Gram matrix instead of
  the D x K system (the same minimizer, D/K times less work), all frames at once by block
  principal pivoting (:func:`nnls_gram`; 3 to 4 times less CPU than scipy's NNLS frame by frame
  for 7 to 30 key-shapes and 300 frames).
* :func:`fit_rig_weights`: rig weights in [0, 1] that best reproduce target displacements at some
  vertices (keymorph fitting), exactly with ``scipy.optimize.lsq_linear``.
* :func:`solve_curves`: the direct facial solve, all frames at once: weights in [0, 1] minimizing
  the marker misfit plus ``smooth`` times the squared frame-to-frame change plus ``ridge`` times
  the squared weights, by accelerated projected gradient (FISTA with restart) on the whole (T, E)
  array with a step per channel (the Hessian's absolute row sums: the rig's shapes are nearly
  collinear at the markers, and one step for all left the small channels far from their minimum),
  the misfit's gradient through the E x E Gram matrix of the rig's shapes; missing markers
  (NaN) drop out of their frame's misfit; optionally a face's priors (:class:`FacePriors`:
  sparse weights, antagonists not both on, mirrored channels alike).
* :func:`solve_motion`: that solve for a marker motion on a rig (the markers carried into the
  rig's frame and units), the one path from motion to the rig that ``facesynth solve`` and
  ``facesynth batch`` share; :func:`solved_curves` makes the ``curves`` artifact of it.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from facesynth.base.blas import one_blas_thread
from facesynth.domain.retarget.face_priors import antagonist_pairs, symmetric_pairs
from facesynth.domain.rig.loading import marker_map
from facesynth.model.curves import RigCurves

if TYPE_CHECKING:
    from facesynth.base.config import SolveSettings
    from facesynth.domain.rig.face import Rig
    from facesynth.model.curves import RigCurves
    from facesynth.model.motion import Motion
    from facesynth.model.provenance import FrameProvenance


def nnls_weights(frames: np.ndarray, shapes: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Non-negative weights of every frame over the key-shapes.

    frames : (N, D) float, e.g. marker displacements flattened (mm); shapes : (K, D) key-shapes.
    Returns weights (N, K) float64 >= 0 and the per-frame RMS residual per point (N,) in the
    frames' units, ``sqrt(|x - w B|^2 / (D / 3))`` (per marker when D = 3M).

    Frames without missing coordinates are solved all at once by :func:`nnls_gram` on the key-shapes'
    K x K Gram matrix (a ridge of 1e-9 of its mean diagonal keeps it positive definite); a frame
    with missing markers (NaN) fits the coordinates it has with scipy's NNLS.
    """
    with one_blas_thread():  # small products: BLAS threads cost more than they save
        return _nnls_weights(np.asarray(frames, np.float64), np.asarray(shapes, np.float64))


def _nnls_weights(x: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    from scipy.optimize import nnls  # deferred: scipy.optimize costs synthesize's start-up

    gram = b @ b.T
    gram[np.diag_indices_from(gram)] += 1e-9 * max(np.trace(gram), 1e-12) / len(gram)
    holes = ~np.isfinite(x)
    partial = holes.any(1)
    w = np.zeros((len(x), len(b)))
    whole = np.flatnonzero(~partial)
    if len(whole):
        w[whole] = nnls_gram(gram, x[whole] @ b.T)
    for i in np.flatnonzero(partial):  # a frame with missing markers: fit the coordinates it has
        seen = ~holes[i]
        if seen.any():
            w[i] = nnls(b[:, seen].T, x[i, seen], maxiter=50 * len(b))[0]
    resid = np.where(holes, 0.0, x - w @ b)
    n_points = np.maximum((~holes).sum(1) / 3, 1)
    rms = np.sqrt((resid**2).sum(1) / n_points)
    return w, rms


#: Most key-shapes for the batched solve of :func:`nnls_gram`; with more, its steps (a batched
#: K x K solve each) cost more than scipy's NNLS per frame on the Cholesky factor (CPU seconds
#: for 2,000 frames of the small sample corpus, batched against per frame: 0.017 / 0.066 at
#: K = 8, 0.062 / 0.064 at K = 14, 0.19 / 0.06 at K = 20, about 70 / 0.3 at K = 80).
BATCHED_MAX_SHAPES = 14


def nnls_gram(gram: np.ndarray, h: np.ndarray, max_iter: int | None = None, stragglers: int = 8) -> np.ndarray:
    """``argmin_w 1/2 w^T G w - h_i^T w`` subject to w >= 0, for every row h_i of h, all at once.

    gram : (K, K) symmetric positive definite G (``B B^T`` of K key-shapes); h : (N, K) the
    frames' products with the key-shapes (``x_i B^T``). Returns (N, K) weights: for frames
    ``x_i``, the non-negative least-squares weights of ``|x_i - w B|``, the same minimizer as
    scipy.optimize.nnls on B^T (unique, G being positive definite).

    Block principal pivoting (Kim & Park 2011, "Fast nonnegative matrix factorization", Alg. 2
    with multiple right-hand sides): every frame keeps a passive set P; each step solves
    ``G_PP w_P = h_P`` for all frames at once (one batched K x K solve, the other rows pinned to
    0), and exchanges the variables that break the optimality conditions (w_P < 0, or gradient
    ``G w - h < 0`` outside P): all of them while their count falls (or for 3 steps after it last
    fell), else only the one with the largest index (Murty's rule, which always terminates). The
    conditions are met to a relative tolerance of 1e-12 of the frame's scale. Once no more than
    ``stragglers`` frames are left (most finish in under 10 steps, a few take 20), and for any
    frame not done in ``max_iter`` steps (default 5 K + 50), scipy's NNLS on the Cholesky factor
    finishes them: the same minimizer, without a batched step per straggler. With more than
    :data:`BATCHED_MAX_SHAPES` key-shapes every frame goes that way.
    """
    g = np.asarray(gram, np.float64)
    h = np.asarray(h, np.float64)
    n, k = h.shape
    w = np.zeros((n, k))
    if n == 0 or k == 0:
        return w
    if k > BATCHED_MAX_SHAPES:
        _finish(g, h, w, np.arange(n))
        return w
    eye = np.eye(k, dtype=bool)

    def solve_on(rows: np.ndarray, pa: np.ndarray) -> None:
        """w and the gradient G w - h of ``rows`` for passive sets ``pa``: ``G_PP w_P = h_P``, the
        rows and columns outside P replaced by the identity (one batched K x K solve)."""
        system = np.where(pa[:, :, None] & pa[:, None, :], g, 0.0)
        system[:, eye] = np.where(pa, np.diagonal(g)[None], 1.0)
        wn = np.linalg.solve(system, np.where(pa, h[rows], 0.0)[..., None])[..., 0]
        wn[~pa] = 0.0
        gn = wn @ g - h[rows]
        gn[pa] = 0.0
        w[rows], grad[rows] = wn, gn

    # Start from the passive sets where the unconstrained minimizer is positive (any start works;
    # this one is usually a step or two from the answer).
    passive = np.linalg.solve(g, h.T).T > 0
    grad = np.empty((n, k))
    active = np.arange(n)
    solve_on(active, passive)
    scale = np.maximum(np.abs(h).max(1), 1e-300)[:, None]  # gradient units
    best = np.full(n, k + 1)
    tries = np.full(n, 3)
    for _ in range(max_iter or 5 * k + 50):
        if len(active) <= stragglers:
            break
        wa, ga, pa = w[active], grad[active], passive[active]
        wscale = np.maximum(np.abs(wa).max(1, keepdims=True), 1e-300)
        bad = (pa & (wa < -1e-12 * wscale)) | (~pa & (ga < -1e-12 * scale[active]))
        count = bad.sum(1)
        going = count > 0
        active, bad, count, pa = active[going], bad[going], count[going], pa[going]
        if not len(active):
            break
        fewer = count < best[active]
        best[active[fewer]] = count[fewer]
        tries[active[fewer]] = 3
        full = fewer | (tries[active] >= 1)
        tries[active[~fewer & full]] -= 1
        flip = bad.copy()
        single = np.flatnonzero(~full)
        if len(single):  # Murty's backup rule: only the infeasible variable with the largest index
            last = k - 1 - np.argmax(bad[single][:, ::-1], axis=1)
            flip[single] = False
            flip[single, last] = True
        pa ^= flip
        passive[active] = pa
        solve_on(active, pa)
    _finish(g, h, w, active)
    return w


def _finish(g: np.ndarray, h: np.ndarray, w: np.ndarray, rows: np.ndarray) -> None:
    """``w[rows]`` by scipy's NNLS, one frame at a time, on the Cholesky factor of G (K x K)."""
    from scipy.linalg import solve_triangular  # deferred: scipy.linalg costs synthesize's start-up
    from scipy.optimize import nnls

    if len(rows):
        upper = np.linalg.cholesky(g).T
        for i in rows:
            w[i] = nnls(upper, solve_triangular(upper, h[i], trans="T"), maxiter=50 * len(g))[0]


def fit_rig_weights(targets: np.ndarray, basis: np.ndarray, ridge: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """Rig weights in [0, 1] reproducing each target.

    targets : (K, D) displacements at the fitted vertices, flattened; basis : (E, D) the rig's
    shape displacements there. ridge : weight of ``|w|^2`` relative to the mean squared norm of a
    basis row (a tie-break between shapes that move the fitted vertices alike).
    Returns (K, E) weights and the (K,) RMS residual per vertex.
    """
    from scipy.optimize import lsq_linear  # deferred: scipy.optimize costs synthesize's start-up

    a = np.asarray(basis, np.float64).T  # (D, E)
    lam = ridge * float((a**2).sum(0).mean())
    if lam > 0:
        a = np.vstack([a, np.sqrt(lam) * np.eye(a.shape[1])])
    out = np.empty((len(targets), a.shape[1]))
    with one_blas_thread():  # small least squares: threads cost more than they save (9 s against 0.5 s for 80 targets)
        for k, t in enumerate(np.asarray(targets, np.float64)):
            rhs = np.concatenate([t, np.zeros(a.shape[0] - len(t))])
            out[k] = lsq_linear(a, rhs, bounds=(0.0, 1.0), method="bvls").x
    resid = np.asarray(targets) - out @ np.asarray(basis, np.float64)
    return out, np.sqrt((resid**2).sum(1) / max(resid.shape[1] / 3, 1))


def solve_curves(frames: np.ndarray, basis: np.ndarray, *, smooth: float, ridge: float, iterations: int,
                 tolerance: float, initial: np.ndarray | None = None, priors: "FacePriors | None" = None
                 ) -> tuple[np.ndarray, np.ndarray, int]:
    """The direct facial solve; see :func:`_solve_curves`. Runs with one BLAS thread: its products
    are small (T x E by E x 3M), and a threaded BLAS spends more on waking threads than on them
    (25 times slower on a busy two-core machine)."""
    with one_blas_thread():
        return _solve_curves(frames, basis, smooth=smooth, ridge=ridge, iterations=iterations, tolerance=tolerance,
                             initial=initial, priors=priors)


def _solve_curves(frames: np.ndarray, basis: np.ndarray, *, smooth: float, ridge: float, iterations: int,
                  tolerance: float, initial: np.ndarray | None = None, priors: "FacePriors | None" = None
                  ) -> tuple[np.ndarray, np.ndarray, int]:
    """The direct facial solve.

    frames : (T, M, 3) marker displacements in rig units (NaN: missing); basis : (E, M, 3) the rig's
    shape displacements at the markers' vertices. smooth : weight of ``sum_t |w_t - w_{t-1}|^2``,
    ridge : of ``|w|^2``, both relative to the mean squared norm of a basis row. Stops when no
    weight moved by more than ``tolerance`` in an iteration, or after ``iterations``. ``initial``
    ((E,) or (T, E)) starts the iterations there instead of at 0 (a live stream starts each batch
    of frames at the weights of the frame before: the same minimum, fewer iterations).
    ``priors`` (:class:`FacePriors`) adds what a face does: ``sparsity`` times ``sum |w_e|`` (an
    L1 term: a channel stays at 0 unless it explains more than about that share of its own full
    displacement, or of the mean shape's for a shape smaller than the mean), ``antagonist`` times ``sum w_i w_j`` over opposing pairs (not both on), and
    ``symmetry`` times ``sum (w_l - w_r)^2`` over mirrored pairs, each relative to the squared
    norm of its channel's basis row (a pair's: the geometric mean of the two). The temporal term is part of the one solve over all frames, so it
    smooths without lag (zero phase), unlike a causal filter.
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
    pr = priors or FacePriors()
    # The face's priors are per channel: relative to each channel's own squared norm (a pair's:
    # the geometric mean of its two), so a large shape (the jaw) is judged by its own size. The
    # L1 term takes at least the mean norm: a small shape (a blink or gaze, 2-3 mm at the
    # markers) would otherwise turn a tracker's millimetre of noise into half a weight.
    own = (a**2).sum(1)  # (E,)
    l1 = pr.sparsity * np.maximum(own, scale)
    ant_i, ant_j = (np.array(x, np.int64) for x in (zip(*pr.antagonists) if pr.antagonists else ((), ())))
    sym_i, sym_j = (np.array(x, np.int64) for x in (zip(*pr.symmetric) if pr.symmetric else ((), ())))
    lam_a = pr.antagonist * np.sqrt(own[ant_i] * own[ant_j])
    lam_y = pr.symmetry * np.sqrt(own[sym_i] * own[sym_j])
    coupling = np.zeros((len(a), len(a)))  # the antagonist term's Hessian: sum lam w_i w_j = w C w^T / 2
    coupling[ant_i, ant_j] = coupling[ant_j, ant_i] = lam_a
    # A step per channel, 1 / D_e, with D the absolute row sums of the Hessian (Gershgorin: D - H is
    # diagonally dominant, so D bounds H and each step descends): the misfit's sum_j sum_d |a_ed| |a_jd|
    # (a bound for every mask), 4 smooth (the path Laplacian's), ridge, the antagonist coupling and
    # 4 symmetry per mirrored pair. The rig's shapes are nearly collinear at the markers (the Gram
    # matrix's condition number is about 1e6), so one scalar step, 1 / |A|^2, left the small channels
    # far from their minimum after thousands of iterations; per channel the same iterations reach it.
    bound = np.abs(a) @ np.abs(a).sum(0) + 4 * lam_s + lam_r + coupling.sum(1)
    np.add.at(bound, sym_i, 4 * lam_y)
    np.add.at(bound, sym_j, 4 * lam_y)
    step = 1.0 / bound  # (E,)
    w = np.zeros((t_count, len(a))) if initial is None else np.clip(np.broadcast_to(initial, (t_count, len(a))), 0.0, 1.0)
    y, theta = w.copy(), 1.0
    # Frames with every marker seen take the misfit's gradient through the E x E Gram matrix,
    # ``y (A A^T) - D A^T`` (D/E times less work per iteration); frames with missing markers
    # through their masked residual.
    whole = seen.all(1)
    partial = np.flatnonzero(~whole)
    gram, da = a @ a.T, d @ a.T
    it = 0
    for it in range(1, iterations + 1):  # noqa: B007 (the count is reported after the loop)
        grad = y @ gram - da + lam_r * y
        if len(partial):
            yp = y[partial]
            grad[partial] = ((yp @ a - d[partial]) * mask[partial]) @ a.T + lam_r * yp
        if t_count > 1 and lam_s > 0:
            diff = np.diff(y, axis=0)
            grad[1:] += lam_s * diff
            grad[:-1] -= lam_s * diff
        if len(ant_i) and pr.antagonist > 0:
            grad += y @ coupling
        if len(sym_i) and pr.symmetry > 0:  # mirrored pairs are disjoint: plain indexing adds once
            gap = 2 * lam_y * (y[:, sym_i] - y[:, sym_j])
            grad[:, sym_i] += gap
            grad[:, sym_j] -= gap
        # the L1 term's proximal step on w >= 0 is a shift before the clip
        w_new = np.clip(y - step * (grad + l1), 0.0, 1.0)
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


@dataclass(frozen=True)
class FacePriors:
    """What :func:`solve_curves` knows of a face (see it): ``sparsity`` (L1), ``antagonist``
    (opposing pairs ``antagonists`` not both on), ``symmetry`` (mirrored pairs ``symmetric``
    alike), weights relative to each channel's squared norm (see :func:`_solve_curves`); pairs index the basis's
    rows (:mod:`facesynth.domain.retarget.face_priors` finds them from a rig's shape names)."""

    sparsity: float = 0.0
    antagonist: float = 0.0
    symmetry: float = 0.0
    antagonists: tuple[tuple[int, int], ...] = ()
    symmetric: tuple[tuple[int, int], ...] = ()

    @classmethod
    def of_rig(cls, shape_names: "list[str] | tuple[str, ...]", settings: "SolveSettings") -> "FacePriors":
        """The priors of a rig with ``shape_names`` at ``settings``' weights."""
        return cls(settings.sparsity, settings.antagonist, settings.symmetry,
                   tuple(antagonist_pairs(shape_names)), tuple(symmetric_pairs(shape_names)))


def solve_motion(motion: "Motion", rig: "Rig", settings: "SolveSettings", where: str) -> tuple[np.ndarray, np.ndarray, int]:
    """The direct facial solve of ``motion`` on ``rig``: (T, E) rig weights in [0, 1], (T,) RMS
    marker residual in rig units and the iterations used. The motion's markers (T, M, 3) mm are
    bound to the rig's marker vertices and carried into the rig's frame and units by a similarity
    fitted from the motion's neutral reference to the rig's neutral at those vertices
    (:func:`facesynth.domain.rig.loading.marker_map`); the solve fits displacements from the reference
    (:func:`solve_curves` with ``settings``' smooth, ridge, iterations and tolerance). ``where``
    names the motion in errors."""
    mmap = marker_map(rig, motion.marker_names, motion.reference, where)
    disp = mmap.displacements(motion.markers, motion.reference)
    basis = rig.deltas[:, mmap.vertices]
    return solve_curves(disp, basis, smooth=settings.smooth, ridge=settings.ridge, iterations=settings.iterations,
                        tolerance=settings.tolerance, priors=FacePriors.of_rig(rig.shape_names, settings))


def solved_curves(motion: "Motion", rig: "Rig", weights: np.ndarray, residual: np.ndarray,
                  provenance: "FrameProvenance | None", method: str | None = None) -> "RigCurves":
    """The ``curves`` artifact of a solve of ``motion`` on ``rig`` (:func:`solve_motion`'s
    weights (T, E) and residual (T,)): ``source = "solve"``, at the motion's rate, with its head
    motion and ``provenance`` (where each frame came from); ``method`` says how, in words (None:
    the regularized solve)."""
    return RigCurves(weights, motion.fps, list(rig.shape_names), rig.name, rig.sha256, "solve", motion.head_rotation,
                     motion.head_translation, residual=residual,
                     method=method or "bounded least squares with temporal smoothness and a face's priors "
                     "(sparsity, antagonists, symmetry)", provenance=provenance)
