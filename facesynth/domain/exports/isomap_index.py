"""The index page of the phoneme-Isomap pictures (``facesynth isomap build --images DIR``):
``index.html`` has an index of the phonemes at the top and shows every cluster's two maps
(:mod:`facesynth.domain.database.isomap_images`); hovering a map names the node, take and
emotion under the pointer with the point's coordinates, and a click gives the
``isomap pick`` command for the point. Self-contained: nothing is loaded from the network.
"""

from __future__ import annotations

import html
import json
from pathlib import Path

import numpy as np

from facesynth.base.config import IsomapSettings
from facesynth.base.progress import progress
from facesynth.domain.database.isomap_images import map_transform, save_cluster_images
from facesynth.model.isomap import Cluster


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


def write_images(folder: Path, clusters: list[Cluster], settings: IsomapSettings,
                 take_of_node: dict[int, str] | None = None) -> None:
    """Write every cluster's two map pictures and ``index.html`` into ``folder``."""
    trajectories = {c.phone: save_cluster_images(c, folder, settings) for c in progress(clusters, "images")}
    write_index(folder, clusters, trajectories, settings.image_size, take_of_node)
