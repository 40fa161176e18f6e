"""A perspective camera that orbits a target point: yaw about the world's up axis (+y),
pitch above the horizon, vertical field of view, fitted once per clip so the view is steady.

World frame of the meshes facesynth draws: +y up, the face looks toward +z, +x is the
subject's left. Camera frame: the camera looks along its -z axis, +y up on the screen.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


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
        yaw, pitch = np.deg2rad(yaw_deg), np.deg2rad(pitch_deg)
        back = np.array([np.sin(yaw) * np.cos(pitch), np.sin(pitch), np.cos(yaw) * np.cos(pitch)])
        right = np.cross([0.0, 1.0, 0.0], back)
        right /= np.linalg.norm(right)
        up = np.cross(back, right)
        tan_half = np.tan(np.deg2rad(fov_deg) / 2)
        focal = 0.5 * height / tan_half
        half_fov = min(tan_half, tan_half * width / height)
        distance = half_extent / np.sin(np.arctan(half_fov))
        rotation = np.stack([right, up, back])
        return cls(rotation, np.asarray(target, np.float64) + distance * back, float(focal), width, height)

    @classmethod
    def fit(cls, vertices: np.ndarray, width: int, height: int, fov_deg: float, yaw_deg: float = 0.0,
            pitch_deg: float = 0.0, focus: tuple[np.ndarray, float] | None = None) -> "Camera":
        """A camera whose view holds ``vertices`` (V, 3), or the sphere ``focus`` = (centre (3,),
        radius) when given (the face region, so a long neck does not shrink the face)."""
        centre, radius = framing(vertices, focus)
        return cls.orbit(centre, radius, width, height, fov_deg, yaw_deg, pitch_deg)

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


def framing(vertices: np.ndarray, focus: tuple[np.ndarray, float] | None = None) -> tuple[np.ndarray, float]:
    """The sphere (centre (3,), radius, mesh units) :meth:`Camera.fit` frames: ``focus`` when
    given, else one about the bounding box of ``vertices`` (V, 3) (0.8 of its half diagonal)."""
    if focus is not None:
        return np.asarray(focus[0], np.float64), float(focus[1])
    lo, hi = np.nanmin(vertices, 0), np.nanmax(vertices, 0)
    return (lo + hi) / 2, 0.5 * float(np.linalg.norm(hi - lo)) * 0.8
