"""Least-cost assignment (the linear sum assignment problem), without importing scipy for small ones.

Pairing a drawing's elements or a key's contours is an assignment of a few items: a
Hungarian method written out over numpy rows solves it in well under a millisecond, where
importing ``scipy.optimize`` costs about 0.4 s of every command's start. Larger problems go
to scipy's ``linear_sum_assignment``.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["min_cost_assignment", "SMALL_ASSIGNMENT"]

SMALL_ASSIGNMENT = 48
"""Problems with at most this many rows and columns are solved here; larger ones by scipy."""


def min_cost_assignment(cost: ArrayLike) -> tuple[NDArray[np.intp], NDArray[np.intp]]:
    """Rows and columns of a least-cost assignment of ``cost (m, n)``: ``min(m, n)`` pairs, rows
    increasing (as ``scipy.optimize.linear_sum_assignment`` returns them). Costs must be finite."""
    matrix = np.asarray(cost, dtype=np.float64)
    if matrix.ndim != 2:
        raise ValueError(f"expected a 2-D cost matrix, found shape {matrix.shape}")
    m, n = matrix.shape
    if m == 0 or n == 0:
        return np.empty(0, np.intp), np.empty(0, np.intp)
    if not np.all(np.isfinite(matrix)):
        raise ValueError("expected finite costs")
    if max(m, n) > SMALL_ASSIGNMENT:
        from scipy.optimize import linear_sum_assignment

        rows, cols = linear_sum_assignment(matrix)
        return rows.astype(np.intp), cols.astype(np.intp)
    if m <= n:
        return _hungarian(matrix)
    cols, rows = _hungarian(matrix.T)
    order = np.argsort(rows)
    return rows[order], cols[order]


def _hungarian(cost: NDArray[np.float64]) -> tuple[NDArray[np.intp], NDArray[np.intp]]:
    """The Hungarian method with potentials (Kuhn–Munkres, shortest augmenting paths) for ``m ≤ n``:
    O(m² n). Rows are added one at a time; each finds the cheapest augmenting path in reduced costs."""
    m, n = cost.shape
    u = np.zeros(m + 1)  # row potentials, 1-based; u[0] unused
    v = np.zeros(n + 1)  # column potentials; column 0 is the virtual start
    owner = np.zeros(n + 1, np.intp)  # owner[j]: the row (1-based) assigned to column j, 0 for none
    for row in range(1, m + 1):
        owner[0] = row
        column = 0
        reach = np.full(n + 1, np.inf)  # least reduced cost of reaching each column so far
        via = np.zeros(n + 1, np.intp)  # the column before it on that path
        used = np.zeros(n + 1, bool)
        while True:
            used[column] = True
            here = owner[column]
            reduced = cost[here - 1] - u[here] - v[1:]
            free = ~used[1:]
            better = free & (reduced < reach[1:])
            reach[1:][better] = reduced[better]
            via[1:][better] = column
            candidates = np.where(free, reach[1:], np.inf)
            nxt = int(np.argmin(candidates)) + 1
            delta = candidates[nxt - 1]
            u[owner[used]] += delta
            v[used] -= delta
            reach[~used] -= delta
            column = nxt
            if owner[column] == 0:
                break
        while column:  # flip the augmenting path
            before = via[column]
            owner[column] = owner[before]
            column = before
    assigned = np.nonzero(owner[1:])[0]
    rows = owner[1:][assigned] - 1
    order = np.argsort(rows)
    return rows[order].astype(np.intp), assigned[order].astype(np.intp)
