"""The Isomap page as a tool: axes in map coordinates on the images, a phoneme index, and a
hover script naming the node, take and emotion under the pointer with its coordinates,
checked in headless Chromium where it is installed."""

import json
import re
import subprocess

import numpy as np
import pytest
from chromium_page import CHROMIUM, remove_singleton_folder
from PIL import Image

from facesynth.base.config import Config
from facesynth.domain.database import isomap_images
from facesynth.model.isomap import PhonemeMaps
from facesynth.model.motiondb import MotionDatabase
from facesynth.stages import isomap

needs_chromium = pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium (Debian package 'chromium') is not installed")


@pytest.fixture(scope="module")
def page(tiny_db, tmp_path_factory):
    d = tmp_path_factory.mktemp("isopage")
    isomap.run(tiny_db, d / "iso.h5", Config.load().settings("isomap"), images=d / "img")
    return d


def _chromium(tmp_path, url, *args, timeout=120):
    profile = tmp_path / "profile"
    cmd = [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
           "--disable-component-update", "--disable-sync", "--no-first-run", f"--user-data-dir={profile}", *args, url]
    try:
        return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    finally:
        remove_singleton_folder(profile)


def test_tick_values_are_round_and_inside():
    ticks = isomap_images.nice_ticks(-47.3, 58.1)
    assert list(ticks) == [-40, -20, 0, 20, 40]
    assert list(isomap_images.nice_ticks(0.013, 0.071)) == pytest.approx([0.02, 0.03, 0.04, 0.05, 0.06, 0.07])


def test_images_have_axes_in_map_coordinates(page):
    maps = PhonemeMaps.read(page / "iso.h5")
    size = Config.load().settings("isomap").image_size
    x0, y0, x1, y1 = isomap_images.plot_box(size)
    for phone, c in maps.clusters.items():
        for kind, points in (("isomap", c.isomap), ("pca", c.pca_map)):
            img = np.asarray(Image.open(page / "img" / f"{phone}_{kind}.png").convert("L"))
            assert (img[y1, x0:x1 + 1] < 80).all() and (img[y0:y1 + 1, x0] < 80).all()  # the frame's bottom and left
            t = isomap_images.map_transform(points, size)
            for v in isomap_images.nice_ticks(t.lo[0], t.hi[0]):  # tick marks below the frame
                px = round(t.x0 + t.sx * v)
                assert (img[y1 + 1:y1 + 6, px] < 80).all()
            assert (img[y1 + 7:y1 + 20, x0:x1] < 128).any()  # tick labels
            # every frame lies inside the frame, where the transform puts it
            px = np.stack([t.x0 + t.sx * points[:, 0], t.y0 + t.sy * points[:, 1]], -1)
            assert (px[:, 0] > x0).all() and (px[:, 0] < x1).all() and (px[:, 1] > y0).all() and (px[:, 1] < y1).all()


def test_index_page_has_a_phoneme_index_and_point_data(page, tiny_db):
    text = (page / "img" / "index.html").read_text()
    maps = PhonemeMaps.read(page / "iso.h5")
    for phone in maps.clusters:
        assert f"href='#ph-{phone}'" in text and f"id='ph-{phone}'" in text
    assert "http://" not in text and "https://" not in text  # self-contained
    data = json.loads(re.search(r"<script type='application/json' id='mapdata'>(.*?)</script>", text, re.S).group(1))
    db = MotionDatabase.read(tiny_db)
    for phone, c in maps.clusters.items():
        assert len(data["maps"][phone]["isomap"]["p"]) == len(c.frames)
        x, y, node = data["maps"][phone]["pca"]["p"][0]
        assert (x, y) == pytest.approx(tuple(c.pca_map[0]), rel=1e-4, abs=1e-9) and node == c.node[0]
    node = str(int(maps.clusters["aa"].node[0]))
    assert data["nodes"][node] == [db.takes.name[int(db.nodes.take[int(node)])], db.nodes.emotion[int(node)]]


@needs_chromium
def test_page_in_headless_chromium_shows_axes_and_hover(page, tmp_path):
    shot = tmp_path / "shot.png"
    r = _chromium(tmp_path, (page / "img" / "index.html").as_uri(), f"--screenshot={shot}", "--window-size=1200,1000")
    assert shot.exists(), r.stderr[-2000:]
    img = np.asarray(Image.open(shot).convert("L")).astype(int)
    assert img.std() > 10 and (img < 60).mean() > 0.001  # not blank
    # The first map's axes: long straight dark lines (the plot frame) with the ticks' row below.
    dark = img < 100
    rows = [y for y in range(img.shape[0]) if _longest_run(dark[y]) > 300]
    cols = [x for x in range(img.shape[1]) if _longest_run(dark[:, x]) > 300]
    assert rows and cols, "no axis lines in the screenshot"

    # Hover: a synthetic pointer over the first frame of /aa/'s Isomap names its node, take and emotion.
    maps = PhonemeMaps.read(page / "iso.h5")
    c = maps.clusters[sorted(maps.clusters)[0]]
    t = isomap_images.map_transform(c.isomap, Config.load().settings("isomap").image_size)
    px, py = t.x0 + t.sx * c.isomap[0, 0], t.y0 + t.sy * c.isomap[0, 1]
    probe = page / "img" / "probe.html"
    probe.write_text((page / "img" / "index.html").read_text() + (
        "<script>var b=document.querySelector('.map').getBoundingClientRect();"
        f"var o={{clientX:b.left+{px:.3f},clientY:b.top+{py:.3f},bubbles:true}};"
        "var m=document.querySelector('.map');m.dispatchEvent(new MouseEvent('mousemove',o));"
        "m.dispatchEvent(new MouseEvent('click',o));</script>"))
    r = _chromium(tmp_path, probe.as_uri(), "--dump-dom")
    dom = r.stdout
    assert 'data-hover="ready"' in dom and "<nav id=\"index\"" in dom, r.stderr[-2000:]
    tip = re.search(r'<div id="tip"[^>]*>(.*?)</div>', dom, re.S).group(1)
    node = int(c.node[0])
    db_take = json.loads(re.search(r"id=\"mapdata\">(.*?)</script>", dom, re.S).group(1))["nodes"][str(node)]
    assert f"node {node}, take {db_take[0]}, {c.emotion[0]}" in tip
    x, y = (float(v) for v in re.search(r"x y: (\S+) (\S+)", tip).groups())
    assert (x, y) == pytest.approx(tuple(c.isomap[0]), abs=2.0 / t.sx)  # within two pixels
    assert f"isomap pick isomap.h5 {c.phone} " in tip


def _longest_run(line: np.ndarray) -> int:
    best = run = 0
    for v in line:
        run = run + 1 if v else 0
        best = max(best, run)
    return best
