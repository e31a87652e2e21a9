"""Shapely measures of drawn contours, for ``bench_inbetweens.py``: the area a drawing paints (fill rules
and stroke bands), one element's structure in its two keys, its tangles and its distortion at a time.

Contours are :class:`tweenrender.DrawnContour` s as ``tweenrender.contours`` returns them; nothing here
uses the package's own measures.
"""

from __future__ import annotations

import math
from collections import defaultdict
from dataclasses import dataclass, field
from typing import Any, Sequence

import numpy as np
import shapely
from shapely.geometry.base import BaseGeometry

__all__ = ["VISIBLE", "Element", "Tangles", "drawn_area", "element_structure", "element_tangles",
           "element_distortion", "group", "winding", "fill_region"]

VISIBLE = 0.1  # alpha x opacity from which paint counts as drawn (fills and strokes fade in and out)


# -- drawn area ------------------------------------------------------------------------------------


def _dedup(points: np.ndarray) -> np.ndarray:
    """``points`` without consecutive repeats (balanced copies of a vertex)."""
    if len(points) < 2:
        return points
    keep = np.ones(len(points), dtype=bool)
    keep[1:] = np.any(np.abs(np.diff(points, axis=0)) > 0, axis=1)
    return points[keep]


def _ring_points(points: np.ndarray) -> np.ndarray:
    """A closed contour's points, repeats removed, closing repeat removed."""
    pts = _dedup(points)
    if len(pts) > 1 and np.all(pts[0] == pts[-1]):
        pts = pts[:-1]
    return pts


def winding(points: np.ndarray, ring: np.ndarray) -> np.ndarray:
    """Winding numbers ``(K,)`` of ``points (K, 2)`` about the closed polygon ``ring (N, 2)``."""
    a = ring
    b = np.roll(ring, -1, axis=0)
    px, py = points[:, 0:1], points[:, 1:2]
    left = (b[:, 0] - a[:, 0]) * (py - a[:, 1]) - (px - a[:, 0]) * (b[:, 1] - a[:, 1])
    up = (a[:, 1] <= py) & (b[:, 1] > py) & (left > 0)
    down = (a[:, 1] > py) & (b[:, 1] <= py) & (left < 0)
    return up.sum(axis=1) - down.sum(axis=1)


def fill_region(rings: Sequence[np.ndarray], signs: Sequence[int], rule: str) -> BaseGeometry:
    """The area filled by closed ``rings`` under ``rule`` (``nonzero``/``evenodd``): the faces of the noded
    rings whose winding number (each ring counted with its sign) is non-zero, or odd."""
    kept = [(r, s) for r, s in zip(rings, signs) if len(r) >= 3]
    rings, signs = [r for r, _ in kept], [s for _, s in kept]
    if not rings:
        return shapely.Polygon()
    if len(rings) == 1:
        polygon = shapely.Polygon(rings[0])
        if polygon.is_valid:
            return polygon
    lines = [shapely.LineString(np.vstack([r, r[:1]])) for r in rings]
    noded = shapely.union_all(lines)
    faces = shapely.get_parts(shapely.polygonize(shapely.get_parts(noded)))
    faces = faces[shapely.area(faces) > 0]
    if len(faces) == 0:
        return shapely.Polygon()
    inside = shapely.get_coordinates(shapely.point_on_surface(faces))
    total = np.zeros(len(faces), dtype=np.int64)
    for ring, sign in zip(rings, signs):
        total += sign * winding(inside, ring)
    keep = total != 0 if rule != "evenodd" else (total % 2) == 1
    return shapely.union_all(faces[keep])


def drawn_area(contours: Sequence[Any]) -> BaseGeometry:
    """The union of what ``contours`` (``DrawnContour`` s) paint: each element's fill by its rule, and the
    stroke band of every stroked contour; paint fainter than ``VISIBLE`` (alpha x opacity) left out."""
    parts: list[BaseGeometry] = []
    for members in group(contours).values():
        filled = [c for c in members if c.closed and c.fill is not None and c.fill[3] * c.opacity >= VISIBLE]
        if filled:
            rings = [_ring_points(c.points) for c in filled]
            signs = [-1 if c.reversed else 1 for c in filled]
            parts.append(fill_region(rings, signs, filled[0].fill_rule))
        for c in members:
            if c.stroke is None or c.stroke[3] * c.opacity < VISIBLE or c.stroke_width <= 0:
                continue
            pts = _dedup(c.points)
            if len(pts) < 2:
                continue
            line = shapely.LineString(np.vstack([pts, pts[:1]]) if c.closed else pts)
            parts.append(shapely.buffer(line, c.stroke_width / 2, quad_segs=4))
    parts = [p for p in parts if not p.is_empty]
    return shapely.union_all(parts) if parts else shapely.Polygon()


# -- one element's structure and tangles ------------------------------------------------------------


def _geometry(points: np.ndarray, closed: bool) -> BaseGeometry | None:
    pts = _ring_points(points) if closed else _dedup(points)
    if closed and len(pts) >= 3:
        return shapely.LinearRing(pts)
    if len(pts) >= 2:
        return shapely.LineString(pts)
    if len(pts) == 1:  # a contour that is one point (growing from it, or not started): it can still be met
        return shapely.Point(pts[0])
    return None


@dataclass
class Element:
    """An element's contours in both keys: which are closed, simple, holes (and in what), which pairs
    are apart in both keys."""

    name: str
    closed: list[bool]
    sizes: list[int]
    k0: list[np.ndarray]
    k1: list[np.ndarray]
    simple: np.ndarray
    apart: np.ndarray  # (P, 2) index pairs apart in both keys
    holes: list[tuple[int, int]] = field(default_factory=list)  # (hole, parent)


def _roles(rings: list[np.ndarray | None]) -> dict[int, tuple[int, int]]:
    """For each closed ring: (depth, innermost parent or -1), by vertex containment (winding != 0)."""
    out: dict[int, tuple[int, int]] = {}
    areas = {i: abs(shapely.Polygon(r).area) for i, r in enumerate(rings) if r is not None}
    for i, ri in enumerate(rings):
        if ri is None:
            continue
        containers = [j for j, rj in enumerate(rings)
                      if j != i and rj is not None and np.mean(winding(ri, rj) != 0) > 0.9]
        parent = min(containers, key=lambda j: areas[j]) if containers else -1
        out[i] = (len(containers), parent)
    return out


def _ring(contour: Any) -> np.ndarray | None:
    """A closed contour's ring (None for an open one, or one with fewer than three distinct points)."""
    pts = _ring_points(contour.points) if contour.closed else None
    return pts if pts is not None and len(pts) >= 3 else None


def element_structure(name: str, k0: list[Any], k1: list[Any], at0: list[Any] | None = None,
                      at1: list[Any] | None = None) -> Element | None:
    """The structure of element ``name`` from its contours next to the two keys (``k0``, ``k1``: a hair inside
    the segment, so each has the vertices it has at every t), or None when they differ. Which contours are apart
    and which are holes is read from the keys themselves where given (``at0``, ``at1``: the contours at t = 0
    and 1, a growing one its point there), else from ``k0``, ``k1``."""
    if len(k0) != len(k1) or any(len(a.points) != len(b.points) or a.closed != b.closed for a, b in zip(k0, k1)):
        return None
    closed = [c.closed for c in k0]
    at0 = at0 if at0 is not None and len(at0) == len(k0) else k0
    at1 = at1 if at1 is not None and len(at1) == len(k1) else k1
    g0 = [_geometry(c.points, c.closed) for c in at0]
    g1 = [_geometry(c.points, c.closed) for c in at1]
    valid = np.array([a is not None and b is not None for a, b in zip(g0, g1)])
    # whether a contour is simple is read a hair inside (a slit's two sides, coincident at the key, part there)
    h0, h1 = ([_geometry(c.points, c.closed) for c in k] for k in (k0, k1))
    simple = np.array([bool(v and a is not None and b is not None and a.is_simple and b.is_simple)
                       for v, a, b in zip(valid, h0, h1)])
    idx = np.flatnonzero(valid)
    i, j = np.triu_indices(len(idx), k=1)
    i, j = idx[i], idx[j]
    if len(i):
        arr0, arr1 = np.array(g0, dtype=object), np.array(g1, dtype=object)
        # a contour that is one point at a key (growing from it, shrinking to it) is drawn nowhere there: it
        # meets nothing, so it is apart from every contour in that key (maths §5.16, as stats counts)
        point0 = np.array([isinstance(g, shapely.Point) for g in arr0])
        point1 = np.array([isinstance(g, shapely.Point) for g in arr1])
        apart0 = ~shapely.intersects(arr0[i], arr0[j]) | point0[i] | point0[j]
        apart1 = ~shapely.intersects(arr1[i], arr1[j]) | point1[i] | point1[j]
        apart = apart0 & apart1
        pairs = np.stack([i[apart], j[apart]], axis=1)
    else:
        pairs = np.zeros((0, 2), dtype=np.int64)
    element = Element(name, closed, [len(c.points) for c in k0], [c.points for c in k0], [c.points for c in k1],
                      simple, pairs)
    r0 = _roles([_ring(c) if v else None for c, v in zip(at0, valid)])
    r1 = _roles([_ring(c) if v else None for c, v in zip(at1, valid)])
    for k in sorted(set(r0) | set(r1)):
        # a hole in both keys, inside the same parent; one that grows or shrinks is a hole as the key that
        # draws it has it (its parent drawn there too)
        roles = [r[k] for r in (r0, r1) if k in r]
        depth, parent = roles[0]
        if all(d % 2 == 1 and q == parent for d, q in roles) and parent >= 0:
            element.holes.append((k, parent))
    return element


@dataclass
class Tangles:
    """What is tangled in one element at one time: counts of each kind (``closed`` is their sum)."""

    closed: int = 0  # self-crossings + holes out + pair crossings of closed contours
    self_cross: int = 0
    hole_out: int = 0
    pair_cross: int = 0
    stroke: int = 0  # crossings involving an open stroke


def element_tangles(element: Element, contours: list[Any]) -> Tangles | None:
    """The tangles of ``element`` at one time (its contours there), or None when they do not align with the keys."""
    if [len(c.points) for c in contours] != element.sizes or [c.closed for c in contours] != element.closed:
        return None
    out = Tangles()
    geoms = [_geometry(c.points, c.closed) for c in contours]
    for k, g in enumerate(geoms):
        if element.simple[k] and g is not None and not g.is_simple:
            if element.closed[k]:
                out.self_cross += 1
            else:
                out.stroke += 1
    for hole, parent in element.holes:
        h, p = _ring_points(contours[hole].points), _ring_points(contours[parent].points)
        if len(h) >= 3 and len(p) >= 3 and np.any(winding(h, p) == 0):
            out.hole_out += 1
    if len(element.apart):
        arr = np.array(geoms, dtype=object)
        i, j = element.apart[:, 0], element.apart[:, 1]
        # a contour that is one point at this t (not started yet, or all grown in) is drawn nowhere: it meets
        # nothing, as in the keys
        drawn = np.array([g is not None and not isinstance(g, shapely.Point) for g in arr])
        ok = drawn[i] & drawn[j]
        if ok.any():
            hit = np.zeros(len(i), dtype=bool)
            hit[ok] = shapely.intersects(arr[i[ok]], arr[j[ok]])
            both_closed = np.array([element.closed[a] and element.closed[b] for a, b in zip(i, j)])
            out.pair_cross += int(np.sum(hit & both_closed))
            out.stroke += int(np.sum(hit & ~both_closed))
    out.closed = out.self_cross + out.hole_out + out.pair_cross
    return out


def element_distortion(element: Element, contours: list[Any], t: float, floor: float) -> float | None:
    """Length-weighted mean deviation of ``log(l_t / l_lerp)`` over the element's edges from its weighted
    mean (the element's change of size); see ``bench_inbetweens.py``."""
    logs, weights = [], []
    for k, c in enumerate(contours):
        e0, e1, et = (np.diff(np.vstack([p, p[:1]]) if element.closed[k] else p, axis=0)
                      for p in (element.k0[k], element.k1[k], c.points))
        l0, l1, lt = (np.hypot(e[:, 0], e[:, 1]) for e in (e0, e1, et))
        blend = (1 - t) * l0 + t * l1
        use = blend > floor
        logs.append(np.log(np.clip(lt[use] / blend[use], math.exp(-5), math.exp(5))))
        weights.append(blend[use])
    w = np.concatenate(weights) if weights else np.zeros(0)
    if w.sum() <= 0:
        return None
    x = np.concatenate(logs)
    return float(np.sum(w * np.abs(x - np.sum(w * x) / w.sum())) / w.sum())


def group(contours: Sequence[Any]) -> dict[str, list[Any]]:
    """``contours`` by element, each element's in drawing order."""
    out: dict[str, list[Any]] = defaultdict(list)
    for c in contours:
        out[c.element].append(c)
    return out
