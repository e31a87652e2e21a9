"""The compiled loop of :func:`~tweenrender.vector.keyframes._room` (numba): per span end and vertex, one pass over
the frames between for the least-squares end correction and one for the interval of corrections that keeps every
frame within the limit. No ``(C, M, N, D)`` arrays are built."""

from __future__ import annotations

import numpy as np

from ..core.jit import cached_jit as _jit

__all__ = ["room_bounds"]


@_jit
def room_bounds(values: np.ndarray, start: np.ndarray, ends: np.ndarray, between: np.ndarray, s: np.ndarray,
                inside: np.ndarray, limit: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """For spans from values ``start (N, D)`` to frames ``ends (C,)`` of ``values (F, N, D)``, measured at frames
    ``between (M,)`` at timed fractions ``s (C, M)`` (where ``inside (C, M)``), with per-vertex ``limit (N,)``:
    the room's ``lo``, ``hi`` ``(C, N)``, the correction's direction ``unit (C, N, D)`` and size ``least (C, N)``."""
    count, vertices, dims = ends.shape[0], start.shape[0], start.shape[1]
    frames = between.shape[0]
    lo = np.empty((count, vertices))
    hi = np.empty((count, vertices))
    unit = np.zeros((count, vertices, dims))
    least = np.empty((count, vertices))
    gap = np.empty(dims)
    mean = np.empty(dims)
    for c in range(count):
        e = ends[c]
        weight = 0.0
        for m in range(frames):
            weight += s[c, m] * s[c, m]
        for n in range(vertices):
            for d in range(dims):
                mean[d] = 0.0
            for m in range(frames):
                if inside[c, m]:
                    f = between[m]
                    for d in range(dims):
                        g = values[f, n, d] - start[n, d] - s[c, m] * (values[e, n, d] - start[n, d])
                        mean[d] += s[c, m] * g
            size2 = 0.0
            for d in range(dims):
                mean[d] = mean[d] / weight
                size2 += mean[d] * mean[d]
            size = np.sqrt(size2)
            least[c, n] = size
            if size > 0:
                for d in range(dims):
                    unit[c, n, d] = mean[d] / size
            else:
                unit[c, n, 0] = 1.0
            r = limit[n]
            low, high = -np.inf, np.inf
            for m in range(frames):
                if not inside[c, m]:
                    continue
                f = between[m]
                along = 0.0
                norm2 = 0.0
                for d in range(dims):
                    gap[d] = values[f, n, d] - start[n, d] - s[c, m] * (values[e, n, d] - start[n, d])
                    along += gap[d] * unit[c, n, d]
                    norm2 += gap[d] * gap[d]
                disc = along * along - norm2 + r * r
                if disc >= 0:
                    root = np.sqrt(disc)
                    a, b = (along - root) / s[c, m], (along + root) / s[c, m]
                else:
                    a, b = np.inf, -np.inf
                if a > low:
                    low = a
                if b < high:
                    high = b
            lo[c, n] = low if low > -r else -r
            hi[c, n] = high if high < r else r
    return lo, hi, unit, least
