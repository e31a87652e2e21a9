"""Outlines cut to a box far around the canvas, so pixel coordinates always fit skia's float32.

A view can magnify without limit (``view = [0, 0, 1e-300, 1e-300]`` is 10³⁰² pixels a
unit): vertices then lie far beyond float32's 3.4·10³⁸. Cutting the outline to a box
(Sutherland–Hodgman, one side at a time) keeps what is drawn on the canvas exactly: for
a closed outline, each cut replaces a run outside the side by a straight line along it,
which changes no winding number inside (so neither fill rule changes a pixel there); for
an open one, the replacement runs along the side, far outside the canvas.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

__all__ = ["FAR", "clip_to_box"]

FAR = float(1 << 21)
"""Half the side of the box outlines are cut to, in pixels: 2 million, beyond any canvas and stroke."""


def clip_to_box(points: NDArray[np.float64], closed: bool = True, far: float = FAR) -> NDArray[np.float64]:
    """``points (N, 2)`` (finite) cut to the box ``[-far, far]²``: ``(M, 2)``, M ≥ 0; unchanged when inside."""
    if len(points) == 0 or np.abs(points).max() <= far:
        return points
    for axis in (0, 1):
        for sign in (1.0, -1.0):
            points = _clip_side(points, axis, sign, far, closed)
            if len(points) == 0:
                return points
    return np.clip(points, -far, far)  # a weighted mean may round one ulp past the box


def _clip_side(points: NDArray[np.float64], axis: int, sign: float, far: float, closed: bool) -> NDArray[np.float64]:
    """Keep the side ``sign · x[axis] ≤ far``; each edge gives its crossing (if it crosses) then its end (if in)."""
    inside = sign * points[:, axis] <= far
    if inside.all():
        return points
    if not inside.any():
        return points[:0]
    start, end = (points, np.roll(points, -1, axis=0)) if closed else (points[:-1], points[1:])
    start_in, end_in = (inside, np.roll(inside, -1)) if closed else (inside[:-1], inside[1:])
    crosses = start_in != end_in
    bound = sign * far
    # the crossing as a weighted mean of the edge's ends: start + t·(end − start) would cancel
    # catastrophically for an end at 1e300 and a crossing near the canvas
    with np.errstate(divide="ignore", invalid="ignore"):  # edges that do not cross are not used
        span = end[:, axis] - start[:, axis]
        to_end = np.where(crosses, (end[:, axis] - bound) / span, 0.0)
        from_start = np.where(crosses, (bound - start[:, axis]) / span, 0.0)
    crossing = to_end[:, None] * start + from_start[:, None] * end
    crossing[:, axis] = bound
    slots = np.stack([crossing, end], axis=1)  # (edges, 2, 2): per edge, crossing then end
    kept = slots[np.stack([crosses, end_in], axis=1)]
    if not closed and inside[0]:
        kept = np.concatenate([points[:1], kept])
    return kept
