"""Compose a frame: the scene's shapes in one panel, or one labelled panel per method."""

from __future__ import annotations

from dataclasses import replace
from typing import Callable, Protocol, Sequence

import numpy as np
import skia
from numpy.typing import NDArray

from ..core.dashes import starting_at, without_repeats
from ..core.timing.timeline import ShapeAt
from ..model import Color, Scene, Shape
from .groups import GroupLayers
from .round_stroke import worth_compiling
from .surface import Raster, StrokeStyle, contours_path, dashed
from ..core.view import Box, Viewport

__all__ = ["Composer", "Layer", "draw_shape", "drawn_style", "label_size", "label_band"]

_LABEL: Color = (30, 34, 45, 255)
_LABEL_SOFT: Color = (30, 34, 45, 150)
_DIVIDER: Color = (30, 34, 45, 70)


class Layer(Protocol):
    """Something drawn in every panel, behind (``under``) or in front of (``over``) the shapes."""

    def under(self, canvas: skia.Canvas, panel: int, width: int, height: int, time: float) -> None: ...

    def over(self, canvas: skia.Canvas, panel: int, width: int, height: int, time: float) -> None: ...


class Composer:
    """Draws frames of ``len(labels)`` side-by-side panels, each ``width × height``.

    ``labels`` holds each panel's caption (the method's name) or ``None`` for a
    plain render, which draws the scene and nothing else. Captions sit in a band
    of :attr:`band` pixels at the top of each panel, above the art, never over it.
    """

    def __init__(self, scene: Scene, labels: Sequence[str | None], width: int, height: int, view: Box) -> None:
        self.scene = scene
        self.labels = tuple(labels)
        self.panel_width, self.height = width, height
        self.width = width * len(self.labels)
        self.band = label_band(height) if any(label is not None for label in self.labels) else 0
        self.viewport = Viewport(view, width, max(1, height - self.band))
        self.raster = Raster(self.width, height, round_strokes=worth_compiling(scene))
        # extras per panel (see raster.overlays): ``under``/``over`` hooks called with
        # (canvas, panel index, panel width, height, time), the canvas in panel pixels
        self.layers: list[Layer] = []
        # the paint order at a time (shape indices), where drawings stack differently at their keys
        self.stacking: Callable[[float], Sequence[int]] | None = None

    def draw(self, panels: Sequence[Sequence[ShapeAt]], time: float, layout: str = "rgba") -> NDArray[np.uint8]:
        """One frame from each panel's shapes (one :class:`ShapeAt` per shape of the scene, in paint order).

        Returns straight RGBA ``(height, width, 4)``, reused by the next call; with
        ``layout="bgra"`` the surface's own premultiplied BGRA pixels, without a
        copy (straight wherever the background is opaque).
        """
        raster = self.raster
        raster.clear(self.scene.background)
        for index, polygons in enumerate(panels):
            raster.canvas.save()
            raster.canvas.translate(index * self.panel_width, 0)
            raster.canvas.clipRect(skia.Rect.MakeWH(self.panel_width, self.height))
            label = self.labels[index]
            if label is not None:
                self.draw_label(label, time)
            raster.canvas.translate(0, self.band)
            art = self.height - self.band
            for layer in self.layers:
                layer.under(raster.canvas, index, self.panel_width, art, time)
            self.draw_shapes(polygons, order=self.stacking(time) if self.stacking is not None else None)
            for layer in self.layers:
                layer.over(raster.canvas, index, self.panel_width, art, time)
            raster.canvas.restore()
        for index in range(1, len(panels)):
            x = index * self.panel_width - 0.5
            raster.line((x, 0), (x, self.height), _DIVIDER, 1.0)
        return raster.bgra() if layout == "bgra" else raster.rgba()

    def draw_shapes(self, shapes: Sequence[ShapeAt], alpha: float = 1.0, order: Sequence[int] | None = None) -> None:
        """Every shape of the scene as it is at one time, in paint order (``order``: shape indices,
        first painted first; default the scene's)."""
        layers = GroupLayers(self.raster.canvas)
        for index in order if order is not None else range(len(shapes)):
            at = shapes[index]
            if at.visible:  # the groups with an opacity it is drawn in, each composited as one
                layers.enter(at.key.groups if at.key is not None else ())
            draw_shape(self.raster, self.viewport, self.scene.shapes[index], at, alpha)
        layers.enter(())

    def draw_label(self, label: str, time: float) -> None:
        size = label_size(self.height)
        pad = size * 0.8
        self.raster.text(label, pad, pad + size, size, _LABEL, bold=True)
        self.raster.text(f"{time:5.2f} s", pad, pad + 2.1 * size, size * 0.75, _LABEL_SOFT)


def label_size(height: int) -> float:
    """The caption's type size in a panel ``height`` pixels tall."""
    return max(11.0, height / 24)


def label_band(height: int) -> int:
    """Pixels at the top of a labelled panel that hold its caption (name and time), above the art."""
    return int(np.ceil(3.3 * label_size(height)))


def draw_shape(raster: Raster, viewport: Viewport, shape: Shape, at: ShapeAt, alpha: float = 1.0) -> None:
    """Draw ``shape`` as it is at one time (``at``) through ``viewport``; non-finite contours are skipped.

    Contours are drawn with the winding and fill rule ``at`` gives (its key's own at a key), and a
    contour growing from a point with its share of the stroke width."""
    if not at.visible:
        return
    pixels = [viewport.to_pixels(c) for c in at.contours]
    if at.dash_starts and at.paint.dash is not None:  # each closed contour from where its dashes start
        flips = at.reversed or (False,) * len(pixels)
        pixels = [without_repeats(starting_at(p, share, flip) if shut else (p[::-1] if share == 1.0 else p), shut)
                  for p, shut, share, flip in zip(pixels, at.closed, at.dash_starts, flips)]
    elif at.reversed:
        pixels = [p[::-1] if flip else p for p, flip in zip(pixels, at.reversed)]
    good = [len(p) >= 2 and bool(np.all(np.isfinite(p))) for p in pixels]
    kept = [(p, shut) for p, shut, ok in zip(pixels, at.closed, good) if ok]
    if not kept:
        return
    if at.clips:  # the key's clip paths (carried with the element between keys), intersected
        canvas = raster.canvas
        canvas.save()
        try:
            for region in at.clips:
                canvas.clipPath(contours_path([viewport.to_pixels(c) for c in region], [True] * len(region)),
                                doAntiAlias=True)
            _fill_and_draw(raster, viewport, shape, at, alpha, pixels, kept)
        finally:
            canvas.restore()
        return
    _fill_and_draw(raster, viewport, shape, at, alpha, pixels, kept)


def _fill_and_draw(raster: Raster, viewport: Viewport, shape: Shape, at: ShapeAt, alpha: float,
                   pixels: list[NDArray[np.float64]], kept: list[tuple[NDArray[np.float64], bool]]) -> None:
    if at.masks:  # the key's masks (carried with the element between keys)
        from .mask import draw_masked

        every = np.concatenate([p for p, _ in kept])
        reach = at.paint.stroke_width * (viewport.scale if shape.stroke_scales else 1.0) * \
            max(1.0, drawn_style(shape, at)[1].miter_limit) + 2.0  # a stroke's miters reach this far out
        (x0, y0), (x1, y1) = every.min(axis=0) - reach, every.max(axis=0) + reach
        shown = raster.canvas.getLocalClipBounds()  # what of it can show
        x0, y0 = max(float(x0), shown.left()), max(float(y0), shown.top())
        x1, y1 = min(float(x1), shown.right()), min(float(y1), shown.bottom())
        draw_masked(raster, viewport, at.masks,
                    lambda: _fill_and_draw(raster, viewport, shape, replace(at, masks=()), alpha, pixels, kept),
                    skia.Rect.MakeLTRB(x0, y0, max(x0, x1), max(y0, y1)))
        return
    paint = at.paint
    if paint.gradient or paint.stroke_gradient or paint.pattern or paint.stroke_pattern:
        from .patterns import paint_shaders

        raster.fill_shader, raster.stroke_shader = paint_shaders(paint, viewport)
        try:
            _draw_kept(raster, viewport, shape, at, alpha, pixels, kept)
        finally:
            raster.fill_shader = raster.stroke_shader = None
        return
    _draw_kept(raster, viewport, shape, at, alpha, pixels, kept)


def _draw_kept(raster: Raster, viewport: Viewport, shape: Shape, at: ShapeAt, alpha: float,
               pixels: list[NDArray[np.float64]], kept: list[tuple[NDArray[np.float64], bool]]) -> None:
    paint = at.paint
    rule, style = drawn_style(shape, at)
    width = paint.stroke_width * (viewport.scale if shape.stroke_scales else 1.0)
    if paint.dash is not None:
        style = dashed(style, paint.dash, viewport.scale if shape.stroke_scales else 1.0)
    good = [len(p) >= 2 and bool(np.all(np.isfinite(p))) for p in pixels]
    if at.fade is None:
        shares = [w for w, ok in zip(at.widths, good) if ok] if at.widths else []
        if not shares or all(w == 1.0 for w in shares) or paint.stroke is None:
            raster.draw_contours([p for p, _ in kept], [shut for _, shut in kept], rule, paint.fill,
                                 paint.stroke, width, style, paint.opacity * alpha)
            return
        # contours growing from a point: one fill of them all, then each stroke width's contours
        opacity = paint.opacity * alpha
        if opacity < 1.0:
            raster.canvas.saveLayerAlpha(None, int(round(255 * min(1.0, opacity))))
        raster.draw_contours([p for p, _ in kept], [shut for _, shut in kept], rule, paint.fill, None, 0.0, style)
        for share in sorted(set(shares)):
            group = [(p, shut) for (p, shut), w in zip(kept, shares) if w == share]
            raster.draw_contours([p for p, _ in group], [s for _, s in group], rule, None, paint.stroke,
                                 width * share, style)
        if opacity < 1.0:
            raster.canvas.restore()
        return
    # a cross-fade: the shape as in the first key, plus the shape as in the second, weighted
    sides = [side for side, ok in zip(at.sides, good) if ok]
    canvas = raster.canvas
    canvas.saveLayerAlpha(None, int(round(255 * min(1.0, paint.opacity * alpha))))
    for skip, weight in ((1, 1.0 - at.fade), (-1, at.fade)):
        own = [(p, shut) for (p, shut), side in zip(kept, sides) if side != skip]
        if not own:
            continue
        canvas.saveLayer(None, skia.Paint(Alphaf=weight, BlendMode=skia.BlendMode.kPlus))
        raster.draw_contours([p for p, _ in own], [s for _, s in own], rule, paint.fill, paint.stroke,
                             width, style)
        canvas.restore()
    canvas.restore()


def drawn_style(shape: Shape, at: ShapeAt) -> tuple[str, StrokeStyle]:
    """The fill rule and stroke ends ``shape`` is drawn with at one time: its key's own, else the shape's."""
    key = at.key
    if key is None:
        return shape.fill_rule, StrokeStyle(shape.cap, shape.join, shape.miter_limit)
    return key.fill_rule or shape.fill_rule, StrokeStyle(key.cap or shape.cap, key.join or shape.join,
                                                         key.miter_limit or shape.miter_limit)
