"""SVG ``<pattern>`` paint servers read into :class:`~tweenrender.model.Pattern` s.

Attributes and content are inherited through ``href`` chains of patterns; the tile ``x``, ``y``, ``width``,
``height`` is in ``patternUnits`` (``objectBoundingBox`` by default: fractions of the element's box; or
``userSpaceOnUse``: lengths, percentages of the viewport), the content in ``patternContentUnits``
(``userSpaceOnUse`` by default, or ``objectBoundingBox``) or placed by the pattern's ``viewBox`` and
``preserveAspectRatio``; ``patternTransform`` (about its ``transform-origin``) and the element's own transform
place the whole.
A tile of zero size paints nothing.
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np
from numpy.typing import NDArray

from ..model import Color, MaskShape, Pattern
from .svg_document import Document, Drawn, Node, href_chain, matrix
from .svg_flatten import Budget
from .svg_transform_origin import about_origin, parse_origin
from .svg_viewport import aspect_matrix, parse_view_box

__all__ = ["Content", "is_pattern", "read_pattern", "mean_color", "pattern_content"]


Content = Callable[[Node, NDArray[np.float64]], "tuple[MaskShape, ...] | None"]
"""The shapes drawn by a pattern's children through a 3x3 map of their user units into the pattern's."""


def _chain(ident: str, document: Document) -> list[Node]:
    """The ``<pattern>`` of ``ident`` and the patterns its ``href`` leads to, nearest first."""
    return href_chain(ident, document, ("pattern",))


def is_pattern(ident: str, document: Document) -> bool:
    """Whether ``ident`` names a ``<pattern>``."""
    nodes = document.ids.get(ident)
    return bool(nodes) and nodes[0].tag == "pattern"


def _value(text: str | None, relative: float) -> float:
    """A tile coordinate: a number (any absolute unit), or a percentage of ``relative``."""
    from svgelements import Length

    text = (text or "0").strip()
    try:
        if text.endswith("%"):
            return float(text[:-1]) / 100.0 * relative
        return float(Length(text).value(ppi=96.0))
    except (ValueError, TypeError):
        return math.nan


def read_pattern(ident: str, document: Document, user_box: tuple[float, float, float, float],
                 placed: NDArray[np.float64], viewport: tuple[float, float], opacity: float, content: Content
                 ) -> Pattern | None:
    """The pattern ``ident`` painting an element whose geometry spans ``user_box`` ``(x, y, w, h)`` in its user
    units, drawn through ``placed`` (3x3, user units → world); ``viewport`` ``(w, h)`` is what percentages of
    ``userSpaceOnUse`` take; ``content`` draws the pattern's children. None when ``ident`` is no pattern or
    its tile cannot be drawn (zero size, a flat box in ``objectBoundingBox`` units)."""
    chain = _chain(ident, document)
    if not chain:
        return None

    def attribute(name: str, default: str | None = None) -> str | None:
        return next((node.attrs[name] for node in chain if name in node.attrs), default)

    bx, by, bw, bh = user_box
    bounding = (attribute("patternUnits", "") or "").strip() != "userSpaceOnUse"
    if bounding:
        x, y = bx + _value(attribute("x"), 1.0) * bw, by + _value(attribute("y"), 1.0) * bh
        w, h = _value(attribute("width"), 1.0) * bw, _value(attribute("height"), 1.0) * bh
    else:
        x, y = _value(attribute("x"), viewport[0]), _value(attribute("y"), viewport[1])
        w, h = _value(attribute("width"), viewport[0]), _value(attribute("height"), viewport[1])
    if not all(math.isfinite(v) for v in (x, y, w, h)) or w <= 0 or h <= 0:
        return None
    box = parse_view_box(attribute("viewBox"))
    if box is not None:
        inner = aspect_matrix(box, w, h, attribute("preserveAspectRatio", "") or "")
    elif (attribute("patternContentUnits", "") or "").strip() == "objectBoundingBox":
        if bw <= 0 or bh <= 0:
            return None
        inner = np.array([[bw, 0.0, 0.0], [0.0, bh, 0.0], [0.0, 0.0, 1.0]])
    else:
        inner = np.eye(3)
    to_tile = np.array([[1.0, 0.0, x], [0.0, 1.0, y], [0.0, 0.0, 1.0]]) @ inner
    holder = next((node for node in chain if node.children), None)
    shapes = content(holder, to_tile) if holder is not None else ()
    if shapes is None:
        return None  # a pattern used inside its own tile: a reference in error, painting nothing
    own = matrix(attribute("patternTransform", "") or "")
    origin_text = chain[0].attrs.get("transform-origin", "")
    if origin_text:  # about the element's box (objectBoundingBox units) or the viewport
        origin = parse_origin(origin_text, (bw, bh) if bounding else viewport, chain[0].font, chain[0].view)
        if origin is not None and bounding:
            origin = (origin[0] + bx, origin[1] + by)
        own = about_origin(own, origin)
    world = placed @ own
    if not np.all(np.isfinite(world)):
        return None
    return Pattern((float(x), float(y), float(w), float(h)),
                   (float(world[0, 0]), float(world[1, 0]), float(world[0, 1]), float(world[1, 1]),
                    float(world[0, 2]), float(world[1, 2])), shapes, float(opacity))


def mean_color(pattern: Pattern) -> Color:
    """A plain colour standing for ``pattern`` (where one colour is drawn: vector output): the mean of its
    shapes' fill and stroke colours, at the pattern's opacity."""
    colours = [c for shape in pattern.shapes for c in (shape.paint.fill, shape.paint.stroke) if c is not None]
    if not colours:
        return (0, 0, 0, 0)  # an empty tile paints nothing
    r, g, b, a = np.mean(np.array(colours, dtype=float), axis=0)
    return (int(round(r)), int(round(g)), int(round(b)), max(1, int(round(a * pattern.opacity))))


def pattern_content(node: Node, ctm: NDArray[np.float64], document: Document, budget: Budget,
                    element: Callable[[Drawn], object | None]) -> tuple[MaskShape, ...] | None:
    """The shapes a ``<pattern>`` ``node``'s children draw through ``ctm`` (3x3, into the pattern's units), each
    read by ``element`` (a shape in those units: a :class:`.svg.Element`, or None); None for a pattern met
    again inside its own content, and for the patterns read on the way back to it (SVG: a recursive
    reference is in error, and what names it paints nothing)."""
    from .svg_document import _Walk

    open_patterns: list[int] = budget.memo.setdefault("patterns being read", [])  # type: ignore[assignment]
    in_cycle: set[int] = budget.memo.setdefault("patterns in a cycle", set())  # type: ignore[assignment]
    if id(node) in open_patterns:  # every pattern read since this one leads back to it: all in error
        in_cycle.update(open_patterns[open_patterns.index(id(node)) + 1:])
        return None
    open_patterns.append(id(node))
    try:
        walker = _Walk(document, False)
        out = []
        for child in node.children:
            for inner in walker.visit(child, {}, ctm, 1.0, True):
                e = element(inner) if inner.visible else None
                if e is not None:
                    out.append(MaskShape(e.contours, e.paint, e.fill_rule, e.cap, e.join,  # type: ignore[attr-defined]
                                         e.miter_limit, e.clips, e.masks))  # type: ignore[attr-defined]
        if id(node) in in_cycle:
            return None
        return tuple(out)
    finally:
        open_patterns.pop()
        in_cycle.discard(id(node))
