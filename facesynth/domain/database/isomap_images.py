"""Pictures of the expressive phoneme-Isomaps (paper IV, Eq. 3, Figs. 5-7): per phoneme cluster
a PNG of its Isomap and one of its PCA map.

Each frame adds a Gaussian of peak ``rho`` in its emotion's colour (black neutral, red angry,
green sad, blue happy), clamped at 1 (Eq. 3); every motion node is drawn as a directed
trajectory and the axes are in map coordinates (the numbers ``facesynth isomap pick`` takes).
``facesynth isomap build --images`` writes them (with the index page of
:mod:`facesynth.domain.exports.isomap_index`), and the constraint page of
:mod:`facesynth.domain.exports.isomap_page` shows the Isomaps.
"""

from __future__ import annotations

import io
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.ndimage import gaussian_filter

from facesynth.base.config import IsomapSettings
from facesynth.model.isomap import Cluster, PhonemeMaps

EMOTION_COLOURS = {"neutral": (0, 0, 0), "angry": (220, 30, 30), "sad": (20, 160, 40), "happy": (30, 70, 230)}

PLOT_MARGINS = (0.14, 0.04, 0.04, 0.10)  # left, top, right, bottom: fractions of the image left for the axes
AXIS_COLOUR = (40, 40, 40)


def plot_box(size: int) -> tuple[int, int, int, int]:
    """The plotting area (x0, y0, x1, y1) in pixels of a ``size`` x ``size`` map image; the
    axes with their tick labels lie outside it, on the left and at the bottom."""
    left, top, right, bottom = PLOT_MARGINS
    return round(left * size), round(top * size), size - 1 - round(right * size), size - 1 - round(bottom * size)


def nice_ticks(lo: float, hi: float, target: int = 5) -> np.ndarray:
    """Round tick values inside [lo, hi], about ``target`` of them, 1, 2 or 5 times a power of ten apart."""
    raw = max(hi - lo, 1e-12) / max(target, 1)
    power = 10.0 ** np.floor(np.log10(raw))
    step = min((m * power for m in (1, 2, 5, 10)), key=lambda v: abs(np.log(v / raw)))
    first = np.ceil(lo / step - 1e-9) * step
    ticks = np.arange(first, hi + 1e-9 * step, step)
    return np.round(ticks / step) * step + 0.0  # no -0.0 or 0.30000000000000004


@dataclass(frozen=True)
class MapTransform:
    """The affine map -> pixel transform of a map image: ``px = x0 + sx * x``, ``py = y0 + sy * y``.

    x0, y0: pixel coordinates of the map's origin.
    sx, sy: pixels per map unit (sy < 0: y up).
    lo, hi: (x, y) the map range shown, in map units (the data range padded by 3%).
    """

    x0: float
    sx: float
    y0: float
    sy: float
    lo: tuple[float, float]
    hi: tuple[float, float]


def map_transform(points: np.ndarray, size: int) -> MapTransform:
    """The map -> pixel transform of a map image of ``points`` (N, 2), with the data range padded
    by 3% inside :func:`plot_box`."""
    lo, hi = points.min(0), points.max(0)
    span = np.maximum(hi - lo, 1e-9)
    lo, hi = lo - 0.03 * span, hi + 0.03 * span
    bx0, by0, bx1, by1 = plot_box(size)
    sx, sy = (bx1 - bx0) / (hi[0] - lo[0]), (by1 - by0) / (hi[1] - lo[1])
    # x0, sx, y0, sy stay NumPy float64 (a float): the page's JSON rounds them as before
    return MapTransform(bx0 - sx * lo[0], sx, by1 + sy * lo[1], -sy,
                        (float(lo[0]), float(lo[1])), (float(hi[0]), float(hi[1])))


#: scipy's Gaussian kernels reach ``int(KERNEL_TRUNCATE * sigma + 0.5)`` pixels from their centre.
KERNEL_TRUNCATE = 4.0


def render_map(points: np.ndarray, emotion: list[str], settings: IsomapSettings) -> tuple[np.ndarray, Callable]:
    """Eq. 3 image of a 2D map (size x size x 3 uint8) and the map -> pixel transform
    (:func:`map_transform`; the axes are drawn by :func:`draw_axes`).

    Each emotion's Gaussians are summed and blended only over the box its frames' kernels
    reach: outside it the density is exactly zero and the blend leaves the pixels as they are,
    and inside it each pixel's sum is the whole image's (the same kernel taps in the same order),
    so the picture is the one of blending every pixel."""
    size = settings.image_size
    t = map_transform(points, size)

    def to_px(p):
        p = np.asarray(p, float)
        return np.stack([t.x0 + t.sx * p[..., 0], t.y0 + t.sy * p[..., 1]], -1)

    px = to_px(points)
    image = np.ones((3, size, size))  # one plane per colour channel
    emo = np.array(emotion)
    s = settings.kernel_sigma_px
    reach = int(KERNEL_TRUNCATE * s + 0.5)
    for name, colour in EMOTION_COLOURS.items():
        sel = emo == name
        if not sel.any():
            continue
        ij = np.clip(np.round(px[sel]).astype(int), 0, size - 1)
        lo = np.maximum(ij.min(0) - reach, 0)
        hi = np.minimum(ij.max(0) + reach + 1, size)
        shape = (hi[1] - lo[1], hi[0] - lo[0])  # rows (y), columns (x)
        cells = (ij[:, 1] - lo[1]) * shape[1] + (ij[:, 0] - lo[0])
        grid = np.bincount(cells, minlength=shape[0] * shape[1]).astype(np.float64).reshape(shape)
        # A sum of unnormalized Gaussians of peak rho (Eq. 3), clamped at one.
        density = np.minimum(1.0, settings.rho * gaussian_filter(grid, s, mode="constant", truncate=KERNEL_TRUNCATE)
                             * (2 * np.pi * s * s))
        keep = 1 - density
        for plane, value in zip(image[:, lo[1]:hi[1], lo[0]:hi[0]], np.array(colour) / 255.0):
            plane *= keep
            if value:  # adding 0 leaves a pixel as it is
                plane += value * density
    return (image.transpose(1, 2, 0) * 255).astype(np.uint8), to_px


def draw_axes(img, points: np.ndarray, size: int) -> None:
    """Draw the plot frame with ticks and tick labels in map coordinates (the numbers
    ``facesynth isomap pick`` takes) on a map image (a Pillow image, changed in place)."""
    from PIL import ImageDraw

    draw = ImageDraw.Draw(img)
    t = map_transform(points, size)
    x0, y0, x1, y1 = plot_box(size)
    # Clear the margins (the Gaussians of points near the edge may spill into them), then the frame.
    for box in ((0, 0, x0 - 1, size - 1), (0, y1 + 1, size - 1, size - 1), (0, 0, size - 1, y0 - 1), (x1 + 1, 0, size - 1, size - 1)):
        draw.rectangle(box, fill=(255, 255, 255))
    draw.rectangle((x0, y0, x1, y1), outline=AXIS_COLOUR, width=1)
    for v in nice_ticks(t.lo[0], t.hi[0]):
        px = round(t.x0 + t.sx * v)
        draw.line([(px, y1), (px, y1 + 5)], fill=AXIS_COLOUR, width=1)
        label = f"{v:g}"
        w = draw.textlength(label)
        draw.text((px - w / 2, y1 + 7), label, fill=AXIS_COLOUR)
    for v in nice_ticks(t.lo[1], t.hi[1]):
        py = round(t.y0 + t.sy * v)
        draw.line([(x0 - 5, py), (x0, py)], fill=AXIS_COLOUR, width=1)
        label = f"{v:g}"
        w = draw.textlength(label)
        draw.text((x0 - 8 - w, py - 6), label, fill=AXIS_COLOUR)
    draw.text((x1 - 8, y1 + 20), "x", fill=AXIS_COLOUR)
    draw.text((4, y0), "y", fill=AXIS_COLOUR)


def save_cluster_images(cluster: Cluster, folder: Path, settings: IsomapSettings) -> list[dict]:
    """Write <phone>_isomap.png and <phone>_pca.png, with node trajectories and axes in map
    coordinates; return the trajectories (node, emotion, pixel polyline) of the Isomap
    image for the index page."""
    trajectories = []
    for kind in ("isomap", "pca"):
        img, lines = map_image(cluster, kind, settings)
        img.save(folder / f"{cluster.phone}_{kind}.png")
        if kind == "isomap":
            trajectories = lines
    return trajectories


def map_image(cluster: Cluster, kind: str, settings: IsomapSettings):
    """The Pillow image of one map of a cluster (``kind`` "isomap" or "pca"): Eq. 3 density,
    every motion node as a grey directed trajectory (orange dot at its end) and axes in map
    coordinates; with the trajectories (node, emotion, pixel polyline)."""
    from PIL import Image, ImageDraw

    points = cluster.isomap if kind == "isomap" else cluster.pca_map
    image, to_px = render_map(points, cluster.emotion, settings)
    img = Image.fromarray(image)
    draw = ImageDraw.Draw(img)
    trajectories = []
    for k in np.unique(cluster.node):
        sel = cluster.node == k
        line = to_px(points[sel])
        colour = (120, 120, 120)
        if len(line) > 1:
            draw.line([tuple(p) for p in line], fill=colour, width=1)
            draw.ellipse([line[-1][0] - 2, line[-1][1] - 2, line[-1][0] + 2, line[-1][1] + 2], fill=(255, 140, 0))
        emo = cluster.emotion[int(np.nonzero(sel)[0][0])]
        trajectories.append({"node": int(k), "emotion": emo, "points": line.round(1).tolist()})
    draw_axes(img, points, settings.image_size)
    return img, trajectories


def page_pictures(maps: PhonemeMaps, phones: Iterable[str], settings: IsomapSettings) -> dict[str, tuple[bytes, np.ndarray]]:
    """For each of ``phones`` (once each, in order) that has a map: its Isomap picture as PNG
    bytes and every cluster row's pixel position (n, 2) on it (what the constraint page shows)."""
    pictures = {}
    for phone in dict.fromkeys(phones):
        if phone in maps.clusters:
            cluster = maps.clusters[phone]
            img, _ = map_image(cluster, "isomap", settings)
            png = io.BytesIO()
            img.save(png, format="png")
            t = map_transform(cluster.isomap, settings.image_size)
            pixels = np.stack([t.x0 + t.sx * cluster.isomap[:, 0], t.y0 + t.sy * cluster.isomap[:, 1]], -1)
            pictures[phone] = (png.getvalue(), pixels)
    return pictures
