"""How a contour or element without a partner comes and goes (maths §5.17).

It grows from (or shrinks to) a point, its area changing linearly in the segment's eased parameter
``t``: scaled about the point by √t while it grows and by √(1 − t) while it shrinks — over the whole
segment, or from the start (to the stop) :mod:`.clearance` finds clear of the other contours
(:func:`.clearance.growth_scale`) — so each frame adds (takes) an equal share of its area. Its stroke width scales
with it, so a stroke's band changes its area linearly too, and nothing is left at the key where
it is a point. Where an easing overshoots, the scale follows it, but stops at 0: a contour never
turns inside out.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

__all__ = ["scaled", "width_share"]

Array = NDArray[np.float64]


def scaled(point: Array, shape: Array, scale: Array) -> Array:
    """``shape (L, 2)`` scaled about ``point (2,)`` by each of ``scale (T,)``: ``(T, L, 2)``, exactly
    ``shape`` at scale 1 and ``point`` at scale 0."""
    out = point + scale[:, None, None] * (shape - point)
    out[scale == 1.0] = shape
    out[scale == 0.0] = point
    return out


def width_share(t: float, grows: bool) -> float:
    """The share of its stroke width a contour growing (``grows``) or shrinking is drawn with at eased
    ``t``: its scale, with ``t`` held in [0, 1] (paint does not overshoot)."""
    clipped = min(max(t, 0.0), 1.0)
    return float(np.sqrt(clipped if grows else 1.0 - clipped))
