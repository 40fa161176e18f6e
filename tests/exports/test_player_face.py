"""The player shows the whole face, as ``facesynth render`` draws it, opened in headless Chromium
(the Debian package ``chromium``) and driven over the DevTools protocol: the picture is render's
(same parts, shading and camera), the eyes are there, the open mouth is dark inside, the head
moves with the head motion, and the timeline is the synthesized path, the current phone
highlighted and a click on a phone seeking to it."""

import dataclasses

import numpy as np
import pytest
from chromium_page import CHROMIUM, ChromiumPage
from scipy.spatial.transform import Rotation

from facesynth.base.config import Config
from facesynth.domain.exports.animation import load
from facesynth.domain.rendering.camera import Camera
from facesynth.domain.rendering.parts import build_scene, frame_points
from facesynth.domain.rendering.raster import BACKGROUND
from facesynth.domain.rendering.video import ShadedView
from facesynth.model.curves import RigCurves
from facesynth.model.meshanim import MeshAnimation
from facesynth.model.motion import Motion
from facesynth.stages import player, rig_mesh, solve, synthesize

pytest.importorskip("websockets", reason="the DevTools protocol client needs the websockets package")
pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium (Debian package 'chromium') is not installed")

WIDTH, HEIGHT = 640, 700
BG = np.round(np.asarray(BACKGROUND) * 255).astype(int)


@pytest.fixture(scope="module")
def made(tiny_db, tiny_corpus, held_out_take, tmp_path_factory):
    config = Config.load()
    d = tmp_path_factory.mktemp("player_face")
    synthesize.run(tiny_db, d / "m.h5", config.settings("synthesize"), config.settings("ingest"),
                   config.settings("align"), phones_path=tiny_corpus / "labels" / f"{held_out_take}.TextGrid")
    solve.run(d / "m.h5", d / "c.h5", config.settings("solve"))
    rig_mesh.run(d / "c.h5", d / "r.h5")
    # the same curves with a head that turns 20 degrees toward +x (yaw about +y) over the clip
    c = RigCurves.read(d / "c.h5")
    yaw = np.linspace(0.0, 20.0, c.n_frames)
    turned = dataclasses.replace(c, head_rotation=Rotation.from_euler("y", yaw[:, None], degrees=True).as_matrix().astype(np.float32),
                                 head_translation=np.zeros((c.n_frames, 3), np.float32))
    turned.write(d / "turned.h5", config="{}", inputs=[d / "c.h5"])
    # and with both eyes looking toward +x in the first half and toward -x in the second
    w = c.weights.copy()
    half = c.n_frames // 2
    for name, first, second in (("eyeLookOut_L", 1, 0), ("eyeLookIn_R", 1, 0), ("eyeLookIn_L", 0, 1), ("eyeLookOut_R", 0, 1)):
        k = c.shape_names.index(name)
        w[:half, k], w[half:, k] = 0.6 * first, 0.6 * second
    dataclasses.replace(c, weights=w).write(d / "gaze.h5", config="{}", inputs=[d / "c.h5"])
    # and a jaw alone opening from rest to jawOpen 0.5, every other weight 0 (the renderer's case,
    # whatever the sample corpus's lips do)
    w = np.zeros_like(c.weights)
    w[:, c.shape_names.index("jawOpen")] = np.linspace(0.0, 0.5, c.n_frames)
    dataclasses.replace(c, weights=w).write(d / "open.h5", config="{}", inputs=[d / "c.h5"])
    rig_mesh.run(d / "open.h5", d / "open_r.h5")
    for name in ("c", "turned", "gaze", "open"):
        player.run(d / f"{name}.h5", d / f"{name}.html")
    return d


@pytest.fixture(scope="module")
def page(made, tmp_path_factory):
    with ChromiumPage((made / "c.html").as_uri() + "#head=0", tmp_path_factory.mktemp("profile"), WIDTH, HEIGHT) as p:
        yield p


def _view(page, t: float, parts: bool = True) -> tuple[np.ndarray, dict]:
    """The 3D view (H, W, 3) uint8 at time ``t`` and the page's state."""
    page.evaluate(f"document.getElementById('parts').checked = {'true' if parts else 'false'}; player.seek({t})")
    state = page.dataset()
    assert state["errors"] == "0", state["error-text"]
    h = page.evaluate("document.getElementById('view').clientHeight")
    return page.screenshot()[:h], state


def _box(img: np.ndarray, xy, r: int = 3) -> np.ndarray:
    x, y = (int(round(v)) for v in xy)
    return img[y - r:y + r + 1, x - r:x + r + 1].reshape(-1, 3).astype(int)


def _open_and_closed(made) -> tuple[int, int]:
    """Frames of the widest and the least open mouth (rig weight jawOpen)."""
    c = RigCurves.read(made / "c.h5")
    jaw = c.weights[:, c.shape_names.index("jawOpen")]
    return int(jaw.argmax()), int(jaw.argmin())


def test_the_page_draws_what_render_draws(made, page):
    a = MeshAnimation.read(made / "r.h5")
    frame, _ = _open_and_closed(made)
    img, state = _view(page, (frame + 0.5) / a.fps)
    assert int(state["frame"]) == frame
    h, w = img.shape[:2]
    settings = dataclasses.replace(Config.load().settings("render"), width=w, height=h, use_opencl=False)
    ref = ShadedView(a, settings, w).frame(a.vertices[frame], frame)
    face = np.abs(ref.astype(int) - BG).max(axis=2) > 3
    diff = np.abs(img.astype(int) - ref.astype(int)).max(axis=2)[face]
    assert face.mean() > 0.1  # the face fills a good part of the view
    # the same geometry, lights and camera: nearly every face pixel within a few levels (the
    # rest: edges, where two rasterizers' anti-aliasing differ)
    assert np.mean(diff <= 3) > 0.85 and np.mean(diff > 40) < 0.03
    assert (img[:5, :5] == BG).all()  # the renderer's background


def test_eyes_are_where_render_puts_them_and_are_drawn(made, page):
    a = MeshAnimation.read(made / "r.h5")
    frame, _ = _open_and_closed(made)
    img, state = _view(page, (frame + 0.5) / a.fps)
    empty, _ = _view(page, (frame + 0.5) / a.fps, parts=False)
    eyes = np.array(state["eyes"].split(), float).reshape(2, 2)
    # independently: the eyeballs' centres of this frame through render's camera
    scene = build_scene(a.rest, a.faces)
    points = scene.positions(a.vertices[frame].astype(np.float64))
    h, w = img.shape[:2]
    cfg = Config.load().settings("render")
    camera = Camera.fit(frame_points(scene), w, h, cfg.fov_deg, cfg.yaw_deg, cfg.pitch_deg)
    for (start, count), shown in zip(scene.eyeball_vertices, eyes):
        expected = camera.project(points[start:start + count].mean(axis=0)[None])[0, :2]
        assert np.abs(expected - shown).max() < 1.5
        with_eye, socket = _box(img, shown), _box(empty, shown)
        # an eye: not the background, and not what the empty socket shows there
        assert np.abs(with_eye - BG).max(axis=1).min() > 20
        assert np.abs(with_eye - socket).max(axis=1).mean() > 40
        # iris or pupil: darker than the sclera and skin around the eye's centre
        assert with_eye.mean(axis=1).min() < 0.6 * np.percentile(_box(img, shown, 12).mean(axis=1), 90)


def _mouth_pixels(img: np.ndarray, a: MeshAnimation, frame: int) -> np.ndarray:
    """(n, 3) the view's pixels inside the inner lip line (the mouth loop through render's camera)."""
    from PIL import Image, ImageDraw

    scene = build_scene(a.rest, a.faces)
    h, w = img.shape[:2]
    cfg = Config.load().settings("render")
    camera = Camera.fit(frame_points(scene), w, h, cfg.fov_deg, cfg.yaw_deg, cfg.pitch_deg)
    loop = camera.project(a.vertices[frame][scene.layout.mouth.loop].astype(np.float64))[:, :2]
    mask = Image.new("L", (w, h), 0)
    ImageDraw.Draw(mask).polygon([tuple(p) for p in loop], fill=1)
    return img[np.asarray(mask, bool)].astype(int)


def test_the_open_mouth_is_dark_inside(made, tmp_path):
    a = MeshAnimation.read(made / "open_r.h5")
    opened = len(a.vertices) - 1  # jawOpen 0.5
    with ChromiumPage((made / "open.html").as_uri() + "#head=0", tmp_path / "profile", WIDTH, HEIGHT) as p:
        img, _ = _view(p, (opened + 0.5) / a.fps)
        empty, _ = _view(p, (opened + 0.5) / a.fps, parts=False)
    inside, hole = _mouth_pixels(img, a, opened), _mouth_pixels(empty, a, opened)
    assert len(inside) > 100  # the mouth is open
    # the cavity: dark and deep red (CAVITY, red about three times green), where the empty hole shows
    # the background or the dark inside of the skin (skin-coloured, red about 1.25 times green)
    def cavity(px):
        return (px.max(axis=1) < 120) & (px[:, 0] > 1.8 * px[:, 1])
    assert cavity(inside).mean() > 0.15  # (the rest: teeth and tongue)
    assert cavity(hole).mean() < 0.02


def test_head_motion_moves_the_head(made, tmp_path):
    c = RigCurves.read(made / "turned.h5")
    boxes = {}
    with ChromiumPage((made / "turned.html").as_uri(), tmp_path / "profile", WIDTH, HEIGHT) as p:
        for head in ("1", "0"):
            p.evaluate(f"document.getElementById('headmotion').checked = {'true' if head == '1' else 'false'}")
            for f in (0, c.n_frames - 1):
                img, _ = _view(p, (f + 0.5) / c.fps)
                ys, xs = np.nonzero(np.abs(img.astype(int) - BG).max(axis=2) > 10)
                boxes[head, f] = np.array([xs.min(), xs.max(), ys.min(), ys.max()])
    last = c.n_frames - 1
    # turned 20 degrees about +y: the head's outline moves sideways by many pixels
    assert np.abs(boxes["1", last] - boxes["1", 0])[:2].max() > 15
    # without the head motion the outline stays (only the face moves)
    assert np.abs(boxes["0", last] - boxes["0", 0]).max() <= 3


def test_the_timeline_is_the_synthesized_path(made, page):
    search, _ = Motion.read_search(made / "m.h5")
    anim = load(made / "c.h5")  # curves alone: the phones come from their own provenance
    shown = page.evaluate("[...document.querySelectorAll('#timeline .phone')].map((d) => [d.firstChild.textContent, "
                          "d.dataset.emotion, Number(d.dataset.node), d.dataset.take, Number(d.dataset.start), "
                          "Number(d.dataset.end)])")
    assert [s[0] for s in shown] == search.phone and [s[1] for s in shown] == search.emotion
    assert [s[2] for s in shown] == [int(n) for n in search.node]
    np.testing.assert_allclose([s[4] for s in shown], search.start)
    np.testing.assert_allclose([s[5] for s in shown], search.end)
    assert [s[3] for s in shown] == [p.take for p in anim.phones]
    # a click on a phone seeks into it, and that phone is highlighted as the current one
    for k in (1, len(search.phone) // 2):
        box = page.evaluate(f"(() => {{ const r = document.querySelectorAll('#timeline .phone')[{k}]"
                            ".getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2]; })()")
        for kind in ("mousePressed", "mouseReleased"):
            page.call("Input.dispatchMouseEvent", type=kind, x=box[0], y=box[1], button="left", clickCount=1)
        state = page.dataset()
        t = float(state["time"])
        assert search.start[k] - 1 / 30 <= t <= search.end[k] + 1 / 30
        frame = int(state["frame"])
        assert int(state["phone"]) == anim.provenance.step[frame] and state["phoneName"] == anim.provenance.phone[frame]
        current = page.evaluate("[...document.querySelectorAll('#timeline .phone.current')].map((d) => Number(d.dataset.index))")
        assert current == [int(state["phone"])]


def test_the_eyes_follow_the_gaze(made, tmp_path):
    c = RigCurves.read(made / "gaze.h5")
    pupils = []
    with ChromiumPage((made / "gaze.html").as_uri() + "#head=0", tmp_path / "profile", WIDTH, HEIGHT) as p:
        for f in (c.n_frames // 4, 3 * c.n_frames // 4):
            img, state = _view(p, (f + 0.5) / c.fps)
            centres = []
            for xy in np.array(state["eyes"].split(), float).reshape(2, 2):
                x0, y0 = (int(round(v)) - 12 for v in xy)
                box = img[y0:y0 + 25, x0:x0 + 25].mean(axis=2)
                ys, xs = np.nonzero(box < np.percentile(box, 8))  # the pupil and the iris's dark ring
                centres.append(x0 + xs.mean())
            pupils.append(centres)
    # looking toward +x (the subject's left, the screen's right in render's view), then toward -x
    assert all(a - b > 5 for a, b in zip(*pupils))  # (13 to 14 px at this size)
