"""Extras drawn in each panel of a frame: vertex paths, onion-skin ghosts, a metric strip.

A :class:`PanelOverlays` is a layer of a :class:`~tweenrender.raster.panels.Composer`:
its ``under`` draws behind the shapes (paths, keys, ghosts), its ``over`` in
front of them (the strip).

* paths: each vertex's trajectory sampled densely with ``core.timeline.evaluate_segment``
  (the Bézier, the rigid arc or the straight line that method really follows),
  thin and light, with every key outlined in dashes;
* onion ``N``: ``N`` inbetweens before and ``N`` after the current frame, every
  :func:`onion_step` frames (a sixth of a second), fading with distance; earlier
  ghosts are outlined warm, later ones cool, like an animator's light table;
* strip: the scene's perimeter ratio (:func:`tweenrender.core.ratios.scene_perimeter_ratio`)
  over the whole clip along the panel's bottom, 1.0 dashed, the current time
  marked and its value printed. Every panel shares one vertical scale.
"""

from __future__ import annotations

from typing import Callable, Sequence

import numpy as np
import skia
from numpy.typing import NDArray

from ..core.ratios import scene_perimeter_ratio
from ..core.timing.timeline import ShapeAt, Track, evaluate_segment, frame_count
from ..model import Color, Scene
from .surface import contours_path, paint_color, polygon_path
from ..core.view import Viewport

__all__ = ["PanelOverlays", "onion_step", "path_polylines", "strip_box", "skia_path", "stroke_paint",
           "fill_paint", "above_strip", "height_with_strip", "PATH_SAMPLES"]

PATH_SAMPLES = 48
"""Samples per vertex path and segment (the curves are quadratic: 48 chords are smooth at any size)."""

_PATH: Color = (40, 48, 70, 110)
_KEY: Color = (40, 48, 70, 170)
_BEFORE: Color = (205, 80, 50, 255)
_AFTER: Color = (45, 115, 205, 255)
_STRIP_BG: Color = (255, 255, 255, 215)
_STRIP_EDGE: Color = (30, 34, 45, 60)
_STRIP_TEXT: Color = (30, 34, 45, 255)
_CURVE: Color = (30, 34, 45, 230)
_NOW: Color = (214, 69, 65, 255)

ShapesAt = Callable[[str | None, float], Sequence[ShapeAt]]


def onion_step(fps: float) -> int:
    """Frames between onion ghosts: ``round(fps / 6)``, at least 1 (4 frames at 24 fps)."""
    return max(1, round(fps / 6))


def path_polylines(track: Track, method: str, samples: int = PATH_SAMPLES) -> list[NDArray[np.float64]]:
    """Every vertex's path over every segment of ``track``: a list of ``(samples, 2)`` world polylines.

    Easing only changes the speed along a path, not its shape, so t is sampled evenly.
    """
    t = np.linspace(0.0, 1.0, samples)
    lines: list[NDArray[np.float64]] = []
    for segment in track.segments:
        stacked = np.stack([np.concatenate(at.contours) for at in evaluate_segment(segment, t, method)])  # (S, N, 2)
        lines.extend(np.transpose(stacked, (1, 0, 2)))
    return lines


def strip_box(width: int, height: int) -> tuple[float, float, float, float]:
    """The strip's pixel rectangle ``(left, top, right, bottom)`` in a ``width × height`` panel."""
    strip = max(30.0, round(height * 0.15))
    pad = max(4.0, round(height * 0.02))
    return pad, height - pad - strip, width - pad, height - pad


def above_strip(viewport: Viewport) -> Viewport:
    """``viewport`` squeezed into the part of its panel above the strip, so no shape hides under it."""
    top = strip_box(viewport.width, viewport.height)[1]
    return Viewport(viewport.view, viewport.width, max(1, int(top - max(4.0, round(viewport.height * 0.02)))))


def height_with_strip(drawing: int) -> int:
    """The smallest panel height whose area above the strip is at least ``drawing`` pixels tall."""
    height = drawing
    while above_strip(Viewport((0.0, 0.0, 1.0, 1.0), 1, height)).height < drawing:
        height += 1
    return height


def skia_path(lines: Sequence[NDArray[np.float64]], closed: bool) -> skia.Path:
    """One skia path through every finite pixel polyline ``(K, 2)`` of ``lines``."""
    path = skia.Path()
    for line in lines:
        if len(line) >= 2 and np.all(np.isfinite(line)):
            path.addPath(polygon_path(line, closed))
    return path


def stroke_paint(color: Color, width: float, alpha: float = 1.0, dashed: bool = False) -> skia.Paint:
    paint = skia.Paint(AntiAlias=True, Style=skia.Paint.kStroke_Style, StrokeWidth=width,
                       StrokeJoin=skia.Paint.kRound_Join, StrokeCap=skia.Paint.kRound_Cap,
                       Color=paint_color(color, alpha))
    if dashed:
        paint.setPathEffect(skia.DashPathEffect.Make([5.0, 4.0], 0.0))
    return paint


def fill_paint(color: Color, alpha: float = 1.0) -> skia.Paint:
    return skia.Paint(AntiAlias=True, Style=skia.Paint.kFill_Style, Color=paint_color(color, alpha))


class PanelOverlays:
    """The overlays of a comparison: one instance serves every panel of a frame.

    ``methods`` holds each panel's method (``None``: each shape's own);
    ``shapes_at(method, time)`` gives every shape as it is at ``time``.
    """

    def __init__(self, scene: Scene, tracks: Sequence[Track], methods: Sequence[str | None],
                 viewport: Viewport, fps: float, shapes_at: ShapesAt, *, paths: bool = False,
                 onion: int = 0, strip: bool = False) -> None:
        self.scene, self.tracks, self.viewport, self.fps = scene, tuple(tracks), viewport, fps
        self.methods = tuple(methods)
        self.shapes_at = shapes_at
        self.onion = max(0, int(onion))
        self.step = onion_step(fps)
        self.duration = scene.duration
        per_shape = [self._shape_methods(m) for m in self.methods]
        self.paths: list[tuple[skia.Path, skia.Path]] | None = None
        if paths:
            self.paths = [self._path_layer(shape_methods) for shape_methods in per_shape]
        self.curves: list[NDArray[np.float64]] | None = None
        if strip:
            times = np.arange(frame_count(self.duration, fps)) / fps
            self.strip_times = times
            self.curves = [scene_perimeter_ratio(self.tracks, m, times) for m in per_shape]
            self.per_shape = per_shape
            low = min(float(np.nanmin(c)) for c in self.curves)
            high = max(float(np.nanmax(c)) for c in self.curves)
            low, high = min(low, 1.0), max(high, 1.0)
            margin = max(0.04, 0.12 * (high - low))
            self.range = (low - margin, high + margin)

    def _shape_methods(self, method: str | None) -> list[str]:
        return [method or self.scene.method_of(shape) for shape in self.scene.shapes]

    def _path_layer(self, shape_methods: Sequence[str]) -> tuple[skia.Path, skia.Path]:
        to_pixels = self.viewport.to_pixels
        curves: list[NDArray[np.float64]] = []
        keys: list[NDArray[np.float64]] = []
        opened: list[NDArray[np.float64]] = []
        for track, shape, method in zip(self.tracks, self.scene.shapes, shape_methods):
            if not track.segments:
                continue
            curves.extend(to_pixels(line) for line in path_polylines(track, method))
            keys.extend(to_pixels(c.points) for key in shape.keys if not key.hidden for c in key.contours if c.closed)
            opened.extend(to_pixels(c.points) for key in shape.keys if not key.hidden for c in key.contours
                          if not c.closed)
        keys_path = skia_path(keys, closed=True)
        keys_path.addPath(skia_path(opened, closed=False))
        return skia_path(curves, closed=False), keys_path

    # -- layer hooks -------------------------------------------------------------------------

    def under(self, canvas: skia.Canvas, panel: int, width: int, height: int, time: float) -> None:
        """Paths, keys and ghosts of ``panel``, drawn before its shapes."""
        if self.paths is not None:
            curves, keys = self.paths[panel]
            canvas.drawPath(keys, stroke_paint(_KEY, 1.2, dashed=True))
            canvas.drawPath(curves, stroke_paint(_PATH, 1.0))
        if self.onion:
            self._ghosts(canvas, panel, time)

    def over(self, canvas: skia.Canvas, panel: int, width: int, height: int, time: float) -> None:
        """The metric strip of ``panel``, drawn after its shapes."""
        if self.curves is not None:
            self._strip(canvas, panel, width, height, time)

    # -- drawing -----------------------------------------------------------------------------

    def _ghosts(self, canvas: skia.Canvas, panel: int, time: float) -> None:
        method = self.methods[panel]
        frame = round(time * self.fps)
        last = frame_count(self.duration, self.fps) - 1
        # farthest first, so nearer ghosts sit on top
        for k in range(self.onion, 0, -1):
            fade = (self.onion + 1 - k) / self.onion  # 1 for the nearest ghost, 1/N for the farthest
            for sign, tint in ((-1, _BEFORE), (1, _AFTER)):
                other = frame + sign * k * self.step
                if not 0 <= other <= last:
                    continue
                for shape, at in zip(self.scene.shapes, self.shapes_at(method, other / self.fps)):
                    if not at.visible:
                        continue
                    pixels = [self.viewport.to_pixels(c) for c in at.contours]
                    path = contours_path(pixels, at.closed, shape.fill_rule)
                    if at.paint.fill is not None:
                        canvas.drawPath(path, fill_paint(at.paint.fill, 0.25 * fade * at.paint.opacity))
                    canvas.drawPath(path, stroke_paint(tint, 1.2, 0.8 * fade))

    def _strip(self, canvas: skia.Canvas, panel: int, width: int, height: int, time: float) -> None:
        from .fonts import font

        assert self.curves is not None
        left, top, right, bottom = strip_box(width, height)
        rect = skia.Rect.MakeLTRB(left, top, right, bottom)
        canvas.drawRect(rect, fill_paint(_STRIP_BG))
        canvas.drawRect(rect, stroke_paint(_STRIP_EDGE, 1.0))
        size = max(9.0, min(16.0, (bottom - top) * 0.3))
        small = font(size * 0.75)
        text = left + size * 0.5
        x0 = (text + max(small.measureText("perimeter ratio"), font(size, bold=True).measureText("0.000"))
              + size * 0.9 + small.measureText("1.0"))  # room for the words, then for the "1.0" tick
        x1 = right - size * 0.6
        y0, y1 = top + size * 0.5, bottom - size * 0.5
        low, high = self.range
        span = max(self.duration, 1e-9)

        def to_xy(t: NDArray[np.float64], r: NDArray[np.float64]) -> NDArray[np.float64]:
            return np.stack([x0 + (x1 - x0) * t / span, y1 - (y1 - y0) * (r - low) / (high - low)], -1)

        one = to_xy(np.array([0.0, span]), np.array([1.0, 1.0]))
        canvas.drawLine(*one[0], *one[1], stroke_paint(_STRIP_TEXT, 1.0, 0.45, dashed=True))
        canvas.drawString("1.0", x0 - small.measureText("1.0") - size * 0.3, one[0][1] + size * 0.27, small,
                          fill_paint(_STRIP_TEXT, 0.6))
        curve = to_xy(self.strip_times, self.curves[panel])
        canvas.drawPath(skia_path([curve], closed=False), stroke_paint(_CURVE, 1.5))
        now = float(scene_perimeter_ratio(self.tracks, self.per_shape[panel], [time])[0])
        x, y = to_xy(np.array([min(time, span)]), np.array([now]))[0]
        canvas.drawLine(x, top + 2, x, bottom - 2, stroke_paint(_NOW, 1.2, 0.8))
        canvas.drawCircle(x, y, max(2.5, size * 0.25), fill_paint(_NOW))
        canvas.drawString("perimeter ratio", text, top + (bottom - top) * 0.42, small, fill_paint(_STRIP_TEXT, 0.7))
        canvas.drawString(f"{now:.3f}", text, top + (bottom - top) * 0.42 + size * 1.05, font(size, bold=True),
                          fill_paint(_STRIP_TEXT))
