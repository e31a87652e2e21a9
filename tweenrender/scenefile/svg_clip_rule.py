"""``clip-rule`` on a clip path's children (SVG 1.1 §14.3.5): each child's region by its own rule, their union.

A clip region is kept as closed contours read under the nonzero rule. A child under ``evenodd`` is turned
into contours whose nonzero region is its even-odd region (shapely: each contour made valid, the pieces
combined by symmetric difference, outer rings anticlockwise and holes clockwise), so the union of the
children stays the nonzero region of all their contours. ``clip-rule`` is inherited: a ``<clipPath>``
takes it from its own ancestors, where it is written in the document, not from the element it clips.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

__all__ = ["evenodd_as_nonzero", "inherited_clip_rule", "signed_area", "union_by_rule"]


class _Node(Protocol):
    tag: str
    attrs: dict[str, str]
    children: list  # type: ignore[type-arg]


_last: list[tuple[object, dict[int, str]]] = []  # the last document asked about, with its clip paths' rules


def inherited_clip_rule(clip: _Node, document: object, own_rule: Callable[[_Node], str | None]) -> str:
    """The ``clip-rule`` the children of ``<clipPath>`` ``clip`` inherit: its own, else its nearest
    ancestor's, else ``nonzero``. ``own_rule(node)`` is a node's own declared value or None (the cascade).

    The rules of every ``<clipPath>`` of a document are found in one walk, kept for the last document."""
    last = _last[0] if _last else None
    if last is not None and last[0] is document:
        rules = last[1]
    else:
        rules = {}
        stack: list[tuple[_Node, str]] = [(document.root, "nonzero")]  # type: ignore[attr-defined]
        while stack:
            node, parent = stack.pop()
            written = (own_rule(node) or "").strip()
            rule = written if written in ("nonzero", "evenodd") else parent
            if node.tag == "clipPath":
                rules[id(node)] = rule
            stack.extend((child, rule) for child in node.children)
        _last[:] = [(document, rules)]
    return rules.get(id(clip), "nonzero")


def evenodd_as_nonzero(contours: Sequence[NDArray[np.float64]]) -> list[NDArray[np.float64]]:
    """Closed contours ``(N, 2)`` whose nonzero region (winding 0 or 1 everywhere) is the even-odd region
    of ``contours`` (each ``(N, 2)``, closed); each returned without its closing repeat."""
    import shapely

    region = None
    for points in contours:
        if len(points) < 3:
            continue
        valid = shapely.make_valid(shapely.Polygon(points))
        piece = shapely.union_all([part for part in shapely.get_parts(valid) if part.geom_type == "Polygon"])
        region = piece if region is None else shapely.symmetric_difference(region, piece)
    if region is None:
        return []
    return rings_of(region)


def rings_of(region: object) -> list[NDArray[np.float64]]:
    """The rings of a shapely region's polygons, each ``(N, 2)`` without its repeated last point, outers
    counter-clockwise and holes clockwise (drawn nonzero, they fill the region)."""
    import shapely
    from shapely.geometry.polygon import orient

    out: list[NDArray[np.float64]] = []
    for polygon in shapely.get_parts(region):
        if polygon.geom_type != "Polygon" or polygon.is_empty:
            continue
        polygon = orient(polygon, 1.0)
        for ring in (polygon.exterior, *polygon.interiors):
            ring_points = np.asarray(ring.coords, dtype=float)[:-1]
            if len(ring_points) >= 3:
                out.append(ring_points)
    return out


def signed_area(contours: Sequence[NDArray[np.float64]]) -> float:
    """The summed signed (shoelace) area of closed ``contours`` (each ``(N, 2)``): its sign is their turn."""
    total = 0.0
    for p in contours:
        x, y = p[:, 0], p[:, 1]
        total += 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))
    return total


def union_by_rule(children: Sequence[tuple[str, list[NDArray[np.float64]]]]) -> list[NDArray[np.float64]]:
    """The contours of a clip path's children ``(clip-rule, closed contours (N, 2))`` whose nonzero region is
    the union of each child's region under its rule: unchanged when every child is ``nonzero``; else the
    ``evenodd`` ones as :func:`evenodd_as_nonzero` gives them and the ``nonzero`` ones turned anticlockwise
    (a child's windings of one sign then add up, never cancel, with another child's)."""
    if all(rule != "evenodd" for rule, _ in children):
        return [p for _, contours in children for p in contours]
    out: list[NDArray[np.float64]] = []
    for rule, contours in children:
        if rule == "evenodd":
            out += evenodd_as_nonzero(contours)
        elif signed_area(contours) < 0:
            out += [p[::-1] for p in contours]
        else:
            out += list(contours)
    return out
