"""Compatible triangulations of contours inside a common convex frame, in two keys (maths §5.9).

Both keys' contours (closed outlines, holes, pieces, open strokes; the same
vertices in both) are put inside one frame — a regular polygon, the same in
both keys — and triangulated so that the two triangulations have the same
triangles and every triangle is counter-clockwise in both keys:

1. each key gets a constrained triangulation of its own: scipy's Delaunay
   triangulation of frame and contour vertices, then every contour edge
   recovered by edge flips (Sloan 1993);
2. the regions between the contours (faces: the frame's inside less the outer
   contours, an outline less its holes, a hole's inside) are told apart by
   which closed contours enclose them; a face with several boundaries is cut
   into one (weakly simple) polygon by *bridges*: an edge of key 0's
   triangulation from one boundary to another, taken as it is where key 1 has
   the same edge, else followed in key 1 by a chain of Steiner points through
   the triangles between its ends (and split as often in key 0);
3. key 1 takes over every edge of key 0's triangulation it can (the segment
   crosses no contour and starts in the same face), so the two triangulations
   agree wherever the keys allow it without new points;
4. in each face the two triangulations, now of one polygon with the same
   boundary, are brought closer by flips and laid on a common convex polygon (boundary corners evenly on a
   circle) and overlaid: every crossing of an edge of one with an edge of the
   other becomes a Steiner point (Aronov, Seidel & Souvaine 1993), and each
   cell of the overlay — the meet of a triangle of each — is cut into a fan.
   A cell lies inside one triangle of each key, so its image is positive in
   both (:mod:`.mesh_overlay`); Steiner points are then relaxed towards fatter triangles.

Pure numpy (and scipy's Delaunay triangulation, imported when it runs).
Keys whose contours cross themselves or each other, wind the other way round, or
nest differently, raise :class:`CompatibleError`, as does an overlay that would
need more than :data:`STEINER_CAP` Steiner points, or bridges of more than :data:`BRIDGE_CAP` (a frame
would then cost more than the animation is worth).
"""

from __future__ import annotations

import math
from collections import deque
from dataclasses import dataclass
from typing import Sequence

import numpy as np
from numpy.typing import NDArray

from ...errors import GeometryError
from .mesh_overlay import fat, fewer_crossings, orient, overlay_face, relax

__all__ = ["BRIDGE_CAP", "COINCIDENT", "CompatibleError", "CompatibleMesh", "compatible_triangulation", "FRAME_SIDES",
           "STEINER_CAP"]

Array = NDArray[np.float64]
Triangles = NDArray[np.intp]

FRAME_SIDES = 24
"""Corners of the frame polygon (a regular polygon around both keys)."""

COINCIDENT = "the key has coincident vertices"
"""Why a key has no compatible triangulation where two of its vertices are one point (a joined contour's slit)."""
STEINER_CAP = 20_000
"""Most crossing points one face's overlay may add; past it the keys have no injective paths here."""

BRIDGE_CAP = 4_000
"""Most points the bridges of one mesh may add (real drawings take at most a few hundred); past it the keys
have no injective paths here: each bridge's chain lengthens the next ones', which can grow without bound."""

_FRAME_SCALE = 2.0  # frame radius over the keys' largest distance from their centre
_FLIP_GUARD = 200  # flips allowed per recovered edge, times the edges it crosses at first

_FRAME = -1  # component of a frame vertex


class CompatibleError(GeometryError):
    """The keys have no compatible triangulation here (contours cross, or nest differently)."""


@dataclass(frozen=True)
class CompatibleMesh:
    """One triangulation in two keys: ``p0``, ``p1`` are ``(V, 2)`` with the contours' ``n``
    vertices first (in the order given), then the frame's ``FRAME_SIDES`` corners, then Steiner
    points; ``triangles (F, 3)`` are counter-clockwise in both keys; ``frame (B,)`` lists the frame
    corners in order; ``steiner`` counts the points added (bridges and overlay)."""

    p0: Array
    p1: Array
    triangles: Triangles
    frame: NDArray[np.intp]
    n: int
    steiner: int


class _Triangulation:
    """A mutable triangulation: counter-clockwise triangles, half-edges ``(u, v) → triangle``,
    constraint edges ``fixed`` (never flipped), a face label per triangle."""

    def __init__(self, points: Array, triangles: Triangles) -> None:
        self.pts: list[tuple[float, float]] = [(float(x), float(y)) for x, y in points]
        self.tri: list[tuple[int, int, int] | None] = []
        self.label: list[int] = []
        self.he: dict[tuple[int, int], int] = {}
        self.out: dict[int, int] = {}
        self.fixed: set[tuple[int, int]] = set()
        self.kept: set[tuple[int, int]] = set()
        for a, b, c in triangles.tolist():
            if orient(self.pts[a], self.pts[b], self.pts[c]) < 0:
                b, c = c, b
            self.add(a, b, c, -1)

    def add(self, a: int, b: int, c: int, label: int) -> int:
        t = len(self.tri)
        self.tri.append((a, b, c))
        self.label.append(label)
        self.he[(a, b)] = self.he[(b, c)] = self.he[(c, a)] = t
        self.out[a], self.out[b], self.out[c] = b, c, a
        return t

    def remove(self, t: int) -> tuple[int, int, int]:
        a, b, c = self.tri[t]  # type: ignore[misc]
        self.tri[t] = None
        del self.he[(a, b)], self.he[(b, c)], self.he[(c, a)]
        return a, b, c

    def third(self, u: int, v: int) -> int:
        """The corner opposite half-edge ``u → v`` in its triangle."""
        a, b, c = self.tri[self.he[(u, v)]]  # type: ignore[misc]
        return c if (a, b) == (u, v) else a if (b, c) == (u, v) else b

    def new_point(self, x: float, y: float) -> int:
        self.pts.append((x, y))
        return len(self.pts) - 1

    def split_triangle(self, t: int, p: int) -> None:
        label = self.label[t]
        a, b, c = self.remove(t)
        self.add(a, b, p, label), self.add(b, c, p, label), self.add(c, a, p, label)

    def split_edge(self, u: int, v: int, p: int) -> None:
        for x, y in ((u, v), (v, u)):
            if (x, y) in self.he:
                t = self.he[(x, y)]
                label, w = self.label[t], self.third(x, y)
                self.remove(t)
                self.add(x, p, w, label), self.add(p, y, w, label)
        for group in (self.fixed, self.kept):
            if _key(u, v) in group:
                group.discard(_key(u, v))
                group.add(_key(u, p)), group.add(_key(p, v))

    def flip(self, u: int, v: int) -> tuple[int, int]:
        x, y = self.third(u, v), self.third(v, u)
        label = self.label[self.he[(u, v)]]
        self.remove(self.he[(u, v)]), self.remove(self.he[(v, u)])
        self.add(u, y, x, label), self.add(y, v, x, label)
        return x, y

    def around(self, a: int) -> list[int]:
        """The triangles with corner ``a``, counter-clockwise (from a boundary edge if ``a`` has one)."""
        start = self.out[a]
        if (a, start) not in self.he:
            start = next(v for (u, v) in self.he if u == a)
        # turn clockwise to the first triangle (or all the way round)
        first = start
        while (first, a) in self.he:
            prev = self.third(first, a)
            if prev == start:
                break
            first = prev
        found, b = [], first
        while (a, b) in self.he:
            t = self.he[(a, b)]
            found.append(t)
            b = self.third(a, b)
            if b == first:
                break
        return found

    def crossed(self, a: int, b: int) -> list[tuple[int, int]] | None:
        """Edges ``(u, v)`` that segment ``a → b`` crosses, in order (u to its right), or None where
        the segment meets a vertex or crosses a fixed or kept edge."""
        pa, pb = self.pts[a], self.pts[b]
        edge = None
        for t in self.around(a):
            x, y, z = self.tri[t]  # type: ignore[misc]
            u, v = (y, z) if x == a else (z, x) if y == a else (x, y)
            if u == b or v == b:
                return []
            su, sv = orient(pa, pb, self.pts[u]), orient(pa, pb, self.pts[v])
            if su < 0 < sv:
                edge = (u, v)
                break
            if (su == 0 and _ahead(pa, pb, self.pts[u])) or (sv == 0 and _ahead(pa, pb, self.pts[v])):
                return None
        if edge is None:
            return None
        found = []
        while True:
            u, v = edge
            if _key(u, v) in self.fixed or _key(u, v) in self.kept or (v, u) not in self.he:
                return None
            found.append(edge)
            w = self.third(v, u)
            if w == b:
                return found
            s = orient(pa, pb, self.pts[w])
            if s == 0:
                return None
            edge = (u, w) if s > 0 else (w, v)

    def recover(self, a: int, b: int, group: set[tuple[int, int]]) -> bool:
        """Make ``a – b`` an edge by flips (Sloan 1993) and put it in ``group``; False where it
        cannot be made (it meets a vertex or crosses a fixed or kept edge)."""
        crossing = self.crossed(a, b)
        if crossing is None:
            return False
        pa, pb = self.pts[a], self.pts[b]
        queue = deque(crossing)
        guard = _FLIP_GUARD * (len(crossing) + 1)
        while queue:
            guard -= 1
            if guard < 0:
                return False
            u, v = queue.popleft()
            x, y = self.third(u, v), self.third(v, u)
            pu, pv, px, py = self.pts[u], self.pts[v], self.pts[x], self.pts[y]
            if fat(pu, py, px) and fat(py, pv, px) and fat(px, pu, py) and fat(pv, px, py):
                self.flip(u, v)
                if {x, y} != {a, b} and _proper(pa, pb, px, py):
                    queue.append((x, y))
            else:
                queue.append((u, v))
        group.add(_key(a, b))
        return True

    def live(self) -> list[int]:
        return [t for t, corners in enumerate(self.tri) if corners is not None]


def _key(u: int, v: int) -> tuple[int, int]:
    return (u, v) if u < v else (v, u)


def _ahead(a: Sequence[float], b: Sequence[float], p: Sequence[float]) -> bool:
    """Whether ``p`` (on the line ``ab``) lies strictly between ``a`` and ``b``."""
    d = (b[0] - a[0]) * (p[0] - a[0]) + (b[1] - a[1]) * (p[1] - a[1])
    return 0 < d < (b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2


def _proper(a: Sequence[float], b: Sequence[float], c: Sequence[float], d: Sequence[float]) -> bool:
    """Whether segments ``ab`` and ``cd`` cross at one point inside both."""
    return orient(a, b, c) * orient(a, b, d) < 0 and orient(c, d, a) * orient(c, d, b) < 0


def _delaunay(points: Array) -> _Triangulation:
    from scipy.spatial import Delaunay

    try:
        found = Delaunay(points)
    except Exception as error:  # qhull refuses degenerate input
        raise CompatibleError(f"the key cannot be triangulated: {error}") from None
    if len(found.coplanar):
        raise CompatibleError(COINCIDENT)
    return _Triangulation(points, found.simplices.astype(np.intp))


@dataclass
class _Keys:
    """Both keys' triangulations, kept in step (same vertex ids), and what each vertex is."""

    one: _Triangulation
    two: _Triangulation
    component: list[int]  # contour index, _FRAME, or a bridge's merged component
    edge_contour: dict[tuple[int, int], int]  # constraint edge → contour (or _FRAME, or bridge -3)
    closed: list[bool]
    inner: set[int]  # vertices inside an open stroke: no bridge starts there (it has two sides)

    def both(self) -> tuple[_Triangulation, _Triangulation]:
        return self.one, self.two


def _winding(points: Array) -> float:
    """Twice the signed area of a closed polygon ``(L, 2)``."""
    x, y = points[:, 0], points[:, 1]
    return float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def _contour_edges(cuts: Sequence[int], closed: Sequence[bool]) -> list[tuple[int, int, int]]:
    edges = []
    for c, (start, end) in enumerate(zip(cuts, cuts[1:])):
        for i in range(start, end - 1):
            edges.append((i, i + 1, c))
        if closed[c] and end - start >= 3:
            edges.append((end - 1, start, c))
    return edges


def _label_faces(mesh: _Triangulation, keys: _Keys, frame_edges: set[tuple[int, int]]) -> dict[frozenset[int], int]:
    """Label each triangle with its face: the closed contours around it (flood fill from the frame)."""
    seen: dict[int, frozenset[int]] = {}
    start = next(t for t in mesh.live() if any(_key(*e) in frame_edges for e in _edges(mesh.tri[t])))
    seen[start] = frozenset()
    queue = deque([start])
    while queue:
        t = queue.popleft()
        inside = seen[t]
        for u, v in _edges(mesh.tri[t]):
            if (v, u) not in mesh.he:
                continue
            s = mesh.he[(v, u)]
            c = keys.edge_contour.get(_key(u, v))
            there = inside ^ {c} if c is not None and c >= 0 and keys.closed[c] else inside
            if s in seen:
                if seen[s] != there:
                    raise CompatibleError("the contours cross each other")
                continue
            seen[s] = there
            queue.append(s)
    names = {inside: k for k, inside in enumerate(sorted(set(seen.values()), key=lambda s: (len(s), sorted(s))))}
    for t, inside in seen.items():
        mesh.label[t] = names[inside]
    return names


def _edges(corners: tuple[int, int, int] | None) -> list[tuple[int, int]]:
    a, b, c = corners  # type: ignore[misc]
    return [(a, b), (b, c), (c, a)]


def compatible_triangulation(k0: Array, k1: Array, cuts: Sequence[int], closed: Sequence[bool],
                             radius: float | None = None) -> CompatibleMesh:
    """A compatible triangulation of contours ``k0``, ``k1`` (``(N, 2)`` each, contour ``c`` is
    rows ``cuts[c]:cuts[c+1]``, closed or open per ``closed``) inside a common frame of
    :data:`FRAME_SIDES` corners on a circle of ``radius`` about the origin (default: twice the
    farthest vertex)."""
    k0, k1 = np.asarray(k0, dtype=np.float64), np.asarray(k1, dtype=np.float64)
    n = len(k0)
    for start, end, shut in zip(cuts, cuts[1:], closed):
        if shut and np.sign(_winding(k0[start:end])) != np.sign(_winding(k1[start:end])):
            raise CompatibleError("a contour winds the other way round in the second key")
    if len(np.unique(k0, axis=0)) < n or len(np.unique(k1, axis=0)) < n:  # as the triangulation would say
        raise CompatibleError(COINCIDENT)  # (a joined contour's slit), at no cost
    if radius is None:
        radius = _FRAME_SCALE * max(float(np.abs(k0).max(initial=0.0)), float(np.abs(k1).max(initial=0.0)),
                                    1e-300) * math.sqrt(2.0)
    angle = 2.0 * np.pi * np.arange(FRAME_SIDES) / FRAME_SIDES
    frame = radius * np.column_stack([np.cos(angle), np.sin(angle)])
    frame_ids = list(range(n, n + FRAME_SIDES))
    keys = _Keys(_delaunay(np.vstack([k0, frame])), _delaunay(np.vstack([k1, frame])),
                 [-9] * n + [_FRAME] * FRAME_SIDES, {}, list(closed), set())
    for c, (start, end) in enumerate(zip(cuts, cuts[1:])):
        for i in range(start, end):
            keys.component[i] = c
        if not closed[c]:
            keys.inner.update(range(start + 1, end - 1))
    frame_edges = {_key(frame_ids[i], frame_ids[(i + 1) % FRAME_SIDES]) for i in range(FRAME_SIDES)}
    for u, v in frame_edges:
        keys.edge_contour[(u, v)] = _FRAME
    for mesh in keys.both():
        mesh.fixed |= frame_edges
        for u, v, c in _contour_edges(cuts, closed):
            keys.edge_contour[_key(u, v)] = c
            if not mesh.recover(u, v, mesh.fixed):
                raise CompatibleError("a contour crosses itself or another contour")
    names = _label_faces(keys.one, keys, frame_edges)
    if _label_faces(keys.two, keys, frame_edges) != names:
        raise CompatibleError("the contours nest differently in the two keys")
    _bridge(keys, cuts, closed, names)
    _take_over(keys)
    return _overlay(keys, n, frame_ids)


def _bridge(keys: _Keys, cuts: Sequence[int], closed: Sequence[bool], names: dict[frozenset[int], int]) -> None:
    """Join every face's boundaries into one by bridges (see the module's notes)."""
    one, two = keys.both()
    parent: dict[int, int] = {}

    def find(c: int) -> int:
        while parent.get(c, c) != c:
            c = parent[c]
        return c

    used: set[int] = set()
    added = 0
    for face in names.values():
        while True:
            candidates = []
            for t in one.live():
                if one.label[t] != face:
                    continue
                for u, v in _edges(one.tri[t]):
                    if u > v or _key(u, v) in one.fixed or (v, u) not in one.he:
                        continue
                    cu, cv = keys.component[u], keys.component[v]
                    if u in keys.inner or v in keys.inner or u in used or v in used or find(cu) == find(cv):
                        continue
                    shared = (u, v) in two.he and (v, u) in two.he and \
                        two.label[two.he[(u, v)]] == face == two.label[two.he[(v, u)]]
                    pu, pv = one.pts[u], one.pts[v]
                    candidates.append((not shared, (pu[0] - pv[0]) ** 2 + (pu[1] - pv[1]) ** 2, u, v))
            if not candidates:
                faced = {find(keys.component[x]) for t in one.live() if one.label[t] == face
                         for x in one.tri[t]}  # type: ignore[union-attr]
                if len(faced) > 1:
                    raise CompatibleError("no bridge left between a face's boundaries")
                break
            _, _, u, v = min(candidates)
            chain = _chain(two, u, v, face)
            if chain is None:
                raise CompatibleError("no bridge between two contours")
            added += len(chain)
            if added > BRIDGE_CAP:
                raise CompatibleError(f"the bridges between the contours would take more than {BRIDGE_CAP} points")
            ids = [u]
            for k, (x, y) in enumerate(_along(one.pts[u], one.pts[v], len(chain))):
                p = one.new_point(x, y)
                assert p == two.new_point(*chain[k][1])
                one.split_edge(ids[-1], v, p)
                ids.append(p)
            ids.append(v)
            _insert_chain(two, chain, ids)
            for a, b in zip(ids, ids[1:]):
                for mesh in keys.both():
                    if (a, b) not in mesh.he and (b, a) not in mesh.he:
                        raise CompatibleError("a bridge did not become an edge")
                    mesh.fixed.add(_key(a, b))
                keys.edge_contour[_key(a, b)] = -3
            keys.component.extend([find(keys.component[u])] * (len(ids) - 2))
            used.update(ids)
            parent[find(keys.component[v])] = find(keys.component[u])


def _along(a: tuple[float, float], b: tuple[float, float], count: int) -> list[tuple[float, float]]:
    s = np.arange(1, count + 1) / (count + 1)
    return [(a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])) for f in s.tolist()]


def _chain(mesh: _Triangulation, u: int, v: int, face: int) -> list[tuple[str, tuple[float, float], object]] | None:
    """Steiner points leading from ``u`` to ``v`` through the triangles of ``face`` between them:
    ``("centre", point, triangle corners)`` and ``("edge", point, (p, q))`` alternately; [] where
    ``u – v`` is an edge already; None where no path exists."""
    if (u, v) in mesh.he and mesh.label[mesh.he[(u, v)]] == face and (v, u) in mesh.he:
        return []
    starts = [t for t in mesh.around(u) if mesh.label[t] == face]
    back: dict[int, tuple[int, tuple[int, int]] | None] = {t: None for t in starts}
    queue = deque(starts)
    end = None
    while queue:
        t = queue.popleft()
        if v in mesh.tri[t]:  # type: ignore[operator]
            end = t
            break
        for x, y in _edges(mesh.tri[t]):
            if _key(x, y) in mesh.fixed or (y, x) not in mesh.he:
                continue
            s = mesh.he[(y, x)]
            if s not in back and mesh.label[s] == face:
                back[s] = (t, (x, y))
                queue.append(s)
    if end is None:
        return None
    path: list[tuple[int, tuple[int, int] | None]] = []
    t: int | None = end
    while t is not None:
        step = back[t]
        path.append((t, step[1] if step is not None else None))
        t = step[0] if step is not None else None
    path.reverse()  # (triangle, edge crossed to reach it): the first is entered by none
    chain: list[tuple[str, tuple[float, float], object]] = []
    for k, (t, entered) in enumerate(path):
        if entered is not None:
            p, q = mesh.pts[entered[0]], mesh.pts[entered[1]]
            chain.append(("edge", ((p[0] + q[0]) / 2, (p[1] + q[1]) / 2), entered))
        a, b, c = (mesh.pts[i] for i in mesh.tri[t])  # type: ignore[union-attr]
        chain.append(("centre", ((a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3), mesh.tri[t]))
    return chain


def _insert_chain(mesh: _Triangulation, chain: list[tuple[str, tuple[float, float], object]], ids: list[int]) -> None:
    """Insert the chain's points (ids ``ids[1:-1]``, already allocated) into ``mesh``."""
    if not chain:
        return
    points = ids[1:-1]
    for (kind, _, where), p in zip(chain, points):
        if kind == "centre":
            mesh.split_triangle(mesh.he[(where[0], where[1])], p)  # type: ignore[index]
    for (kind, _, where), p in zip(chain, points):
        if kind == "edge":
            mesh.split_edge(where[0], where[1], p)  # type: ignore[index]


def _take_over(keys: _Keys) -> None:
    """Key 1 takes every edge of key 0's triangulation it can have in the same face (module notes, 3)."""
    one, two = keys.both()
    wanted = []
    for t in one.live():
        for u, v in _edges(one.tri[t]):
            if u < v and _key(u, v) not in one.fixed and (v, u) in one.he:
                pu, pv = two.pts[u], two.pts[v]
                wanted.append(((pu[0] - pv[0]) ** 2 + (pu[1] - pv[1]) ** 2, u, v, one.label[t]))
    wanted.sort()
    for _, u, v, face in wanted:
        if (u, v) in two.he or (v, u) in two.he:
            if two.label[two.he.get((u, v), two.he.get((v, u), -1))] == face:
                two.kept.add(_key(u, v))
            continue
        route = two.crossed(u, v)
        if not route:
            continue
        first = two.he[route[0]]
        if two.label[first] != face:
            continue
        two.recover(u, v, two.kept)


def _faces_walk(mesh: _Triangulation, face: int, start: tuple[int, int]
                ) -> tuple[list[int], dict[tuple[int, int], int]]:
    """The boundary of ``face`` with the face on the left, from half-edge ``start``: its vertices in
    order (a vertex may come more than once) and which occurrence each corner ``(triangle, vertex)``
    of the face belongs to."""
    order: list[int] = []
    corner: dict[tuple[int, int], int] = {}
    u, v = start
    while True:
        order.append(u)
        k = len(order) - 1
        # turn about v through the face until the next fixed edge
        x, y = u, v
        while True:
            t = mesh.he[(x, y)]
            corner[(t, y)] = (k + 1)  # occurrence of y after u (fixed below when the walk closes)
            w = mesh.third(x, y)
            if _key(y, w) in mesh.fixed:
                u, v = y, w
                break
            x = w
        if (u, v) == start:
            break
        if len(order) > 4 * len(mesh.pts) + 8:
            raise CompatibleError("a face's boundary does not close")
    m = len(order)
    return order, {key: occ % m for key, occ in corner.items()}


def _corners(mesh: _Triangulation, face: int, occurrence: dict[tuple[int, int], int]) -> list[tuple[int, int, int]]:
    """The triangles of ``face`` by the boundary occurrences of their corners."""
    found = []
    for t in mesh.live():
        if mesh.label[t] == face:
            a, b, c = mesh.tri[t]  # type: ignore[misc]
            found.append((occurrence[(t, a)], occurrence[(t, b)], occurrence[(t, c)]))
    return found


def _overlay(keys: _Keys, n: int, frame_ids: list[int]) -> CompatibleMesh:
    one, two = keys.both()
    p0, p1 = list(one.pts), list(two.pts)
    triangles: list[tuple[int, int, int]] = []
    faces = sorted({one.label[t] for t in one.live()})
    for face in faces:
        start = min((u, v) for (u, v), t in one.he.items() if one.label[t] == face and _key(u, v) in one.fixed)
        order, corners0 = _faces_walk(one, face, start)
        if start not in two.he or two.label[two.he[start]] != face:
            raise CompatibleError("a face's boundary differs between the keys")
        order1, corners1 = _faces_walk(two, face, start)
        if order != order1:
            raise CompatibleError("a face's boundary differs between the keys")
        tris0 = _corners(one, face, corners0)
        tris1 = _corners(two, face, corners1)
        tris0, tris1 = fewer_crossings(len(order), tris0, tris1, [p0[v] for v in order],  # type: ignore[arg-type]
                                        [p1[v] for v in order])
        found = overlay_face(len(order), tris0, tris1, STEINER_CAP)
        if found is None:
            raise CompatibleError(f"the overlay needs more than {STEINER_CAP} Steiner points in one face")
        cells, extra = found
        base = len(p0)
        for a, b, s, c, d, u in extra:
            pa, pb, pc, pd = p0[order[a]], p0[order[b]], p1[order[c]], p1[order[d]]
            p0.append((pa[0] + s * (pb[0] - pa[0]), pa[1] + s * (pb[1] - pa[1])))
            p1.append((pc[0] + u * (pd[0] - pc[0]), pc[1] + u * (pd[1] - pc[1])))
        m = len(order)
        for cell in cells:
            triangles.append(tuple(order[i] if i < m else base + i - m for i in cell))  # type: ignore[arg-type]
    tris = np.array(triangles, dtype=np.intp).reshape(-1, 3)
    start = n + len(frame_ids)
    return CompatibleMesh(relax(np.array(p0), tris, start), relax(np.array(p1), tris, start), tris,
                          np.array(frame_ids, dtype=np.intp), n, len(p0) - start)
