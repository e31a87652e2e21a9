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

import hashlib
import sys
from collections import OrderedDict

import numpy as np
from numpy.typing import NDArray

from .geometry import cross

__all__ = ["distinct_outline", "self_crossing", "self_crossings"]

Array = NDArray[np.float64]

_REMEMBERED = 256  # outlines' sweeps whose crossings are kept
_found: OrderedDict[bytes, list[Array | None]] = OrderedDict()
_BLOCK = 1 << 18  # edge pairs tested at once in numpy, to bound memory on large outlines
_ROWS = 64  # edges tested at once against every later one: blocks narrow as the triangle of pairs does
_NUMPY_PAIRS = 20_000_000  # pairs of edges a process tests in numpy (~0.3 s) before it loads the compiled loop
_numpy_pairs = 0


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
    first = _first_meeting(a, b)
    if first is not None and (best is None or first < best[:2]):
        i, j = first
        _, where = _segments_meet(a[i:i + 1], b[i:i + 1], a[j:j + 1], b[j:j + 1])
        best = (i, j, where[0])
    return None if best is None else np.asarray(best[2], dtype=np.float64)


def self_crossings(frames: Array) -> list[Array | None]:
    """:func:`self_crossing` of each outline of ``frames (T, N, 2)``: a list of T points or None (remembered
    for the last few asked about: a report's table and its charts measure the same inbetweens)."""
    frames = np.ascontiguousarray(frames, dtype=np.float64)
    key = hashlib.blake2b(repr(frames.shape).encode() + frames.tobytes(), digest_size=20).digest()
    found = _found.get(key)
    if found is None:
        found = [self_crossing(frame) for frame in frames]
        for point in found:
            if point is not None:
                point.flags.writeable = False  # shared by every caller
        _found[key] = found
        while len(_found) > _REMEMBERED:
            _found.popitem(last=False)
    else:
        _found.move_to_end(key)
    return list(found)


def _first_meeting(a: Array, b: Array) -> tuple[int, int] | None:
    """The lowest-numbered pair ``(i, j)``, ``i < j``, of edges ``a → b`` (``(N, 2)`` each, an outline's)
    that are not neighbours and that :func:`_segments_meet` says share a point, or None.

    The same test, term for term (each cross product of the same differences, so the same rounding), made
    pair by pair in a compiled loop that stops at the first pair that meets; while numba is not loaded
    (it costs about half a second to load), outlines are tested in numpy until :data:`_NUMPY_PAIRS` pairs
    of edges have been, the same answers.
    """
    global _numpy_pairs
    n = len(a)
    pairs = n * n // 2
    if "numba" not in sys.modules and _numpy_pairs + pairs <= _NUMPY_PAIRS:
        _numpy_pairs += pairs
        return _first_meeting_numpy(a, b)
    from ._crossing_kernel import first_meeting

    i, j = first_meeting(np.ascontiguousarray(a[:, 0]), np.ascontiguousarray(a[:, 1]),
                         np.ascontiguousarray(b[:, 0]), np.ascontiguousarray(b[:, 1]))
    return None if i < 0 else (int(i), int(j))


def _first_meeting_numpy(a: Array, b: Array) -> tuple[int, int] | None:
    """:func:`_first_meeting` in numpy, for small outlines while numba is not loaded.

    The same test, term for term (each cross product of the same differences, so the same rounding), made
    on rows of edges against every later edge at once: first whether the ends of edge i lie on both sides
    of edge j's line (or on it), by broadcasting; then, for the pairs that do, the other half of the test.
    """
    n = len(a)
    ax, ay, bx, by = a[:, 0], a[:, 1], b[:, 0], b[:, 1]
    ex, ey = bx - ax, by - ay  # each edge's vector: q2 - q1 (and p2 - p1) of every pair
    rows = max(1, min(_ROWS, _BLOCK // n))
    for start in range(0, n - 2, rows):
        stop = min(start + rows, n - 2)
        first = start + 2  # the lowest j a row of this block pairs with (j > i + 1)
        qx, qy, qex, qey = ax[None, first:], ay[None, first:], ex[None, first:], ey[None, first:]
        d1 = qex * (ay[start:stop, None] - qy) - qey * (ax[start:stop, None] - qx)  # cross(q2 - q1, p1 - q1)
        d2 = qex * (by[start:stop, None] - qy) - qey * (bx[start:stop, None] - qx)  # cross(q2 - q1, p2 - q1)
        straddle = np.sign(d1) * np.sign(d2) <= 0.0
        i = np.arange(start, stop)[:, None]
        j = np.arange(first, n)[None, :]
        straddle &= (j > i + 1) & ~((i == 0) & (j == n - 1))
        r, c = np.nonzero(straddle)  # row-major: in order of (i, j)
        if len(r) == 0:
            continue
        pi, qj = r + start, c + first
        d3 = _cross(ex[pi], ey[pi], ax[qj] - ax[pi], ay[qj] - ay[pi])  # cross(p2 - p1, q1 - p1)
        d4 = _cross(ex[pi], ey[pi], bx[qj] - ax[pi], by[qj] - ay[pi])  # cross(p2 - p1, q2 - p1)
        d1, d2 = d1[r, c], d2[r, c]
        collinear = (d1 == 0.0) & (d2 == 0.0) & (d3 == 0.0) & (d4 == 0.0)
        hit = (np.sign(d3) * np.sign(d4) <= 0.0) & ~collinear
        for k in np.flatnonzero(collinear):  # collinear: do they overlap?
            ii, jj = int(pi[k]), int(qj[k])
            hit[k] = bool(_segments_meet(a[ii:ii + 1], b[ii:ii + 1], a[jj:jj + 1], b[jj:jj + 1])[0][0])
        if hit.any():
            k = int(np.argmax(hit))
            return int(pi[k]), int(qj[k])
    return None


def _cross(ux: Array, uy: Array, vx: Array, vy: Array) -> Array:
    """:func:`~.geometry.cross` of ``u`` and ``v`` given by their coordinates: ``ux*vy - uy*vx``, the same
    operations."""
    return ux * vy - uy * vx


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
