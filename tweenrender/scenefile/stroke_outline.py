"""A stroke drawn as the filled shape it paints: where an element drawn with a stroke alone is matched
with one drawn with a fill alone (an outline icon with a filled one), its stroke is outlined, so that
the band of ink it draws — a ring, for a closed contour — morphs into the other's filled shape instead
of the other's fill fading in over the whole of what it encloses.

The outline is the union of each contour's stroke band (shapely's buffer: half the width on either
side, with the element's caps and joins, round ones flattened to within 1 % of the half width), its
rings oriented for the nonzero rule (outlines counter-clockwise, holes clockwise); the paint fills it
with the stroke's colour. At its key it draws what the stroke drew.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import numpy as np

from ..model import Contour, Paint, frozen_points

Element = Any
"""A :class:`.svg.Element` (not imported: :mod:`.svg` draws strokes under a non-uniform transform with
:func:`outlined`)."""

__all__ = ["stroke_only", "fill_only", "outlined"]

_CAPS = {"round": "round", "butt": "flat", "square": "square"}
_JOINS = {"round": "round", "bevel": "bevel"}  # every other join is a miter
_QUAD_SEGMENTS = 12  # segments a quarter circle of a round cap or join is drawn with: within 1 % of its radius


def stroke_only(paint: Paint) -> bool:
    """Whether ``paint`` draws a stroke and no fill."""
    fills = paint.gradient is not None or (paint.fill is not None and paint.fill[3] > 0)
    return not fills and paint.stroke is not None and paint.stroke[3] > 0 and paint.stroke_width > 0


def fill_only(paint: Paint) -> bool:
    """Whether ``paint`` draws a fill and no stroke."""
    fills = paint.gradient is not None or (paint.fill is not None and paint.fill[3] > 0)
    strokes = paint.stroke is not None and paint.stroke[3] > 0 and paint.stroke_width > 0
    return fills and not strokes


def outlined(element: Element) -> Element:
    """``element`` (stroked, not filled) as the filled outline of its stroke; itself where the outline is
    empty (a stroke of zero length with flat caps draws nothing) or the stroke is dashed (its dashes are laid
    along the outline as it moves)."""
    if element.paint.dash is not None:
        return element
    from shapely import LineString, LinearRing, Point, orient_polygons, unary_union

    half = 0.5 * element.paint.stroke_width
    style = {"cap_style": _CAPS.get(element.cap, "round"), "join_style": _JOINS.get(element.join, "mitre"),
             "mitre_limit": max(element.miter_limit, 1.0), "quad_segs": _QUAD_SEGMENTS}
    bands = []
    for contour in element.contours:
        points = np.unique(contour.points, axis=0)
        if len(points) == 1:  # a dot: drawn by round and square caps only
            if style["cap_style"] != "flat":
                bands.append(Point(points[0]).buffer(half, quad_segs=_QUAD_SEGMENTS,
                                                     cap_style=style["cap_style"]))
            continue
        line = LinearRing(contour.points) if contour.closed and len(contour.points) >= 3 else LineString(contour.points)
        bands.append(line.buffer(half, **style))
    shape = orient_polygons(unary_union(bands)) if bands else None
    if shape is None or shape.is_empty:
        return element
    polygons = list(getattr(shape, "geoms", [shape]))
    contours = []
    for polygon in polygons:
        if polygon.geom_type != "Polygon" or polygon.is_empty:
            continue
        for ring in (polygon.exterior, *polygon.interiors):
            points = np.asarray(ring.coords, dtype=np.float64)[:-1]  # shapely repeats the first point
            if len(points) >= 3:
                contours.append(Contour(frozen_points(points), True))
    if not contours:
        return element
    paint = replace(element.paint, fill=element.paint.stroke, stroke=None, stroke_width=0.0,
                    gradient=element.paint.stroke_gradient, stroke_gradient=None,
                    pattern=element.paint.stroke_pattern, stroke_pattern=None)
    return replace(element, contours=tuple(contours), paint=paint, fill_rule="nonzero")
