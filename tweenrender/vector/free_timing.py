"""One span on a timing free in both handles, for values that keep to one straight line (maths §5.12).

:func:`.keyframes.fit_keyframes` times a span by ``cubic-bezier(1/3, p, 2/3, q)``, whose progress is a cubic
in time. A contour growing with its area linear in t (maths §5.17) is scaled by √t, upright at its start,
which no cubic follows: its keyed scale needed a keyframe every few frames. CSS's cubic-bezier is free in
both handles, and with ``x1 = 0`` it leaves its start upright: ``cubic-bezier(0, 0.436, 0.574, 0.786)``
follows √t to 1.2e-4 of the way. So where every frame's values lie on the straight line between the first
and the last that move (a scale about a point moves the centre with it), the values are one span whose
timing is fitted to their progress along that line, held before and after, and checked at every frame.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..core.memo import Remembered
from ..core.timing.easing import CubicBezier
from ..encode.vector_data import HANDLE_DIGITS, STRAIGHT, Handles

__all__ = ["FreeSpan", "free_span"]

Array = NDArray[np.float64]

_GROWING: Handles = (0.0, 0.436054, 0.573517, 0.785867)
"""A CSS cubic-bezier within 1.2e-4 of √x on [0, 1] (a shape grown with its area linear in time)."""
_SHRINKING: Handles = (1.0 - _GROWING[2], 1.0 - _GROWING[3], 1.0 - _GROWING[0], 1.0 - _GROWING[1])
"""Its mirror, 1 − √(1 − x) (a shape shrunk so)."""
_SEARCH_EVALUATIONS = 800  # timings the search for a span's handles measures, at most
_TABLE = 513  # points of the curve the search reads each timing's progress off (checked exactly after)
_SAME_PROGRESS = 9  # decimals to which two spans' progress agree for one search to serve both
_searched: Remembered[Handles] = Remembered(64)
"""The handles found for each progress searched lately: contours growing on one timing (a clip's pieces, a face's
eyes) have one progress but for rounding, and each span found is still checked at every frame."""


@dataclass(frozen=True)
class FreeSpan:
    """Keyframes of one point: ``frames`` (increasing, from 0 to F − 1), their ``values (K, D)`` and each span's CSS
    cubic-bezier ``eases`` (K − 1)."""

    frames: tuple[int, ...]
    values: Array
    eases: tuple[Handles, ...]


def free_span(values: Array, tolerance: float) -> FreeSpan | None:
    """``values (F, D)`` (one point's D coordinates at each frame) as a held start, one span and a held end: the
    frames before the first that moves and after the last keep their values, and between them the values go
    straight from one to the other on a CSS cubic-bezier fitted to their progress (the first or last step of the
    move may be a straight span of its own: a shape that starts growing between two frames). None where some
    value leaves that straight line, or no timing found keeps every frame within ``tolerance`` (Euclidean over
    D), or nothing would be saved (fewer than three frames move)."""
    values = np.asarray(values, dtype=np.float64)
    count = len(values)
    if count < 3 or not np.all(np.isfinite(values)):
        return None
    moves = np.flatnonzero(np.any(values[1:] != values[:-1], axis=1))  # frame k → k + 1 changes
    if len(moves) == 0:
        return None
    first, last = int(moves[0]), int(moves[-1]) + 1
    if last - first < 3:
        return None
    for low, high in ((first, last), (first + 1, last), (first, last - 1), (first + 1, last - 1)):
        if high - low < 3:
            continue
        handles = _fitted(values[low:high + 1], tolerance)
        if handles is not None:  # a step at either end (a shape that starts growing between frames) goes straight
            frames = tuple(sorted({0, first, low, high, last, count - 1}))
            eases = tuple(handles if (a, b) == (low, high) else STRAIGHT for a, b in zip(frames, frames[1:]))
            return FreeSpan(frames, values[list(frames)], eases)
    return None


def _fitted(inside: Array, tolerance: float) -> Handles | None:
    """The handles of one span from the first of ``inside (n, D)`` to the last that plays every frame within
    ``tolerance`` (replayed as CSS's cubic-bezier, :class:`~tweenrender.core.timing.easing.CubicBezier`), or None:
    the values leave the straight line between them, or no timing found does."""
    start, end = inside[0], inside[-1]
    chord = end - start
    length = float(np.linalg.norm(chord))
    if length == 0.0:
        return None
    progress = (inside - start) @ chord / (length * length)  # (n,)
    x = np.arange(len(inside)) / (len(inside) - 1)

    def miss(handles: Handles) -> float:  # as a player plays the span (the curve solved at each frame's time)
        played = start + CubicBezier(*handles)(x)[:, None] * chord
        return float(np.linalg.norm(played - inside, axis=1).max())

    if float(np.linalg.norm(inside - (start + progress[:, None] * chord), axis=1).max()) > tolerance:
        return None
    handles = _search(x, progress)
    return handles if miss(handles) <= tolerance else None


def _search(x: Array, progress: Array) -> Handles:
    """The handles, to :data:`HANDLE_DIGITS` decimals, that miss the frames by least: from √t's (or its mirror's,
    for a progress that starts slowly), refined by Nelder and Mead's search within a bounded number of timings;
    searched once for a progress that agrees with one searched lately to :data:`_SAME_PROGRESS` decimals."""
    key = np.round(progress, _SAME_PROGRESS).tobytes()  # x is the frames' times: fixed by the progress's length
    return _searched.get(key, lambda: _searched_handles(x, progress))


def _searched_handles(x: Array, progress: Array) -> Handles:
    from scipy.optimize import minimize

    growing = float(np.mean(progress - x)) >= 0.0
    begin = _GROWING if growing else _SHRINKING
    u = np.linspace(0.0, 1.0, _TABLE)[:, None]
    basis = np.hstack([3.0 * (1.0 - u) ** 2 * u, 3.0 * (1.0 - u) * u * u])  # (T, 2): the curve at u, less u³
    cube = u[:, 0] ** 3

    def cost(h: Array) -> float:  # the progress's largest miss, the curve read off a table (the search only)
        if h[0] < 0.0 or h[0] > 1.0 or h[2] < 0.0 or h[2] > 1.0:
            return np.inf
        xs = basis @ h[[0, 2]] + cube
        ys = basis @ h[[1, 3]] + cube
        return float(np.abs(np.interp(x, xs, ys) - progress).max())

    found = minimize(cost, np.array(begin), method="Nelder-Mead",
                     options={"maxfev": _SEARCH_EVALUATIONS, "xatol": 1e-6, "fatol": 1e-7,
                              "initial_simplex": np.array(begin) + np.vstack([np.zeros(4), 0.05 * np.eye(4)])
                              * np.where(np.array(begin) > 0.5, -1.0, 1.0)})
    best = found.x if np.isfinite(found.fun) else np.array(begin)
    best = np.round(best, HANDLE_DIGITS) + 0.0
    best[[0, 2]] = np.clip(best[[0, 2]], 0.0, 1.0)
    return (float(best[0]), float(best[1]), float(best[2]), float(best[3]))
