"""The player's live mode as a person uses it: ``facesynth player --live`` writes a page that holds
the built-in rig with its 52 ARKit blendshapes; opened in headless Chromium (where the Debian
package is installed) against a stream server on 127.0.0.1, it sends its speech in real time,
shows the frames as they arrive and opens the mouth."""

import asyncio
import itertools
import json
import re
import shutil
import subprocess
import threading
import time
import urllib.request
import wave

import numpy as np
import pytest
from click.testing import CliRunner

from facesynth.base.config import Config
from facesynth.cli import main
from facesynth.domain.exports import player
from facesynth.domain.live.core import LiveModel
from facesynth.domain.live.server import StreamServer
from facesynth.domain.rig.face import load_face_rig
from facesynth.model.motiondb import MotionDatabase

CHROMIUM = shutil.which("chromium")
pytest.importorskip("websockets", reason="the stream server needs the websockets package")


def _open_until_done(url: str, tmp_path, deadline_s: float) -> dict:
    """Open ``url`` in headless Chromium in real time (a live page cannot run on virtual time: its
    frames come over a socket) and read ``document.body.dataset`` through the DevTools protocol
    (on 127.0.0.1) until the page says the stream is done or ``deadline_s`` passes."""
    from websockets.sync.client import connect

    cmd = [CHROMIUM, "--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
           "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run",
           "--autoplay-policy=no-user-gesture-required", f"--user-data-dir={tmp_path / 'profile'}",
           "--remote-debugging-address=127.0.0.1", "--remote-debugging-port=0", url]
    browser = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    try:
        start = time.monotonic()
        port_file = tmp_path / "profile" / "DevToolsActivePort"
        while not port_file.exists() or not port_file.read_text().strip():
            assert time.monotonic() - start < 30 and browser.poll() is None, "Chromium did not start"
            time.sleep(0.1)
        port = int(port_file.read_text().split()[0])
        targets = json.loads(urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list", timeout=10).read())
        page = next(t for t in targets if t["type"] == "page")
        expression = ("JSON.stringify(Object.assign({}, document.body.dataset, "
                      "{'error-text': document.getElementById('errors').textContent}))")
        with connect(page["webSocketDebuggerUrl"], max_size=None) as cdp:
            for n in itertools.count(1):
                cdp.send(json.dumps({"id": n, "method": "Runtime.evaluate", "params": {"expression": expression}}))
                reply = json.loads(cdp.recv(timeout=10))
                while reply.get("id") != n:
                    reply = json.loads(cdp.recv(timeout=10))
                data = json.loads(reply["result"]["result"].get("value") or "{}")
                body = {re.sub(r"[A-Z]", lambda m: "-" + m.group(0).lower(), k): v for k, v in data.items()}
                if body.get("live-done") == "1" or body.get("errors", "0") != "0" or time.monotonic() - start > deadline_s:
                    return body
                time.sleep(0.25)
    finally:
        browser.terminate()
        browser.wait(10)
    raise AssertionError("unreachable")


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


def test_a_live_page_needs_a_websocket_url_and_no_artifact(tmp_path, tiny_corpus):
    r = CliRunner().invoke(main, ["player", "--live", "http://127.0.0.1:1", "-o", str(tmp_path / "l.html")])
    assert r.exit_code == 1 and "WebSocket URL" in r.output and not (tmp_path / "l.html").exists()
    r = CliRunner().invoke(main, ["player", "-o", str(tmp_path / "l.html")])
    assert r.exit_code == 2 and "either an ARTIFACT" in r.output


@pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium (Debian package 'chromium') is not installed")
def test_live_page_in_headless_chromium(tiny_db, tiny_corpus, held_out_take, tmp_path):
    config = Config.load()
    model = LiveModel(MotionDatabase.read(tiny_db), config.settings("synthesize"), config.settings("stream"),
                      config.settings("solve"))
    loop = asyncio.new_event_loop()
    server = StreamServer(model, config.settings("align"), "127.0.0.1", 0)
    loop.run_until_complete(server.start())
    thread = threading.Thread(target=loop.run_forever, daemon=True)
    thread.start()
    try:
        url = f"ws://127.0.0.1:{server.port}"
        wav = tiny_corpus / "audio" / f"{held_out_take}.wav"
        out = tmp_path / "live.html"
        r = CliRunner().invoke(main, ["player", "--live", url, "--audio", str(wav), "-o", str(out)])
        assert r.exit_code == 0, r.output
        seconds = float(re.search(r"([0-9.]+) s of speech", r.output).group(1))
        body = _open_until_done(out.as_uri() + "#start", tmp_path, deadline_s=seconds + 30)
    finally:
        asyncio.run_coroutine_threadsafe(server.stop(), loop).result(10)
        loop.call_soon_threadsafe(loop.stop)
        thread.join(10)
        loop.close()
    assert body.get("ready") == "1", body
    assert body["errors"] == "0", body["error-text"]
    frames = int(body["live-received"])
    # the whole utterance came back (frames at the stream's rate) and was shown, in order, at its time
    assert frames == pytest.approx(seconds * config.settings("stream").fps, abs=3)
    assert body.get("live-done") == "1" and body["live"].startswith("finished")
    # (the screen refreshes as it can in headless Chromium: a frame due while another is shown is skipped)
    assert int(body["frame"]) == frames - 1 and 5 <= int(body["live-shown"]) <= frames
    assert float(body["jaw-max"]) > 0.2  # the mouth opened on the speech
    assert float(body["jaw"]) < 0.5 * float(body["jaw-max"])  # and closed at its end
