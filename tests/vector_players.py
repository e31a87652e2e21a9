"""Independent players of the vector outputs, and the acceptance measures (DESIGN, "Measures used in
acceptance"): rlottie and ThorVG (pip wheels with the player inside) and Skottie (skia's Lottie player,
npm ``canvaskit-wasm`` run by node, CPU raster) draw Lottie JSON; headless Chromium draws an animated
SVG paused at a time.

lottie-web (the bodymovin player, npm ``lottie-web``) draws Lottie JSON with its SVG renderer in headless
Chromium, stopped at each frame.

Skottie and lottie-web come from the npm folder ``.ci/run`` installs into: ``$TWEENRENDER_NPM`` if set, else
``~/.cache/tweenrender/npm`` (``node_modules/canvaskit-wasm`` and ``node_modules/lottie-web`` inside);
without it, or without node (Skottie) or chromium (lottie-web), the checks that need it skip, saying so."""

from __future__ import annotations

import base64
import contextlib
import json
import os
import shutil
import subprocess
import tempfile
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import numpy as np

IOU, COLOUR = 0.98, 0.03
"""The acceptance bounds: coverage IoU at least, colour error at most."""
_INK = 32  # a pixel is ink where a channel differs from the background by more than 32/255


def bezier_timing(x: np.ndarray, handles: np.ndarray | tuple[float, float, float, float]) -> np.ndarray:
    """CSS ``cubic-bezier(x1, y1, x2, y2)`` at ``x (T,)`` as players evaluate it: y(u) where x(u) = x, u found
    by bisection; ``handles`` one ``(4,)`` for all or ``(T, 4)``, one for each x."""
    x1, y1, x2, y2 = np.asarray(handles, dtype=np.float64).T

    def curve(u: np.ndarray, p1: np.ndarray, p2: np.ndarray) -> np.ndarray:
        return 3 * (1 - u) ** 2 * u * p1 + 3 * (1 - u) * u ** 2 * p2 + u ** 3

    low, high = np.zeros_like(x), np.ones_like(x)
    for _ in range(60):
        middle = (low + high) / 2
        below = curve(middle, x1, x2) < x
        low, high = np.where(below, middle, low), np.where(below, high, middle)
    return curve((low + high) / 2, y1, y2)


def ink(picture: np.ndarray, background: tuple[int, int, int]) -> np.ndarray:
    """Where ``picture (H, W, ≥3)`` uint8 differs from the opaque ``background`` by more than 32/255: ``(H, W)``
    bool (|v − level| > 32 tested as v < level − 32 or v > level + 32, on the uint8 values as they are)."""
    out = np.zeros(picture.shape[:2], dtype=bool)
    for channel, level in enumerate(background[:3]):
        values = picture[..., channel]
        if level - _INK > 0:
            out |= values < level - _INK
        if level + _INK < 255:
            out |= values > level + _INK
    return out


def measures(a: np.ndarray, b: np.ndarray, background: tuple[int, int, int]) -> tuple[float, float]:
    """Coverage IoU (|ink A ∩ ink B| / |ink A ∪ ink B|, 1 when neither has ink) and colour error (mean
    absolute RGB difference / 255 over the union of ink, 0 when neither has ink) of two RGB pictures."""
    ink_a, ink_b = ink(a, background), ink(b, background)
    union = ink_a | ink_b
    count = np.count_nonzero(union)
    if count == 0:
        return 1.0, 0.0
    # channel by channel, summed as integers: the same mean as over the (count, 3) differences at once
    total = sum(int(np.abs(a[..., c][union].astype(np.int16) - b[..., c][union].astype(np.int16)).sum())
                for c in range(3))
    return np.count_nonzero(ink_a & ink_b) / count, float(total / (3 * count) / 255.0)


def coverage_iou(a: np.ndarray, b: np.ndarray, background: tuple[int, int, int]) -> float:
    """|ink A ∩ ink B| / |ink A ∪ ink B| (1 when neither has ink)."""
    return measures(a, b, background)[0]


def colour_error(a: np.ndarray, b: np.ndarray, background: tuple[int, int, int]) -> float:
    """Mean absolute RGB difference / 255 over the union of ink (0 when neither has ink)."""
    return measures(a, b, background)[1]


def over(picture: np.ndarray, background: tuple[int, int, int]) -> np.ndarray:
    """Straight RGBA ``(H, W, 4)`` composited over an opaque ``background``: ``(H, W, 3)`` uint8."""
    if picture.shape[-1] == 3 or np.all(picture[..., 3] == 255):
        return picture[..., :3]
    alpha = picture[..., 3:4].astype(np.float32) / 255.0
    return np.rint(picture[..., :3] * alpha + np.array(background, dtype=np.float32) * (1 - alpha)).astype(np.uint8)


def background_of(scene: object) -> tuple[int, int, int]:
    """The opaque colour a scene's pictures are compared over: its background, else white."""
    colour = scene.background  # type: ignore[attr-defined]
    return colour[:3] if colour[3] == 255 else (255, 255, 255)


def check_pictures(scene: object, pictures: list[np.ndarray], frames: list[int], method: str | None,
                   player: str, ours: Callable[[int], np.ndarray] | None = None) -> list[tuple[float, float]]:
    """Assert that each of ``pictures`` (RGB or straight RGBA) of ``frames`` is within :data:`IOU` and
    :data:`COLOUR` of ``tr.frame`` of ``scene`` at the same time (``ours(frame)``, where given, is that frame
    over the background, already drawn); returns the measures per frame."""
    background = background_of(scene)
    draw = ours or (lambda frame: project_frame(scene, frame, method))
    out = []
    for frame, picture in zip(frames, pictures):
        theirs = over(picture, background) if picture.shape[-1] == 4 else picture
        iou, error = measures(draw(frame), theirs, background)
        assert iou >= IOU and error <= COLOUR, f"{player}, frame {frame}: IoU {iou:.4f}, colour error {error:.4f}"
        out.append((iou, error))
    return out


def project_frame(scene: object, frame: int, method: str | None) -> np.ndarray:
    """``tr.frame`` of ``scene`` at frame ``frame`` under ``method``, over its background: ``(H, W, 3)`` uint8."""
    import tweenrender as tr

    return over(tr.frame(scene, frame / scene.fps, method=method), background_of(scene))  # type: ignore[attr-defined]


def sample_frames(scene: object, count: int) -> list[int]:
    """Ten frames evenly from the first to the last, and the frames on both sides of every key
    (where the layers of consecutive segments hand over)."""
    keys = {round(key.time * scene.fps) for shape in scene.shapes for key in shape.keys}  # type: ignore[attr-defined]
    around = {f + d for f in keys for d in (-1, 0) if 0 <= f + d < count}
    return sorted({0, count - 1, *np.linspace(0, count - 1, 10).round().astype(int).tolist(), *around})


class Clip:
    """``scene`` under ``method`` written once as Lottie and once as an animated SVG into ``folder`` (each when
    first asked for), with the project's own frames drawn once each: what several players are checked against."""

    def __init__(self, scene: object, folder: Path, method: str | None = None, name: str = "clip") -> None:
        from tweenrender.plan.job import total_frames

        self.scene, self.folder, self.method, self.name = scene, folder, method, name
        self.count = total_frames(scene)
        self.sample = sample_frames(scene, self.count)
        self._lottie: Path | None = None
        self._svg: Path | None = None
        self._ours: dict[int, np.ndarray] = {}

    @property
    def size(self) -> tuple[int, int]:
        return self.scene.size  # type: ignore[attr-defined]

    @property
    def lottie(self) -> Path:
        """The Lottie file of the clip, written on first need."""
        if self._lottie is None:
            import tweenrender as tr

            self._lottie = tr.write(self.scene, self.folder / f"{self.name}.json", method=self.method)
        return self._lottie

    def svg(self) -> Path:
        """The animated SVG of the clip, written on first need."""
        if self._svg is None:
            import tweenrender as tr

            self._svg = tr.write(self.scene, self.folder / f"{self.name}.svg", method=self.method)
        return self._svg

    def ours(self, frame: int) -> np.ndarray:
        """The project's frame ``frame`` over the background: ``(H, W, 3)`` uint8, drawn once."""
        if frame not in self._ours:
            self._ours[frame] = project_frame(self.scene, frame, self.method)
        return self._ours[frame]

    def frames(self, every_frame: bool) -> list[int]:
        return list(range(self.count)) if every_frame else self.sample

    def check(self, pictures: list[np.ndarray], frames: list[int], player: str) -> None:
        check_pictures(self.scene, pictures, frames, self.method, player, self.ours)

    def check_rlottie_thorvg(self, every_frame: bool = True) -> None:
        """rlottie's pictures of every frame (or the sample) and ThorVG's of the sample."""
        frames = self.frames(every_frame)
        self.check(rlottie_frames(self.lottie, frames, self.size), frames, "rlottie")
        self.check(thorvg_frames(self.lottie, self.sample, self.size), self.sample, "ThorVG")

    def check_skottie(self, every_frame: bool = True) -> None:
        frames = self.frames(every_frame)
        self.check(skottie_frames(self.lottie, frames, self.size), frames, "Skottie")

    def check_lottie_web(self, every_frame: bool = True, browser: PlayerBrowser | None = None) -> None:
        frames = self.frames(every_frame)
        self.check(lottie_web_frames(self.lottie, frames, self.size, background_of(self.scene), browser), frames,
                   "lottie-web")

    def five_times(self) -> list[int]:
        """The frames at t = 0, ¼, ½, ¾, 1 of the clip."""
        return sorted({round(q * (self.count - 1)) for q in (0, 0.25, 0.5, 0.75, 1)})

    def check_chromium(self, browser: PlayerBrowser | None = None) -> None:
        """Chromium's pictures of the animated SVG paused at t = 0, ¼, ½, ¾, 1 (at frame times)."""
        frames = self.five_times()
        fps = self.scene.fps  # type: ignore[attr-defined]
        pictures = chromium_svg_frames([(self.svg(), [f / fps for f in frames], self.size)], browser)[0]
        self.check(pictures, frames, f"Chromium, {self.name}")


def check_lottie_players(scene: object, folder: Path, method: str | None = None, every_frame: bool = True) -> None:
    """Write ``scene`` as Lottie and check what rlottie (every frame, or :func:`sample_frames`) and ThorVG
    (the sample) draw of it against the project's frames."""
    Clip(scene, folder, method).check_rlottie_thorvg(every_frame)


def check_skottie(scene: object, folder: Path, method: str | None = None, every_frame: bool = True) -> None:
    """Write ``scene`` as Lottie and check what Skottie draws of every frame (or :func:`sample_frames`)
    against the project's frames (the caller skips first where :func:`skottie_missing` says why it cannot run)."""
    Clip(scene, folder, method, "skottie").check_skottie(every_frame)


def check_lottie_web(scene: object, folder: Path, method: str | None = None, every_frame: bool = True) -> None:
    """Write ``scene`` as Lottie and check what lottie-web (SVG renderer, headless Chromium) draws of every frame
    (or :func:`sample_frames`) against the project's frames (the caller skips first where
    :func:`lottie_web_missing` says why it cannot run)."""
    Clip(scene, folder, method, "lottie-web").check_lottie_web(every_frame)


def check_chromium(cases: list[tuple[str, object, str | None]], folder: Path,
                   browser: PlayerBrowser | None = None) -> None:
    """Write each ``(name, scene, method)`` as an animated SVG and check Chromium's pictures at t = 0, ¼, ½, ¾, 1
    of the clip (at frame times) against the project's frames, one browser for all (``browser`` if given)."""
    import tweenrender as tr
    from tweenrender.plan.job import total_frames

    files, picks = [], []
    for name, scene, method in cases:
        target = tr.write(scene, folder / f"{name}.svg", method=method)
        count = total_frames(scene)
        frames = sorted({round(q * (count - 1)) for q in (0, 0.25, 0.5, 0.75, 1)})
        files.append((target, [f / scene.fps for f in frames], scene.size))  # type: ignore[attr-defined]
        picks.append(frames)
    shots = chromium_svg_frames(files, browser)
    for (name, scene, method), frames, pictures in zip(cases, picks, shots):
        check_pictures(scene, pictures, frames, method, f"Chromium, {name}")


def npm_folder() -> Path:
    """Where ``.ci/run`` installs the npm players: ``$TWEENRENDER_NPM``, else ``~/.cache/tweenrender/npm``."""
    return Path(os.environ.get("TWEENRENDER_NPM") or Path.home() / ".cache" / "tweenrender" / "npm")


def skottie_missing() -> str | None:
    """Why Skottie cannot be run here (``None``: it can)."""
    if shutil.which("node") is None:
        return "no node on this machine to run Skottie (npm canvaskit-wasm)"
    if not (npm_folder() / "node_modules" / "canvaskit-wasm" / "bin" / "full" / "canvaskit.js").exists():
        return f"Skottie (npm canvaskit-wasm) is not installed in {npm_folder()} (.ci/run installs it there)"
    return None


def lottie_web_player() -> Path:
    """Where lottie-web's player script is in :func:`npm_folder`."""
    return npm_folder() / "node_modules" / "lottie-web" / "build" / "player" / "lottie.min.js"


def lottie_web_missing() -> str | None:
    """Why lottie-web cannot be run here (``None``: it can)."""
    from tests.browser import chromium

    if chromium() is None:
        return "no chromium on this machine to run lottie-web"
    if not lottie_web_player().exists():
        return f"lottie-web (npm lottie-web) is not installed in {npm_folder()} (.ci/run installs it there)"
    return None


_LOTTIE_PAGE = """<!doctype html><html><head><style>
html, body {{ margin: 0; overflow: hidden; background: {background} }} svg {{ display: block }}</style></head><body>
<div id="stage" style="width:{width}px;height:{height}px"></div>
<script src="{player}"></script><script src="animation.js"></script>
<script>window.animation = lottie.loadAnimation({{container: document.getElementById("stage"), renderer: "svg",
loop: false, autoplay: false, animationData: window.animationData}});</script></body></html>"""


class PlayerBrowser:
    """One headless Chromium page kept for many pictures (each start of a browser costs about half a CPU
    second): :meth:`show` a URL at a size, then :meth:`shot`."""

    def __init__(self) -> None:
        from tests.browser import _Browser, chromium

        executable = chromium()
        if executable is None:
            raise FileNotFoundError("chromium")
        self._profile = tempfile.TemporaryDirectory(prefix="tweenrender-players-")
        self.browser = _Browser(executable, self._profile.name)
        target = self.browser.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        self.session = self.browser.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        self.browser.send("Page.enable", session=self.session)

    def show(self, url: str, size: tuple[int, int], ready: str) -> None:
        """Load ``url`` in a ``size = (width, height)`` window and wait until the JavaScript ``ready`` holds."""
        width, height = size
        self.browser.send("Emulation.setDeviceMetricsOverride",
                          {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False},
                          session=self.session)
        self.browser.send("Page.navigate", {"url": url}, session=self.session)
        _wait_for(self.browser, self.session, f"location.href === {json.dumps(url)} && ({ready})")

    def run(self, expression: str) -> None:
        self.browser.send("Runtime.evaluate", {"expression": expression, "returnByValue": True}, session=self.session)

    def shot(self) -> np.ndarray:
        return _painted_shot(self.browser, self.session)

    def close(self) -> None:
        self.browser.close()
        self._profile.cleanup()


@contextlib.contextmanager
def _kept_or_own(browser: PlayerBrowser | None) -> Iterator[PlayerBrowser]:
    """``browser`` when given (left open), else a browser of its own, closed afterwards."""
    if browser is not None:
        yield browser
        return
    own = PlayerBrowser()
    try:
        yield own
    finally:
        own.close()


def lottie_web_frames(path: Path, frames: list[int], size: tuple[int, int], background: tuple[int, int, int],
                      browser: PlayerBrowser | None = None) -> list[np.ndarray]:
    """lottie-web's pictures of ``frames`` (its SVG renderer in headless Chromium, ``goToAndStop`` at each frame,
    over the opaque ``background``; in ``browser`` if given): RGB ``(H, W, 3)`` each."""
    width, height = size
    out = []
    with tempfile.TemporaryDirectory(prefix="tweenrender-lottie-web-") as scratch, _kept_or_own(browser) as shown:
        (Path(scratch) / "animation.js").write_text(f"window.animationData = {path.read_text(encoding='utf-8')};",
                                                    encoding="utf-8")
        page = Path(scratch) / "page.html"
        page.write_text(_LOTTIE_PAGE.format(background="rgb({},{},{})".format(*background), width=width,
                                            height=height, player=lottie_web_player().resolve().as_uri()),
                        encoding="utf-8")
        shown.show(page.resolve().as_uri(), size, "!!(window.animation && window.animation.isLoaded)")
        for frame in frames:
            shown.run(f"window.animation.goToAndStop({frame}, true)")
            out.append(shown.shot())
    return out


def _painted_shot(browser, session) -> np.ndarray:  # type: ignore[no-untyped-def]
    """The page once two animation frames have been painted: ``(H, W, 3)`` uint8."""
    from tests.helpers import read_png

    browser.send("Runtime.evaluate", {"expression": "new Promise(r => requestAnimationFrame(() => "
                                                    "requestAnimationFrame(r)))",
                                      "awaitPromise": True}, session=session)
    shot = browser.send("Page.captureScreenshot", {"format": "png", "optimizeForSpeed": True}, session=session)
    with tempfile.NamedTemporaryFile(suffix=".png") as handle:
        handle.write(base64.b64decode(shot["data"]))
        handle.flush()
        return read_png(Path(handle.name))[..., :3]


def skottie_frames(path: Path, frames: list[int], size: tuple[int, int]) -> list[np.ndarray]:
    """Skottie's pictures of ``frames`` (CanvasKit's CPU raster, run by node): straight RGBA ``(H, W, 4)`` each."""
    width, height = size
    script = Path(__file__).with_name("skottie_frames.js")
    with tempfile.TemporaryDirectory(prefix="tweenrender-skottie-") as scratch:
        out = Path(scratch) / "frames.rgba"
        done = subprocess.run(["node", str(script), str(npm_folder() / "node_modules" / "canvaskit-wasm"), str(path),
                               str(width), str(height), str(out), *map(str, frames)],
                              capture_output=True, text=True, timeout=600)
        assert done.returncode == 0, f"Skottie failed on {path}: {done.stderr.strip()[-500:]}"
        raw = np.frombuffer(out.read_bytes(), np.uint8).reshape(len(frames), height, width, 4)
    return [frame.copy() for frame in raw]


def rlottie_frames(path: Path, frames: list[int], size: tuple[int, int]) -> list[np.ndarray]:
    """rlottie's pictures of ``frames``: straight RGBA ``(H, W, 4)`` each (it draws premultiplied BGRA)."""
    from rlottie_python import LottieAnimation

    width, height = size
    animation = LottieAnimation.from_file(str(path))
    out = []
    for f in frames:
        raw = np.frombuffer(animation.lottie_animation_render(frame_num=f, width=width, height=height),
                            np.uint8).reshape(height, width, 4)
        out.append(_unpremultiply(raw[..., [2, 1, 0, 3]]))
    return out


def thorvg_frames(path: Path, frames: list[int], size: tuple[int, int]) -> list[np.ndarray]:
    """ThorVG's pictures of ``frames``: straight RGBA ``(H, W, 4)`` each."""
    import thorvg_python as tvg

    width, height = size
    engine = tvg.Engine()
    try:
        canvas = tvg.SwCanvas(engine)
        canvas.set_target(width, height)
        animation = tvg.LottieAnimation(engine)
        picture = animation.get_picture()
        picture.load_data(path.read_bytes(), "lottie", None, True)
        picture.set_size(width, height)
        canvas.add(picture)
        out = []
        for f in frames:
            animation.set_frame(float(f))
            canvas.update()
            canvas.draw(True)
            canvas.sync()
            out.append(np.array(canvas.get_pillow("RGBA")))
        return out
    finally:
        engine.term() if hasattr(engine, "term") else None


def _unpremultiply(rgba: np.ndarray) -> np.ndarray:
    if np.all(rgba[..., 3] == 255):
        return rgba
    alpha = rgba[..., 3:4].astype(np.float64)
    with np.errstate(divide="ignore", invalid="ignore"):
        rgb = np.where(alpha > 0, rgba[..., :3] * 255.0 / alpha, 0)
    return np.concatenate([np.clip(np.rint(rgb), 0, 255), alpha], axis=-1).astype(np.uint8)


_PAUSE = """
(() => {{ const svg = document.documentElement; svg.pauseAnimations(); svg.setCurrentTime({time});
  return svg.getCurrentTime(); }})()
"""


def chromium_svg_frames(files: list[tuple[Path, list[float], tuple[int, int]]],
                        browser: PlayerBrowser | None = None) -> list[list[np.ndarray]]:
    """Headless Chromium's pictures of each animated SVG ``(path, times, (width, height))``, paused at
    each of its ``times`` seconds: RGB ``(H, W, 3)`` each, one browser for all (``browser`` if given)."""
    out = []
    with _kept_or_own(browser) as shown:
        for path, times, size in files:
            shown.show(path.resolve().as_uri(), size, "document.readyState === 'complete'")
            shots = []
            for when in times:
                shown.run(_PAUSE.format(time=repr(float(when))))
                shots.append(shown.shot())
            out.append(shots)
    return out


def _wait_for(browser: object, session: str, condition: str, seconds: float = 20.0) -> None:
    """Poll the page until the JavaScript ``condition`` holds."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        reply = browser.send("Runtime.evaluate",  # type: ignore[attr-defined]
                             {"expression": condition, "returnByValue": True}, session=session)
        if reply.get("result", {}).get("value") is True:
            return
        time.sleep(0.05)
    raise TimeoutError(f"the page never met {condition}")


def module_browser() -> Iterator[PlayerBrowser | None]:
    """A test module's fixture body: one headless Chromium for every picture its browser players take, closed
    after the module (None where there is no chromium)."""
    from tests.browser import chromium

    if chromium() is None:
        yield None
        return
    kept = PlayerBrowser()
    try:
        yield kept
    finally:
        kept.close()
