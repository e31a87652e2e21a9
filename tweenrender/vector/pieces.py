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

__all__ = ["apart_pieces", "cut_holes", "pieces_and_holes", "MOST_CONTOURS"]

Array = NDArray[np.float64]

MOST_CONTOURS = 400
"""Contours a run may have for its pieces to be looked for (the boxes of every two are compared at every frame)."""
_MOST_POINTS = 2_000_000  # points of one contour's edges, over every frame, that are looked at closely
_SPREAD = 8  # frames measured at once when two contours are looked at closely


def apart_pieces(contours: list[Array], apart: float) -> tuple[tuple[int, ...], ...] | None:
    """The contours ``(F, L_i, 2)`` (pixels, at every frame; each taken as closed, as a fill closes an open one)
    grouped into pieces such that every contour of a piece stays more than ``apart`` from every contour of
    another piece at every frame, and outside it: the contours that come that near, or lie inside one another,
    at some frame are in one piece (and so, in turn, are their own such neighbours). Pieces in the order of their
    first contour; None where there are more than :data:`MOST_CONTOURS` contours or a point is not finite."""
    if not _usable(contours):
        return None
    return _pieces(_Space(contours, apart))


def pieces_and_holes(contours: list[Array], rules: str | Sequence[str], apart: float, cutting: bool = True
                     ) -> tuple[tuple[tuple[int, ...], ...], tuple[tuple[int, ...], ...]] | None:
    """:func:`apart_pieces` of the contours and, with ``cutting``, each piece's holes (:func:`cut_holes` of its
    contours, as indices of ``contours``), the distances between contours measured once for both; None as
    :func:`apart_pieces`."""
    if not _usable(contours):
        return None
    space = _Space(contours, apart)
    pieces = _pieces(space)
    holes = tuple(_holes(space, list(members), rules) if cutting and len(members) > 1 else () for members in pieces)
    return pieces, holes


def _usable(contours: list[Array]) -> bool:
    return 0 < len(contours) <= MOST_CONTOURS and all(c.size and np.all(np.isfinite(c)) for c in contours)


def _pieces(space: "_Space") -> tuple[tuple[int, ...], ...]:
    """The pieces of :func:`apart_pieces`, by the contours' distances and nesting in ``space``."""
    count = len(space.rings)
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
    if len(contours) < 2 or not _usable(contours):
        return ()
    return _holes(_Space(contours, apart), list(range(len(contours))), rules)


def _holes(space: "_Space", members: list[int], rules: str | Sequence[str]) -> tuple[int, ...]:
    """The holes of :func:`cut_holes` among the contours ``members`` of ``space`` (their indices there)."""
    areas = np.stack([_signed_areas(space.rings[i][:, :-1]) for i in members], axis=1)  # (F, M)
    every = np.concatenate([space.rings[i].reshape(-1, 2) for i in members])
    least = 1e-9 * max(float(np.abs(every).max()), 1.0) ** 2
    rule_at = [rules] * len(areas) if isinstance(rules, str) else list(rules)
    out = []
    for k, h in enumerate(members):
        others = [(n, j) for n, j in enumerate(members) if j != h]
        if any(space.close(h, j) for _, j in others):
            continue
        for f in range(len(areas)):
            if abs(areas[f, k]) <= least:
                continue
            if any(space.holds(h, j, f) for _, j in others):
                break
            around = [n for n, j in others if space.holds(j, h, f)]
            if rule_at[f] == "evenodd":
                if len(around) % 2 != 1:
                    break
            else:
                outside = int(sum(np.sign(areas[f, n]) for n in around))
                if outside == 0 or outside + int(np.sign(areas[f, k])) != 0:
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
        self._close: dict[tuple[int, int], bool] = {}

    def close(self, i: int, j: int) -> bool:
        """Whether contours ``i`` and ``j`` come within ``apart`` of each other (or cross) at some frame: then a
        point of ``i``'s edges, cut into steps, lies within the reach of ``j``'s edges (a contour too long to look
        at so closely counts as coming near). Measured once a pair, a few frames at a time, spread over the clip
        first: the first frame where they meet settles it."""
        pair = (min(i, j), max(i, j))
        found = self._close.get(pair)
        if found is None:
            found = self._measure(*pair)
            self._close[pair] = found
        return found

    def _measure(self, i: int, j: int) -> bool:
        at = np.flatnonzero(self.boxes[:, i, j])
        if not len(at):
            return False
        points = self._densified(i)
        if points is None:
            return True
        order = np.concatenate([at[k::_SPREAD] for k in range(_SPREAD)])  # every _SPREAD-th frame first
        for start in range(0, len(order), _SPREAD):
            frames = order[start:start + _SPREAD]
            if float(distance_to_polyline(points[frames], self.rings[j][frames]).min()) <= self.reach:
                return True
        return False

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
