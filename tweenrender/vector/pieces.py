"""Which contours of a run stay apart from the others at every frame, so a file may draw them as paths of their own.

Drawn as one path, a run's contours are filled together under its fill rule: a contour inside another may
make a hole, two that cross may cancel where they overlap. Drawn apart, each path is filled alone. The two
agree wherever no contour of one path comes near, crosses or lies inside a contour of another at any frame:
each path then covers pixels no other covers, however it is filled, stroked or antialiased.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from ..core.contours import inside
from .curves import distance_to_polyline

__all__ = ["apart_pieces", "MOST_CONTOURS"]

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
    frames = len(contours[0])
    step = apart  # points of each edge this far apart at most: a crossing passes within half a step of one
    reach = apart + 0.5 * step
    low = np.stack([c.min(axis=1) for c in contours], axis=1) - reach  # (F, C, 2)
    high = np.stack([c.max(axis=1) for c in contours], axis=1) + reach
    near = np.zeros((frames, count, count), dtype=bool)  # boxes that meet, frame by frame
    for f in range(frames):
        near[f] = np.all((low[f][:, None] <= high[f][None]) & (low[f][None] <= high[f][:, None]), axis=-1)
    group = list(range(count))

    def root(i: int) -> int:
        while group[i] != i:
            group[i] = group[group[i]]
            i = group[i]
        return i

    rings = [np.concatenate([c, c[:, :1]], axis=1) for c in contours]
    dense: dict[int, Array | None] = {}
    for i, j in zip(*np.nonzero(np.triu(near.any(axis=0), 1))):
        i, j = int(i), int(j)
        if root(i) == root(j):
            continue
        at = np.flatnonzero(near[:, i, j])
        if _meet(rings, dense, i, j, at, step, reach):
            a, b = root(i), root(j)
            group[max(a, b)] = min(a, b)
    pieces: dict[int, list[int]] = {}
    for i in range(count):
        pieces.setdefault(root(i), []).append(i)
    return tuple(tuple(members) for members in pieces.values())


def _meet(rings: list[Array], dense: dict[int, Array | None], i: int, j: int, at: NDArray[np.intp], step: float,
          reach: float) -> bool:
    """Whether closed contours ``i`` and ``j`` (``rings``, first point repeated at the end) come within ``reach``
    of each other, or one lies inside the other, at one of the frames ``at``."""
    a, b = rings[i][at], rings[j][at]
    # where the two come within ``apart`` (or cross), a point of ``i``'s edges lies within ``reach`` of ``j``'s
    points = _densified(rings, dense, i, step)
    if points is None or float(distance_to_polyline(points[at], b).min()) <= reach:
        return True  # too long to look at closely: taken as meeting
    for f in range(len(at)):
        if len(b[f]) > 3 and bool(inside(a[f, :1], b[f, :-1])[0]):
            return True
        if len(a[f]) > 3 and bool(inside(b[f, :1], a[f, :-1])[0]):
            return True
    return False


def _densified(rings: list[Array], dense: dict[int, Array | None], index: int, step: float) -> Array | None:
    """The points of ring ``index`` ``(F, L + 1, 2)`` with each edge cut into pieces no longer than ``step`` at
    any frame: ``(F, P, 2)`` (kept in ``dense``); None where they would be more than :data:`_MOST_POINTS`."""
    if index in dense:
        return dense[index]
    ring = rings[index]
    edges = np.diff(ring, axis=1)  # (F, L, 2)
    cuts = np.maximum(1, np.ceil(np.linalg.norm(edges, axis=-1).max(axis=0) / step)).astype(np.intp)  # (L,)
    found = None
    if int(cuts.sum()) * len(ring) <= _MOST_POINTS:
        share = np.concatenate([np.arange(n) / n for n in cuts.tolist()])  # (P,)
        start = np.repeat(np.arange(len(cuts)), cuts)
        found = ring[:, start] + share[None, :, None] * edges[:, start]
    dense[index] = found
    return found
