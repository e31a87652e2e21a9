"""The distance cost's searches in plain numpy, for small keys: the same answers as the compiled
kernels of ``_cyclic_dtw`` (same sums in the same order, same tie rules), without numba's start-up.

Loading numba and its cached kernels costs 0.3–0.5 s of a command's start; for keys of a
hundred vertices these searches take milliseconds. The grids and step names are those of
``_dtw_grid``. Each dynamic program runs along anti-diagonals (every node of a diagonal
depends only on the two before it), so a diagonal is one vectorised numpy step; the closed
search solves every start at once, one row of the arrays per start.
"""

from __future__ import annotations

import sys

import numpy as np
from numpy.typing import NDArray

__all__ = ["SEARCH_NODES", "PROCESS_NODES", "takes", "distance_matrix", "maes_search", "open_search"]

STEP_B, STEP_AB, STEP_A = 0, 1, 2  # as in _dtw_grid (importing it would load numba)

SEARCH_NODES = 1_500_000
"""The largest search done here, in nodes visited (``(m + 1)(n + 1)`` per start, ``n`` starts):
keys of about 110 vertices each, some 30 ms."""
PROCESS_NODES = 4_000_000
"""Nodes one process searches here before it loads numba after all (numba then pays for itself)."""

Array = NDArray[np.float64]
_spent = 0  # nodes searched here so far by this process


def takes(m: int, n: int, closed: bool = True) -> bool:
    """Whether the search of keys of ``m`` and ``n`` vertices is done here: while numba is not
    loaded, for a small search, within this process's budget (counted when it says yes)."""
    global _spent
    nodes = (m + 1) * (n + 1) * (n if closed else 2)
    if "numba" in sys.modules or nodes > SEARCH_NODES or _spent + nodes > PROCESS_NODES:
        return False
    _spent += nodes
    return True


def distance_matrix(a: Array, b: Array) -> Array:
    """``W[i, j] = |a_i - b_j|``: ``(m, n)`` from ``a (m, 2)``, ``b (n, 2)`` (as the kernel sums it)."""
    dx = a[:, 0, None] - b[None, :, 0]
    dy = a[:, 1, None] - b[None, :, 1]
    return np.sqrt(dx * dx + dy * dy)


def _start_order(n: int) -> list[int]:
    """The order in which ``maes_search`` meets the starts (0, then each middle, depth first):
    among equally cheap starts it keeps the first met."""
    order, stack = [0], [(0, n)]
    while stack:
        low, high = stack.pop()
        if high - low < 2:
            continue
        middle = (low + high) // 2
        order.append(middle)
        stack += [(middle, high), (low, middle)]
    return order


def _closed_costs(w: Array, starts: NDArray[np.intp], moves: NDArray[np.uint8] | None = None) -> Array:
    """The cheapest closed path of each start ``(S,)``: from ``(0, s)`` to ``(m, s + n)`` in
    unrolled columns, every node paid on arrival (the start once, by the closing node).
    With ``moves ((m + 1, n + 1))`` and one start, the step arriving at each node ``(i, k = c - s)``."""
    m, n = w.shape
    # windows[r, o, x] = w[r, (o + x) mod n]: node (i, k) of start s costs windows[i mod m, (k + s0) mod n, s - s0]
    # for the first start s0, one contiguous row of starts at a time
    first, count = int(starts[0]), len(starts)
    assert np.array_equal(starts, np.arange(first, first + count))
    windows = np.lib.stride_tricks.sliding_window_view(np.concatenate([w, w], axis=1), count, axis=1)
    rows = np.arange(m + 1) % m
    before2 = np.full((m + 2, count), np.inf)  # diagonal d - 2: node i at i + 1 (0: i = -1), one column per start
    before1 = np.full((m + 2, count), np.inf)  # diagonal d - 1
    before1[1] = 0.0
    for d in range(1, m + n + 1):
        i = np.arange(max(0, d - n), min(m, d) + 1)
        k = d - i
        left, diagonal, above = before1[i + 1], before2[i], before1[i]
        better = diagonal < left
        best = np.where(better, diagonal, left)
        if moves is not None:
            move = np.where(better, STEP_AB, STEP_B)
            moves[i, k] = np.where(above < best, STEP_A, move)[:, 0]
        best = np.minimum(best, above)
        now = np.full_like(before1, np.inf)
        now[i + 1] = best + windows[rows[i], (k + first) % n]
        before2, before1 = before1, now
    return before1[m + 1]


def maes_search(w: Array) -> tuple[float, NDArray[np.int64]]:
    """What ``_cyclic_dtw.maes_search`` returns: the least cost over every start and its nodes
    ``(L + 1, 2)`` in unrolled coordinates, end first (here by solving every start, O(m n²))."""
    m, n = w.shape
    costs = _closed_costs(w, np.arange(n))
    best = min(costs)
    start = next(s for s in _start_order(n) if costs[s] == best)
    moves = np.zeros((m + 1, n + 1), np.uint8)
    _closed_costs(w, np.array([start]), moves)
    nodes = []
    i, k = m, n
    while True:
        nodes.append((i, start + k))
        if i == 0 and k == 0:
            break
        move = moves[i, k]
        if move != STEP_A:
            k -= 1
        if move != STEP_B:
            i -= 1
    return float(best), np.array(nodes, np.int64)


def open_search(w: Array) -> tuple[float, NDArray[np.int64]]:
    """What ``_cyclic_dtw.open_search`` returns: the cheapest monotone path from ``(0, 0)`` to
    ``(m - 1, n - 1)`` (every node paid once) and its nodes ``(L, 2)``, start first; ties prefer
    STEP_AB, then STEP_B, then STEP_A."""
    m, n = w.shape
    moves = np.zeros((m, n), np.uint8)
    before2 = np.full(m + 1, np.inf)  # node i at i + 1 (0: i = -1)
    before1 = np.full(m + 1, np.inf)
    before1[1] = w[0, 0]
    for d in range(1, m + n - 1):
        i = np.arange(max(0, d - n + 1), min(m - 1, d) + 1)
        j = d - i
        diagonal, left, above = before2[i], before1[i + 1], before1[i]
        better = left < diagonal
        best = np.where(better, left, diagonal)
        move = np.where(better, STEP_B, STEP_AB)
        move = np.where(above < best, STEP_A, move)
        moves[i, j] = move
        now = np.full(m + 1, np.inf)
        now[i + 1] = np.minimum(best, above) + w[i, j]
        before2, before1 = before1, now
    path = []
    i, j = m - 1, n - 1
    while True:
        path.append((i, j))
        if i == 0 and j == 0:
            break
        move = moves[i, j]
        if move != STEP_A:
            j -= 1
        if move != STEP_B:
            i -= 1
    return float(before1[m]), np.array(path[::-1], np.int64)
