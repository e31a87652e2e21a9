"""The overlay step of compatible triangulations (maths §5.9), and the orientation tests they share.

Two triangulations of one polygon (corners by index ``0 … m-1`` in boundary order), each valid in
its own key, are brought closer by edge flips — each valid in its own key — while that lowers the
number of their edges that cross (:func:`fewer_crossings`), then laid on a regular ``m``-gon and
overlaid: every crossing becomes a point, every cell of the overlay (the meet of a triangle of
each) a fan (:func:`overlay_face`; Aronov, Seidel & Souvaine 1993). :func:`relax` moves the points
a triangulation may move towards fatter triangles. Pure numpy.
"""

from __future__ import annotations

import math
from heapq import heappop, heappush
from typing import Sequence

import numpy as np
from numpy.typing import NDArray

__all__ = ["orient", "fat", "relax", "fewer_crossings", "overlay_face"]

Array = NDArray[np.float64]
Triangles = NDArray[np.intp]


def orient(a: Sequence[float], b: Sequence[float], c: Sequence[float]) -> float:
    """Twice the signed area of triangle ``abc`` (positive counter-clockwise)."""
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


_THIN = 1e-9  # a new triangle whose sine at a corner is below this counts as flat


def fat(a: Sequence[float], b: Sequence[float], c: Sequence[float]) -> bool:
    """Whether triangle ``abc`` is counter-clockwise and not flat to rounding (its sine at ``a``
    above :data:`_THIN`): flips make no triangle that rounding could turn over."""
    area = orient(a, b, c)
    return area > _THIN * math.hypot(b[0] - a[0], b[1] - a[1]) * math.hypot(c[0] - a[0], c[1] - a[1])


_RELAX_ROUNDS = 40
_STEPS = np.array([1.0, 0.5, 0.25])


def relax(points: Array, triangles: Triangles, start: int) -> Array:
    """Move the Steiner points (rows from ``start`` on; drawn by no contour) towards the mean of
    their neighbours, or into their thinnest triangle, wherever that fattens the thinnest triangle
    around them: the overlay's slivers, thin enough to turn over in floating point, get room.
    A point moves only where every triangle around it stays counter-clockwise; in a round, points
    that move are never neighbours (the rest wait for the next round)."""
    points = points.copy()
    if start >= len(points) or len(triangles) == 0:
        return points
    # one row per (Steiner corner v, its triangle): the two other corners a, b, counter-clockwise after v
    v = np.concatenate([triangles[:, k] for k in range(3)])
    a = np.concatenate([triangles[:, (k + 1) % 3] for k in range(3)])
    b = np.concatenate([triangles[:, (k + 2) % 3] for k in range(3)])
    keep = v >= start
    order = np.argsort(v[keep], kind="stable")
    v, a, b = v[keep][order], a[keep][order], b[keep][order]
    heads = np.flatnonzero(np.r_[True, v[1:] != v[:-1]])
    movable = v[heads]  # (S,)
    slot = np.repeat(np.arange(len(heads)), np.diff(np.r_[heads, len(v)]))
    counts = np.diff(np.r_[heads, len(v)])
    # neighbouring Steiner points, as pairs of slots
    index = np.full(len(points), -1)
    index[movable] = np.arange(len(movable))
    pairs = np.column_stack([slot, index[a]])
    pairs = pairs[pairs[:, 1] >= 0]
    priority = np.random.default_rng(0).permutation(len(movable))

    def areas(p: Array) -> Array:  # (R, C) doubled areas of each row's triangle with v at p (R, C, 2)
        pa, pb = points[a][:, None, :], points[b][:, None, :]
        return (pa[..., 0] - p[..., 0]) * (pb[..., 1] - p[..., 1]) - (pa[..., 1] - p[..., 1]) * (pb[..., 0] - p[..., 0])

    for _ in range(_RELAX_ROUNDS):
        here = points[movable]  # (S, 2)
        own = areas(here[slot][:, None, :])[:, 0]
        now = np.minimum.reduceat(own, heads)  # (S,)
        mean = np.add.reduceat(0.5 * (points[a] + points[b]), heads) / counts[:, None]
        thinnest = np.lexsort((own, slot))[heads]  # each point's thinnest triangle
        inside = (points[a[thinnest]] + points[b[thinnest]] + here) / 3.0
        goals = np.concatenate([here[:, None, :] + _STEPS[None, :, None] * (g - here)[:, None, :]
                                for g in (mean, inside)], axis=1)  # (S, 6, 2)
        value = np.minimum.reduceat(areas(goals[slot]), heads, axis=0)  # (S, 6)
        pick = np.argmax(value, axis=1)
        best = value[np.arange(len(movable)), pick]
        wants = best > np.maximum(now, 0.0) * 1.01 + 1e-300
        if not wants.any():
            break
        # of two neighbours that both want to move, the lower priority waits
        both = wants[pairs[:, 0]] & wants[pairs[:, 1]]
        lower = np.where(priority[pairs[both, 0]] < priority[pairs[both, 1]], pairs[both, 0], pairs[both, 1])
        wants[lower] = False
        chosen = np.flatnonzero(wants)
        points[movable[chosen]] = goals[chosen, pick[chosen]]
        priority = np.roll(priority, 1)
    return points


class _Polygon:
    """A triangulated polygon by corner indices: half-edge ``(a, b) → c`` for each counter-clockwise triangle."""

    def __init__(self, m: int, triangles: list[tuple[int, int, int]]) -> None:
        self.m = m
        self.he: dict[tuple[int, int], int] = {}
        for a, b, c in triangles:
            self.he[(a, b)], self.he[(b, c)], self.he[(c, a)] = c, a, b

        self.chords = {(a, b) for (a, b) in self.he if a < b and (b, a) in self.he}

    def flip(self, a: int, b: int) -> tuple[int, int]:
        x, y = self.he.pop((a, b)), self.he.pop((b, a))
        self.chords.discard((min(a, b), max(a, b)))
        self.chords.add((min(x, y), max(x, y)))
        del self.he[(b, x)], self.he[(x, a)], self.he[(a, y)], self.he[(y, b)]
        for u, v, w in ((a, y, x), (y, b, x)):
            self.he[(u, v)], self.he[(v, w)], self.he[(w, u)] = w, u, v
        return x, y

    def triangles(self) -> list[tuple[int, int, int]]:
        return [(a, b, c) for (a, b), c in self.he.items() if a < b and a < c]


def _crossing_count(a: int, b: int, lo: NDArray[np.intp], hi: NDArray[np.intp]) -> int:
    """How many chords ``(lo, hi)`` of the ``m``-gon cross chord ``(a, b)``."""
    a, b = min(a, b), max(a, b)
    return int(np.count_nonzero(_crossing(a, b, lo, hi)))


def _crossing(a: int | NDArray[np.intp], b: int | NDArray[np.intp], lo: int | NDArray[np.intp],
              hi: int | NDArray[np.intp]) -> NDArray[np.bool_]:
    """Whether chord ``(a, b)`` crosses chord ``(lo, hi)`` of the ``m``-gon (each ``a < b``, ``lo < hi``;
    either side arrays of one shape): one end strictly between the other's, the other strictly outside."""
    return ((a < lo) & (lo < b) & (b < hi)) | ((lo < a) & (a < hi) & (hi < b))


class _Crossings:
    """How many chords of one triangulation of the ``m``-gon cross each chord asked about: counted against its
    chords when first asked, then kept as it flips (a flip changes the count of the chords crossing the
    chord it takes away or the one it adds, by one each)."""

    def __init__(self, chords: set[tuple[int, int]]) -> None:
        ends = sorted(chords)
        self._lo = np.array([lo for lo, _ in ends], dtype=np.intp)  # its chords (C,), each lo < hi
        self._hi = np.array([hi for _, hi in ends], dtype=np.intp)
        self._row = {chord: k for k, chord in enumerate(ends)}
        self._asked_lo = np.zeros(16, dtype=np.intp)  # the chords asked about: the first ``_size`` entries
        self._asked_hi = np.zeros(16, dtype=np.intp)
        self._count = np.zeros(16, dtype=np.intp)
        self._slot: dict[tuple[int, int], int] = {}
        self._size = 0

    def __call__(self, a: int, b: int) -> int:
        chord = (min(a, b), max(a, b))
        k = self._slot.get(chord)
        if k is None:
            if self._size == len(self._count):
                self._asked_lo, self._asked_hi, self._count = (np.concatenate([v, np.zeros_like(v)]) for v in
                                                                (self._asked_lo, self._asked_hi, self._count))
            k = self._slot[chord] = self._size
            self._size += 1
            self._asked_lo[k], self._asked_hi[k] = chord
            self._count[k] = _crossing_count(a, b, self._lo, self._hi)
        return int(self._count[k])

    def flipped(self, gone: tuple[int, int], made: tuple[int, int]) -> list[tuple[int, int]]:
        """The triangulation's chord ``gone`` became ``made`` (each ``(lo, hi)``): the chords asked about whose
        count changed."""
        row = self._row.pop(gone)
        self._row[made] = row
        self._lo[row], self._hi[row] = made
        a, b = self._asked_lo[:self._size], self._asked_hi[:self._size]
        change = _crossing(a, b, *made).astype(np.intp) - _crossing(a, b, *gone)
        self._count[:self._size] += change
        moved = np.flatnonzero(change)
        return list(zip(a[moved].tolist(), b[moved].tolist()))


_FLIP_ROUNDS = 100  # passes of crossing-reducing flips over both triangulations


def fewer_crossings(m: int, tris0: list[tuple[int, int, int]], tris1: list[tuple[int, int, int]],
                     pos0: list[tuple[float, float]], pos1: list[tuple[float, float]]
                     ) -> tuple[list[tuple[int, int, int]], list[tuple[int, int, int]]]:
    """Flip edges of either triangulation (each flip valid in its own key) while it lowers the number
    of crossings between them: fewer Steiner points in the overlay.

    Each side's chords are tried in order, pass after pass; a chord tried and left is not tried again until its
    quadrilateral, or a count it was tried on, changes (trying it would leave it again). A chord's crossings with
    the other's chords are counted once and kept up to date as the other flips, and whether its flip keeps both
    new triangles fat in its key is worked out once for each quadrilateral: the same flips, in the same order,
    as trying every chord on every pass and counting afresh."""
    meshes = (_Polygon(m, tris0), _Polygon(m, tris1))
    positions = (pos0, pos1)
    crossings = (_Crossings(meshes[1].chords), _Crossings(meshes[0].chords))  # side s counts the other's
    fats: tuple[dict[tuple[int, int, int, int], bool], ...] = ({}, {})
    settled: tuple[set[tuple[int, int]], ...] = (set(), set())  # chords tried and left, each side
    tried_across: tuple[dict[tuple[int, int], list[tuple[int, int]]], ...] = ({}, {})  # them by their flip's chord
    for _ in range(_FLIP_ROUNDS):
        changed = False
        for side in (0, 1):
            mesh, other, pos, count, fits = meshes[side], meshes[1 - side], positions[side], crossings[side], fats[side]
            left, across = settled[side], tried_across[side]
            listed = mesh.chords - other.chords  # this pass's chords, in order
            queue = sorted(listed - left)  # a sorted list is a heap
            while queue:
                a, b = heappop(queue)
                if (a, b) in left or (a, b) not in mesh.he:
                    continue
                x, y = mesh.he[(a, b)], mesh.he[(b, a)]
                fit = fits.get((a, b, x, y))
                if fit is None:
                    fit = fits[(a, b, x, y)] = (fat(pos[a], pos[y], pos[x]) and fat(pos[y], pos[b], pos[x])
                                                and fat(pos[x], pos[a], pos[y]) and fat(pos[b], pos[x], pos[y]))
                made = (min(x, y), max(x, y))
                if not (fit and count(x, y) < count(a, b)):
                    left.add((a, b))
                    across.setdefault(made, []).append((a, b))
                    continue
                mesh.flip(a, b)
                changed = True
                for chord in (made, (min(a, x), max(a, x)), (min(x, b), max(x, b)), (min(b, y), max(b, y)),
                              (min(y, a), max(y, a))):  # the chords whose quadrilateral the flip changed
                    if chord in left:
                        left.discard(chord)
                        if chord in listed and chord > (a, b):
                            heappush(queue, chord)  # still to come in this pass
                theirs, their_across = settled[1 - side], tried_across[1 - side]
                for chord in crossings[1 - side].flipped((a, b), made):
                    theirs.discard(chord)
                    theirs.difference_update(their_across.pop(chord, ()))
        if not changed:
            break
    return meshes[0].triangles(), meshes[1].triangles()


def overlay_face(m: int, tris0: list[tuple[int, int, int]], tris1: list[tuple[int, int, int]], cap: int
                 ) -> tuple[list[tuple[int, int, int]], list[tuple[int, int, float, int, int, float]]] | None:
    """Overlay two triangulations of one ``m``-gon (corners as boundary indices) laid on a regular
    ``m``-gon: the cells' triangles (indices ``≥ m`` are the crossing points) and each crossing
    point as ``(a, b, s, c, d, u)``: at ``s`` along edge ``a → b`` of the first, ``u`` along
    ``c → d`` of the second; None where that would take more than ``cap`` points."""

    def chords(tris: list[tuple[int, int, int]]) -> set[tuple[int, int]]:
        found = set()
        for tri in tris:
            for k in range(3):
                a, b = sorted((tri[k], tri[(k + 1) % 3]))
                if (b - a) % m not in (1, m - 1):
                    found.add((a, b))
        return found

    c0, c1 = chords(tris0), chords(tris1)
    only0 = np.array(sorted(c0 - c1), dtype=np.intp).reshape(-1, 2)
    only1 = np.array(sorted(c1 - c0), dtype=np.intp).reshape(-1, 2)
    if len(only0) == 0:
        return list(tris0), []
    a, b = only0[:, 0][:, None], only0[:, 1][:, None]
    c, d = only1[:, 0][None, :], only1[:, 1][None, :]
    hit = ((a < c) & (c < b) & (b < d)) | ((c < a) & (a < d) & (d < b))
    i, j = np.nonzero(hit)
    if len(i) > cap:
        return None
    angle = 2.0 * np.pi * np.arange(m) / m
    q = np.column_stack([np.cos(angle), np.sin(angle)])
    qa, qb, qc, qd = q[only0[i, 0]], q[only0[i, 1]], q[only1[j, 0]], q[only1[j, 1]]
    r, e = qb - qa, qd - qc
    denom = r[:, 0] * e[:, 1] - r[:, 1] * e[:, 0]
    w = qc - qa
    s = (w[:, 0] * e[:, 1] - w[:, 1] * e[:, 0]) / denom
    u = (w[:, 0] * r[:, 1] - w[:, 1] * r[:, 0]) / denom
    points = qa + s[:, None] * r
    # the planar graph: boundary edges and every chord cut at its crossings
    outgoing: dict[int, list[tuple[float, int]]] = {}

    def link(x: int, y: int, direction: Array) -> None:
        outgoing.setdefault(x, []).append((math.atan2(direction[1], direction[0]), y))
        outgoing.setdefault(y, []).append((math.atan2(-direction[1], -direction[0]), x))

    for k in range(m):
        link(k, (k + 1) % m, q[(k + 1) % m] - q[k])
    for chord in c0 & c1:
        link(chord[0], chord[1], q[chord[1]] - q[chord[0]])
    for side, chords_k, own, param in ((0, only0, i, s), (1, only1, j, u)):
        for k, (x, y) in enumerate(chords_k.tolist()):
            on = np.flatnonzero(own == k)
            stops = [x] + (m + on[np.argsort(param[on])]).tolist() + [y]
            direction = q[y] - q[x]
            for p, r_ in zip(stops, stops[1:]):
                link(p, r_, direction)
    for v in outgoing:
        outgoing[v].sort()
    position = {(v, y): k for v, edges in outgoing.items() for k, (_, y) in enumerate(edges)}
    done: set[tuple[int, int]] = set()
    cells: list[tuple[int, int, int]] = []
    for (x, y) in list(position):
        if (x, y) in done:
            continue
        cycle, hx, hy, outside = [], x, y, False
        while (hx, hy) not in done:
            done.add((hx, hy))
            cycle.append(hx)
            outside = outside or (hx, hy) == (1, 0)  # the boundary walked backwards: the outside
            edges = outgoing[hy]
            nxt = edges[position[(hy, hx)] - 1][1]
            hx, hy = hy, nxt
        if len(cycle) < 3 or outside:
            continue
        cells.extend((cycle[0], cycle[k], cycle[k + 1]) for k in range(1, len(cycle) - 1))
    extra = [(int(only0[i[k], 0]), int(only0[i[k], 1]), float(s[k]), int(only1[j[k], 0]), int(only1[j[k], 1]),
              float(u[k])) for k in range(len(i))]
    return cells, extra
