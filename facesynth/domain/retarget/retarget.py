"""Key-shape retargeting (Chuang & Bregler 2005 §4.2-4.3, Eq. 8-9) with the expression-weighted
blend across emotions.

Each emotion e has key-shapes B_e (K_e marker displacements) and keymorphs G_e (K_e rig weight
vectors, or K_e meshes). A frame x is decomposed in every emotion's key-shapes by NNLS
(Eq. 8: ``x ~ sum_k a_ek B_ek``, a >= 0); the emotion weights ``p_e`` come from how well each set
explains it (``exp(-(r_e / scale)^2)`` of its RMS residual r_e, normalized, then a moving average
over time), so a sentence that moves from neutral to happy moves between keymorph sets. The
retargeted frame is ``sum_e p_e sum_k a_ek G_ek`` (Eq. 9): rig weights when the keymorphs are rig
weights (clipped to [0, 1]), and the per-key-shape blend weights ``p_e a_ek`` for mesh blending.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .solve import nnls_weights


@dataclass
class Retargeted:
    """alpha : (T, K) blend weights over all emotions' key-shapes (K = sum K_e), emotion order as
    given; emotion_weights : (T, L); residual : (T, L) RMS per marker of each emotion's fit (mm)."""

    alpha: np.ndarray
    emotion_weights: np.ndarray
    residual: np.ndarray


def emotion_blend(residual: np.ndarray, scale: float, window: int) -> np.ndarray:
    """(T, L) emotion weights from (T, L) residuals: a softmin, smoothed over ``window`` frames."""
    z = -((residual / scale) ** 2)
    z -= z.max(1, keepdims=True)
    p = np.exp(z)
    p /= p.sum(1, keepdims=True)
    if window > 1:
        kernel = np.ones(window) / window
        pad = window // 2
        padded = np.pad(p, ((pad, window - 1 - pad), (0, 0)), mode="edge")
        p = np.stack([np.convolve(padded[:, j], kernel, mode="valid") for j in range(p.shape[1])], 1)
        p /= p.sum(1, keepdims=True)
    return p


def decompose(frames: np.ndarray, shape_sets: list[np.ndarray], scale: float, window: int,
              fixed: int | None = None) -> Retargeted:
    """Frames (T, D) displacements over each emotion's key-shapes ((K_e, D) each).

    fixed : the index of one emotion to use alone (every frame weight 1), or None to blend.
    """
    x = np.asarray(frames, np.float64)
    alphas, residuals = [], []
    for shapes in shape_sets:
        w, rms = nnls_weights(x, shapes)
        alphas.append(w)
        residuals.append(rms)
    residual = np.stack(residuals, 1)
    if fixed is None:
        p = emotion_blend(residual, scale, window)
    else:
        p = np.zeros_like(residual)
        p[:, fixed] = 1.0
    alpha = np.concatenate([p[:, [e]] * a for e, a in enumerate(alphas)], 1)
    return Retargeted(alpha, p, residual)
