"""An independent, exact brute-force tangle test for the tests: every pair of edges, rational arithmetic.

Two edges cross *properly* when each one's ends lie strictly on opposite sides of the other's line;
the sides are decided with :class:`fractions.Fraction` (every float is a rational exactly), so no
rounding enters. A float box test only skips pairs whose boxes are apart by more than a margin
(such edges cannot meet), which keeps the brute force fast enough for real icon outlines.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np


def _side(a: tuple[Fraction, Fraction], b: tuple[Fraction, Fraction], c: tuple[Fraction, Fraction]) -> int:
    value = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (value > 0) - (value < 0)


def _edges(points: np.ndarray, closed: bool) -> list[tuple[int, int]]:
    n = len(points)
    m = n if closed and n >= 3 else n - 1
    return [(i, (i + 1) % n) for i in range(max(m, 0))]


def proper_pairs(a: np.ndarray, b: np.ndarray, closed_a: bool, closed_b: bool, same: bool) -> int:
    """How many pairs of edges of polyline ``a`` and ``b`` cross properly (``same``: a == b, neighbours skipped)."""
    ea, eb = _edges(a, closed_a), _edges(b, closed_b)
    if not ea or not eb:
        return 0
    pa = np.array([[a[i], a[j]] for i, j in ea])
    pb = np.array([[b[i], b[j]] for i, j in eb])
    lo_a, hi_a = pa.min(axis=1), pa.max(axis=1)
    lo_b, hi_b = pb.min(axis=1), pb.max(axis=1)
    margin = 1e-9 * (1.0 + max(np.abs(pa).max(), np.abs(pb).max()))
    near = np.all(lo_a[:, None] <= hi_b[None] + margin, axis=2) & np.all(lo_b[None] <= hi_a[:, None] + margin, axis=2)
    count = 0
    for i, j in zip(*np.nonzero(near)):
        if same:
            if i >= j:
                continue
            (p, q), (r, s) = ea[i], eb[j]
            if len({p, q, r, s}) < 4:
                continue  # neighbours share a vertex
        p, q = ((Fraction(float(x)), Fraction(float(y))) for x, y in pa[i])
        r, s = ((Fraction(float(x)), Fraction(float(y))) for x, y in pb[j])
        if _side(p, q, r) * _side(p, q, s) < 0 and _side(r, s, p) * _side(r, s, q) < 0:
            count += 1
    return count


def inside(point: np.ndarray, polygon: np.ndarray) -> bool:
    """Even-odd ray test (float; used only away from the outline)."""
    x, y = point
    hit = False
    for (x1, y1), (x2, y2) in zip(polygon, np.roll(polygon, -1, axis=0)):
        if (y1 > y) != (y2 > y) and x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
            hit = not hit
    return hit


def tangled(contours: list[np.ndarray], closed: list[bool], parent: list[int | None]) -> bool:
    """A contour crosses itself properly, or crosses its parent, or lies wholly outside it."""
    for c, (points, shut) in enumerate(zip(contours, closed)):
        if proper_pairs(points, points, shut, shut, True):
            return True
        p = parent[c]
        if p is not None:
            if proper_pairs(points, contours[p], shut, True, False):
                return True
            if not any(inside(v, contours[p]) for v in points):
                return True
    return False


def parents_of(contours: list[np.ndarray], closed: list[bool]) -> list[int | None]:
    """The smallest closed contour around each contour's first vertex."""
    def area(p: np.ndarray) -> float:
        return abs(float(np.sum(p[:, 0] * np.roll(p[:, 1], -1) - np.roll(p[:, 0], -1) * p[:, 1]))) / 2

    out: list[int | None] = []
    for c, points in enumerate(contours):
        around = [d for d, q in enumerate(contours) if d != c and closed[d] and len(q) >= 3 and inside(points[0], q)]
        out.append(min(around, key=lambda d: area(contours[d])) if around else None)
    return out
