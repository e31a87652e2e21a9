"""Where and when a contour without a partner grows or shrinks so that it meets no other (maths §5.17).

A contour that only one key has grows from (shrinks to) a point. Scaled about its partner-side anchor
over the whole segment it may cross the contours that move meanwhile: an outline that still covers
the place where a new piece belongs, a piece swept over by a shape on its way. So each such contour
(with the contours it holds in its key, which come and go with it as one group) is placed by a search
over a grid of eased ``t``: for each candidate *point* — the partner-side anchor first, then the
deepest point inside the contour, its centre of area, and the point inside it farthest from where the
other contours start (for an open stroke: its middle vertex, its centre of length, its ends) — the earliest *start* (the latest *stop*, for
one that shrinks) from which, scaled about that point with its area linear in ``t`` over the rest of
the segment, it touches no other contour of the element at any grid time and keeps the nesting it
has in its key. The first candidate point with the earliest start wins; where none is clear before
:data:`LATEST`, the contour keeps its anchor and the whole segment (and the measures say it tangles).
Groups are placed largest first, each clear of those placed before it; where one is left without a
clear start, the stuck ones are placed first instead, if that leaves fewer stuck. The checks a
placement makes are counted (:data:`BUDGET`), so a drawing of many pieces costs a bounded time.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Sequence

import numpy as np
from numpy.typing import NDArray

from ..contours import centre_of_area, inside
from ..geometry import bounding_boxes, signed_area
from ..memo import Remembered
from ..tangles import _relation, proper_crossings

__all__ = ["GRID", "LATEST", "Growth", "place", "deepest_point", "farthest_point", "growth_scale"]

Array = NDArray[np.float64]

GRID = np.linspace(0.0, 1.0, 26)
"""The eased t at which a placement is checked against the other contours."""

STARTS = np.round(np.arange(0.0, 0.86, 0.05), 2)
"""The starts tried, earliest first (for one that shrinks, 1 - the stop)."""

LATEST = float(STARTS[-1])
"""The latest start tried: a contour that cannot grow clear of the others in the last 15 % of the segment
grows over all of it."""

_PROBE_CELLS = 24  # grid cells across a contour's box when looking for its deepest point
_FAR_POINTS = 512  # the other contours' points a farthest point is measured from, at most (evenly picked)
BUDGET = 200_000
"""The work a placement may do in all, in vertices checked (a group and the contours whose boxes meet
its box, at one grid time, for each check); the groups left when it is spent come from their anchors
over the whole segment, so a drawing of many pieces costs a bounded time."""


@dataclass(frozen=True, slots=True)
class Growth:
    """How one contour without a partner comes (``grows``) or goes: scaled about ``point (2,)``, its
    area linear in the eased ``t`` from ``start`` to ``stop`` (0 before, full after, when growing)."""

    point: Array
    grows: bool
    start: float = 0.0
    stop: float = 1.0
    stuck: bool = False  # searched, and no start up to LATEST is clear: it meets another contour as it comes


def growth_scale(growth: Growth, t: Array) -> Array:
    """The scale of a contour placed by ``growth`` at eased parameters ``t (T,)``: ``(T,)`` in [0, 1]
    (held at 0 outside [0, 1] too: an overshooting easing never turns it inside out)."""
    share = (np.asarray(t, dtype=np.float64) - growth.start) / (growth.stop - growth.start)
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
    boxes = bounding_boxes(shapes)
    holder: list[int] = list(range(len(shapes)))
    for j, inner in enumerate(shapes):
        # inside another needs its box within the other's
        boxed = np.flatnonzero(np.all(boxes[:, :2] <= boxes[j, :2], axis=1)
                               & np.all(boxes[j, 2:] <= boxes[:, 2:], axis=1))
        around = [i for i in boxed.tolist()
                  if i != j and closed[i] and grows[i] == grows[j] and area[i] > area[j]
                  and len(shapes[i]) >= 3 and bool(np.all(inside(inner, shapes[i])))]
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
    done_lo: list[Array] = []  # (G, 2): their boxes at each grid time
    done_hi: list[Array] = []
    fixed = _Around.of(list(others), [bool(c) for c in others_closed])  # boxed once for every group
    for group in groups:
        root = group[0]
        forward = grows[root]
        members = [np.asarray(shapes[m], dtype=np.float64) for m in group]
        member_closed = [bool(closed[m]) and len(shapes[m]) >= 3 for m in group]
        # search in the direction of growth: a shrinking group's times run backwards
        seen = [f if forward else f[::-1] for f in list(others) + done_frames]
        lo = np.concatenate([fixed.lo, np.stack(done_lo, axis=1)], axis=1) if done_lo else fixed.lo
        hi = np.concatenate([fixed.hi, np.stack(done_hi, axis=1)], axis=1) if done_hi else fixed.hi
        around = _Around(seen, fixed.closed + done_closed, lo if forward else lo[::-1], hi if forward else hi[::-1])
        final = _final_relations(members, member_closed, around)
        candidates = [np.asarray(anchors[root], dtype=np.float64)]
        if member_closed[0]:
            candidates += [deepest_point(members[0]), centre_of_area([members[0]], [True])]
            first = [o[0] for o in seen if len(o[0])]
            if first:
                candidates.append(farthest_point(members[0], np.concatenate(first)))
        elif len(members[0]):  # a stroke: its middle, its centre of length, its ends
            stroke = members[0]
            candidates += [stroke[len(stroke) // 2], centre_of_area([stroke], [False]), stroke[0], stroke[-1]]
        best: tuple[float, Array] | None = None
        for point in candidates:
            limit = LATEST if best is None else best[0] - 1e-9
            start = _earliest(point, members, member_closed, around, final, limit, budget)
            if start is not None and (best is None or start < best[0]):
                best = (start, point)
            if best is not None and best[0] == 0.0:
                break
        searched = budget[0] > 0  # else the search was cut short: whether it would meet one is not known
        if best is None:
            stuck.add(root)
        start, point = best if best is not None else (0.0, candidates[0])
        met = best is None and searched
        growth = Growth(point, forward, start, 1.0, met) if forward else Growth(point, False, 0.0, 1.0 - start, met)
        scale = growth_scale(growth, GRID)[:, None, None]
        for m, member in zip(group, members):
            placed[m] = growth
            done_frames.append(point + scale * (member - point))
            done_closed.append(bool(closed[m]) and len(member) >= 3)
            done_lo.append(done_frames[-1].min(axis=1))
            done_hi.append(done_frames[-1].max(axis=1))
    return placed, stuck  # type: ignore[return-value]


def _final_relations(members: list[Array], member_closed: list[bool], around: _Around) -> NDArray[np.int8]:
    """How each of closed ``members (L_m, 2)`` lies against each closed contour ``around`` at the last grid
    time (1 member inside, -1 other inside member, 0 neither, or either one open): ``(M, O)``. Only the
    pairs with one box within the other are tested."""
    out = np.zeros((len(members), len(around.frames)), dtype=np.int8)
    lo, hi = around.lo[-1], around.hi[-1]  # (O, 2)
    shut = np.array(around.closed, dtype=bool)
    for m, (member, member_shut) in enumerate(zip(members, member_closed)):
        if not member_shut or not len(member):
            continue
        m_lo, m_hi = member.min(axis=0), member.max(axis=0)
        within = (np.all(m_lo >= lo, axis=1) & np.all(m_hi <= hi, axis=1)) | \
            (np.all(lo >= m_lo, axis=1) & np.all(hi <= m_hi, axis=1))
        for o in np.flatnonzero(within & shut).tolist():
            out[m, o] = _relation(member[None], around.frames[o][-1][None])[0]
    return out


def _earliest(point: Array, members: list[Array], member_closed: list[bool], around: _Around,
              final: NDArray[np.int8], limit: float, budget: list[int]) -> float | None:
    """The earliest of :data:`STARTS` (up to ``limit``) from which ``members`` scaled about ``point``
    stay clear of the contours ``around``, or None (also once ``budget[0]`` checks are spent, counting
    down). The grid time at which a start failed is tried first for the next one (where one start
    meets a contour, the next mostly does too)."""
    own = sum(len(m) for m in members)
    sizes = np.array([f.shape[1] for f in around.frames], dtype=np.int64)
    lo = np.array([m.min(axis=0) for m in members])  # (M, 2): a scaled contour's box is its box scaled
    hi = np.array([m.max(axis=0) for m in members])
    failed: list[int] = []
    for start in STARTS[STARTS <= limit + 1e-12].tolist():
        times = np.flatnonzero(GRID > start).tolist()
        order = [k for k in failed if k in times] + times
        for k in order:
            if budget[0] <= 0:
                return None
            s = np.sqrt((GRID[k] - start) / (1.0 - start))
            now_lo, now_hi = point + s * (lo - point), point + s * (hi - point)
            meets = (np.all(now_lo[:, None] <= around.hi[k][None], axis=2)
                     & np.all(around.lo[k][None] <= now_hi[:, None], axis=2))
            budget[0] -= own + int(sizes[meets.any(axis=0)].sum())  # the contours whose boxes meet are tested
            if not _clear([point + s * (m - point) for m in members], member_closed, around, k, meets, final):
                failed = [k]
                break
        else:
            return float(start)
    return None


_placed: Remembered[list[Growth]] = Remembered(256)


def cached(key: bytes, compute: Callable[[], list[Growth]]) -> list[Growth]:
    """``compute()`` for ``key`` (a digest of what it depends on), remembered for the last few asked."""
    return _placed.get(key, compute)
