"""The player's live mode as a person uses it: ``facesynth player --live`` writes a page that holds
the built-in rig with its 52 ARKit blendshapes; opened in headless Chromium (where the Debian
package is installed) against a stream server on 127.0.0.1, it sends its speech in real time (a
file, or a microphone: Chromium's fake capture device playing the sample voice), shows the frames
as they arrive, opens the mouth and measures the latency. It draws the face the player and
``facesynth render`` draw: eyes, mouth cavity, teeth and tongue, the same shading and camera."""

import asyncio
import dataclasses
import importlib.resources
import json
import math
import re
import shutil
import threading
import time
import wave
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from chromium_page import ChromiumPage
from click.testing import CliRunner

from facesynth.base.config import Config
from facesynth.cli import main
from facesynth.domain.capture.facegood import shipped
from facesynth.domain.exports import player
from facesynth.domain.live.server import StreamServer
from facesynth.domain.live.synthesizer import LiveModel
from facesynth.domain.rendering.parts import build_scene
from facesynth.domain.rendering.raster import BACKGROUND
from facesynth.domain.rendering.video import ShadedView
from facesynth.domain.rig.face import gaze_from_rig_weights, load_face_rig
from facesynth.formats.blendshape_curves import read_mapping
from facesynth.model.motiondb import MotionDatabase

CHROMIUM = shutil.which("chromium")
pytest.importorskip("websockets", reason="the stream server needs the websockets package")
needs_chromium = pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium (Debian package 'chromium') is not installed")


@pytest.fixture(scope="module")
def stream_url(tiny_db):
    """A ``facesynth stream --serve 127.0.0.1:0`` server on the tiny database, in a thread of
    this process (each page that connects is its own session); its WebSocket URL."""
    config = Config.load()
    # the voice's frames (the default, set here whatever the configuration), which arrive at the
    # speech's own pace: with stream.voice "off" the recognised phones' frames come a second late in
    # bursts, and a headless Chromium on a loaded machine shows too few of them for the mouth checks below
    stream = dataclasses.replace(config.settings("stream"), voice="articulation")
    model = LiveModel(MotionDatabase.read(tiny_db), config.settings("synthesize"), stream, config.settings("solve"))
    loop = asyncio.new_event_loop()
    server = StreamServer(model, config.settings("align"), "127.0.0.1", 0)
    loop.run_until_complete(server.start())
    thread = threading.Thread(target=loop.run_forever, daemon=True)
    thread.start()
    try:
        yield f"ws://127.0.0.1:{server.port}"
    finally:
        asyncio.run_coroutine_threadsafe(server.stop(), loop).result(10)
        loop.call_soon_threadsafe(loop.stop)
        thread.join(10)
        loop.close()


def _dashed(dataset: dict) -> dict:
    """``document.body.dataset``'s keys as the page's HTML names them (``liveReceived`` -> ``live-received``)."""
    return {re.sub(r"[A-Z]", lambda m: "-" + m.group(0).lower(), k): v for k, v in dataset.items()}


def _open_until_done(url: str, tmp_path, deadline_s: float) -> dict:
    """Open ``url`` in headless Chromium in real time (a live page cannot run on virtual time: its
    frames come over a socket) and read ``document.body.dataset`` through the DevTools protocol
    (on 127.0.0.1) until the page says the stream is done or ``deadline_s`` passes."""
    start = time.monotonic()
    with ChromiumPage(url, tmp_path / "profile", flags=("--autoplay-policy=no-user-gesture-required",)) as page:
        while True:
            body = _dashed(page.dataset())
            if body.get("live-done") == "1" or body.get("errors", "0") != "0" or time.monotonic() - start > deadline_s:
                return body
            time.sleep(0.25)


def test_live_targets_are_the_rig_shapes_each_arkit_name_drives(tiny_corpus, held_out_take):
    rig = load_face_rig()
    data = player.live_payload("ws://127.0.0.1:8765", tiny_corpus / "audio" / f"{held_out_take}.wav")
    assert data["target_names"] == list(rig.arkit_names) and len(data["targets"]) == 52
    # a frame's weights pose the page's mesh as the rig poses its from_arkit weights
    arkit = np.linspace(0.0, 1.0, 52)
    targets = np.stack([np.frombuffer(player.base64.b64decode(t), np.int16) * s
                        for t, s in zip(data["targets"], data["scales"])])
    posed = rig.neutral.reshape(-1) + arkit @ targets
    assert np.abs(posed - rig.evaluate(rig.from_arkit(arkit)).reshape(-1)).max() < 0.01  # mm, int16 steps
    pcm = np.frombuffer(player.base64.b64decode(data["pcm"]), "<i2")
    with wave.open(str(tiny_corpus / "audio" / f"{held_out_take}.wav")) as w:  # a 16 kHz file: sent as it is
        assert w.getframerate() == 16000 and np.array_equal(pcm, np.frombuffer(w.readframes(w.getnframes()), "<i2"))


def test_live_parts_follow_the_arkit_weights_within_half_a_millimetre():
    """The eyeballs, cavity, teeth and tongue of the live page are morph targets of the 52 ARKit
    weights (a linearisation of the renderer's rigid jaw and gaze): on a real performer's frames
    (FACEGOOD's, every 300th, mapped to ARKit as ``ingest`` maps them) they stand where the
    renderer places them, within half a millimetre."""
    rig = load_face_rig()
    scene = build_scene(rig.neutral, rig.faces)
    parts_rest, targets = player.live_parts_targets(rig, scene)
    assert targets.shape == (52, parts_rest.size) and np.abs(targets).max() > 1.0  # the jaw moves the teeth
    arrays, _, _ = shipped()
    table = importlib.resources.files("facesynth").joinpath("data/facegood_arkit.csv")
    mapping = read_mapping(Path(str(table)), [str(n) for n in arrays["names"]], rig.arkit_names, "FACEGOOD")
    arkit = np.clip(arrays["curves"].astype(np.float64) @ mapping, 0.0, 1.0)[::300]
    assert arkit[:, rig.arkit_names.index("jawOpen")].max() > 0.3  # frames with the mouth well open among them
    worst = 0.0
    for a in arkit:
        w = rig.from_arkit(a)
        gaze = gaze_from_rig_weights(w[None], rig.shape_names)
        exact = scene.positions(rig.evaluate(w), None if gaze is None else gaze[0])[scene.n_skin:]
        worst = max(worst, float(np.linalg.norm(exact - parts_rest - (a @ targets).reshape(-1, 3), axis=1).max()))
    assert worst < 0.5, worst


def test_a_live_page_needs_a_websocket_url_and_no_artifact(tmp_path, tiny_corpus):
    r = CliRunner().invoke(main, ["player", "--live", "http://127.0.0.1:1", "-o", str(tmp_path / "l.html")])
    assert r.exit_code == 1 and "WebSocket URL" in r.output and not (tmp_path / "l.html").exists()
    r = CliRunner().invoke(main, ["player", "-o", str(tmp_path / "l.html")])
    assert r.exit_code == 2 and "either an ARTIFACT" in r.output


@needs_chromium
def test_live_page_in_headless_chromium(stream_url, tiny_corpus, held_out_take, tmp_path):
    config = Config.load()
    wav = tiny_corpus / "audio" / f"{held_out_take}.wav"
    out = tmp_path / "live.html"
    r = CliRunner().invoke(main, ["player", "--live", stream_url, "--audio", str(wav), "-o", str(out)])
    assert r.exit_code == 0, r.output
    seconds = float(re.search(r"([0-9.]+) s of speech", r.output).group(1))
    body = _open_until_done(out.as_uri() + "#start", tmp_path, deadline_s=seconds + 30)
    assert body.get("ready") == "1", body
    assert body["errors"] == "0", body["error-text"]
    frames = int(body["live-received"])
    # the whole utterance came back (frames at the stream's rate) and was shown, in order, at its time
    assert frames == pytest.approx(seconds * config.settings("stream").fps, abs=3)
    assert body.get("live-done") == "1" and body["live"].startswith("finished")
    # (the screen refreshes as it can in headless Chromium: a frame due while another is shown is skipped)
    assert int(body["frame"]) == frames - 1 and 5 <= int(body["live-shown"]) <= frames
    # the mouth opened on the speech: the voice's jaw reaches about 0.2 in a tenth of the frames sent
    # (0.25 at most), and a loaded machine shows only some of them, so not always its highest
    assert float(body["jaw-max"]) > 0.12
    assert float(body["jaw"]) < 0.5 * float(body["jaw-max"])  # and closed at its end
    assert body["live-states"].split(" | ")[:3] == ["connecting", "connected", "streaming (file)"]
    # a file is sent up to 100 ms ahead of its time in the speech, so its frames may come back before it
    _check_latency(body, frames, ahead_ms=100.0)


def _check_latency(body: dict, frames: int, ahead_ms: float = 0.0) -> None:
    """Every frame's latency was measured, and the page's median, p95 and last (ms) are finite and
    no earlier than the audio they show could have reached the server: ``ahead_ms`` before its
    time in the speech (a microphone's sample goes only once it is spoken: 0, so positive)."""
    assert int(body["latency-count"]) == frames
    median, p95, last = (float(body[f"latency-{k}"]) for k in ("median", "p95", "last"))
    shown = {k: v for k, v in body.items() if k.startswith("latency")}
    assert all(math.isfinite(v) and v > -ahead_ms for v in (median, p95, last)), shown
    assert median <= p95 < 30_000, shown  # (seconds off would be a wrong origin, not a slow server)


def _wait(page, done, deadline_s: float, what: str) -> dict:
    """``page.dataset()`` once ``done(dataset)`` holds, polled; fails after ``deadline_s``."""
    start = time.monotonic()
    while True:
        body = _dashed(page.dataset())
        if done(body):
            return body
        assert time.monotonic() - start < deadline_s and body.get("errors") == "0", f"{what}: {body}"
        time.sleep(0.2)


def _live_page(url: str, tmp_path: Path) -> Path:
    """A live page for the server at ``url`` with no speech of its own (the microphone's page)."""
    out = tmp_path / "mic.html"
    r = CliRunner().invoke(main, ["player", "--live", url, "-o", str(out)])
    assert r.exit_code == 0, r.output
    return out


def _speak_into_the_microphone(page, seconds: float) -> tuple[dict, float]:
    """Press the microphone button (a user gesture, as a click is), let the fake device speak for
    ``seconds`` of captured audio, press it again; the page once the server has sent its end, and
    the wall-clock seconds the microphone was on."""
    _wait(page, lambda b: b.get("live") == "connected", 30, "the page did not connect")
    click = "document.getElementById('livemic').click()"
    page.call("Runtime.evaluate", expression=click, userGesture=True)
    on = time.monotonic()
    _wait(page, lambda b: float(b.get("mic-seconds", 0)) >= seconds and int(b.get("live-received", 0)) > 0,
          seconds + 30, "no frames came back from the microphone")
    assert page.evaluate("document.getElementById('livemic').textContent") == "stop microphone"
    page.call("Runtime.evaluate", expression=click, userGesture=True)
    wall = time.monotonic() - on
    body = _wait(page, lambda b: b.get("live-done") == "1", 30, "the stream did not finish")
    assert page.evaluate("document.getElementById('livemic').textContent") == "microphone"
    assert page.evaluate("document.getElementById('livemic').disabled") is True  # one stream a connection
    return body, wall


def _fake_microphone(wav: Path) -> tuple[str, ...]:
    """Chromium's flags for a microphone that is granted without asking and plays ``wav``."""
    return ("--use-fake-ui-for-media-stream", "--use-fake-device-for-media-stream",
            f"--use-file-for-fake-audio-capture={wav}")


def _check_microphone_stream(body: dict, seconds_on: float) -> None:
    frames, fps = int(body["live-received"]), Config.load().settings("stream").fps
    assert body["errors"] == "0", body["error-text"]
    states = body["live-states"].split(" | ")
    assert states[:3] == ["connecting", "connected", "streaming (microphone)"], states
    # after the second press the server was told the end and answered with its own
    assert states[-2:] == ["finishing", f"finished ({frames} frames)"] and body["live"] == states[-1], states
    captured = float(body["mic-seconds"])
    # captured at the speed of speech (16 kHz samples as they came), all of it animated
    assert 0.5 * seconds_on < captured < seconds_on + 0.5, (captured, seconds_on)
    assert frames == pytest.approx(captured * fps, abs=3)
    assert 5 <= int(body["live-shown"]) <= frames
    assert float(body["jaw-max"]) > 0.1  # the mouth opened on the voice the fake microphone played (rest: 0.02)
    _check_latency(body, frames)


@needs_chromium
def test_microphone_in_headless_chromium(stream_url, tiny_corpus, held_out_take, tmp_path):
    # the fake microphone plays the sample voice's held-out take (16 kHz mono, looped): deterministic speech
    wav = tiny_corpus / "audio" / f"{held_out_take}.wav"
    with ChromiumPage(_live_page(stream_url, tmp_path).as_uri(), tmp_path / "profile", flags=_fake_microphone(wav)) as page:
        body, seconds_on = _speak_into_the_microphone(page, 3.0)
    assert body["mic-capture"] == "AudioWorklet at 16000 Hz"  # the browser resampled the microphone
    _check_microphone_stream(body, seconds_on)


@needs_chromium
def test_microphone_without_audio_worklet_or_16_khz_context(stream_url, tiny_corpus, held_out_take, tmp_path):
    """An older browser's path: no AudioWorklet (a ScriptProcessorNode captures) and a context at
    the device's rate (the page's own resampler makes the 16 kHz)."""
    wav = tiny_corpus / "audio" / f"{held_out_take}.wav"
    with ChromiumPage(_live_page(stream_url, tmp_path).as_uri(), tmp_path / "profile", flags=_fake_microphone(wav)) as page:
        page.evaluate("""{
            const Base = window.AudioContext;
            window.AudioContext = class extends Base {
              constructor() { super(); }  // the device's rate, whatever is asked
              get audioWorklet() { return undefined; }
            };
        }""")
        body, seconds_on = _speak_into_the_microphone(page, 3.0)
    kind, rate = re.fullmatch(r"(\S+) at (\d+) Hz", body["mic-capture"]).groups()
    assert kind == "ScriptProcessorNode" and int(rate) != 16000, body["mic-capture"]
    _check_microphone_stream(body, seconds_on)


@needs_chromium
def test_a_refused_or_missing_microphone_says_so(stream_url, tmp_path):
    press = "document.getElementById('livemic').click()"
    # a device, but the permission prompt is answered no (as a person who refuses it)
    flags = ("--use-fake-device-for-media-stream", "--deny-permission-prompts")
    with ChromiumPage(_live_page(stream_url, tmp_path).as_uri(), tmp_path / "profile", flags=flags) as page:
        _wait(page, lambda b: b.get("live") == "connected", 30, "the page did not connect")
        page.call("Runtime.evaluate", expression=press, userGesture=True)
        body = _wait(page, lambda b: b["live"] != "connected", 30, "no answer to the microphone button")
        assert body["live"] == "microphone refused: allow this page to use the microphone and press microphone again."
        # a browser that gives the page no getUserMedia at all
        page.evaluate("Object.defineProperty(navigator, 'mediaDevices', { value: undefined, configurable: true })")
        page.call("Runtime.evaluate", expression=press, userGesture=True)
        body = _wait(page, lambda b: b["live"].startswith("no microphone"), 30, "no answer without getUserMedia")
        assert body["live"].count(".") == 1 and body["live"].endswith(".")  # one sentence
        assert page.evaluate("document.getElementById('livemic').textContent") == "microphone"
    assert body["errors"] == "0" and body["error-text"] == "", body  # said in the state line, not thrown
    assert body["live-received"] == "0" and "latency-count" not in body


LIVE_W, LIVE_H = 640, 700
BG = np.round(np.asarray(BACKGROUND) * 255).astype(int)


def _posed(page, named: dict) -> tuple[np.ndarray, dict]:
    """The live page's view (H, W, 3) uint8 posed by ``named`` ARKit weights, and its state."""
    page.evaluate(f"player.pose({json.dumps(named)})")
    page.evaluate("new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done)))")  # drawn
    state = _dashed(page.dataset())
    assert state["errors"] == "0", state["error-text"]
    h = page.evaluate("document.getElementById('view').clientHeight")
    return page.screenshot()[:h], state


def _rendered(named: dict, width: int, height: int) -> np.ndarray:
    """``facesynth render``'s picture of the built-in rig posed by ``named`` ARKit weights."""
    rig = load_face_rig()
    arkit = np.zeros(len(rig.arkit_names))
    for name, value in named.items():
        arkit[rig.arkit_names.index(name)] = value
    settings = dataclasses.replace(Config.load().settings("render"), width=width, height=height, use_opencl=False)
    view = ShadedView(SimpleNamespace(rest=rig.neutral, faces=rig.faces, gaze=None), settings, width)
    return view.frame(rig.evaluate(rig.from_arkit(arkit)), 0)


def _near(img: np.ndarray, xy, r: int) -> np.ndarray:
    """(n, 3) int pixels of the (2r + 1)-pixel square about ``xy`` (x, y)."""
    x, y = (int(round(v)) for v in xy)
    return img[y - r:y + r + 1, x - r:x + r + 1].reshape(-1, 3).astype(int)


def _whitish(px: np.ndarray) -> np.ndarray:
    """Sclera or teeth: bright and nearly grey (skin's green is about 0.8 of its red, theirs above 0.93)."""
    return (px[:, 0] > 120) & (px[:, 1] > 0.93 * px[:, 0])


@needs_chromium
def test_the_live_page_draws_eyes_teeth_and_the_renderers_face(stream_url, tmp_path):
    with ChromiumPage(_live_page(stream_url, tmp_path).as_uri(), tmp_path / "profile", LIVE_W, LIVE_H) as page:
        rest, at_rest = _posed(page, {})
        opened, at_open = _posed(page, {"jawOpen": 0.6})
    h, w = rest.shape[:2]
    # the eyes: at each eyeball's centre on screen, sclera (whitish) and a dark iris or pupil, not skin
    eyes = np.array(at_rest["eyes"].split(), float).reshape(2, 2)
    skin = _near(rest, (eyes[:, 0].mean(), eyes[:, 1].mean() - 0.6 * abs(eyes[0, 0] - eyes[1, 0])), 4)  # the brow's middle
    assert not _whitish(skin).any() and (skin.min(axis=0) > 100).all()
    for eye in eyes:
        px = _near(rest, eye, 10)
        assert _whitish(px).sum() >= 5, eye                                   # sclera
        assert px.sum(axis=1).min() < 0.5 * skin.sum(axis=1).mean(), eye      # iris and pupil, darker than skin
    # the open mouth: teeth (whitish) and the dark red cavity between the lips; none of either at rest
    mouth = np.array(at_open["mouth"].split(), float)
    inside, closed = _near(opened, mouth, 12), _near(rest, np.array(at_rest["mouth"].split(), float), 12)
    assert _whitish(inside).sum() >= 5 and not _whitish(closed).any()
    assert ((inside.max(axis=1) < 120) & (inside[:, 0] > 1.8 * inside[:, 1])).sum() >= 10
    # the picture is render's (parts, shading, camera): at rest and with the jaw open, nearly every pixel
    # of the face within a few levels (the rest: edges, where two rasterizers' anti-aliasing differ)
    for img, named in ((rest, {}), (opened, {"jawOpen": 0.6})):
        ref = _rendered(named, w, h)
        face = np.abs(ref.astype(int) - BG).max(axis=2) > 3
        diff = np.abs(img.astype(int) - ref.astype(int)).max(axis=2)[face]
        assert face.mean() > 0.15 and np.mean(diff <= 3) > 0.85 and np.mean(diff > 40) < 0.03, named
