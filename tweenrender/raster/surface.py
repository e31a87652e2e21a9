"""A reusable skia raster surface: antialiased polygons, strokes and text, read out as straight RGBA."""

from __future__ import annotations

import numpy as np
import skia
from numpy.typing import NDArray

from ..model import Color
from .clip import clip_to_box
from .fonts import drawable, font

__all__ = ["Raster", "paint_color", "polygon_path"]

# skia's serialised path (version 5): int32 header (version | fill type << 8),
# point, conic and verb counts, then float32 points and one byte per verb,
# padded to 4 bytes. Building it with numpy avoids a Python loop over vertices;
# ``_SERIAL_OK`` checks once that this skia reads it back, else addPoly is used.
_MOVE, _LINE, _CLOSE = 0, 1, 5


def _serialised(points: NDArray[np.float64], closed: bool) -> bytes:
    """``points (N, 2)`` as one skia path contour, in skia's serialised form."""
    n = len(points)
    verbs = np.full(n + int(closed), _LINE, dtype=np.uint8)
    verbs[0] = _MOVE
    if closed:
        verbs[-1] = _CLOSE
    pad = (-len(verbs)) % 4
    header = np.array([5, n, 0, len(verbs)], dtype="<i4")
    return b"".join((header.tobytes(), np.ascontiguousarray(points, dtype="<f4").tobytes(),
                     verbs.tobytes(), bytes(pad)))


def _check_serial() -> bool:
    probe = np.array([[1.0, 2.0], [3.5, 4.0], [5.0, 7.25]])
    path = skia.Path()
    try:
        read = path.readFromMemory(_serialised(probe, True))
    except Exception:  # noqa: BLE001 - any refusal means: use the slow, documented route
        return False
    return bool(read) and path.countVerbs() == 4 and [(p.x(), p.y()) for p in path.getPoints(3)] == \
        [tuple(row) for row in probe.tolist()]


_SERIAL_OK = _check_serial()


def polygon_path(points: NDArray[np.float64], closed: bool = True) -> skia.Path:
    """A skia path through ``points (N, 2)`` pixels (finite), closed or open; vertices far off the canvas
    are cut away first (see :mod:`.clip`), so every coordinate fits float32."""
    path = skia.Path()
    points = clip_to_box(points, closed)
    if len(points) == 0:
        return path
    if _SERIAL_OK and path.readFromMemory(_serialised(points, closed)):
        return path
    path.reset()
    path.addPoly([skia.Point(x, y) for x, y in points.tolist()], closed)
    return path


def paint_color(color: Color, alpha: float = 1.0) -> int:
    """A straight RGBA tuple (0..255) as a skia ARGB colour, its alpha scaled by ``alpha``."""
    r, g, b, a = color
    return skia.ColorSetARGB(int(round(a * alpha)), r, g, b)


class Raster:
    """One skia surface of ``width × height`` pixels, reused frame after frame.

    The surface draws straight into a numpy array (premultiplied BGRA, no copy),
    which :meth:`bgra` hands out as it is.
    """

    def __init__(self, width: int, height: int) -> None:
        self.width, self.height = width, height
        self._pixels = np.zeros((height, width, 4), dtype=np.uint8)
        self.surface = skia.Surface(self._pixels, colorType=skia.kBGRA_8888_ColorType,
                                    alphaType=skia.kPremul_AlphaType)
        self.canvas = self.surface.getCanvas()
        self._rgba = np.empty((height, width, 4), dtype=np.uint8)
        self._straight = skia.ImageInfo.Make(width, height, skia.kRGBA_8888_ColorType, skia.kUnpremul_AlphaType)
        self._premul = skia.ImageInfo.Make(width, height, skia.kRGBA_8888_ColorType, skia.kPremul_AlphaType)
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
        path = polygon_path(pixels, closed)
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
        self.canvas.drawString(drawable(words), x, y, font(size, bold), self._fill)

    def rgba(self) -> NDArray[np.uint8]:
        """The picture as straight (unpremultiplied) RGBA, ``(height, width, 4)``.

        The array is reused by the next call: copy it to keep it. Where every
        pixel is opaque, premultiplied equals straight, so a plain swizzle is
        read first (about 6× cheaper at 1080p than skia's unpremultiply) and
        the full conversion runs only if some pixel is translucent.
        """
        self._read(self._premul)
        if not _all_opaque(self._rgba):
            self._read(self._straight)
        return self._rgba

    def bgra(self) -> NDArray[np.uint8]:
        """The surface's own pixels, premultiplied BGRA ``(height, width, 4)``: no copy.

        Equal to straight BGRA wherever alpha is 255 (any picture on an opaque
        background). Changes with the next drawing.
        """
        return self._pixels

    def opaque(self) -> bool:
        """Whether every pixel has alpha 255."""
        return _all_opaque(self._pixels)

    def _read(self, info: skia.ImageInfo) -> None:
        if not self.surface.readPixels(info, self._rgba, self.width * 4, 0, 0):
            raise RuntimeError("skia could not read the surface's pixels")


def _all_opaque(pixels: NDArray[np.uint8]) -> bool:
    """Alpha 255 everywhere in ``pixels (H, W, 4)`` with alpha last (RGBA or BGRA).

    As little-endian uint32 each pixel is ``alpha << 24 | ...``, so one
    minimum over the words answers it without a strided pass over the bytes.
    """
    words = pixels.reshape(-1).view("<u4")
    return bool(words.min(initial=0xFFFFFFFF) >= 0xFF000000)
