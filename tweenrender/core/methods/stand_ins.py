"""Stand-ins: where a contour without a partner sits, small, in the key that lacks it (maths §5.17).

The injective paths (:mod:`.injective`) hold every contour in one compatible mesh, so none crosses
another at any t; a contour that grows (shrinks) has no contour in one key to mesh. Its *stand-in*
there is a small copy of it, scaled about its centre by ``ε`` and moved to a point ``p`` of the face
it must be in: inside the same partnered closed contours (even-odd) as the contour itself in the
key that has it, so the two keys nest alike. Contours without a partner nested in one another (a
new piece with its hole) share their outermost one's centre, ``ε`` and ``p``, so their stand-ins
nest as they do. ``p`` is where the partnered contours' compatible mesh carries the contour's centre
(a point inside it), where that has room; else the nearest such point to the centre, among the centre
itself and points just either side of the edges nearest it, with room around it; ``ε`` makes the copy
at most :data:`_SHARE` of that room (and at most :data:`_SMALL` of the contour).
"""

from __future__ import annotations

from typing import Callable, Sequence

import numpy as np
from numpy.typing import NDArray

from ..contours import inside, _probe

__all__ = ["stand_ins"]

Array = NDArray[np.float64]

_SMALL = 0.02  # a stand-in is at most this share of its contour's size
_SHARE = 0.4  # ... and its radius at most this share of the room about its point
_NEAREST = 48  # edges whose foot points (either side) are tried as the stand-in's point
_SIDES = (0.25, 0.05)  # the foot points are moved off their edge by these shares of the room sought
_ROOM = 0.01  # room sought about a point: this share of the drawing's size
_CARRIED = 0.25  # the point the mesh carries a contour's centre to is taken where it has this share of that room


Carry = Callable[[Array, int], "Array | None"]


def stand_ins(paired: Sequence[tuple[Array, Array]], paired_closed: Sequence[bool],
              alone: Sequence[Array], alone_closed: Sequence[bool], grows: Sequence[bool],
              carry: Carry | None = None) -> list[Array] | None:
    """A stand-in ``(L_i, 2)`` for each contour without a partner ``alone[i] (L_i, 2)``, in the key that
    lacks it (key 0 where ``grows[i]``, else key 1), given the partnered contours ``paired[j]`` (its
    ``(M_j, 2)`` in key 0 and in key 1); None where one has no room in its face. ``carry(points (P, 2),
    key)`` says where points of one key are in the other by the partnered contours' mesh (None where it
    cannot): a stand-in goes there first, where it has room, so the mesh carries it least far."""
    out: list[Array | None] = [None] * len(alone)
    for side in (True, False):
        which = [i for i in range(len(alone)) if grows[i] == side]
        if not which:
            continue
        here = [k1 if side else k0 for k0, k1 in paired]
        there = [k0 if side else k1 for k0, k1 in paired]
        move = None if carry is None else (lambda points, key=1 if side else 0: carry(points, key))
        placed = _side(here, there, list(paired_closed), [alone[i] for i in which], [alone_closed[i] for i in which],
                       move)
        if placed is None:
            return None
        for i, found in zip(which, placed):
            out[i] = found
    return out  # type: ignore[return-value]


def _side(here: list[Array], there: list[Array], closed: list[bool], alone: list[Array],
          alone_closed: list[bool], move: Callable[[Array], "Array | None"] | None) -> list[Array] | None:
    """Stand-ins in ``there`` for the contours ``alone`` drawn in ``here`` (partnered contours ``here[j]``
    and ``there[j]``)."""
    shut = [j for j, c in enumerate(closed) if c and len(here[j]) >= 3]
    probes = np.array([_probe(a) if c and len(a) >= 3 else np.asarray(a[0], dtype=np.float64)
                       for a, c in zip(alone, alone_closed)])
    faces = np.array([inside(probes, here[j]) for j in shut]).T.reshape(len(alone), len(shut))
    # the contours without a partner enclosing each one (closed ones, even-odd): its group's root is the outermost
    holders = [[k for k in range(len(alone)) if k != i and alone_closed[k] and len(alone[k]) >= 3
                and inside(probes[i:i + 1], alone[k])[0]] for i in range(len(alone))]
    roots = [min(h + [i], key=lambda k: len(holders[k])) for i, h in enumerate(holders)]
    everything = np.concatenate([np.asarray(c, dtype=np.float64).reshape(-1, 2) for c in here + there + alone])
    size = float(np.ptp(everything, axis=0).max()) or 1.0
    segments = _segments(there, closed)
    out: list[Array | None] = [None] * len(alone)
    groups = sorted(set(roots))
    carried = move(probes[groups]) if move is not None else None
    for g, root in enumerate(groups):
        group = [i for i in range(len(alone)) if roots[i] == root]
        points = np.concatenate([np.asarray(alone[i], dtype=np.float64) for i in group])
        centre = probes[root]
        radius = float(np.hypot(*(points - centre).T).max())
        found = None
        if carried is not None:
            found = _point(carried[g], faces[root], there, shut, segments, _ROOM * size, search=False)
            if found is not None and found[1] < _CARRIED * _ROOM * size:
                found = None
        if found is None:
            found = _point(centre, faces[root], there, shut, segments, _ROOM * size)
        if found is None:
            return None
        point, room = found
        if radius == 0.0:
            scale = 0.0
        else:
            scale = min(_SMALL, _SHARE * room / radius)
        for i in group:
            out[i] = point + scale * (np.asarray(alone[i], dtype=np.float64) - centre)
        mine = [out[i] for i in group]
        segments = np.concatenate([segments, _segments(mine, [alone_closed[i] for i in group])])  # type: ignore[arg-type]
    return out  # type: ignore[return-value]


def _segments(contours: Sequence[Array], closed: Sequence[bool]) -> Array:
    """Every edge of ``contours`` as ``(E, 2, 2)`` (a closed contour's closing edge included)."""
    parts = [np.zeros((0, 2, 2))]
    for c, shut in zip(contours, closed):
        c = np.asarray(c, dtype=np.float64).reshape(-1, 2)
        if len(c) == 1:
            parts.append(np.stack([c, c], axis=1))
            continue
        ends = np.roll(c, -1, axis=0) if shut else c[1:]
        parts.append(np.stack([c[:len(ends)], ends], axis=1))
    return np.concatenate(parts)


def _distances(points: Array, segments: Array) -> Array:
    """Distance from each of ``points (P, 2)`` to the nearest of ``segments (E, 2, 2)``: ``(P,)``."""
    if len(segments) == 0:
        return np.full(len(points), np.inf)
    a, d = segments[:, 0], segments[:, 1] - segments[:, 0]
    rel = points[:, None, :] - a[None]
    length = np.sum(d * d, axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.clip(np.where(length > 0, np.sum(rel * d, axis=2) / length, 0.0), 0.0, 1.0)
    foot = a[None] + s[..., None] * d[None]
    return np.hypot(*(points[:, None, :] - foot).transpose(2, 0, 1)).min(axis=1)


def _point(centre: Array, face: NDArray[np.bool_], there: list[Array], shut: list[int], segments: Array,
           room: float, search: bool = True) -> tuple[Array, float] | None:
    """The nearest point to ``centre (2,)`` inside exactly the closed contours ``face`` says (of ``there``'s
    ``shut`` ones) with room about it, and that room (distance to ``segments``); None where none is found
    (without ``search``, ``centre`` itself or None)."""
    candidates = [centre[None]]
    if len(segments) and search:
        a, d = segments[:, 0], segments[:, 1] - segments[:, 0]
        length = np.sum(d * d, axis=1)
        with np.errstate(divide="ignore", invalid="ignore"):
            s = np.clip(np.where(length > 0, ((centre - a) * d).sum(axis=1) / length, 0.0), 0.0, 1.0)
        foot = a + s[:, None] * d
        near = np.argsort(np.hypot(*(foot - centre).T))[:_NEAREST]
        normal = np.column_stack([-d[near, 1], d[near, 0]])
        norm = np.hypot(*normal.T)
        normal = normal / np.where(norm > 0, norm, 1.0)[:, None]
        for share in _SIDES:
            step = share * room * 4.0
            candidates += [foot[near] + step * normal, foot[near] - step * normal]
    points = np.concatenate(candidates)
    ok = np.ones(len(points), dtype=bool)
    for k, j in enumerate(shut):
        ok &= inside(points, there[j]) == face[k]
    if not ok.any():
        return None
    points = points[ok]
    clear = _distances(points, segments)
    roomy = clear >= room
    pool = np.flatnonzero(roomy) if roomy.any() else np.flatnonzero(clear > 0)
    if len(pool) == 0:
        return None
    best = pool[np.argmin(np.hypot(*(points[pool] - centre).T))]
    return points[best], float(clear[best])
