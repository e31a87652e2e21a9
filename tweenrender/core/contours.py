"""Contours of a key: which are holes, which contour of one key goes with which of the next (maths §5.7).

A closed contour inside an odd number of other closed contours is a *hole*,
else an *outer* outline (nesting decides, whatever the fill rule); an open
contour is a stroke. Contours of consecutive keys are paired by a minimum-cost
assignment within each role — outer with outer, hole with hole, open with
open — on where they sit in their shape and how large they are, never by
drawing order. Two pairs that are nested one way in one key and another way in the
other would have to pass through each other: the smaller is parted
(:func:`keep_nesting`). A contour left without a partner grows from (or shrinks to) an
*anchor*: the point of the partner key's drawing nearest its centre of area (maths §5.17).
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from numpy.typing import NDArray

from .correspondence.assignment import min_cost_assignment
from .geometry import bounding_boxes, boxes_holding, hull_area, signed_area
from .tangles import _relation, proper_crossings

__all__ = ["ROLES", "inside", "roles", "pair_contours", "keep_nesting", "nearest_point", "anchor",
           "anchors", "centre_of_area", "contour_size", "apparent_area"]

Array = NDArray[np.float64]
ROLES = ("outer", "hole", "open")

_SIZE_WEIGHT = 0.7


def inside(points: Array, polygon: Array) -> NDArray[np.bool_]:
    """Whether each of ``points (P, 2)`` lies inside the closed ``polygon (N, 2)`` (even-odd rule): ``(P,)``."""
    x, y = points[:, 0:1], points[:, 1:2]  # (P, 1)
    x0, y0 = polygon[:, 0], polygon[:, 1]  # (N,)
    x1, y1 = np.roll(x0, -1), np.roll(y0, -1)
    crosses = (y0 > y) != (y1 > y)  # (P, N)
    with np.errstate(divide="ignore", invalid="ignore"):
        at = x0 + (y - y0) * (x1 - x0) / (y1 - y0)
    return ((crosses & (x < at)).sum(axis=1) % 2).astype(bool)


def roles(contours: Sequence[Array], closed: Sequence[bool]) -> list[str]:
    """``"outer"``, ``"hole"`` or ``"open"`` for each contour ``(N_i, 2)`` of one key."""
    out = []
    shut = [i for i, c in enumerate(closed) if c and len(contours[i]) >= 3]
    boxes = bounding_boxes([contours[j] for j in shut])  # only a box holding the probe can have it inside
    for i, points in enumerate(contours):
        if not closed[i]:
            out.append("open")
            continue
        probe = _probe(points)
        near = (shut[k] for k in boxes_holding(probe, boxes).tolist())
        depth = sum(int(inside(probe[None], contours[j])[0]) for j in near if j != i)
        out.append("hole" if depth % 2 else "outer")
    return out


def _probe(points: Array) -> Array:
    """A point just inside the contour near its first edge of some length (not on another contour's
    boundary by chance); copies of a vertex, which balancing stacks, are passed over."""
    if len(points) < 3 or signed_area(points) == 0:
        return points.mean(axis=0)
    k = int(np.argmax(np.any(np.roll(points, -1, axis=0) != points, axis=1)))
    a, b = points[k], points[(k + 1) % len(points)]
    mid = 0.5 * (a + b)
    edge = b - a
    normal = np.array([-edge[1], edge[0]])  # left of the edge: inside for counter-clockwise
    if signed_area(points) < 0:
        normal = -normal
    span = float(np.ptp(points, axis=0).max())
    length = float(np.hypot(*normal))
    step = normal / length * min(1e-6 * span, 0.25 * length)
    return mid + step


def apparent_area(points: Array) -> float:
    """How much area a closed contour ``(N, 2)`` looks to cover: the geometric mean of its own area and its
    convex hull's. A ring drawn as one contour (out round the outside, back round the inside) covers more
    to the eye than its thin band of ink, a crescent less than its hull; a convex contour, its area."""
    return float(np.sqrt(abs(float(signed_area(points))) * hull_area(points)))


def contour_size(points: Array, closed: bool) -> float:
    """A length that measures how large a contour looks: √ of its :func:`apparent_area` for a closed one,
    its length for an open one; at least its bounding box's diagonal / 100 so that flat contours still
    compare."""
    diag = float(np.hypot(*np.ptp(points, axis=0))) if len(points) else 0.0
    if closed and len(points) >= 3:
        measure = float(np.sqrt(apparent_area(points)))
    else:
        measure = float(np.linalg.norm(np.diff(points, axis=0), axis=1).sum())
    return max(measure, diag / 100.0, 1e-300)


def pair_contours(a: Sequence[Array], a_closed: Sequence[bool], b: Sequence[Array],
                  b_closed: Sequence[bool], forced: Sequence[tuple[int, int]] = ()
                  ) -> list[tuple[int | None, int | None]]:
    """Which contour of key a goes with which of key b: ``(i, j)`` pairs, ``None`` for no partner.

    ``forced`` pairs (shape hints make them; each contour at most once, of one role) are kept
    as they are; the others are paired among themselves as follows.

    Within a role as many contours are paired as the smaller key has, at the least total
    cost; the rest have no partner. The cost of a pair is the distance between the
    contours' centres, each taken relative to its own key's centre and divided by the keys'
    size, plus how much their sizes differ (``0.7 · |ln(size_a / size_b)|``). Pairs are
    sorted by ``i`` (contours of a in order), then the new contours of b by ``j``.
    """
    role_a, role_b = roles(a, a_closed), roles(b, b_closed)
    centre_a, centre_b = _box_centre(a), _box_centre(b)
    scale = max(_key_scale(a), _key_scale(b), 1e-300)
    pairs: list[tuple[int | None, int | None]] = [(i, j) for i, j in forced]
    taken_a, taken_b = {i for i, _ in forced}, {j for _, j in forced}
    for role in ROLES:
        ia = [i for i, r in enumerate(role_a) if r == role and i not in taken_a]
        jb = [j for j, r in enumerate(role_b) if r == role and j not in taken_b]
        if not ia or not jb:
            pairs += [(i, None) for i in ia] + [(None, j) for j in jb]
            continue
        if len(ia) == len(jb) == 1:
            pairs.append((ia[0], jb[0]))
            continue
        pa = np.array([_box_centre([a[i]]) - centre_a for i in ia])
        pb = np.array([_box_centre([b[j]]) - centre_b for j in jb])
        sa = np.log([contour_size(a[i], a_closed[i]) for i in ia])
        sb = np.log([contour_size(b[j], b_closed[j]) for j in jb])
        cost = (np.hypot(pa[:, None, 0] - pb[None, :, 0], pa[:, None, 1] - pb[None, :, 1]) / scale
                + _SIZE_WEIGHT * np.abs(sa[:, None] - sb[None]))
        rows, cols = min_cost_assignment(cost)
        pairs += [(ia[r], jb[c]) for r, c in zip(rows, cols)]
        paired_rows, paired_cols = set(rows.tolist()), set(cols.tolist())
        pairs += [(i, None) for k, i in enumerate(ia) if k not in paired_rows]
        pairs += [(None, j) for k, j in enumerate(jb) if k not in paired_cols]
    matched = sorted((p for p in pairs if p[0] is not None), key=lambda p: p[0])  # type: ignore[arg-type, return-value]
    new = sorted((p for p in pairs if p[0] is None), key=lambda p: p[1])  # type: ignore[arg-type, return-value]
    return matched + new


def keep_nesting(partners: Sequence[tuple[int | None, int | None]], a: Sequence[Array],
                 a_closed: Sequence[bool], b: Sequence[Array], b_closed: Sequence[bool],
                 forced: Sequence[tuple[int, int]] = ()) -> list[tuple[int | None, int | None]]:
    """``partners`` (as :func:`pair_contours` gives them) with no two pairs nested differently in
    the two keys: where one pair's contour lies inside another's in key a but not in key b (or the
    other way round), the two would have to pass through each other; the smaller pair (by the
    sizes of its two contours) is parted into one contour that shrinks away and one that grows,
    until every two pairs apart in both keys are nested alike. ``forced`` pairs are never parted."""
    kept = [(i, j) for i, j in partners if i is not None and j is not None]
    alone = [p for p in partners if p[0] is None or p[1] is None]
    fixed = set(forced)
    shut_a = [bool(c) and len(x) >= 3 for x, c in zip(a, a_closed)]
    shut_b = [bool(c) and len(x) >= 3 for x, c in zip(b, b_closed)]
    while True:
        closed = [(i, j) for i, j in kept if shut_a[i] and shut_b[j]]  # type: ignore[index]
        worst = _misnested(closed, a, b)
        if not worst:
            break
        size = {p: contour_size(a[p[0]], True) + contour_size(b[p[1]], True) for pq in worst for p in pq}  # type: ignore[index]
        candidates = [p for pq in worst for p in pq if p not in fixed]
        if not candidates:
            break
        parted = min(candidates, key=lambda p: size[p])
        kept.remove(parted)
        alone += [(parted[0], None), (None, parted[1])]
    matched = sorted((p for p in kept + alone if p[0] is not None), key=lambda p: p[0])  # type: ignore[arg-type, return-value]
    new = sorted((p for p in alone if p[0] is None), key=lambda p: p[1])  # type: ignore[arg-type, return-value]
    return matched + new


def _misnested(pairs: Sequence[tuple[int, int]], a: Sequence[Array], b: Sequence[Array]
               ) -> list[tuple[tuple[int, int], tuple[int, int]]]:
    """The two-pair sets of closed ``pairs`` apart in both keys (no common point) whose nesting
    differs between key a and key b."""
    if len(pairs) < 2:
        return []
    ka = [np.asarray(a[i], dtype=np.float64) for i, _ in pairs]
    kb = [np.asarray(b[j], dtype=np.float64) for _, j in pairs]
    meeting = set(proper_crossings(ka, [True] * len(ka), touching=True)) | \
        set(proper_crossings(kb, [True] * len(kb), touching=True))
    out = []
    # nested in either key needs boxes one within the other there: the other pairs are apart in both
    for p, q in sorted(_boxes_within(bounding_boxes(ka)) | _boxes_within(bounding_boxes(kb))):
        if (p, q) in meeting:
            continue
        if _nested(ka[p], ka[q]) != _nested(kb[p], kb[q]):
            out.append((pairs[p], pairs[q]))
    return out


def _boxes_within(boxes: Array) -> set[tuple[int, int]]:
    """The index pairs ``(p, q)``, ``p < q``, of ``boxes (C, 4)`` (``[xmin, ymin, xmax, ymax]``) where one box
    lies within the other, edges included: each box against the boxes whose left edge falls within its
    own x range (found in the boxes sorted by left edge), so the work follows the pairs whose x ranges
    nest, not every pair."""
    order = np.argsort(boxes[:, 0], kind="stable")
    left = boxes[order, 0]
    out: set[tuple[int, int]] = set()
    for p in range(len(boxes)):
        lo, hi = np.searchsorted(left, boxes[p, 0], "left"), np.searchsorted(left, boxes[p, 2], "right")
        others = order[lo:hi]
        held = others[(boxes[others, 1] >= boxes[p, 1]) & (boxes[others, 2] <= boxes[p, 2])
                      & (boxes[others, 3] <= boxes[p, 3]) & (others != p)]  # within box p
        out.update((min(p, int(q)), max(p, int(q))) for q in held.tolist())
    return out


def _nested(c: Array, d: Array) -> int:
    """1 where closed ``c (L, 2)`` lies inside ``d (M, 2)``, -1 where ``d`` inside ``c``, else 0 (boxes first)."""
    c_lo, c_hi, d_lo, d_hi = c.min(axis=0), c.max(axis=0), d.min(axis=0), d.max(axis=0)
    if not (np.all(c_lo >= d_lo) and np.all(c_hi <= d_hi)) and not (np.all(d_lo >= c_lo) and np.all(d_hi <= c_hi)):
        return 0
    return int(_relation(c[None], d[None])[0])


def _box_centre(contours: Sequence[Array]) -> Array:
    """The centre of the contours' bounding box (unlike the vertex mean, blind to how densely
    curves were flattened)."""
    every = np.concatenate(contours)
    return 0.5 * (every.min(axis=0) + every.max(axis=0))


def _key_scale(contours: Sequence[Array]) -> float:
    every = np.concatenate(contours)
    return float(np.hypot(*np.ptp(every, axis=0)))


def nearest_point(point: Array, contours: Sequence[Array], closed: Sequence[bool]) -> Array:
    """The point of the contours' outlines (open ones not closed) nearest to ``point (2,)``: ``(2,)``."""
    best, best_d = point, np.inf
    for points, shut in zip(contours, closed):
        if len(points) == 1:
            starts, ends = points, points
        else:
            starts = points if shut else points[:-1]
            ends = np.roll(points, -1, axis=0) if shut else points[1:]
        edge = ends - starts
        length2 = (edge * edge).sum(axis=1)
        with np.errstate(divide="ignore", invalid="ignore"):
            s = np.where(length2 > 0, ((point - starts) * edge).sum(axis=1) / length2, 0.0)
        foot = starts + np.clip(s, 0.0, 1.0)[:, None] * edge
        d = np.hypot(*(foot - point).T)
        k = int(np.argmin(d))
        if d[k] < best_d:
            best, best_d = foot[k], float(d[k])
    return np.asarray(best, dtype=np.float64)


def centre_of_area(contours: Sequence[Array], closed: Sequence[bool]) -> Array:
    """The centre of area of the region the contours ``(N_i, 2)`` enclose, holes (by nesting) taken
    away: ``(2,)``. Without area (open strokes, flat contours) the centre of their length, and
    without length the mean of their vertices."""
    kinds = roles(contours, closed)
    total, moment = 0.0, np.zeros(2)
    for points, kind in zip(contours, kinds):
        if kind == "open" or len(points) < 3:
            continue
        x, y = points[:, 0], points[:, 1]
        x1, y1 = np.roll(x, -1), np.roll(y, -1)
        cross = x * y1 - x1 * y
        area = 0.5 * float(cross.sum())
        if area == 0.0:
            continue
        centre = np.array([((x + x1) * cross).sum(), ((y + y1) * cross).sum()]) / (6.0 * area)
        weight = -abs(area) if kind == "hole" else abs(area)
        total += weight
        moment += weight * centre
    if total > 0.0:
        return moment / total
    length, moment = 0.0, np.zeros(2)
    for points, shut in zip(contours, closed):
        ends = np.roll(points, -1, axis=0) if shut else points[1:]
        starts = points if shut else points[:-1]
        pieces = np.hypot(*(ends - starts).T)
        length += float(pieces.sum())
        moment += (0.5 * (starts + ends) * pieces[:, None]).sum(axis=0)
    if length > 0.0:
        return moment / length
    return np.concatenate(list(contours)).mean(axis=0)


def anchor(contour: Array, partner: Sequence[Array], partner_closed: Sequence[bool], fill_rule: str,
           closed: bool = True) -> Array:
    """Where a contour ``(N, 2)`` without a partner grows from or shrinks to: the point of the partner
    key's drawing nearest its centre of area (:func:`centre_of_area`) — that centre if it lies in the
    partner key's filled region, else the nearest point of the partner's outlines: ``(2,)``."""
    return anchors([contour], [closed], partner, partner_closed, fill_rule)[0]


def anchors(contours: Sequence[Array], closed: Sequence[bool], partner: Sequence[Array],
            partner_closed: Sequence[bool], fill_rule: str) -> Array:
    """:func:`anchor` of each of ``contours (N_i, 2)`` against one partner key: ``(K, 2)``. The partner's
    contours are boxed once; a centre is tested only against the contours whose boxes hold it, and its
    nearest point sought only among those whose boxes lie no farther than some contour's first vertex."""
    out = np.zeros((len(contours), 2))
    shut = [np.asarray(p, dtype=np.float64) for p, c in zip(partner, partner_closed) if c and len(p) >= 3]
    shut_boxes = bounding_boxes(shut)
    boxes = bounding_boxes(partner)
    firsts = np.array([p[0] if len(p) else (np.inf, np.inf) for p in partner], dtype=np.float64).reshape(-1, 2)
    winding: dict[int, float] = {}
    for k, (contour, shut_k) in enumerate(zip(contours, closed)):
        centre = centre_of_area([contour], [shut_k])
        out[k] = centre
        near = boxes_holding(centre, shut_boxes).tolist()  # outside every other box: inside none
        hits = [k2 for k2 in near if inside(centre[None], shut[k2])[0]]
        if fill_rule == "evenodd":
            filled = len(hits) % 2 == 1
        else:
            filled = sum(winding.setdefault(h, float(np.sign(signed_area(shut[h])))) for h in hits) != 0
        if filled or not partner:
            continue
        gap = np.hypot(*np.maximum(0.0, np.maximum(boxes[:, :2] - centre, centre - boxes[:, 2:])).T)  # to each box
        reach = float(np.min(np.hypot(*(firsts - centre).T)))  # the nearest point is no farther
        chosen = np.flatnonzero(gap <= reach).tolist()
        out[k] = nearest_point(centre, [partner[c] for c in chosen], [partner_closed[c] for c in chosen])
    return out
