"""Pieces and holes without a partner joined by a slit to a contour that has one (maths §5.17).

In a filled, unstroked element, a closed contour that the other key lacks — a second piece, a hole
— would otherwise grow from a point, and where the element's moving outline leaves it no room
until late in the segment, grow in a few frames (a pop). Joined instead to a neighbour by a
*slit* (an edge walked there and back), it is part of one contour that has a partner and morphs
with it: the slit opens into a channel and the piece or hole is formed along the way.

The joined contour draws exactly what its parts drew: walking a slit there and back adds nothing to
any winding number, so every point is covered as before under either fill rule. A piece is joined
to the nearest outer contour winding its way, a hole to the contour it lies in (the keyhole of a
polygon with a hole); a piece that winds the other way is walked backwards where that draws the same
(even-odd, or a piece clear of every other contour). The slit is the shortest join between the two
outlines that crosses no contour of the key; where there is none, the contour is left to grow.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from numpy.typing import NDArray

from ..contours import inside
from ..geometry import cross, signed_area

__all__ = ["CANDIDATES", "join_alone"]

Array = NDArray[np.float64]

CANDIDATES = 24
"""Joins tried per contour, shortest first, before it is left to grow."""

_PAIRS_CAP = 1_000_000  # vertex pairs measured when looking for the shortest join


def join_alone(contours: Sequence[Array], closed: Sequence[bool], partnered: Sequence[bool], wanted: Sequence[int],
               evenodd: bool, toward: tuple[float, float] | None = None) -> tuple[list[Array], list[bool]]:
    """One key's contours ``(N_i, 2)`` with each closed one of ``wanted`` that has no partner
    (``partnered[i]`` False) joined into a neighbour where it can be: the contours (a joined one's
    neighbour now holds it, in the neighbour's place) and, per contour, whether it was joined into
    another (and is gone). With ``toward`` (a direction), each slit leaves its piece from the vertex
    farthest that way (:func:`_slit`)."""
    n = len(contours)
    points = [np.asarray(c, dtype=np.float64) for c in contours]
    shut = [bool(closed[i]) and len(points[i]) >= 3 and signed_area(points[i]) != 0.0 for i in range(n)]
    parent = _parents(points, shut)
    depth = [_depth(parent, i) for i in range(n)]
    root = list(range(n))  # the contour each one's outline is now part of
    has_partner = [bool(partnered[i]) and shut[i] for i in range(n)]
    joined = [False] * n
    out = list(points)
    alone = sorted((i for i in set(wanted) if shut[i] and not partnered[i]), key=lambda i: (-depth[i], i))
    for u in alone:
        if parent[u] is not None:
            targets = [_find(root, parent[u])]
            if np.sign(signed_area(points[u])) == np.sign(signed_area(points[parent[u]])):
                if not evenodd:
                    continue  # under nonzero it is no hole: walked backwards it would draw differently
                out[u] = out[u][::-1].copy()
        else:
            targets = sorted({_find(root, t) for t in range(n) if parent[t] is None and has_partner[_find(root, t)]
                              and _find(root, t) != u}, key=lambda t: _gap(out[u], out[t]))
            if not targets:
                continue
        for t in targets[:4]:
            piece = out[u]
            if parent[u] is None and np.sign(signed_area(piece)) != np.sign(signed_area(out[t])):
                if not (evenodd or _clear(u, out, root, shut)):
                    continue
                piece = piece[::-1].copy()
            slit = _slit(out[t], piece, [out[k] for k in range(n) if shut[k] and _find(root, k) == k
                                         and k not in (t, u)], toward)
            if slit is None:
                continue
            ti, ui = slit
            out[t] = np.concatenate([out[t][:ti + 1], piece[ui:], piece[:ui + 1], out[t][ti:]])
            root[u], joined[u] = t, True
            has_partner[t] = has_partner[t] or has_partner[u]
            break
    return out, joined


def _parents(points: Sequence[Array], shut: Sequence[bool]) -> list[int | None]:
    """Per contour, the smallest closed contour it lies in (by a vertex and its box), or None."""
    n = len(points)
    boxes = np.array([[*p.min(axis=0), *p.max(axis=0)] if len(p) else [0, 0, 0, 0] for p in points])
    areas = [abs(float(signed_area(p))) if shut[i] else 0.0 for i, p in enumerate(points)]
    out: list[int | None] = []
    for i in range(n):
        best, best_area = None, np.inf
        for j in range(n):
            if j == i or not shut[j] or not len(points[i]) or areas[j] <= areas[i] or areas[j] >= best_area:
                continue
            if not (boxes[j, :2] <= boxes[i, :2]).all() or not (boxes[i, 2:] <= boxes[j, 2:]).all():
                continue
            if inside(points[i][:1], points[j])[0]:
                best, best_area = j, areas[j]
        out.append(best)
    return out


def _depth(parent: Sequence[int | None], i: int) -> int:
    d, k = 0, parent[i]
    while k is not None and d <= len(parent):
        d, k = d + 1, parent[k]
    return d


def _find(root: list[int], i: int) -> int:
    while root[i] != i:
        i = root[i]
    return i


def _gap(a: Array, b: Array) -> float:
    """The least distance between a vertex of ``a (N, 2)`` and one of ``b (M, 2)`` (on a subsample of
    each where both are long)."""
    return float(np.sqrt(_distances(a, b)[0].min()))


def _distances(a: Array, b: Array) -> tuple[Array, Array, Array]:
    """Squared distances ``(N', M')`` between subsampled vertices of ``a`` and ``b``, with the indices
    ``(N',)``, ``(M',)`` of the vertices measured."""
    step = max(1, int(np.ceil(np.sqrt(len(a) * len(b) / _PAIRS_CAP))))
    ia, ib = np.arange(0, len(a), step), np.arange(0, len(b), step)
    d = a[ia, None, :] - b[None, ib, :]
    return (d * d).sum(axis=2), ia, ib


def _clear(u: int, out: Sequence[Array], root: list[int], shut: Sequence[bool]) -> bool:
    """Whether contour ``u``'s outline (with what is joined into it) shares its box with no other contour:
    walked backwards, it then draws the same under nonzero."""
    lo, hi = out[u].min(axis=0), out[u].max(axis=0)
    for k, p in enumerate(out):
        if k == u or not shut[k] or _find(root, k) == u or _find(root, k) != k:
            continue
        if (p.min(axis=0) <= hi).all() and (lo <= p.max(axis=0)).all():
            return False
    return True


def _slit(target: Array, piece: Array, others: Sequence[Array], toward: tuple[float, float] | None = None
          ) -> tuple[int, int] | None:
    """The shortest join from a vertex of ``target (N, 2)`` to one of ``piece (M, 2)`` that crosses
    no edge of either or of ``others``: their vertex indices, or None. With ``toward`` (a direction
    ``(dx, dy)``), the join leaves from the piece's vertex farthest that way (from its vertex mean) to the
    nearest vertex of ``target`` it reaches so."""
    walls = [target, piece, *others]
    starts = np.concatenate(walls)
    ends = np.concatenate([np.roll(w, -1, axis=0) for w in walls])
    if toward is not None:
        ui = int(np.argmax((piece - piece.mean(axis=0)) @ np.asarray(toward, dtype=np.float64)))
        gaps = ((target - piece[ui]) ** 2).sum(axis=1)
        candidates = [(int(ti), ui) for ti in np.argsort(gaps, kind="stable")[:CANDIDATES]]
    else:
        squared, it, ip = _distances(target, piece)
        candidates = [(int(it[flat // len(ip)]), int(ip[flat % len(ip)]))
                      for flat in np.argsort(squared, axis=None)[:CANDIDATES]]
    for ti, ui in candidates:
        if not _crosses(target[ti], piece[ui], starts, ends):
            return ti, ui
    return None


def _crosses(p: Array, q: Array, starts: Array, ends: Array) -> bool:
    """Whether segment ``p q`` crosses any of the edges ``starts (E, 2) → ends (E, 2)`` at a point
    inside both (touching at ``p`` or ``q`` allowed)."""
    d1 = cross(q - p, starts - p)
    d2 = cross(q - p, ends - p)
    d3 = cross(ends - starts, p - starts)
    d4 = cross(ends - starts, q - starts)
    proper = (d1 * d2 < 0.0) & (d3 * d4 < 0.0)
    # an edge's vertex lying on the slit's inside also blocks it
    span = q - p
    length2 = float(span @ span)
    if length2 == 0.0:
        return bool(proper.any())
    s = ((starts - p) @ span) / length2
    on = (np.abs(d1) <= 1e-12 * length2) & (s > 1e-9) & (s < 1.0 - 1e-9)
    return bool(proper.any() or on.any())
