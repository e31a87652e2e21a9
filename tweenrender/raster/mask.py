"""SVG masks drawn with skia: what an element draws, multiplied by what its masks let through.

The element is drawn into a layer; the masks' coverage is drawn into a second layer over it, blended
``kDstIn`` (the element kept in proportion to the coverage's alpha). One mask's coverage is its content
drawn into a layer turned to alpha by its luminance (``skia.LumaColorFilter``: luminance × alpha, as
SVG's luminance masks) or kept as drawn (an alpha mask), inside the mask's region, times the masks on
the mask itself; several masks multiply; weighted alternatives (a mask between keys) add up (``kPlus``).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager

import numpy as np
import skia
from numpy.typing import NDArray

from ..core.view import Viewport
from ..model import Mask, MaskShape
from .surface import Raster, StrokeStyle, contours_path, dashed

__all__ = ["draw_masked"]

MaskBlend = Sequence[tuple[float, Sequence[Mask], NDArray[np.float64]]]
"""``(weight, masks, world move (3, 3))`` alternatives (see :mod:`..core.mask_motion`)."""


def draw_masked(raster: Raster, viewport: Viewport, blend: MaskBlend, draw: Callable[[], None],
                bounds: skia.Rect | None = None) -> None:
    """Call ``draw`` (which draws an element on ``raster``) with what it draws masked by ``blend``; ``bounds``
    (pixels), when given, holds all that ``draw`` draws, and the layers are kept to it."""
    canvas = raster.canvas
    with _layer(canvas, bounds, None):
        draw()
        with _layer(canvas, bounds, skia.Paint(BlendMode=skia.BlendMode.kDstIn)):
            for weight, masks, move in blend:
                if weight <= 0:
                    continue
                with _layer(canvas, bounds, skia.Paint(Alphaf=min(1.0, float(weight)), BlendMode=skia.BlendMode.kPlus)):
                    _coverage(raster, viewport, masks, move, bounds)


@contextmanager
def _layer(canvas: skia.Canvas, bounds: skia.Rect | None, paint: skia.Paint | None) -> Iterator[None]:
    """A layer of ``canvas`` (kept to ``bounds``) drawn into, then blended down by ``paint`` — also when
    drawing it fails."""
    canvas.saveLayer(bounds, paint)
    try:
        yield
    finally:
        canvas.restore()


def _coverage(raster: Raster, viewport: Viewport, masks: Sequence[Mask], move: NDArray[np.float64],
              bounds: skia.Rect | None = None) -> None:
    """Into the current (clear) layer, as alpha, the product of what ``masks`` (moved by ``move``) let through."""
    canvas = raster.canvas
    if not masks:
        canvas.drawPaint(skia.Paint(Color=skia.ColorWHITE))
        return
    _one(raster, viewport, masks[0], move)
    for mask in masks[1:]:
        with _layer(canvas, bounds, skia.Paint(BlendMode=skia.BlendMode.kDstIn)):
            _one(raster, viewport, mask, move)


def _one(raster: Raster, viewport: Viewport, mask: Mask, move: NDArray[np.float64]) -> None:
    """One mask's coverage, moved by the world map ``move``, into the current layer."""
    canvas = raster.canvas
    canvas.save()
    try:
        pixel_move = viewport.matrix @ move @ np.linalg.inv(viewport.matrix)
        if not np.all(np.isfinite(pixel_move)):
            return
        canvas.concat(skia.Matrix.MakeAll(*(float(v) for v in pixel_move[0]), *(float(v) for v in pixel_move[1]),
                                          0.0, 0.0, 1.0))
        canvas.clipPath(contours_path([viewport.to_pixels(c.points) for c in mask.region], [True] * len(mask.region)),
                        doAntiAlias=True)
        with _layer(canvas, None, None if mask.alpha else skia.Paint(ColorFilter=_luminance(mask.linear))):
            for shape in mask.shapes:
                _shape(raster, viewport, shape)
            if mask.masks:
                with _layer(canvas, None, skia.Paint(BlendMode=skia.BlendMode.kDstIn)):
                    _coverage(raster, viewport, mask.masks, np.eye(3))
    finally:
        canvas.restore()


def _luminance(linear: bool) -> skia.ColorFilter:
    """The filter that turns colours into alpha by their luminance (of linear RGB values with ``linear``)."""
    luma = skia.LumaColorFilter.Make()
    return skia.ColorFilters.Compose(luma, skia.ColorFilters.SRGBToLinearGamma()) if linear else luma


def _shape(raster: Raster, viewport: Viewport, shape: MaskShape) -> None:
    """One shape of a mask's content, with its clips and masks."""
    pixels = [viewport.to_pixels(c.points) for c in shape.contours]
    kept = [(p, c.closed) for p, c in zip(pixels, shape.contours) if len(p) >= 2 and np.all(np.isfinite(p))]
    if not kept:
        return
    paint = shape.paint

    def draw() -> None:
        from .patterns import paint_shaders

        raster.fill_shader, raster.stroke_shader = paint_shaders(paint, viewport)
        try:
            raster.draw_contours([p for p, _ in kept], [c for _, c in kept], shape.fill_rule, paint.fill,
                                 paint.stroke, paint.stroke_width * viewport.scale,
                                 dashed(StrokeStyle(shape.cap, shape.join, shape.miter_limit), paint.dash,
                                        viewport.scale), paint.opacity)
        finally:
            raster.fill_shader = raster.stroke_shader = None

    canvas = raster.canvas
    canvas.save()
    try:
        for region in shape.clips:
            canvas.clipPath(contours_path([viewport.to_pixels(c.points) for c in region], [True] * len(region)),
                            doAntiAlias=True)
        if shape.masks:
            draw_masked(raster, viewport, ((1.0, shape.masks, np.eye(3)),), draw)
        else:
            draw()
    finally:
        canvas.restore()
