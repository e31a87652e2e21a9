"""``clip-path`` written as a CSS basic shape (CSS Masking §5.1, CSS Shapes §3): ``circle()``.

``circle( [<radius>] [at <position>] ) [<box>]``: the radius is a length, a percentage (of the reference
box's normalised diagonal, √((w² + h²) / 2)), ``closest-side`` (the default) or ``farthest-side``; the
position is one or two of ``left``/``center``/``right``/``top``/``bottom``, lengths or percentages of the
box (default its centre). The box is the element's ``fill-box`` (``content-box``, ``padding-box``), its
``stroke-box`` (``border-box``, the default, and ``margin-box``: the fill box grown by half the stroke
width) or ``view-box`` (the viewport it is in). A value that does not read as one of these is invalid, and
an invalid ``clip-path`` clips nothing (as browsers do).
"""

from __future__ import annotations

import math
import re

import numpy as np
from numpy.typing import NDArray

__all__ = ["PREFIX", "is_basic_shape", "circle_outline"]

PREFIX = "\0shape "
"""What the clip reference of a basic shape starts with (a name no file can give a ``<clipPath>``)."""

_Box = tuple[float, float, float, float]
_NUMBER = r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?"
_CIRCLE = re.compile(r"^\s*circle\(\s*([^)]*)\)\s*([a-z-]*)\s*$")
_LENGTH = re.compile(rf"^({_NUMBER})(px|%)?$")
_FILL_BOXES = ("fill-box", "content-box", "padding-box")
_STROKE_BOXES = ("", "stroke-box", "border-box", "margin-box")
_MAX_VERTICES = 4096


def is_basic_shape(value: str) -> bool:
    """Whether a ``clip-path`` value is written as a basic shape (``circle(…)``, ``inset(…)``, …)."""
    return re.match(r"^\s*(circle|ellipse|inset|polygon|path|rect|xywh)\(", value) is not None


def _length(text: str, percent_of: float) -> float | None:
    """A length in user units (``px`` or unitless) or a percentage of ``percent_of``; None when neither."""
    match = _LENGTH.match(text)
    if match is None:
        return None
    value = float(match.group(1))
    return value * percent_of / 100.0 if match.group(2) == "%" else value


def _position(words: list[str], box: _Box) -> tuple[float, float] | None:
    """``at <position>`` as a point in user units; None when unreadable."""
    x, y, w, h = box
    centre = [x + w / 2, y + h / 2]
    keywords = {"left": (0, 0.0), "right": (0, 1.0), "top": (1, 0.0), "bottom": (1, 1.0)}
    if not 1 <= len(words) <= 2:
        return None
    for k, word in enumerate(words):
        if word == "center":
            continue
        if word in keywords:
            axis, fraction = keywords[word]
            centre[axis] = (x, y)[axis] + fraction * (w, h)[axis]
            continue
        axis = k if len(words) == 2 else 0
        value = _length(word, (w, h)[axis])
        if value is None:
            return None
        centre[axis] = (x, y)[axis] + value
    return centre[0], centre[1]


def circle_outline(value: str, fill_box: _Box, stroke_width: float, view_box: _Box, tolerance: float
                   ) -> NDArray[np.float64] | None:
    """The circle of ``clip-path: circle(…)`` as a closed outline ``(N, 2)`` in user units, flattened within
    ``tolerance`` (user units); None when ``value`` is not a circle this reads (then no clip applies).
    ``fill_box`` and ``view_box`` are ``(x, y, width, height)``; ``stroke_width`` grows the stroke box."""
    match = _CIRCLE.match(value.strip().lower())
    if match is None:
        return None
    inside, box_name = match.group(1).split(), match.group(2)
    if box_name in _FILL_BOXES:
        box = fill_box
    elif box_name in _STROKE_BOXES:
        half = max(stroke_width, 0.0) / 2
        box = (fill_box[0] - half, fill_box[1] - half, fill_box[2] + 2 * half, fill_box[3] + 2 * half)
    elif box_name == "view-box":
        box = view_box
    else:
        return None
    at = inside.index("at") if "at" in inside else len(inside)
    radius_words, position_words = inside[:at], inside[at + 1:]
    centre = _position(position_words, box) if at < len(inside) else (box[0] + box[2] / 2, box[1] + box[3] / 2)
    if centre is None or len(radius_words) > 1:
        return None
    cx, cy = centre
    x, y, w, h = box
    sides = (abs(cx - x), abs(x + w - cx), abs(cy - y), abs(y + h - cy))
    word = radius_words[0] if radius_words else "closest-side"
    if word == "closest-side":
        radius = min(sides)
    elif word == "farthest-side":
        radius = max(sides)
    else:
        found = _length(word, math.hypot(w, h) / math.sqrt(2))
        if found is None or found < 0:
            return None
        radius = found
    if not (radius > 0 and math.isfinite(radius)):
        return np.zeros((0, 2))  # a circle of no size: nothing is left
    step = math.acos(max(-1.0, 1.0 - tolerance / radius)) if tolerance < radius else math.pi / 2
    count = min(_MAX_VERTICES, max(16, math.ceil(math.pi / max(step, 1e-9))))
    angles = np.linspace(0.0, 2 * math.pi, count, endpoint=False)
    return np.column_stack([cx + radius * np.cos(angles), cy + radius * np.sin(angles)])
