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
drawn as a directed trajectory and axes in map coordinates (the numbers ``isomap pick``
takes); ``index.html`` has an index of the phonemes at the top and shows them all: hovering
a map names the node, take and emotion under the pointer with the point's coordinates, and
a click gives the ``isomap pick`` command for the point.
"""

from __future__ import annotations

import contextlib
import html
import time
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.ndimage import gaussian_filter
from scipy.spatial import Delaunay

from ..artifacts import atomic_folder, check_output, check_output_folder, published_together
from ..config import IsomapSettings, settings_json
from ..errors import InputError
from ..limits import require_memory
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


def map_transform(points: np.ndarray, size: int) -> dict:
    """The affine map -> pixel transform of a map image: ``px = x0 + sx * x``, ``py = y0 + sy * y``
    (sy < 0: y up), with the data range padded by 3% inside :func:`plot_box`."""
    lo, hi = points.min(0), points.max(0)
    span = np.maximum(hi - lo, 1e-9)
    lo, hi = lo - 0.03 * span, hi + 0.03 * span
    bx0, by0, bx1, by1 = plot_box(size)
    sx, sy = (bx1 - bx0) / (hi[0] - lo[0]), (by1 - by0) / (hi[1] - lo[1])
    return {"x0": bx0 - sx * lo[0], "sx": sx, "y0": by1 + sy * lo[1], "sy": -sy,
            "lo": [float(lo[0]), float(lo[1])], "hi": [float(hi[0]), float(hi[1])]}


def render_map(points: np.ndarray, emotion: list[str], settings: IsomapSettings) -> tuple[np.ndarray, Callable]:
    """Eq. 3 image of a 2D map (size x size x 3 uint8) and the map -> pixel transform
    (:func:`map_transform`; the axes are drawn by :func:`draw_axes`)."""
    size = settings.image_size
    t = map_transform(points, size)

    def to_px(p):
        p = np.asarray(p, float)
        return np.stack([t["x0"] + t["sx"] * p[..., 0], t["y0"] + t["sy"] * p[..., 1]], -1)

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
    for v in nice_ticks(t["lo"][0], t["hi"][0]):
        px = round(t["x0"] + t["sx"] * v)
        draw.line([(px, y1), (px, y1 + 5)], fill=AXIS_COLOUR, width=1)
        label = f"{v:g}"
        w = draw.textlength(label)
        draw.text((px - w / 2, y1 + 7), label, fill=AXIS_COLOUR)
    for v in nice_ticks(t["lo"][1], t["hi"][1]):
        py = round(t["y0"] + t["sy"] * v)
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
        draw_axes(img, points, settings.image_size)
        img.save(folder / f"{cluster.phone}_{kind}.png")
    return trajectories


def hover_data(clusters: list[Cluster], size: int, take_of_node: dict[int, str] | None = None) -> dict:
    """What the index page's hover script needs: per phoneme and map the map -> pixel
    transform and every frame as ``[x, y, node]`` in map coordinates; per node its take and
    emotion."""
    maps, nodes = {}, {}
    take_of_node = take_of_node or {}
    for c in clusters:
        entry = {}
        for kind, points in (("isomap", c.isomap), ("pca", c.pca_map)):
            t = map_transform(points, size)
            entry[kind] = {"t": [round(t[k], 6) for k in ("x0", "sx", "y0", "sy")],
                           "p": [[float(f"{x:.5g}"), float(f"{y:.5g}"), int(n)] for (x, y), n in zip(points, c.node)]}
        maps[c.phone] = entry
        for n in np.unique(c.node):
            emo = c.emotion[int(np.nonzero(c.node == n)[0][0])]
            nodes[str(int(n))] = [take_of_node.get(int(n), ""), emo]
    return {"maps": maps, "nodes": nodes}


HOVER_SCRIPT = r"""
(function () {
  var data = JSON.parse(document.getElementById('mapdata').textContent);
  var tip = document.getElementById('tip');
  function nearest(points, x, y, t) {
    var best = -1, bestD = 1e300;
    for (var i = 0; i < points.length; i++) {
      var dx = (points[i][0] - x) * t[1], dy = (points[i][1] - y) * t[3];
      var d = dx * dx + dy * dy;
      if (d < bestD) { bestD = d; best = i; }
    }
    return bestD <= 100 ? points[best] : null;  /* within 10 pixels */
  }
  document.querySelectorAll('.map').forEach(function (box) {
    var phone = box.dataset.phone, kind = box.dataset.kind, m = data.maps[phone][kind];
    var t = m.t, flag = kind === 'pca' ? ' --pca-map' : '';
    function at(ev) {
      var r = box.getBoundingClientRect();
      var px = ev.clientX - r.left, py = ev.clientY - r.top;
      return [(px - t[0]) / t[1], (py - t[2]) / t[3]];
    }
    box.addEventListener('mousemove', function (ev) {
      var xy = at(ev), hit = nearest(m.p, xy[0], xy[1], t);
      var coords = xy[0].toPrecision(4) + ' ' + xy[1].toPrecision(4);
      var text = '/' + phone + '/ ' + (kind === 'pca' ? 'PCA map' : 'Isomap') + '  x y: ' + coords;
      if (hit) {
        var n = data.nodes[String(hit[2])];
        text = 'node ' + hit[2] + ', take ' + n[0] + ', ' + n[1] + '\n' + text;
      }
      tip.textContent = text + '\nclick to copy: isomap pick isomap.h5 ' + phone + ' ' + coords + flag;
      tip.style.left = (ev.pageX + 14) + 'px'; tip.style.top = (ev.pageY + 14) + 'px';
      tip.style.display = 'block';
    });
    box.addEventListener('mouseleave', function () { tip.style.display = 'none'; });
    box.addEventListener('click', function (ev) {
      var xy = at(ev), line = 'facesynth isomap pick isomap.h5 ' + phone + ' ' + xy[0].toPrecision(4) + ' ' + xy[1].toPrecision(4) + flag;
      document.getElementById('picked').value = line;
      if (navigator.clipboard) { navigator.clipboard.writeText(line).catch(function () {}); }
    });
  });
  document.body.dataset.hover = 'ready';
})();
"""


def write_index(folder: Path, clusters: list[Cluster], trajectories: dict[str, list[dict]], size: int,
                take_of_node: dict[int, str] | None = None) -> None:
    """Write ``index.html``: an index of the phonemes at the top, then every cluster's two
    maps (axes in map coordinates). Hovering a map shows the node, take and emotion under
    the pointer and the point's coordinates; clicking puts the ``isomap pick`` command for
    it in the box at the top (and on the clipboard). Self-contained: the point data is
    embedded as JSON, nothing is loaded from the network."""
    import json

    data = json.dumps(hover_data(clusters, size, take_of_node), separators=(",", ":")).replace("</", "<\\/")
    index = " ".join(f"<a href='#ph-{html.escape(c.phone)}'>/{html.escape(c.phone)}/</a>" for c in clusters)
    parts = ["<!doctype html><meta charset='utf-8'><title>facesynth phoneme-Isomaps</title>",
             "<style>body{font-family:sans-serif} .pair{display:inline-block;margin:8px;vertical-align:top}"
             " .map{position:relative;display:inline-block;cursor:crosshair} svg{position:absolute;left:0;top:0}"
             " polyline{fill:none;stroke:transparent;stroke-width:6} polyline:hover{stroke:orange}"
             " #index{position:sticky;top:0;background:#fff;padding:4px 0;border-bottom:1px solid #ccc;line-height:1.6}"
             " #index a{margin-right:6px} #picked{width:40em;font-family:monospace}"
             " #tip{position:absolute;display:none;white-space:pre;background:#ffe;border:1px solid #888;"
             "padding:3px 5px;font:12px monospace;pointer-events:none;z-index:9}</style>",
             "<h1>Phoneme-Isomaps</h1>",
             f"<nav id='index'>Phonemes: {index}<br><label>Picked point: <input id='picked' readonly"
             " placeholder='click a map: the isomap pick command for that point'></label></nav>",
             "<p>Left: Isomap; right: PCA map (paper Fig. 5). Black neutral, red angry, green sad, blue happy."
             " Grey lines are motion nodes (orange dot: their end). The axes are in map coordinates, the numbers"
             " <code>facesynth isomap pick ISOMAP.h5 PHONE X Y</code> takes (<code>--pca-map</code> for the right map)."
             " Hover a map for the node, take and emotion under the pointer and the point's coordinates;"
             " click to copy the pick command.</p>",
             "<div id='tip'></div>"]
    for c in clusters:
        polylines = "".join(
            f"<polyline points='{' '.join(f'{x},{y}' for x, y in t['points'])}'><title>node {t['node']} ({t['emotion']})</title></polyline>"
            for t in trajectories.get(c.phone, []))
        note = f" — {html.escape(c.note)}" if c.note else ""
        phone = html.escape(c.phone)
        parts.append(
            f"<div class='pair' id='ph-{phone}'><h2>/{phone}/ ({len(c.frames)} frames, {len(np.unique(c.node))} nodes){note}</h2>"
            f"<div class='map' data-phone='{phone}' data-kind='isomap'><img src='{phone}_isomap.png' width={size} height={size} alt='Isomap of /{phone}/'>"
            f"<svg width={size} height={size}>{polylines}</svg></div> "
            f"<div class='map' data-phone='{phone}' data-kind='pca'><img src='{phone}_pca.png' width={size} height={size} alt='PCA map of /{phone}/'></div></div>")
    parts.append(f"<script type='application/json' id='mapdata'>{data}</script>")
    parts.append(f"<script>{HOVER_SCRIPT}</script>")
    (folder / "index.html").write_text("\n".join(parts), encoding="utf-8")


def memory_estimate(nodes: Nodes, settings: IsomapSettings) -> float:
    """Bytes the largest cluster's Isomap needs: its exactly embedded frames' geodesic distances
    (n x n float64), the neighbour graph's shortest paths and the double-centred copy, about
    three n x n float64 arrays."""
    counts: dict[str, int] = {}
    for phone, c in zip(nodes.phone, nodes.frame_count):
        counts[phone] = counts.get(phone, 0) + int(c)
    largest = max(counts.values(), default=0)
    exact = largest if settings.max_exact_frames <= 0 else min(largest, settings.max_exact_frames)
    return 3.0 * 8 * exact * exact


@dataclass(frozen=True)
class IsomapResult:
    """What ``facesynth isomap build`` embedded.

    clusters: phoneme clusters embedded.
    frames: frames over all clusters.
    embed_s: seconds spent embedding them.
    largest: frames of the largest cluster.
    notes: per phone, why a small cluster got fewer neighbours (expected; shown with -v).
    """

    clusters: int
    frames: int
    embed_s: float
    largest: int
    notes: dict[str, str]


@dataclass(frozen=True)
class Pick:
    """The frame at a point picked on a phoneme's map (``facesynth isomap pick``).

    markers: (M, 3) the frame's markers, mm.
    marker_names: their names.
    corners: the three frames (rows of the cluster) of the triangle around the point.
    weights: their barycentric weights, summing to 1.
    nodes: the motion nodes those frames belong to.
    """

    markers: np.ndarray
    marker_names: list[str]
    corners: list[int]
    weights: list[float]
    nodes: list[int]


def run(db_path: Path, out: Path, settings: IsomapSettings, images: Path | None = None,
        overwrite: bool = False) -> IsomapResult:
    """Embed every phoneme cluster of ``db_path``, write ``out`` (an ``isomap`` artifact) and,
    with ``images``, the PNGs and ``index.html`` there."""
    check_output(out, overwrite)
    if images is not None:
        check_output_folder(images, "the images", overwrite)
    if settings.n_neighbors < 2:
        raise InputError("isomap.n_neighbors must be at least 2.")
    db = MotionDatabase.read(db_path)
    require_memory(memory_estimate(db.nodes, settings), "embedding the largest phoneme cluster", str(db_path))
    t0 = time.perf_counter()
    clusters = build_clusters(db.coeffs, db.nodes, settings)
    embed_s = time.perf_counter() - t0
    with published_together(), contextlib.ExitStack() as stack:  # the artifact and the images, or neither
        if images is not None:  # written beside the folder, renamed into place after the artifact
            folder = stack.enter_context(atomic_folder(images, "the images", overwrite))
            trajectories = {c.phone: save_cluster_images(c, folder, settings) for c in progress(clusters, "images")}
            take_of_node = {k: db.takes.name[int(db.nodes.take[k])] for k in range(len(db.nodes))}
            write_index(folder, clusters, trajectories, settings.image_size, take_of_node)
        PhonemeMaps(db.model, db.marker_names, {c.phone: c for c in clusters}).write(
            out, config=settings_json(settings), inputs=[db_path], overwrite=overwrite)
    small = {c.phone: c.note for c in clusters if c.note}
    return IsomapResult(len(clusters), int(sum(len(c.frames) for c in clusters)), embed_s,
                        max(len(c.frames) for c in clusters), small)


def _triangulate(points: np.ndarray) -> np.ndarray:
    tri = triangulate(points)
    return np.zeros((0, 3), np.int32) if tri is None else tri.simplices.astype(np.int32)


def pick(isomap_path: Path, phone: str, x: float, y: float, use_pca_map: bool = False) -> Pick:
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
    return Pick(maps.model.reconstruct(frame[None])[0], maps.marker_names, corners.tolist(), weights.round(6).tolist(),
                cluster.node[corners].tolist())





def markers_csv(markers: np.ndarray, names: list[str]) -> list[str]:
    """Lines of a marker frame (M, 3) mm as CSV: ``marker,x_mm,y_mm,z_mm``."""
    return ["marker,x_mm,y_mm,z_mm"] + [f"{name},{x:.4f},{y:.4f},{z:.4f}" for name, (x, y, z) in zip(names, markers)]
