"""SVG's error rules for geometry data: path data and points are drawn up to their first error.

SVG 1.1 (F.2, implementation notes on path data) and SVG 2 (§9.5.4): a renderer draws a path up to
the last complete command before an error in its data; a ``points`` list with an odd count of numbers
or a stray token is read up to its last whole pair before it.
"""

from __future__ import annotations

import re

__all__ = ["path_prefix", "points_prefix", "smooth_controls"]

_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
_SEPARATORS = re.compile(r"[\s,]*")
_SPACE = re.compile(r"\s*")
_ARGUMENTS = {"M": 2, "L": 2, "T": 2, "H": 1, "V": 1, "C": 6, "S": 4, "Q": 4, "A": 7, "Z": 0}


def _numbers(text: str, position: int, count: int, arc: bool) -> tuple[list[str], int] | None:
    """``count`` numbers from ``position`` (an arc's 4th and 5th are the flags ``0``/``1``), each after an
    optional comma-or-space separator, and the position after them; None where the data breaks."""
    values: list[str] = []
    for k in range(count):
        position = (_SEPARATORS if k else _SPACE).match(text, position).end()  # type: ignore[union-attr]
        if k == 0 and position < len(text) and text[position] == ",":
            return None  # a comma may not lead a command's arguments
        if arc and k in (3, 4):
            if position < len(text) and text[position] in "01":
                values.append(text[position])
                position += 1
                continue
            return None
        match = _NUMBER.match(text, position)
        if match is None:
            return None
        values.append(match.group())
        position = match.end()
    return values, position


def path_prefix(data: str) -> tuple[str, bool]:
    """The longest leading part of path data ``data`` SVG draws, rewritten with plain separators, and
    whether all of ``data`` was read. ``""`` when nothing is drawn (no leading moveto)."""
    out: list[str] = []
    position = _SPACE.match(data).end()  # type: ignore[union-attr]
    command = ""
    while True:
        position = _SPACE.match(data, position).end()  # type: ignore[union-attr]
        if position >= len(data):
            return " ".join(out), True
        letter = data[position]
        if letter.upper() in _ARGUMENTS:
            command = letter
            position += 1
            if not out and command not in "Mm":
                return "", False
            if command in "Zz":
                out.append(command)
                continue
        elif not command or command in "Zz":
            return " ".join(out), False  # numbers with no command to repeat
        else:
            position = _SEPARATORS.match(data, position).end()  # type: ignore[union-attr]
        read = _numbers(data, position, _ARGUMENTS[command.upper()], command in "Aa")
        if read is None:
            return " ".join(out), False
        values, position = read
        out.append(command + " " + " ".join(values))
        if command in "Mm":
            command = "L" if command == "M" else "l"  # numbers after a moveto repeat as linetos


def points_prefix(points: str) -> tuple[str, bool]:
    """The whole ``x,y`` pairs a ``points`` list is read as up to its first error, and whether all was read."""
    numbers: list[str] = []
    position = _SPACE.match(points).end()  # type: ignore[union-attr]
    whole = True
    while position < len(points):
        if numbers:
            position = _SEPARATORS.match(points, position).end()  # type: ignore[union-attr]
            if position >= len(points):
                break
        match = _NUMBER.match(points, position)
        if match is None:
            whole = False
            break
        numbers.append(match.group())
        position = _SPACE.match(points, match.end()).end()  # type: ignore[union-attr]
    if len(numbers) % 2:
        numbers, whole = numbers[:-1], False
    return " ".join(f"{numbers[k]},{numbers[k + 1]}" for k in range(0, len(numbers), 2)), whole


def smooth_controls(path):  # type: ignore[no-untyped-def]
    """An svgelements ``Path`` with the first control point of its smooth curves as SVG 1.1 (§8.3.6,
    §8.3.7) defines it: ``S`` reflects the previous segment's second control point only when that segment
    is a cubic, ``T`` the previous control point only when that segment is a quadratic; after anything
    else the control point is the current point (svgelements reflects across kinds: ``T`` after ``S``
    bent the wrong way)."""
    from svgelements import CubicBezier, QuadraticBezier

    previous = None
    for segment in path:
        if getattr(segment, "smooth", False):
            if isinstance(segment, CubicBezier) and not isinstance(previous, CubicBezier):
                segment.control1 = type(segment.start)(segment.start)
            elif isinstance(segment, QuadraticBezier) and not isinstance(previous, QuadraticBezier):
                segment.control = type(segment.start)(segment.start)
        previous = segment
    return path
