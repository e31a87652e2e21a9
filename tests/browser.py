"""A real headless browser for tests: Debian's ``chromium``, driven over the DevTools protocol on a pipe.

No driver library and no network: chromium reads protocol messages on file
descriptor 3 and writes on 4 (``--remote-debugging-pipe``), each a JSON object
ended by a NUL byte. :func:`open_page` loads a page and reports what a person
would notice: console errors and uncaught exceptions, failed loads, each media
element's state, and a screenshot.
"""

from __future__ import annotations

import base64
import contextlib
import json
import os
import shutil
import subprocess
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterator

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run", "--mute-audio",
         "--autoplay-policy=no-user-gesture-required", "--remote-debugging-pipe"]


def chromium() -> str | None:
    """The path of Debian's chromium, or None."""
    return shutil.which("chromium") or shutil.which("chromium-browser")


@dataclass
class PageReport:
    errors: list[str] = field(default_factory=list)  # console errors, exceptions, failed loads
    media: list[dict[str, Any]] = field(default_factory=list)  # one per <video>/<img>
    screenshot: bytes = b""  # PNG


class _Browser:
    def __init__(self, executable: str, profile: str) -> None:
        commands_read, self._commands = os.pipe()
        self._replies, replies_write = os.pipe()

        def wire() -> None:  # in the child: the pipes at the descriptors chromium expects
            os.dup2(commands_read, 3)
            os.dup2(replies_write, 4)

        self.process = subprocess.Popen([executable, *FLAGS, f"--user-data-dir={profile}", "about:blank"],
                                        stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                        stderr=subprocess.DEVNULL, preexec_fn=wire, pass_fds=(3, 4))
        os.close(commands_read)
        os.close(replies_write)
        self._buffer = b""
        self._next = 0
        self.events: list[dict[str, Any]] = []

    def send(self, method: str, params: dict[str, Any] | None = None, session: str | None = None,
             timeout: float = 30.0) -> dict[str, Any]:
        self._next += 1
        message: dict[str, Any] = {"id": self._next, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self._commands, json.dumps(message).encode() + b"\0")
        deadline = time.monotonic() + timeout
        while True:
            reply = self._read(deadline)
            if reply.get("id") == self._next:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply.get("result", {})
            self.events.append(reply)

    def _read(self, deadline: float) -> dict[str, Any]:
        import select

        while b"\0" not in self._buffer:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([self._replies], [], [], left)[0]:
                raise TimeoutError("chromium did not answer in time")
            chunk = os.read(self._replies, 1 << 16)
            if not chunk:
                raise RuntimeError("chromium closed its pipe")
            self._buffer += chunk
        raw, _, self._buffer = self._buffer.partition(b"\0")
        return json.loads(raw)

    def pump(self, seconds: float) -> None:
        """Collect events for ``seconds``."""
        deadline = time.monotonic() + seconds
        try:
            while True:
                self.events.append(self._read(deadline))
        except TimeoutError:
            pass

    def close(self) -> None:
        try:
            self.send("Browser.close", timeout=5)
        except Exception:  # noqa: BLE001 - it may already be gone
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        os.close(self._commands)
        os.close(self._replies)


_MEDIA = """
(() => Array.from(document.querySelectorAll("video, img")).map(e => e.tagName === "VIDEO"
  ? {tag: "video", src: e.getAttribute("src"), readyState: e.readyState, error: e.error && e.error.code,
     duration: e.duration, paused: e.paused, width: e.videoWidth, height: e.videoHeight, time: e.currentTime}
  : {tag: "img", src: e.getAttribute("src"), complete: e.complete, naturalWidth: e.naturalWidth,
     naturalHeight: e.naturalHeight}))()
"""


def open_page(url: str, settle: float = 3.0, size: tuple[int, int] = (1280, 2400)) -> PageReport:
    """Load ``url`` in a fresh headless chromium; wait ``settle`` seconds; report what happened."""
    with _session(url, size, ("Runtime", "Log", "Page", "Network")) as (browser, session):
        browser.pump(settle)
        report = PageReport()
        report.media = browser.send("Runtime.evaluate", {"expression": _MEDIA, "returnByValue": True},
                                    session=session)["result"]["value"]
        shot = browser.send("Page.captureScreenshot", {"format": "png", "captureBeyondViewport": False},
                            session=session)
        report.screenshot = base64.b64decode(shot["data"])
        for event in browser.events:
            method, params = event.get("method"), event.get("params", {})
            if method == "Runtime.consoleAPICalled" and params.get("type") in ("error", "assert"):
                report.errors.append("console: " + " ".join(str(a.get("value", a.get("description")))
                                                             for a in params.get("args", [])))
            elif method == "Runtime.exceptionThrown":
                report.errors.append("exception: " + json.dumps(params.get("exceptionDetails", {}))[:300])
            elif method == "Log.entryAdded" and params.get("entry", {}).get("level") == "error":
                entry = params["entry"]
                report.errors.append(f"log: {entry.get('text')} {entry.get('url', '')}")
            elif method == "Network.loadingFailed" and not params.get("canceled"):
                report.errors.append(f"load failed: {params.get('errorText')}")
        return report


def page_url(path: Path) -> str:
    return path.resolve().as_uri()


class LivePage:
    """A page kept open in headless chromium, for tests that change things while it runs."""

    def __init__(self, browser: _Browser, session: str) -> None:
        self._browser = browser
        self._session = session

    def evaluate(self, expression: str) -> Any:
        """The value of a JavaScript expression on the page (JSON-like values)."""
        reply = self._browser.send("Runtime.evaluate", {"expression": expression, "returnByValue": True},
                                   session=self._session)
        if "exceptionDetails" in reply:
            raise RuntimeError(f"{expression}: {reply['exceptionDetails']}")
        return reply["result"].get("value")

    def wait_for(self, expression: str, timeout: float = 20.0, every: float = 0.05) -> Any:
        """Poll ``expression`` until it is truthy (its value), or raise TimeoutError after ``timeout`` seconds.
        An exception counts as not yet (the page may still be loading), and is reported at the timeout."""
        deadline = time.monotonic() + timeout
        while True:
            try:
                value = self.evaluate(expression)
            except RuntimeError as error:
                value = error
            if value and not isinstance(value, RuntimeError):
                return value
            if time.monotonic() > deadline:
                raise TimeoutError(f"{expression} still {value!r} after {timeout} s")
            time.sleep(every)

    def exceptions(self) -> list[str]:
        """Uncaught exceptions and console errors the page has had so far."""
        found = []
        for event in self._browser.events:
            method, params = event.get("method"), event.get("params", {})
            if method == "Runtime.exceptionThrown":
                found.append(json.dumps(params.get("exceptionDetails", {}))[:300])
            elif method == "Runtime.consoleAPICalled" and params.get("type") in ("error", "assert"):
                found.append(json.dumps(params.get("args", []))[:300])
        return found

    def mouse(self, kind: str, x: float, y: float) -> None:
        """A left-button mouse event (``"mousePressed"``, ``"mouseMoved"``, ``"mouseReleased"``) at CSS pixel
        ``(x, y)`` of the page, as the person's pointer sends it."""
        params = {"type": kind, "x": x, "y": y, "button": "left", "clickCount": 1,
                  "buttons": 0 if kind == "mouseReleased" else 1}
        self._browser.send("Input.dispatchMouseEvent", params, session=self._session)

    def click(self, x: float, y: float) -> None:
        self.mouse("mouseMoved", x, y)
        self.mouse("mousePressed", x, y)
        self.mouse("mouseReleased", x, y)

    def drag(self, start: tuple[float, float], end: tuple[float, float], steps: int = 8) -> None:
        self.mouse("mouseMoved", *start)
        self.mouse("mousePressed", *start)
        for i in range(1, steps + 1):
            self.mouse("mouseMoved", start[0] + (end[0] - start[0]) * i / steps, start[1] + (end[1] - start[1]) * i / steps)
        self.mouse("mouseReleased", *end)

    def screenshot(self) -> bytes:
        shot = self._browser.send("Page.captureScreenshot", {"format": "png"}, session=self._session)
        return base64.b64decode(shot["data"])


@contextlib.contextmanager
def live_page(url: str, size: tuple[int, int] = (1400, 900)) -> Iterator[LivePage]:
    """Open ``url`` in a fresh headless chromium and keep it open for the ``with`` block."""
    with _session(url, size, ("Runtime",)) as (browser, session):
        yield LivePage(browser, session)


@contextlib.contextmanager
def _session(url: str, size: tuple[int, int], domains: tuple[str, ...]) -> Iterator[tuple[_Browser, str]]:
    """A fresh headless chromium showing ``url`` at ``size`` with ``domains`` enabled: (browser, session)."""
    executable = chromium()
    if executable is None:
        raise FileNotFoundError("chromium")
    with tempfile.TemporaryDirectory(prefix="tweenrender-chromium-") as profile:
        browser = _Browser(executable, profile)
        try:
            target = browser.send("Target.createTarget", {"url": "about:blank"})["targetId"]
            session = browser.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
            for domain in domains:
                browser.send(f"{domain}.enable", session=session)
            browser.send("Emulation.setDeviceMetricsOverride",
                         {"width": size[0], "height": size[1], "deviceScaleFactor": 1, "mobile": False},
                         session=session)
            browser.send("Page.navigate", {"url": url}, session=session)
            yield browser, session
        finally:
            browser.close()


def svg_screenshots(svgs: list[Path], sizes: list[tuple[int, int]], slot: int, folder: Path) -> list[Any]:
    """Chromium's pictures of ``svgs``, each drawn as an ``<img>`` of its size ``(w, h)`` at the top left of
    a ``slot`` × ``slot`` place, all in one screenshot: RGB floats ``(h, w, 3)`` in [0, 255]."""
    import imageio.v3 as iio

    images = "".join(f"<img src='{svg.as_uri()}' width='{w}' height='{h}' "
                     f"style='position:absolute;left:0;top:{slot * i}px'>" for i, (svg, (w, h)) in
                     enumerate(zip(svgs, sizes)))
    page, shot = folder / "page.html", folder / "shot.png"
    page.write_text(f"<html><body style='margin:0;background:white'>{images}</body></html>")
    subprocess.run([chromium() or "chromium", "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
                    "--allow-file-access-from-files", f"--window-size={slot},{slot * len(svgs)}",
                    f"--screenshot={shot}", page.as_uri()], capture_output=True, timeout=120, check=False)
    whole = iio.imread(shot, mode="RGB").astype(float)
    return [whole[slot * i:slot * i + h, :w] for i, (w, h) in enumerate(sizes)]
