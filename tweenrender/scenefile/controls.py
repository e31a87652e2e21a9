"""The animator's controls in a scene file: ``ease``, ``spacing``, ``hints`` and ``stagger``.

Each reader takes the parsed value, its key path and ``fail(where, message)``, which builds the
one-line :class:`~tweenrender.errors.SceneError` naming the file, the key path and what was
expected; the core modules (:mod:`..core.easing`, :mod:`..core.spacing`, :mod:`..core.hints`)
do the work.
"""

from __future__ import annotations

import difflib
import math
import re
from typing import Any, Callable, Sequence

import numpy as np

from ..core.timing.easing import EASING_FORMS, NAMED, Easing, EasingSyntaxError, parse_easing
from ..core.contours import pair_contours
from ..core.correspondence.hints import (SNAP_REACH, HintError, check_links, forced_contour_pairs, insert_hints, segment_links,
                          snap_point)
from ..core.timing.spacing import SpacingError, spacing_chart
from ..errors import SceneError
from ..model import TURNS, Contour, Hint, Key

__all__ = ["read_easing", "read_timing", "read_hints", "read_steering", "check_steering", "pinned", "check_hints",
           "read_stagger", "check_stagger", "check_shape_stagger"]

Fail = Callable[[str, str], SceneError]
_LETTER = re.compile(r"[a-z]")
_NAMES = ("linear", *NAMED, "hold")


def read_easing(value: Any, where: str, fail: Fail) -> Easing:
    """An ``ease`` value: a name, ``cubic-bezier(…)`` or ``steps(…)``."""
    if not isinstance(value, str):
        raise fail(where, f"expected an easing ({', '.join(EASING_FORMS)}), found {type(value).__name__} "
                          f"{value!r}"[:200])
    try:
        return parse_easing(value)
    except EasingSyntaxError as error:
        close = difflib.get_close_matches(value.strip(), _NAMES, n=1, cutoff=0.6)
        hint = f" (did you mean {close[0]!r}?)" if close and "(" not in value else ""
        raise fail(where, f"{error}{hint}") from None


def read_timing(table: dict[str, Any], where: str, fail: Fail, default: tuple[str, Easing]) -> tuple[str, Easing]:
    """A key's timing: ``ease`` or ``spacing`` (never both), else ``default``; as ``(text, easing)``."""
    if "ease" in table and "spacing" in table:
        raise fail(f"{where}.spacing", "expected either ease or spacing on a key, found both")
    if "ease" in table:
        easing = read_easing(table["ease"], f"{where}.ease", fail)
        return easing.text, easing
    if "spacing" in table:
        ticks = table["spacing"]
        if not isinstance(ticks, list) or not all(isinstance(v, (int, float)) and not isinstance(v, bool)
                                                  for v in ticks):
            raise fail(f"{where}.spacing", "expected a list of positions from 0 to 1 (0 first, 1 last, "
                                           "non-decreasing)")
        if len(ticks) > 10_000:
            raise fail(f"{where}.spacing", f"expected at most 10000 positions, found {len(ticks)}")
        try:
            chart = spacing_chart([float(v) for v in ticks])
        except (SpacingError, OverflowError) as error:
            index = getattr(error, "index", None)
            place = f"{where}.spacing" + (f"[{index}]" if index is not None else "")
            raise fail(place, f"{error} in a spacing chart (0 first, 1 last, non-decreasing)") from None
        return "spacing", chart
    return default


def read_hints(value: Any, where: str, fail: Fail, limit: float) -> dict[str, tuple[float, float]]:
    """``hints = { a = [x, y], … }``: letters a–z to points."""
    if not isinstance(value, dict):
        raise fail(where, "expected a table of hints, letters a–z to [x, y] points, e.g. { a = [0, 1] }")
    out = {}
    for letter, point in value.items():
        if not _LETTER.fullmatch(str(letter)):
            raise fail(f"{where}.{letter}", f"expected a hint letter a–z, found {str(letter)[:20]!r}")
        ok = (isinstance(point, list) and len(point) == 2
              and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in point)
              and all(math.isfinite(float(v)) and abs(float(v)) <= limit for v in point))
        if not ok:
            raise fail(f"{where}.{letter}", f"expected an [x, y] point (finite, within ±{limit:g}), "
                                            f"found {point!r}"[:200])
        out[str(letter)] = (float(point[0]), float(point[1]))
    return out


def pinned(contours: Sequence[Contour], hints: dict[str, tuple[float, float]], where: str, fail: Fail,
           scale: float = 1.0) -> tuple[tuple[Contour, ...], tuple[Hint, ...], list[np.ndarray]]:
    """``contours`` with each hint snapped onto them (a vertex inserted where one falls inside an edge),
    the hints on their vertices, and where each contour's old vertices went. ``scale`` converts the
    contours' units to the hints' own, for messages."""
    if not hints:
        return tuple(contours), (), [np.arange(len(c.points)) for c in contours]
    points = [c.points for c in contours]
    closed = [c.closed for c in contours]
    every = np.concatenate(points)
    reach = SNAP_REACH * float(np.hypot(*np.ptp(every, axis=0)))
    snaps = {}
    for letter, point in hints.items():
        snap = snap_point(points, closed, point)
        if snap.distance > reach:
            raise fail(f"{where}.{letter}", f"expected a point within {reach / scale:.6g} of the key's outline "
                                            f"(2 % of its bounding box's diagonal), found one "
                                            f"{snap.distance / scale:.6g} away")
        snaps[letter] = snap
    try:
        new, placed, moved = insert_hints(points, closed, snaps)
    except HintError as error:
        raise fail(f"{where}.{error.letters[-1]}", error.message) from None
    return tuple(Contour(p, c.closed) for p, c in zip(new, contours)), placed, moved


def check_hints(keys: Sequence[Key], where_of: Callable[[int], str], fail: Fail) -> None:
    """Every letter on a key is on the key before or after it (past breakdown keys, which are made from
    the segment they split, hints included), and each segment's letters can all be honoured
    (:func:`..core.hints.check_links`). ``where_of(k)`` is key k's path."""
    def drawn(q: int) -> bool:
        return keys[q].breakdown is None or bool(keys[q].contours)

    for k, key in enumerate(keys):
        for hint in key.hints:
            before = next((keys[q] for q in range(k - 1, -1, -1) if drawn(q)), None)
            after = next((keys[q] for q in range(k + 1, len(keys)) if drawn(q)), None)
            near = [other for other in (before, after) if other is not None]
            if not any(hint.letter in {h.letter for h in other.hints} for other in near):
                raise fail(f"{where_of(k)}.hints.{hint.letter}",
                           f"expected hint {hint.letter} on the key before or after too, found it on neither")
    for k in range(1, len(keys)):
        before, after = keys[k - 1], keys[k]
        links = segment_links(before.hints, after.hints)
        if not links:
            continue
        try:
            check_links([c.points for c in before.contours], [c.closed for c in before.contours],
                        [c.points for c in after.contours], [c.closed for c in after.contours], links)
        except HintError as error:
            raise fail(f"{where_of(k)}.hints.{error.letters[-1]}", error.message) from None


def read_stagger(value: Any, where: str, fail: Fail, what: str = "a stagger") -> float:
    """``stagger`` (or a drawing's ``hold``, ``what``): seconds, from 0."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(float(value)) \
            or not 0.0 <= float(value) <= 1e6:
        raise fail(where, f"expected {what} in seconds from 0, found {value!r}"[:200])
    return float(value)


def check_stagger(stagger: float, elements: int, start: float, end: float, where: str, fail: Fail) -> None:
    """``stagger × (elements − 1)`` must be shorter than the segment from ``start`` to ``end`` seconds."""
    if elements > 1 and stagger * (elements - 1) >= end - start:
        raise fail(where, f"expected stagger × (elements − 1) shorter than the segment ({end - start:g} s), found "
                          f"{stagger:g} × {elements - 1} = {stagger * (elements - 1):g} s")


def check_shape_stagger(keys: Sequence[Key], stagger: float, where: str, where_of: Callable[[int], str],
                        fail: Fail) -> None:
    """A shape's stagger spreads its contours over each segment: it must leave every segment time to move."""
    if stagger <= 0:
        return
    for k in range(1, len(keys)):
        before, after = keys[k - 1], keys[k]
        a, b = before.contours, after.contours
        if len(a) == 1 and len(b) == 1:
            continue
        links = forced_contour_pairs(segment_links(before.hints, after.hints))
        count = len(pair_contours([c.points for c in a], [c.closed for c in a], [c.points for c in b],
                                  [c.closed for c in b], forced=links))
        try:
            check_stagger(stagger, count, before.time + before.delay, after.time, where, fail)
        except SceneError as error:
            raise fail(where, f"{error.message} (the segment from {where_of(k - 1)})") from None


def read_steering(table: dict[str, Any], where: str, fail: Fail, limit: float) -> dict[str, Any]:
    """A key's ``turn``, ``turns``, ``arcs`` and ``breakdown`` (maths §5.13–5.15), as :class:`Key` fields."""
    out: dict[str, Any] = {}
    if "turn" in table:
        if table["turn"] not in TURNS:
            raise fail(f"{where}.turn", f'expected "cw", "ccw" or "shortest", found {table["turn"]!r}'[:200])
        out["turn"] = table["turn"]
    if "turns" in table:
        value = table["turns"]
        if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value <= 1000:
            raise fail(f"{where}.turns",
                       f"expected a whole number of extra turns from 0 to 1000, found {value!r}"[:200])
        out["turns"] = int(value)
    if "arcs" in table:
        if not isinstance(table["arcs"], dict) or not table["arcs"]:
            raise fail(f"{where}.arcs", "expected a table of hint letters to the [x, y] point each passes through "
                                        "halfway, e.g. { a = [0, 1] }")
        points = read_hints(table["arcs"], f"{where}.arcs", fail, limit)
        out["arcs"] = tuple(sorted(points.items()))
    if "breakdown" in table:
        value = table["breakdown"]
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(float(value)) \
                or not -10.0 <= float(value) <= 10.0:
            raise fail(f"{where}.breakdown", f"expected a favour from -10 to 10 (0 the key before, 1 the key "
                                             f"after), found {value!r}"[:200])
        out["breakdown"] = float(value)
    return out


def check_steering(keys: Sequence[Key], method: str, where_of: Callable[[int], str], fail: Fail) -> None:
    """A shape's steering fields make sense where they are: a breakdown between two keys, turns and arcs on
    a key that starts a segment, arcs only on letters both ends of that segment carry, no turn under
    ``linear`` (straight paths have no rigid frame). ``where_of(k)`` is key k's path."""
    for k, key in enumerate(keys):
        here = where_of(k)
        if key.breakdown is not None and (k == 0 or k == len(keys) - 1):
            raise fail(f"{here}.breakdown", "expected a key before and a key after a breakdown, found it "
                                            f"{'first' if k == 0 else 'last'}")
        steered = [name for name, on in (("turn", key.turn is not None), ("turns", key.turns > 0),
                                         ("arcs", bool(key.arcs))) if on]
        if steered and k == len(keys) - 1:
            raise fail(f"{here}.{steered[0]}", f"expected {steered[0]} on a key that starts a segment, found it "
                                               "on the last key")
        for name in steered[:2]:
            if name != "arcs" and method == "linear":
                raise fail(f"{here}.{name}", f'expected no {name} under method "linear" (straight paths have no '
                                             'rigid frame to turn); choose rigid, nonlinear or another method')
        if key.arcs:
            first = max(q for q in range(k + 1) if keys[q].breakdown is None)
            last = next(q for q in range(k + 1, len(keys)) if keys[q].breakdown is None)
            carried = {h.letter for h in keys[first].hints} & {h.letter for h in keys[last].hints}
            either = {h.letter for h in keys[first].hints} | {h.letter for h in keys[last].hints}
            for letter, _ in key.arcs:
                if letter not in carried:
                    found = "one" if letter in either else "neither"
                    raise fail(f"{here}.arcs.{letter}", f"expected hint {letter} on both keys of the segment, "
                                                        f"found it on {found}")
