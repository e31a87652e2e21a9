"""Which contours of a run stay apart from the others at every frame, so a file may draw them as paths of their own.

Drawn as one path, a run's contours are filled together under its fill rule: a contour inside another may
make a hole, two that cross may cancel where they overlap. Drawn apart, each path is filled alone. The two
agree wherever no contour of one path comes near, crosses or lies inside a contour of another at any frame:
each path then covers pixels no other covers, however it is filled, stroked or antialiased.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from numpy.typing import NDArray

from ..core.contours import inside
from .curves import distance_to_polyline

__all__ = ["apart_pieces", "cut_holes", "MOST_CONTOURS"]

Array = NDArray[np.float64]

MOST_CONTOURS = 400
"""Contours a run may have for its pieces to be looked for (the boxes of every two are compared at every frame)."""
_MOST_POINTS = 2_000_000  # points of one contour's edges, over every frame, that are looked at closely


def apart_pieces(contours: list[Array], apart: float) -> tuple[tuple[int, ...], ...] | None:
    """The contours ``(F, L_i, 2)`` (pixels, at every frame; each taken as closed, as a fill closes an open one)
    grouped into pieces such that every contour of a piece stays more than ``apart`` from every contour of
    another piece at every frame, and outside it: the contours that come that near, or lie inside one another,
    at some frame are in one piece (and so, in turn, are their own such neighbours). Pieces in the order of their
    first contour; None where there are more than :data:`MOST_CONTOURS` contours or a point is not finite."""
    count = len(contours)
    if count == 0 or count > MOST_CONTOURS or not all(c.size and np.all(np.isfinite(c)) for c in contours):
        return None
    space = _Space(contours, apart)
    group = list(range(count))

    def root(i: int) -> int:
        while group[i] != i:
            group[i] = group[group[i]]
            i = group[i]
        return i

    for i, j in zip(*np.nonzero(np.triu(space.boxes.any(axis=0), 1))):
        i, j = int(i), int(j)
        if root(i) != root(j) and (space.close(i, j) or space.nested(i, j)):
            a, b = root(i), root(j)
            group[max(a, b)] = min(a, b)
    pieces: dict[int, list[int]] = {}
    for i in range(count):
        pieces.setdefault(root(i), []).append(i)
    return tuple(tuple(members) for members in pieces.values())


def cut_holes(contours: list[Array], rules: str | Sequence[str], apart: float) -> tuple[int, ...]:
    """Which of the closed contours ``(F, L_i, 2)`` of one piece are holes a mask can cut out of the others: at
    every frame each stays more than ``apart`` from every other contour, holds none of them, and the fill rule
    (``nonzero`` or ``evenodd``; ``rules``: one for every frame, or one per frame) leaves its inside empty and the
    outside next to it filled (where it has no area, it draws nothing). The other contours, filled without it,
    then fill its inside too; cut out, it is empty again, and nothing else changes."""
    count = len(contours)
    if count < 2 or count > MOST_CONTOURS or not all(c.size and np.all(np.isfinite(c)) for c in contours):
        return ()
    space = _Space(contours, apart)
    areas = np.stack([_signed_areas(c) for c in contours], axis=1)  # (F, C)
    rule_at = [rules] * len(areas) if isinstance(rules, str) else list(rules)
    least = 1e-9 * max(float(np.abs(np.concatenate([c.reshape(-1, 2) for c in contours])).max()), 1.0) ** 2
    out = []
    for h in range(count):
        others = [j for j in range(count) if j != h]
        if any(space.close(h, j) for j in others):
            continue
        for f in range(len(areas)):
            if abs(areas[f, h]) <= least:
                continue
            if any(space.holds(h, j, f) for j in others):
                break
            around = [j for j in others if space.holds(j, h, f)]
            if rule_at[f] == "evenodd":
                if len(around) % 2 != 1:
                    break
            else:
                outside = int(sum(np.sign(areas[f, j]) for j in around))
                if outside == 0 or outside + int(np.sign(areas[f, h])) != 0:
                    break
        else:
            out.append(h)
    return tuple(out)


class _Space:
    """Closed contours ``(F, L_i, 2)`` and whether two come within ``apart`` (:meth:`close`) or nest (:meth:`holds`)
    at a frame; their boxes, grown by the reach, ``boxes (F, C, C)``: whether two meet, frame by frame."""

    def __init__(self, contours: list[Array], apart: float) -> None:
        self.step = apart  # points of each edge this far apart at most: a crossing passes within half a step of one
        self.reach = apart + 0.5 * self.step
        low = np.stack([c.min(axis=1) for c in contours], axis=1) - self.reach  # (F, C, 2)
        high = np.stack([c.max(axis=1) for c in contours], axis=1) + self.reach
        self.boxes = np.stack([np.all((lo[:, None] <= hi[None]) & (lo[None] <= hi[:, None]), axis=-1)
                               for lo, hi in zip(low, high)])
        self.rings = [np.concatenate([c, c[:, :1]], axis=1) for c in contours]
        self._dense: dict[int, Array | None] = {}

    def close(self, i: int, j: int) -> bool:
        """Whether contours ``i`` and ``j`` come within ``apart`` of each other (or cross) at some frame: then a
        point of ``i``'s edges, cut into steps, lies within the reach of ``j``'s edges (a contour too long to look
        at so closely counts as coming near)."""
        at = np.flatnonzero(self.boxes[:, i, j])
        if not len(at):
            return False
        points = self._densified(i)
        return points is None or float(distance_to_polyline(points[at], self.rings[j][at]).min()) <= self.reach

    def holds(self, outer: int, inner: int, f: int) -> bool:
        """Whether contour ``inner``'s first point lies inside contour ``outer`` at frame ``f`` (even-odd)."""
        ring = self.rings[outer][f, :-1]
        return bool(self.boxes[f, outer, inner]) and len(ring) >= 3 and \
            bool(inside(self.rings[inner][f, :1], ring)[0])

    def nested(self, i: int, j: int) -> bool:
        """Whether ``i`` lies inside ``j`` or ``j`` inside ``i`` at some frame."""
        return any(self.holds(i, j, f) or self.holds(j, i, f) for f in np.flatnonzero(self.boxes[:, i, j]).tolist())

    def _densified(self, index: int) -> Array | None:
        """The points of ring ``index`` with each edge cut into pieces no longer than the step at any frame:
        ``(F, P, 2)`` (kept); None where they would be more than :data:`_MOST_POINTS`."""
        if index in self._dense:
            return self._dense[index]
        ring = self.rings[index]
        edges = np.diff(ring, axis=1)  # (F, L, 2)
        cuts = np.maximum(1, np.ceil(np.linalg.norm(edges, axis=-1).max(axis=0) / self.step)).astype(np.intp)
        found = None
        if int(cuts.sum()) * len(ring) <= _MOST_POINTS:
            share = np.concatenate([np.arange(n) / n for n in cuts.tolist()])  # (P,)
            start = np.repeat(np.arange(len(cuts)), cuts)
            found = ring[:, start] + share[None, :, None] * edges[:, start]
        self._dense[index] = found
        return found


def _signed_areas(contour: Array) -> Array:
    """The shoelace area of a closed contour ``(F, L, 2)`` at each frame: ``(F,)``, its sign its winding."""
    x, y = contour[..., 0], contour[..., 1]
    return 0.5 * np.sum(x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y, axis=1)
