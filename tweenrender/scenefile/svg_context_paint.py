"""SVG 2's ``context-fill`` and ``context-stroke``: the fill or stroke of the *context element* — inside
``<use>``, the ``<use>`` that instances the element (resolved through nested ``<use>`` s); inside a marker,
the element it marks. Elsewhere they paint nothing."""

from __future__ import annotations

__all__ = ["NO_CONTEXT", "context_of", "in_context"]

Context = tuple[str, str]
"""The context element's ``(fill, stroke)`` paint values, themselves free of context keywords."""

NO_CONTEXT: Context = ("none", "none")
_KEYWORDS = {"context-fill": 0, "context-stroke": 1}


def in_context(value: str, context: Context) -> str:
    """``value`` (a ``fill`` or ``stroke`` value) with a context keyword replaced by the context's paint."""
    index = _KEYWORDS.get(value.strip())
    return value if index is None else context[index]


def context_of(style: dict[str, str], context: Context) -> Context:
    """The context a ``<use>`` of computed ``style`` gives what it instances, inside ``context``."""
    return in_context(style.get("fill", "black"), context), in_context(style.get("stroke", "none"), context)
