"""The bilinear style/content model of Chuang & Bregler (2005) §3, on 3D marker frames.

The paper factors 2D video (AAM shape and texture, Eq. 1-3) into an expression (style) and a
speech (content) factor. facesynth works on 3D markers with the head motion removed, so the
facial vector ``y`` of Eq. 3 is here the PCA coefficients of the normalized markers (Eq. 1
alone; there is no texture term).

Eq. 4, the symmetric model (Tenenbaum & Freeman 2000)::

    y[s, c, k] = sum_ij E[s, i] W[k, i, j] C[c, j]

with S styles (emotions, style vectors ``E`` (S, I)), C aligned content frames (content
vectors ``C`` (C, J)) and K facial components (``W`` (K, I, J)). The fit alternates three
linear least-squares steps (styles given W and content, Eq. 5; content given W and styles,
Eq. 6; W given both) until the squared error stops falling; every step cannot raise it.

Analysis of a new frame (§3.3) iterates Eq. 5 and 6 from the mean training content vector;
restyling replaces the frame's style vector by the Eq. 7 blend
``alpha * e_target + (1 - alpha) * e_frame`` and adds back what the model does not explain,
so that ``alpha = 0`` gives the input back exactly.
"""

from __future__ import annotations

import numpy as np

from facesynth.model.expression import BilinearModel


def _style_matrix(W: np.ndarray, c: np.ndarray) -> np.ndarray:
    """(T, K, I): for each content vector c (T, J), the matrix W . c of Eq. 5."""
    return np.einsum("kij,tj->tki", W, c)


def _content_matrix(W: np.ndarray, e: np.ndarray) -> np.ndarray:
    """(T, K, J): for each style vector e (T, I), the matrix W^VT . e of Eq. 6."""
    return np.einsum("kij,ti->tkj", W, e)


def _solve_rows(A: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Least-squares x for each row: A (T, K, n), y (T, K) -> (T, n) (pseudo-inverse, as Eq. 5-6)."""
    return np.einsum("tnk,tk->tn", np.linalg.pinv(A), y)


def _lstsq(A: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Least squares by the pseudo-inverse of the small Gram matrix: A (n, p) with n >> p, b (n, q) -> (p, q)."""
    return np.linalg.pinv(A.T @ A) @ (A.T @ b)


def fit(Y: np.ndarray, emotions: list[str], mean: np.ndarray, basis: np.ndarray, *, content_dim: int,
        max_iterations: int, tolerance: float) -> BilinearModel:
    """Fit Eq. 4 to aligned data by alternating least squares.

    Y : (S, C, K) float64 PCA coefficients: style s, aligned content frame c (the same speech
        at the same phone-relative time in every emotion), component k.
    emotions : the S style names. mean, basis : the PCA model the coefficients are in.
    content_dim : J. max_iterations : most ALS sweeps. tolerance : stop when a sweep lowers
        the error by less than this fraction of it.
    The style dimension I is S (one vector per fitted emotion, as in the paper).
    """
    S, C, K = Y.shape
    J = min(content_dim, C, S * K)
    I = S
    # initial factors from the SVDs of the two unfoldings (Tenenbaum & Freeman's initialisation)
    E = np.linalg.svd(Y.reshape(S, C * K) @ Y.reshape(S, C * K).T)[0][:, :I]
    content = Y.transpose(1, 0, 2).reshape(C, S * K)
    Cm = content @ np.linalg.eigh(content.T @ content)[1][:, ::-1][:, :J]   # top-J left singular directions
    Cm /= np.maximum(np.linalg.norm(Cm, axis=0), 1e-12)
    errors: list[float] = []

    def solve_W(E, Cm):
        # y[s, c, k] = E[s] W_k C[c]: W_k = E^+ Y_k (C^T)^+ for every k at once
        return np.einsum("is,sck,jc->kij", np.linalg.pinv(E), Y, np.linalg.pinv(Cm), optimize=True)

    def error(E, W, Cm):
        return float(np.mean((np.einsum("si,kij,cj->sck", E, W, Cm, optimize=True) - Y) ** 2))

    W = solve_W(E, Cm)
    for _ in range(max_iterations):
        # Eq. 5 for every style: stack the content frames, solve for e_s
        A = np.einsum("kij,cj->cki", W, Cm).reshape(C * K, I)
        E = _lstsq(A, Y.reshape(S, C * K).T).T
        # Eq. 6 for every content frame: stack the styles, solve for c
        B = np.einsum("kij,si->skj", W, E).reshape(S * K, J)
        Cm = _lstsq(B, Y.transpose(0, 2, 1).reshape(S * K, C)).T
        # keep the factors well scaled (the product is unchanged by the rescaling W absorbs)
        E, Cm = E / np.linalg.norm(E, axis=1).mean(), Cm / max(np.linalg.norm(Cm, axis=1).mean(), 1e-12)
        W = solve_W(E, Cm)
        errors.append(error(E, W, Cm))
        if len(errors) > 1 and errors[-2] - errors[-1] <= tolerance * errors[-2]:
            break
    return BilinearModel(mean, basis, list(emotions), E, W, Cm.mean(axis=0), np.array(errors))


def _affine_weights(A: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Per row, w minimising |A w - y| subject to sum(w) = 1 (KKT system): A (T, K, S), y (T, K) -> (T, S)."""
    T, _, S = A.shape
    kkt = np.zeros((T, S + 1, S + 1))
    kkt[:, :S, :S] = np.einsum("tks,tkr->tsr", A, A)
    kkt[:, :S, S] = kkt[:, S, :S] = 1.0
    rhs = np.concatenate([np.einsum("tks,tk->ts", A, y), np.ones((T, 1))], axis=1)
    return np.einsum("tij,tj->ti", np.linalg.pinv(kkt), rhs)[:, :S]


def analyze(model: BilinearModel, coeffs: np.ndarray, *, iterations: int, init: str = "mean_content"
            ) -> tuple[np.ndarray, np.ndarray]:
    """Each frame's style and content vectors (§3.3, Eq. 5-6).

    coeffs : (T, K) PCA coefficients. Returns style (T, I) and content (T, J).

    Eq. 5 and 6 alternate from ``init`` (see below). Eq. 5 solves the style as
    an affine combination of the fitted style vectors (weights summing to one): solved freely,
    a frame's style and content trade off (any e -> k e, c -> c / k, and with K PCA components
    close to I + J the content absorbs the style), so the style found is not comparable with
    the fitted ones and Eq. 7's blend with them moves the face far off; within their affine
    span it is on their scale, and a frame of a fitted emotion analyses to about its vector.
    """
    T = len(coeffs)
    # init "mean_content": the paper's start (the mean training content vector); "best_style":
    # the fitted style that explains the frame best with its own content (Eq. 6 per style),
    # which finds exact bilinear frames exactly where the paper's start may settle elsewhere
    best_err = np.full(T, np.inf)
    e = np.zeros((T, model.styles.shape[1]))
    c = np.broadcast_to(model.content_mean, (T, len(model.content_mean))).copy()
    for style in (model.styles if init == "best_style" else ()):
        es = np.broadcast_to(style, (T, len(style)))
        cs = _solve_rows(_content_matrix(model.W, es), coeffs)
        err = np.sum((synthesize(model, es, cs) - coeffs) ** 2, axis=1)
        better = err < best_err
        best_err[better], e[better], c[better] = err[better], style, cs[better]
    for _ in range(iterations):
        w = _affine_weights(np.einsum("tki,si->tks", _style_matrix(model.W, c), model.styles), coeffs)   # Eq. 5
        e = w @ model.styles
        c = _solve_rows(_content_matrix(model.W, e), coeffs)                                            # Eq. 6
    return e, c


def synthesize(model: BilinearModel, style: np.ndarray, content: np.ndarray) -> np.ndarray:
    """Eq. 4 for each frame: style (T, I), content (T, J) -> (T, K) coefficients."""
    return np.einsum("ti,kij,tj->tk", style, model.W, content)


def restyle(model: BilinearModel, frames: np.ndarray, target: np.ndarray, alpha: np.ndarray, *,
            iterations: int, smooth_frames: float = 0.0, init: str = "mean_content") -> tuple[np.ndarray, np.ndarray]:
    """Frames in another expression (Eq. 7).

    frames : (T, M, 3) mm (rows with NaN are returned unchanged). target : (T, I) the target
    style vector of each frame. alpha : (T,) intensity in [0, 1] (0 leaves the frame as it is).
    smooth_frames : Gaussian sigma (frames) smoothing the analysed style over time; 0: per frame.
    init : where the analysis starts (:func:`analyze`).
    Returns the restyled frames (T, M, 3) float32 mm and each frame's analysed style (T, I).
    """
    out = frames.astype(np.float32).copy()
    ok = np.isfinite(frames.reshape(len(frames), -1)).all(axis=1)
    styles = np.full((len(frames), model.styles.shape[1]), np.nan)
    if not ok.any():
        return out, styles
    y = model.coefficients(frames[ok])
    e, c = analyze(model, y, iterations=iterations, init=init)
    if smooth_frames > 0 and len(e) > 1:
        # the per-frame style jitters (the paper's §7 notes it); a smoothed style, with the
        # content solved again for it (Eq. 6), keeps the blend of Eq. 7 steady
        from scipy.ndimage import gaussian_filter1d

        e = gaussian_filter1d(e, smooth_frames, axis=0, mode="nearest")
        c = _solve_rows(_content_matrix(model.W, e), y)
    a = alpha[ok, None]
    blended = a * target[ok] + (1 - a) * e                       # Eq. 7
    change = synthesize(model, blended, c) - synthesize(model, e, c)
    out[ok] = (frames[ok] + (change @ model.basis).reshape(-1, frames.shape[1], 3)).astype(np.float32)
    styles[ok] = e
    return out, styles


def warp_take(markers: np.ndarray, fps: float, src_phones: tuple[np.ndarray, np.ndarray],
              ref_phones: tuple[np.ndarray, np.ndarray], ref_times: np.ndarray) -> np.ndarray:
    """Time-warp a take onto another's timeline phone by phone (linear within each phone).

    markers : (F, M, 3) the take's frames at ``fps``. src_phones, ref_phones : (starts, ends)
    in s of the same (spoken) phone sequence in the take and in the reference; what lies
    between consecutive phones (a pause in one take only) is warped linearly. ref_times : (T,) s on
    the reference timeline. Returns (T, M, 3): the take at the corresponding times (linear
    interpolation between frames).
    """
    knots_ref = np.column_stack(ref_phones).ravel()    # start, end of every phone: pauses between them
    knots_src = np.column_stack(src_phones).ravel()    # may differ and are warped linearly
    t_src = np.interp(ref_times, knots_ref, knots_src)
    pos = np.clip(t_src * fps, 0, len(markers) - 1)
    lo = np.floor(pos).astype(int)
    hi = np.minimum(lo + 1, len(markers) - 1)
    w = (pos - lo)[:, None, None]
    return (1 - w) * markers[lo] + w * markers[hi]
