"""Round-joined strokes of detailed outlines drawn from distances by a compiled kernel, not by skia's stroker.

A stroke with round joins (and round caps, or no open ends) is every point within
half its width of the outline, so each pixel's coverage follows from its
distance to the nearest segments (see ``_stroke_kernel``): faster than skia's
stroker on detailed outlines and closer to the exact area on smooth ones
(``benchmarks/bench_render.py`` and ``benchmarks/stroke_accuracy.py`` measure both). It is
used only where it can draw what skia would: straight onto the surface's own
pixels (no layer), under a rectangular clip and a uniform scale with
translation, in scenes that stroke at least :data:`MIN_SEGMENTS` such segments a
frame (below that the kernel's start-up is not repaid), so a scene's strokes are
drawn one way in every frame, whichever way the frame is asked for.
"""

from __future__ import annotations

from types import ModuleType
from typing import Sequence

import numpy as np
import skia
from numpy.typing import NDArray

from ..model import Scene

__all__ = ["MIN_SEGMENTS", "MIN_WIDTH", "worth_compiling", "draws_on", "stroke_contours"]

MIN_SEGMENTS = 20_000
"""Fewest round-stroked segments in a frame of a scene for the compiled stroke to be used: its start-up
(importing numba and loading the kernel, measured in docs/performance.md) is then repaid within a
second or two of video."""

MIN_WIDTH = 1.0
"""Narrowest stroke, in device pixels, drawn from distances: below a pixel both sides of the stroke cross
one pixel, which the kernel's two-edge coverage does not model."""


def _kernel() -> ModuleType:
    """The compiled kernel, imported on first need (numba costs ~0.2 s to import)."""
    from . import _stroke_kernel

    return _stroke_kernel


def worth_compiling(scene: Scene) -> bool:
    """Whether ``scene`` strokes at least :data:`MIN_SEGMENTS` segments with round joins in a frame, each
    shape counted at its most detailed stroked key (a closed contour of N vertices has N, an open one
    N - 1; open contours count only under round caps)."""
    total = 0
    for shape in scene.shapes:
        if shape.join != "round":
            continue
        most = 0
        for key in shape.keys:
            if key.hidden or key.paint.stroke is None or key.paint.stroke[3] == 0 or key.paint.stroke_width <= 0:
                continue
            if shape.cap != "round" and not all(c.closed for c in key.contours):
                continue
            most = max(most, sum(len(c.points) - (0 if c.closed else 1) for c in key.contours))
        total += most
    return total >= MIN_SEGMENTS


def draws_on(canvas: skia.Canvas, address: int) -> tuple[float, float, float, skia.IRect] | None:
    """``(scale, dx, dy, clip)`` when ``canvas`` draws straight onto the pixels at ``address`` (its top
    layer is that memory) under a rectangular clip and a uniform scale with translation; ``None``
    otherwise."""
    if not canvas.isClipRect():
        return None
    top = canvas.accessTopLayerPixels()  # a layer's own memory inside saveLayer (peekPixels gives the base)
    if top is None or np.asarray(top).__array_interface__["data"][0] != address:
        return None
    matrix = canvas.getTotalMatrix()
    if not matrix.isScaleTranslate():
        return None
    sx, sy = matrix.getScaleX(), matrix.getScaleY()
    if sx <= 0 or sx != sy:
        return None
    return sx, matrix.getTranslateX(), matrix.getTranslateY(), canvas.getDeviceClipBounds()


def stroke_contours(pixels: NDArray[np.uint8], contours: Sequence[NDArray[np.float64]], closed: Sequence[bool],
                    width: float, premultiplied: NDArray[np.float64], scale: float = 1.0,
                    offset: tuple[float, float] = (0.0, 0.0), clip: tuple[int, int, int, int] | None = None) -> int:
    """Blend the round-joined, round-capped stroke of ``contours`` (each ``(N_i, 2)``, finite; segments that
    ``scale`` and ``offset`` take past float range are dropped) ``width`` device pixels wide, in ``premultiplied (4,)`` colour (0..255,
    the pixels' channel order, alpha last), source-over onto premultiplied ``pixels (H, W, 4)`` inside
    ``clip`` (left, top, right, bottom; default the whole). Returns the number of pixels touched."""
    if not contours:
        return 0
    kernel = _kernel()
    points = contours[0] if len(contours) == 1 else np.concatenate(contours)
    height, wide = pixels.shape[:2]
    left, top, right, bottom = clip if clip is not None else (0, 0, wide, height)
    left, top, right, bottom = max(0, left), max(0, top), min(wide, right), min(height, bottom)
    # segments that scale and offset take past float range are left out by the kernel: they are off-canvas
    return int(kernel.stroke_polylines(pixels, np.ascontiguousarray(points, dtype=np.float64),
                                       np.array([len(c) for c in contours], dtype=np.int64),
                                       np.array(closed, dtype=np.bool_), float(scale), float(offset[0]),
                                       float(offset[1]), width / 2, np.asarray(premultiplied, dtype=np.float64),
                                       left, top, right, bottom))
