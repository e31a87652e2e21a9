"""Vertex paths between two corresponding keys (same vertex count), vectorised over t.

Every function takes keys ``k0, k1`` of shape ``(N, 2)`` and times ``t`` of shape
``(T,)`` in [0, 1] and returns the inbetweens, shape ``(T, N, 2)``.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..geometry import best_fit_rotation, centroid, rotate, spoke_rotation

__all__ = [
    "linear", "nonlinear", "nonlinear_controls", "rigid", "bezier2", "as_times",
]

Array = NDArray[np.float64]

# |M_i - Cm| below this fraction of the shape's size counts as "no direction" (maths §4).
_DEGENERATE = 1e-9


def as_times(t: ArrayLike) -> Array:
    """``t`` as a float64 ``(T,)`` array (a scalar becomes ``(1,)``)."""
    return np.atleast_1d(np.asarray(t, dtype=np.float64))


def linear(k0: Array, k1: Array, t: ArrayLike) -> Array:
    """Straight-line paths ``(1-t)·K0 + t·K1``: ``(T, N, 2)``."""
    t = as_times(t)[:, None, None]
    return (1.0 - t) * k0 + t * k1


def bezier2(p0: Array, p1: Array, p2: Array, t: ArrayLike) -> Array:
    """Quadratic Bézier through control points ``(N, 2)`` each, at ``t (T,)``: ``(T, N, 2)``."""
    t = as_times(t)[:, None, None]
    s = 1.0 - t
    return s * s * p0 + 2.0 * s * t * p1 + t * t * p2


def nonlinear_controls(k0: Array, k1: Array,
                       centers: tuple[Array, Array] | None = None) -> tuple[Array, Array, Array]:
    """The thesis's quadratic Bézier control points ``P0, P1, P2``, each ``(N, 2)`` (maths §4).

    The middle control point is placed so that the path passes at t = 0.5 through
    the linear midpoint frame pushed back out to each vertex's mean distance from
    the center of mass — or from ``centers`` ``(c0, c1)``, each ``(2,)``, when the
    shape turns about some other point (a joint).
    """
    c0, c1 = (centroid(k0), centroid(k1)) if centers is None else centers
    mid = 0.5 * (k0 + k1)
    cm = 0.5 * (c0 + c1)
    u0, u1 = k0 - c0, k1 - c1
    dist = 0.5 * (np.linalg.norm(u0, axis=-1) + np.linalg.norm(u1, axis=-1))  # (N,)

    direction = mid - cm
    length = np.linalg.norm(direction, axis=-1)
    scale = max(float(dist.max(initial=0.0)), 1e-300)
    flat = length <= _DEGENERATE * scale
    if np.any(flat):
        # Near a 180° turn the midpoint frame collapses onto its center: turn the
        # first key's spoke by half the best-fit rotation instead (or the last key's
        # spoke back, for a vertex that starts at the center).
        phi = float(spoke_rotation(u0, u1))
        spoke = np.where(
            (np.linalg.norm(u0, axis=-1) > 0)[:, None], rotate(u0, phi / 2), rotate(u1, -phi / 2)
        )
        direction = np.where(flat[:, None], spoke, direction)
        length = np.linalg.norm(direction, axis=-1)
    unit = np.divide(direction, length[:, None], out=np.zeros_like(direction), where=length[:, None] > 0)
    reshaped = cm + unit * dist[:, None]
    p1 = 2.0 * reshaped - 0.5 * (k0 + k1)
    return k0, p1, k1


def nonlinear(k0: Array, k1: Array, t: ArrayLike) -> Array:
    """The thesis's nonlinear (quadratic Bézier) paths: ``(T, N, 2)``."""
    return bezier2(*nonlinear_controls(k0, k1), t)


def rigid(k0: Array, k1: Array, t: ArrayLike) -> Array:
    """Exact rigid paths (maths §5.2): the center moves straight, the spokes turn by ``t·φ``.

    A rigid motion is reproduced at every t; a non-rigid change is blended
    linearly in the turning frame. Returns ``(T, N, 2)``.
    """
    t = as_times(t)
    c0, c1 = centroid(k0), centroid(k1)
    phi = float(best_fit_rotation(k0, k1))
    u0 = k0 - c0
    u1 = rotate(k1 - c1, -phi)
    center = (1.0 - t)[:, None] * c0 + t[:, None] * c1  # (T, 2)
    spokes = linear(u0, u1, t)  # (T, N, 2)
    return center[:, None, :] + rotate(spokes, (t * phi)[:, None])
