"""Strokes under a skew or a non-uniform scale: SVG strokes an element in its own user space, so its pen is
stretched and sheared by the element's transform (a line of width 80 under ``skewX(-45)`` is a parallelogram,
a circle under ``scale(2, 1)`` is stroked thicker left and right than top and bottom). A world stroke has
one width all round; such a stroke is drawn instead as the filled outline of its user-space stroke
(:func:`.stroke_outline.outlined`, with the element's caps, joins and miter limit), placed in the world.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from numpy.typing import NDArray

from ..model import Contour, frozen_points

__all__ = ["clipped_miters", "in_stroke_space"]

_ROUND = 1e-6  # singular values of the transform this close (relatively) draw a round pen


def in_stroke_space(element: object, placed: NDArray[np.float64], clipped_miters: bool = False) -> list[object]:
    """``element`` (a :class:`.svg.Element`, world units) as drawn when ``placed`` (3x3, its user units → world)
    stretches its pen, or its miter joins are clipped at the miter limit (``clipped_miters``: SVG 2's
    ``stroke-linejoin="miter-clip"``, which no renderer's stroke draws): its fill alone, then its stroke's
    outline filled with the stroke's paint; itself when the pen stays round (and miters are not clipped), it
    draws no stroke, or the stroke is dashed."""
    from .stroke_outline import outlined

    paint = element.paint  # type: ignore[attr-defined]
    strokes = paint.stroke is not None and paint.stroke[3] > 0 and paint.stroke_width > 0
    if not strokes or paint.dash is not None or not np.all(np.isfinite(placed)):
        return [element]
    linear = placed[:2, :2]
    largest, smallest = np.linalg.svd(linear, compute_uv=False)
    determinant = abs(float(np.linalg.det(linear)))
    if (largest - smallest <= _ROUND * largest and not clipped_miters) or determinant == 0:
        return [element]
    back = np.linalg.inv(placed)
    user = tuple(Contour(frozen_points(_apply(back, c.points)), c.closed)
                 for c in element.contours)  # type: ignore[attr-defined]
    stroke = replace(element, contours=user, paint=replace(  # type: ignore[type-var]
        paint, fill=None, gradient=None, pattern=None, stroke_width=paint.stroke_width / np.sqrt(determinant)))
    drawn = outlined(stroke)
    if drawn is stroke:  # nothing to outline
        return [element]
    drawn = replace(drawn, contours=tuple(Contour(frozen_points(_apply(placed, c.points)), True)
                                          for c in drawn.contours))
    fills = paint.gradient is not None or (paint.fill is not None and paint.fill[3] > 0)
    if not fills:
        return [drawn]
    body = replace(element, paint=replace(paint, stroke=None, stroke_gradient=None,
                                                             stroke_pattern=None))  # type: ignore[type-var]
    return [body, replace(drawn, id=None)]


def _apply(matrix: NDArray[np.float64], points: NDArray[np.float64]) -> NDArray[np.float64]:
    """``points (N, 2)`` through the affine ``matrix (3, 3)``."""
    return np.asarray(points, dtype=np.float64) @ matrix[:2, :2].T + matrix[:2, 2]


def clipped_miters(style: dict[str, str]) -> bool:
    """Whether an element's computed ``style`` clips its miters (``stroke-linejoin: miter-clip``)."""
    return style.get("stroke-linejoin", "").strip() == "miter-clip"
