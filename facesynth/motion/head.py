"""Rigid head motion carried along with synthesized motion.

normalize keeps each captured frame's head transform (``captured = R_t @ normalized + t_t``).
Takes were captured at different places in the capture volume, so a frame's head motion is
taken relative to its take's mean pose: ``R_rel = Rbar^T R_t``, ``t_rel = Rbar^T (t_t - tbar)``
(Rbar the rotation nearest the take's mean, tbar its mean translation). A synthesized frame
gets the relative head motion of its source frame; pauses are interpolated (rotations by
slerp) and the result is smoothed lightly so joins between takes do not jerk the head.

scipy is imported where it is used: importing it costs more than the head motion of a
sentence, and ``synthesize`` imports it (:func:`import_scipy`) while the search runs.
"""

from __future__ import annotations

import numpy as np


def relative_to_take(rotations: np.ndarray, translations: np.ndarray, take_ranges: list[slice]) -> tuple[np.ndarray, np.ndarray]:
    """Per frame head motion relative to its take's mean pose. (F, 3, 3), (F, 3)."""
    rel_r = rotations.astype(np.float64).copy()
    rel_t = translations.astype(np.float64).copy()
    for sl in take_ranges:
        r = rotations[sl].astype(np.float64)
        if len(r) == 0:
            continue
        u, _, vt = np.linalg.svd(r.mean(axis=0))
        mean_r = u @ np.diag([1.0, 1.0, np.linalg.det(u @ vt)]) @ vt
        rel_r[sl] = mean_r.T @ r
        rel_t[sl] = (translations[sl] - translations[sl].mean(axis=0)) @ mean_r
    return rel_r, rel_t


def import_scipy() -> None:
    """Import the scipy modules :func:`follow_sources` uses (about 0.3 s), e.g. while a device works."""
    import scipy.ndimage  # noqa: F401
    import scipy.spatial.transform  # noqa: F401


def follow_sources(source_frame: np.ndarray, rotations: np.ndarray, translations: np.ndarray,
                   smooth_frames: float = 3.0) -> tuple[np.ndarray, np.ndarray]:
    """Head motion for frames copied from ``source_frame`` (-1: interpolate). Returns (T, 3, 3), (T, 3)."""
    from scipy.ndimage import gaussian_filter1d
    from scipy.spatial.transform import Rotation, Slerp

    have = np.nonzero(source_frame >= 0)[0]
    n = len(source_frame)
    if len(have) == 0:
        return np.broadcast_to(np.eye(3), (n, 3, 3)).copy(), np.zeros((n, 3))
    frames = np.arange(n)
    known = Rotation.from_matrix(rotations[source_frame[have]])
    if len(have) == 1:
        rot = Rotation.from_matrix(np.repeat(known.as_matrix(), n, axis=0))
    else:
        rot = Slerp(have, known)(np.clip(frames, have[0], have[-1]))
    trans = np.stack([np.interp(frames, have, translations[source_frame[have], a]) for a in range(3)], 1)
    if smooth_frames > 0 and n > 1:
        rotvec = gaussian_filter1d(rot.as_rotvec(), smooth_frames, axis=0, mode="nearest")
        rot = Rotation.from_rotvec(rotvec)
        trans = gaussian_filter1d(trans, smooth_frames, axis=0, mode="nearest")
    return rot.as_matrix(), trans


def apply(vertices: np.ndarray, rotation: np.ndarray, translation: np.ndarray, scale: float,
          to_mesh: np.ndarray, offset: np.ndarray) -> np.ndarray:
    """Move mesh vertices (V, 3) by a head motion given in the normalized (marker) frame.
    The similarity ``mesh = scale * to_mesh @ normalized + offset`` relates the two frames."""
    normalized = (vertices - offset) @ to_mesh / scale
    moved = normalized @ rotation.T + translation
    return scale * moved @ to_mesh.T + offset
