"""A storyboard in the style of the thesis's figures 6.1 and 7.3: keys and inbetweens overlaid.

One row per method on a shared world view, so sizes compare across rows: the
keys outlined strongly over a light fill, the inbetweens as thin outlines over
a fainter fill, each row labelled with its method and the scene's perimeter
ratio at the middle of each segment (:mod:`tweenrender.core.ratios`). Each segment's
timing is drawn as an animator's chart between its keys (:mod:`.timing_chart`), and
shape hints as lettered dots on the keys, with the paths they force.

A scene of whole drawings is shown as a filmstrip instead: each row the keys and
inbetweens side by side, each drawn as the frame is (paint, stroke widths, paint
order), with its outlines as a thin overlay and its time beneath.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
import skia
from numpy.typing import NDArray

from ...core.ratios import scene_perimeter_ratio, segment_midpoints
from ...core.timing.timeline import Track
from ...model import Color, Paint, Scene
from ..overlays import path_polylines, skia_path, stroke_paint
from ..painter import Painter
from ..surface import Raster, contours_path
from ...core.view import Box, Viewport

__all__ = ["SheetLayout", "sheet_layout", "draw_sheet", "inbetween_times", "is_drawing", "seconds"]

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


def sheet_layout(view: Box, rows: int, size: tuple[int, int] | None, cells: int = 1) -> SheetLayout:
    """The asked ``size``, or 1280 wide with rows as tall as the view's aspect asks (200 to 420 px drawings;
    a filmstrip of ``cells`` pictures a row: as tall as a cell asks, with its caption, 60 px at least)."""
    if size is not None:
        return SheetLayout(size[0], size[1], rows)
    width = 1280
    x0, y0, x1, y1 = view
    if cells > 1:
        cell = (width - 32 - _GAP * (cells - 1)) / cells
        drawing = float(max(60.0, cell * (y1 - y0) / (x1 - x0) + 1.6 * max(10.0, min(16.0, cell * 0.14))))
    else:
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
    spacing = f", every {seconds(times[1] - times[0])} s" if len(times) > 1 else ""
    legend = (f"bold: keys at {', '.join(seconds(k) for k in _key_times(scene))} s  ·  "
              f"thin: {len(times)} inbetweens{spacing}" + ("  ·  lines: vertex paths" if paths else "")
              + f"  ·  red ticks: where each frame falls ({scene.fps:g} fps)")
    if is_drawing(scene):
        legend = (f"keys at {', '.join(seconds(k) for k in _key_times(scene))} s and {len(times)} inbetweens{spacing}, "
                  "as drawn; thin lines: the outlines" + ("; vertex paths" if paths else ""))
    raster.text(legend, layout.pad, layout.title * 0.9, size * 0.62, _SOFT)
    for row, method in enumerate(methods):
        shape_methods = [method for _ in scene.shapes]
        top = layout.title + row * layout.row
        if row:
            raster.line((0, top), (layout.width, top), _RULE, 1.0)
        label = min(layout.label * 0.42, layout.title * 0.4)
        raster.text(method, layout.pad, top + layout.label * 0.72, label, _INK, bold=True)
        if len(mids):
            ratios = scene_perimeter_ratio(tracks, shape_methods, mids)
            words = "  ·  ".join(f"{seconds(m)} s: {r:.5f}" for m, r in zip(mids[:6], ratios[:6]))
            note = f"perimeter ratio at mid-segment  {words}"
            raster.text(note, layout.pad + font(label, bold=True).measureText(method) + label,
                        top + layout.label * 0.72, label * 0.72, _SOFT)
        left, y, width, height = layout.drawing(row)
        port = Viewport(view, width, height)
        canvas.save()
        canvas.translate(left, y)
        canvas.clipRect(skia.Rect.MakeWH(width, height))
        if is_drawing(scene):
            canvas.restore()
            _filmstrip(raster, scene, tracks, method, view, (left, y, width, height), times, paths)
            continue
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


def is_drawing(scene: Scene) -> bool:
    """Whether the scene holds whole drawings (keys that know their place in a drawing's paint order)."""
    from ...core.stacking import layered

    return layered(scene.shapes)


_GAP = 6.0  # pixels between the cells of a filmstrip
_OVERLAY: Color = (30, 34, 45, 90)


def _filmstrip(raster: Raster, scene: Scene, tracks: Sequence[Track], method: str, view: Box,
               area: tuple[float, float, int, int], inbetweens: NDArray[np.float64], paths: bool) -> None:
    """One row of a drawing's sheet: the first key, the inbetweens and the last key, each as drawn."""
    from ...core.stacking import order_at, stacking_plan
    from ..panels import draw_shape

    left, top, width, height = area
    times = np.concatenate([[0.0], inbetweens, [scene.duration]])
    plan = stacking_plan(scene.shapes, lambda i, when: tracks[i].at(when, method))
    cell = (width - _GAP * (len(times) - 1)) / len(times)
    caption = max(10.0, min(16.0, cell * 0.14))
    port = Viewport(view, max(1, int(cell)), max(1, int(height - 1.6 * caption)))
    canvas = raster.canvas
    keys = set(_key_times(scene))
    for k, when in enumerate(times.tolist()):
        x = left + k * (cell + _GAP)
        canvas.save()
        canvas.translate(x, top)
        canvas.clipRect(skia.Rect.MakeWH(cell, height))
        shapes = [track.at(np.array([when]), method)[0] for track in tracks]
        if paths:
            lines = [port.to_pixels(line) for track in tracks for line in path_polylines(track, method)]
            canvas.drawPath(skia_path(lines, closed=False), stroke_paint(_PATH, 0.8))
        for index in order_at(plan, scene.shapes, when):
            draw_shape(raster, port, scene.shapes[index], shapes[index])
        for at in shapes:
            if at.visible and at.contours:
                pixels = [port.to_pixels(c) for c in at.contours]
                if all(np.all(np.isfinite(p)) for p in pixels):
                    canvas.drawPath(skia_path(pixels, closed=True) if all(at.closed) else
                                    contours_path(pixels, at.closed), stroke_paint(_OVERLAY, 0.7))
        words = f"{seconds(when)} s" + (" key" if when in keys else "")
        raster.text(words, 2.0, height - 0.4 * caption, caption, _INK if when in keys else _SOFT, bold=when in keys)
        canvas.restore()


def seconds(value: float) -> str:
    """A time as a label: to the millisecond, no trailing zeros (``1/12`` → ``"0.083"``)."""
    return f"{round(value, 3) + 0.0:.3f}".rstrip("0").rstrip(".")


def _key_times(scene: Scene) -> list[float]:
    return sorted({key.time for shape in scene.shapes if len(shape.keys) > 1 for key in shape.keys})


