"""``transform-origin`` (CSS Transforms 1 §6; an SVG 2 presentation attribute): the point a transform turns
and scales about.

The transform ``M`` of an element with origin ``(ox, oy)`` is ``translate(ox, oy) M translate(-ox, -oy)``.
The origin is one, two or three values (a third, the z offset, does not move a 2-D drawing): keywords
``left``, ``center``, ``right``, ``top``, ``bottom``, lengths, and percentages of the viewport the element
is in (SVG elements' reference box is the view box, ``transform-box: view-box``); one value sets x (or y,
for ``top`` and ``bottom``) with the other centred. A value that cannot be read leaves the origin at
``0 0``, the initial value, as browsers drop an invalid declaration.
"""

from __future__ import annotations

import math
import re

import numpy as np
from numpy.typing import NDArray

from .svg_lengths import user_units

__all__ = ["about_origin", "parse_origin"]

_FRACTIONS = {"left": 0.0, "top": 0.0, "center": 0.5, "right": 1.0, "bottom": 1.0}
_HORIZONTAL, _VERTICAL = ("left", "right"), ("top", "bottom")
_NUMBER_FIRST = re.compile(r"[+-]?(?:\d|\.\d)")


def parse_origin(text: str, box: tuple[float, float], font: tuple[float, float],
                 view: tuple[float, float]) -> tuple[float, float] | None:
    """The origin written ``text`` in user units, given the view box's size ``box`` (what percentages and
    keywords are of), the element's ``font`` (``em``, ``rem``) and the outermost viewport ``view``; None
    when it is ``0 0`` or cannot be read."""
    words = text.lower().replace(",", " ").split()
    if not 1 <= len(words) <= 3:
        return None
    words = words[:2]
    if len(words) == 1:
        words = ["center", words[0]] if words[0] in _VERTICAL else [words[0], "center"]
    elif words[0] in _VERTICAL or words[1] in _HORIZONTAL:  # "top left", "bottom 10px" is not valid CSS
        if not (words[0] in _FRACTIONS and words[1] in _FRACTIONS):
            return None
        words = [words[1], words[0]]
    if words[0] in _VERTICAL or words[1] in _HORIZONTAL:
        return None
    x = _coordinate(words[0], box[0], font, view)
    y = _coordinate(words[1], box[1], font, view)
    if x is None or y is None or (x == 0.0 and y == 0.0):
        return None
    return x, y


def _coordinate(word: str, side: float, font: tuple[float, float], view: tuple[float, float]) -> float | None:
    """One coordinate of the origin: a keyword or a percentage of ``side``, or a length (user units)."""
    if word in _FRACTIONS:
        return _FRACTIONS[word] * side
    if word.endswith("%"):
        try:
            value = float(word[:-1]) * side / 100.0
        except ValueError:
            return None
        return value if math.isfinite(value) else None
    if not _NUMBER_FIRST.match(word):
        return None
    return user_units(word, font, view)


def about_origin(transform: NDArray[np.float64], origin: tuple[float, float] | None) -> NDArray[np.float64]:
    """The 3x3 ``transform`` moved to act about ``origin`` ``(x, y)`` (None: the user space's origin)."""
    if origin is None:
        return transform
    x, y = origin
    there = np.array([[1.0, 0.0, x], [0.0, 1.0, y], [0.0, 0.0, 1.0]])
    back = np.array([[1.0, 0.0, -x], [0.0, 1.0, -y], [0.0, 0.0, 1.0]])
    return there @ transform @ back
