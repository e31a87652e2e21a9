"""SVG ``linearGradient`` and ``radialGradient`` paint servers read into :class:`~tweenrender.model.Gradient` s.

Attributes and stops are inherited through ``href`` chains, as SVG says; ``gradientUnits``
(``objectBoundingBox`` by default, or ``userSpaceOnUse``), ``gradientTransform`` and
``spreadMethod`` are kept; the result is placed in world units by the element's own transform.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from ..model import Color, Gradient
from .svg_color import parse_color
from .scene_limits import LIMITS
from .svg_document import Document, Node, href_chain, matrix, own_style
from .svg_flatten import Refusal
from .svg_transform_origin import about_origin, parse_origin

__all__ = ["read_gradient", "gradient_ref", "stop_color"]

_SHARED = ("gradientUnits", "gradientTransform", "spreadMethod", "transform-origin")  # taken across kinds
# percentages: of the bounding box's unit square, or of the viewport in userSpaceOnUse
_DEFAULTS = {"linearGradient": {"x1": "0%", "y1": "0%", "x2": "100%", "y2": "0%"},
             "radialGradient": {"cx": "50%", "cy": "50%", "r": "50%"}}


def gradient_ref(value: str) -> str | None:
    """The id in ``url(#id)`` (with any fallback after it), else None."""
    value = value.strip()
    if not value.startswith("url("):
        return None
    ref = value[4:].partition(")")[0].strip().strip("'\"")
    return ref[1:] if ref.startswith("#") else None


def _chain(ident: str, document: Document) -> list[Node]:
    """The gradient node of ``ident`` and the nodes its ``href`` leads to, nearest first."""
    return href_chain(ident, document, tuple(_DEFAULTS))


def _number(text: str, relative: float) -> float:
    """A gradient coordinate: a number, or a percentage of ``relative``."""
    text = text.strip()
    try:
        value = float(text[:-1]) / 100.0 * relative if text.endswith("%") else float(text)
    except ValueError:
        return math.nan
    return value


def _ancestors(target: Node, document: Document) -> list[Node]:
    """The elements around ``target``, outermost first (empty when it is not in the document's tree)."""
    stack: list[tuple[Node, tuple[Node, ...]]] = [(document.root, ())]
    while stack:
        node, above = stack.pop()
        if node is target:
            return list(above)
        stack.extend((child, above + (node,)) for child in node.children)
    return []


def _inherited(name: str, nodes: list[Node], document: Document, default: str) -> str:
    """Property ``name`` as the innermost of ``nodes`` (outermost first) that sets it other than ``inherit``."""
    for node in reversed(nodes):
        value = own_style(node, document).get(name, "").strip()
        if value and value != "inherit":
            return value
    return default


def stop_color(stop: Node, holder: Node, document: Document) -> tuple[float, float, float, float]:
    """A ``<stop>``'s colour with its ``stop-opacity`` folded in: ``(r, g, b, a)`` floats in [0, 255];
    ``currentColor`` and ``inherit`` are taken from the gradient and the elements around it."""
    own = own_style(stop, document)
    text = own.get("stop-color", "black").strip() or "black"
    if text in ("inherit", "currentColor", "currentcolor"):
        around = _ancestors(holder, document) + [holder]
        if text == "inherit":  # stop-color is not inherited: the parent's own value, up through inherits
            text = "black"
            for node in reversed(around):
                value = own_style(node, document).get("stop-color", "").strip()
                if value != "inherit":
                    text = value or "black"
                    break
        if text.lower() == "currentcolor":
            own_colour = own.get("color", "").strip()
            text = own_colour if own_colour and own_colour != "inherit" else _inherited("color", around, document,
                                                                                         "black")
    c = parse_color(text) or (0, 0, 0, 255)
    opacity_text = own.get("stop-opacity", "1").strip()
    try:
        alpha = float(opacity_text[:-1]) / 100.0 if opacity_text.endswith("%") else float(opacity_text)
    except ValueError:
        alpha = 1.0
    return float(c[0]), float(c[1]), float(c[2]), min(max(alpha, 0.0), 1.0) * c[3]


def _stops(nodes: list[Node], document: Document, opacity: float) -> list[tuple[float, Color]]:
    holder = next((n for n in nodes if any(c.tag == "stop" for c in n.children)), None)
    if holder is None:
        return []
    written = [c for c in holder.children if c.tag == "stop"]
    if len(written) > LIMITS["gradient_stops"]:
        raise Refusal(f"gradient {holder.attrs.get('id', '')!r} (line {holder.line}): expected at most "
                      f"{LIMITS['gradient_stops']} stops, found {len(written)}")
    stops: list[tuple[float, Color]] = []
    last = 0.0
    for stop in written:
        offset = _number(stop.attrs.get("offset", "0"), 1.0)
        offset = min(max(offset if math.isfinite(offset) else 0.0, 0.0, last), 1.0)  # clamped, never decreasing
        last = offset
        r, g, b, alpha = stop_color(stop, holder, document)
        stops.append((offset, (int(r), int(g), int(b), int(round(alpha * opacity)))))
    return stops


def read_gradient(ident: str, document: Document, user_box: tuple[float, float, float, float],
                  to_world: NDArray[np.float64], viewport: tuple[float, float], opacity: float = 1.0
                  ) -> Gradient | None:
    """The gradient ``ident`` filling an element whose geometry spans ``user_box`` ``(x, y, w, h)`` in its
    own user units, drawn through ``to_world`` (3x3, user units → world); ``viewport`` ``(w, h)`` is what
    percentages of ``userSpaceOnUse`` take. None when ``ident`` is no gradient or has no stops (the
    paint's fallback then applies). ``opacity`` multiplies the stops' alpha."""
    chain = _chain(ident, document)
    if not chain:
        return None
    kind = chain[0].tag

    def attribute(name: str, default: str | None = None) -> str | None:
        own = name not in _SHARED  # geometry: from gradients of the same kind only
        for node in chain:
            if name in node.attrs and not (own and node.tag != kind):
                return node.attrs[name]
        return default

    stops = _stops(chain, document, opacity)
    if not stops:
        return None
    units = (attribute("gradientUnits", "objectBoundingBox") or "").strip()
    bounding = units != "userSpaceOnUse"
    x, y, w, h = user_box
    # percentages: of the bounding box (whose units are fractions already), else of the viewport
    across, down = (1.0, 1.0) if bounding else viewport
    relative = {"x1": across, "x2": across, "cx": across, "fx": across, "y1": down, "y2": down, "cy": down,
                "fy": down, "r": 1.0 if bounding else math.hypot(across, down) / math.sqrt(2)}
    relative["fr"] = relative["r"]
    names = ("x1", "y1", "x2", "y2") if kind == "linearGradient" else ("cx", "cy", "r", "fx", "fy", "fr")
    values = []
    for name in names:
        if name in ("fx", "fy"):  # the focus defaults to the centre
            text = attribute(name) or attribute("c" + name[1], _DEFAULTS[kind]["c" + name[1]])
        else:
            text = attribute(name, _DEFAULTS[kind].get(name, "0"))
        values.append(_number(text or "0", relative[name]))
    if not all(math.isfinite(v) for v in values):
        return None
    if kind == "radialGradient" and values[5] <= 0:  # no focal radius (a negative one is an error: none)
        values.pop()
    own = about_origin(matrix(attribute("gradientTransform", "") or ""), parse_origin(
        chain[0].attrs.get("transform-origin", ""), (across, down), chain[0].font, chain[0].view))
    if bounding:
        if w <= 0 or h <= 0:
            return None  # SVG: a bounding-box gradient on a flat element is not drawn; the fallback colour is
        own = np.array([[w, 0.0, x], [0.0, h, y], [0.0, 0.0, 1.0]]) @ own
    placed = to_world @ own
    spread = (attribute("spreadMethod", "pad") or "pad").strip()
    return Gradient("linear" if kind == "linearGradient" else "radial", tuple(float(v) for v in values),
                    (float(placed[0, 0]), float(placed[1, 0]), float(placed[0, 1]), float(placed[1, 1]),
                     float(placed[0, 2]), float(placed[1, 2])),
                    tuple(stops), spread if spread in ("pad", "reflect", "repeat") else "pad")
