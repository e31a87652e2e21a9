"""Gradient fills as skia shaders: a :class:`~tweenrender.model.Gradient` placed through a viewport."""

from __future__ import annotations

import numpy as np
import skia
from numpy.typing import NDArray

from ..model import Gradient
from ..core.view import Viewport, pixel_affine

__all__ = ["gradient_shader"]

_TILES = {"pad": skia.TileMode.kClamp, "reflect": skia.TileMode.kMirror, "repeat": skia.TileMode.kRepeat}


def _pixel_matrix(gradient: Gradient, viewport: Viewport) -> skia.Matrix:
    full = pixel_affine(gradient, viewport)
    return skia.Matrix.MakeAll(*(float(v) for v in full[0]), *(float(v) for v in full[1]), 0.0, 0.0, 1.0)


def gradient_shader(gradient: Gradient, viewport: Viewport) -> skia.Shader | None:
    """The shader that paints ``gradient`` on a canvas drawn through ``viewport``; None where it cannot be
    placed (a flat matrix, non-finite numbers)."""
    matrix = _pixel_matrix(gradient, viewport)
    if not matrix.invert(skia.Matrix()) or not all(np.isfinite(gradient.geometry)):
        return None
    offsets = [float(offset) for offset, _ in gradient.stops]
    colours = [skia.Color(r, g, b, a) for _, (r, g, b, a) in gradient.stops]
    if len(colours) == 1:
        offsets, colours = [0.0, 1.0], colours * 2
    tile = _TILES.get(gradient.spread, skia.TileMode.kClamp)
    if gradient.kind == "linear":
        x1, y1, x2, y2 = gradient.geometry
        if (x1, y1) == (x2, y2):  # SVG: the last stop's colour over the whole area
            return skia.Shaders.Color(colours[-1])
        return skia.GradientShader.MakeLinear([skia.Point(x1, y1), skia.Point(x2, y2)], colours, offsets, tile, 0,
                                              matrix)
    cx, cy, r, fx, fy = gradient.geometry[:5]
    fr = gradient.geometry[5] if len(gradient.geometry) > 5 else 0.0  # the focal radius
    if r <= 0:
        return skia.Shaders.Color(colours[-1])
    if (fx, fy) == (cx, cy) and fr == 0:
        return skia.GradientShader.MakeRadial(skia.Point(cx, cy), r, colours, offsets, tile, 0, matrix)
    return skia.GradientShader.MakeTwoPointConical(skia.Point(fx, fy), fr, skia.Point(cx, cy), r, colours, offsets,
                                                   tile, 0, matrix)
