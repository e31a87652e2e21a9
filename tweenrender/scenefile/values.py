"""Typed readers of a parsed scene document's values: each refuses what it does not expect with an error
that names the file, the key path (and, for TOML, its line), what was expected and what was found."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any, Callable

from ..errors import SceneError, did_you_mean
from ..model import Color
from .locate import json_line_of, line_of

__all__ = ["ValueReader", "short", "describe", "parse_color"]


def short(value: Any) -> str:
    """A repr short enough for a one-line message (huge integers included)."""
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) > 10**30:
        return f"an integer of {len(str(abs(value))) if abs(value).bit_length() < 14000 else 'over 4000'} digits"
    shown = repr(value)
    return shown if len(shown) <= 40 else shown[:37] + "..."


def describe(value: Any) -> str:
    """How a found value reads in a message: its kind and a short repr."""
    kinds = {bool: "a boolean", int: "a number", float: "a number", str: "a string", type(None): "null"}
    if isinstance(value, dict):
        return f"a table of {len(value)} key{'s' * (len(value) != 1)}"
    if isinstance(value, list):
        if value and all(isinstance(v, dict) for v in value):
            return f"an array of {len(value)} table{'s' * (len(value) != 1)}"
        return f"a list of {len(value)} item{'s' * (len(value) != 1)}"
    kind = kinds.get(type(value), type(value).__name__)
    return f"{kind} {short(value)}"


class ValueReader:
    """Reads the values of one parsed document (``fmt`` ``"toml"`` or ``"json"``); knows where it came from,
    for messages."""

    def __init__(self, path: Path, text: str, fmt: str) -> None:
        self.path = path
        self.text = text
        self.locate = json_line_of if fmt == "json" else line_of

    def fail(self, where: str, message: str) -> SceneError:
        line = self.locate(self.text, where) if where else None
        place = f"{where} (line {line})" if line else where
        return SceneError(self.path, place or None, message)

    def table(self, value: Any, where: str, allowed: tuple[str, ...]) -> dict[str, Any]:
        if not isinstance(value, dict):
            raise self.fail(where, f"expected a table, found {describe(value)}")
        for key in value:
            if key not in allowed:
                at = f"{where}.{key}" if where else str(key)
                raise self.fail(at, f"unknown key {short(key)}{did_you_mean(str(key), allowed)}; "
                                    f"expected one of {', '.join(allowed)}")
        return value

    def number(self, value: Any, where: str, low: float = -math.inf, high: float = math.inf,
               what: str = "a number") -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.fail(where, f"expected {what}, found {describe(value)}")
        try:
            number = float(value)
        except OverflowError:  # an integer beyond float range
            number = math.inf
        if not math.isfinite(number):
            raise self.fail(where, f"expected {what} (finite), found {short(value)}")
        if not low <= number <= high:
            raise self.fail(where, f"expected {what} from {low:g} to {high:g}, found {short(value)}")
        return number

    def integer(self, value: Any, where: str, low: int, high: int, what: str) -> int:
        if isinstance(value, bool) or not isinstance(value, int):
            if isinstance(value, float) and value.is_integer():
                value = int(value)
            else:
                raise self.fail(where, f"expected {what}, found {describe(value)}")
        if not low <= value <= high:
            raise self.fail(where, f"expected {what} from {low} to {high}, found {short(value)}")
        return value

    def string(self, value: Any, where: str) -> str:
        if not isinstance(value, str):
            raise self.fail(where, f"expected a string, found {describe(value)}")
        return value

    def choice(self, value: Any, where: str, choices: tuple[str, ...], what: str) -> str:
        word = self.string(value, where)
        if word not in choices:
            raise self.fail(where, f"unknown {what} {short(word)}{did_you_mean(word, choices)}; "
                                   f"expected one of {', '.join(choices)}")
        return word

    def listing(self, value: Any, where: str, what: str) -> list[Any]:
        if not isinstance(value, list):
            raise self.fail(where, f"expected {what}, found {describe(value)}")
        return value

    def color(self, value: Any, where: str) -> Color:
        return parse_color(self.string(value, where), lambda msg: self.fail(where, msg))

    def boolean(self, value: Any, where: str) -> bool:
        if not isinstance(value, bool):
            raise self.fail(where, f"expected true or false, found {describe(value)}")
        return value

    def color_or_none(self, value: Any, where: str) -> Color | None:
        if isinstance(value, str) and value.strip().lower() == "none":
            return None
        return self.color(value, where)


def parse_color(text: str, fail: Callable[[str], Exception]) -> Color:
    """``#rgb``, ``#rgba``, ``#rrggbb`` or ``#rrggbbaa`` → straight RGBA 0..255."""
    digits = text[1:] if text.startswith("#") else None
    if digits is None or len(digits) not in (3, 4, 6, 8) or any(c not in "0123456789abcdefABCDEF" for c in digits):
        raise fail(f"expected a colour #rgb, #rgba, #rrggbb or #rrggbbaa, found {short(text)}")
    if len(digits) in (3, 4):
        digits = "".join(c * 2 for c in digits)
    if len(digits) == 6:
        digits += "ff"
    r, g, b, a = (int(digits[i:i + 2], 16) for i in range(0, 8, 2))
    return (r, g, b, a)
