"""``facesynth isomap``: expressive phoneme-Isomaps (paper IV, Eq. 3, Figs. 5-7).

For each phoneme cluster (every frame of every node of one phone) a 2D Isomap with
``n_neighbors`` neighbours, the 2D PCA map of the same frames beside it (Fig. 5), and a
Delaunay triangulation of each map, so a picked 2D point gives a new frame by barycentric
interpolation of three captured frames (Fig. 7).

Large clusters: Isomap's geodesic distances and eigendecomposition grow as n^2 to n^3, so
at most ``max_exact_frames`` evenly spaced frames are embedded exactly and the others are
placed by Isomap's out-of-sample extension (the landmark approach). A cluster too small for
``n_neighbors`` uses one neighbour fewer than it has frames; below four frames its Isomap
map falls back to the PCA map. Both are reported.

Images (``--images DIR``): per phoneme a PNG of the Isomap and one of the PCA map,
rendered with Eq. 3 — each frame adds a Gaussian of peak ``rho`` in its emotion's colour
(black neutral, red angry, green sad, blue happy), clamped at 1 — with every motion node
drawn as a directed trajectory; ``index.html`` shows them all, and hovering a trajectory
names its node.
"""

from __future__ import annotations

import html
import time
import warnings
from pathlib import Path

import numpy as np
from scipy.ndimage import gaussian_filter
from scipy.spatial import Delaunay

from ..artifacts import check_output, check_output_folder
from ..config import IsomapSettings, settings_json
from ..errors import InputError
from ..model.isomap import Cluster, PhonemeMaps
from ..model.motiondb import MotionDatabase, Nodes
from ..progress import progress

EMOTION_COLOURS = {"neutral": (0, 0, 0), "angry": (220, 30, 30), "sad": (20, 160, 40), "happy": (30, 70, 230)}


def cluster_frames(nodes: Nodes, phone: str) -> tuple[np.ndarray, np.ndarray, np.ndarray, list[str]]:
    """All frames of the nodes of ``phone``, with node, relative time in the node and emotion."""
    frames, node, rel, emo = [], [], [], []
    for k in np.nonzero(np.array(nodes.phone) == phone)[0]:
        c = int(nodes.frame_count[k])
        frames.append(np.arange(nodes.frame_start[k], nodes.frame_start[k] + c))
        node.append(np.full(c, k))
        rel.append(np.linspace(0.0, 1.0, c))
        emo += [nodes.emotion[k]] * c
    return np.concatenate(frames), np.concatenate(node), np.concatenate(rel), emo


def pca_map(x: np.ndarray) -> np.ndarray:
    """Projection on the cluster's two largest principal axes (Fig. 5, left)."""
    centred = x - x.mean(0)
    _, _, vt = np.linalg.svd(centred, full_matrices=False)
    out = centred @ vt[:2].T
    if out.shape[1] < 2:
        out = np.pad(out, ((0, 0), (0, 2 - out.shape[1])))
    return out * np.sign(out[np.abs(out).argmax(0), [0, 1]] + 1e-30)


def embed(x: np.ndarray, n_neighbors: int, max_exact: int) -> tuple[np.ndarray, int, int, str]:
    """2D Isomap of x (n, K). Returns (embedding, neighbours used, frames embedded exactly, note)."""
    from sklearn.manifold import Isomap

    n = len(x)
    if n < 4:
        return pca_map(x), 0, 0, f"only {n} frames: shown as the PCA map"
    k = min(n_neighbors, n - 2)
    note = "" if k == n_neighbors else f"{n} frames: {k} neighbours instead of {n_neighbors}"
    exact = np.arange(n) if (max_exact <= 0 or n <= max_exact) else np.linspace(0, n - 1, max_exact).round().astype(int)
    model = Isomap(n_neighbors=k, n_components=2, eigen_solver="dense" if len(exact) < 600 else "arpack")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # disconnected neighbour graphs are completed by sklearn
        fitted = model.fit_transform(x[exact])
        out = np.empty((n, 2))
        out[exact] = fitted
        rest = np.setdiff1d(np.arange(n), exact)
        if len(rest):
            out[rest] = model.transform(x[rest])
    out *= np.sign(out[np.abs(out).argmax(0), [0, 1]] + 1e-30)  # fixed signs: deterministic output
    return out, k, len(exact), note


def build_clusters(coeffs: np.ndarray, nodes: Nodes, settings: IsomapSettings, phones: list[str] | None = None) -> list[Cluster]:
    """Embed every phoneme cluster (or those of ``phones``) of the database frames ``coeffs`` (F, K)."""
    out = []
    for phone in progress(phones or sorted(set(nodes.phone)), "isomap"):
        frames, node, rel, emo = cluster_frames(nodes, phone)
        x = coeffs[frames].astype(np.float64)
        iso, k, exact, note = embed(x, settings.n_neighbors, settings.max_exact_frames)
        flat = pca_map(x)
        out.append(Cluster(phone, frames, node, rel, emo, iso, flat, k, exact, note, coeffs[frames],
                           {"isomap": _triangulate(iso), "pca_map": _triangulate(flat)}))
    return out


def triangulate(points: np.ndarray) -> Delaunay | None:
    """The Delaunay triangulation of a 2D map (deterministic for the same points), or None if degenerate."""
    unique = np.unique(points.round(9), axis=0)
    if len(unique) < 3 or np.linalg.matrix_rank(unique - unique[0]) < 2:
        return None
    return Delaunay(points, qhull_options="QJ")


def barycentric_pick(points: np.ndarray, xy: tuple[float, float]) -> tuple[np.ndarray, np.ndarray] | None:
    """The triangle (three frame rows) holding xy and its barycentric weights, or None outside."""
    tri = triangulate(points)
    if tri is None:
        return None
    s = int(tri.find_simplex(np.array([xy], float))[0])
    if s < 0:
        return None
    t = tri.transform[s]
    b = t[:2] @ (np.asarray(xy, float) - t[2])
    return tri.simplices[s], np.array([b[0], b[1], 1.0 - b.sum()])


def render_map(points: np.ndarray, emotion: list[str], settings: IsomapSettings) -> tuple[np.ndarray, callable]:
    """Eq. 3 image of a 2D map (size x size x 3 uint8) and the map -> pixel transform."""
    size = settings.image_size
    lo, hi = points.min(0), points.max(0)
    span = np.maximum(hi - lo, 1e-9)
    margin = 0.06 * size

    def to_px(p):
        q = (np.asarray(p) - lo) / span
        return np.stack([margin + q[..., 0] * (size - 2 * margin), size - margin - q[..., 1] * (size - 2 * margin)], -1)

    px = to_px(points)
    image = np.ones((size, size, 3))
    emo = np.array(emotion)
    for name, colour in EMOTION_COLOURS.items():
        sel = emo == name
        if not sel.any():
            continue
        grid = np.zeros((size, size))
        ij = np.clip(np.round(px[sel]).astype(int), 0, size - 1)
        np.add.at(grid, (ij[:, 1], ij[:, 0]), 1.0)
        # A sum of unnormalized Gaussians of peak rho (Eq. 3), clamped at one.
        s = settings.kernel_sigma_px
        density = np.minimum(1.0, settings.rho * gaussian_filter(grid, s, mode="constant") * (2 * np.pi * s * s))
        image = image * (1 - density[..., None]) + (np.array(colour) / 255.0) * density[..., None]
    return (image * 255).astype(np.uint8), to_px


def save_cluster_images(cluster: Cluster, folder: Path, settings: IsomapSettings) -> list[dict]:
    """Write <phone>_isomap.png and <phone>_pca.png with node trajectories; return the
    trajectories (node, emotion, pixel polyline) of the Isomap image for the index page."""
    from PIL import Image, ImageDraw

    trajectories = []
    for kind, points in (("isomap", cluster.isomap), ("pca", cluster.pca_map)):
        image, to_px = render_map(points, cluster.emotion, settings)
        img = Image.fromarray(image)
        draw = ImageDraw.Draw(img)
        for k in np.unique(cluster.node):
            sel = cluster.node == k
            line = to_px(points[sel])
            colour = (120, 120, 120)
            if len(line) > 1:
                draw.line([tuple(p) for p in line], fill=colour, width=1)
                draw.ellipse([line[-1][0] - 2, line[-1][1] - 2, line[-1][0] + 2, line[-1][1] + 2], fill=(255, 140, 0))
            if kind == "isomap":
                emo = cluster.emotion[int(np.nonzero(sel)[0][0])]
                trajectories.append({"node": int(k), "emotion": emo, "points": line.round(1).tolist()})
        img.save(folder / f"{cluster.phone}_{kind}.png")
    return trajectories


def write_index(folder: Path, clusters: list[Cluster], trajectories: dict[str, list[dict]], size: int) -> None:
    """Write ``index.html`` showing every cluster's two maps, with node trajectories to hover."""
    parts = ["<!doctype html><meta charset='utf-8'><title>facesynth phoneme-Isomaps</title>",
             "<style>body{font-family:sans-serif} .pair{display:inline-block;margin:8px;vertical-align:top}"
             " .map{position:relative;display:inline-block} svg{position:absolute;left:0;top:0}"
             " polyline{fill:none;stroke:transparent;stroke-width:6} polyline:hover{stroke:orange}</style>",
             "<h1>Phoneme-Isomaps</h1><p>Left: Isomap; right: PCA map (paper Fig. 5). Black neutral, red angry,"
             " green sad, blue happy. Grey lines are motion nodes (orange dot: their end); hover a line for its node id.</p>"]
    for c in clusters:
        polylines = "".join(
            f"<polyline points='{' '.join(f'{x},{y}' for x, y in t['points'])}'><title>node {t['node']} ({t['emotion']})</title></polyline>"
            for t in trajectories.get(c.phone, []))
        note = f" — {html.escape(c.note)}" if c.note else ""
        parts.append(
            f"<div class='pair'><h2>/{html.escape(c.phone)}/ ({len(c.frames)} frames, {len(np.unique(c.node))} nodes){note}</h2>"
            f"<div class='map'><img src='{c.phone}_isomap.png' width={size} height={size}>"
            f"<svg width={size} height={size}>{polylines}</svg></div> "
            f"<img src='{c.phone}_pca.png' width={size} height={size}></div>")
    (folder / "index.html").write_text("\n".join(parts), encoding="utf-8")


def run(db_path: Path, out: Path, settings: IsomapSettings, images: Path | None = None, overwrite: bool = False) -> dict:
    """Embed every phoneme cluster of ``db_path``, write ``out`` (an ``isomap`` artifact) and,
    with ``images``, the PNGs and ``index.html`` there; returns a summary."""
    check_output(out, overwrite)
    if images is not None:
        check_output_folder(images, "the images")
    if settings.n_neighbors < 2:
        raise InputError("isomap.n_neighbors must be at least 2.")
    db = MotionDatabase.read(db_path)
    t0 = time.perf_counter()
    clusters = build_clusters(db.coeffs, db.nodes, settings)
    embed_s = time.perf_counter() - t0
    if images is not None:
        images.mkdir(parents=True, exist_ok=True)
        trajectories = {c.phone: save_cluster_images(c, images, settings) for c in progress(clusters, "images")}
        write_index(images, clusters, trajectories, settings.image_size)
    PhonemeMaps(db.model, db.marker_names, {c.phone: c for c in clusters}).write(
        out, config=settings_json(settings), inputs=[db_path], overwrite=overwrite)
    small = {c.phone: c.note for c in clusters if c.note}
    return {"clusters": len(clusters), "frames": int(sum(len(c.frames) for c in clusters)), "embed_s": embed_s,
            "largest": max(len(c.frames) for c in clusters), "notes": small}


def _triangulate(points: np.ndarray) -> np.ndarray:
    tri = triangulate(points)
    return np.zeros((0, 3), np.int32) if tri is None else tri.simplices.astype(np.int32)


def pick(isomap_path: Path, phone: str, x: float, y: float, use_pca_map: bool = False) -> tuple[np.ndarray, list[str], dict]:
    """Fig. 7: the frame at a picked 2D point as markers (M, 3) mm, by barycentric
    interpolation of the three captured frames of the covering triangle."""
    maps = PhonemeMaps.read(isomap_path)
    cluster = maps.cluster(phone, isomap_path)
    kind = "pca_map" if use_pca_map else "isomap"
    points = getattr(cluster, kind)
    hit = barycentric_pick(points, (x, y))
    if hit is None:
        lo, hi = points.min(0), points.max(0)
        raise InputError(
            f"/{phone}/: the point ({x:g}, {y:g}) lies outside the triangulation of its {kind.replace('_', ' ')} "
            f"(x {lo[0]:.3g} to {hi[0]:.3g}, y {lo[1]:.3g} to {hi[1]:.3g}); pick a point inside it."
        )
    corners, weights = hit
    frame = (weights[:, None] * cluster.coefficients[corners].astype(np.float64)).sum(0)
    info = {"corners": corners.tolist(), "weights": weights.round(6).tolist(), "nodes": cluster.node[corners].tolist()}
    return maps.model.reconstruct(frame[None])[0], maps.marker_names, info




def markers_csv(markers: np.ndarray, names: list[str]) -> list[str]:
    """Lines of a marker frame (M, 3) mm as CSV: ``marker,x_mm,y_mm,z_mm``."""
    return ["marker,x_mm,y_mm,z_mm"] + [f"{name},{x:.4f},{y:.4f},{z:.4f}" for name, (x, y, z) in zip(names, markers)]
