"""Polygon measures, vectorised over any leading axes.

A polygon is ``(..., N, 2)`` float64, closed implicitly; results drop the last two axes.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from numpy.typing import NDArray

__all__ = ["bounding_boxes", "boxes_holding", 
    "centroid", "edges", "edge_lengths", "perimeter", "signed_area", "area",
    "best_fit_rotation", "spoke_rotation", "rotate", "cross", "outline_length", "hull_area",
]

Array = NDArray[np.float64]


def cross(a: Array, b: Array) -> Array:
    """2-D cross product ``a.x*b.y - a.y*b.x`` over the last axis."""
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def centroid(points: Array) -> Array:
    """Center of mass of unit-mass vertices (the vertex mean, maths §1): ``(..., 2)``."""
    return points.mean(axis=-2)


def edges(points: Array) -> Array:
    """Edge vectors ``V[i+1] - V[i]``: ``(..., N, 2)``."""
    return np.roll(points, -1, axis=-2) - points


def edge_lengths(points: Array) -> Array:
    """Edge lengths ``|V[i+1] - V[i]|``: ``(..., N)``."""
    return np.linalg.norm(edges(points), axis=-1)


def perimeter(points: Array) -> Array:
    """Sum of edge lengths: ``(...)``."""
    return edge_lengths(points).sum(axis=-1)


def outline_length(contours: Sequence[Array], closed: Sequence[bool]) -> float:
    """Total length of contours ``(N_i, 2)``: perimeters of the closed ones, lengths of the open ones."""
    total = 0.0
    for points, shut in zip(contours, closed):
        total += float(perimeter(points)) if shut else float(np.linalg.norm(np.diff(points, axis=0), axis=1).sum())
    return total


def signed_area(points: Array) -> Array:
    """Shoelace area, positive for counter-clockwise winding: ``(...)``."""
    return 0.5 * cross(points, np.roll(points, -1, axis=-2)).sum(axis=-1)


def area(points: Array) -> Array:
    return np.abs(signed_area(points))


def hull_area(points: Array) -> float:
    """The area of the convex hull of ``points (N, 2)`` (quickhull, each split one numpy pass): the
    triangle from a chord to the farthest point beyond it, then the same on the two new chords."""
    pts = np.asarray(points, dtype=np.float64).reshape(-1, 2)
    if len(pts) < 3:
        return 0.0
    a, b = pts[np.argmin(pts[:, 0])], pts[np.argmax(pts[:, 0])]
    total = 0.0
    chords = [(a, b, pts), (b, a, pts)]
    while chords:
        p, q, near = chords.pop()
        height = cross(q - p, near - p)  # twice the triangle (p, q, x) for each x: > 0 beyond the chord
        out = height > 0.0
        if not out.any():
            continue
        beyond, k = near[out], int(np.argmax(height))
        far = near[k]
        total += 0.5 * float(height[k])
        chords += [(p, far, beyond), (far, q, beyond)]
    return total


def best_fit_rotation(a: Array, b: Array) -> Array:
    """Angle φ ∈ (−π, π] that best turns ``a - centroid(a)`` onto ``b - centroid(b)`` (2-D Kabsch).

    ``a`` and ``b`` are ``(..., N, 2)`` with corresponding vertices. φ is 0 when
    the fit is undefined (all vertices at the center).
    """
    return spoke_rotation(a - centroid(a)[..., None, :], b - centroid(b)[..., None, :])


def spoke_rotation(u: Array, v: Array) -> Array:
    """Angle φ ∈ (−π, π] that best turns offsets ``u`` onto offsets ``v``, both ``(..., N, 2)``,
    about their common origin (0 when undefined)."""
    s = cross(u, v).sum(axis=-1)
    c = (u * v).sum(axis=(-2, -1))
    phi = np.arctan2(s, c)
    # atan2 returns −π for (−0, negative): keep the half-open interval (−π, π].
    return np.where(phi <= -np.pi, np.pi, phi)


def rotate(vectors: Array, angle: Array | float) -> Array:
    """Turn ``(..., 2)`` vectors counter-clockwise by ``angle`` (broadcast over leading axes)."""
    angle = np.asarray(angle, dtype=np.float64)
    c, s = np.cos(angle)[..., None], np.sin(angle)[..., None]
    x, y = vectors[..., 0:1], vectors[..., 1:2]
    return np.concatenate([c * x - s * y, s * x + c * y], axis=-1)


def bounding_boxes(contours: Sequence[NDArray[np.float64]]) -> NDArray[np.float64]:
    """Each contour's ``(N_i, 2)`` bounding box ``[xmin, ymin, xmax, ymax]``: ``(C, 4)`` (an empty contour's
    box holds nothing: ``[inf, inf, -inf, -inf]``)."""
    out = np.empty((len(contours), 4))
    out[:, :2], out[:, 2:] = np.inf, -np.inf
    for i, points in enumerate(contours):
        points = np.asarray(points, dtype=np.float64)
        if len(points):
            out[i, :2], out[i, 2:] = points.min(axis=0), points.max(axis=0)
    return out


def boxes_holding(point: NDArray[np.float64], boxes: NDArray[np.float64]) -> NDArray[np.intp]:
    """The indices of ``boxes (C, 4)`` holding ``point (2,)``, edges included: the only contours an exact
    point-in-polygon test can find it inside (``(K,)``, ascending)."""
    x, y = float(point[0]), float(point[1])
    return np.flatnonzero((boxes[:, 0] <= x) & (x <= boxes[:, 2]) & (boxes[:, 1] <= y) & (y <= boxes[:, 3]))
