"""Injective paths: in-betweens that never cross themselves (maths §5.9).

After Gotsman & Surazhsky, "Guaranteed intersection-free polygon morphing"
(2001), on Floater & Gotsman, "How to morph tilings injectively" (1999):

1. a rigid turn is taken out: where key 1 is key 0 turned (to within ``_RIGID`` of its
   size, after the best fit, maths §5.2), key 1 is turned back by that angle φ about its vertex
   mean; between keys that differ φ = 0 (a best-fit turn of unlike shapes is arbitrary and
   would swing the in-betweens round); both keys are centred;
2. the contours of both keys get one compatible triangulation inside a common
   frame (:mod:`.compatible`);
3. in each key every vertex but the frame's is the mean-value combination
   (Floater 2003: positive weights) of its neighbours; at ``t`` the weights are
   blended, ``λ(t) = (1-t)·λ(0) + t·λ(1)`` (t clamped to [0, 1]), and the
   vertices solve ``x_i = Σ_j λ_ij(t)·x_j`` with the frame held (one sparse LU,
   :mod:`.tutte`). By Tutte and Floater the result is a valid triangulation at every
   t, so no contour crosses itself or another, and a hole stays in its outline;
4. that solve is valid but lets the shape wander and distort; the in-between drawn is the
   shape-keeping solve of :mod:`.bounded_distortion` (each triangle turning and stretching by
   a share of its own change), made injective by descents that never turn a triangle over, at
   grid points from either key, whose weights are blended as in step 3 (the solve of step 3
   itself is drawn only for a mesh too large to descend);
5. the contours are centred (their vertex mean follows the straight path) and scaled about it
   to the keys' interpolated area, ``(1-s)·A0 + s·A1`` (closed contours' signed areas summed):
   a similarity keeps them simple;
6. the path of steps 4–5 is paced: the frame at ``t`` is the path at the ``s`` that has come the
   share ``t`` of its way, measured by the area the contours sweep (:meth:`_Paths._pace`), ``s`` by ``t``
   a monotone cubic through the samples (so the speed changes without a jolt at each): the solve
   alone moves fastest out of the keys, a pop in the first and last frame steps;
7. the rigid motion is put back: the shape turns by ``t·φ`` about its vertex
   mean, which moves on a straight line.

Copies of a vertex (balancing by copies) are spread along their edges first
(:func:`.balance.spread`): coincident vertices cannot be triangulated. Keys
whose contours cross themselves or each other, or nest differently, have no
such paths: they take the exact rigid paths (maths §5.2) instead, as do
contours of fewer than three vertices (two for an open stroke), and open strokes
all at one point. An open stroke's repeated vertices are spread along its next edge.
"""

from __future__ import annotations

import math
from typing import Callable, Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..balance import coincident_runs, spread
from ..contours import inside, roles
from .bounded_distortion import ShapeKeepingSolve, material_triangles
from .compatible import CompatibleError, CompatibleMesh, compatible_triangulation
from ..geometry import area, best_fit_rotation, centroid, cross, rotate
from .paths import as_times, rigid
from ..memo import Remembered

__all__ = ["carried_points", "injective", "injective_contours", "injective_fallback", "injective_mesh"]

Array = NDArray[np.float64]

_CACHE = 256  # pairs of keys whose mesh is kept (a drawing's elements are evaluated block by block)
_TOUCH = 1e-6  # a vertex two contours share is moved this share of the key's size into one of them
_RIGID = 0.05  # a key is the other turned when, best turned onto it, it is off by this share of its size
_cache: Remembered[tuple[Callable[..., list[Array]], str | None, "_Paths | None"]] = Remembered(_CACHE)
_EVALUATED = 32  # evaluations kept, by keys and t: a report asks for a method's sweep, and auto for the same
_EVALUATED_BYTES = 32 << 20  # and at most this many bytes of them (a render's blocks of frames pass through)
_FRAME_BYTES = 16 << 20  # a pair of keys' solved frames kept by their t, at most this many bytes
_PACE = np.concatenate([[0.0, 1 / 512, 1 / 128, 1 / 32], np.arange(1, 16) / 16, [1 - 1 / 32, 1 - 1 / 128, 1 - 1 / 512, 1.0]])
"""The s at which the solve's path is sampled to pace it (closer at the keys, where it moves fastest)."""
_EVEN = 0.05  # the share of the pacing that is even in s: a stretch where the path stands still takes time too
_evaluated: Remembered[list[Array]] = Remembered(_EVALUATED, lambda v: sum(f.nbytes for f in v), _EVALUATED_BYTES)


def injective_mesh(k0s: Sequence[Array], k1s: Sequence[Array], closed: Sequence[bool]) -> CompatibleMesh | None:
    """The compatible triangulation :func:`injective_contours` uses for these contours, in the keys'
    turned and centred frame (step 1), or None where the contours take the rigid paths instead."""
    paths = _paths_of(k0s, k1s, closed)[2] if len(k0s) else None
    return None if paths is None else paths.mesh


class _Paths:
    """Injective paths of one pair of keys: call with ``t (T,)`` for ``(T, N, 2)``."""

    def __init__(self, k0: Array, k1: Array, cuts: Sequence[int], closed: Sequence[bool]) -> None:
        # work at unit size: coordinates near the float range's ends neither overflow nor underflow
        self.scale = float(max(np.abs(k0).max(initial=0.0), np.abs(k1).max(initial=0.0))) or 1.0
        k0, k1 = k0 / self.scale, k1 / self.scale
        self.c0, self.c1 = centroid(k0), centroid(k1)
        self.phi = _rigid_turn(k0 - self.c0, k1 - self.c1)
        a0, a1 = k0 - self.c0, rotate(k1 - self.c1, -self.phi)
        self.mesh = mesh = compatible_triangulation(a0, a1, cuts, closed)
        self.n = len(k0)
        self.cuts, self.closed = list(cuts), list(closed)
        # a closed contour's area counts for its region, minus where it is a hole (inside an odd number of
        # others, as the mesh keeps in both keys), whichever way it winds
        shut = [c for c, closed_c in enumerate(self.closed) if closed_c and cuts[c + 1] - cuts[c] >= 3]
        kinds = roles([a0[cuts[c]:cuts[c + 1]] for c in shut], [True] * len(shut))
        self.signs = {c: (-1.0 if kind == "hole" else 1.0) for c, kind in zip(shut, kinds)}
        self.areas = (self._area(a0), self._area(a1))
        self.keeping = ShapeKeepingSolve(mesh, material_triangles(mesh, self.cuts, self.closed))
        self._solved: dict[float, Array] = {}  # each t's frame before its turn, by t: the same for any other t
        self._progress: Array | None = None
        self._timing: Callable[[float], Array] | None = None  # s by t, through :meth:`_pace`'s samples

    def _frame(self, s: float) -> Array:
        """The centred, unturned, unsized frame ``(N, 2)`` at ``s`` in [0, 1] (it depends on ``s`` alone, so it
        is kept: a report asks for its measures' t, the sweep and the clip's frames, which share some t)."""
        found = self._solved.get(s)
        if found is None:
            kept = self.keeping(s)[:self.n]
            found = kept - kept.mean(axis=0)  # its vertex mean on the straight path
            if (len(self._solved) + 1) * found.nbytes <= _FRAME_BYTES:
                self._solved[s] = found
        return found

    def _pace(self) -> Array:
        """The share of the segment's time at which the solve's path reaches each of ``_PACE (P,)``: ``(P,)``
        from 0 to 1, each stretch between two samples taking the share of the contours' swept area
        (:meth:`_swept`, each frame sized to its area) it holds, so each frame changes the picture alike
        (``_EVEN`` of it by ``s`` itself)."""
        if self._progress is None:
            frames = [self._sized(self._frame(s), s) for s in _PACE.tolist()]
            steps = np.array([self._swept(a, b) for a, b in zip(frames, frames[1:])])
            total = float(steps.sum())
            even = np.diff(_PACE)
            spans = (1.0 - _EVEN) * steps / total + _EVEN * even if total > 0.0 and np.isfinite(total) else even
            self._progress = np.concatenate([[0.0], np.cumsum(spans)]) / float(spans.sum())
        return self._progress

    def _swept(self, a: Array, b: Array) -> float:
        """The area the contours' edges sweep from ``a (N, 2)`` to ``b (N, 2)``, each edge the parallelogram of
        its mean direction and its ends' mean step: what a viewer sees change (a vertex sliding along its
        contour sweeps none)."""
        total = 0.0
        for c, (start, end) in enumerate(zip(self.cuts, self.cuts[1:])):
            pa, pb = a[start:end], b[start:end]
            if self.closed[c]:
                pa, pb = np.vstack([pa, pa[:1]]), np.vstack([pb, pb[:1]])
            edge = 0.5 * (np.diff(pa, axis=0) + np.diff(pb, axis=0))
            step = 0.5 * ((pb - pa)[1:] + (pb - pa)[:-1])
            total += float(np.abs(cross(edge, step)).sum())
        return total

    def _paced(self, t: float) -> float:
        """The ``s`` at which the solve's path has come the share ``t`` of its way (:meth:`_pace`)."""
        if t <= 0.0 or t >= 1.0:
            return t
        if self._timing is None:  # monotone and once differentiable: the frames' speed changes without a jolt
            from scipy.interpolate import PchipInterpolator

            self._timing = PchipInterpolator(self._pace(), _PACE)
        return float(min(max(float(self._timing(t)), 0.0), 1.0))

    def _area(self, points: Array) -> float:
        """The area the closed contours of ``points (N, 2)`` enclose, holes taken away (each contour's area
        unsigned, counted by whether it is a hole): contours wound either way count alike."""
        return sum(sign * float(area(points[self.cuts[c]:self.cuts[c + 1]])) for c, sign in self.signs.items())

    def _sized(self, x: Array, s: float) -> Array:
        """``x (N, 2)`` scaled about its vertex mean to the keys' interpolated area: a similarity,
        which keeps every contour as simple as it is (the solve alone pulls shapes in mid-way)."""
        goal = (1.0 - s) * self.areas[0] + s * self.areas[1]
        now = self._area(x)
        if goal == 0.0 or now == 0.0 or (goal > 0) != (now > 0):
            return x
        middle = x.mean(axis=0)
        return middle + math.sqrt(goal / now) * (x - middle)

    def __call__(self, t: Array, paced: bool = True) -> Array:
        out = np.empty((len(t), self.n, 2))
        for f, s in enumerate(np.clip(t, 0.0, 1.0).tolist()):
            at = self._paced(s) if paced else s
            out[f] = self._sized(self._frame(at), at)
        center = (1.0 - t)[:, None] * self.c0 + t[:, None] * self.c1
        return self.scale * (center[:, None, :] + rotate(out, (t * self.phi)[:, None]))


def _rigid_turn(a: Array, b: Array) -> float:
    """The angle that turns ``a`` onto ``b`` (both ``(N, 2)``, centred) where ``b`` is ``a`` turned, to
    within ``_RIGID`` of its size; else 0: between shapes that differ, a best-fit turn is arbitrary
    and would swing the in-betweens round (each triangle's own turn is kept by the solve)."""
    phi = float(best_fit_rotation(a, b))
    size = float(np.sqrt(np.mean(np.sum(a * a, axis=1)) + np.mean(np.sum(b * b, axis=1)))) or 1.0
    residual = float(np.sqrt(np.mean(np.sum((rotate(a, phi) - b) ** 2, axis=1))))
    return phi if residual <= _RIGID * size else 0.0


def _build(k0: Array, k1: Array, cuts: Sequence[int], closed: Sequence[bool]
           ) -> tuple[Callable[..., list[Array]], str | None, _Paths | None]:
    """The paths of every contour, those that cannot be in the mesh on the rigid paths of all; why
    the rigid paths were taken for all (None where the mesh holds every contour it can); and the mesh's
    paths (None where there is no mesh)."""
    meshed = [_meshable(k0[a:b], k1[a:b], c) for a, b, c in zip(cuts, cuts[1:], closed)]

    def all_rigid(t: Array, paced: bool = True) -> list[Array]:  # the rigid paths of every contour
        return _split(rigid(k0, k1, t), cuts)

    if not (np.all(np.isfinite(k0)) and np.all(np.isfinite(k1))):
        return all_rigid, "the keys are not finite", None
    if not any(meshed):
        return all_rigid, "no contour has three vertices (an open one two)", None
    picked = [c for c in range(len(meshed)) if meshed[c]]
    m0, m1, mcuts = _meshed_keys(k0, k1, cuts, closed, picked)
    try:
        paths = _Paths(m0, m1, mcuts, [closed[c] for c in picked])
    except CompatibleError as error:
        return all_rigid, str(error), None
    every = list(range(len(meshed)))

    def evaluate(t: Array, paced: bool = True) -> list[Array]:
        found = dict(zip(picked, _split(paths(t, paced), mcuts)))
        if len(found) == len(every):
            return [found[c] for c in every]
        rigidly = all_rigid(t)
        return [found.get(c, rigidly[c]) for c in every]

    return evaluate, None, paths


def _meshed_keys(k0: Array, k1: Array, cuts: Sequence[int], closed: Sequence[bool], picked: Sequence[int]
                 ) -> tuple[Array, Array, list[int]]:
    """The keys of the ``picked`` contours, copies spread, concatenated: ``(M, 2)`` twice and their cuts."""
    parts0, parts1 = [], []
    for c in picked:
        a, b = k0[cuts[c]:cuts[c + 1]], k1[cuts[c]:cuts[c + 1]]
        if closed[c] and (coincident_runs(a) or coincident_runs(b)):
            a, b = spread(a, b)
        elif not closed[c]:
            a, b = _spread_open(a), _spread_open(b)
        parts0.append(a)
        parts1.append(b)
    mcuts = np.concatenate([[0], np.cumsum([len(p) for p in parts0])]).astype(int).tolist()
    shut = [closed[c] for c in picked]
    return _apart(np.concatenate(parts0), mcuts, shut), _apart(np.concatenate(parts1), mcuts, shut), mcuts


def _apart(points: Array, cuts: Sequence[int], closed: Sequence[bool]) -> Array:
    """``points (M, 2)`` with each vertex that two closed contours share (they touch there, as drawn) moved
    :data:`_TOUCH` of the key's size into the smaller contour's own region: the contours are apart, so
    they can be meshed, and the key as drawn changes by less than a millionth (the keys themselves are
    drawn at t = 0 and 1)."""
    unique, where, count = np.unique(points, axis=0, return_inverse=True, return_counts=True)
    if len(unique) == len(points):
        return points
    out = np.array(points)
    owner = np.searchsorted(np.asarray(cuts), np.arange(len(points)), side="right") - 1
    size = float(np.ptp(points, axis=0).max()) or 1.0
    for group in np.flatnonzero(count > 1):
        shared = np.flatnonzero(where.ravel() == group)
        contours = {int(owner[i]) for i in shared}
        if len(contours) < 2 or not all(closed[c] for c in contours):
            continue  # copies within one contour, or an open stroke: not two outlines touching
        for i in sorted(shared, key=lambda i: _region(points, cuts, int(owner[i])))[:-1]:  # all but the largest
            out[i] = _inward(points, cuts, int(owner[i]), int(i), _TOUCH * size)
    return out


def _region(points: Array, cuts: Sequence[int], c: int) -> float:
    return float(area(points[cuts[c]:cuts[c + 1]]))


def _inward(points: Array, cuts: Sequence[int], c: int, i: int, step: float) -> Array:
    """Vertex ``i`` of contour ``c`` moved ``step`` along its corner's bisector, into the contour's region."""
    ring = points[cuts[c]:cuts[c + 1]]
    k = i - cuts[c]
    here, before, after = ring[k], ring[k - 1], ring[(k + 1) % len(ring)]
    u, v = before - here, after - here
    u, v = u / (np.hypot(*u) or 1.0), v / (np.hypot(*v) or 1.0)
    bisector = u + v if np.hypot(*(u + v)) > 1e-12 else np.array([-u[1], u[0]])
    bisector = bisector / np.hypot(*bisector)
    ahead = here + step * bisector
    return ahead if inside(ahead[None], ring)[0] else here - step * bisector


def _meshable(a: Array, b: Array, closed: bool) -> bool:
    """Whether a contour ``(L, 2)`` in both keys can be in the mesh: three vertices (two for an open
    stroke), and an open stroke not all at one point in either key."""
    if len(a) < (3 if closed else 2):
        return False
    return closed or (bool(np.any(a != a[0])) and bool(np.any(b != b[0])))


def _spread_open(points: Array) -> Array:
    """An open stroke ``(L, 2)`` with each run of equal vertices spread along the next edge (the
    previous one for a run at the end), within its first half: the stroke as drawn is unchanged."""
    out = np.array(points, dtype=np.float64)
    n, i = len(out), 0
    while i < n:
        j = i
        while j + 1 < n and np.array_equal(out[j + 1], out[i]):
            j += 1
        k = j - i + 1
        if k >= 2:
            if j + 1 < n:  # toward the next vertex; the run's first copy stays
                step = (out[j + 1] - out[i]) / (2 * k)
                for m in range(1, k):
                    out[i + m] = out[i] + m * step
            elif i > 0:  # a run at the end: toward the previous vertex; the last copy stays
                step = (out[i - 1] - out[i]) / (2 * k)
                for m in range(k - 1):
                    out[i + m] = out[j] + (k - 1 - m) * step
        i = j + 1
    return out


def _split(frames: Array, cuts: Sequence[int]) -> list[Array]:
    return [frames[:, a:b] for a, b in zip(cuts, cuts[1:])]


def injective_contours(k0s: Sequence[Array], k1s: Sequence[Array], closed: Sequence[bool], t: ArrayLike,
                       paced: bool = True) -> list[Array]:
    """Injective inbetweens of a shape's corresponding contours (``k0s[i]``, ``k1s[i]`` both
    ``(L_i, 2)``; ``closed[i]``), all in one mesh, at ``t (T,)``: one ``(T, L_i, 2)`` per contour. Without
    ``paced``, the path's own states at ``s = t`` (step 6 left out): what ``auto`` measures a path by, so that
    its choice depends on the path and not on how it is timed.

    The mesh of a set of keys is cached, so successive blocks of frames of one segment pay it once; the
    inbetweens at a set of ``t`` are remembered too (``auto`` choosing injective paths, and a report's
    measures, ask for the same ones again).
    """
    paths, _, _ = _paths_of(k0s, k1s, closed)
    t = as_times(t)
    key = _key(k0s, k1s, closed) + b"|" + np.ascontiguousarray(t, dtype=np.float64).tobytes() + bytes([paced])

    def evaluated() -> list[Array]:
        found = paths(t, paced)
        for frames, a, b in zip(found, k0s, k1s):
            frames[t == 0.0] = a
            frames[t == 1.0] = b
        return found

    return [frames.copy() for frames in _evaluated.get(key, evaluated)]  # the caller's own: they may be written


def carried_points(k0s: Sequence[Array], k1s: Sequence[Array], closed: Sequence[bool], points: ArrayLike,
                   side: int, build: bool = True) -> Array | None:
    """Where ``points (P, 2)`` of key ``side`` (0 or 1) are in the other key by the compatible mesh of these
    contours (:func:`injective_contours`): each point keeps its barycentric place in its triangle, so it
    keeps its place among the contours (inside the same ones). ``(P, 2)``; None where the contours have no
    such mesh (or, without ``build``, where it has not been built); a point outside the frame keeps its
    place."""
    if not k0s:
        return None
    found = _paths_of(k0s, k1s, closed) if build else _cache.known(_key(k0s, k1s, closed))
    paths = None if found is None else found[2]  # the mesh the paths use, built once
    if paths is None:
        return None
    mesh = paths.mesh
    here, there = (mesh.p0, mesh.p1) if side == 0 else (mesh.p1, mesh.p0)
    q = np.asarray(points, dtype=np.float64).reshape(-1, 2) / paths.scale
    q = q - paths.c0 if side == 0 else rotate(q - paths.c1, -paths.phi)
    a, b, c = (here[mesh.triangles[:, k]] for k in range(3))
    det = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])  # (F,)
    rel = q[:, None, :] - a[None]  # (P, F, 2)
    u = (rel[..., 0] * (c[:, 1] - a[:, 1]) - rel[..., 1] * (c[:, 0] - a[:, 0])) / det
    v = ((b[:, 0] - a[:, 0]) * rel[..., 1] - (b[:, 1] - a[:, 1]) * rel[..., 0]) / det
    w = 1.0 - u - v
    worst = np.minimum(np.minimum(u, v), w)  # (P, F): ≥ 0 inside
    tri = np.argmax(worst, axis=1)
    rows = np.arange(len(q))
    a2, b2, c2 = (there[mesh.triangles[tri, k]] for k in range(3))
    out = w[rows, tri, None] * a2 + u[rows, tri, None] * b2 + v[rows, tri, None] * c2
    out = np.where((worst[rows, tri] >= -1e-9)[:, None], out, q)
    out = rotate(out, paths.phi) + paths.c1 if side == 0 else out + paths.c0  # back to the other key's frame
    return out * paths.scale


def injective_fallback(k0s: Sequence[Array], k1s: Sequence[Array], closed: Sequence[bool]) -> str | None:
    """Why contours ``k0s``, ``k1s`` (as :func:`injective_contours` takes them) have no injective paths and
    take the rigid ones instead — keys whose contours cross, nest differently, wind apart — or None."""
    return _paths_of(k0s, k1s, closed)[1]


def _key(k0s: Sequence[Array], k1s: Sequence[Array], closed: Sequence[bool]) -> bytes:
    """What a shape's injective paths depend on: its contours' keys and which are closed."""
    k0 = np.concatenate([np.asarray(k, dtype=np.float64).reshape(-1, 2) for k in k0s])
    k1 = np.concatenate([np.asarray(k, dtype=np.float64).reshape(-1, 2) for k in k1s])
    cuts = np.concatenate([[0], np.cumsum([len(k) for k in k0s])]).astype(int).tolist()
    return k0.tobytes() + b"|" + k1.tobytes() + b"|" + repr((cuts, list(closed))).encode()


def _paths_of(k0s: Sequence[Array], k1s: Sequence[Array], closed: Sequence[bool]
              ) -> tuple[Callable[..., list[Array]], str | None, _Paths | None]:
    k0 = np.concatenate([np.asarray(k, dtype=np.float64).reshape(-1, 2) for k in k0s])
    k1 = np.concatenate([np.asarray(k, dtype=np.float64).reshape(-1, 2) for k in k1s])
    cuts = np.concatenate([[0], np.cumsum([len(k) for k in k0s])]).astype(int).tolist()
    key = _key(k0s, k1s, closed)
    return _cache.get(key, lambda: _build(k0, k1, cuts, [bool(c) for c in closed]))


def injective(k0: Array, k1: Array, t: ArrayLike, joints: Sequence[tuple[int, int]] = ()) -> Array:
    """Injective inbetweens of one closed outline ``(N, 2)`` at ``t (T,)``: ``(T, N, 2)``."""
    return injective_contours([k0], [k1], [True], t)[0]
