"""A reusable skia raster surface: antialiased polygons, strokes and text, read out as straight RGBA."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Sequence

import numpy as np
import skia
from numpy.typing import NDArray

from ..model import Color, Dash
from .clip import clip_to_box
from .fonts import drawable, font
from .round_stroke import MIN_WIDTH, draws_on, stroke_contours
from .slits import unslit

__all__ = ["Raster", "paint_color", "polygon_path", "contours_path", "clipped_contours", "StrokeStyle", "dashed",
           "fill_and_stroke", "hides_fill_edge"]

# skia's serialised path (version 5): int32 header (version | fill type << 8),
# point, conic and verb counts, then float32 points and one byte per verb,
# padded to 4 bytes. Building it with numpy avoids a Python loop over vertices;
# ``_SERIAL_OK`` checks once that this skia reads it back, else addPoly is used.
_MOVE, _LINE, _CLOSE = 0, 1, 5


def _serialised(contours: Sequence[NDArray[np.float64]], closed: Sequence[bool], fill_type: int = 0) -> bytes:
    """Contours ``(N_i, 2)`` as one skia path, in skia's serialised form (``fill_type`` 0 winding, 1 even-odd)."""
    verbs = []
    for points, shut in zip(contours, closed):
        run = np.full(len(points) + int(shut), _LINE, dtype=np.uint8)
        run[0] = _MOVE
        if shut:
            run[-1] = _CLOSE
        verbs.append(run)
    every = np.concatenate(verbs) if verbs else np.empty(0, np.uint8)
    points = np.concatenate(contours) if contours else np.empty((0, 2))
    pad = (-len(every)) % 4
    header = np.array([5 | (fill_type << 8), len(points), 0, len(every)], dtype="<i4")
    return b"".join((header.tobytes(), np.ascontiguousarray(points, dtype="<f4").tobytes(),
                     every.tobytes(), bytes(pad)))


def _check_serial() -> bool:
    probe = np.array([[1.0, 2.0], [3.5, 4.0], [5.0, 7.25]])
    path = skia.Path()
    try:
        read = path.readFromMemory(_serialised([probe, probe[:2] + 9], [True, False], 1))
    except Exception:  # noqa: BLE001 - any refusal means: use the slow, documented route
        return False
    return bool(read) and path.countVerbs() == 6 and [(p.x(), p.y()) for p in path.getPoints(5)] == \
        [tuple(row) for row in probe.tolist() + (probe[:2] + 9).tolist()] and \
        path.getFillType() == skia.PathFillType.kEvenOdd


_SERIAL_OK = _check_serial()


def polygon_path(points: NDArray[np.float64], closed: bool = True) -> skia.Path:
    """A skia path through ``points (N, 2)`` pixels, N ≥ 1, closed or open."""
    return contours_path([points], [closed])


def contours_path(contours: Sequence[NDArray[np.float64]], closed: Sequence[bool],
                  fill_rule: str = "nonzero") -> skia.Path:
    """One skia path of every contour ``(N_i, 2)`` in pixels (finite), closed or open, under ``fill_rule``
    (``"nonzero"`` or ``"evenodd"``); vertices far off the canvas are cut away first (see :mod:`.clip`),
    so every coordinate fits float32."""
    contours, closed = clipped_contours(contours, closed)
    return _path_of(contours, closed, fill_rule)


def clipped_contours(contours: Sequence[NDArray[np.float64]],
                     closed: Sequence[bool]) -> tuple[list[NDArray[np.float64]], list[bool]]:
    """``contours`` (each ``(N_i, 2)`` pixels, finite) cut to the box of :mod:`.clip`, empty ones dropped,
    with their ``closed`` flags."""
    kept = [(clip_to_box(points, shut), shut) for points, shut in zip(contours, closed)]
    kept = [(points, shut) for points, shut in kept if len(points)]
    return [p for p, _ in kept], [s for _, s in kept]


def _path_of(contours: list[NDArray[np.float64]], closed: list[bool], fill_rule: str) -> skia.Path:
    """The skia path of contours already cut by :func:`clipped_contours`."""
    path = skia.Path()
    even = fill_rule == "evenodd"
    if not contours:
        return path
    if _SERIAL_OK and path.readFromMemory(_serialised(contours, closed, int(even))):
        return path
    path.reset()
    for points, shut in zip(contours, closed):
        path.addPoly([skia.Point(x, y) for x, y in points.tolist()], shut)
    path.setFillType(skia.PathFillType.kEvenOdd if even else skia.PathFillType.kWinding)
    return path


@dataclass(frozen=True, slots=True)
class StrokeStyle:
    """How a shape's outline is stroked: caps, joins and miter limit (SVG's names), and its dash pattern
    in pixels (``dash``: dash, gap, … an even count summing to more than 0; ``()``: solid), which starts
    ``dash_offset`` pixels into the pattern on each contour."""

    cap: str = "round"
    join: str = "round"
    miter_limit: float = 4.0
    dash: tuple[float, ...] = ()
    dash_offset: float = 0.0


_CAPS = {"butt": skia.Paint.kButt_Cap, "round": skia.Paint.kRound_Cap, "square": skia.Paint.kSquare_Cap}
_JOINS = {"miter": skia.Paint.kMiter_Join, "round": skia.Paint.kRound_Join, "bevel": skia.Paint.kBevel_Join}
_ROUND = StrokeStyle()


def dashed(style: StrokeStyle, dash: Dash | None, scale: float) -> StrokeStyle:
    """``style`` with the dash pattern ``dash`` (scene units, ``None``: solid) at ``scale`` pixels per unit;
    solid when the scaled pattern is not one skia can lay (not finite, or its period under 1e-6 px)."""
    if dash is None:
        return replace(style, dash=(), dash_offset=0.0)
    lengths = tuple(float(v) * scale for v in dash.lengths)
    period = sum(lengths)
    if not (math.isfinite(period) and period > 1e-6 and all(v >= 0 for v in lengths)):
        return replace(style, dash=(), dash_offset=0.0)
    return replace(style, dash=lengths, dash_offset=float(dash.offset) * scale)


def _dash_effect(dash: tuple[float, ...], offset: float) -> skia.PathEffect:
    """skia's dashing of ``dash`` (pixels) starting ``offset`` pixels into it (any sign: taken modulo the period)."""
    period = float(sum(dash))
    return skia.DashPathEffect.Make(list(dash), offset % period if math.isfinite(offset) else 0.0)


def hides_fill_edge(stroke: skia.Paint, fill: skia.Paint, matrix: skia.Matrix | None = None) -> bool:
    """Whether ``stroke`` drawn over ``fill`` along the same path covers every pixel the fill's
    antialiasing would blend.

    An opaque, plain-coloured stroke at least 2 device pixels wide covers a
    pixel wholly wherever the fill's edge crosses it (the pixel lies within
    half a width of the edge on both sides), so the fill can be drawn aliased
    there: about a quarter of a stroked frame's drawing time on detailed
    outlines, and no pixel of the picture changes by more than antialiasing
    noise (tests/raster/test_fast_paths.py compares both ways).
    """
    plain = all(p.getShader() is None and p.getColorFilter() is None and p.getMaskFilter() is None
                and p.getImageFilter() is None and p.getPathEffect() is None
                and p.getBlendMode() == skia.BlendMode.kSrcOver and p.getAlpha() == 255 for p in (stroke, fill))
    if not plain or not stroke.isAntiAlias() or stroke.getStyle() != skia.Paint.kStroke_Style:
        return False
    scale = 1.0
    if matrix is not None:
        if not matrix.isScaleTranslate():
            return False
        scale = min(abs(matrix.getScaleX()), abs(matrix.getScaleY()))
    return stroke.getStrokeWidth() * scale >= 2.0


def fill_and_stroke(canvas: skia.Canvas, path: skia.Path, fill: skia.Paint | None, stroke: skia.Paint | None,
                    hidden_by: skia.Paint | None = None) -> None:
    """Fill ``path`` with ``fill`` (if given), then stroke it with ``stroke`` (if given): the plain two
    draws, except that a fill wholly edged by an opaque stroke skips its antialiasing (see
    :func:`hides_fill_edge`). ``hidden_by``: the stroke that will be drawn over the fill by other means."""
    edge = stroke if stroke is not None else hidden_by
    if fill is not None:
        if edge is not None and fill.isAntiAlias() and hides_fill_edge(edge, fill, canvas.getTotalMatrix()):
            fill = skia.Paint(fill)
            fill.setAntiAlias(False)
        canvas.drawPath(path, fill)
    if stroke is not None:
        canvas.drawPath(path, stroke)


def paint_color(color: Color, alpha: float = 1.0) -> int:
    """A straight RGBA tuple (0..255) as a skia ARGB colour, its alpha scaled by ``alpha``."""
    r, g, b, a = color
    return skia.ColorSetARGB(int(round(a * alpha)), r, g, b)


class Raster:
    """One skia surface of ``width × height`` pixels, reused frame after frame.

    The surface draws straight into a numpy array (premultiplied BGRA, no copy),
    which :meth:`bgra` hands out as it is. With ``round_strokes`` set,
    :meth:`draw_contours` draws round-joined strokes with the compiled kernel of
    :mod:`.round_stroke` wherever it can draw what skia would.
    """

    def __init__(self, width: int, height: int, round_strokes: bool = False) -> None:
        self.width, self.height = width, height
        self.round_strokes = round_strokes
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
        self._restyled = False  # the stroke paint has other caps or joins than round ones
        self._address = self._pixels.ctypes.data
        self.fill_shader: skia.Shader | None = None  # set while a gradient fills (see raster.gradients)
        self.stroke_shader: skia.Shader | None = None  # set while a gradient strokes

    def clear(self, color: Color) -> None:
        self.canvas.clear(paint_color(color))

    def polygon(self, pixels: NDArray[np.float64], fill: Color | None, stroke: Color | None = None,
                stroke_width: float = 0.0, alpha: float = 1.0, closed: bool = True) -> None:
        """Fill and/or stroke the outline through ``pixels (N, 2)``; non-finite outlines are skipped."""
        if len(pixels) < 2 or not np.all(np.isfinite(pixels)):
            return
        self.draw_path(polygon_path(pixels, closed), fill if closed else None, stroke, stroke_width, opacity=alpha)

    def draw_path(self, path: skia.Path, fill: Color | None, stroke: Color | None = None, stroke_width: float = 0.0,
                  style: StrokeStyle = StrokeStyle(), opacity: float = 1.0) -> None:
        """Fill and/or stroke ``path`` (pixels), through :func:`fill_and_stroke`. With ``opacity`` < 1 and
        both fill and stroke, the two are drawn into a layer first, so their overlap is not darkened
        twice (as SVG's ``opacity``)."""
        fills = fill is not None and fill[3] > 0
        strokes = stroke is not None and stroke[3] > 0 and stroke_width > 0
        if opacity <= 0 or not (fills or strokes):
            return
        layer = opacity < 1.0 and fills and strokes
        fill_paint, stroke_paint = self._paints(fill if fills else None, stroke if strokes else None, stroke_width,
                                                style, 1.0 if layer else opacity)
        if layer:
            self.canvas.saveLayerAlpha(None, int(round(255 * opacity)))
        fill_and_stroke(self.canvas, path, fill_paint, stroke_paint)
        if layer:
            self.canvas.restore()

    def _paints(self, fill: Color | None, stroke: Color | None, stroke_width: float, style: StrokeStyle,
                alpha: float) -> tuple[skia.Paint | None, skia.Paint | None]:
        """The raster's fill and stroke paints set for ``fill`` and ``stroke`` (``None``: not drawn) at
        ``alpha``; the stroke's caps and joins go back to round at the next call (``line`` strokes
        with round ones too)."""
        if self._restyled:
            self._stroke.setStrokeCap(skia.Paint.kRound_Cap)
            self._stroke.setStrokeJoin(skia.Paint.kRound_Join)
            self._stroke.setStrokeMiter(_ROUND.miter_limit)
            self._restyled = False
        fill_paint = stroke_paint = None
        if fill is not None:
            if self.fill_shader is not None:  # a gradient: the shader's colours at the fill's opacity
                fill_paint = skia.Paint(AntiAlias=True, Style=skia.Paint.kFill_Style, Shader=self.fill_shader)
                fill_paint.setAlphaf(alpha)
            else:
                fill_paint = self._fill
                fill_paint.setColor(paint_color(fill, alpha))
        if stroke is not None:
            stroke_paint = self._stroke
            stroke_paint.setColor(paint_color(stroke, alpha))
            if self.stroke_shader is not None:  # a gradient: the shader's colours at the stroke's opacity
                stroke_paint = skia.Paint(stroke_paint)
                stroke_paint.setShader(self.stroke_shader)
                stroke_paint.setAlphaf(alpha)
            stroke_paint.setStrokeWidth(stroke_width)
            if style != _ROUND:
                stroke_paint.setStrokeCap(_CAPS[style.cap])
                stroke_paint.setStrokeJoin(_JOINS[style.join])
                stroke_paint.setStrokeMiter(style.miter_limit)
                self._restyled = True
                if style.dash:  # a copy: skia's paint takes no path effect back off
                    stroke_paint = skia.Paint(stroke_paint)
                    stroke_paint.setPathEffect(_dash_effect(style.dash, style.dash_offset))
        return fill_paint, stroke_paint

    def draw_contours(self, contours: Sequence[NDArray[np.float64]], closed: Sequence[bool], fill_rule: str,
                      fill: Color | None, stroke: Color | None = None, stroke_width: float = 0.0,
                      style: StrokeStyle = StrokeStyle(), opacity: float = 1.0) -> None:
        """Fill and/or stroke ``contours`` (each ``(N_i, 2)`` pixels, finite) as one path under ``fill_rule``;
        as :meth:`draw_path`, with the stroke drawn by the compiled kernel where :attr:`round_strokes` allows
        and it draws what skia would (a round join, round caps or no open end, at least a pixel wide, no
        layer between; see :func:`.round_stroke.draws_on`). A fill alone is drawn without slits
        (:func:`.slits.unslit`)."""
        fills = fill is not None and fill[3] > 0
        strokes = stroke is not None and stroke[3] > 0 and stroke_width > 0
        if fills and not strokes:
            loops = [unslit(points) if shut else [points] for points, shut in zip(contours, closed)]
            closed = [shut for parts, shut in zip(loops, closed) for _ in parts]
            contours = [part for parts in loops for part in parts]
        contours, closed = clipped_contours(contours, closed)
        placed = None
        if (self.round_strokes and strokes and opacity > 0 and not (opacity < 1.0 and fills)
                and style.join == "round" and (style.cap == "round" or all(closed)) and not style.dash
                and self.stroke_shader is None):
            placed = draws_on(self.canvas, self._address)
        if placed is None or placed[0] * stroke_width < MIN_WIDTH:
            self.draw_path(_path_of(contours, closed, fill_rule), fill, stroke, stroke_width, style, opacity)
            return
        scale, dx, dy, clip = placed
        if fills:
            fill_paint, stroke_paint = self._paints(fill, stroke, stroke_width, style, opacity)
            fill_and_stroke(self.canvas, _path_of(contours, closed, fill_rule), fill_paint, None,
                            hidden_by=stroke_paint)
        r, g, b, _ = stroke  # type: ignore[misc]
        alpha = int(round(stroke[3] * opacity))  # type: ignore[index]
        premultiplied = np.array([b, g, r, 255.0]) * (alpha / 255.0)
        stroke_contours(self._pixels, contours, closed, scale * stroke_width, premultiplied, scale, (dx, dy),
                        (clip.left(), clip.top(), clip.right(), clip.bottom()))

    def line(self, a: tuple[float, float], b: tuple[float, float], color: Color, width: float = 1.0) -> None:
        _, paint = self._paints(None, color, width, _ROUND, 1.0)
        self.canvas.drawLine(a[0], a[1], b[0], b[1], paint)

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
