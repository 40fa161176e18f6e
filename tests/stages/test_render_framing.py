"""``facesynth render`` frames the whole head, centred (and the pages, which fit the same camera:
tests/exports/test_player_face.py and test_player_live.py compare their pictures with render's):
the camera's fit on its own, on the built-in rig's head (not its neck) and on a closed mesh."""

import dataclasses
from types import SimpleNamespace

import numpy as np
import pytest

from facesynth.base.config import Config
from facesynth.domain.rendering import parts
from facesynth.domain.rendering.camera import FRAME_MARGIN, Camera
from facesynth.domain.rendering.raster import BACKGROUND
from facesynth.domain.rendering.video import ShadedView
from facesynth.domain.rig.face import load_face_rig

BG = np.round(np.asarray(BACKGROUND) * 255).astype(int)


def _extremes(camera: Camera, points: np.ndarray) -> np.ndarray:
    """Free pixels left, right, above and below the projected ``points``."""
    px = camera.project(points)[:, :2].astype(np.float64)
    return np.array([px[:, 0].min(), camera.width - px[:, 0].max(), px[:, 1].min(), camera.height - px[:, 1].max()])


@pytest.mark.parametrize(("width", "height", "yaw", "pitch"), [(640, 480, 25.0, 6.0), (240, 320, -40.0, -20.0),
                                                                (300, 300, 0.0, 0.0)])
def test_the_fit_centres_the_points_with_the_margin_where_they_bind(width, height, yaw, pitch):
    points = np.random.default_rng(3).normal(size=(500, 3)) * [60.0, 90.0, 70.0] + [5.0, -20.0, 40.0]
    camera = Camera.fit(points, width, height, 30.0, yaw, pitch)
    left, right, top, bottom = _extremes(camera, points)
    assert left == pytest.approx(right, abs=0.01) and top == pytest.approx(bottom, abs=0.01)  # centred both ways
    # the side that binds keeps exactly the margin (of the half-size); the other at least that
    binding = min(left / (width / 2), top / (height / 2))
    assert binding == pytest.approx(FRAME_MARGIN, abs=1e-6)
    assert left / (width / 2) >= FRAME_MARGIN - 1e-6 and top / (height / 2) >= FRAME_MARGIN - 1e-6
    assert np.all(camera.to_camera(points)[:, 2] < 0)  # every point in front of the camera
    # and it is the nearest such camera: 1 % nearer, the binding side keeps less than the margin
    nearer = dataclasses.replace(camera, eye=camera.eye - 0.01 * np.linalg.norm(camera.eye - points.mean(0)) * camera.rotation[2])
    free = _extremes(nearer, points) / np.array([width, width, height, height]) * 2
    assert free.min() < 0.9 * FRAME_MARGIN


def _rendered(rest: np.ndarray, faces: np.ndarray, width: int, height: int) -> np.ndarray:
    settings = dataclasses.replace(Config.load().settings("render"), width=width, height=height, supersample=1,
                                   use_opencl=False)
    return ShadedView(SimpleNamespace(rest=rest, faces=faces, gaze=None), settings, width).frame(rest, 0)


def _box(img: np.ndarray) -> np.ndarray:
    """Free pixels left, right, above and below what is not background."""
    ys, xs = np.nonzero(np.abs(img.astype(int) - BG).max(axis=2) > 3)
    h, w = img.shape[:2]
    return np.array([xs.min(), w - 1 - xs.max(), ys.min(), h - 1 - ys.max()])


@pytest.mark.parametrize(("width", "height"), [(320, 240), (200, 300)])
def test_the_rigs_whole_head_is_in_the_frame_and_centred(width, height):
    rig = load_face_rig()
    img = _rendered(rig.neutral, rig.faces, width, height)
    left, right, top, _ = _box(img)
    # the top of the head is in the picture, with a margin (the old brow-to-chin framing cut it)
    assert top >= 0.5 * FRAME_MARGIN * height / 2
    # the head, ears and all, between the sides, centred (its silhouette: the neck below it is wider than
    # nothing, so the sides are measured above the chin)
    scene = parts.build_scene(rig.neutral, rig.faces)
    settings = dataclasses.replace(Config.load().settings("render"), width=width, height=height)
    camera = Camera.fit(parts.frame_points(scene), width, height, settings.fov_deg, settings.yaw_deg, settings.pitch_deg)
    chin_row = int(camera.project(parts.frame_points(scene))[:, 1].max())
    head = img[:chin_row]
    ys, xs = np.nonzero(np.abs(head.astype(int) - BG).max(axis=2) > 3)
    sides = np.array([xs.min(), width - 1 - xs.max()])
    assert sides.min() >= 0.5 * FRAME_MARGIN * min(width, height) / 2
    assert abs(sides[0] - sides[1]) <= 0.03 * width
    # the chin is in the picture above its bottom edge, the head centred top to bottom
    free_below = height - 1 - chin_row
    assert free_below >= 0.5 * FRAME_MARGIN * height / 2 and abs(free_below - top) <= 0.03 * height


def _ellipsoid(radii=(70.0, 100.0, 80.0), centre=(10.0, 150.0, -30.0), rings: int = 24, segments: int = 32):
    theta = np.linspace(0.0, np.pi, rings + 1)[1:-1]
    phi = np.arange(segments) * 2 * np.pi / segments
    ring = np.stack([np.sin(theta)[:, None] * np.cos(phi), np.cos(theta)[:, None] * np.ones_like(phi),
                     np.sin(theta)[:, None] * np.sin(phi)], -1).reshape(-1, 3)
    vertices = np.concatenate([[[0.0, 1.0, 0.0]], ring, [[0.0, -1.0, 0.0]]]) * radii + centre
    n, last = len(theta), 1 + len(ring)
    top = np.stack([np.zeros(segments, int), 1 + (np.arange(segments) + 1) % segments, 1 + np.arange(segments)], 1)
    grid = 1 + parts._grid_faces(n, segments, closed=True)
    base = 1 + (n - 1) * segments
    bottom = np.stack([np.full(segments, last), base + np.arange(segments), base + (np.arange(segments) + 1) % segments], 1)
    return vertices, np.concatenate([top, grid, bottom])


@pytest.mark.parametrize(("width", "height"), [(320, 240), (200, 300)])
def test_a_mesh_without_a_face_is_framed_whole_and_centred(width, height):
    vertices, faces = _ellipsoid()
    left, right, top, bottom = _box(_rendered(vertices, faces, width, height))
    margin = 0.5 * FRAME_MARGIN * min(width, height) / 2
    assert min(left, right, top, bottom) >= margin  # inside, with a margin on every side
    assert abs(left - right) <= 0.03 * width and abs(top - bottom) <= 0.03 * height  # centred
