"""A perspective camera looking from a direction (yaw about the world's up axis (+y), pitch
above the horizon) with a vertical field of view, fitted once per clip to the points it frames
(the whole head, :func:`~facesynth.domain.rendering.parts.frame_points`) so the view is steady:
the nearest place from which they fit with a margin, centred (:func:`fit_eye`).

World frame of the meshes facesynth draws: +y up, the face looks toward +z, +x is the
subject's left. Camera frame: the camera looks along its -z axis, +y up on the screen.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Fraction of the picture's half-width (or half-height) left free beyond the framed points on
#: the side where they bind (:meth:`Camera.fit`).
FRAME_MARGIN = 0.08


@dataclass(frozen=True)
class Camera:
    """rotation : (3, 3) world -> camera; eye : (3,) camera position in mesh units;
    focal_px : focal length in pixels; width, height : image size in pixels."""

    rotation: np.ndarray
    eye: np.ndarray
    focal_px: float
    width: int
    height: int

    @classmethod
    def orbit(cls, target: np.ndarray, half_extent: float, width: int, height: int, fov_deg: float,
              yaw_deg: float = 0.0, pitch_deg: float = 0.0) -> "Camera":
        """A camera looking at ``target`` (3,) from the direction given by ``yaw_deg`` (positive:
        from the subject's left, +x) and ``pitch_deg`` (positive: from above), far enough that a
        sphere of radius ``half_extent`` (mesh units) about the target fills the frame's
        shorter side."""
        rotation = view_rotation(yaw_deg, pitch_deg)
        tan_half = np.tan(np.deg2rad(fov_deg) / 2)
        focal = 0.5 * height / tan_half
        half_fov = min(tan_half, tan_half * width / height)
        distance = half_extent / np.sin(np.arctan(half_fov))
        return cls(rotation, np.asarray(target, np.float64) + distance * rotation[2], float(focal), width, height)

    @classmethod
    def fit(cls, points: np.ndarray, width: int, height: int, fov_deg: float, yaw_deg: float = 0.0,
            pitch_deg: float = 0.0, margin: float = FRAME_MARGIN) -> "Camera":
        """The nearest camera looking from the direction of ``yaw_deg`` and ``pitch_deg`` (as
        :meth:`orbit`) whose picture holds every one of ``points`` (n, 3) (the head's, from
        :func:`~facesynth.domain.rendering.parts.frame_points`; NaN rows ignored) with ``margin``
        of the half-size free on each side where the points bind, and their extremes centred:
        as far left of the middle as right, as far above as below (:func:`fit_eye`)."""
        rotation = view_rotation(yaw_deg, pitch_deg)
        tan_half = np.tan(np.deg2rad(fov_deg) / 2)
        eye = fit_eye(points, rotation, tan_half * width / height, tan_half, margin)
        return cls(rotation, eye, float(0.5 * height / tan_half), width, height)

    def scaled(self, factor: int) -> "Camera":
        """The same view at ``factor`` times the resolution (for supersampling)."""
        return Camera(self.rotation, self.eye, self.focal_px * factor, self.width * factor, self.height * factor)

    def to_camera(self, points: np.ndarray) -> np.ndarray:
        """(n, 3) world points -> (n, 3) camera-frame points."""
        return (np.asarray(points, np.float64) - self.eye) @ self.rotation.T

    def project(self, points: np.ndarray) -> np.ndarray:
        """(n, 3) world points -> (n, 4) float32: pixel x, pixel y, depth (> 0 in front), 0."""
        c = self.to_camera(points)
        depth = -c[:, 2]
        safe = np.where(depth > 1e-6, depth, 1e-6)
        x = self.width / 2 + self.focal_px * c[:, 0] / safe
        y = self.height / 2 - self.focal_px * c[:, 1] / safe
        return np.stack([x, y, depth, np.zeros_like(x)], 1).astype(np.float32)

    def directions(self, vectors: np.ndarray) -> np.ndarray:
        """(n, 3) world directions (normals) -> (n, 4) float32 camera-frame directions (w = 0)."""
        d = np.asarray(vectors, np.float64) @ self.rotation.T
        return np.concatenate([d, np.zeros((len(d), 1))], 1).astype(np.float32)


def view_rotation(yaw_deg: float, pitch_deg: float) -> np.ndarray:
    """(3, 3) world -> camera rotation (rows: right, up, back) of a camera looking from the
    direction ``yaw_deg`` (positive: from the subject's left, +x), ``pitch_deg`` (from above)."""
    yaw, pitch = np.deg2rad(yaw_deg), np.deg2rad(pitch_deg)
    back = np.array([np.sin(yaw) * np.cos(pitch), np.sin(pitch), np.cos(yaw) * np.cos(pitch)])
    right = np.cross([0.0, 1.0, 0.0], back)
    right /= np.linalg.norm(right)
    return np.stack([right, np.cross(back, right), back])


def _centre(coord: np.ndarray, depth_to: np.ndarray, iterations: int = 60) -> float:
    """The camera coordinate e (along one image axis) that centres points at ``coord`` (n,) with
    depths ``depth_to`` (n,) > 0 from the camera: max((coord - e) / depth) = -min(...), by
    bisection (the balance falls as e grows)."""
    lo, hi = float(coord.min()), float(coord.max())
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        u = (coord - mid) / depth_to
        lo, hi = (mid, hi) if u.max() + u.min() > 0 else (lo, mid)
    return 0.5 * (lo + hi)


def fit_eye(points: np.ndarray, rotation: np.ndarray, tan_x: float, tan_y: float, margin: float) -> np.ndarray:
    """The camera position (3,) world units, for a camera of ``rotation`` (3, 3) world -> camera
    whose picture spans tan_x and tan_y (the tangents of its horizontal and vertical half-angles),
    that holds ``points`` (n, 3) with ``margin`` (a fraction of the half-size) free on the side
    where they bind, their extremes centred in both directions.

    In camera coordinates (c, the camera looking along -z) a point projects to
    (c_x - e_x) / (e_z - c_z) in units of the picture's half-tangent, which must lie within
    +-a = +-(1 - margin) tan_x: e_x + a e_z >= max(c_x + a c_z) =: P and -e_x + a e_z >=
    max(-c_x + a c_z) =: Q, so the nearest e_z is (P + Q) / 2a (and likewise (R + S) / 2b for
    y); at the larger of the two, e_x and e_y are placed so the extremes are equally far from
    the middle (:func:`_centre`). The page (facesynth/data/player.html, ``fitEye``) does the same."""
    p = np.asarray(points, np.float64)
    p = p[np.isfinite(p).all(1)]
    if not len(p):
        raise ValueError("fit_eye needs at least one finite point")
    c = p @ np.asarray(rotation, np.float64).T
    a, b = (1.0 - margin) * tan_x, (1.0 - margin) * tan_y
    ez = max((np.max(c[:, 0] + a * c[:, 2]) + np.max(-c[:, 0] + a * c[:, 2])) / (2 * a),
             (np.max(c[:, 1] + b * c[:, 2]) + np.max(-c[:, 1] + b * c[:, 2])) / (2 * b))
    ez = max(ez, float(c[:, 2].max()) + 1e-6 * (1.0 + float(np.ptp(c))))  # every point in front
    depth = ez - c[:, 2]
    e = np.array([_centre(c[:, 0], depth), _centre(c[:, 1], depth), ez])
    return e @ np.asarray(rotation, np.float64)
