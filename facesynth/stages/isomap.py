"""``facesynth isomap``: expressive phoneme-Isomaps (paper IV, Eq. 3, Figs. 5-7).

The embeddings (for each phoneme cluster a 2D Isomap, the PCA map beside it and their Delaunay
triangulations; landmark Isomap for large clusters) and the barycentric pick of Fig. 7 are
:mod:`facesynth.domain.database.embedding`; this stage reads the database, writes the ``isomap`` artifact and
the images.

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
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.ndimage import gaussian_filter

from facesynth.base.config import IngestSettings, IsomapSettings, settings_json
from facesynth.base.errors import InputError
from facesynth.base.limits import require_memory
from facesynth.base.phonemes import PAU
from facesynth.base.progress import progress
from facesynth.domain import methods
from facesynth.domain.database.embedding import barycentric_pick, build_clusters, memory_estimate
from facesynth.domain.exports import isomap_page as export
from facesynth.domain.methods import steps
from facesynth.model.artifacts import atomic_folder, atomic_path, check_output, check_output_folder, published_together
from facesynth.model.isomap import Cluster, PhonemeMaps
from facesynth.model.motion import Motion
from facesynth.model.motiondb import MotionDatabase

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
            entry[kind] = {"t": [round(v, 6) for v in (t.x0, t.sx, t.y0, t.sy)],
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


@dataclass(frozen=True)
class PageResult:
    """What ``facesynth isomap page`` wrote.

    phones: spoken phones of the utterance.
    maps: phoneme maps on the page.
    missing: spoken phones the database has no node (and so no map) of.
    constraints: constraints given with ``--constraints``, shown on the page.
    bytes: the page's size.
    notes: warnings for the user.
    """

    phones: int
    maps: int
    missing: list[str]
    constraints: int
    bytes: int
    notes: list[str]


def page(isomap_path: Path, db_path: Path, phones_path: Path, out: Path, settings: IsomapSettings,
         ingest_settings: IngestSettings, emotions_path: Path | None = None, constraints_path: Path | None = None,
         motion_path: Path | None = None, overwrite: bool = False) -> PageResult:
    """Write the constraint page (paper VI-A, Fig. 9; :mod:`facesynth.domain.exports.isomap_page`) of
    an utterance over the maps of ``isomap_path`` built from ``db_path``, marking the path of
    the synthesized ``motion_path``."""
    import io

    check_output(out, overwrite)
    maps = PhonemeMaps.read(isomap_path)
    db = MotionDatabase.read(db_path)
    export.require_same_database(isomap_path, PhonemeMaps.KIND, "was built", db_path,
                                 f"run facesynth isomap build {db_path} -o ISOMAP.h5 and use that")
    export.check_maps(maps, db, isomap_path, db_path)
    utt = steps.read_utterance(ingest_settings, phones_path=phones_path, emotions_path=emotions_path).utterance
    constraints = steps.constraints_for(methods.get("dp"), db, constraints_path, utt)
    missing = export.require_some_map(utt, maps, phones_path, db_path)
    path, notes = None, []
    if motion_path is not None:
        export.require_same_database(motion_path, Motion.KIND, "was synthesized", db_path,
                                     f"give a motion synthesized from {db_path}, or that motion's database")
        path = export.check_path(Motion.read_search(motion_path)[0], utt, db, motion_path, phones_path, db_path)
        differ = export.emotion_differences(path, utt)
        if differ:
            k = differ[0]
            notes.append(f"{motion_path} was synthesized with other emotions than the page's at {len(differ)} phones "
                         f"(phone {k} /{utt.phones[k]}/: {path.emotion[k]}, not {utt.emotions[k]}); "
                         "give the --emotions it was made with")
    pictures = {}
    for phone in dict.fromkeys(utt.phones):
        if phone in maps.clusters:
            cluster = maps.clusters[phone]
            img, _ = map_image(cluster, "isomap", settings)
            png = io.BytesIO()
            img.save(png, format="png")
            t = map_transform(cluster.isomap, settings.image_size)
            pixels = np.stack([t.x0 + t.sx * cluster.isomap[:, 0], t.y0 + t.sy * cluster.isomap[:, 1]], -1)
            pictures[phone] = (png.getvalue(), pixels)
    data = export.page_data(maps, db, utt, constraints, path, pictures,
                            export.synthesize_command(db_path, phones_path, emotions_path))
    text = export.render_page(data, f"Constraints for {phones_path.name}", settings.image_size)
    with atomic_path(out, overwrite) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return PageResult(sum(p != PAU for p in utt.phones), len(pictures), missing, len(constraints),
                      len(text.encode("utf-8")), notes)
