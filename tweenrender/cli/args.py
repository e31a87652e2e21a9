"""Argument converters and output helpers shared by the commands."""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any, Callable, TypeVar

from ..errors import UsageError, printable

Number = TypeVar("Number", int, float)

__all__ = ["method", "methods", "size", "fps", "times", "count", "print_json", "print_path", "escaped",
           "max_frames_flag", "seconds"]


def methods(text: str) -> tuple[str, ...]:
    """Comma-separated method names (the library checks each against the method registry)."""
    names = tuple(m.strip() for m in text.split(",") if m.strip())
    if not names:
        raise UsageError("expected at least one method name")
    return names


def method(text: str) -> str:
    """One method name (``--method``)."""
    names = methods(text)
    if len(names) != 1:
        raise UsageError(f"--method: expected one method, found {len(names)} ({text}); "
                         "use --compare for several")
    return names[0]


def size(text: str) -> tuple[int, int]:
    """``WIDTHxHEIGHT`` as two whole numbers (the library checks their range)."""
    width, x, height = text.lower().partition("x")
    try:
        if not x:
            raise ValueError
        return int(width), int(height)
    except ValueError:
        raise UsageError(f"--size: expected WIDTHxHEIGHT in pixels, e.g. 1920x1080, found {text!r}") from None


def fps(text: str) -> float:
    """A number of frames per second (the library checks its range)."""
    try:
        return float(text)
    except ValueError:
        raise UsageError(f"--fps: expected a number of frames per second, found {text!r}") from None


def seconds(text: str) -> float:
    """A positive, finite number of seconds (``--step``)."""
    import math

    try:
        value = float(text)
    except ValueError:
        raise UsageError(f"--step: expected seconds as a number, found {text!r}") from None
    if not (math.isfinite(value) and 0 < value <= 1e6):
        raise UsageError(f"--step: expected seconds above 0 and at most 1000000, found {text}")
    return value


def pause(flag: str) -> Callable[[str], float]:
    """Seconds from 0 (``--hold``, ``--stagger``)."""
    return _ranged(float, "seconds as a number", 0.0, 1e6, flag)


def times(text: str) -> list[float]:
    try:
        values = [float(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise UsageError(f"--t: expected comma-separated numbers in [0, 1], found {text!r}") from None
    if not values or not all(0.0 <= v <= 1.0 for v in values):
        raise UsageError(f"--t: expected comma-separated numbers in [0, 1], found {text!r}")
    return values


def print_json(data: Any) -> None:
    json.dump(data, sys.stdout, indent=2)  # ASCII: names with control characters come out as \u escapes
    sys.stdout.write("\n")


def print_path(path: Any) -> None:
    """Print the path written, escaped like any text from outside (see :func:`~tweenrender.errors.printable`)."""
    print(printable(str(path)))


def escaped(report: Any) -> Any:
    """A copy of a report (dicts, lists, numbers, text) with every text made printable, for the text reports."""
    if isinstance(report, str):
        return printable(report)
    if isinstance(report, dict):
        return {escaped(key): escaped(value) for key, value in report.items()}
    if isinstance(report, (list, tuple)):
        return type(report)(escaped(value) for value in report)
    return report


def count(low: int, high: int, flag: str) -> Callable[[str], int]:
    """An argparse converter for a whole number from ``low`` to ``high``."""
    return _ranged(int, "a whole number", low, high, flag)


def _plain(number: float) -> str:
    """``240`` rather than ``240.0``, and ``1000000000000`` rather than ``1e+12``."""
    return str(int(number)) if float(number).is_integer() else f"{number:g}"


def _ranged(parse: Callable[[str], Number], what: str, low: float, high: float,
            flag: str) -> Callable[[str], Number]:
    """A converter: ``parse(text)``, refused unless it lies from ``low`` to ``high``."""

    def convert(text: str) -> Number:
        try:
            value = parse(text)
        except ValueError:
            raise UsageError(f"{flag}: expected {what}, found {text!r}") from None
        if not low <= value <= high:
            raise UsageError(f"{flag}: expected {_plain(low)} to {_plain(high)}, found {text}")
        return value

    return convert


def max_frames_flag(p: Any) -> None:
    """``--max-frames N``: the guard against renders that would run for days (the library holds to it)."""
    from ..api import DEFAULT_MAX_FRAMES

    p.add_argument("--max-frames", type=int, default=DEFAULT_MAX_FRAMES, metavar="N",
                   help=f"refuse to render more frames than this (default {DEFAULT_MAX_FRAMES})")
