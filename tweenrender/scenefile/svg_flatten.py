"""Flattening SVG geometry: subpaths of lines, Béziers and arcs → polygons within a tolerance.

Curves are split until no point of the curve lies farther than the tolerance
(world units) from the polygon; straight segments stay single edges. Every
vertex counts against a budget, so a huge path is refused while it is read.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray
from svgelements import Arc, Close, CubicBezier, Line, Move, QuadraticBezier

__all__ = ["Refusal", "Budget", "MAX_DEPTH", "subpaths", "flatten", "distinct", "zero_length_segment"]

MAX_DEPTH = 48  # Bézier halvings; the flatness bound shrinks 4x per halving
MAX_COORDINATE = 1e9
"""World coordinates of control points and vertices, as in scene files: far beyond any drawing, and
small enough that the flattening's products stay finite."""


class Refusal(Exception):
    """Raised while reading a drawing; the caller names the file (and element)."""


class Budget:
    """Vertices left to a drawing; :meth:`spend` refuses once they run out."""

    def __init__(self, limit: int, tolerance: float) -> None:
        self.limit, self.left, self.tolerance = limit, limit, tolerance
        self.memo: dict[object, object] = {}  # what one reading of the drawing works out once (masks)

    def spend(self, count: int) -> None:
        self.left -= count
        if self.left < 0:
            raise Refusal(f"expected at most {self.limit} vertices, found more at tolerance {self.tolerance:g}")


def subpaths(segments: list[object], dots: bool = False) -> list[tuple[list[object], bool]]:
    """The subpaths that draw something, each with whether it is closed (ends in Z); with ``dots``, those of
    zero length too (``M x y L x y``, ``M x y Z``: where round and square caps draw a dot)."""
    out: list[tuple[list[object], bool]] = []
    current: list[object] | None = None
    for segment in segments:
        if isinstance(segment, Move):
            current = None
            continue
        if current is None:
            current = []
            out.append((current, False))
        current.append(segment)
        if isinstance(segment, Close):
            out[-1] = (current, True)
            current = None  # a command after Z starts a new subpath at the same point
    return [(s, closed) for s, closed in out if dots or any(_draws(segment) for segment in s)]


def _draws(segment: object) -> bool:
    points = [segment.start, segment.end]  # type: ignore[attr-defined]
    if isinstance(segment, QuadraticBezier):
        points.append(segment.control)
    elif isinstance(segment, CubicBezier):
        points += [segment.control1, segment.control2]
    return any(p != points[0] for p in points[1:])


def flatten(segments: list[object], to_world: NDArray[np.float64], tol: float, budget: Budget) -> NDArray[np.float64]:
    """World vertices of a subpath, its start first; curves within ``tol`` of their chords."""
    if not segments:
        return np.empty((0, 2))
    linear, offset = to_world[:2, :2], to_world[:2, 2]

    def world(*points: object) -> NDArray[np.float64]:
        local = np.array([(p.x, p.y) for p in points], dtype=np.float64)  # type: ignore[attr-defined]
        with np.errstate(invalid="ignore", over="ignore"):  # refused just below
            placed = local @ linear.T + offset
        if not np.all(np.isfinite(placed)):
            raise Refusal("expected finite coordinates, found infinite or NaN ones after transforms")
        largest = float(np.abs(placed).max(initial=0.0))
        if largest > MAX_COORDINATE:
            raise Refusal(f"expected coordinates within ±{MAX_COORDINATE:g} after transforms, found {largest:.3g}")
        return placed

    out: list[NDArray[np.float64]] = [world(segments[0].start)]  # type: ignore[attr-defined]
    budget.spend(1)
    for segment in segments:
        if isinstance(segment, CubicBezier):
            piece = _flatten_bezier(world(segment.start, segment.control1, segment.control2, segment.end), tol, budget)
        elif isinstance(segment, QuadraticBezier):
            piece = _flatten_bezier(world(segment.start, segment.control, segment.end), tol, budget)
        elif isinstance(segment, Arc):
            piece = _flatten_arc(segment, linear, offset, tol, world(segment.end), budget)
        elif isinstance(segment, (Line, Close)):
            piece = world(segment.end)
        else:
            raise Refusal(f"expected lines, Béziers and arcs, found a {type(segment).__name__} segment")
        budget.spend(len(piece))
        out.append(piece)
    return np.concatenate(out)


def _flatten_bezier(nodes: NDArray[np.float64], tol: float, budget: Budget) -> NDArray[np.float64]:
    """Vertices after the first of a Bézier ``(degree + 1, 2)``, by halving until flat.

    Each emitted chord's piece is within ``tol`` of it (see :func:`_flatness`),
    so the whole curve is within ``tol`` of the polygon.
    """
    out: list[NDArray[np.float64]] = []
    stack = [(nodes, 0)]
    while stack:
        piece, depth = stack.pop()
        if _flatness(piece) <= tol:
            out.append(piece[-1])
            budget.spend(1)
            continue
        if depth >= MAX_DEPTH:
            raise Refusal(f"expected a tolerance the coordinates can resolve, found {tol:g}")
        left, right = _halve(piece)
        stack += [(right, depth + 1), (left, depth + 1)]
    return np.array(out)


def _flatness(nodes: NDArray[np.float64]) -> float:
    """An upper bound of the distance from a Bézier to its chord (segment first–last node).

    The smaller of two sound bounds: the curve lies in its control points' convex
    hull and distance to a segment is convex, so the farthest control point
    bounds it (zero for any straight curve); and, writing B(t) - L(t) as
    Σ b_i(t) (P_i - L(i/n)) with L the chord at uniform speed, that is at most
    (1 - 2^(1-n)) max |P_i - L(i/n)| (3/4 for cubics, 1/2 for quadratics).
    """
    first, last = nodes[0], nodes[-1]
    inner = nodes[1:-1]
    chord = last - first
    length2 = float(chord @ chord)
    s = np.clip((inner - first) @ chord / length2, 0.0, 1.0) if length2 > 0 else np.zeros(len(inner))
    hull = np.max(np.hypot(*(inner - first - s[:, None] * chord).T))
    n = len(nodes) - 1
    u = np.arange(1, n)[:, None] / n
    uniform = (1.0 - 2.0 ** (1 - n)) * np.max(np.hypot(*(inner - first - u * chord).T))
    return float(min(hull, uniform))


def _halve(nodes: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """de Casteljau at t = 1/2: the control points of both halves."""
    left, right, level = [nodes[0]], [nodes[-1]], nodes
    while len(level) > 1:
        level = 0.5 * (level[:-1] + level[1:])
        left.append(level[0])
        right.append(level[-1])
    return np.array(left), np.array(right[::-1])


def _flatten_arc(
    arc: Arc, linear: NDArray[np.float64], offset: NDArray[np.float64], tol: float, end: NDArray[np.float64],
    budget: Budget,
) -> NDArray[np.float64]:
    """Vertices after the first of an elliptical arc, at equal steps of its parameter; ``end`` ``(1, 2)``.

    Locally the arc is c + a cos θ + b sin θ (a, b its semi-axes); in the world
    it is c' + W (cos θ, sin θ) with W = linear @ [a b], the affine image of a
    unit circle. A chord spanning Δ of the unit circle stays within the sagitta
    1 - cos(Δ/2) of it, and W stretches no distance by more than its largest
    singular value σ, so steps Δ ≤ 2 arccos(1 - tol/σ) keep the curve within tol.
    For a circle of radius r this is the exact sagitta rule (σ = r).
    """
    rx, ry = float(arc.rx), float(arc.ry)
    if arc.sweep == 0 or rx == 0 or ry == 0:
        return end  # a zero-radius arc is a straight line (SVG's rule)
    center = np.array([arc.center.x, arc.center.y])
    a = np.array([arc.prx.x, arc.prx.y]) - center
    b = (ry / rx) * np.array([-a[1], a[0]])  # svgelements' frame: t = π/2 lies 90° on from prx
    axes = np.column_stack([a, b])
    theta0, theta1 = (
        math.atan2(*np.linalg.solve(axes, np.array([p.x, p.y]) - center)[::-1]) for p in (arc.start, arc.end)
    )
    # The sweep from the exact end points, in the direction and turn count of svgelements' sweep.
    sweep = theta1 - theta0 + 2 * math.pi * round((arc.sweep - (theta1 - theta0)) / (2 * math.pi))
    world_axes = linear @ axes
    sigma = float(np.linalg.norm(world_axes, 2))
    if sigma <= tol:
        step = math.pi / 2
    else:
        # 1 - cos(Δ/2) = tol/σ, written as 2·sin²(Δ/4) so that a tiny tol/σ does not round to Δ = 0
        step = min(math.pi / 2, 4.0 * math.asin(math.sqrt(tol / (2.0 * sigma))))
    if abs(sweep) / step > budget.left:
        budget.spend(budget.left + 1)
    n = max(1, math.ceil(abs(sweep) / step - 1e-12))
    theta = theta0 + sweep * np.arange(1, n) / n
    inner = (linear @ center + offset) + np.column_stack([np.cos(theta), np.sin(theta)]) @ world_axes.T
    return np.vstack([inner, end])


def distinct(points: NDArray[np.float64], closed: bool = True) -> NDArray[np.float64]:
    """Without consecutive duplicates, nor (``closed``) a last vertex repeating the first (within 1e-9 of the extent)."""
    if len(points) == 0:
        return points
    eps = 1e-9 * float(np.max(np.ptp(points, axis=0)))
    moved = np.abs(np.diff(points, axis=0)).max(axis=1) > eps
    kept = points[np.concatenate([[True], moved])]
    if closed:
        back = np.abs(kept - kept[0]).max(axis=1) > eps
        last = len(kept)
        while last > 1 and not back[last - 1]:
            last -= 1
        kept = kept[:last]
    return np.array(kept, dtype=np.float64)


def zero_length_segment(point: NDArray[np.float64], to_world: NDArray[np.float64], tol: float) -> NDArray[np.float64]:
    """A zero-length subpath at world ``point (2,)`` as a segment ``(2, 2)`` of length ``tol`` centred on it along
    the user x axis (mapped by ``to_world``, 3x3): the direction SVG gives its square caps; within the tolerance."""
    axis = np.asarray(to_world, dtype=np.float64)[:2, 0]
    norm = float(np.hypot(*axis))
    step = axis / norm * tol if norm > 0 and np.isfinite(norm) else np.array([tol, 0.0])
    return np.array([point - 0.5 * step, point + 0.5 * step], dtype=np.float64)
