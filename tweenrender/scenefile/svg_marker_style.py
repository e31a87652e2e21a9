"""Which markers an element names: the ``marker-start``, ``marker-mid`` and ``marker-end`` properties, and
the ``marker`` shorthand, which counts in style sheets and ``style`` only (CSS: a ``marker`` attribute is no
presentation attribute, and is ignored)."""

from __future__ import annotations

from typing import Any

from .svg_css import cascade, style_attribute

__all__ = ["MARKER_PROPERTIES", "marker_longhands"]

MARKER_PROPERTIES = ("marker-start", "marker-mid", "marker-end")
"""The inherited properties naming an element's markers (``url(#id)`` or ``none``)."""


def marker_longhands(own: dict[str, str], node: Any, sheet: tuple[Any, ...]) -> dict[str, str]:
    """``own`` (the properties of ``node``, an :class:`.svg_document.Node`) with the ``marker`` shorthand of
    the style ``sheet`` declarations matching it and of its ``style`` spread over the three longhands (a
    longhand the sheets or ``style`` set too keeps its own value); a ``marker`` attribute is dropped."""
    inline = style_attribute(node.attrs["style"]) if "style" in node.attrs else {}
    css = cascade({}, sheet, inline, frozenset(("marker",) + MARKER_PROPERTIES))
    out = {k: v for k, v in own.items() if k != "marker"}
    if "marker" in css:
        out.update({k: css["marker"] for k in MARKER_PROPERTIES})
        out.update((k, css[k]) for k in MARKER_PROPERTIES if k in css)
    return out
