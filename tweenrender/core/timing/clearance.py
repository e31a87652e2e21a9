"""Where and when a contour without a partner grows or shrinks so that it meets no other (maths §5.17).

A contour that only one key has grows from (shrinks to) a point. Scaled about its partner-side anchor
over the whole segment it may cross the contours that move meanwhile: an outline that still covers
the place where a new piece belongs, a piece swept over by a shape on its way. So each such contour
(with the contours it holds in its key, which come and go with it as one group) is placed by a search
over a grid of eased ``t``: for each candidate *point* — the partner-side anchor first, then the
deepest point inside the contour, its centre of area, and the point inside it farthest from where the
other contours start (for an open stroke: its middle vertex, its centre of length, its ends) — the
*room* at each grid time: the largest share of its area that, scaled about that point, touches no
other contour of the element and keeps the nesting it has in its key, there and at the grid time
before (what sweeps over it in between is then on its other side). Its area follows the greatest
convex profile under the room (:func:`_profile`): the most even growth clear of the others, whose
fastest step is the least any can have (a shrinking one: the same, time reversed). The candidate
with the least fastest step wins; where every one would need over :data:`STEEPEST` (all its area in
the last 15 % of the segment), the contour keeps its anchor and the whole segment (and the measures
say it tangles).
Groups are placed largest first, each clear of those placed before it; where one is left without a
clear start, the stuck ones are placed first instead, if that leaves fewer stuck. The checks a
placement makes are counted (:data:`BUDGET`), so a drawing of many pieces costs a bounded time.
"""

from __future__ import annotations

from collections import OrderedDict
from dataclasses import dataclass
from typing import Callable, Sequence

import numpy as np
from numpy.typing import NDArray

from ..contours import centre_of_area, inside
from ..geometry import signed_area
from ..tangles import _relation, proper_crossings

__all__ = ["GRID", "LATEST", "STEEPEST", "Growth", "place", "deepest_point", "farthest_point", "growth_scale"]

Array = NDArray[np.float64]

GRID = np.linspace(0.0, 1.0, 26)
"""The eased t at which a placement is checked against the other contours."""

LATEST = 0.85
"""A contour that would have to gain all its area after this t (or lose it before ``1 - LATEST``) ..."""

STEEPEST = 1.0 / (1.0 - LATEST)
"""... that is, faster than this share of its area per unit of t (1 is evenly over the whole segment),
grows about its anchor over the whole segment instead."""

_BISECTIONS = 6  # halvings of the share a grid time allows, where it sets the rate

_PROBE_CELLS = 24  # grid cells across a contour's box when looking for its deepest point
_FAR_POINTS = 512  # the other contours' points a farthest point is measured from, at most (evenly picked)
BUDGET = 200_000
"""The work a placement may do in all, in vertices checked (a group and every contour it is checked
against, at one grid time, for each check); the groups left when it is spent come from their anchors
over the whole segment, so a drawing of many pieces costs a bounded time."""


@dataclass(frozen=True, slots=True)
class Growth:
    """How one contour without a partner comes (``grows``) or goes: scaled about ``point (2,)``, its
    area linear in the eased ``t`` from ``start`` to ``stop`` (0 before, full after, when growing)."""

    point: Array
    grows: bool
    start: float = 0.0
    stop: float = 1.0
    shares: Array | None = None
    """Where set, ``(G,)``: the share of its area it has at each :data:`GRID` time counted in the direction
    of growth (0 first, 1 last; for one that shrinks, at ``1 - t``), linear between them; ``start`` and
    ``stop`` are then where it starts and ends changing."""


def growth_scale(growth: Growth, t: Array) -> Array:
    """The scale of a contour placed by ``growth`` at eased parameters ``t (T,)``: ``(T,)`` in [0, 1]
    (never below 0 outside [0, 1]: an overshooting easing never turns it inside out)."""
    t = np.asarray(t, dtype=np.float64)
    if growth.shares is not None:
        x = t if growth.grows else 1.0 - t
        rate = (growth.shares[-1] - growth.shares[-2]) / (GRID[-1] - GRID[-2])  # past its key it goes on
        return np.sqrt(np.where(x > 1.0, 1.0 + rate * (x - 1.0), np.interp(x, GRID, growth.shares)))
    share = (t - growth.start) / (growth.stop - growth.start)
    if not growth.grows:
        share = 1.0 - share
    return np.sqrt(np.clip(share, 0.0, None))


def deepest_point(contour: Array) -> Array:
    """A point well inside closed ``contour (N, 2)``: of a grid over its box, the inside point farthest
    from its outline (its centre of area where no grid point is inside): ``(2,)``."""
    grid = _inside_grid(contour)
    if not len(grid):
        return centre_of_area([contour], [True])
    a, b = contour, np.roll(contour, -1, axis=0)
    edge = b - a
    length2 = np.maximum((edge * edge).sum(axis=1), 1e-300)
    s = np.clip(((grid[:, None, :] - a) * edge).sum(axis=2) / length2, 0.0, 1.0)
    gap = np.hypot(*(grid[:, None, :] - a - s[..., None] * edge).transpose(2, 0, 1)).min(axis=1)
    return grid[int(np.argmax(gap))]


def farthest_point(contour: Array, others: Array) -> Array:
    """Of a grid inside closed ``contour (N, 2)``, the point farthest from the points ``others (M, 2)``
    (where the other contours are when it starts to grow): ``(2,)``; its centre of area without one."""
    grid = _inside_grid(contour)
    if not len(grid):
        return centre_of_area([contour], [True])
    if len(others) > _FAR_POINTS:
        others = others[np.linspace(0, len(others) - 1, _FAR_POINTS).astype(np.intp)]
    gap = np.hypot(*(grid[:, None, :] - others[None]).transpose(2, 0, 1)).min(axis=1)
    return grid[int(np.argmax(gap))]


def _inside_grid(contour: Array) -> Array:
    """The points of a grid of :data:`_PROBE_CELLS` cells across ``contour``'s box that lie inside it: ``(P, 2)``."""
    lo, hi = contour.min(axis=0), contour.max(axis=0)
    steps = [np.linspace(lo[k], hi[k], _PROBE_CELLS + 1)[1:-1] for k in range(2)]
    grid = np.stack(np.meshgrid(*steps), axis=-1).reshape(-1, 2)
    return grid[inside(grid, contour)] if len(contour) >= 3 else grid[:0]


def _groups(shapes: Sequence[Array], closed: Sequence[bool], grows: Sequence[bool]) -> list[list[int]]:
    """The contours without a partner in groups that come and go together: each outermost one with the
    ones (coming or going the same way) inside it in its key; largest groups first."""
    area = [abs(signed_area(s)) if c and len(s) >= 3 else 0.0 for s, c in zip(shapes, closed)]
    holder: list[int] = list(range(len(shapes)))
    for j, inner in enumerate(shapes):
        around = [i for i, outer in enumerate(shapes)
                  if i != j and closed[i] and grows[i] == grows[j] and area[i] > area[j]
                  and len(outer) >= 3 and bool(np.all(inside(inner, outer)))]
        if around:
            holder[j] = max(around, key=lambda i: area[i])
    roots = sorted({holder[j] for j in range(len(shapes))}, key=lambda i: -area[i])
    return [[r] + [j for j in range(len(shapes)) if holder[j] == r and j != r] for r in roots]


@dataclass(frozen=True, slots=True)
class _Around:
    """The other contours a group must keep clear of, at every :data:`GRID` time in the direction of
    growth: ``frames[j] (G, M_j, 2)``, which are ``closed``, and their boxes ``lo``, ``hi`` ``(G, O, 2)``."""

    frames: list[Array]
    closed: list[bool]
    lo: Array
    hi: Array

    @staticmethod
    def of(frames: list[Array], closed: list[bool]) -> "_Around":
        if not frames:
            empty = np.zeros((len(GRID), 0, 2))
            return _Around(frames, closed, empty, empty)
        return _Around(frames, closed, np.stack([f.min(axis=1) for f in frames], axis=1),
                       np.stack([f.max(axis=1) for f in frames], axis=1))


def _clear(members: list[Array], member_closed: list[bool], around: _Around, k: int, meets: NDArray[np.bool_],
           relations: NDArray[np.int8]) -> bool:
    """Whether contours ``members`` touch none of the contours ``around`` at grid time ``k`` and keep
    ``relations`` ``(M, O)`` with them (1 member inside other, -1 other inside member, 0 neither;
    closed pairs only); ``meets (M, O)``: whose boxes meet."""
    near = meets.any(axis=0)
    if np.any(relations[:, ~near] != 0):
        return False
    others = np.flatnonzero(near).tolist()
    for o in others:
        other = around.frames[o][k]
        for m, member in enumerate(members):
            if member_closed[m] and around.closed[o]:
                now = int(_relation(member[None], other[None])[0]) if meets[m, o] else 0
                if now != relations[m, o]:
                    return False
    if not others:
        return True
    count = len(members)
    # a vertex and its copies (balancing stacks them) are one point: their zero-length edges would only
    # send every orientation test to exact arithmetic
    touching = proper_crossings([_distinct(m) for m in members] + [_distinct(around.frames[o][k]) for o in others],
                                list(member_closed) + [around.closed[o] for o in others], touching=True)
    return not any(c < count <= d for c, d in touching)


def _distinct(points: Array) -> Array:
    """``points (L, 2)`` without a vertex equal to the one before it: ``(L', 2)``, L' ≥ 1."""
    if len(points) < 2:
        return points
    keep = np.ones(len(points), dtype=bool)
    keep[1:] = np.any(points[1:] != points[:-1], axis=1)
    return points[keep]


def place(shapes: Sequence[Array], closed: Sequence[bool], grows: Sequence[bool], anchors: Sequence[Array],
          others: Sequence[Array], others_closed: Sequence[bool]) -> list[Growth]:
    """Growths for contours without a partner, ``shapes[i] (L_i, 2)`` as their key draws them, that
    keep clear of the element's moving contours ``others[j] (G, M_j, 2)`` (at :data:`GRID`) and of one
    another: one :class:`Growth` per shape (``anchors[i] (2,)``: where it would come from unplaced)."""
    groups = _groups(shapes, closed, grows)
    budget = [BUDGET]  # vertices left to check, for both orders
    placed, stuck = _place_in(groups, shapes, closed, grows, anchors, others, others_closed, budget)
    if stuck and budget[0] > 0:  # a group placed later had no room left: place the stuck ones first
        again, still = _place_in([g for g in groups if g[0] in stuck] + [g for g in groups if g[0] not in stuck],
                                 shapes, closed, grows, anchors, others, others_closed, budget)
        if len(still) < len(stuck):
            placed = again
    return placed


def _place_in(groups: list[list[int]], shapes: Sequence[Array], closed: Sequence[bool], grows: Sequence[bool],
              anchors: Sequence[Array], others: Sequence[Array], others_closed: Sequence[bool], budget: list[int]
              ) -> tuple[list[Growth], set[int]]:
    """:func:`place` with the groups placed in the order given (``budget[0]``: vertices left to check,
    counted down): the growths, and the roots of the groups that found no clear start (left at their
    anchor over the whole segment)."""
    placed: list[Growth | None] = [None] * len(shapes)
    stuck: set[int] = set()
    done_frames: list[Array] = []  # (G, L, 2) of the groups placed so far
    done_closed: list[bool] = []
    for group in groups:
        root = group[0]
        forward = grows[root]
        members = [np.asarray(shapes[m], dtype=np.float64) for m in group]
        member_closed = [bool(closed[m]) and len(shapes[m]) >= 3 for m in group]
        # search in the direction of growth: a shrinking group's times run backwards
        seen = [f if forward else f[::-1] for f in list(others) + done_frames]
        around = _Around.of(seen, [bool(c) for c in list(others_closed) + done_closed])
        final = np.array([[int(_relation(m[None], o[-1][None])[0]) if mc and oc else 0
                           for o, oc in zip(seen, around.closed)] for m, mc in zip(members, member_closed)],
                         dtype=np.int8).reshape(len(members), len(seen))
        candidates = [np.asarray(anchors[root], dtype=np.float64)]
        if member_closed[0]:
            candidates += [deepest_point(members[0]), centre_of_area([members[0]], [True])]
            first = [o[0] for o in seen if len(o[0])]
            if first:
                candidates.append(farthest_point(members[0], np.concatenate(first)))
        elif len(members[0]):  # a stroke: its middle, its centre of length, its ends
            stroke = members[0]
            candidates += [stroke[len(stroke) // 2], centre_of_area([stroke], [False]), stroke[0], stroke[-1]]
        best: tuple[float, Array, Array] | None = None  # steepest rate, shares, point
        for point in candidates:
            limit = STEEPEST if best is None else best[0] - 1e-9
            found = _profile(point, members, member_closed, around, final, limit, budget)
            if found is not None:
                best = (found[0], found[1], point)
                if found[0] <= 1.0 + 1e-9:  # as even as it gets: its area linear over the whole segment
                    break
        if best is None:
            stuck.add(root)
            growth = Growth(candidates[0], forward)
        else:
            _, shares, point = best
            moving = np.flatnonzero((shares > 0.0) & (shares < 1.0))
            begin = float(GRID[max(int(moving[0]) - 1, 0)]) if len(moving) else 0.0
            end = float(GRID[min(int(moving[-1]) + 1, len(GRID) - 1)]) if len(moving) else 1.0
            start, stop = (begin, end) if forward else (1.0 - end, 1.0 - begin)
            growth = Growth(point, forward, start, stop, shares)
        scale = growth_scale(growth, GRID)[:, None, None]
        point = growth.point
        for m, member in zip(group, members):
            placed[m] = growth
            done_frames.append(point + scale * (member - point))
            done_closed.append(bool(closed[m]) and len(member) >= 3)
    return placed, stuck  # type: ignore[return-value]


def _profile(point: Array, members: list[Array], member_closed: list[bool], around: _Around,
             final: NDArray[np.int8], limit: float, budget: list[int]) -> tuple[float, Array] | None:
    """How ``members`` grow about ``point`` clear of the contours ``around``, as evenly as they can:
    the share of their area at each :data:`GRID` time ``(G,)`` (0 first, 1 last), and its steepest rate
    (share per unit of t, ≥ 1), or None where that is over ``limit`` (also once ``budget[0]`` checks are
    spent, counting down).

    From the last grid time back, the *room*: the largest share each time allows (clear there and at the
    grid time before, and no more than the next time's: the area never shrinks while growing), found by
    bisection. The shares are the greatest convex profile under the room from 0 to 1 (:func:`_under`): of
    all the profiles under it, the one whose steepest rate, ``max (1 − room) / (1 − t)``, is least, and
    the most even (the taut string). Each share is checked at its time."""
    cost = sum(len(m) for m in members) + sum(f.shape[1] for f in around.frames)
    lo = np.array([m.min(axis=0) for m in members])  # (M, 2): a scaled contour's box is its box scaled
    hi = np.array([m.max(axis=0) for m in members])
    last = len(GRID) - 1

    def clear(k: int, share: float) -> bool | None:
        if share <= 0.0:
            return True  # a point draws nothing
        if budget[0] <= 0:
            return None
        budget[0] -= cost
        s = np.sqrt(share)
        now_lo, now_hi = point + s * (lo - point), point + s * (hi - point)
        meets = (np.all(now_lo[:, None] <= around.hi[k][None], axis=2)
                 & np.all(around.lo[k][None] <= now_hi[:, None], axis=2))
        scaled = [point + s * (m - point) for m in members]
        if not _clear(scaled, member_closed, around, k, meets, final):
            return False
        # and as large, clear of where the others were at the grid time before: between the two it is
        # no larger, and what sweeps over it in between is on its other side then
        budget[0] -= cost
        meets = (np.all(now_lo[:, None] <= around.hi[k - 1][None], axis=2)
                 & np.all(around.lo[k - 1][None] <= now_hi[:, None], axis=2))
        return _clear(scaled, member_closed, around, k - 1, meets, final)

    room = np.ones(len(GRID))
    room[0] = 0.0
    rate = 1.0
    for k in range(last - 1, 0, -1):
        cap = room[k + 1]
        ok = clear(k, cap)
        if ok is None:
            return None
        if not ok:
            # first whether it has the room the steepest rate so far needs (then it only evens the
            # profile, found roughly), else how much less (that sets the rate, found finely)
            needed = min(max(0.0, 1.0 - rate * (1.0 - GRID[k])), cap)
            ok = clear(k, needed) if needed > 0.0 else False
            if ok is None:
                return None
            below, above, halvings = (needed, cap, _BISECTIONS // 2) if ok else (0.0, needed, _BISECTIONS)
            for _ in range(halvings if above > below else 0):
                middle = 0.5 * (below + above)
                ok = clear(k, middle)
                if ok is None:
                    return None
                below, above = (middle, above) if ok else (below, middle)
            cap = below
        room[k] = cap
        rate = max(rate, (1.0 - cap) / (1.0 - GRID[k]))
        if rate > limit:
            return None
    shares = _under(room)
    for k in range(1, last):
        if 0.0 < shares[k] < room[k]:  # under a share found clear, but clear only where it is checked
            ok = clear(k, float(shares[k]))
            if not ok:
                return None
    return rate, shares


def _under(room: Array) -> Array:
    """The greatest convex function of :data:`GRID` under ``room (G,)`` (with ``room[0] = 0`` and
    ``room[-1] = 1``), at the grid times: ``(G,)``, rising from 0 to 1 (the lower convex hull)."""
    hull: list[int] = []
    for k in range(len(GRID)):
        while len(hull) >= 2:
            i, j = hull[-2], hull[-1]
            # j lies on or above the chord from i to k: not a corner of the lower hull
            if (room[j] - room[i]) * (GRID[k] - GRID[i]) >= (room[k] - room[i]) * (GRID[j] - GRID[i]):
                hull.pop()
            else:
                break
        hull.append(k)
    return np.interp(GRID, GRID[hull], room[hull])


_cache: OrderedDict[bytes, list[Growth]] = OrderedDict()
_CACHED = 256


def cached(key: bytes, compute: Callable[[], list[Growth]]) -> list[Growth]:
    """``compute()`` for ``key`` (a digest of what it depends on), remembered for the last few asked."""
    found = _cache.get(key)
    if found is not None:
        _cache.move_to_end(key)
        return found
    value = compute()
    _cache[key] = value
    while len(_cache) > _CACHED:
        _cache.popitem(last=False)
    return value
