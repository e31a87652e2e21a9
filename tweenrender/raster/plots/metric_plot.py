"""Quality measures over t, one panel per shape segment, drawn like the Q-curve plots.

Each panel has four charts sharing the t axis — the perimeter and area ratios
against the keys' interpolated values, the worst relative edge-length error
and the worst turning-angle error (degrees) — with one line per method in the
Q-curve plots' colours, and beneath them one row per method marking in red the
t at which that method's outline crosses itself.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np
import skia
from numpy.typing import NDArray

from ...model import Color
from ..painter import SOFT as _SOFT
from ..painter import Painter
from ..surface import Raster, paint_color
from .qcurve_plot import NOTHING_MOVES, PALETTE

__all__ = ["MPanel", "MEASURES", "metrics_picture", "nice_ticks"]

MEASURES: tuple[tuple[str, str], ...] = (
    ("perimeter_ratio", "perimeter / interpolated keys'"),
    ("area_ratio", "area / interpolated keys'"),
    ("edge_error", "worst edge-length error"),
    ("angle_error", "worst turning-angle error (°)"),
)
"""The charts of a panel: the measure's name in :class:`MPanel` ``series``, and its caption."""

_INK: Color = (30, 34, 45, 255)
_GRID: Color = (30, 34, 45, 35)
_FRAME: Color = (30, 34, 45, 70)
_CROSS: Color = (205, 30, 40, 255)
_BACK: Color = (255, 255, 255, 255)


@dataclass(frozen=True, slots=True)
class MPanel:
    """One shape segment: ``t (T,)``; per method, each measure of :data:`MEASURES` ``(T,)`` in
    ``series[method][name]`` and where the outline crosses itself in ``crossing[method]`` ``(T,)``."""

    title: str
    subtitle: str
    t: NDArray[np.float64]
    series: dict[str, dict[str, NDArray[np.float64]]]
    crossing: dict[str, NDArray[np.bool_]]


def nice_ticks(low: float, high: float, count: int = 4) -> list[float]:
    """About ``count`` round values spanning ``[low, high]`` (steps of 1, 2 or 5 × 10^k)."""
    if not (math.isfinite(low) and math.isfinite(high)) or high <= low:
        return [low]
    raw = (high - low) / max(count, 1)
    power = 10.0 ** math.floor(math.log10(raw))
    step = next(m * power for m in (1, 2, 5, 10) if m * power >= raw)
    first = math.ceil(low / step - 1e-9) * step
    return [round(first + k * step, 12) for k in range(int((high - first) / step + 1e-9) + 1)]


def _range(values: list[NDArray[np.float64]], name: str) -> tuple[float, float]:
    """The value range of one chart: the data's, widened a little, never narrower than a floor."""
    finite = np.concatenate([v[np.isfinite(v)] for v in values]) if values else np.zeros(0)
    if finite.size == 0:
        return (0.0, 1.0)
    low, high = float(finite.min()), float(finite.max())
    if name.endswith("ratio"):  # ratios are read around 1
        low, high = min(low, 1.0), max(high, 1.0)
        floor = 0.02
    else:  # errors are read from 0
        low = 0.0
        floor = 1.0 if name == "angle_error" else 0.01
    if high - low < floor:
        middle = 0.5 * (low + high) if name.endswith("ratio") else floor / 2
        low, high = (middle - floor / 2, middle + floor / 2) if name.endswith("ratio") else (0.0, floor)
    pad = 0.06 * (high - low)
    return (low - pad if name.endswith("ratio") else 0.0, high + pad)


class _Painter(Painter):
    def polyline(self, points: NDArray[np.float64], color: Color, width: float) -> None:
        finite = np.all(np.isfinite(points), axis=1)
        path = skia.Path()
        started = False
        for (x, y), ok in zip(points.tolist(), finite.tolist()):
            if not ok:
                started = False
                continue
            if started:
                path.lineTo(x, y)
            else:
                path.moveTo(x, y)
                started = True
        self.stroke.setColor(paint_color(color))
        self.stroke.setStrokeWidth(width * self.scale)
        self.canvas.drawPath(path, self.stroke)


def _chart(p: _Painter, panel: MPanel, name: str, caption: str, x: float, y: float, w: float, h: float) -> None:
    s = p.scale
    p.text(caption, x, y - 6 * s, 12, _INK, bold=True)
    methods = list(panel.series)
    low, high = _range([panel.series[m][name] for m in methods], name)
    left = x + 44 * s  # room for the value labels
    width = w - 44 * s
    bottom = y + h - 16 * s
    height = h - 16 * s

    def at(t: NDArray[np.float64], v: NDArray[np.float64]) -> NDArray[np.float64]:
        return np.stack([left + t * width, bottom - (v - low) / (high - low) * height], axis=-1)

    for tick in nice_ticks(low, high):
        if low <= tick <= high:
            py = float(at(np.zeros(1), np.array([tick]))[0, 1])
            p.line(np.array([left, py]), np.array([left + width, py]), _GRID, 1.0)
            p.text(f"{tick:g}", left - 5 * s, py + 4 * s, 10, _SOFT, anchor="right")
    if name.endswith("ratio") and low < 1.0 < high:
        py = float(at(np.zeros(1), np.ones(1))[0, 1])
        p.line(np.array([left, py]), np.array([left + width, py]), _FRAME, 1.5)
    for tick in (0.0, 0.25, 0.5, 0.75, 1.0):
        px = left + tick * width
        p.line(np.array([px, bottom]), np.array([px, bottom + 3 * s]), _SOFT, 1.0)
        p.text(f"{tick:g}", px, bottom + 14 * s, 10, _SOFT, anchor="middle")
    p.canvas.save()
    p.canvas.clipRect(skia.Rect.MakeLTRB(left, bottom - height, left + width, bottom))
    for k, method in reversed(list(enumerate(methods))):
        p.polyline(at(panel.t, np.asarray(panel.series[method][name], dtype=np.float64)),
                   PALETTE[k % len(PALETTE)], 2.0)
    p.canvas.restore()
    p.stroke.setColor(paint_color(_FRAME))
    p.stroke.setStrokeWidth(1.0)
    p.canvas.drawRect(skia.Rect.MakeLTRB(left, bottom - height, left + width, bottom), p.stroke)


def _panel(p: _Painter, panel: MPanel, x: float, y: float, width: float, height: float) -> None:
    s = p.scale
    lines = p.heading(panel.title, panel.subtitle, x, y, width)
    methods = list(panel.series)
    # legend: one swatch per method
    lx, ly = x + 14 * s, y + (64 + 17 * (lines - 1)) * s
    for k, method in enumerate(methods):
        color = PALETTE[k % len(PALETTE)]
        words = p.text_width(method, 12, True)
        if lx + (26 * s + words) > x + width - 14 * s:
            lx, ly = x + 14 * s, ly + 18 * s
        p.line(np.array([lx, ly - 4 * s]), np.array([lx + 18 * s, ly - 4 * s]), color, 3.0)
        p.text(method, lx + 22 * s, ly, 12, color, bold=True)
        lx += 36 * s + words
    crossing_rows = len(methods)
    top = ly + 28 * s
    strip = (crossing_rows * 14 + 30) * s
    grid_h = y + height - strip - top - 8 * s
    cell_w = (width - 42 * s) / 2
    cell_h = grid_h / 2
    for k, (name, caption) in enumerate(MEASURES):
        cx = x + 14 * s + (k % 2) * (cell_w + 14 * s)
        cy = top + (k // 2) * cell_h + 8 * s
        _chart(p, panel, name, caption, cx, cy, cell_w, cell_h - 22 * s)
    # where each method's outline crosses itself
    sy = y + height - strip + 6 * s
    p.text("outline crosses itself (red) at t:", x + 14 * s, sy + 4 * s, 12, _INK, bold=True)
    left, right = x + 14 * s + 130 * s, x + width - 14 * s
    for k, method in enumerate(methods):
        row = sy + (16 + 14 * k) * s
        p.text(method, left - 8 * s, row + 4 * s, 10, PALETTE[k % len(PALETTE)], anchor="right")
        p.line(np.array([left, row]), np.array([right, row]), _GRID, 5.0)
        marks = np.asarray(panel.crossing[method], dtype=bool)
        for t in panel.t[marks]:
            px = left + float(t) * (right - left)
            p.line(np.array([px, row - 5 * s]), np.array([px, row + 5 * s]), _CROSS, 2.0)
        if not marks.any():
            p.text("never", right - 4 * s, row + 4 * s, 10, _SOFT, anchor="right")


def metrics_picture(panels: Sequence[MPanel], panel_size: tuple[int, int] = (960, 640),
                    scale: float = 1.0, note: str = NOTHING_MOVES) -> NDArray[np.uint8]:
    """Every panel stacked in one column, straight RGBA ``(H, W, 4)``; without panels, ``note`` says why."""
    w = int(panel_size[0] * scale)
    heights = [int((panel_size[1] + 14 * max(0, len(panel.series) - 4)) * scale) for panel in panels] or \
        [int(120 * scale)]
    raster = Raster(w, sum(heights))
    raster.clear(_BACK)
    painter = _Painter(raster, scale)
    if not panels:
        painter.note(note, 20 * scale, heights[0] / 2, w - 40 * scale)
    top = 0.0
    for panel, h in zip(panels, heights):
        if top > 0:
            painter.line(np.array([0.0, top]), np.array([float(w), top]), _FRAME, 1.0)
        _panel(painter, panel, 0.0, top, float(w), float(h))
        top += h
    return raster.rgba().copy()
