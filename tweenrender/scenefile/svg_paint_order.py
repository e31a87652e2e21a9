"""``paint-order`` (SVG 2 §13.6): the stroke painted before the fill.

The value is ``normal`` or one to three of ``fill``, ``stroke``, ``markers``, each at most once; the ones
not written follow in their usual order (fill, stroke, markers). A value that breaks this rule is invalid
and reads as ``normal``. Where the stroke comes before the fill, the element is drawn as two: its stroke
alone, then its fill alone, with the same outline, clips and masks (the fill keeps the element's id, the
stroke has none, so that pairing by id follows the fill). Markers are not drawn, so their place is
accepted and otherwise left aside.
"""

from __future__ import annotations

from dataclasses import replace
from typing import TypeVar

__all__ = ["in_paint_order", "stroke_first"]

_PARTS = ("fill", "stroke", "markers")
_Element = TypeVar("_Element")


def stroke_first(value: str) -> bool:
    """Whether the ``paint-order`` value ``value`` paints the stroke before the fill."""
    words = value.strip().lower().split()
    if not words or words == ["normal"] or len(set(words)) != len(words) or not set(words) <= set(_PARTS):
        return False
    order = words + [part for part in _PARTS if part not in words]
    return order.index("stroke") < order.index("fill")


def in_paint_order(element: _Element, value: str) -> list[_Element]:
    """``element`` (a :class:`.svg.Element`) as drawn under ``paint-order`` ``value``: itself, or its stroke
    alone then its fill alone when the stroke comes first and both are painted."""
    paint = element.paint  # type: ignore[attr-defined]
    fills = paint.fill is not None and paint.fill[3] > 0
    strokes = paint.stroke is not None and paint.stroke[3] > 0 and paint.stroke_width > 0
    if not (fills and strokes and stroke_first(value)):
        return [element]
    stroke_alone = replace(paint, fill=None, gradient=None, pattern=None)
    fill_alone = replace(paint, stroke=None, stroke_gradient=None, stroke_pattern=None)
    stroke = replace(element, id=None, paint=stroke_alone)  # type: ignore[type-var]
    fill = replace(element, paint=fill_alone)  # type: ignore[type-var]
    return [stroke, fill]
