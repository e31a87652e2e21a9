"""Independent players of the vector outputs, and the acceptance measures (DESIGN, "Measures used in
acceptance"): rlottie and ThorVG (pip wheels with the player inside) draw Lottie JSON; headless
Chromium draws an animated SVG paused at a time."""

from __future__ import annotations

import base64
import json
import tempfile
import time
from pathlib import Path

import numpy as np

_INK = 32  # a pixel is ink where a channel differs from the background by more than 32/255


def ink(picture: np.ndarray, background: tuple[int, int, int]) -> np.ndarray:
    """Where ``picture (H, W, ≥3)`` differs from the opaque ``background`` by more than 32/255: ``(H, W)`` bool."""
    return np.any(np.abs(picture[..., :3].astype(np.int16) - np.array(background, dtype=np.int16)) > _INK, axis=-1)


def measures(a: np.ndarray, b: np.ndarray, background: tuple[int, int, int]) -> tuple[float, float]:
    """Coverage IoU (|ink A ∩ ink B| / |ink A ∪ ink B|, 1 when neither has ink) and colour error (mean
    absolute RGB difference / 255 over the union of ink, 0 when neither has ink) of two RGB pictures."""
    ink_a, ink_b = ink(a, background), ink(b, background)
    union = ink_a | ink_b
    count = np.count_nonzero(union)
    if count == 0:
        return 1.0, 0.0
    difference = np.abs(a[..., :3].astype(np.int16) - b[..., :3].astype(np.int16))[union]
    return np.count_nonzero(ink_a & ink_b) / count, float(difference.mean() / 255.0)


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


def chromium_svg_frames(files: list[tuple[Path, list[float], tuple[int, int]]]) -> list[list[np.ndarray]]:
    """Headless Chromium's pictures of each animated SVG ``(path, times, (width, height))``, paused at
    each of its ``times`` seconds: RGB ``(H, W, 3)`` each, one browser for all."""
    from tests.browser import _Browser, chromium
    from tests.helpers import read_png

    executable = chromium()
    if executable is None:
        raise FileNotFoundError("chromium")
    out = []
    with tempfile.TemporaryDirectory(prefix="tweenrender-chromium-") as profile:
        browser = _Browser(executable, profile)
        try:
            target = browser.send("Target.createTarget", {"url": "about:blank"})["targetId"]
            session = browser.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
            browser.send("Page.enable", session=session)
            for path, times, (width, height) in files:
                browser.send("Emulation.setDeviceMetricsOverride",
                             {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False},
                             session=session)
                url = path.resolve().as_uri()
                browser.send("Page.navigate", {"url": url}, session=session)
                _wait_for(browser, session, f"location.href === {json.dumps(url)} && document.readyState === 'complete'")
                shots = []
                for when in times:
                    browser.send("Runtime.evaluate", {"expression": _PAUSE.format(time=repr(float(when))),
                                                      "returnByValue": True}, session=session)
                    browser.send("Runtime.evaluate", {"expression": "new Promise(r => requestAnimationFrame(() => "
                                                                    "requestAnimationFrame(r)))",
                                                      "awaitPromise": True}, session=session)
                    shot = browser.send("Page.captureScreenshot", {"format": "png"}, session=session)
                    with tempfile.NamedTemporaryFile(suffix=".png") as handle:
                        handle.write(base64.b64decode(shot["data"]))
                        handle.flush()
                        shots.append(read_png(Path(handle.name))[..., :3])
                out.append(shots)
        finally:
            browser.close()
    return out


def _wait_for(browser: object, session: str, condition: str, seconds: float = 20.0) -> None:
    """Poll the page until the JavaScript ``condition`` holds."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        reply = browser.send("Runtime.evaluate", {"expression": condition, "returnByValue": True},  # type: ignore[attr-defined]
                             session=session)
        if reply.get("result", {}).get("value") is True:
            return
        time.sleep(0.05)
    raise TimeoutError(f"the page never met {condition}")
