"""Proper crossings of a shape's contours: does an in-between tangle? (maths §5.9, DESIGN ``crossings``)

A shape *tangles* at a frame when one of its contours crosses itself properly
— two edges that are not neighbours meet at one point inside both, each
passing to the other's far side — or when a hole leaves its outline: the hole
crosses its outline properly, or lies wholly outside it. Touching (a vertex on
an edge, collinear overlap) does not count, nor do two pieces overlapping.
Which contour is a hole of which is read from the first frame: a closed
contour's *parent* is the smallest closed contour around its first vertex.

Orientation signs are exact: a float determinant within its rounding bound of
zero is recomputed in exact rational arithmetic (:class:`fractions.Fraction`),
so the answer does not depend on floating-point luck. Candidate edge pairs are
found by sorting the edges' x-ranges (sweep and prune), so a frame costs far
less than all pairs.
"""

from __future__ import annotations

from collections import OrderedDict
from fractions import Fraction
from typing import Sequence

import numpy as np
from numpy.typing import NDArray

__all__ = ["SWEEP", "parents", "tangles", "tangled_times", "proper_crossings", "linear_tangles"]

Array = NDArray[np.float64]

SWEEP = np.linspace(0.0, 1.0, 101)
"""The swept t of a segment at which crossings are looked for (``stats``' ``crossings``, ``auto``)."""

_CACHED = 1024  # shapes whose straight paths' crossings are kept
_linear_cache: OrderedDict[bytes, list[float]] = OrderedDict()

_BOUND = 4.0 * np.finfo(np.float64).eps  # relative rounding bound of a 2x2 orientation determinant


Indices = NDArray[np.intp]


def _edges(contours: Sequence[Array], closed: Sequence[bool]) -> tuple[Array, Array, Indices, Indices, Indices]:
    """Every edge ``a → b`` (``(E, 2)`` each), its contour, its index in the contour and the contour's edge count."""
    a, b, owner, index, count = [], [], [], [], []
    for c, (points, shut) in enumerate(zip(contours, closed)):
        points = np.asarray(points, dtype=np.float64)
        m = len(points) if shut and len(points) >= 3 else len(points) - 1
        if m <= 0:
            continue
        a.append(points[:m])
        b.append(np.roll(points, -1, axis=0)[:m] if shut else points[1:m + 1])
        owner.append(np.full(m, c))
        index.append(np.arange(m))
        count.append(np.full(m, m if shut else -1))
    if not a:
        empty = np.zeros((0, 2))
        none = np.zeros(0, dtype=np.intp)
        return empty, empty, none, none, none
    return (np.concatenate(a), np.concatenate(b), np.concatenate(owner), np.concatenate(index),
            np.concatenate(count))


def _sign(ax: Array, ay: Array, bx: Array, by: Array, cx: Array, cy: Array) -> NDArray[np.int8]:
    """Exact sign of ``orient(a, b, c)`` for arrays of points."""
    left = (bx - ax) * (cy - ay)
    right = (by - ay) * (cx - ax)
    det = left - right
    sign = np.sign(det).astype(np.int8)
    unsure = np.flatnonzero(np.abs(det) <= _BOUND * (np.abs(left) + np.abs(right)))
    for k in unsure.tolist():
        f = [Fraction(float(v[k])) for v in (ax, ay, bx, by, cx, cy)]
        exact = (f[2] - f[0]) * (f[5] - f[1]) - (f[3] - f[1]) * (f[4] - f[0])
        sign[k] = (exact > 0) - (exact < 0)
    return sign


def _candidates(a: Array, b: Array) -> tuple[NDArray[np.intp], NDArray[np.intp]]:
    """Pairs ``i < j`` of edges whose bounding boxes meet."""
    lo, hi = np.minimum(a[:, 0], b[:, 0]), np.maximum(a[:, 0], b[:, 0])
    order = np.argsort(lo, kind="stable")
    lo_sorted = lo[order]
    end = np.searchsorted(lo_sorted, hi[order], side="right")
    counts = np.maximum(end - np.arange(1, len(order) + 1), 0)
    first = np.repeat(np.arange(len(order)), counts)
    offset = np.arange(counts.sum()) - np.repeat(np.cumsum(counts) - counts, counts)
    i, j = order[first], order[first + 1 + offset]
    ylo_i, yhi_i = np.minimum(a[i, 1], b[i, 1]), np.maximum(a[i, 1], b[i, 1])
    ylo_j, yhi_j = np.minimum(a[j, 1], b[j, 1]), np.maximum(a[j, 1], b[j, 1])
    meet = (ylo_i <= yhi_j) & (ylo_j <= yhi_i)
    return i[meet], j[meet]


def proper_crossings(contours: Sequence[Array], closed: Sequence[bool]) -> list[tuple[int, int]]:
    """The pairs of contours ``(c, d)``, ``c ≤ d``, that cross properly (``c == d``: it crosses itself)."""
    a, b, owner, index, count = _edges(contours, closed)
    if len(a) < 2:
        return []
    i, j = _candidates(a, b)
    same = owner[i] == owner[j]
    gap = np.abs(index[i] - index[j])
    neighbours = same & ((gap == 1) | ((count[i] > 0) & (gap == count[i] - 1)))
    i, j = i[~neighbours], j[~neighbours]
    if len(i) == 0:
        return []
    p, q, r, s = a[i], b[i], a[j], b[j]
    d1 = _sign(p[:, 0], p[:, 1], q[:, 0], q[:, 1], r[:, 0], r[:, 1])
    d2 = _sign(p[:, 0], p[:, 1], q[:, 0], q[:, 1], s[:, 0], s[:, 1])
    keep = (d1.astype(int) * d2) < 0
    d3 = _sign(r[keep, 0], r[keep, 1], s[keep, 0], s[keep, 1], p[keep, 0], p[keep, 1])
    d4 = _sign(r[keep, 0], r[keep, 1], s[keep, 0], s[keep, 1], q[keep, 0], q[keep, 1])
    cross = (d3.astype(int) * d4) < 0
    c, d = owner[i][keep][cross], owner[j][keep][cross]
    return sorted({(int(min(x, y)), int(max(x, y))) for x, y in zip(c.tolist(), d.tolist())})


def _inside(point: Array, polygon: Array) -> bool:
    """Even-odd test of ``point (2,)`` against ``polygon (N, 2)``."""
    x, y = point
    a, b = polygon, np.roll(polygon, -1, axis=0)
    spans = (a[:, 1] > y) != (b[:, 1] > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        at = a[:, 0] + (y - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
    return bool(np.count_nonzero(spans & (x < at)) % 2)


def _area(polygon: Array) -> float:
    x, y = polygon[:, 0], polygon[:, 1]
    return abs(float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))) / 2.0


def parents(contours: Sequence[Array], closed: Sequence[bool]) -> list[int | None]:
    """Each contour's parent: the smallest other closed contour around its first vertex (None for none)."""
    shut = [c for c, (p, s) in enumerate(zip(contours, closed)) if s and len(p) >= 3]
    areas = {c: _area(np.asarray(contours[c], dtype=np.float64)) for c in shut}
    out: list[int | None] = []
    for c, points in enumerate(contours):
        around = [d for d in shut if d != c and len(points) and
                  _inside(np.asarray(points, dtype=np.float64)[0], np.asarray(contours[d], dtype=np.float64))]
        out.append(min(around, key=lambda d: areas[d]) if around else None)
    return out


def tangles(contours: Sequence[Array], closed: Sequence[bool], parent: Sequence[int | None]) -> bool:
    """Whether one frame tangles: a contour crosses itself, or a contour crosses or leaves its ``parent``."""
    for c, d in proper_crossings(contours, closed):
        if c == d or parent[c] == d or parent[d] == c:
            return True
    for c, p in enumerate(parent):
        if p is not None and len(contours[c]) and \
                not _inside(np.asarray(contours[c], dtype=np.float64)[0], np.asarray(contours[p], dtype=np.float64)):
            # wholly outside is a leaving; on an edge or partly outside shows as a crossing above
            first = np.asarray(contours[c], dtype=np.float64)
            if not any(_inside(point, np.asarray(contours[p], dtype=np.float64)) for point in first):
                return True
    return False


def tangled_times(frames: Sequence[Array], closed: Sequence[bool], t: Array) -> list[float]:
    """The ``t (T,)`` at which contours ``frames[i] (T, L_i, 2)`` tangle, parents read from the first frame."""
    t = np.asarray(t, dtype=np.float64)
    if not frames:
        return []
    parent = parents([f[0] for f in frames], closed)
    return [float(x) for k, x in enumerate(t.tolist()) if tangles([f[k] for f in frames], closed, parent)]


def linear_tangles(k0s: Sequence[Array], k1s: Sequence[Array], closed: Sequence[bool]) -> list[float]:
    """The t of :data:`SWEEP` at which the straight-line inbetweens of contours ``k0s[i]``, ``k1s[i]``
    (``(L_i, 2)`` each) tangle (remembered for the last few shapes asked about)."""
    a = [np.asarray(k, dtype=np.float64) for k in k0s]
    b = [np.asarray(k, dtype=np.float64) for k in k1s]
    key = b"|".join(x.tobytes() + b"/" + y.tobytes() for x, y in zip(a, b)) + repr(list(closed)).encode()
    found = _linear_cache.get(key)
    if found is None:
        t = SWEEP[:, None, None]
        found = tangled_times([(1.0 - t) * x + t * y for x, y in zip(a, b)], closed, SWEEP)
        _linear_cache[key] = found
        while len(_linear_cache) > _CACHED:
            _linear_cache.popitem(last=False)
    else:
        _linear_cache.move_to_end(key)
    return list(found)
