"""The compiled loops of :mod:`.curves` (numba), each with the very float operations of the array expression it
replaces (the same products and sums, in the same order, so the same rounding), and none of its temporaries:

* :func:`polyline_distances`, a point's distance to a polyline (:func:`~.curves.distance_to_polyline`), one
  segment at a time: no ``(F, P, S, 2)`` arrays, memory that does not grow with the polyline;
* :func:`weighted_sums`, the points of cubics from their Bernstein weights and control points (and their
  derivatives), in place of a small ``np.einsum`` over many frames.
"""

from __future__ import annotations

import numpy as np

from ..core.jit import cached_jit as _jit

__all__ = ["polyline_distances", "weighted_sums"]


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


@_jit
def weighted_sums(weights: np.ndarray, points: np.ndarray) -> np.ndarray:
    """``Σ_k weights[n, k] · points[b, k, d]`` for ``weights (n, K)`` and ``points (B, K, D)``: ``(B, n, D)``, each
    sum taken from zero in the order of k (as ``np.einsum("nk,bkd->bnd", ...)`` takes it)."""
    count, terms = weights.shape[0], weights.shape[1]
    batches, dims = points.shape[0], points.shape[2]
    out = np.empty((batches, count, dims))
    for b in range(batches):
        for n in range(count):
            for d in range(dims):
                acc = 0.0
                for k in range(terms):
                    acc += weights[n, k] * points[b, k, d]
                out[b, n, d] = acc
    return out
