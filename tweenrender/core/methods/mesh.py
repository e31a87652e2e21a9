"""Compatible triangulations of two corresponding polygons, for as-rigid-as-possible paths (maths §5.4).

One key's polygon is triangulated — ear clipping as a seed, Lawson flips to the
constrained Delaunay triangulation, then Delaunay refinement (after Ruppert:
circumcentres of poor or large triangles inserted, boundary edges split at
their midpoints where a new point would crowd them) — and the same triangles
are carried to the other key: a vertex on a boundary edge keeps its fraction
along that edge, an interior vertex is placed as rigidly as possible with the
boundary held (a few local/global iterations). Triangles that fold over in
the other key are then repaired where an edge flip or moving an interior
vertex to the middle of its neighbours removes the fold; the triangulation of
whichever key folds less is kept. Pure numpy (and scipy's sparse solver);
a polygon that is not simple, or has no area, raises :class:`MeshError`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ...errors import GeometryError
from ..crossings import self_crossing
from ..geometry import signed_area

__all__ = ["MeshError", "Mesh", "compatible_mesh", "triangulate", "ear_clip", "edge_matrix"]

Array = NDArray[np.float64]
Triangles = NDArray[np.intp]

_QUALITY = math.sqrt(2.0)  # circumradius / shortest edge above this is poor (min angle below 20.7°)
_SIZE = 8.0  # the largest triangle allowed is the polygon's area over this
_BUDGET = 6  # Steiner points allowed per boundary vertex (and at least 300)
_FIT_ROUNDS = 12



class MeshError(GeometryError):
    """The polygon cannot be triangulated (not simple, no area, repeated vertices)."""


@dataclass(frozen=True)
class Mesh:
    """Triangles over two keys: ``p0``, ``p1`` are ``(V, 2)`` with the polygon's ``n`` vertices first,
    in order; ``triangles (F, 3)`` are counter-clockwise in ``p0``; ``folds`` counts triangles
    whose orientation flips in ``p1``; ``source`` is the key (0 or 1) that was triangulated."""

    p0: Array
    p1: Array
    triangles: Triangles
    n: int
    folds: int
    source: int


def edge_matrix(points: Array, triangles: Triangles) -> Array:
    """Each triangle's edge vectors ``[b - a, c - a]`` as columns: ``(F, 2, 2)``."""
    a, b, c = (points[triangles[:, k]] for k in range(3))
    return np.stack([b - a, c - a], axis=-1)


def _doubled_areas(points: Array, triangles: Triangles) -> Array:
    return np.linalg.det(edge_matrix(points, triangles))


def compatible_mesh(k0: Array, k1: Array) -> Mesh:
    """A triangulation of corresponding simple polygons ``k0``, ``k1`` ``(n, 2)`` valid in both
    where it can be: the one of ``k0`` unless ``k1``'s folds less. Raises :class:`MeshError` when
    neither key can be triangulated."""
    k0, k1 = np.asarray(k0, dtype=np.float64), np.asarray(k1, dtype=np.float64)
    found: list[Mesh] = []
    errors: list[str] = []
    for source in (0, 1):
        a, b = (k0, k1) if source == 0 else (k1, k0)
        try:
            p, triangles, boundary = triangulate(a)
        except MeshError as error:
            errors.append(str(error))
            continue
        q = _carry(p, triangles, boundary, a, b)
        triangles, q = _repair(p, q, triangles, boundary[:, 0] < 0)
        folds = int((_doubled_areas(q, triangles) * _orientation(p, triangles) <= 0).sum())
        mesh = Mesh(p, q, triangles, len(a), folds, 0) if source == 0 else \
            Mesh(q, p, triangles, len(a), folds, 1)
        found.append(mesh)
        if folds == 0:
            break
    if not found:
        raise MeshError(errors[0])
    best = min(found, key=lambda m: m.folds)
    if best.source == 1 and _doubled_areas(best.p0, best.triangles).sum() < 0:
        # counter-clockwise in p0 as promised (key 1 was triangulated; key 0 winds the other way)
        best = Mesh(best.p0, best.p1, best.triangles[:, ::-1].copy(), best.n, best.folds, 1)
    return best


def _orientation(p: Array, triangles: Triangles) -> Array:
    return np.sign(_doubled_areas(p, triangles))


# -- one polygon ---------------------------------------------------------------------------------


def _check_polygon(points: Array) -> None:
    n = len(points)
    if n < 3:
        raise MeshError(f"a polygon needs 3 vertices, found {n}")
    if np.any(np.all(points == np.roll(points, 1, axis=0), axis=1)):
        raise MeshError("the polygon repeats a vertex")
    if not np.all(np.isfinite(points)):
        raise MeshError("the polygon has a coordinate that is not finite")
    if float(signed_area(points)) == 0.0:
        raise MeshError("the polygon has no area")
    if self_crossing(points) is not None:
        raise MeshError("the polygon crosses itself")


def triangulate(points: Array) -> tuple[Array, Triangles, Array]:
    """Constrained Delaunay triangulation of the simple polygon ``points (n, 2)``, refined.

    Returns the vertices ``(V, 2)`` (the polygon's first), triangles ``(F, 3)`` counter-clockwise,
    and for each vertex where it lies on the boundary: ``(V, 2)`` of (edge index, fraction along
    that edge), ``(-1, nan)`` for an interior vertex.
    """
    points = np.asarray(points, dtype=np.float64)
    _check_polygon(points)
    n = len(points)
    # triangulated at unit size: the refinement's tests multiply up to six lengths, which underflow
    # for polygons under about 1e-50 across (and overflow for huge ones)
    low = points.min(axis=0)
    extent = float(np.max(points.max(axis=0) - low))
    unit = (points - low) / extent
    ccw = float(signed_area(points)) > 0
    order = np.arange(n) if ccw else np.arange(n)[::-1]
    seed = ear_clip(unit[order])
    mesh = _Refiner(unit[order], seed, order, ccw)
    mesh.make_delaunay()
    area = abs(float(signed_area(unit)))
    mesh.refine(max_area=area / _SIZE, budget=max(300, _BUDGET * n))
    vertices, triangles, places = mesh.result()
    vertices = vertices * extent + low
    vertices[:n] = points  # the polygon's own vertices exactly, not rounded through the unit copy
    return vertices, triangles, places


def ear_clip(points: Array) -> Triangles:
    """Triangles ``(n - 2, 3)`` of a simple counter-clockwise polygon ``(n, 2)`` by ear clipping.

    An ear is a strictly convex vertex whose triangle holds no other vertex, not even on its
    sides; collinear vertices are never clipped, so no triangle is flat.
    """
    points = np.asarray(points, dtype=np.float64)
    n = len(points)
    live = list(range(n))
    x, y = points[:, 0], points[:, 1]
    triangles: list[tuple[int, int, int]] = []

    def is_ear(k: int) -> bool:
        m = len(live)
        a, b, c = live[(k - 1) % m], live[k], live[(k + 1) % m]
        ax, ay, bx, by, cx, cy = x[a], y[a], x[b], y[b], x[c], y[c]
        if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) <= 0:
            return False
        others = np.array([v for v in live if v not in (a, b, c)], dtype=np.intp)
        if len(others) == 0:
            return True
        px, py = x[others], y[others]
        d1 = (bx - ax) * (py - ay) - (by - ay) * (px - ax)
        d2 = (cx - bx) * (py - by) - (cy - by) * (px - bx)
        d3 = (ax - cx) * (py - cy) - (ay - cy) * (px - cx)
        inside = (d1 >= 0) & (d2 >= 0) & (d3 >= 0)
        return not inside.any()

    k = 0
    misses = 0
    while len(live) > 3:
        if misses > len(live):
            raise MeshError("ear clipping found no ear (the polygon is not simple)")
        k %= len(live)
        if is_ear(k):
            m = len(live)
            triangles.append((live[(k - 1) % m], live[k], live[(k + 1) % m]))
            del live[k]
            k = max(k - 1, 0)
            misses = 0
        else:
            k += 1
            misses += 1
    a, b, c = live
    if (x[b] - x[a]) * (y[c] - y[a]) - (y[b] - y[a]) * (x[c] - x[a]) <= 0:
        raise MeshError("ear clipping left a flat triangle (the polygon is not simple)")
    triangles.append((a, b, c))
    return np.array(triangles, dtype=np.intp)


def _incircle(ax: float, ay: float, bx: float, by: float, cx: float, cy: float, dx: float, dy: float) -> float:
    """Positive when d lies inside the circle through counter-clockwise a, b, c."""
    adx, ady, bdx, bdy, cdx, cdy = ax - dx, ay - dy, bx - dx, by - dy, cx - dx, cy - dy
    return ((adx * adx + ady * ady) * (bdx * cdy - cdx * bdy)
            - (bdx * bdx + bdy * bdy) * (adx * cdy - cdx * ady)
            + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady))


def _orient(ax: float, ay: float, bx: float, by: float, cx: float, cy: float) -> float:
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)


class _Refiner:
    """A mutable constrained triangulation of one counter-clockwise polygon: flips, insertions."""

    def __init__(self, points: Array, seed: Triangles, order: NDArray[np.intp], ccw: bool) -> None:
        n = len(points)
        self.n = n
        self.order = order  # position k of the working polygon is vertex order[k] of the caller's
        self.x: list[float] = points[:, 0].tolist()
        self.y: list[float] = points[:, 1].tolist()
        # where each vertex lies on the caller's polygon: (edge, fraction) or (-1, nan)
        self.on_edge: list[tuple[int, float]] = []
        for k in range(n):
            self.on_edge.append((int(order[k]), 0.0))
        self.tris: dict[int, tuple[int, int, int]] = {}
        self.edge: dict[tuple[int, int], int] = {}
        self.next_id = 0
        # boundary subsegments of the working polygon: (u, v) in counter-clockwise order →
        # (caller's edge index, fraction at u, fraction at v)
        self.segments: dict[tuple[int, int], tuple[int, float, float]] = {}
        # the same subsegments as rows of arrays (diametral circles), for vectorised encroachment tests
        self._rows: dict[tuple[int, int], int] = {}
        self._circles = np.zeros((2 * n + 16, 3))  # centre x, centre y, radius²
        self._alive = np.zeros(2 * n + 16, dtype=bool)
        self._count = 0
        for k in range(n):
            u, v = k, (k + 1) % n
            if ccw:
                self.segments[(u, v)] = (int(order[u]), 0.0, 1.0)
            else:  # the caller's edge runs from order[v] to order[u]
                self.segments[(u, v)] = (int(order[v]), 1.0, 0.0)
        for key in self.segments:
            self._add_circle(key)
        for a, b, c in seed.tolist():
            self.add(a, b, c)

    # -- bookkeeping -------------------------------------------------------------------------
    def _add_circle(self, key: tuple[int, int]) -> None:
        if self._count == len(self._alive):
            self._circles = np.concatenate([self._circles, np.zeros_like(self._circles)])
            self._alive = np.concatenate([self._alive, np.zeros_like(self._alive)])
        u, v = key
        x, y = self.x, self.y
        self._circles[self._count] = (0.5 * (x[u] + x[v]), 0.5 * (y[u] + y[v]),
                                      0.25 * ((x[u] - x[v]) ** 2 + (y[u] - y[v]) ** 2))
        self._alive[self._count] = True
        self._rows[key] = self._count
        self._count += 1

    def add(self, a: int, b: int, c: int) -> int:
        t = self.next_id
        self.next_id += 1
        self.tris[t] = (a, b, c)
        self.edge[(a, b)] = t
        self.edge[(b, c)] = t
        self.edge[(c, a)] = t
        return t

    def remove(self, t: int) -> tuple[int, int, int]:
        a, b, c = self.tris.pop(t)
        for e in ((a, b), (b, c), (c, a)):
            if self.edge.get(e) == t:
                del self.edge[e]
        return a, b, c

    def apex(self, u: int, v: int) -> int | None:
        """The third vertex of the triangle holding the directed edge ``u → v``."""
        t = self.edge.get((u, v))
        if t is None:
            return None
        a, b, c = self.tris[t]
        return c if (a, b) == (u, v) else a if (b, c) == (u, v) else b

    def fixed(self, u: int, v: int) -> bool:
        return (u, v) in self.segments or (v, u) in self.segments

    def poor(self, t: int, max_area: float) -> bool:
        a, b, c = self.tris[t]
        x, y = self.x, self.y
        la = (x[b] - x[c]) ** 2 + (y[b] - y[c]) ** 2
        lb = (x[c] - x[a]) ** 2 + (y[c] - y[a]) ** 2
        lc = (x[a] - x[b]) ** 2 + (y[a] - y[b]) ** 2
        area2 = _orient(x[a], y[a], x[b], y[b], x[c], y[c])
        if area2 <= 0:
            return False
        # circumradius² / shortest² = (la·lb·lc) / (4·area2²·shortest²), squared lengths, area2 = 2·area
        ratio2 = la * lb * lc / (4.0 * area2 * area2 * min(la, lb, lc))
        return ratio2 > _QUALITY ** 2 or 0.5 * area2 > max_area

    # -- flips -----------------------------------------------------------------------------
    def legal(self, u: int, v: int) -> bool:
        """Whether the edge ``u → v`` is locally Delaunay (or fixed, or on the hull)."""
        if self.fixed(u, v):
            return True
        c, d = self.apex(u, v), self.apex(v, u)
        if c is None or d is None:
            return True
        x, y = self.x, self.y
        return _incircle(x[u], y[u], x[v], y[v], x[c], y[c], x[d], y[d]) <= 0

    def flip(self, u: int, v: int) -> tuple[int, int]:
        """Replace the diagonal ``u–v`` of triangles (u, v, c), (v, u, d) by ``c–d``."""
        c, d = self.apex(u, v), self.apex(v, u)
        assert c is not None and d is not None
        self.remove(self.edge[(u, v)])
        self.remove(self.edge[(v, u)])
        self.add(c, u, d)
        self.add(d, v, c)
        return c, d

    def make_delaunay(self) -> None:
        stack = [e for e in self.edge if e[0] < e[1]]
        self._legalize(stack)

    def _legalize(self, stack: list[tuple[int, int]]) -> None:
        guard = 0
        limit = 50 * (len(self.tris) + 10) ** 2
        while stack:
            guard += 1
            if guard > limit:  # flips always end on exact arithmetic; this is a net for rounding
                break
            u, v = stack.pop()
            if (u, v) not in self.edge or self.legal(u, v):
                continue
            c, d = self.flip(u, v)
            stack.extend([(u, d), (d, v), (v, c), (c, u)])

    # -- insertion -----------------------------------------------------------------------------
    def locate(self, px: float, py: float, start: int) -> tuple[str, object]:
        """Walk from triangle ``start`` towards the point: ``("inside", t)``, ``("edge", (u, v))``
        when it lies on an edge, or ``("blocked", (u, v))`` at the boundary subsegment in the way."""
        x, y = self.x, self.y
        t = start
        for _ in range(4 * len(self.tris) + 16):
            a, b, c = self.tris[t]
            moved = False
            on: tuple[int, int] | None = None
            for u, v in ((a, b), (b, c), (c, a)):
                side = _orient(x[u], y[u], x[v], y[v], px, py)
                if side < 0:
                    nxt = self.edge.get((v, u))
                    if nxt is None:
                        return "blocked", (u, v)
                    t = nxt
                    moved = True
                    break
                if side == 0:
                    on = (u, v)
            if not moved:
                return ("edge", on) if on is not None else ("inside", t)
        return "blocked", None

    def insert_inside(self, t: int, px: float, py: float) -> int:
        p = self._new_vertex(px, py, (-1, math.nan))
        a, b, c = self.remove(t)
        self.add(a, b, p)
        self.add(b, c, p)
        self.add(c, a, p)
        self._legalize([(a, b), (b, c), (c, a)])
        return p

    def insert_on_edge(self, u: int, v: int, px: float, py: float, where: tuple[int, float]) -> int:
        p = self._new_vertex(px, py, where)
        outer: list[tuple[int, int]] = []
        for s, e in ((u, v), (v, u)):
            c = self.apex(s, e)
            if c is None:
                continue
            self.remove(self.edge[(s, e)])
            self.add(s, p, c)
            self.add(p, e, c)
            outer.extend([(e, c), (c, s)])
        if (u, v) in self.segments:
            edge, fu, fv = self.segments.pop((u, v))
            self._alive[self._rows.pop((u, v))] = False
            fm = 0.5 * (fu + fv)
            self.segments[(u, p)] = (edge, fu, fm)
            self.segments[(p, v)] = (edge, fm, fv)
            self._add_circle((u, p))
            self._add_circle((p, v))
        self._legalize(outer)
        return p

    def _new_vertex(self, px: float, py: float, where: tuple[int, float]) -> int:
        self.x.append(px)
        self.y.append(py)
        self.on_edge.append(where)
        return len(self.x) - 1

    def split_segment(self, u: int, v: int) -> int:
        edge, fu, fv = self.segments[(u, v)]
        fm = 0.5 * (fu + fv)
        return self.insert_on_edge(u, v, 0.5 * (self.x[u] + self.x[v]), 0.5 * (self.y[u] + self.y[v]), (edge, fm))

    def encroached(self, px: float, py: float) -> tuple[int, int] | None:
        """A boundary subsegment whose diametral circle holds the point strictly, or None."""
        circles = self._circles[:self._count]
        inside = (circles[:, 0] - px) ** 2 + (circles[:, 1] - py) ** 2 < circles[:, 2] * (1 - 1e-12)
        hits = np.flatnonzero(inside & self._alive[:self._count])
        if len(hits) == 0:
            return None
        row = int(hits[0])
        return next(key for key, r in self._rows.items() if r == row)

    def refine(self, max_area: float, budget: int) -> None:
        """Delaunay refinement until every triangle is good and small, or ``budget`` points are added."""
        x, y = self.x, self.y
        shortest = min(math.dist((x[u], y[u]), (x[v], y[v])) for u, v in self.segments)
        floor = 1e-3 * shortest  # subsegments this short are not split again
        added = 0
        queue = [t for t in self.tris if self.poor(t, max_area)]
        skipped: set[tuple[int, int, int]] = set()
        while queue and added < budget:
            t = queue.pop()
            if t not in self.tris or not self.poor(t, max_area) or self.tris[t] in skipped:
                continue
            a, b, c = self.tris[t]
            cx, cy = _circumcentre(x[a], y[a], x[b], y[b], x[c], y[c])
            before = set(self.tris)
            segment = self.encroached(cx, cy)
            if segment is None:
                kind, found = self.locate(cx, cy, t)
                if kind == "inside":
                    self.insert_inside(found, cx, cy)  # type: ignore[arg-type]
                elif kind == "edge" and not self.fixed(*found):  # type: ignore[misc]
                    self.insert_on_edge(*found, cx, cy, (-1, math.nan))  # type: ignore[misc]
                else:
                    segment = found  # type: ignore[assignment]
                    if segment is not None and segment not in self.segments:
                        segment = (segment[1], segment[0]) if (segment[1], segment[0]) in self.segments else None
            if segment is not None:
                u, v = segment
                if math.dist((x[u], y[u]), (x[v], y[v])) < 2 * floor:
                    skipped.add(self.tris[t])
                    continue
                self.split_segment(u, v)
            elif t in self.tris and set(self.tris) == before:
                skipped.add(self.tris[t])
                continue
            added += 1
            queue.extend(s for s in set(self.tris) - before if self.poor(s, max_area))
            if t in self.tris:
                queue.append(t)

    def result(self) -> tuple[Array, Triangles, Array]:
        """Vertices in the caller's order (polygon first), triangles counter-clockwise, boundary places."""
        n = self.n
        count = len(self.x)
        caller = np.concatenate([self.order, np.arange(n, count)])  # working index → caller index
        points = np.empty((count, 2))
        points[caller] = np.column_stack([self.x, self.y])
        triangles = caller[np.array(list(self.tris.values()), dtype=np.intp)]
        places = np.empty((count, 2))
        places[caller] = np.array(self.on_edge, dtype=np.float64)
        return points, triangles, places


def _circumcentre(ax: float, ay: float, bx: float, by: float, cx: float, cy: float) -> tuple[float, float]:
    bx, by, cx, cy = bx - ax, by - ay, cx - ax, cy - ay
    d = 2.0 * (bx * cy - by * cx)
    b2, c2 = bx * bx + by * by, cx * cx + cy * cy
    return ax + (cy * b2 - by * c2) / d, ay + (bx * c2 - cx * b2) / d


# -- the other key -------------------------------------------------------------------------------


def _carry(p: Array, triangles: Triangles, places: Array, a: Array, b: Array) -> Array:
    """Positions ``(V, 2)`` in key ``b`` of the vertices ``p`` triangulating key ``a``."""
    n = len(a)
    q = np.empty_like(p)
    q[:n] = b
    edge = places[:, 0]
    on = edge >= 0
    on[:n] = False
    if on.any():
        i = edge[on].astype(np.intp)
        f = places[on, 1][:, None]
        q[on] = (1.0 - f) * b[i] + f * b[(i + 1) % n]
    inner = np.flatnonzero(edge < 0)
    if len(inner):
        q[inner] = _fit_interior(p, q, triangles, inner)
    return q


def _fit_interior(p: Array, q: Array, triangles: Triangles, inner: NDArray[np.intp]) -> Array:
    """Interior vertices ``inner`` placed as rigidly as possible with every other vertex held."""
    from scipy.sparse import csr_matrix
    from scipy.sparse.linalg import splu

    from ..geometry import best_fit_rotation

    held = np.ones(len(p), dtype=bool)
    held[inner] = False
    tails = triangles.reshape(-1)
    heads = np.roll(triangles, -1, axis=1).reshape(-1)
    rows = np.arange(len(tails))
    weight = np.repeat(0.5 * np.abs(_doubled_areas(p, triangles)), 3)
    D = csr_matrix((np.concatenate([-np.ones(len(rows)), np.ones(len(rows))]),
                    (np.concatenate([rows, rows]), np.concatenate([tails, heads]))), shape=(len(rows), len(p)))
    L = (D.T @ D.multiply(weight[:, None])).tocsc()
    free = np.flatnonzero(~held)
    fixed = np.flatnonzero(held)
    solve = splu(L[free][:, free].tocsc())
    coupling = L[free][:, fixed]
    e0 = p[heads] - p[tails]
    n_boundary = int(held.sum())
    angle = np.full(len(triangles), float(best_fit_rotation(p[held], q[held])) if n_boundary >= 2 else 0.0)
    out = q.copy()
    for round_ in range(_FIT_ROUNDS):
        turned = _rotate(e0, np.repeat(angle, 3))
        rhs = D.T @ (weight[:, None] * turned)
        out[free] = solve.solve(np.asarray(rhs[free] - coupling @ out[fixed]))
        e1 = out[heads] - out[tails]
        s = (e0[:, 0] * e1[:, 1] - e0[:, 1] * e1[:, 0]).reshape(-1, 3).sum(axis=1)
        c = (e0 * e1).sum(axis=1).reshape(-1, 3).sum(axis=1)
        angle = np.arctan2(s, c)
    return out[inner]


def _rotate(v: Array, angle: Array) -> Array:
    c, s = np.cos(angle), np.sin(angle)
    return np.column_stack([c * v[:, 0] - s * v[:, 1], s * v[:, 0] + c * v[:, 1]])


# -- repair ----------------------------------------------------------------------------------------


def _repair(p: Array, q: Array, triangles: Triangles, movable: NDArray[np.bool_]) -> tuple[Triangles, Array]:
    """Remove folds of ``q`` where flipping an edge, or moving an interior vertex to the middle of
    its neighbours, does so while keeping every triangle valid in ``p``."""
    triangles = triangles.copy()
    q = q.copy()
    for _ in range(8):
        sign0 = _orientation(p, triangles)
        folded = _doubled_areas(q, triangles) * sign0 <= 0
        if not folded.any():
            break
        changed = _flip_folds(p, q, triangles, folded)
        changed |= _smooth_folds(p, q, triangles, folded, movable)
        if not changed:
            break
    return triangles, q


def _flip_folds(p: Array, q: Array, triangles: Triangles, folded: NDArray[np.bool_]) -> bool:
    """Flip interior edges of folded triangles where both new triangles are valid in p and q."""
    owner: dict[tuple[int, int], int] = {}
    for t, (a, b, c) in enumerate(triangles.tolist()):
        owner[(a, b)], owner[(b, c)], owner[(c, a)] = t, t, t
    keys = (p.tolist(), q.tolist())  # the two keys' vertices as floats: one candidate at a time

    def valid(a: int, b: int, c: int) -> bool:  # counter-clockwise in both keys
        return all(_orient(*x[a], *x[b], *x[c]) > 0 for x in keys)

    changed = False
    for t in np.flatnonzero(folded).tolist():
        a, b, c = triangles[t].tolist()
        for u, v, w in ((a, b, c), (b, c, a), (c, a, b)):
            s = owner.get((v, u))
            if s is None:
                continue
            d = [x for x in triangles[s].tolist() if x not in (u, v)][0]
            if valid(w, u, d) and valid(d, v, w):  # both new triangles, in p and in q
                new = np.array([[w, u, d], [d, v, w]], dtype=np.intp)
                triangles[t], triangles[s] = new
                for k, tri in ((t, new[0]), (s, new[1])):
                    x0, x1, x2 = tri.tolist()
                    owner[(x0, x1)], owner[(x1, x2)], owner[(x2, x0)] = k, k, k
                owner.pop((u, v), None)
                owner.pop((v, u), None)
                changed = True
                break
    return changed


def _smooth_folds(p: Array, q: Array, triangles: Triangles, folded: NDArray[np.bool_],
                  movable: NDArray[np.bool_]) -> bool:
    """Move interior vertices of folded triangles to the mean of their neighbours in q, when that
    leaves fewer folds around them."""
    changed = False
    for v in np.unique(triangles[folded]).tolist():
        if not movable[v]:
            continue
        ring = np.flatnonzero(np.any(triangles == v, axis=1))
        neighbours = np.unique(triangles[ring])
        neighbours = neighbours[neighbours != v]
        sign0 = _orientation(p, triangles[ring])
        before = int((_doubled_areas(q, triangles[ring]) * sign0 <= 0).sum())
        saved = q[v].copy()
        q[v] = q[neighbours].mean(axis=0)
        after = int((_doubled_areas(q, triangles[ring]) * sign0 <= 0).sum())
        if after < before:
            changed = True
        else:
            q[v] = saved
    return changed
