"""A reusable skia raster surface: antialiased polygons, strokes and text, read out as straight RGBA."""

from __future__ import annotations

import numpy as np
import skia
from numpy.typing import NDArray

from ..model import Color
from .fonts import font

__all__ = ["Raster", "paint_color"]


def paint_color(color: Color, alpha: float = 1.0) -> int:
    """A straight RGBA tuple (0..255) as a skia ARGB colour, its alpha scaled by ``alpha``."""
    r, g, b, a = color
    return skia.ColorSetARGB(int(round(a * alpha)), r, g, b)


class Raster:
    """One skia surface of ``width × height`` pixels, reused frame after frame."""

    def __init__(self, width: int, height: int) -> None:
        self.width, self.height = width, height
        self.surface = skia.Surface(width, height)
        self.canvas = self.surface.getCanvas()
        self._rgba = np.empty((height, width, 4), dtype=np.uint8)
        self._straight = skia.ImageInfo.Make(width, height, skia.kRGBA_8888_ColorType, skia.kUnpremul_AlphaType)
        self._fill = skia.Paint(AntiAlias=True, Style=skia.Paint.kFill_Style)
        self._stroke = skia.Paint(AntiAlias=True, Style=skia.Paint.kStroke_Style,
                                  StrokeJoin=skia.Paint.kRound_Join, StrokeCap=skia.Paint.kRound_Cap)

    def clear(self, color: Color) -> None:
        self.canvas.clear(paint_color(color))

    def polygon(self, pixels: NDArray[np.float64], fill: Color | None, stroke: Color | None = None,
                stroke_width: float = 0.0, alpha: float = 1.0, closed: bool = True) -> None:
        """Fill and/or stroke the outline through ``pixels (N, 2)``; non-finite outlines are skipped."""
        if len(pixels) < 2 or not np.all(np.isfinite(pixels)):
            return
        path = skia.Path()
        path.addPoly([skia.Point(x, y) for x, y in pixels.tolist()], closed)
        if fill is not None and closed:
            self._fill.setColor(paint_color(fill, alpha))
            self.canvas.drawPath(path, self._fill)
        if stroke is not None and stroke_width > 0:
            self._stroke.setColor(paint_color(stroke, alpha))
            self._stroke.setStrokeWidth(stroke_width)
            self.canvas.drawPath(path, self._stroke)

    def line(self, a: tuple[float, float], b: tuple[float, float], color: Color, width: float = 1.0) -> None:
        self._stroke.setColor(paint_color(color))
        self._stroke.setStrokeWidth(width)
        self.canvas.drawLine(a[0], a[1], b[0], b[1], self._stroke)

    def text(self, words: str, x: float, y: float, size: float, color: Color, bold: bool = False) -> None:
        """Draw ``words`` with its baseline's left end at pixel ``(x, y)``."""
        self._fill.setColor(paint_color(color))
        self.canvas.drawString(words, x, y, font(size, bold), self._fill)

    def rgba(self) -> NDArray[np.uint8]:
        """The picture as straight (unpremultiplied) RGBA, ``(height, width, 4)``.

        The array is reused by the next call: copy it to keep it.
        """
        if not self.surface.readPixels(self._straight, self._rgba, self.width * 4, 0, 0):
            raise RuntimeError("skia could not read the surface's pixels")
        return self._rgba
