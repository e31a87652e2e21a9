"""Proper crossings of a shape's contours: does an in-between tangle? (maths §5.9; ``stats``' ``crossings``)

A shape *tangles* at a frame when one of its contours crosses itself properly
— two edges that are not neighbours meet at one point inside both, each
passing to the other's far side — or when a hole leaves its outline: the hole
crosses its outline properly, or lies wholly outside it. Touching (a vertex on
an edge, collinear overlap) does not count. Which contour is a hole of which
is read from the first frame: a closed contour's *parent* is the smallest
closed contour around its first vertex.

:func:`contact_times` adds what a viewer sees as well (``stats``' ``crossings``
and ``stroke_crossings``): two contours of one shape that are *apart* in both
keys — no common point, and the same nesting (one inside the other, or
neither) in both — *meet* at a frame when they cross (their edges properly, or
passing through each other where they only touch), or (closed contours) when
one comes to lie inside the other or leaves it. A contour lying along another
without passing through it (collinear edges) only touches it.

Orientation signs are exact: a float determinant within its rounding bound of
zero is settled by the signs of its factors where one of its products has a zero
factor (coincident points), else recomputed in exact rational arithmetic (each
float an integer over a power of two, so integers over a common one), so the
answer does not depend on floating-point luck. Candidate edge pairs are found by sorting the edges'
x-ranges (sweep and prune), so a frame costs far less than all pairs.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from typing import Sequence

import numpy as np
from numpy.typing import NDArray

from .geometry import bounding_boxes, boxes_holding
from .memo import Remembered

__all__ = ["SWEEP", "parents", "tangles", "tangled_times", "proper_crossings", "crossing_pairs", "linear_tangles",
           "point_states", "held_pairs", "Apart", "apart_in_keys", "contact_times"]

Array = NDArray[np.float64]

SWEEP = np.linspace(0.0, 1.0, 101)
"""The swept t of a segment at which crossings are looked for (``stats``' ``crossings``, ``auto``)."""

_CACHED = 1024  # shapes whose straight paths' crossings are kept
_linear_cache: Remembered[list[float]] = Remembered(_CACHED)
_apart_cache: Remembered[Apart] = Remembered(_CACHED)  # keys' contours apart in both, by their digest

_BOUND = 4.0 * np.finfo(np.float64).eps  # relative rounding bound of a 2x2 orientation determinant


Indices = NDArray[np.intp]


def _edges(contours: Sequence[Array], closed: Sequence[bool]) -> tuple[Array, Array, Indices, Indices, Indices]:
    """Every edge ``a → b`` (``(E, 2)`` each), its contour, its index in the contour and the contour's edge count."""
    a, b, owner, index, count = [], [], [], [], []
    for c, (points, shut) in enumerate(zip(contours, closed)):
        points = np.asarray(points, dtype=np.float64)
        m = len(points) if shut and len(points) >= 3 else len(points) - 1
        if m <= 0:
            continue
        a.append(points[:m])
        b.append(np.concatenate([points[1:], points[:1]]) if m == len(points) else points[1:m + 1])  # each end
        owner.append(np.full(m, c))
        index.append(np.arange(m))
        count.append(np.full(m, m if shut else -1))
    if not a:
        empty = np.zeros((0, 2))
        none = np.zeros(0, dtype=np.intp)
        return empty, empty, none, none, none
    return (np.concatenate(a), np.concatenate(b), np.concatenate(owner), np.concatenate(index),
            np.concatenate(count))


def _sign(ax: Array, ay: Array, bx: Array, by: Array, cx: Array, cy: Array) -> NDArray[np.int8]:
    """Exact sign of ``orient(a, b, c)`` for arrays of points."""
    left = (bx - ax) * (cy - ay)
    right = (by - ay) * (cx - ax)
    det = left - right
    sign = np.sign(det).astype(np.int8)
    unsure = np.flatnonzero(np.abs(det) <= _BOUND * (np.abs(left) + np.abs(right)))
    if len(unsure):
        unsure = unsure[~_settled_by_a_zero_factor(sign, unsure, ax, ay, bx, by, cx, cy)]
    if len(unsure):
        columns = [v[unsure].tolist() for v in (ax, ay, bx, by, cx, cy)]
        for k, values in zip(unsure.tolist(), zip(*columns)):
            sign[k] = _exact_sign(values)
    return sign


def _settled_by_a_zero_factor(sign: NDArray[np.int8], unsure: Indices, ax: Array, ay: Array, bx: Array, by: Array,
                              cx: Array, cy: Array) -> NDArray[np.bool_]:
    """Settle, in ``sign``, the ``unsure`` determinants one of whose two products is exactly zero, and
    say which (``(U,)``): a difference of two floats is 0 exactly when they are equal and otherwise has
    the sign of the exact difference (IEEE rounding is monotonic), so each exact product's sign is the
    product of its factors' signs, and where one product is 0 the determinant's sign is the other's.
    Points that coincide (a balanced key's copies, a contour grown from one point) are nearly all of
    these."""
    left = np.sign(bx[unsure] - ax[unsure]) * np.sign(cy[unsure] - ay[unsure])
    right = np.sign(by[unsure] - ay[unsure]) * np.sign(cx[unsure] - ax[unsure])
    settled = (left == 0.0) | (right == 0.0)
    sign[unsure[settled]] = (left - right)[settled].astype(np.int8)
    return settled


def _exact_sign(values: Sequence[float]) -> int:
    """The sign of ``orient(a, b, c)`` for ``values = (ax, ay, bx, by, cx, cy)``, in exact rational
    arithmetic: every float is an integer over a power of two, so over the largest of those powers the
    determinant is one of integers."""
    ratios = [float(v).as_integer_ratio() for v in values]
    shift = max(q.bit_length() for _, q in ratios) - 1
    ax, ay, bx, by, cx, cy = (n << (shift - q.bit_length() + 1) for n, q in ratios)
    exact = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    return (exact > 0) - (exact < 0)


def _candidates(a: Array, b: Array) -> tuple[NDArray[np.intp], NDArray[np.intp]]:
    """Pairs ``i < j`` of edges whose bounding boxes meet."""
    lo, hi = np.minimum(a[:, 0], b[:, 0]), np.maximum(a[:, 0], b[:, 0])
    order = np.argsort(lo, kind="stable")
    lo_sorted = lo[order]
    end = np.searchsorted(lo_sorted, hi[order], side="right")
    counts = np.maximum(end - np.arange(1, len(order) + 1), 0)
    first = np.repeat(np.arange(len(order)), counts)
    offset = np.arange(counts.sum()) - np.repeat(np.cumsum(counts) - counts, counts)
    i, j = order[first], order[first + 1 + offset]
    ylo_i, yhi_i = np.minimum(a[i, 1], b[i, 1]), np.maximum(a[i, 1], b[i, 1])
    ylo_j, yhi_j = np.minimum(a[j, 1], b[j, 1]), np.maximum(a[j, 1], b[j, 1])
    meet = (ylo_i <= yhi_j) & (ylo_j <= yhi_i)
    return i[meet], j[meet]


def proper_crossings(contours: Sequence[Array], closed: Sequence[bool],
                     touching: bool = False) -> list[tuple[int, int]]:
    """The pairs of contours ``(c, d)``, ``c ≤ d``, that cross properly (``c == d``: it crosses itself);
    with ``touching``, the pairs of different contours whose edges share any point at all."""
    proper, touched = _meetings(contours, closed)
    return sorted(touched if touching else proper)


def _meetings(contours: Sequence[Array], closed: Sequence[bool]
              ) -> tuple[set[tuple[int, int]], set[tuple[int, int]]]:
    """The pairs ``(c, d)``, ``c ≤ d``, that cross properly (``c == d``: it crosses itself), and the pairs
    of different contours whose edges share any point (crossing, touching or overlapping)."""
    a, b, owner, index, count = _edges(contours, closed)
    if len(a) < 2:
        return set(), set()
    i, j = _candidates(a, b)
    same = owner[i] == owner[j]
    gap = np.abs(index[i] - index[j])
    neighbours = same & ((gap == 1) | ((count[i] > 0) & (gap == count[i] - 1)))
    i, j = i[~neighbours], j[~neighbours]
    p, q, r, s = a[i], b[i], a[j], b[j]
    d1 = _sign(p[:, 0], p[:, 1], q[:, 0], q[:, 1], r[:, 0], r[:, 1]).astype(int)
    d2 = _sign(p[:, 0], p[:, 1], q[:, 0], q[:, 1], s[:, 0], s[:, 1]).astype(int)
    # touching: each edge's ends on both sides of the other's line or on it; collinear edges whose
    # boxes meet (every candidate's do) overlap
    keep = d1 * d2 <= 0
    d3 = _sign(r[keep, 0], r[keep, 1], s[keep, 0], s[keep, 1], p[keep, 0], p[keep, 1]).astype(int)
    d4 = _sign(r[keep, 0], r[keep, 1], s[keep, 0], s[keep, 1], q[keep, 0], q[keep, 1]).astype(int)
    c, d = owner[i][keep], owner[j][keep]
    meet = d3 * d4 <= 0
    cross = meet & (d3 * d4 < 0) & ((d1 * d2)[keep] < 0)
    touch = meet & (c != d)
    return ({(int(min(x, y)), int(max(x, y))) for x, y in zip(c[cross].tolist(), d[cross].tolist())},
            {(int(min(x, y)), int(max(x, y))) for x, y in zip(c[touch].tolist(), d[touch].tolist())})


def crossing_pairs(contours: Sequence[Array], closed: Sequence[bool]) -> set[tuple[int, int]]:
    """:func:`proper_crossings`, and the pairs of different contours that pass through each other where
    they only touch (a vertex on the other's outline): one has vertices strictly inside the other closed
    contour and strictly outside it."""
    proper, touched = _meetings(contours, closed)
    out = set(proper)
    for c, d in touched - proper:
        for inner, outer in ((c, d), (d, c)):
            if closed[outer] and len(contours[outer]) >= 3:
                states = point_states(np.asarray(contours[inner], dtype=np.float64)[None],
                                      np.asarray(contours[outer], dtype=np.float64)[None])
                if np.any(states == 1) and np.any(states == -1):
                    out.add((c, d))
                    break
    return out


def _inside(point: Array, polygon: Array) -> bool:
    """Even-odd test of ``point (2,)`` against ``polygon (N, 2)``."""
    x, y = point
    a, b = polygon, np.roll(polygon, -1, axis=0)
    spans = (a[:, 1] > y) != (b[:, 1] > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        at = a[:, 0] + (y - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
    return bool(np.count_nonzero(spans & (x < at)) % 2)


def _area(polygon: Array) -> float:
    x, y = polygon[:, 0], polygon[:, 1]
    return abs(float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))) / 2.0


def parents(contours: Sequence[Array], closed: Sequence[bool]) -> list[int | None]:
    """Each contour's parent: the smallest other closed contour around its first vertex (None for none,
    and for a contour that is one point: growing from it, it is no hole yet; where it comes to lie is
    what :func:`contact_times` checks of contours apart in both keys). Only the contours whose bounding
    boxes hold the vertex are tested."""
    shut = [c for c, (p, s) in enumerate(zip(contours, closed)) if s and len(p) >= 3]
    boxes = bounding_boxes([contours[c] for c in shut])
    areas = {c: _area(np.asarray(contours[c], dtype=np.float64)) for c in shut}
    out: list[int | None] = []
    for c, points in enumerate(contours):
        points = np.asarray(points, dtype=np.float64)
        near = [] if _flat(points) else [shut[k] for k in boxes_holding(points[0], boxes).tolist()]
        around = [d for d in near if d != c and _inside(points[0], np.asarray(contours[d], dtype=np.float64))]
        out.append(min(around, key=lambda d: areas[d]) if around else None)
    return out


def held_pairs(boxes: Array) -> tuple[Indices, Indices]:
    """The index pairs ``(p, q)``, ``p != q``, of ``boxes (C, 4)`` (``[xmin, ymin, xmax, ymax]``) where box ``q``
    lies within box ``p``, edges included: ``(K,)`` each. Each box is set only against the boxes whose left
    edge falls within its x range (a sweep over the boxes sorted by left edge), so the work follows the
    pairs whose x ranges nest, not every pair. An empty box (``[inf, inf, -inf, -inf]``) is in no pair."""
    none = np.zeros(0, dtype=np.intp)
    usable = np.flatnonzero(boxes[:, 0] <= boxes[:, 2])
    if len(usable) < 2:
        return none, none
    order = usable[np.argsort(boxes[usable, 0], kind="stable")]
    left = boxes[order, 0]
    start = np.searchsorted(left, left, side="left")
    end = np.searchsorted(left, boxes[order, 2], side="right")
    counts = end - start
    first = np.repeat(np.arange(len(order)), counts)
    offset = np.arange(counts.sum()) - np.repeat(np.cumsum(counts) - counts, counts)
    p, q = order[first], order[np.repeat(start, counts) + offset]
    keep = ((p != q) & (boxes[q, 1] >= boxes[p, 1]) & (boxes[q, 2] <= boxes[p, 2])
            & (boxes[q, 3] <= boxes[p, 3]))
    return p[keep], q[keep]


def tangles(contours: Sequence[Array], closed: Sequence[bool], parent: Sequence[int | None]) -> bool:
    """Whether one frame tangles: a contour crosses itself, or a contour crosses or leaves its ``parent``."""
    for c, d in proper_crossings(contours, closed):
        if c == d or parent[c] == d or parent[d] == c:
            return True
    for c, p in enumerate(parent):
        if p is not None and len(contours[c]) and \
                not _inside(np.asarray(contours[c], dtype=np.float64)[0], np.asarray(contours[p], dtype=np.float64)):
            # wholly outside is a leaving; on an edge or partly outside shows as a crossing above
            first = np.asarray(contours[c], dtype=np.float64)
            if not any(_inside(point, np.asarray(contours[p], dtype=np.float64)) for point in first):
                return True
    return False


def tangled_times(frames: Sequence[Array], closed: Sequence[bool], t: Array) -> list[float]:
    """The ``t (T,)`` at which contours ``frames[i] (T, L_i, 2)`` tangle, parents read from the first frame."""
    t = np.asarray(t, dtype=np.float64)
    if not frames:
        return []
    parent = parents([f[0] for f in frames], closed)
    return [float(x) for k, x in enumerate(t.tolist()) if tangles([f[k] for f in frames], closed, parent)]


def linear_tangles(k0s: Sequence[Array], k1s: Sequence[Array], closed: Sequence[bool]) -> list[float]:
    """The t of :data:`SWEEP` at which the straight-line inbetweens of contours ``k0s[i]``, ``k1s[i]``
    (``(L_i, 2)`` each) tangle (remembered for the last few shapes asked about)."""
    a = [np.asarray(k, dtype=np.float64) for k in k0s]
    b = [np.asarray(k, dtype=np.float64) for k in k1s]
    key = b"|".join(x.tobytes() + b"/" + y.tobytes() for x, y in zip(a, b)) + repr(list(closed)).encode()
    t = SWEEP[:, None, None]
    return list(_linear_cache.get(key, lambda: tangled_times([(1.0 - t) * x + t * y for x, y in zip(a, b)], closed,
                                                             SWEEP)))


def point_states(points: Array, polygon: Array) -> NDArray[np.int8]:
    """Where each of ``points (T, K, 2)`` lies against the closed ``polygon (T, E, 2)`` of the same
    frame, exactly: 1 inside (even-odd), -1 outside, 0 on its outline: ``(T, K)``."""
    points = np.asarray(points, dtype=np.float64)
    a = np.asarray(polygon, dtype=np.float64)
    b = np.roll(a, -1, axis=1)
    shape = (points.shape[0], points.shape[1], a.shape[1])
    p = np.broadcast_to(points[:, :, None, :], shape + (2,))
    lo = np.where((a[..., 1] <= b[..., 1])[..., None], a, b)[:, None]  # each edge's lower end, then upper
    hi = np.where((a[..., 1] <= b[..., 1])[..., None], b, a)[:, None]
    lo, hi = np.broadcast_to(lo, shape + (2,)), np.broadcast_to(hi, shape + (2,))
    side = _sign(lo[..., 0].ravel(), lo[..., 1].ravel(), hi[..., 0].ravel(), hi[..., 1].ravel(),
                 p[..., 0].ravel(), p[..., 1].ravel()).reshape(shape)
    y = p[..., 1]
    spans = (lo[..., 1] <= y) & (y < hi[..., 1])  # half-open: a vertex on the ray counts once
    crossings = np.count_nonzero(spans & (side > 0), axis=2)  # the edge passes right of the point
    box = ((np.minimum(lo[..., 0], hi[..., 0]) <= p[..., 0]) & (p[..., 0] <= np.maximum(lo[..., 0], hi[..., 0]))
           & (lo[..., 1] <= y) & (y <= hi[..., 1]))
    on = np.any((side == 0) & box, axis=2)
    return np.where(on, 0, np.where(crossings % 2 == 1, 1, -1)).astype(np.int8)


_PROBES = 8  # vertices tried, in order, for one not on the other contour's outline


def _nesting(inner: Array, outer: Array) -> NDArray[np.bool_]:
    """Whether closed ``inner (T, L, 2)`` lies inside closed ``outer (T, M, 2)`` at each frame, read at its
    first vertices not on ``outer``'s outline (its boxes first): ``(T,)``. Meant for contours that do not
    cross; one whose probes all lie on ``outer`` is not inside."""
    inner, outer = np.asarray(inner, dtype=np.float64), np.asarray(outer, dtype=np.float64)
    boxed = np.all((inner.min(axis=1) >= outer.min(axis=1)) & (inner.max(axis=1) <= outer.max(axis=1)), axis=1)
    out = np.zeros(len(inner), dtype=bool)
    rows = np.flatnonzero(boxed)
    if len(rows) == 0:
        return out
    states = point_states(inner[rows, :_PROBES], outer[rows])
    first = np.argmax(states != 0, axis=1)
    out[rows] = states[np.arange(len(rows)), first] == 1
    return out


def _relation(c: Array, d: Array) -> NDArray[np.int8]:
    """1 where closed ``c (T, L, 2)`` lies inside ``d (T, M, 2)``, -1 where ``d`` inside ``c``, else 0: ``(T,)``."""
    inside = _nesting(c, d)
    around = _nesting(d, c) & ~inside
    return (inside.astype(np.int8) - around.astype(np.int8)).astype(np.int8)


def _shut(contour: Array, closed: bool) -> bool:
    return bool(closed) and len(contour) >= 3


def _flat(contour: Array) -> bool:
    """Whether ``contour (L, 2)`` is one point (or none)."""
    points = np.asarray(contour, dtype=np.float64)
    return len(points) == 0 or not np.any(points != points[:1])


def _flat_frames(frames: Array) -> NDArray[np.bool_]:
    """Whether ``frames (T, L, 2)`` is one point (or none) at each frame: ``(T,)``."""
    if frames.shape[1] == 0:
        return np.ones(len(frames), dtype=bool)
    return ~np.any(frames != frames[:, :1], axis=(1, 2))


@dataclass(frozen=True, slots=True)
class Apart:
    """What two keys of one shape say about its contours (indices into them).

    ``nested``: ``(c, d, relation)`` for closed contours ``c < d`` apart in both keys and one inside the
    other in both alike (1: c inside d, -1: d inside c); ``joined``: the pairs ``(c, d)``, ``c < d``, not
    apart in both keys — they meet (share a point) in either key, or (closed) are nested differently.
    Every other pair of non-empty contours is apart in both keys, side by side (closed) or one open at
    least. A contour that is one point in a key (growing from it, shrinking to it) is not drawn there:
    its pairs are read from the other key alone. ``parent``: each contour's parent in the first key
    (:func:`parents`), None where the two meet in either key. ``crossed``: the contours that cross
    themselves properly in either key.
    """

    nested: tuple[tuple[int, int, int], ...]
    joined: frozenset[tuple[int, int]]
    parent: tuple[int | None, ...]
    crossed: frozenset[int] = frozenset()


def apart_in_keys(k0s: Sequence[Array], k1s: Sequence[Array], closed: Sequence[bool]) -> Apart:
    """Which contours of keys ``k0s``, ``k1s`` (``(L_i, 2)`` each, corresponding) are apart in both
    (remembered for the last few keys asked about: every method of a segment asks about the same)."""
    k0s = [np.asarray(k, dtype=np.float64) for k in k0s]
    k1s = [np.asarray(k, dtype=np.float64) for k in k1s]
    digest = hashlib.blake2b(repr([bool(c) for c in closed]).encode(), digest_size=20)
    for k in (*k0s, *k1s):
        digest.update(repr(k.shape).encode())
        digest.update(np.ascontiguousarray(k).tobytes())
    key = digest.digest()
    return _apart_cache.get(key, lambda: _apart_in_keys(k0s, k1s, closed))


def _apart_in_keys(k0s: list[Array], k1s: list[Array], closed: Sequence[bool]) -> Apart:
    shut = [_shut(k, c) for k, c in zip(k0s, closed)]
    # a contour that is one point in a key (growing from it, shrinking to it) is not drawn there: a pair is
    # read from the keys that draw both
    drawn = [[not _flat(k) for k in keys] for keys in (k0s, k1s)]
    meeting: set[tuple[int, int]] = set()
    crossed: set[int] = set()
    for keys, here in zip((k0s, k1s), drawn):
        proper, touched = _meetings(keys, shut)
        meeting.update((c, d) for c, d in touched if here[c] and here[d])
        crossed.update(c for c, d in proper if c == d)
    # one inside the other in a key needs its box within the other's there: every other pair is side by side
    boxed: set[tuple[int, int]] = set()
    for keys, here in zip((k0s, k1s), drawn):
        ids = [c for c in range(len(keys)) if shut[c] and here[c]]
        p, q = held_pairs(bounding_boxes([keys[c] for c in ids]))
        boxed.update((min(ids[x], ids[y]), max(ids[x], ids[y])) for x, y in zip(p.tolist(), q.tolist()))
    nested, joined = [], set(meeting)
    for c, d in sorted(boxed - meeting):
        relations = {int(_relation(keys[c][None], keys[d][None])[0])
                     for keys, here in zip((k0s, k1s), drawn) if here[c] and here[d]}
        if len(relations) > 1:
            joined.add((c, d))
        elif relations and (first := relations.pop()):
            nested.append((c, d, first))
    # a contour that meets the one around it in a key is no hole of it there (the keys already cross)
    parent = [p if p is None or (min(c, p), max(c, p)) not in meeting else None
              for c, p in enumerate(parents(k0s, shut))]
    return Apart(tuple(nested), frozenset(joined), tuple(parent), frozenset(crossed))


def contact_times(frames: Sequence[Array], closed: Sequence[bool], t: Array,
                  k0s: Sequence[Array], k1s: Sequence[Array], *, with_key_crossings: bool = True
                  ) -> tuple[list[float], list[float]]:
    """The ``t (T,)`` at which contours ``frames[i] (T, L_i, 2)`` of one shape, keys ``k0s``, ``k1s``
    (``(L_i, 2)``), tangle: ``(crossings, stroke_crossings)``.

    ``crossings``: a closed contour crosses itself properly; a closed contour crosses its parent (read
    from the first key) or lies wholly outside it; two closed contours apart in both keys cross, or
    one lies inside the other where it did not in the keys, or no longer does. ``stroke_crossings``:
    an open stroke crosses itself properly, or crosses a contour it is apart from in both keys.
    Two contours cross where they do properly, or pass through each other where they only touch
    (:func:`crossing_pairs`). A closed contour of fewer than three vertices counts as a stroke. Without
    ``with_key_crossings``, a contour that crosses itself properly in a key is not counted crossing
    itself (it does near that key whatever the in-betweens: what ``auto`` compares is what a method
    could avoid).
    """
    t = np.asarray(t, dtype=np.float64)
    if not frames:
        return [], []
    frames = [np.asarray(f, dtype=np.float64) for f in frames]
    shut = [_shut(k, c) for k, c in zip(k0s, closed)]
    keys = apart_in_keys(k0s, k1s, closed)
    tangled = np.zeros(len(t), dtype=bool)
    stroked = np.zeros(len(t), dtype=bool)
    crossed: list[set[tuple[int, int]]] = []
    filled = [c for c in range(len(frames)) if shut[c] and frames[c].shape[1] > 0]
    inside_pairs = {(c, d) for c, d, _ in keys.nested}
    bound = frozenset() if with_key_crossings else keys.crossed
    for k in range(len(t)):
        found = crossing_pairs([f[k] for f in frames], shut)
        crossed.append(found)
        for c, d in found:
            if c == d and c in bound:
                continue
            if c == d:
                tangled[k] |= shut[c]
                stroked[k] |= not shut[c]
            elif shut[c] and shut[d] and (keys.parent[c] == d or keys.parent[d] == c):
                tangled[k] = True
            elif (c, d) not in keys.joined and (c, d) not in inside_pairs:
                # apart in both keys: strokes meet where they cross, closed contours side by side too
                tangled[k] |= shut[c] and shut[d]
                stroked[k] |= not (shut[c] and shut[d])
    flat = [_flat_frames(f) for f in frames]  # (T,) each: one point then, drawn nowhere
    for c, p in enumerate(keys.parent):
        if shut[c] and p is not None:  # wholly outside: no vertex inside (partly outside shows as a crossing)
            rest = np.flatnonzero(~tangled & ~flat[c] & ~flat[p])
            rest = rest[point_states(frames[c][rest, :1], frames[p][rest])[:, 0] != 1]
            for k in rest.tolist():  # the first vertex is not inside: is any other?
                tangled[k] = not np.any(point_states(frames[c][k:k + 1], frames[p][k:k + 1]) == 1)
    for c, d, relation in keys.nested:
        met = np.array([(c, d) in found for found in crossed])
        tangled |= met
        rest = np.flatnonzero(~met & ~tangled & ~flat[c] & ~flat[d])
        if len(rest):
            tangled[rest] |= _relation(frames[c][rest], frames[d][rest]) != relation
    tangled |= _side_by_side_nest(frames, filled, tangled, keys.joined | inside_pairs, flat)
    return [float(x) for x in t[tangled]], [float(x) for x in t[stroked]]


def _side_by_side_nest(frames: Sequence[Array], filled: Sequence[int], done: NDArray[np.bool_],
                       not_side_by_side: frozenset[tuple[int, int]] | set[tuple[int, int]],
                       flat: Sequence[NDArray[np.bool_]]) -> NDArray[np.bool_]:
    """Frames ``(T,)`` not ``done`` at which two of the closed contours ``filled`` (indices into ``frames``,
    ``(T, L_i, 2)`` each), side by side in both keys (no pair of ``not_side_by_side``), lie one inside the
    other: only the pairs whose boxes lie one within the other at that frame are tested; a contour that
    is one point at a frame (``flat[c] (T,)``) lies in none there."""
    out = np.zeros(len(done), dtype=bool)
    if len(filled) < 2:
        return out
    lows = np.stack([np.where(flat[c][:, None], np.inf, frames[c].min(axis=1)) for c in filled], axis=1)  # (T, C, 2)
    highs = np.stack([np.where(flat[c][:, None], -np.inf, frames[c].max(axis=1)) for c in filled], axis=1)
    for k in np.flatnonzero(~done).tolist():
        p, q = held_pairs(np.concatenate([lows[k], highs[k]], axis=1))
        for x, y in zip(p.tolist(), q.tolist()):
            c, d = min(filled[x], filled[y]), max(filled[x], filled[y])
            if (c, d) not in not_side_by_side and _relation(frames[c][k:k + 1], frames[d][k:k + 1])[0] != 0:
                out[k] = True
                break
    return out
