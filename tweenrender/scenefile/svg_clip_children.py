"""A clip path's children as CSS Masking §5.1 and SVG 1.1 §14.3.5 define them.

Only shapes, ``<text>`` and a ``<use>`` that names one of them directly contribute to a clip path; any other
child (``<g>``, ``<switch>``, ``<image>``, a ``<use>`` of a group or a symbol) is ignored. A child may have a
``clip-path`` of its own: its region is then the intersection of its shape (under its ``clip-rule``) with
that clip path's regions. The intersection is exact on the flattened contours (shapely): the plane is cut
into faces by every edge, and a face is kept when its winding numbers say it is inside under each rule.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from .svg_clip_rule import rings_of

__all__ = ["VALID_CHILDREN", "valid_clip_child", "region", "intersection"]

VALID_CHILDREN = ("path", "polygon", "polyline", "rect", "circle", "ellipse", "line", "text")
"""The elements that contribute to a clip path (``<use>`` too, when it names one of them)."""


class _Node(Protocol):
    tag: str
    attrs: dict[str, str]
    svg: bool


def valid_clip_child(node: _Node, ids: dict[str, list[_Node]]) -> bool:  # type: ignore[type-arg]
    """Whether ``node``, a child of a ``<clipPath>``, contributes to its region (``ids``: the document's ids)."""
    if not node.svg:
        return False
    if node.tag in VALID_CHILDREN:
        return True
    if node.tag != "use":
        return False
    href = node.attrs.get("href", node.attrs.get("xlink:href", "")).strip()
    target = ids.get(href[1:]) if href.startswith("#") else None
    return bool(target) and target[0].svg and target[0].tag in VALID_CHILDREN  # type: ignore[index]


def _winding(point: NDArray[np.float64], contours: Sequence[NDArray[np.float64]]) -> int:
    """The winding number of the closed ``contours`` (each ``(N, 2)``) around ``point`` ``(2,)``."""
    x, y = point
    total = 0
    for p in contours:
        a, b = p, np.roll(p, -1, axis=0)
        cross = (b[:, 0] - a[:, 0]) * (y - a[:, 1]) - (x - a[:, 0]) * (b[:, 1] - a[:, 1])
        up = (a[:, 1] <= y) & (b[:, 1] > y) & (cross > 0)
        down = (a[:, 1] > y) & (b[:, 1] <= y) & (cross < 0)
        total += int(np.count_nonzero(up)) - int(np.count_nonzero(down))
    return total


def region(contours: Sequence[NDArray[np.float64]], rule: str):  # type: ignore[no-untyped-def]
    """The region of closed ``contours`` (each ``(N, 2)``) under ``rule`` (``nonzero`` or ``evenodd``), as a
    shapely geometry (empty when they enclose nothing)."""
    import shapely

    rings = [np.vstack([p, p[:1]]) for p in contours if len(p) >= 3]
    if not rings:
        return shapely.Polygon()
    edges = shapely.node(shapely.MultiLineString(rings))
    faces = shapely.get_parts(shapely.polygonize(shapely.get_parts(edges)))
    kept = []
    for face in faces:
        inside = np.asarray(face.point_on_surface().coords[0], dtype=float)
        winding = _winding(inside, [p for p in contours if len(p) >= 3])
        if (winding % 2 != 0) if rule == "evenodd" else winding != 0:
            kept.append(face)
    return shapely.union_all(kept) if kept else shapely.Polygon()


def intersection(contours: Sequence[NDArray[np.float64]], rule: str,
                 regions: Sequence[Sequence[NDArray[np.float64]]]) -> list[NDArray[np.float64]]:
    """Closed contours ``(N, 2)`` whose nonzero region (winding 0 or 1) is the region of ``contours`` under
    ``rule`` intersected with each of ``regions`` (closed contours, nonzero); [] when nothing is left."""
    import shapely

    kept = region(contours, rule)
    for other in regions:
        if kept.is_empty:
            break
        kept = shapely.intersection(kept, region(other, "nonzero"))
    return rings_of(kept)
