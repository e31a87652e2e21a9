"""Viewports an SVG drawing opens inside itself: a nested ``<svg>``, a ``<symbol>`` (through ``<use>``), an
``<svg>`` instanced by ``<use>`` (SVG 1.1 §7.9, §5.6; SVG 2 §5.6.2).

A viewport is a rectangle ``x, y, width, height`` in the user space around it (percentages of the
viewport around it; ``width`` and ``height`` 100 % by default, a ``<use>``'s own ``width`` and ``height``
replacing those of the ``<svg>`` or ``<symbol>`` it instances), a new user space inside it (its
``viewBox`` placed by ``preserveAspectRatio``, else its origin at ``x, y``), and a clip to the rectangle
unless ``overflow`` is ``visible`` or ``auto``. A viewport of zero width or height draws nothing.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from .svg_lengths import user_units

__all__ = ["Viewport", "aspect_matrix", "nested_viewport", "outermost_size", "parse_view_box", "renders", "root_size"]


class Node(Protocol):
    """An element of the drawing's tree (:class:`.svg_document.Node`)."""

    tag: str
    attrs: dict[str, str]
    font: tuple[float, float]
    view: tuple[float, float]


@dataclass(frozen=True, slots=True)
class Viewport:
    """A viewport opened by an element.

    ``to_parent`` (3 × 3) maps its user space into the user space around it; ``rect`` ``(x, y, width,
    height)`` is its rectangle in that outer space, or None when its content is not clipped; ``size``
    ``(width, height)`` is what percentages inside it are of (its viewBox's, else its own size).
    """

    to_parent: NDArray[np.float64]
    rect: tuple[float, float, float, float] | None
    size: tuple[float, float]


def aspect_matrix(box: tuple[float, float, float, float], width: float, height: float, rule: str
                  ) -> NDArray[np.float64]:
    """The 3x3 map of view box ``box`` ``(x, y, w, h)`` into a ``width`` × ``height`` viewport at the origin by
    the ``preserveAspectRatio`` value ``rule`` (default ``xMidYMid meet``; SVG 1.1 §7.8)."""
    words = rule.split()
    if words[:1] == ["defer"]:
        words = words[1:]
    align = words[0] if words else "xMidYMid"
    x, y, w, h = box
    sx, sy = width / w, height / h
    if align != "none":
        sx = sy = max(sx, sy) if words[1:2] == ["slice"] else min(sx, sy)
    where = {"Min": 0.0, "Mid": 0.5, "Max": 1.0}
    fx, fy = (where.get(align[1:4], 0.5), where.get(align[5:8], 0.5)) if len(align) == 8 else (0.5, 0.5)
    return np.array([[sx, 0.0, -x * sx + (width - w * sx) * fx], [0.0, sy, -y * sy + (height - h * sy) * fy],
                     [0.0, 0.0, 1.0]])


def parse_view_box(text: str | None) -> tuple[float, float, float, float] | None:
    """A ``viewBox`` value as ``(x, y, width, height)``, or None when it is missing or in error (four finite
    numbers with a positive width and height are needed: SVG ignores any other)."""
    numbers = _four_numbers(text)
    if numbers is None or numbers[2] <= 0 or numbers[3] <= 0:
        return None
    return numbers


def _four_numbers(text: str | None) -> tuple[float, float, float, float] | None:
    """``text``'s four finite numbers (separated by spaces or commas), else None."""
    try:
        x, y, w, h = (float(v) for v in (text or "").replace(",", " ").split())
    except ValueError:
        return None
    return (x, y, w, h) if all(math.isfinite(v) for v in (x, y, w, h)) else None


def _length(text: str | None, relative: float, default: float, font: tuple[float, float],
            view: tuple[float, float] = (100.0, 100.0)) -> float:
    """A length attribute in user units (units at 96 per inch, percentages of ``relative``, ``em``, ``rem``
    and ``ex`` of ``font``, viewport units of ``view``); ``default`` when missing or unreadable."""
    value = None if text is None or not text.strip() else user_units(text, font, view, relative)
    return default if value is None else value


def renders(root: Node) -> bool:
    """Whether the root ``<svg>`` draws anything: a ``width`` or ``height`` of zero or less disables its
    rendering (SVG 1.1 §7.2; a negative one is in error, and renderers draw nothing either), and so does a
    ``viewBox`` of zero width or height."""
    for name in ("width", "height"):
        value = user_units(root.attrs.get(name, ""), root.font, strict=True)
        if value is not None and value <= 0:
            return False
    return not _zero_view_box(root.attrs.get("viewBox"))


def _zero_view_box(text: str | None) -> bool:
    """Whether ``viewBox`` is four finite numbers with a zero width or height and neither negative (which
    disables rendering; a negative one is in error and ignored)."""
    numbers = _four_numbers(text)
    return numbers is not None and min(numbers[2], numbers[3]) == 0  # neither negative, one zero


def root_size(root: Node) -> tuple[float, float]:
    """What percentages directly inside the root ``<svg>`` are of: its viewBox's size, else its absolute
    ``width`` and ``height``, else 100 × 100."""
    box = parse_view_box(root.attrs.get("viewBox"))
    if box is not None:
        return box[2], box[3]
    sizes = root.attrs.get("width", ""), root.attrs.get("height", "")
    if "%" not in "".join(sizes):
        w, h = _length(sizes[0], 100.0, 0.0, root.font), _length(sizes[1], 100.0, 0.0, root.font)
        if w > 0 and h > 0:
            return w, h
    return 100.0, 100.0


def outermost_size(root: Node) -> tuple[float, float]:
    """The outermost ``<svg>``'s viewport in CSS px, what ``vw`` and ``vh`` are of: its absolute ``width`` and
    ``height``; one of them missing (or a percentage) taken from the other by the ``viewBox``'s aspect, or
    the ``viewBox``'s own size; else 100 × 100."""
    box = parse_view_box(root.attrs.get("viewBox"))
    sizes = []
    for name in ("width", "height"):
        text = root.attrs.get(name, "")
        value = 0.0 if "%" in text else _length(text, 100.0, 0.0, root.font)
        sizes.append(value if value > 0 and math.isfinite(value) else None)
    width, height = sizes
    if box is not None:
        if width is None and height is None:
            width, height = box[2], box[3]
        elif width is None:
            width = height * box[2] / box[3]  # type: ignore[operator]
        elif height is None:
            height = width * box[3] / box[2]
    return (width or 100.0, height or 100.0)


def nested_viewport(node: Node, parent_size: tuple[float, float], overflow: str,
                    instance: Node | None = None) -> Viewport | None:
    """The viewport of a nested ``<svg>`` or of a ``<symbol>`` instanced by ``<use>`` ``instance`` (whose
    ``width`` and ``height``, when given, replace the element's); None when it draws nothing (zero size).

    ``parent_size`` is what percentages are of; ``overflow`` the element's ``overflow`` property. A symbol
    sits at the origin of the ``<use>`` (whose ``x``, ``y`` the caller has applied); a negative size is
    in error and read as ``auto`` (100 %).
    """
    pw, ph = parent_size
    if node.tag == "symbol":
        x = y = 0.0
    else:
        x = _length(node.attrs.get("x"), pw, 0.0, node.font, node.view)
        y = _length(node.attrs.get("y"), ph, 0.0, node.font, node.view)
    sizes = []
    for name, relative in (("width", pw), ("height", ph)):
        source = instance if instance is not None and instance.attrs.get(name, "").strip() else node
        value = _length(source.attrs.get(name), relative, relative, source.font, source.view)
        sizes.append(relative if value < 0 else value)
    width, height = sizes
    if width <= 0 or height <= 0:
        return None
    box = parse_view_box(node.attrs.get("viewBox"))
    offset = np.array([[1.0, 0.0, x], [0.0, 1.0, y], [0.0, 0.0, 1.0]])
    if box is None:
        to_parent, size = offset, (width, height)
    else:
        to_parent = offset @ aspect_matrix(box, width, height, node.attrs.get("preserveAspectRatio", ""))
        size = (box[2], box[3])
    clipped = overflow.strip().lower() not in ("visible", "auto")
    return Viewport(to_parent, (x, y, width, height) if clipped else None, size)
