"""Rigid head motion carried along with synthesized motion.

normalize keeps each captured frame's head transform (``captured = R_t @ normalized + t_t``).
Takes were captured at different places in the capture volume, so a frame's head motion is
taken relative to its take's mean pose: ``R_rel = Rbar^T R_t``, ``t_rel = Rbar^T (t_t - tbar)``
(Rbar the rotation nearest the take's mean, tbar its mean translation;
:func:`facesynth.model.frames.relative_to_take`, a property of the stored head frames). A synthesized frame
gets the relative head motion of its source frame; pauses are interpolated (rotations by
slerp) and the result is smoothed lightly so joins between takes do not jerk the head.

The rotations are handled as unit quaternions in NumPy (slerp as scipy's ``Slerp``, the
smoothing as ``scipy.ndimage.gaussian_filter1d`` with ``mode="nearest"`` on rotation vectors):
importing scipy took longer (about 0.3 s of CPU, 0.6 s on a busy machine) than ``synthesize``'s
whole search on the paper preset; ``tests/motion/test_head.py`` checks both against scipy.
"""

from __future__ import annotations

import numpy as np


def quat_from_matrix(m: np.ndarray) -> np.ndarray:
    """Unit quaternions (x, y, z, w), (F, 4) float64, of rotation matrices (F, 3, 3) (Shepperd's
    method: the largest of w, x, y, z is found first, so no division by a small number)."""
    m = np.asarray(m, np.float64).reshape(-1, 3, 3)
    tr = np.trace(m, axis1=1, axis2=2)
    cand = np.stack([m[:, 0, 0], m[:, 1, 1], m[:, 2, 2], tr], axis=1)
    k = np.argmax(cand, axis=1)
    q = np.empty((len(m), 4))
    for c in range(3):  # x, y or z largest
        sel = k == c
        i, j, l = c, (c + 1) % 3, (c + 2) % 3
        mm = m[sel]
        q[sel, i] = 1 - cand[sel, 3] + 2 * mm[:, i, i]
        q[sel, j] = mm[:, j, i] + mm[:, i, j]
        q[sel, l] = mm[:, l, i] + mm[:, i, l]
        q[sel, 3] = mm[:, l, j] - mm[:, j, l]
    sel = k == 3
    mm = m[sel]
    q[sel, 0] = mm[:, 2, 1] - mm[:, 1, 2]
    q[sel, 1] = mm[:, 0, 2] - mm[:, 2, 0]
    q[sel, 2] = mm[:, 1, 0] - mm[:, 0, 1]
    q[sel, 3] = 1 + cand[sel, 3]
    return q / np.linalg.norm(q, axis=1, keepdims=True)


def quat_to_matrix(q: np.ndarray) -> np.ndarray:
    """(F, 3, 3) rotation matrices of quaternions (x, y, z, w) (F, 4)."""
    q = q / np.linalg.norm(q, axis=1, keepdims=True)
    x, y, z, w = q.T
    return np.stack([np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)], -1),
                     np.stack([2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)], -1),
                     np.stack([2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)], -1)], 1)


def quat_multiply(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Hamilton products a b of quaternions (x, y, z, w), broadcast (..., 4)."""
    ax, ay, az, aw = np.moveaxis(a, -1, 0)
    bx, by, bz, bw = np.moveaxis(b, -1, 0)
    return np.stack([aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz], -1)


def quat_to_rotvec(q: np.ndarray) -> np.ndarray:
    """Rotation vectors (angle in [0, pi] times the unit axis, radians), (F, 3), of quaternions (F, 4)."""
    q = np.where(q[:, 3:4] < 0, -q, q)  # w >= 0: the angle is at most pi
    vec = np.linalg.norm(q[:, :3], axis=1)
    angle = 2 * np.arctan2(vec, q[:, 3])
    small = angle <= 1e-3
    # angle / sin(angle / 2), by its Taylor series where the angle is small
    scale = np.where(small, 2 + angle ** 2 / 12 + 7 * angle ** 4 / 2880,
                     angle / np.sin(np.where(small, 1.0, angle) / 2))
    return scale[:, None] * q[:, :3]


def quat_from_rotvec(v: np.ndarray) -> np.ndarray:
    """Quaternions (x, y, z, w), (F, 4), of rotation vectors (F, 3) (radians)."""
    angle = np.linalg.norm(v, axis=1)
    small = angle <= 1e-3
    # sin(angle / 2) / angle, by its Taylor series where the angle is small
    scale = np.where(small, 0.5 - angle ** 2 / 48 + angle ** 4 / 3840,
                     np.sin(angle / 2) / np.where(small, 1.0, angle))
    return np.concatenate([scale[:, None] * v, np.cos(angle / 2)[:, None]], axis=1)


def gaussian_smooth(x: np.ndarray, sigma: float) -> np.ndarray:
    """``scipy.ndimage.gaussian_filter1d(x, sigma, axis=0, mode="nearest")``: a Gaussian of
    radius int(4 sigma + 0.5) samples, normalized, with the edge samples repeated."""
    radius = int(4.0 * sigma + 0.5)
    taps = np.exp(-0.5 * (np.arange(-radius, radius + 1) / sigma) ** 2)
    taps /= taps.sum()
    padded = np.concatenate([np.repeat(x[:1], radius, 0), x, np.repeat(x[-1:], radius, 0)])
    out = np.zeros_like(x, dtype=np.float64)
    for k, w in enumerate(taps):
        out += w * padded[k : k + len(x)]
    return out


def follow_sources(source_frame: np.ndarray, rotations: np.ndarray, translations: np.ndarray,
                   smooth_frames: float = 3.0) -> tuple[np.ndarray, np.ndarray]:
    """Head motion for frames copied from ``source_frame`` (-1: interpolate). Returns (T, 3, 3), (T, 3)."""
    have = np.nonzero(source_frame >= 0)[0]
    n = len(source_frame)
    if len(have) == 0:
        return np.broadcast_to(np.eye(3), (n, 3, 3)).copy(), np.zeros((n, 3))
    frames = np.arange(n)
    known = quat_from_matrix(rotations[source_frame[have]])
    if len(have) == 1:
        rot = np.repeat(known, n, axis=0)
    else:
        # slerp between the known frames around them: q_i exp(s log(q_i^-1 q_{i+1})), s in [0, 1]
        times = np.clip(frames, have[0], have[-1]).astype(np.float64)
        seg = np.clip(np.searchsorted(have, times, side="right") - 1, 0, len(have) - 2)
        inverse = known[:-1] * np.array([-1.0, -1.0, -1.0, 1.0])
        delta = quat_to_rotvec(quat_multiply(inverse, known[1:]))
        s = (times - have[seg]) / (have[seg + 1] - have[seg])
        rot = quat_multiply(known[seg], quat_from_rotvec(delta[seg] * s[:, None]))
    trans = np.stack([np.interp(frames, have, translations[source_frame[have], a]) for a in range(3)], 1)
    if smooth_frames > 0 and n > 1:
        rot = quat_from_rotvec(gaussian_smooth(quat_to_rotvec(rot), smooth_frames))
        trans = gaussian_smooth(trans, smooth_frames)
    return quat_to_matrix(rot), trans


def apply(vertices: np.ndarray, rotation: np.ndarray, translation: np.ndarray, scale: float,
          to_mesh: np.ndarray, offset: np.ndarray) -> np.ndarray:
    """Move mesh vertices (V, 3) by a head motion given in the normalized (marker) frame.
    The similarity ``mesh = scale * to_mesh @ normalized + offset`` relates the two frames."""
    normalized = (vertices - offset) @ to_mesh / scale
    moved = normalized @ rotation.T + translation
    return scale * moved @ to_mesh.T + offset
