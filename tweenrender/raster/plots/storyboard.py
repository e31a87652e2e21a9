"""A storyboard in the style of the thesis's figures 6.1 and 7.3: keys and inbetweens overlaid.

One row per method on a shared world view, so sizes compare across rows: the
keys outlined strongly over a light fill, the inbetweens as thin outlines over
a fainter fill, each row labelled with its method and the scene's perimeter
ratio at the middle of each segment (:mod:`tweenrender.core.ratios`). Each segment's
timing is drawn as an animator's chart between its keys (:mod:`.timing_chart`), and
shape hints as lettered dots on the keys.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
import skia
from numpy.typing import NDArray

from ...core.ratios import perimeter_ratio, segment_midpoints
from ...core.timeline import Track
from ...model import Color, Paint, Scene
from ..overlays import path_polylines, skia_path, stroke_paint
from ..painter import Painter
from ..surface import Raster, contours_path
from ..view import Box, Viewport

__all__ = ["SheetLayout", "sheet_layout", "draw_sheet", "inbetween_times"]

_INK: Color = (30, 34, 45, 255)
_SOFT: Color = (30, 34, 45, 150)
_RULE: Color = (30, 34, 45, 50)
_PATH: Color = (40, 48, 70, 90)


def inbetween_times(duration: float, count: int) -> NDArray[np.float64]:
    """``count`` times evenly spaced strictly inside ``(0, duration)``: ``(count,)`` seconds."""
    return np.linspace(0.0, duration, count + 2)[1:-1]


class SheetLayout:
    """Pixel geometry of a sheet: a title band, then ``rows`` rows, each a label band over a drawing."""

    def __init__(self, width: int, height: int, rows: int) -> None:
        self.width, self.height, self.rows = width, height, rows
        self.title = max(24.0, min(64.0, height * 0.08))
        self.row = (height - self.title) / rows
        self.label = max(16.0, min(44.0, self.row * 0.16))
        self.pad = max(4.0, min(16.0, width * 0.012))

    def drawing(self, row: int) -> tuple[float, float, int, int]:
        """Left, top, width, height (pixels) of the drawing area of ``row``."""
        top = self.title + row * self.row + self.label
        return self.pad, top, int(self.width - 2 * self.pad), int(max(1.0, self.row - self.label - self.pad))


def sheet_layout(view: Box, rows: int, size: tuple[int, int] | None) -> SheetLayout:
    """The asked ``size``, or 1280 wide with rows as tall as the view's aspect asks (200 to 420 px drawings)."""
    if size is not None:
        return SheetLayout(size[0], size[1], rows)
    width = 1280
    x0, y0, x1, y1 = view
    drawing = float(np.clip((width - 32) * (y1 - y0) / (x1 - x0), 200, 420))
    probe = SheetLayout(width, 1000, rows)
    row = drawing + probe.pad + max(16.0, min(44.0, drawing * 0.19))
    return SheetLayout(width, int(round(64 + rows * row)), rows)


def draw_sheet(scene: Scene, tracks: Sequence[Track], methods: Sequence[str], view: Box,
               layout: SheetLayout, count: int, paths: bool = False) -> NDArray[np.uint8]:
    """The storyboard as straight RGBA ``(height, width, 4)`` (a new array)."""
    from ..fonts import font

    raster = Raster(layout.width, layout.height)
    canvas = raster.canvas
    raster.clear(scene.background)
    times = inbetween_times(scene.duration, count)
    mids = segment_midpoints(tracks)
    title = scene.title or (scene.path.stem if scene.path else "scene")
    size = layout.title * 0.42
    room = layout.width - 2 * layout.pad
    title_size = min(size, size * room / max(font(size, bold=True).measureText(title), 1.0))  # fit, never clip
    raster.text(title, layout.pad, layout.title * 0.56, title_size, _INK, bold=True)
    spacing = f", every {times[1] - times[0]:g} s" if len(times) > 1 else ""
    legend = (f"bold: keys at {', '.join(f'{k:g}' for k in _key_times(scene))} s  ·  "
              f"thin: {len(times)} inbetweens{spacing}" + ("  ·  lines: vertex paths" if paths else "")
              + f"  ·  red ticks: where each frame falls ({scene.fps:g} fps)")
    raster.text(legend, layout.pad, layout.title * 0.9, size * 0.62, _SOFT)
    for row, method in enumerate(methods):
        shape_methods = [method for _ in scene.shapes]
        top = layout.title + row * layout.row
        if row:
            raster.line((0, top), (layout.width, top), _RULE, 1.0)
        label = min(layout.label * 0.42, layout.title * 0.4)
        raster.text(method, layout.pad, top + layout.label * 0.72, label, _INK, bold=True)
        if len(mids):
            ratios = perimeter_ratio(tracks, shape_methods, mids)
            words = "  ·  ".join(f"{m:g} s: {r:.5f}" for m, r in zip(mids[:6], ratios[:6]))
            note = f"perimeter ratio at mid-segment  {words}"
            raster.text(note, layout.pad + font(label, bold=True).measureText(method) + label,
                        top + layout.label * 0.72, label * 0.72, _SOFT)
        left, y, width, height = layout.drawing(row)
        port = Viewport(view, width, height)
        canvas.save()
        canvas.translate(left, y)
        canvas.clipRect(skia.Rect.MakeWH(width, height))
        if paths:
            lines = [port.to_pixels(line) for track, m in zip(tracks, shape_methods) for line in path_polylines(track, m)]
            canvas.drawPath(skia_path(lines, closed=False), stroke_paint(_PATH, 1.0))
        for when in times:
            for track, shape in zip(tracks, scene.shapes):
                if track.segments:
                    at = track.at(np.array([when]), method)[0]
                    if at.visible:
                        _outline(raster, port, shape.fill_rule, at.contours, at.closed, at.paint, 0.07, 1.1, 0.9)
        for shape in scene.shapes:
            for key in shape.keys:
                if not key.hidden:
                    _outline(raster, port, shape.fill_rule, [c.points for c in key.contours],
                             [c.closed for c in key.contours], key.paint, 0.2, 2.6, 1.0, key.paint.stroke or _INK)
        from .timing_chart import draw_hint_marks, draw_timing_charts

        marks = Painter(raster, 1.0)
        draw_timing_charts(marks, port, (0.0, 0.0), scene, tracks, scene.fps)
        draw_hint_marks(marks, port, (0.0, 0.0), scene.shapes, tracks, method)
        canvas.restore()
    return raster.rgba().copy()


def _outline(raster: Raster, port: Viewport, fill_rule: str, contours: Sequence[NDArray[np.float64]],
             closed: Sequence[bool], paint: Paint, fill_alpha: float, width: float, edge_alpha: float,
             edge: Color | None = None) -> None:
    """A light fill and a thin outline of contours in the colour they are painted (keys: a stronger edge)."""
    color = paint.fill or paint.stroke or _INK
    path = contours_path([port.to_pixels(c) for c in contours], closed, fill_rule)
    raster.draw_path(path, color if paint.fill is not None else None, None, 0.0, opacity=fill_alpha)
    raster.draw_path(path, None, edge or color, width, opacity=edge_alpha)


def _key_times(scene: Scene) -> list[float]:
    return sorted({key.time for shape in scene.shapes if len(shape.keys) > 1 for key in shape.keys})


