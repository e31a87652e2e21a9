"""Spread balancing (maths §5.6): copies of a vertex spread along its edges instead of stacked.

Balancing (maths §2) pairs a vertex of one key with ``k > 1`` vertices of the
other and makes ``k`` copies of it at one point (the thesis's rule, ``copies``).
*Spread* moves those copies along the key's own outline — onto the halves of the
two edges that meet at the vertex — at the arc-length proportions of the ``k``
vertices of the other key they pair with. One copy, the one whose proportion
falls nearest the vertex, stays on it exactly, so the key's outline (the
polygon as drawn) is unchanged; only its vertices are spread, and no edge is
left with zero length.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from numpy.typing import NDArray

__all__ = ["spread", "spread_copies", "coincident_runs"]

Array = NDArray[np.float64]

_MARGIN = 0.05  # proportions are kept within [margin, 1 - margin] of the run's stretch of outline


def coincident_runs(points: Array) -> list[tuple[int, int]]:
    """Maximal runs of consecutive equal vertices of a closed polygon ``(N, 2)``: ``(start, length)``
    pairs with ``length ≥ 2``; a run may wrap past the last vertex. None when every vertex is equal."""
    points = np.asarray(points)
    n = len(points)
    same = np.all(points == np.roll(points, 1, axis=0), axis=1)  # same[i]: vertex i equals vertex i-1
    if n == 0 or same.all():
        return []
    starts = np.flatnonzero(~same)
    runs = []
    for k, start in enumerate(starts):
        end = starts[(k + 1) % len(starts)]
        length = (end - start) % n or n
        if length >= 2:
            runs.append((int(start), int(length)))
    return runs


def spread(k0: Array, k1: Array, fixed: Sequence[int] = ()) -> tuple[Array, Array]:
    """Balanced keys ``(L, 2)`` with each run of copies spread along its key's outline: two new arrays.

    Runs are found by position (consecutive equal vertices), so keys whose
    repeated vertices were drawn that way are spread too. A key whose
    vertices all coincide is returned as it is. The copies at the indices
    ``fixed`` (hinted vertices) stay on their vertex in both keys.
    """
    k0 = np.array(k0, dtype=np.float64)
    k1 = np.array(k1, dtype=np.float64)
    return _spread_one(k0, k1, fixed), _spread_one(k1, k0, fixed)


def spread_copies(k0: Array, k1: Array, fixed: Sequence[int] = ()) -> tuple[Array, Array]:
    """:func:`spread` where either closed key ``(L, 2)`` has copies of a vertex; else the keys as they are."""
    if coincident_runs(k0) or coincident_runs(k1):
        return spread(k0, k1, fixed)
    return k0, k1


def _spread_one(key: Array, other: Array, fixed: Sequence[int] = ()) -> Array:
    out = key.copy()
    n = len(key)
    for start, length in coincident_runs(key):
        index = (start + np.arange(-1, length + 1)) % n  # the run with one neighbour each side
        corner = key[start]
        before = 0.5 * (key[index[0]] + corner)
        after = 0.5 * (corner + key[index[-1]])
        # where the run's copies go: the half-edge before the vertex, then the half-edge after it
        # lengths by hypot: a norm's squares underflow to zero on edges under about 1e-154
        first, second = float(np.hypot(*(corner - before))), float(np.hypot(*(after - corner)))
        # the other key's stretch: half its edge in, its run of vertices, half its edge out
        stretch = other[index].copy()
        stretch[0] = 0.5 * (other[index[0]] + other[index[1]])
        stretch[-1] = 0.5 * (other[index[-2]] + other[index[-1]])
        steps = np.hypot(*np.diff(stretch, axis=0).T)
        total = float(steps.sum())
        if total > 0:
            share = np.cumsum(steps)[:-1] / total  # (length,) proportions of the run's vertices
        else:
            share = np.arange(1, length + 1) / (length + 1)
        share = _MARGIN + (1.0 - 2.0 * _MARGIN) * share
        place = share * (first + second)
        stay = int(np.argmin(np.abs(place - first)))
        pinned = [k for k in range(length) if int(index[k + 1]) in fixed]
        if pinned:  # a hinted copy stays (one per run at most: hints sit on distinct vertices); the copies
            stay = pinned[0]  # before it go on the half-edge before the vertex, those after it after
            k = np.arange(length)
            place = np.where(k < stay, first * (k + 1) / (stay + 1),
                             first + second * (k - stay) / max(length - stay, 1))
        for k, at in enumerate(place):
            slot = index[k + 1]
            if k == stay:
                out[slot] = corner
            elif at < first:
                out[slot] = before + (corner - before) * (at / first)
            elif second > 0:
                out[slot] = corner + (after - corner) * ((at - first) / second)
            else:  # both half-edges of zero length (a key drawn at one point): the copy stays too
                out[slot] = corner
    return out
