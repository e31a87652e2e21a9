"""SVG 2's ``context-fill`` and ``context-stroke``: the fill or stroke of the *context element* — inside
``<use>``, the ``<use>`` that instances the element (resolved through nested ``<use>`` s); inside a marker,
the element it marks. Elsewhere they paint nothing. A paint server (``url(#…)``) so taken is drawn in the
context element's user space and bounding box, not the shape's."""

from __future__ import annotations

from typing import Any

__all__ = ["NO_CONTEXT", "Context", "context_of", "in_context", "source_of"]

Source = tuple[str, Any, Any]
"""A context paint: its value (free of context keywords), and the context element's user space (3x3, None:
none) and node (whose bounding box ``objectBoundingBox`` units are of)."""

Context = tuple[Source, Source]
"""The context element's fill and stroke."""

NO_CONTEXT: Context = (("none", None, None), ("none", None, None))
_KEYWORDS = {"context-fill": 0, "context-stroke": 1}


def in_context(value: str, context: Context) -> str:
    """``value`` (a ``fill`` or ``stroke`` value) with a context keyword replaced by the context's paint."""
    index = _KEYWORDS.get(value.strip())
    return value if index is None else context[index][0]


def source_of(value: str, context: Context) -> tuple[Any, Any] | None:
    """Where ``value`` paints from when it is a context keyword naming a paint server: ``(space, node)`` of
    the context element; else None (the shape's own)."""
    index = _KEYWORDS.get(value.strip())
    if index is None or not context[index][0].strip().startswith("url(") or context[index][1] is None:
        return None
    return context[index][1], context[index][2]


def context_of(style: dict[str, str], context: Context, space: Any = None, node: Any = None) -> Context:
    """The context an element of computed ``style`` (a ``<use>``, a marked shape) in user space ``space`` gives
    what it instances or marks, inside ``context``."""
    def entry(name: str, default: str) -> Source:
        value = style.get(name, default)
        index = _KEYWORDS.get(value.strip())
        return context[index] if index is not None else (value, space, node)

    return entry("fill", "black"), entry("stroke", "none")
