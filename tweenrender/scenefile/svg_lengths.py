"""Lengths relative to the font and the viewport, and ``Q``: what CSS Values 3 defines and svgelements reads as
bare numbers.

``em`` is the element's ``font-size``, ``rem`` the root element's, ``ex`` and ``ch`` half an ``em`` (CSS's
value when the font's x-height or the advance of its "0" is not known: no font is read for shapes);
``vw``, ``vh``, ``vmin`` and ``vmax`` a hundredth of the outermost ``<svg>``'s viewport's width, height,
smaller and larger side (its ``width`` and ``height`` in CSS px, else its ``viewBox``'s size), as CSS px of the
user space they are written in; ``Q`` a quarter of a millimetre. A
``font-size`` is a length (``em`` and ``%`` of the parent's), or a keyword (``medium`` = 16 px, CSS's
scale of 1.2 per step; ``smaller``, ``larger``).
"""

from __future__ import annotations

import math
import re

__all__ = ["DEFAULT_FONT_SIZE", "DEFAULT_VIEW", "font_relative", "font_size", "is_length", "user_units"]

DEFAULT_FONT_SIZE = 16.0
"""``medium``, the initial ``font-size`` (CSS px, = user units)."""

_LENGTH = re.compile(r"^\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*(rem|em|ex|ch|q|vw|vh|vmin|vmax)\s*$",
                     re.IGNORECASE)
_ABSOLUTE = re.compile(r"^\s*[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?(?:px|pt|pc|mm|cm|in|%)?\s*$",
                       re.IGNORECASE)
_KEYWORDS = {"xx-small": 9.0, "x-small": 10.0, "small": 13.0, "medium": 16.0, "large": 18.0, "x-large": 24.0,
             "xx-large": 32.0, "xxx-large": 48.0}
_PER_UNIT = {"em": 1.0, "ex": 0.5, "ch": 0.5}
DEFAULT_VIEW = (100.0, 100.0)
"""The outermost viewport's size (CSS px) when the drawing gives none."""


def font_relative(text: str, em: float, rem: float, view: tuple[float, float] = DEFAULT_VIEW) -> float | None:
    """``text`` in user units when it is a number in ``em``, ``rem``, ``ex``, ``ch``, ``Q`` or a viewport unit
    (``view``: the outermost viewport's width and height); else None."""
    match = _LENGTH.match(text)
    if match is None:
        return None
    number, unit = float(match.group(1)), match.group(2).lower()
    if unit == "q":
        return number * 96.0 / 25.4 / 4.0
    if unit[0] == "v":
        width, height = view
        side = {"vw": width, "vh": height, "vmin": min(width, height), "vmax": max(width, height)}[unit]
        value = number * side / 100.0
    else:
        value = number * (rem if unit == "rem" else em * _PER_UNIT[unit])
    return value if math.isfinite(value) else None


def font_size(text: str | None, parent: float, root: float, view: tuple[float, float] = DEFAULT_VIEW) -> float:
    """The ``font-size`` written ``text`` (None: inherited) in user units, given the parent's and the root's
    (and the outermost viewport's size ``view``); what cannot be read is inherited."""
    if text is None:
        return parent
    value = text.strip().lower()
    if value in _KEYWORDS:
        return _KEYWORDS[value]
    if value == "smaller":
        return parent / 1.2
    if value == "larger":
        return parent * 1.2
    if value.endswith("%"):
        try:
            found = parent * float(value[:-1]) / 100.0
        except ValueError:
            return parent
    else:
        relative = font_relative(value, parent, root, view)
        if relative is not None:
            found = relative
        else:
            from svgelements import Length

            try:
                found = float(Length(value).value(ppi=96.0, relative_length=parent))
            except (ValueError, TypeError):
                return parent
    return found if math.isfinite(found) and found >= 0 else parent


def is_length(text: str) -> bool:
    """Whether ``text`` is a number with an absolute unit, a percentage or no unit (CSS's grammar): what
    is not (``44mmx``, ``auto``) is in error, and the attribute takes its initial value."""
    return _ABSOLUTE.match(text) is not None


def user_units(text: str, font: tuple[float, float] = (DEFAULT_FONT_SIZE, DEFAULT_FONT_SIZE),
               view: tuple[float, float] = DEFAULT_VIEW, relative: float = 1.0, *, strict: bool = False) -> float | None:
    """``text`` as a length in user units: the units above of ``font`` (``(font-size, root's)``) and ``view``,
    else absolute units at 96 per inch and percentages of ``relative`` (svgelements); None where it is not a
    length (with ``strict``, by CSS's grammar: :func:`is_length`) or its value is not finite."""
    value = font_relative(text, *font, view)
    if value is None:
        if strict and not is_length(text):
            return None
        from svgelements import Length

        try:
            found = Length(text.strip()).value(ppi=96.0, relative_length=relative)
        except (ValueError, TypeError):
            return None
        value = float(found) if isinstance(found, (int, float)) else math.nan
    return value if math.isfinite(value) else None
