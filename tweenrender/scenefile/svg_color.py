"""CSS colour values as SVG renderers read them (CSS Color 3 and 4's legacy syntax).

Names, ``#rgb``, ``#rgba``, ``#rrggbb``, ``#rrggbbaa``, ``rgb()``/``rgba()`` with numbers (decimals too) or
percentages and an alpha as a number or a percentage, ``hsl()``/``hsla()`` with the hue taken modulo 360 and
saturation and lightness clamped; function names are case-insensitive, and out-of-range values are clamped.
"""

from __future__ import annotations

import math
import re

__all__ = ["parse_color"]

RGBA = tuple[int, int, int, int]

_FUNCTION = re.compile(r"^(rgba?|hsla?)\((.*)\)$", re.IGNORECASE | re.DOTALL)
_SPLIT = re.compile(r"\s*[,/\s]\s*")


def _value(text: str, full: float) -> float:
    """A number, or a percentage of ``full``; NaN when unreadable."""
    try:
        return float(text[:-1]) * full / 100.0 if text.endswith("%") else float(text)
    except ValueError:
        return math.nan


def _byte(value: float) -> int:
    return round(min(max(value, 0.0), 255.0))


def _alpha(parts: list[str]) -> float:
    return min(max(_value(parts[3], 1.0), 0.0), 1.0) if len(parts) == 4 else 1.0


def _hsl(h: float, s: float, light: float) -> tuple[float, float, float]:
    """sRGB in [0, 1] of hue ``h`` (degrees), saturation and lightness in [0, 1] (CSS Color 3 §4.2.4)."""
    h = (h % 360.0) / 360.0
    q = light * (1 + s) if light <= 0.5 else light + s - light * s
    p = 2 * light - q

    def channel(t: float) -> float:
        t %= 1.0
        if t < 1 / 6:
            return p + (q - p) * 6 * t
        if t < 1 / 2:
            return q
        if t < 2 / 3:
            return p + (q - p) * (2 / 3 - t) * 6
        return p

    return channel(h + 1 / 3), channel(h), channel(h - 1 / 3)


def parse_color(text: str) -> RGBA | None:
    """``(r, g, b, a)`` bytes of the colour ``text``; None when it is no colour."""
    value = text.strip()
    match = _FUNCTION.match(value)
    if match is None:
        return _named_or_hex(value)
    parts = [p for p in _SPLIT.split(match.group(2).strip()) if p]
    if len(parts) not in (3, 4):
        return None
    if match.group(1).lower().startswith("rgb"):
        if len({p.endswith("%") for p in parts[:3]}) > 1:
            return None  # numbers and percentages may not be mixed
        channels = [_value(p, 255.0) for p in parts[:3]]
        alpha = _alpha(parts)
        if any(math.isnan(c) for c in channels) or math.isnan(alpha):
            return None
        return (*(_byte(c) for c in channels), _byte(alpha * 255.0))  # type: ignore[return-value]
    hue = _value(parts[0].removesuffix("deg"), 1.0)
    s, light = (min(max(_value(p, 1.0), 0.0), 1.0) if p.endswith("%") else math.nan for p in parts[1:3])
    alpha = _alpha(parts)
    if any(math.isnan(v) for v in (hue, s, light, alpha)):
        return None
    r, g, b = _hsl(hue, s, light)
    return _byte(r * 255.0), _byte(g * 255.0), _byte(b * 255.0), _byte(alpha * 255.0)


def _named_or_hex(value: str) -> RGBA | None:
    from svgelements import Color as SvgColor

    if value.startswith("#") and len(value) in (4, 5, 7, 9):
        digits = value[1:]
        if all(c in "0123456789abcdefABCDEF" for c in digits):
            if len(digits) <= 4:
                digits = "".join(c * 2 for c in digits)
            channels = [int(digits[k:k + 2], 16) for k in range(0, len(digits), 2)]
            return (channels[0], channels[1], channels[2], channels[3] if len(channels) == 4 else 255)
        return None
    if not value.isalpha():
        return None
    name = value.lower()
    packed = SvgColor.parse_color_lookup(name)  # 0xRRGGBBAA; an unknown name looks up as black
    if packed is None or (packed == 0xFF and name != "black"):
        return None
    return (packed >> 24) & 0xFF, (packed >> 16) & 0xFF, (packed >> 8) & 0xFF, packed & 0xFF
