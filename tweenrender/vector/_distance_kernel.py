"""The compiled loop of :func:`~tweenrender.vector.curves.distance_to_polyline` (numba).

Each point is measured against each segment of its frame's polyline with the very float operations of the
vectorised measure it replaces (the same products and sums, in the same order, so the same rounding), one
segment at a time: no ``(F, P, S, 2)`` arrays are built, and memory does not grow with the polyline.
"""

from __future__ import annotations

import numpy as np

from ..core.jit import cached_jit as _jit

__all__ = ["polyline_distances"]


@_jit
def polyline_distances(points: np.ndarray, polyline: np.ndarray) -> np.ndarray:
    """Distance from each of ``points (F, P, 2)`` to the segments of ``polyline (F, Q, 2)`` (Q ≥ 2) at the
    same frame: ``(F, P)``. A segment's foot is its start plus its direction times the clipped projection
    (the direction's squared length at least 1e-300)."""
    frames, count, ends = points.shape[0], points.shape[1], polyline.shape[1]
    out = np.empty((frames, count))
    for f in range(frames):
        for p in range(count):
            px, py = points[f, p, 0], points[f, p, 1]
            best = np.inf
            for k in range(ends - 1):
                ax, ay = polyline[f, k, 0], polyline[f, k, 1]
                abx, aby = polyline[f, k + 1, 0] - ax, polyline[f, k + 1, 1] - ay
                length = abx * abx + aby * aby
                if length < 1e-300:
                    length = 1e-300
                s = ((px - ax) * abx + (py - ay) * aby) / length
                if s < 0.0:
                    s = 0.0
                elif s > 1.0:
                    s = 1.0
                dx, dy = px - (ax + s * abx), py - (ay + s * aby)
                d = dx * dx + dy * dy
                if d < best:
                    best = d
            out[f, p] = np.sqrt(best)
    return out
