"""Does a closed outline cross (or touch) itself, and where?

The outline is the polygon with consecutive coincident vertices merged (a
zero-length edge is no edge). It crosses itself when two edges that are not
neighbours share a point — a proper crossing, a vertex touching an edge, or
collinear overlap all count — or when two neighbouring edges fold back onto
each other (a turn of exactly 180°). An outline of fewer than three distinct
vertices has nothing to cross. Orientation tests are exact for coordinates
whose products are exact in float64 (small integers, say), so the tests can
check this against exact arithmetic.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from .geometry import cross

__all__ = ["distinct_outline", "self_crossing", "self_crossings"]

Array = NDArray[np.float64]

_BLOCK = 1 << 18  # edge pairs tested at once, to bound memory on large outlines


def distinct_outline(points: Array) -> Array:
    """``points (N, 2)`` with every vertex equal to the one before it (cyclically) dropped: ``(M, 2)``."""
    points = np.asarray(points, dtype=np.float64)
    if len(points) == 0:
        return points
    keep = np.any(points != np.roll(points, 1, axis=0), axis=1)
    if not keep.any():  # every vertex at one point
        return points[:1]
    return points[keep]


def self_crossing(points: Array) -> Array | None:
    """A point ``(2,)`` where the outline ``(N, 2)`` crosses or touches itself, or None.

    Among several crossings, the one on the lowest-numbered pair of edges is given.
    """
    p = distinct_outline(points)
    n = len(p)
    if n < 3:
        return None
    a, b = p, np.roll(p, -1, axis=0)
    # Neighbouring edges i, i+1 share vertex i+1; they overlap beyond it only when they fold back.
    forward = b - a
    after = np.roll(forward, -1, axis=0)
    folded = (cross(forward, after) == 0.0) & ((forward * after).sum(axis=1) < 0.0)
    best: tuple[int, int, Array] | None = None
    if folded.any():
        i = int(np.flatnonzero(folded)[0])
        best = (i, (i + 1) % n, b[i])
    rows = np.arange(n)
    step = max(1, _BLOCK // n)
    for start in range(0, n, step):
        i, j = np.meshgrid(rows[start:start + step], rows, indexing="ij")
        # each unordered pair once, i < j, neither neighbours (edge 0 and edge n-1 are neighbours)
        pick = (j > i + 1) & ~((i == 0) & (j == n - 1))
        i, j = i[pick], j[pick]
        if len(i) == 0:
            continue
        hit, where = _segments_meet(a[i], b[i], a[j], b[j])
        if hit.any():
            k = int(np.flatnonzero(hit)[0])
            if best is None or (int(i[k]), int(j[k])) < best[:2]:
                best = (int(i[k]), int(j[k]), where[k])
            break  # pairs are in order of i: later blocks hold larger i
    return None if best is None else np.asarray(best[2], dtype=np.float64)


def self_crossings(frames: Array) -> list[Array | None]:
    """:func:`self_crossing` of each outline of ``frames (T, N, 2)``: a list of T points or None."""
    return [self_crossing(frame) for frame in np.asarray(frames, dtype=np.float64)]


def _segments_meet(p1: Array, p2: Array, q1: Array, q2: Array) -> tuple[NDArray[np.bool_], Array]:
    """Whether closed segments ``p1p2`` and ``q1q2`` (each ``(K, 2)``) share a point, and one such point."""
    d1 = cross(q2 - q1, p1 - q1)
    d2 = cross(q2 - q1, p2 - q1)
    d3 = cross(p2 - p1, q1 - p1)
    d4 = cross(p2 - p1, q2 - p1)
    collinear = (d1 == 0.0) & (d2 == 0.0) & (d3 == 0.0) & (d4 == 0.0)
    general = (np.sign(d1) * np.sign(d2) <= 0.0) & (np.sign(d3) * np.sign(d4) <= 0.0) & ~collinear
    low = np.maximum(np.minimum(p1, p2), np.minimum(q1, q2))
    high = np.minimum(np.maximum(p1, p2), np.maximum(q1, q2))
    overlap = collinear & np.all(low <= high, axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(d1 != d2, d1 / (d1 - d2), 0.0)
    where = np.where(general[:, None], p1 + s[:, None] * (p2 - p1), 0.5 * (low + high))
    return general | overlap, where
