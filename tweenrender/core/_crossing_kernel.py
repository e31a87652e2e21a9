"""The compiled pair loop of :func:`~tweenrender.core.crossings.self_crossing` (numba).

Every pair of edges is tested with the very same float operations as the vectorised test it replaces
(each cross product of the same differences, in the same order, so the same rounding), but one pair at
a time in order of ``(i, j)``: it stops at the first pair that meets, and builds no ``(N, N)`` arrays.
"""

from __future__ import annotations

import numpy as np

from .jit import cached_jit as _jit

__all__ = ["first_meeting"]


@_jit
def _straddles(d1: float, d2: float) -> bool:
    """``sign(d1) * sign(d2) <= 0``, as numpy gives it (False where either is NaN)."""
    if d1 != d1 or d2 != d2:
        return False
    return not ((d1 > 0.0 and d2 > 0.0) or (d1 < 0.0 and d2 < 0.0))


@_jit
def first_meeting(ax: np.ndarray, ay: np.ndarray, bx: np.ndarray, by: np.ndarray) -> tuple[int, int]:
    """The lowest-numbered pair ``(i, j)``, ``i < j``, of edges ``a → b`` (coordinates ``(N,)`` each, an
    outline's) that are not neighbours and share a point, or ``(-1, -1)``.

    Edges i and j share a point when the ends of each lie on both sides of the other's line (or on it),
    not all four on one line; when all four are, when their boxes overlap in both coordinates.
    """
    n = ax.shape[0]
    ex = bx - ax
    ey = by - ay
    for i in range(n - 2):
        pax, pay, pbx, pby, pex, pey = ax[i], ay[i], bx[i], by[i], ex[i], ey[i]
        for j in range(i + 2, n):
            if i == 0 and j == n - 1:
                continue
            qx, qy, qex, qey = ax[j], ay[j], ex[j], ey[j]
            d1 = qex * (pay - qy) - qey * (pax - qx)  # cross(q2 - q1, p1 - q1)
            d2 = qex * (pby - qy) - qey * (pbx - qx)  # cross(q2 - q1, p2 - q1)
            if not _straddles(d1, d2):
                continue
            d3 = pex * (ay[j] - pay) - pey * (ax[j] - pax)  # cross(p2 - p1, q1 - p1)
            d4 = pex * (by[j] - pay) - pey * (bx[j] - pax)  # cross(p2 - p1, q2 - p1)
            if d1 == 0.0 and d2 == 0.0 and d3 == 0.0 and d4 == 0.0:  # on one line: do they overlap?
                low_x = max(min(pax, pbx), min(ax[j], bx[j]))
                high_x = min(max(pax, pbx), max(ax[j], bx[j]))
                low_y = max(min(pay, pby), min(ay[j], by[j]))
                high_y = min(max(pay, pby), max(ay[j], by[j]))
                if low_x <= high_x and low_y <= high_y:
                    return i, j
            elif _straddles(d3, d4):
                return i, j
    return -1, -1
