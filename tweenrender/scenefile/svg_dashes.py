"""``stroke-dasharray`` and ``stroke-dashoffset`` read as SVG 2 and CSS define them.

A dash array is lengths (units, ``em``, percentages of the viewport's normalised diagonal
√((w² + h²) / 2)) separated by commas and/or white space; an odd count is repeated to an even one.
A negative length, or anything unreadable, makes the whole value invalid: the stroke is solid, as
``none``; so is an array summing to 0. The offset is one such length (negative allowed; invalid: 0).
With a ``pathLength`` (a finite number > 0), lengths along the path are in its units: the pattern is
scaled by the path's own length over it.
"""

from __future__ import annotations

import math
import re

from ..model import Dash
from .svg_lengths import user_units

__all__ = ["read_dash", "along_path_length"]

_SEPARATOR = re.compile(r"\s*,\s*|\s+")


def read_dash(style: dict[str, str], font: tuple[float, float], diagonal: float, scale: float) -> Dash | None:
    """The element's dash pattern from its resolved ``style``, in user units times ``scale`` (its stroke
    width's factor into world units); None for a solid stroke. ``font`` is its ``(font-size, root's)``,
    ``diagonal`` what percentages are of."""
    text = style.get("stroke-dasharray", "none").strip()
    if not text or text.lower() == "none":
        return None
    items = [item for item in _SEPARATOR.split(text) if item]
    lengths = [user_units(item, font, relative=diagonal) for item in items]
    if not lengths or any(v is None or v < 0 for v in lengths):
        return None  # an invalid value: as none
    values = [float(v) for v in lengths]  # type: ignore[arg-type]
    if len(values) % 2:
        values += values
    if not sum(values) > 0:
        return None
    offset = user_units(style.get("stroke-dashoffset", "0").strip() or "0", font, relative=diagonal) or 0.0
    return Dash(tuple(v * scale for v in values), offset * scale)


def along_path_length(dash: Dash, path_length: str | None, length: float) -> Dash:
    """``dash`` scaled by ``length`` (the element's own length, user units) over its ``pathLength`` attribute;
    itself when that is missing or not a finite number > 0."""
    try:
        author = float((path_length or "").strip())
    except ValueError:
        return dash
    if not (math.isfinite(author) and author > 0 and math.isfinite(length) and length > 0):
        return dash
    factor = length / author
    return Dash(tuple(v * factor for v in dash.lengths), dash.offset * factor)
