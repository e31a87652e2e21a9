"""Cubic Bézier contours fitted to exact polylines at every frame, with one vertex count (maths §5.12).

A contour's exact in-between is a polyline ``(F, L, 2)`` (F frames, L vertices, the same vertex
identity at every frame). :func:`fit_curves` picks *break* vertices once for all frames (the corners,
then more where needed) and fits each span between two breaks with one cubic whose ends are the
breaks' exact points and whose inner control points are least squares over the span's vertices,
at parameters fixed across frames (mean chord length). The fit is then one linear map of the samples,
so control points move as smoothly as the vertices do and keyframe well. From each break, one cubic
reaches as far as it can (:func:`_longest_span`) while, at every frame, each vertex of the polyline
lies within the tolerance of the drawn cubic and each point of the cubic (densely sampled) within it
of the polyline; the next cubic starts where it ends.

A curve is held as ``(F, M, 3, 2)``: per break vertex its in control point, the vertex, its out control
point, absolute pixels (an open contour's first in and last out are the vertex itself, as are both
control points of a span that is one edge of the polyline: it is straight at every frame). A player
interpolating vertices and tangents straight between keyframes draws the Bézier of the interpolated
control points; as a Bézier point is a convex combination of its control points, control points within
``e`` of the fitted ones draw points within ``e`` of the fitted curve.

A contour keyframed only at its two keys (it moves straight between them) is fitted as a :class:`Blend`: the
cubics at the two keys alone, every frame's cubic their blend by the motion's progress, exactly what a player
draws, measured against every frame. Each key's inner points are then refitted to where the cubic passes
nearest to that key's polyline (:func:`_slid_keys`), rather than to the key's vertices at the shared
parameters: a key's vertices need not lie where a cubic's parameter puts them (a vertex of one key matched to
copies of the other's), and the measure of every frame says whether the in-betweens allow the slide.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = ["Blend", "RIDGE", "STRAIGHT_RIDGE", "distance_to_polyline", "fit_curves", "free_points", "with_fixed_points", "curve_points", "curve_error", "CORNER_DEGREES"]

Array = NDArray[np.float64]

CORNER_DEGREES = 50.0
"""A vertex where the polyline turns by more than this at some frame is a break (a corner)."""

RIDGE = 0.05
"""The ridge on a span's inner offsets, as a share of their normal matrix's mean diagonal: it keeps control
points steady from frame to frame, so that keyframes fitted to them reach far."""

STRAIGHT_RIDGE = 1e-4
"""A ridge for a contour that moves straight between two keys: its keyframes are those two, so the fit may
follow each span as closely as it can (where that takes fewer cubics)."""

_MEASURED_SHARE = 0.97
"""The share of the tolerance a span's measured error may reach: the measure draws the cubic through points,
and a long span's cubic may stray a little farther between them."""
_NEWTON_ROUNDS = 10
"""Newton steps on a span's parameters when the fit at mean chord length misses."""
_SLIDES = 4
"""Refits of a blend's key cubics to the nearest points of their polylines (:func:`_slid_keys`)."""
_DENSE = 24  # points of the cubic measured per span, besides those at the vertices' parameters


@dataclass(frozen=True)
class Blend:
    """Curves blended between two frames, as a player draws a path keyframed at them: frame ``f``'s control points
    are ``(1 - s_f)·A + s_f·B``, A and B the cubics at frames ``first`` and ``last``, ``s = progress (F,)`` (0 at
    ``first``, 1 at ``last``). :func:`fit_curves` then fits A and B alone and measures every frame's blend."""

    first: int
    last: int
    progress: Array

    def of(self, keys: Array) -> Array:
        """Every frame's control points ``(F, 4, 2)`` from the two frames' ``keys (2, 4, 2)``."""
        return keys[0] + self.progress[:, None, None] * (keys[1] - keys[0])


def _bernstein(u: Array) -> Array:
    """The cubic Bernstein basis at ``u (n,)``: ``(n, 4)``."""
    v = 1.0 - u
    return np.stack([v ** 3, 3 * v * v * u, 3 * v * u * u, u ** 3], axis=-1)


def _parameters(samples: Array, i0: int, i1: int) -> Array:
    """Parameters in [0, 1] of vertices ``i0..i1`` of ``samples (F, L', 2)``: mean chord length over frames
    (even where the span has no length at any frame): ``(i1 - i0 + 1,)``."""
    steps = np.linalg.norm(np.diff(samples[:, i0:i1 + 1], axis=1), axis=-1).mean(axis=0)  # (n + 1,)
    total = float(steps.sum())
    if not np.isfinite(total) or total <= 1e-12:
        return np.linspace(0.0, 1.0, i1 - i0 + 1)
    return np.concatenate([[0.0], np.cumsum(steps) / total])


def _fit_span(samples: Array, i0: int, i1: int, ridge: float = 0.0) -> tuple[Array, Array]:
    """The cubic over vertices ``i0..i1`` of ``samples (F, L', 2)`` at every frame: control points
    ``(F, 4, 2)`` and the vertices' parameters ``(i1 - i0 + 1,)``, one set for all frames (mean chord
    length), so the fit is one linear map of the samples. (Moving the parameters towards each vertex's
    nearest point, Newton's way, was measured to save nothing on icon pairs.)"""
    u = _parameters(samples, i0, i1)
    return _solve(samples, i0, i1, u, ridge), u


def _blend_fit(ring: Array, i0: int, i1: int, ridge: float, blend: Blend) -> tuple[Array, Array, Array]:
    """The cubics over vertices ``i0..i1`` of ``ring (F, L', 2)`` at ``blend``'s two frames, at one set of parameters
    (mean chord length over every frame) and then slid along their polylines (:func:`_slid_keys`), and every
    frame's cubic blended between them: control points ``(F, 4, 2)``, the two frames' ``(2, 4, 2)`` and the
    parameters ``(i1 - i0 + 1,)``."""
    ends = ring[[blend.first, blend.last]]
    u = _parameters(ring, i0, i1)
    keys = _slid_keys(ends, i0, i1, u, ridge)
    return blend.of(keys), keys, u


def _slid_keys(ends: Array, i0: int, i1: int, u: Array, ridge: float) -> Array:
    """The two key cubics ``(2, 4, 2)`` over vertices ``i0..i1`` of ``ends (2, L', 2)`` fitted at the parameters ``u``,
    then refitted, :data:`_SLIDES` times, to the points of the key polylines nearest to where the cubics pass at
    ``u``: each key's vertices may slide along its own polyline, so the two keys need not reach their matched
    vertices at one parameter. Every fit is at ``u``: one least-squares map (:func:`_solver`) serves them all."""
    solver = _solver(u, ridge)
    keys = _solve(ends, i0, i1, u, ridge, solver)
    if i1 - i0 < 2:
        return keys
    span = ends[:, i0:i1 + 1]
    for _ in range(_SLIDES):
        passing = curve_points(keys, u[1:-1])  # (2, n, 2)
        targets = ends.copy()
        targets[:, i0 + 1:i1] = _nearest_on_polyline(passing, span)
        keys = _solve(targets, i0, i1, u, ridge, solver)
    return keys


def _nearest_on_polyline(points: Array, polyline: Array) -> Array:
    """The point of the polyline ``polyline (F, Q, 2)`` (Q ≥ 2) nearest to each of ``points (F, P, 2)``: ``(F, P, 2)``."""
    a, b = polyline[:, :-1], polyline[:, 1:]  # (F, S, 2)
    ab = b - a
    length = np.maximum(np.sum(ab * ab, axis=-1), 1e-300)
    s = np.clip(np.einsum("fpsd,fsd->fps", points[:, :, None] - a[:, None], ab) / length[:, None], 0.0, 1.0)
    foot = a[:, None] + s[..., None] * ab[:, None]  # (F, P, S, 2)
    which = np.argmin(np.sum((points[:, :, None] - foot) ** 2, axis=-1), axis=-1)  # (F, P)
    return np.take_along_axis(foot, which[..., None, None], axis=2)[:, :, 0]


def _solver(u: Array, ridge: float) -> Array | None:
    """The least-squares map from the offsets of a span's inner vertices, at parameters ``u (n + 2,)``, to those of its
    two inner control points: ``(2, n)``, a ``ridge`` (a share of the normal matrix's mean diagonal) keeping them
    steady where the parameters crowd; ``None`` where there are no inner vertices."""
    inner = u[1:-1]
    if inner.size == 0:
        return None
    basis = _bernstein(inner)[:, 1:3]  # (n, 2)
    normal = basis.T @ basis
    # least norm where the parameters give no hold (every inner vertex on an end: no offset moves the cubic)
    return np.linalg.pinv(normal + ridge * np.trace(normal) / 2 * np.eye(2)) @ basis.T


def _solve(samples: Array, i0: int, i1: int, u: Array, ridge: float = 0.0, solver: Array | None = None) -> Array:
    """Control points ``(F, 4, 2)`` of the cubic from vertex ``i0`` to ``i1`` of ``samples (F, L', 2)`` through
    the vertices at parameters ``u``: the straight line's thirds plus inner offsets solved by least squares
    (:func:`_solver`, or ``solver``, its map at these ``u`` and ``ridge``)."""
    p0, p3 = samples[:, i0], samples[:, i1]  # (F, 2)
    thirds = np.stack([p0, (2 * p0 + p3) / 3, (p0 + 2 * p3) / 3, p3], axis=1)  # (F, 4, 2): the straight line
    inner = u[1:-1]
    if inner.size == 0:
        return thirds
    solve = _solver(u, ridge) if solver is None else solver  # (2, n)
    residual = samples[:, i0 + 1:i1] - (p0[:, None] + inner[None, :, None] * (p3 - p0)[:, None])  # (F, n, 2)
    controls = thirds.copy()
    controls[:, 1:3] += np.einsum("kn,fnd->fkd", solve, residual)
    return controls


def curve_points(controls: Array, u: Array) -> Array:
    """Points of cubics ``controls (..., 4, 2)`` at parameters ``u (n,)``: ``(..., n, 2)``."""
    return _weighted(_bernstein(u), controls)


def _weighted(weights: Array, points: Array) -> Array:
    """``Σ_k weights[n, k] · points[..., k, d]`` for ``weights (n, K)`` and ``points (..., K, D)``: ``(..., n, D)``
    (a compiled loop, :mod:`._curve_kernels`)."""
    from ._curve_kernels import weighted_sums

    lead = points.shape[:-2]
    flat = np.ascontiguousarray(points, dtype=np.float64).reshape(-1, *points.shape[-2:])
    found = weighted_sums(np.ascontiguousarray(weights, dtype=np.float64), flat)
    return found.reshape(*lead, *found.shape[1:])


def distance_to_polyline(points: Array, polyline: Array) -> Array:
    """Distance from each of ``points (F, P, 2)`` to the polyline ``polyline (F, Q, 2)`` (its Q - 1
    segments; one point if Q is 1) at the same frame: ``(F, P)`` (a compiled loop over the segments,
    :mod:`._curve_kernels`)."""
    if polyline.shape[1] == 1:
        return np.linalg.norm(points - polyline, axis=-1)
    from ._curve_kernels import polyline_distances

    return polyline_distances(np.ascontiguousarray(points, dtype=np.float64),
                              np.ascontiguousarray(polyline, dtype=np.float64))


def curve_error(controls: Array, u: Array, polyline: Array) -> tuple[Array, Array]:
    """How far cubics ``controls (F, 4, 2)`` are from ``polyline (F, n, 2)`` (the span's exact vertices,
    at parameters ``u (n,)``), both ways: per frame the larger of the vertices' distance to the cubic
    (drawn through ``_DENSE`` points, the vertices' parameters and the midpoints between them) and the cubic's points' distance to
    the polyline, ``(F,)``; and each vertex's largest distance over frames, ``(n,)``."""
    dense = np.union1d(np.union1d(np.linspace(0.0, 1.0, max(_DENSE, 2 * len(u))), u), (u[1:] + u[:-1]) / 2)
    drawn = curve_points(controls, dense)  # (F, D, 2)
    vertices = distance_to_polyline(polyline, drawn)  # (F, n)
    points = distance_to_polyline(drawn, polyline)  # (F, D)
    return np.maximum(vertices.max(axis=1), points.max(axis=1)), vertices.max(axis=0)


def _spans(ring: Array, breaks: list[int], tolerance: float, ridge: float,
           blend: Blend | None = None) -> tuple[dict[tuple[int, int], Array], float]:
    """The cubics from each of ``breaks`` (increasing vertex indices of ``ring (F, L', 2)``) to the next, each as
    long as it can be (:func:`_longest_span`): control points ``(F, 4, 2)`` by ``(first, last)`` vertex, and the
    largest error measured."""
    spans: dict[tuple[int, int], Array] = {}
    worst = 0.0
    for i0, i1 in zip(breaks, breaks[1:]):
        while i0 < i1:
            end, controls, error = _longest_span(ring, i0, i1, tolerance, ridge, blend)
            spans[(i0, end)] = controls
            worst = max(worst, error)
            i0 = end
    return spans, worst


def _span_fit(ring: Array, i0: int, i1: int, tolerance: float, ridge: float,
              blend: Blend | None = None) -> tuple[Array, float] | None:
    """The cubic over vertices ``i0..i1`` of ``ring (F, L', 2)`` and its error, or ``None`` if it misses by
    more than ``tolerance`` at some frame; an edge always fits (error 0; with a ``blend``, how far its blended
    ends stray from the frames' vertices). Fitted at mean chord length (:func:`_fit_span`), then, if that
    misses, at parameters moved :data:`_NEWTON_ROUNDS` times by Newton's step on the squared distances summed
    over frames (one set of parameters for all frames, so the fit stays one linear map of the samples). With a
    ``blend``, the cubics are fitted at its two frames and every frame's is their blend (:func:`_blend_fit`),
    measured against every frame."""
    if blend is not None:
        controls, keys, u = _blend_fit(ring, i0, i1, ridge, blend)
    else:
        controls, u = _fit_span(ring, i0, i1, ridge)
    if i1 - i0 < 2:
        if blend is None:
            return controls, 0.0
        return controls, float(np.linalg.norm(controls[:, [0, 3]] - ring[:, [i0, i1]], axis=-1).max())
    tolerance *= _MEASURED_SHARE
    error = float(curve_error(controls, u, ring[:, i0:i1 + 1])[0].max())
    if error > tolerance:
        ends = ring[[blend.first, blend.last]] if blend is not None else ring
        moved = controls
        for _ in range(_NEWTON_ROUNDS):
            if blend is not None:
                u = _newton_step(ends[:, i0:i1 + 1], keys, u)
                keys = _slid_keys(ends, i0, i1, u, ridge)
            else:
                u = _newton_step(ring[:, i0:i1 + 1], moved, u)
                moved = _solve(ring, i0, i1, u, ridge)
        if blend is not None:
            moved = blend.of(keys)
        moved_error = float(curve_error(moved, u, ring[:, i0:i1 + 1])[0].max())
        if moved_error < error:
            controls, error = moved, moved_error
    return (controls, error) if error <= tolerance else None


def _newton_step(points: Array, controls: Array, u: Array) -> Array:
    """Parameters ``u (n,)`` of ``points (F, n, 2)`` on the cubics ``controls (F, 4, 2)`` moved by one Newton step
    on ``sum_f |B_f(u_j) - p_fj|²`` (ends kept at 0 and 1, order kept)."""
    inner = u[1:-1]
    if inner.size == 0:
        return u
    v = 1.0 - inner
    first = 3 * _weighted(np.stack([v * v, 2 * v * inner, inner * inner], axis=-1), np.diff(controls, axis=1))
    second = 6 * _weighted(np.stack([v, inner], axis=-1), np.diff(controls, n=2, axis=1))
    miss = curve_points(controls, inner) - points[:, 1:-1]
    slope = np.sum(miss * first, axis=(0, 2))
    curvature = np.sum(first * first + miss * second, axis=(0, 2))
    step = np.where(curvature > 1e-12, slope / np.where(curvature > 1e-12, curvature, 1.0), 0.0)
    moved = np.maximum.accumulate(np.clip(inner - step, 0.0, 1.0))
    return np.concatenate([[0.0], moved, [1.0]])


def _longest_span(ring: Array, i0: int, stop: int, tolerance: float, ridge: float,
                  blend: Blend | None = None) -> tuple[int, Array, float]:
    """The farthest vertex ``end`` (at most ``stop``) that one cubic from vertex ``i0`` reaches within
    ``tolerance`` at every frame, found by doubling steps and then halving the gap between the last end
    that fits and the first that fails (a span's fit nearly always worsens as it grows): ``end``, the
    span's control points ``(F, 4, 2)`` and its error. Taking the longest span from each break in turn
    needs far fewer cubics than splitting spans at their worst vertex."""
    end = i0 + 1
    best = _span_fit(ring, i0, end, tolerance, ridge, blend)
    assert best is not None
    failed, step = stop + 1, 1
    while end < stop:
        candidate = min(end + step, stop)
        found = _span_fit(ring, i0, candidate, tolerance, ridge, blend)
        if found is None:
            failed = candidate
            break
        end, best, step = candidate, found, 2 * step
    while failed - end > 1 and end < stop:
        middle = (end + failed) // 2
        found = _span_fit(ring, i0, middle, tolerance, ridge, blend)
        if found is None:
            failed = middle
        else:
            end, best = middle, found
    return end, best[0], best[1]


def _corners(samples: Array, closed: bool) -> set[int]:
    """Vertices of ``samples (F, L, 2)`` where the polyline turns by more than :data:`CORNER_DEGREES` at
    some frame (every vertex but the ends of an open one)."""
    count = samples.shape[1]
    if count < 3:
        return set()
    before = samples - np.roll(samples, 1, axis=1)
    after = np.roll(samples, -1, axis=1) - samples
    size = np.linalg.norm(before, axis=-1) * np.linalg.norm(after, axis=-1)
    with np.errstate(invalid="ignore", divide="ignore"):
        cosine = np.where(size > 0, np.sum(before * after, axis=-1) / np.where(size > 0, size, 1.0), 1.0)
    turned = np.any(cosine < np.cos(np.radians(CORNER_DEGREES)), axis=0)  # (L,)
    if not closed:
        turned[[0, -1]] = False
    return {int(i) for i in np.flatnonzero(turned)}


def fit_curves(samples: Array, closed: bool, tolerance: float, ridge: float = RIDGE,
               blend: Blend | None = None) -> tuple[NDArray[np.intp], Array, float]:
    """Cubic Bézier contours for the polylines ``samples (F, L, 2)`` within ``tolerance`` pixels of them
    at every frame (both ways): the break vertices ``(M,)`` (indices into L, increasing), the curves
    ``(F, M, 3, 2)`` (in control point, vertex, out control point) and the largest distance measured (0
    where every span is one edge). Samples must be finite."""
    count = samples.shape[1]
    if count < 2:
        vertices = samples[:, :, None].repeat(3, axis=2)
        return np.arange(count), vertices, 0.0
    ring = np.concatenate([samples, samples[:, :1]], axis=1) if closed else samples  # (F, L', 2)
    last = ring.shape[1] - 1
    breaks = sorted(_corners(samples, closed) | {0, last})
    spans, worst = _spans(ring, breaks, tolerance, ridge, blend)
    if closed and len(spans) < 3 and last >= 3:  # a closed contour takes at least three spans
        spans, worst = _spans(ring, sorted(set(breaks) | {last // 3, (2 * last) // 3}), tolerance, ridge, blend)
    order = sorted(spans)
    frames = samples.shape[0]
    heads = np.array([i0 for i0, _ in order], dtype=np.intp)
    curves = np.empty((frames, len(order), 3, 2))
    for k, key in enumerate(order):
        controls = spans[key]
        if key[1] - key[0] == 1:  # an edge: straight at every frame, its control points on its ends
            controls = controls[:, [0, 0, 3, 3]]
        curves[:, k, 1] = controls[:, 0]
        curves[:, k, 2] = controls[:, 1]
        curves[:, (k + 1) % len(order), 0] = controls[:, 2]
    if not closed:  # the last vertex ends the last span: no span leaves it
        end = spans[order[-1]]
        tail = np.stack([end[:, 2], end[:, 3], end[:, 3]], axis=1)[:, None]  # (F, 1, 3, 2)
        curves[:, 0, 0] = curves[:, 0, 1]
        curves = np.concatenate([curves, tail], axis=1)
        heads = np.append(heads, last)
    return heads, curves, worst


def free_points(curves: Array) -> NDArray[np.bool_]:
    """Which points of ``curves (F, M, 3, 2)`` are their own (``(M, 3)``): every vertex, and each control
    point that differs from its vertex at some frame (the others are the vertex, at every frame)."""
    free = np.any(curves != curves[:, :, 1:2], axis=(0, 3))
    free[:, 1] = True
    return free


def with_fixed_points(points: Array, free: NDArray[np.bool_]) -> Array:
    """Curves ``(K, M, 3, 2)`` from the values ``(K, count of free, 2)`` of their ``free (M, 3)`` points, the
    others on their vertex."""
    curves = np.zeros((len(points), *free.shape, 2))
    curves[:, free] = points
    vertices = curves[:, :, 1:2].repeat(3, axis=2)
    return np.where(free[None, :, :, None], curves, vertices)
