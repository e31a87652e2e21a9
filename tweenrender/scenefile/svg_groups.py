"""Group opacity (SVG 1.1 §14.5): a container's ``opacity`` applies to its content composited as one.

A drawing read with a layered walk gives each element the groups with an opacity it is in
(``Element.groups``: ``(group number, opacity)``, outermost first), and leaves their opacity out of its paint.
Where the group changes nothing, its opacity goes back into the paint (so the element stays plain, and
vector formats can carry it): a group of one element, or one whose elements' boxes (strokes included)
do not overlap, since then no element is drawn over another inside it.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace
from typing import Any, TypeVar

import numpy as np

Element = TypeVar("Element", bound=Any)
"""A drawing's element (:class:`.svg.Element`): ``contours``, ``paint``, ``miter_limit``, ``groups``."""

__all__ = ["fold_lone_groups"]

_MOST_COMPARED = 400
"""Elements in one group past which their boxes are not compared (the group is kept)."""


def _box(element: Any) -> tuple[float, float, float, float]:
    """The element's box ``(xmin, ymin, xmax, ymax)`` in world units, its stroke's half width around it."""
    every = np.concatenate([np.asarray(c.points, dtype=float) for c in element.contours])
    pad = element.paint.stroke_width / 2 * max(element.miter_limit, 1.5) if element.paint.stroke is not None else 0.0
    (x0, y0), (x1, y1) = every.min(axis=0), every.max(axis=0)
    return (float(x0 - pad), float(y0 - pad), float(x1 + pad), float(y1 + pad))


def _overlap(boxes: Sequence[tuple[float, float, float, float]]) -> bool:
    """Whether any two of ``boxes`` overlap."""
    b = np.asarray(boxes, dtype=float)
    apart_x = (b[:, None, 2] <= b[None, :, 0]) | (b[None, :, 2] <= b[:, None, 0])
    apart_y = (b[:, None, 3] <= b[None, :, 1]) | (b[None, :, 3] <= b[:, None, 1])
    touching = ~(apart_x | apart_y)
    np.fill_diagonal(touching, False)
    return bool(touching.any())


def fold_lone_groups(elements: Sequence[Element]) -> tuple[Element, ...]:
    """``elements`` with every group that changes nothing folded into its elements' paint opacity."""
    members: dict[int, list[int]] = {}
    for index, element in enumerate(elements):
        for number, _ in element.groups:
            members.setdefault(number, []).append(index)
    kept = set()
    for number, indices in members.items():
        if len(indices) > _MOST_COMPARED or (len(indices) > 1 and _overlap([_box(elements[i]) for i in indices])):
            kept.add(number)
    out = []
    for element in elements:
        if not element.groups:
            out.append(element)
            continue
        folded = float(np.prod([alpha for number, alpha in element.groups if number not in kept]))
        paint = replace(element.paint, opacity=element.paint.opacity * folded)
        out.append(replace(element, paint=paint, groups=tuple(g for g in element.groups if g[0] in kept)))
    return tuple(out)
