"""Argument converters and output helpers shared by the commands."""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any, Callable, TypeVar

from ..errors import UsageError, printable
from ..model import METHODS

Number = TypeVar("Number", int, float)

__all__ = ["method", "methods", "size", "fps", "times", "count", "print_json", "print_path", "escaped", "png_target",
           "max_frames_flag", "check_frame_count", "seconds"]


def methods(text: str) -> tuple[str, ...]:
    import difflib

    names = tuple(m.strip() for m in text.split(",") if m.strip())
    for name in names:
        if name not in METHODS:
            close = difflib.get_close_matches(name, METHODS, n=1)
            hint = f" (did you mean {close[0]!r}?)" if close else ""
            raise UsageError(f"unknown method {name!r}{hint}; expected one of {', '.join(METHODS)}")
    if not names:
        raise UsageError("expected at least one method name")
    return names


def method(text: str) -> str:
    """One method name (``--method``), with a "did you mean" for a misspelt one."""
    names = methods(text)
    if len(names) != 1:
        raise UsageError(f"--method: expected one method, found {len(names)} ({text}); "
                         "use --compare for several")
    return names[0]


def size(text: str) -> tuple[int, int]:
    from ..scenefile import LIMITS

    width, x, height = text.lower().partition("x")
    try:
        size = (int(width), int(height))
    except ValueError:
        raise UsageError(f"--size: expected WIDTHxHEIGHT in pixels, e.g. 1920x1080, found {text!r}") from None
    if not x or not all(1 <= s <= LIMITS["canvas"] for s in size):
        raise UsageError(f"--size: expected WIDTHxHEIGHT from 1 to {LIMITS['canvas']} each, found {text!r}")
    return size


def fps(text: str) -> float:
    from ..scenefile import LIMITS

    low, high = LIMITS["fps"]
    return _ranged(float, "a number of frames per second", low, high, "--fps")(text)


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


def curve(text: str) -> str:
    """An easing (``--ease``): a name, ``cubic-bezier(…)`` or ``steps(…)``, checked here, passed on as written."""
    from ..core.easing import parse_easing

    try:
        parse_easing(text)
    except ValueError as error:
        raise UsageError(f"--ease: {error}") from None
    return text


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


def png_target(args: Any, kind: str, what: str) -> Path:
    """``-o`` as a PNG path, or ``output/<scene stem>-<kind>.png``; ``what`` names it in errors."""
    if args.output is None:
        return Path("output") / f"{Path(args.scene).stem}-{kind}.png"
    target = Path(args.output)
    if target.suffix.lower() != ".png":
        raise UsageError(f"-o {target}: {what} is a PNG; give a name ending in .png")
    return target


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


DEFAULT_MAX_FRAMES = 100_000


def max_frames_flag(p: Any) -> None:
    """``--max-frames N``: the guard against renders that would run for days."""
    p.add_argument("--max-frames", type=count(1, 10**12, "--max-frames"), default=DEFAULT_MAX_FRAMES,
                   metavar="N", help=f"refuse to render more frames than this (default {DEFAULT_MAX_FRAMES})")


def check_frame_count(frames: int, limit: int, what: str) -> None:
    """Refuse ``frames`` over ``--max-frames``; ``what`` says whose frames (a scene, the reel)."""
    if frames > limit:
        raise UsageError(f"{what}: {frames} frames is more than --max-frames {limit}; "
                         "raise --max-frames to render it anyway")
