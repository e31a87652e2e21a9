"""Timing curves of a segment (maths §5.11): how far along the way it is at each fraction of its time.

An easing maps the time fraction ``u`` in [0, 1] of a segment to the fraction of the way
``t``; every easing gives ``t = 0`` at ``u = 0`` and ``t = 1`` at ``u = 1``, so a key's own
time always shows the key (``steps`` and ``hold`` act strictly between keys). Between the
keys ``t`` may leave [0, 1] (a ``cubic-bezier`` with ``y`` outside it overshoots).

* ``linear``, and the older ``in`` (u²), ``out`` and ``in-out`` (smoothstep), which are exact
  cubic Béziers (1/3, 0, 2/3, 1/3), (1/3, 2/3, 2/3, 1), (1/3, 0, 2/3, 1) — evaluated by their
  polynomials, so their values are what they always were;
* CSS's ``ease``, ``ease-in``, ``ease-out``, ``ease-in-out`` and ``cubic-bezier(x1, y1, x2, y2)``
  (x1, x2 in [0, 1], y free): ``t = y(s)`` where ``x(s) = u``, solved by Newton's method with a
  bisection fallback, as browsers do, to 1e-12 in s;
* ``steps(n)`` / ``steps(n, jump-start | jump-end | jump-none | jump-both)`` (also ``start``,
  ``end``) as CSS Easing Level 1;
* ``hold``: the key stays until the next key's time.

A spacing chart (:mod:`.spacing`) is an easing too. Every easing is a small frozen object whose
``text`` is how a scene writes it; a Bézier keeps its ``handles`` for the exporters.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Callable, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .spacing import Spacing

__all__ = ["Easing", "CubicBezier", "Steps", "Hold", "Linear", "EasingSyntaxError", "parse_easing", "LINEAR",
           "NAMED", "JUMPS", "EASING_FORMS"]

Array = NDArray[np.float64]


class EasingSyntaxError(ValueError):
    """Text that is not an easing; the message says what was expected (the caller adds where)."""


@dataclass(frozen=True, slots=True)
class Linear:
    """``t = u``."""

    text: str = "linear"

    def __call__(self, u: ArrayLike) -> Array:
        """Eased fractions of ``u (T,)`` in [0, 1]: ``(T,)``."""
        return _times(u).copy()

    @property
    def overshoots(self) -> bool:
        return False


@dataclass(frozen=True, slots=True)
class CubicBezier:
    """CSS ``cubic-bezier(x1, y1, x2, y2)``: the curve from (0, 0) to (1, 1) with these two handles."""

    x1: float
    y1: float
    x2: float
    y2: float
    text: str = ""

    @property
    def handles(self) -> tuple[float, float, float, float]:
        return (self.x1, self.y1, self.x2, self.y2)

    @property
    def overshoots(self) -> bool:
        """Whether ``t`` can leave [0, 1] (a handle's y outside it)."""
        return not (0.0 <= self.y1 <= 1.0 and 0.0 <= self.y2 <= 1.0)

    def __call__(self, u: ArrayLike) -> Array:
        """Eased fractions ``y(s)`` where ``x(s) = u``, for ``u (T,)`` in [0, 1]: ``(T,)``."""
        u = _times(u)
        exact = _POLYNOMIALS.get(self.handles)
        if exact is not None:
            return np.asarray(exact(u), dtype=np.float64)
        s = self.solve(u)
        out = _bezier(s, self.y1, self.y2)
        out[u == 0.0] = 0.0
        out[u == 1.0] = 1.0
        return out

    def solve(self, u: Array) -> Array:
        """The curve parameter ``s (T,)`` where ``x(s) = u (T,)``."""
        u = np.clip(u, 0.0, 1.0)
        s = u.copy()
        for _ in range(8):  # Newton from s = u: converges in a few steps away from flat spots of x
            error = _bezier(s, self.x1, self.x2) - u
            slope = _slope(s, self.x1, self.x2)
            steep = np.abs(slope) > 1e-6
            s = np.where(steep, s - error / np.where(steep, slope, 1.0), s)
        s = np.clip(s, 0.0, 1.0)
        left = np.abs(_bezier(s, self.x1, self.x2) - u) > 1e-13
        if left.any():  # bisection where Newton did not settle (x is non-decreasing: x1, x2 in [0, 1])
            target = u[left]
            low, high = np.zeros_like(target), np.ones_like(target)
            for _ in range(60):
                mid = 0.5 * (low + high)
                below = _bezier(mid, self.x1, self.x2) < target
                low, high = np.where(below, mid, low), np.where(below, high, mid)
            s[left] = 0.5 * (low + high)
        return s


@dataclass(frozen=True, slots=True)
class Steps:
    """CSS ``steps(n, jump)``, except that ``u = 0`` and ``u = 1`` give 0 and 1 (the keys)."""

    count: int
    jump: str = "jump-end"
    text: str = ""

    @property
    def overshoots(self) -> bool:
        return False

    def __call__(self, u: ArrayLike) -> Array:
        """CSS Easing Level 1: step = ⌊u·n⌋ (+1 for jump-start, jump-both), at most the jumps,
        divided by the jumps (n; n − 1 for jump-none; n + 1 for jump-both): ``(T,)`` for ``u (T,)``."""
        u = _times(u)
        jumps = {"jump-start": self.count, "jump-end": self.count, "jump-none": self.count - 1,
                 "jump-both": self.count + 1}[self.jump]
        step = np.floor(u * self.count)
        if self.jump in ("jump-start", "jump-both"):
            step += 1.0
        out = np.minimum(step, jumps) / jumps
        out[u <= 0.0] = 0.0
        out[u >= 1.0] = 1.0
        return out


@dataclass(frozen=True, slots=True)
class Hold:
    """The first key until the next key's time: 0 for every u < 1."""

    text: str = "hold"

    @property
    def overshoots(self) -> bool:
        return False

    def __call__(self, u: ArrayLike) -> Array:
        u = _times(u)
        return np.where(u >= 1.0, 1.0, 0.0)


Easing = Union[Linear, CubicBezier, Steps, Hold, Spacing]

LINEAR = Linear()
NAMED: dict[str, tuple[float, float, float, float]] = {
    "in": (1 / 3, 0.0, 2 / 3, 1 / 3),  # x(s) = s, y(s) = s²
    "out": (1 / 3, 2 / 3, 2 / 3, 1.0),  # y(s) = 1 - (1 - s)²
    "in-out": (1 / 3, 0.0, 2 / 3, 1.0),  # y(s) = 3s² - 2s³
    "ease": (0.25, 0.1, 0.25, 1.0),
    "ease-in": (0.42, 0.0, 1.0, 1.0),
    "ease-out": (0.0, 0.0, 0.58, 1.0),
    "ease-in-out": (0.42, 0.0, 0.58, 1.0),
}
"""Named easings that are cubic Béziers, by their handles ``(x1, y1, x2, y2)``: the older names ``in``,
``out``, ``in-out`` and CSS's four keywords (``linear`` is :data:`LINEAR`). The one table of easing
names and numbers: the scene files, the command line and the vector files' timing all read it."""
_POLYNOMIALS: dict[tuple[float, float, float, float], Callable[[Array], Array]] = {
    # the older names: exact cubic Béziers whose x(s) = s, evaluated as they always were
    NAMED["in"]: lambda u: u * u,
    NAMED["out"]: lambda u: 1.0 - (1.0 - u) ** 2,
    NAMED["in-out"]: lambda u: u * u * (3.0 - 2.0 * u),
}
JUMPS = ("jump-start", "jump-end", "jump-none", "jump-both")
_JUMP_ALIASES = {"start": "jump-start", "end": "jump-end"}
EASING_FORMS = ("linear", *NAMED, "hold", "cubic-bezier(x1, y1, x2, y2)", "steps(n[, jump])")
"""What an ``ease`` may say, as error messages list it."""

_NUMBER = r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*"
_BEZIER = re.compile(r"cubic-bezier\(" + ",".join([_NUMBER] * 4) + r"\)")
_STEPS = re.compile(r"steps\(\s*([-+]?\d+)\s*(?:,\s*([a-z-]+)\s*)?\)")


def parse_easing(text: str) -> Easing:
    """The easing ``text`` names; :class:`EasingSyntaxError` saying what was expected otherwise."""
    word = text.strip()
    if word == "linear":
        return LINEAR
    if word == "hold":
        return Hold()
    if word in NAMED:
        return CubicBezier(*NAMED[word], text=word)
    if word.startswith("cubic-bezier"):
        found = _BEZIER.fullmatch(word)
        if not found:
            raise EasingSyntaxError(f"expected cubic-bezier(x1, y1, x2, y2) with four numbers, found {text!r}")
        x1, y1, x2, y2 = (float(v) for v in found.groups())
        if not all(math.isfinite(v) for v in (x1, y1, x2, y2)):
            raise EasingSyntaxError(f"expected finite numbers in cubic-bezier, found {text!r}")
        if not (0.0 <= x1 <= 1.0 and 0.0 <= x2 <= 1.0):
            raise EasingSyntaxError(f"expected x1 and x2 from 0 to 1 in cubic-bezier(x1, y1, x2, y2), found {text!r}")
        if max(abs(y1), abs(y2)) > 1e3:
            raise EasingSyntaxError(f"expected y1 and y2 from -1000 to 1000 in cubic-bezier, found {text!r}")
        return CubicBezier(x1, y1, x2, y2, text=word)
    if word.startswith("steps"):
        found = _STEPS.fullmatch(word)
        if not found:
            raise EasingSyntaxError(f"expected steps(n) or steps(n, {' | '.join(JUMPS)}), found {text!r}")
        written, jump = found.group(1), found.group(2) or "jump-end"
        digits = len(written.lstrip("+-").lstrip("0"))
        # past 4300 digits int() itself refuses, in Python's words: a count that long is just too large
        count = int(written) if digits <= 9 else (-1 if written.startswith("-") else 10**10)
        shown = written if digits <= 9 else f"a number of {digits} digits"
        jump = _JUMP_ALIASES.get(jump, jump)
        if jump not in JUMPS:
            raise EasingSyntaxError(f"expected a jump of {', '.join(JUMPS)} in steps(n, jump), "
                                    f"found {found.group(2)!r}")
        least = 2 if jump == "jump-none" else 1
        if not least <= count <= 10_000:
            raise EasingSyntaxError(f"expected n from {least} to 10000 in steps(n{', jump-none' * (least == 2)}), "
                                    f"found {shown}")
        return Steps(count, jump, text=word)
    raise EasingSyntaxError(f"unknown easing {text!r}; expected one of {', '.join(EASING_FORMS)}")


def _times(u: ArrayLike) -> Array:
    return np.atleast_1d(np.asarray(u, dtype=np.float64))


def _bezier(s: Array, p1: float, p2: float) -> Array:
    """One coordinate of the cubic from 0 to 1 with inner control values ``p1``, ``p2``, at ``s (T,)``."""
    r = 1.0 - s
    return 3.0 * r * r * s * p1 + 3.0 * r * s * s * p2 + s * s * s


def _slope(s: Array, p1: float, p2: float) -> Array:
    r = 1.0 - s
    return 3.0 * r * r * p1 + 6.0 * r * s * (p2 - p1) + 3.0 * s * s * (1.0 - p2)
