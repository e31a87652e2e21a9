"""SVG's conditional processing: ``<switch>`` and the attributes that make an element render or not.

SVG 1.1 §5.8 and SVG 2 §5.7: an element renders only when its conditions hold —
``requiredExtensions`` names no extension a renderer lacks (the reader has none, so the attribute
present is false), ``systemLanguage`` lists a language of the reader's (English, ``en`` and any
``en-…``; read with a fixed language so that a drawing renders the same everywhere), and
``requiredFeatures`` (dropped by SVG 2) always holds, as in browsers. A ``<switch>`` renders its
first direct child that is a graphics element or container in the SVG namespace whose conditions
hold, whatever its ``display``; the rest are not rendered.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol

__all__ = ["LANGUAGE", "conditions_hold", "switch_choice"]

LANGUAGE = "en"
"""The primary language subtag the reader matches ``systemLanguage`` against."""


class Element(Protocol):
    """An element of the tree (:class:`.svg_document.Node`)."""

    tag: str
    attrs: dict[str, str]
    children: list  # type: ignore[type-arg]
    svg: bool


def conditions_hold(node: Element) -> bool:
    """Whether ``node``'s conditional processing attributes let it render."""
    attrs = node.attrs
    if "requiredExtensions" in attrs:
        return False
    if "systemLanguage" in attrs:
        tags = [t.strip().lower() for t in attrs["systemLanguage"].split(",")]
        return any(t.split("-")[0] == LANGUAGE for t in tags if t)
    return True


def switch_choice(node: Element, renderable: Sequence[str]) -> Element | None:
    """The child a ``<switch>`` renders (the first of the tags ``renderable`` whose conditions hold), or None."""
    for child in node.children:
        if child.svg and child.tag in renderable and conditions_hold(child):
            return child
    return None
