"""An independent tangle check for the tests, with shapely (GEOS): does one element's drawing tangle?

For the contours of one element at a time t (closed ones as rings, open ones as lines) and the same
contours at its two keys, t is *tangled* when a closed contour is not simple (one that touches itself in a
key, a joined contour's slit: when two of its edges cross properly, in exact arithmetic), a hole meets its outline
(the smallest closed contour of the first key around its first vertex) or lies outside it, or two
closed contours that are apart in both keys (no common point, and each inside the other or not alike
in both keys) meet at t: their rings share a point, or one lies inside the other where it did not in
the keys. Open strokes are checked the same way among themselves and against every contour (a
stroke not simple, or meeting a contour it is apart from in both keys), with no containment.

A contour that is one point at a time (growing from it, or shrinking to it) is not drawn there: it meets
no contour and lies inside none, and in a key where it is one point it is apart from every other, the
pair read from the other key alone.

GEOS counts touching as meeting where the code counts only proper crossings; on real drawings moving
in floating point the two differ only by chance, which the tests allow for by comparing counts.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from shapely.geometry import LinearRing, LineString, Point, Polygon

from tests.core.exact_tangles import inside as exact_inside
from tests.core.exact_tangles import proper_pairs


def _flat(points: np.ndarray) -> bool:
    """Whether a contour is one point (one growing from it or shrinking to it, at that time)."""
    return len(np.unique(np.asarray(points), axis=0)) < 2


def _line(points: np.ndarray, closed: bool) -> LineString | LinearRing | Point:
    if _flat(points):
        return Point(points[0])
    return LinearRing(points) if closed else LineString(points)


def _inside(inner: np.ndarray, outer: np.ndarray) -> bool:
    """Whether closed ``inner``'s first vertex lies inside closed ``outer`` (even-odd, as GEOS reads a ring;
    nothing lies inside a contour of fewer than three distinct points)."""
    if len(np.unique(np.asarray(outer), axis=0)) < 3:
        return False
    return bool(Polygon(outer).buffer(0).contains(Point(inner[0]))) if _simple(outer) else \
        _even_odd(inner[0], outer)


def _even_odd(point: np.ndarray, polygon: np.ndarray) -> bool:
    """Even-odd for a ring that is not simple (a joined contour's slit): the parity of a ray's crossings.
    (The faces GEOS's polygonize makes of the noded ring hold each point once, whatever its parity: a
    point in a joined hole's face counted as inside.)"""
    return exact_inside(np.asarray(point, dtype=np.float64), np.asarray(polygon, dtype=np.float64))


def _simple(points: np.ndarray) -> bool:
    return bool(LinearRing(points).is_simple)


def parents(contours: Sequence[np.ndarray], closed: Sequence[bool]) -> list[int | None]:
    """Each contour's smallest closed contour around its first vertex (by area), or None (a contour that
    is one point holds nothing)."""
    out: list[int | None] = []
    for c, points in enumerate(contours):
        around = [d for d, other in enumerate(contours)
                  if d != c and closed[d] and len(other) >= 3 and not _flat(points) and _inside(points, other)]
        out.append(min(around, key=lambda d: Polygon(contours[d]).area) if around else None)
    return out


def _state(c: np.ndarray, d: np.ndarray) -> int:
    """1: c inside d, -1: d inside c, 0: neither (closed contours that do not meet)."""
    return 1 if _inside(c, d) else -1 if _inside(d, c) else 0


def tangled(at: Sequence[np.ndarray], keys0: Sequence[np.ndarray], keys1: Sequence[np.ndarray],
            closed: Sequence[bool]) -> tuple[bool, bool]:
    """Whether the element's closed contours ``at`` tangle, and whether its open strokes do (a contour
    that meets the one around it in either key is no hole of it: the keys already cross)."""
    lines = [_line(p, s) for p, s in zip(at, closed)]
    keyed = [[_line(p, s) for p, s in zip(keys, closed)] for keys in (keys0, keys1)]
    parent = [p if p is None or not any(k[c].intersects(k[p]) for k in keyed) else None
              for c, p in enumerate(parents(keys0, closed))]
    shut, stroke = False, False
    # a contour that touches itself in a key (a joined contour's slit, walked there and back) is not simple
    # by GEOS there, and touching does not count: such a contour tangles where its edges cross properly,
    # decided in exact arithmetic
    judged = [all(k[c].is_simple for k in keyed) for c in range(len(at))]
    for c, line in enumerate(lines):
        crosses = not line.is_simple if judged[c] else \
            proper_pairs(np.asarray(at[c]), np.asarray(at[c]), closed[c], closed[c], same=True) > 0
        if crosses:
            if closed[c]:
                shut = True
            else:
                stroke = True
        p = parent[c]
        if closed[c] and p is not None and not (_flat(at[c]) or _flat(at[p])) \
                and (line.intersects(lines[p]) or not _inside(at[c], at[p])):
            shut = True
    for c in range(len(at)):
        for d in range(c + 1, len(at)):
            if _flat(at[c]) or _flat(at[d]):
                continue  # one point now: drawn nowhere
            both_drawn = [not (_flat(keys[c]) or _flat(keys[d])) for keys in (keys0, keys1)]
            if any(k[c].intersects(k[d]) for k, drawn in zip(keyed, both_drawn) if drawn):
                continue  # touching or crossing in a key: not apart
            both = closed[c] and closed[d]
            if both:
                states = {_state(keys[c], keys[d]) for keys, drawn in zip((keys0, keys1), both_drawn) if drawn} or {0}
                if len(states) > 1:
                    continue  # nested in one key only: they must pass each other
            met = lines[c].intersects(lines[d]) or (both and _state(at[c], at[d]) not in states)
            if met and both:
                shut = True
            elif met:
                stroke = True
    return shut, stroke
