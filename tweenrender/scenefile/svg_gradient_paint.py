"""An element's gradient paint: its fill's and its stroke's ``url(#gradient)`` read into the paint.

Both take the element's geometry's bounding box (for ``objectBoundingBox`` units) and its own opacity
(``fill-opacity``, ``stroke-opacity``). SVG: a gradient in ``objectBoundingBox`` units on an element
whose box has no width or no height (a horizontal or vertical line) cannot be drawn; the paint's
fallback colour (``url(#g) green``) paints instead, or nothing without one.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from numpy.typing import NDArray

from ..model import Color, Paint
from .svg_color import parse_color
from .svg_document import Document, opacity_value
from .svg_gradients import _chain, gradient_ref, read_gradient
from .svg_patterns import Content, is_pattern, mean_color, read_pattern

__all__ = ["with_gradients"]

_FLAT = 1e-9  # a box side under this fraction of the other is none


def with_gradients(paint: Paint, style: dict[str, str], document: Document, placed: NDArray[np.float64],
                   contours: list[tuple[NDArray[np.float64], bool]], viewport: tuple[float, float],
                   content: Content | None = None) -> Paint:
    """``paint`` with the gradients or patterns of its fill and stroke, where they are ``url(#…)`` of a linear or
    radial gradient or a pattern (:mod:`.svg_patterns`, whose children ``content`` draws; without it a pattern
    keeps the paint's colour). ``placed`` (3x3) maps the element's user units to the world, where
    ``contours`` (``(N_i, 2)`` each) are; ``viewport`` ``(w, h)`` is what percentages of ``userSpaceOnUse``
    take."""
    refs = gradient_ref(style.get("fill", "")), gradient_ref(style.get("stroke", ""))
    if refs == (None, None) or not contours:
        return paint
    every = np.concatenate([points for points, _ in contours])
    user = (np.linalg.inv(placed) @ np.column_stack([every, np.ones(len(every))]).T)[:2].T
    (x0, y0), (x1, y1) = user.min(axis=0), user.max(axis=0)
    w, h = float(x1 - x0), float(y1 - y0)
    if w <= _FLAT * h:
        w = 0.0
    if h <= _FLAT * w:
        h = 0.0
    box = (float(x0), float(y0), w, h)
    changes: dict[str, object] = {}
    for ident, colour, gradient, name in ((refs[0], "fill", "gradient", "fill"),
                                          (refs[1], "stroke", "stroke_gradient", "stroke")):
        if ident is None or getattr(paint, colour) is None:
            continue
        opacity = _opacity(style.get(f"{name}-opacity"))
        if content is not None and is_pattern(ident, document):
            pattern = read_pattern(ident, document, box, placed, viewport, opacity, content)
            flat = w <= 0 or h <= 0  # a box without area: the fallback colour, as for gradients
            changes[colour] = mean_color(pattern) if pattern is not None else \
                _fallback(style.get(name, ""), opacity) if flat else None
            if pattern is not None:
                changes["pattern" if name == "fill" else "stroke_pattern"] = pattern
            continue
        found = read_gradient(ident, document, box, placed, viewport, opacity)
        if found is not None:
            changes[gradient] = found
        elif (w <= 0 or h <= 0) and _bounding(ident, document):
            changes[colour] = _fallback(style.get(name, ""), opacity)
    return replace(paint, **changes) if changes else paint  # type: ignore[arg-type]


def _bounding(ident: str, document: Document) -> bool:
    """Whether ``ident`` is a gradient with stops in ``objectBoundingBox`` units."""
    chain = _chain(ident, document)
    if not chain or not any(c.tag == "stop" for node in chain for c in node.children):
        return False
    units = next((node.attrs["gradientUnits"] for node in chain if "gradientUnits" in node.attrs), "")
    return units.strip() != "userSpaceOnUse"


def _fallback(value: str, opacity: float) -> Color | None:
    """The fallback colour after ``url(…)`` in a paint ``value`` at ``opacity``; None without one."""
    rest = value.strip()[4:].partition(")")[2].strip()
    if not rest or rest == "none":
        return None
    c = parse_color(rest)
    if c is None:
        return None
    return (c[0], c[1], c[2], int(round(c[3] * opacity)))


def _opacity(text: str | None) -> float:
    """``fill-opacity`` or ``stroke-opacity``: a number or percentage clamped to [0, 1] (1 when unreadable)."""
    return 1.0 if text is None else opacity_value(text)
