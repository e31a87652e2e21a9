"""Marks for diagrams (plots, correspondence pictures) on a :class:`Raster`, sized by one scale."""

from __future__ import annotations

import numpy as np
import skia
from numpy.typing import NDArray

from ..model import Color
from .fonts import font, wrap
from .surface import Raster, paint_color

__all__ = ["Painter", "INK", "SOFT"]

_WHITE: Color = (255, 255, 255, 255)
INK: Color = (30, 34, 45, 255)
"""The diagrams' text and line colour."""
SOFT: Color = (30, 34, 45, 150)
"""The diagrams' secondary text."""


class Painter:
    """Lines, dots, rings and text in pixels; every width and size is multiplied by ``scale``."""

    def __init__(self, raster: Raster, scale: float) -> None:
        self.raster, self.canvas, self.scale = raster, raster.canvas, scale
        self.fill = skia.Paint(AntiAlias=True, Style=skia.Paint.kFill_Style)
        self.stroke = skia.Paint(AntiAlias=True, Style=skia.Paint.kStroke_Style,
                                 StrokeCap=skia.Paint.kRound_Cap, StrokeJoin=skia.Paint.kRound_Join)

    def line(self, a: NDArray[np.float64], b: NDArray[np.float64], color: Color, width: float,
             alpha: float = 1.0) -> None:
        self.stroke.setColor(paint_color(color, alpha))
        self.stroke.setStrokeWidth(width * self.scale)
        self.canvas.drawLine(float(a[0]), float(a[1]), float(b[0]), float(b[1]), self.stroke)

    def dot(self, p: NDArray[np.float64], radius: float, color: Color, hollow: bool = False) -> None:
        """A filled dot, or a ring on white when ``hollow``."""
        if hollow:
            self.dot(p, radius, _WHITE)
            self.ring(p, radius, color, 1.5)
            return
        self.fill.setColor(paint_color(color))
        self.canvas.drawCircle(float(p[0]), float(p[1]), radius * self.scale, self.fill)

    def ring(self, p: NDArray[np.float64], radius: float, color: Color, width: float = 1.6) -> None:
        self.stroke.setColor(paint_color(color))
        self.stroke.setStrokeWidth(width * self.scale)
        self.canvas.drawCircle(float(p[0]), float(p[1]), radius * self.scale, self.stroke)

    def text(self, words: str, x: float, y: float, size: float, color: Color = INK, bold: bool = False,
             anchor: str = "left") -> None:
        """``words`` at ``size`` (before scaling) with the baseline's left end, middle (``anchor="middle"``)
        or right end (``"right"``) at pixel ``(x, y)``."""
        size *= self.scale
        if anchor != "left":
            width = font(size, bold).measureText(words)
            x -= width if anchor == "right" else width / 2
        self.raster.text(words, x, y, size, color, bold)

    def heading(self, title: str, subtitle: str, x: float, y: float, width: float) -> int:
        """A panel's bold title and its subtitle, wrapped to the panel's ``width`` less margins, from the
        panel's top left ``(x, y)`` in pixels; returns the subtitle's number of lines."""
        s = self.scale
        self.text(title, x + 14 * s, y + 24 * s, 16, bold=True)
        lines = wrap(subtitle, 13 * s, width - 28 * s)
        for k, line in enumerate(lines):
            self.text(line, x + 14 * s, y + (44 + 17 * k) * s, 13, SOFT)
        return len(lines)

    def note(self, words: str, x: float, middle: float, width: float, size: float = 16) -> None:
        """``words`` at ``size`` (before scaling), wrapped to ``width`` pixels from ``x``, the lines' baselines
        centred on pixel row ``middle``."""
        lines = wrap(words, size * self.scale, width)
        step = 1.35 * size * self.scale
        for k, line in enumerate(lines):
            self.text(line, x, middle + (k - (len(lines) - 1) / 2) * step, size)

    def text_width(self, words: str, size: float, bold: bool = False) -> float:
        """Pixels ``words`` take at ``size`` (before scaling)."""
        return font(size * self.scale, bold).measureText(words)
