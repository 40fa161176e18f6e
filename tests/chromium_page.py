"""A page opened in headless Chromium (the Debian package ``chromium``) and driven over the
DevTools protocol on 127.0.0.1: evaluate JavaScript, take screenshots. Used by the tests of the
player, the live page and the Isomap pages, and by ``benchmarks/player_fps.py``."""

from __future__ import annotations

import base64
import io
import itertools
import json
import os
import shutil
import subprocess
import time
import urllib.request
from pathlib import Path

import numpy as np

CHROMIUM = shutil.which("chromium")


def remove_singleton_folder(profile: Path) -> None:
    """Remove the folder Chromium made in the system's temporary folder for its singleton socket
    (named by the profile's ``SingletonSocket`` link), which a browser ended by a signal leaves
    behind. Call it once the browser has exited."""
    link = Path(profile) / "SingletonSocket"
    if link.is_symlink():
        folder = Path(os.readlink(link)).parent
        if folder.name.startswith("org.chromium.Chromium."):
            shutil.rmtree(folder, ignore_errors=True)


class ChromiumPage:
    """``url`` in a headless Chromium with a ``width`` x ``height`` viewport (SwiftShader WebGL) and
    any further command-line ``flags`` (a fake microphone, say); a context manager that ends the
    browser it started."""

    def __init__(self, url: str, profile: Path, width: int = 900, height: int = 800, timeout_s: float = 60.0,
                 flags: tuple[str, ...] = ()):
        from websockets.sync.client import connect

        cmd = [CHROMIUM, "--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
               "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run",
               "--hide-scrollbars", f"--window-size={width},{height}", "--force-device-scale-factor=1",
               f"--user-data-dir={profile}", "--remote-debugging-address=127.0.0.1", "--remote-debugging-port=0",
               *flags, url]
        self.profile = Path(profile)
        (self.profile / "DevToolsActivePort").unlink(missing_ok=True)  # a stale one from an earlier browser
        self.browser = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        self.ids = itertools.count(1)
        try:
            start = time.monotonic()
            port_file = Path(profile) / "DevToolsActivePort"
            while not port_file.exists() or not port_file.read_text().strip():
                if time.monotonic() - start > timeout_s or self.browser.poll() is not None:
                    raise RuntimeError("Chromium did not start")
                time.sleep(0.1)
            port = int(port_file.read_text().split()[0])
            targets = json.loads(urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list", timeout=10).read())
            page = next(t for t in targets if t["type"] == "page")
            self.cdp = connect(page["webSocketDebuggerUrl"], max_size=None).__enter__()
            self.call("Emulation.setDeviceMetricsOverride", width=width, height=height, deviceScaleFactor=1, mobile=False)
            self._wait_ready(url, start + timeout_s)
        except BaseException:
            self.close()
            raise

    def _wait_ready(self, url: str, deadline: float) -> None:
        """Wait until the document at ``url`` says ``data-ready="1"`` on its body."""
        ready = f"location.href === {json.dumps(url)} && document.body && document.body.dataset.ready"
        while self.evaluate(ready) != "1":
            if time.monotonic() > deadline:
                raise RuntimeError(f"the page did not get ready: {self.evaluate('document.body && document.body.innerText')}")
            time.sleep(0.2)

    def navigate(self, url: str, timeout_s: float = 60.0) -> None:
        """Load ``url`` in this page (a new document: give it another address than the current
        one, not only another fragment) and wait until it is ready."""
        self.call("Page.navigate", url=url)
        self._wait_ready(url, time.monotonic() + timeout_s)

    def call(self, method: str, **params) -> dict:
        n = next(self.ids)
        self.cdp.send(json.dumps({"id": n, "method": method, "params": params}))
        while True:
            reply = json.loads(self.cdp.recv(timeout=120))
            if reply.get("id") == n:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply["result"]

    def evaluate(self, expression: str):
        """The value of a JavaScript expression (awaited when it is a promise)."""
        result = self.call("Runtime.evaluate", expression=expression, returnByValue=True, awaitPromise=True)
        if "exceptionDetails" in result:
            raise RuntimeError(f"{expression}: {result['exceptionDetails']}")
        return result["result"].get("value")

    def dataset(self) -> dict:
        """``document.body.dataset`` with the text of ``#errors`` as ``error-text``."""
        return json.loads(self.evaluate("JSON.stringify(Object.assign({}, document.body.dataset, "
                                        "{'error-text': document.getElementById('errors').textContent}))"))

    def screenshot(self) -> np.ndarray:
        """The viewport as (H, W, 3) uint8 RGB."""
        from PIL import Image

        png = base64.b64decode(self.call("Page.captureScreenshot", format="png")["data"])
        return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"))

    def close(self) -> None:
        if getattr(self, "cdp", None) is not None:
            self.cdp.close()
        self.browser.terminate()
        try:
            self.browser.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.browser.kill()
            self.browser.wait()
        remove_singleton_folder(self.profile)

    def __enter__(self) -> "ChromiumPage":
        return self

    def __exit__(self, *exc) -> None:
        self.close()
