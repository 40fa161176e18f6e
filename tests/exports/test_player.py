"""``facesynth player`` as a person uses it: the page opened in headless Chromium (where the
Debian package is installed) loads without errors, shows the artifact's frame count and
duration, moves the mesh when scrubbed, lists each phone with its emotion and provenance, and
needs no network."""

import base64
import re

import numpy as np
import pytest
from chromium_page import CHROMIUM, ChromiumPage
from click.testing import CliRunner
from coded_audio import COMPRESSED, coded

from facesynth.base.config import Config
from facesynth.cli import main
from facesynth.domain.exports import player
from facesynth.domain.exports.animation import load
from facesynth.model.meshanim import MeshAnimation
from facesynth.model.motion import Motion
from facesynth.stages import deform, synthesize

needs_chromium = pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium (Debian package 'chromium') is not installed")


@pytest.fixture(scope="module")
def page(tiny_db, tiny_corpus, held_out_take, tmp_path_factory):
    config = Config.load()
    d = tmp_path_factory.mktemp("player")
    synthesize.run(tiny_db, d / "m.h5", config.settings("synthesize"), config.settings("ingest"),
                   config.settings("align"), phones_path=tiny_corpus / "labels" / f"{held_out_take}.TextGrid")
    deform.run(d / "m.h5", tiny_corpus / "face.obj", tiny_corpus / "markers.csv", d / "a.h5", config.settings("deform"))
    audio = tiny_corpus / "audio" / f"{held_out_take}.wav"
    r = CliRunner().invoke(main, ["player", str(d / "a.h5"), "--motion", str(d / "m.h5"), "--audio", str(audio),
                                  "-o", str(d / "player.html")])
    assert r.exit_code == 0, r.output
    return d


def test_page_is_self_contained_and_compact(page):
    text = (page / "player.html").read_text()
    assert not re.search(r"""(src|href)\s*=\s*["']?(https?:)?//""", text)  # nothing fetched at view time
    assert "three.js" in text and "MIT License" in text  # the vendored library's license travels with it
    assert text.count('id="three-') == 3 and 'id="anim"' in text and "data:audio/wav;base64," in text
    a = MeshAnimation.read(page / "a.h5")
    assert len(text) < 0.5 * a.vertices.nbytes + 8e6  # principal components, not every frame's vertices


def test_principal_targets_reproduce_the_mesh_animation(page):
    anim = load(page / "a.h5")
    basis, weights = player.principal_targets(anim.vertices, anim.rest)
    q, scale = player.quantize(basis)
    again = anim.rest.reshape(-1) + weights @ (q * scale[:, None])
    err = np.abs(again.reshape(anim.vertices.shape) - anim.vertices).max()
    assert err < 0.05  # mm, at most MAX_COMPONENTS components and int16 targets


@needs_chromium
def test_player_in_headless_chromium(page, tmp_path):
    url = (page / "player.html").as_uri()
    a = MeshAnimation.read(page / "a.h5")
    anim = load(page / "a.h5")
    basis, weights = player.principal_targets(anim.vertices, anim.rest)

    seen = {}
    times = (0.0, 0.5 * a.vertices.shape[0] / a.fps)
    # each time in an address of its own (``#t=`` is read when the page loads)
    addresses = [f"{url}?open={k}#t={t:.4f}" for k, t in enumerate(times)]
    with ChromiumPage(addresses[0], tmp_path / "profile", 900, 800) as browser:
        for t, address in zip(times, addresses):
            if address != addresses[0]:
                browser.navigate(address)
            dom = browser.evaluate("document.documentElement.outerHTML")
            body = browser.dataset()
            assert body["errors"] == "0", body["error-text"]
            # the frame count and duration shown are the artifact's
            assert int(body["frames"]) == len(a.vertices)
            assert float(body["duration"]) == pytest.approx(len(a.vertices) / a.fps, abs=1e-5)
            assert f'<span id="frames">{len(a.vertices)}</span>' in dom
            assert f'<span id="duration">{len(a.vertices) / a.fps:.3f}</span>' in dom
            frame = int(body["frame"])
            assert frame == min(len(a.vertices) - 1, int(np.floor(t * a.fps + 1e-6)))
            # the mesh the page poses at that time is the artifact's frame (mean vertex, mm)
            mean = np.array([float(v) for v in body["mean"].split()])
            assert np.abs(mean - a.vertices[frame].mean(axis=0)).max() < 0.05
            # a screenshot: a face is drawn in the 3D view
            seen[t] = (mean, dom, browser.screenshot().mean(axis=2))
    (m0, dom, shot0), (m1, _, shot1) = seen.values()
    assert np.abs(m0 - m1).max() > 1e-3  # scrubbing moved the mesh

    # the timeline: every phone with its emotion, and the take and node it came from
    search, provenance = Motion.read_search(page / "m.h5")
    phones = re.findall(r'<div class="phone[^"]*"[^>]*data-take="([^"]*)" data-node="(-?\d+)"[^>]*>([^<]*)<small>([^<]*)</small>', dom)
    assert [p[2] for p in phones] == search.phone and [p[3] for p in phones] == search.emotion
    assert [int(p[1]) for p in phones] == [int(n) for n in search.node]
    for (take, _, phone, _), step in zip(phones, range(len(phones))):
        taken = provenance.take[(provenance.step == step) & (provenance.take >= 0)]
        # the take most of the phone's frames came from; none for a pause regenerated as silence
        assert take == (provenance.take_names[int(np.bincount(taken).argmax())] if len(taken) else ""), phone

    # the screenshots at the two times: a face is drawn, and it differs where the mouth moves
    view = slice(0, int(0.7 * 800) - 10)
    assert shot0[view].std() > 10  # something is drawn in the 3D view
    assert np.abs(shot0[view] - shot1[view]).max() > 30 and (np.abs(shot0[view] - shot1[view]) > 10).sum() > 50
    assert weights.shape[0] == len(a.vertices) and basis.shape[0] >= 1


def test_the_face_parts_on_the_page_are_the_renderers(tmp_path):
    """The eyeballs, cavity, teeth and tongue the page poses (rest + int16 principal targets) are
    where the renderer places them for every frame, gaze included."""
    import base64

    from facesynth.domain.rendering.parts import build_scene
    from facesynth.domain.rig.face import BUILTIN_RIG_NAME, builtin_rig_sha256, gaze_from_rig_weights, load_face_rig
    from facesynth.model.curves import RigCurves

    rig = load_face_rig()
    rng = np.random.default_rng(0)
    weights = np.clip(rng.normal(0.2, 0.2, (24, len(rig.shape_names))), 0, 1).astype(np.float32)
    RigCurves(weights, 30.0, list(rig.shape_names), BUILTIN_RIG_NAME, builtin_rig_sha256(), "solve").write(
        tmp_path / "c.h5", config="{}", inputs=[])
    face = player.payload(load(tmp_path / "c.h5"))["face"]
    f32 = lambda b64: np.frombuffer(base64.b64decode(b64), np.float32)  # noqa: E731
    rest = f32(face["parts_rest"])
    k = len(face["targets"])
    targets = np.stack([np.frombuffer(base64.b64decode(t), np.int16) * s for t, s in zip(face["targets"], face["scales"])])
    shown = rest + f32(face["weights"]).reshape(-1, k) @ targets
    scene = build_scene(rig.neutral, rig.faces)
    gaze = gaze_from_rig_weights(weights, rig.shape_names)
    skins = rig.evaluate(weights)
    placed = np.stack([scene.positions(s, g)[scene.n_skin:] for s, g in zip(skins, gaze)]).reshape(len(weights), -1)
    assert face["vertices"] == scene.n_vertices and np.abs(np.abs(gaze).max()) > 0.05
    assert np.abs(shown - placed).max() < 0.01  # mm: the principal targets and int16 steps


@pytest.mark.parametrize("name", COMPRESSED)
def test_the_pages_speech_from_coded_speech(page, coded_speech, tmp_path, name):
    """``player --audio`` (and the live page's) with the sentence as M4A, MP3, Opus, Ogg or an
    MP4's sound: the page holds its sound as a WAV, and the live page's 16 kHz PCM follows the
    WAV's at r > 0.99 with the same number of samples; a silent video writes no page."""
    path = coded(coded_speech, name)
    r = CliRunner().invoke(main, ["player", str(page / "a.h5"), "--motion", str(page / "m.h5"), "--audio", str(path),
                                  "-o", str(tmp_path / "p.html")])
    assert r.exit_code == 0, r.output
    assert "data:audio/wav;base64," in (tmp_path / "p.html").read_text()
    pcm = [np.frombuffer(base64.b64decode(player.live_payload("ws://127.0.0.1:1", p)["pcm"]), "<i2")
           for p in (coded_speech["wav"], path)]
    assert len(pcm[1]) == len(pcm[0]) and np.corrcoef(pcm[0], pcm[1])[0, 1] > 0.99
    r = CliRunner().invoke(main, ["player", str(page / "a.h5"), "--audio", str(coded_speech["silent"]),
                                  "-o", str(tmp_path / "silent.html")])
    assert r.exit_code == 1 and "has no audio stream" in r.output and not (tmp_path / "silent.html").exists()
