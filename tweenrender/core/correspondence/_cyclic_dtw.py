"""Compiled kernels of the cyclic correspondence search (numba); the API is in ``correspond.py``.

The distance cost's searches on the grid of ``_dtw_grid``: Maes' divide and conquer over the
starts, the every-start reference and the open curves' search. The Sederberg–Greenwood kernels
(``_sg_kernel``) are given here too, so that this module offers every kernel ``correspond.py``
calls, as ``_small_dtw`` does for small keys.
"""

from __future__ import annotations

import math

import numpy as np

from ._dtw_grid import STEP_A, STEP_AB, STEP_B, copy_nodes
from ._sg_kernel import (angle_change, bend_work, sg_every_start_search, sg_forward, sg_path_energy, sg_tables,
                         sg_trace, stretch_work)
from ..jit import cached_jit as _jit

__all__ = [
    "STEP_B", "STEP_AB", "STEP_A",
    "distance_matrix", "maes_search", "maes_slots", "start_again", "middle_band", "push_halves", "every_start_search",
    "sg_tables", "sg_forward", "sg_trace", "sg_every_start_search", "sg_path_energy",
    "stretch_work", "bend_work", "angle_change", "open_search",
]


# --------------------------------------------------------------------------- distance


@_jit
def distance_matrix(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``W[i, j] = |a_i - b_j|``: ``(m, n)`` from ``a (m, 2)``, ``b (n, 2)``."""
    m, n = a.shape[0], b.shape[0]
    w = np.empty((m, n))
    for i in range(m):
        ax, ay = a[i, 0], a[i, 1]
        for j in range(n):
            dx, dy = ax - b[j, 0], ay - b[j, 1]
            w[i, j] = math.sqrt(dx * dx + dy * dy)
    return w


@_jit
def solve_start(w: np.ndarray, lo: np.ndarray, hi: np.ndarray,
                moves: np.ndarray, prev: np.ndarray, cur: np.ndarray) -> float:
    """Cheapest path from ``(0, s)`` to ``(m, s + n)`` inside columns ``lo[i]..hi[i]`` of each row.

    The start is ``s = lo[0]``; bands only widen to the right from row to row
    (``lo`` and ``hi`` never decrease) and ``hi[m] = s + n``. A node's cost
    ``w[i mod m, c mod n]`` is paid on arrival, so the start is paid once, by the
    closing node. ``moves[i, c]`` gets the step that arrived at each node. Ties
    prefer STEP_B, then STEP_AB, then STEP_A: tracing back then yields the
    *leftmost* optimal path (the smallest columns in every row), so that the
    paths of different starts nest and ``maes_search``'s bands stay thin.
    ``prev`` and ``cur`` are scratch rows of length ``2n + 1``; column ``c`` is
    kept at ``c + 1`` so that column -1 is a +inf sentinel.
    """
    m, n = w.shape
    s = lo[0]
    prev[0] = cur[0] = np.inf
    cur[s + 1] = 0.0
    for c in range(s + 1, hi[0] + 1):
        cur[c + 1] = cur[c] + w[0, c - n if c >= n else c]
        moves[0, c] = STEP_B
    for i in range(1, m + 1):
        prev, cur = cur, prev
        first, last = lo[i], hi[i]
        # Predecessors outside the row above's band cost +inf: no checks in the hot loop.
        for c in range(first - 1, lo[i - 1]):
            prev[c + 1] = np.inf
        for c in range(hi[i - 1] + 1, last + 1):
            prev[c + 1] = np.inf
        row = w[i if i < m else 0]
        row_moves = moves[i]
        left = np.inf
        for part in range(2):  # before and after the column wraps round b
            start, stop = (first, min(last + 1, n)) if part == 0 else (max(first, n), last + 1)
            shift = 0 if part == 0 else n
            for c in range(start, stop):
                best = left
                move = STEP_B
                diagonal, above = prev[c], prev[c + 1]
                if diagonal < best:
                    best = diagonal
                    move = STEP_AB
                if above < best:
                    best = above
                    move = STEP_A
                left = best + row[c - shift]
                cur[c + 1] = left
                row_moves[c] = move
    return cur[s + n + 1]


@_jit
def trace_back(moves: np.ndarray, s: int, n: int, row_first: np.ndarray, row_last: np.ndarray,
               nodes: np.ndarray) -> int:
    """Follow ``moves`` back from ``(m, s + n)`` to ``(0, s)``.

    Writes the path's first and last column in each row and its nodes, end first,
    into ``nodes``; returns the number of nodes (the closing node included).
    """
    i, c = moves.shape[0] - 1, s + n
    row_last[i] = c
    count = 0
    while True:
        nodes[count, 0] = i
        nodes[count, 1] = c
        count += 1
        row_first[i] = c
        if i == 0 and c == s:
            return count
        move = moves[i, c]
        if move != STEP_A:
            c -= 1
        if move != STEP_B:
            i -= 1
            row_last[i] = c


@_jit
def maes_slots(m: int, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Room for Maes' divide and conquer over ``n`` starts of ``m + 1`` rows: ``(row_first, row_last, stack)``.

    Bounding paths live in slots: 0 for start 0, 1 for start n, 2 + d for the middle start solved at
    recursion depth d (depth-first order never needs two live paths of the same depth); ``row_first``
    and ``row_last (slots, m + 1)`` hold each row's first and last column of a slot's path. The
    depth-first stack holds tasks (first start, last start, their slots, depth), the whole range first.
    """
    depth_limit = 2
    while (1 << (depth_limit - 2)) < n:
        depth_limit += 1
    row_first = np.empty((depth_limit + 2, m + 1), np.int64)
    row_last = np.empty((depth_limit + 2, m + 1), np.int64)
    stack = np.empty((2 * depth_limit + 4, 5), np.int64)
    stack[0, 0], stack[0, 1], stack[0, 2], stack[0, 3], stack[0, 4] = 0, n, 0, 1, 0
    return row_first, row_last, stack


@_jit
def start_again(row_first: np.ndarray, row_last: np.ndarray, n: int) -> None:
    """Slot 1 is start n: start 0's path (slot 0) one turn round b later."""
    for i in range(row_first.shape[1]):
        row_first[1, i] = row_first[0, i] + n
        row_last[1, i] = row_last[0, i] + n


@_jit
def middle_band(row_first: np.ndarray, row_last: np.ndarray, slot_lo: int, slot_hi: int, mid: int, n: int,
                lo: np.ndarray, hi: np.ndarray) -> None:
    """``lo``, ``hi (m + 1,)``: the columns start ``mid`` may use, each row's hull of the bounding paths
    in ``slot_lo`` and ``slot_hi``, within its own turn ``mid … mid + n``."""
    for i in range(lo.shape[0]):
        lo[i] = max(mid, min(row_first[slot_lo, i], row_first[slot_hi, i]))
        hi[i] = min(mid + n, max(row_last[slot_lo, i], row_last[slot_hi, i]))


@_jit
def push_halves(stack: np.ndarray, top: int, s_lo: int, mid: int, s_hi: int, slot_lo: int, slot: int,
                slot_hi: int, depth: int) -> int:
    """Push the two halves of a task whose middle start ``mid`` is in ``slot``; returns the new top.
    The lower half is pushed last so that it runs first (either order is correct)."""
    stack[top, 0], stack[top, 1], stack[top, 2] = mid, s_hi, slot
    stack[top, 3], stack[top, 4] = slot_hi, depth + 1
    stack[top + 1, 0], stack[top + 1, 1], stack[top + 1, 2] = s_lo, mid, slot_lo
    stack[top + 1, 3], stack[top + 1, 4] = slot, depth + 1
    return top + 2


@_jit
def maes_search(w: np.ndarray) -> tuple[float, np.ndarray]:
    """Exact minimal closed path over every start, by Maes' divide and conquer: O(mn log n).

    Why it is exact: two monotone paths with steps (0,1), (1,1), (1,0) can only
    cross at a shared node (no step crosses another between nodes), and node
    costs add, so between two shared nodes either path's segment can replace
    the other's. An optimal path of start ``s < mid < t`` that strays left of
    the optimal path of ``s`` (or right of that of ``t``) can therefore follow
    it instead at no extra cost: start ``mid`` is solved only in the band
    between the two. Each row's band is the hull of both paths' columns, which
    stays valid even if ties let the two paths cross.
    Returns the cost and the nodes ``(L + 1, 2)`` in unrolled coordinates, end first.
    """
    m, n = w.shape
    moves = np.empty((m + 1, 2 * n), np.uint8)
    prev = np.empty(2 * n + 1)
    cur = np.empty(2 * n + 1)
    lo = np.empty(m + 1, np.int64)
    hi = np.empty(m + 1, np.int64)
    nodes = np.empty((m + n + 1, 2), np.int64)
    best_nodes = np.empty((m + n + 1, 2), np.int64)
    row_first, row_last, stack = maes_slots(m, n)

    for i in range(m + 1):
        lo[i], hi[i] = 0, n
    best = solve_start(w, lo, hi, moves, prev, cur)
    best_count = trace_back(moves, lo[0], n, row_first[0], row_last[0], best_nodes)
    start_again(row_first, row_last, n)

    top = 1
    while top > 0:
        top -= 1
        s_lo, s_hi = stack[top, 0], stack[top, 1]
        slot_lo, slot_hi, depth = stack[top, 2], stack[top, 3], stack[top, 4]
        if s_hi - s_lo < 2:
            continue
        mid = (s_lo + s_hi) // 2
        middle_band(row_first, row_last, slot_lo, slot_hi, mid, n, lo, hi)
        value = solve_start(w, lo, hi, moves, prev, cur)
        slot = 2 + depth
        count = trace_back(moves, mid, n, row_first[slot], row_last[slot], nodes)
        if value < best:
            best, best_count = value, count
            copy_nodes(nodes, best_nodes, count)
        top = push_halves(stack, top, s_lo, mid, s_hi, slot_lo, slot, slot_hi, depth)
    return best, copy_nodes(best_nodes, np.empty((best_count, 2), np.int64), best_count)


@_jit
def every_start_search(w: np.ndarray) -> tuple[float, np.ndarray]:
    """Reference search: the full O(mn) dynamic program for each of the n starts, O(m n²).

    Same return as ``maes_search``.
    """
    m, n = w.shape
    moves = np.empty((m + 1, 2 * n), np.uint8)
    prev = np.empty(2 * n + 1)
    cur = np.empty(2 * n + 1)
    lo = np.empty(m + 1, np.int64)
    hi = np.empty(m + 1, np.int64)
    best, best_start = np.inf, 0
    for s in range(n):
        for i in range(m + 1):
            lo[i], hi[i] = s, s + n
        value = solve_start(w, lo, hi, moves, prev, cur)
        if value < best:
            best, best_start = value, s
    for i in range(m + 1):
        lo[i], hi[i] = best_start, best_start + n
    solve_start(w, lo, hi, moves, prev, cur)  # again, to trace the best path back
    nodes = np.empty((m + n + 1, 2), np.int64)
    count = trace_back(moves, best_start, n, np.empty(m + 1, np.int64),
                       np.empty(m + 1, np.int64), nodes)
    return best, copy_nodes(nodes, np.empty((count, 2), np.int64), count)


# --------------------------------------------------------------------------- open curves


@_jit
def open_search(w: np.ndarray) -> tuple[float, np.ndarray]:
    """Cheapest monotone path from ``(0, 0)`` to ``(m - 1, n - 1)`` of ``w (m, n)``: its cost (every
    node paid once) and its nodes ``(L, 2)``, start first. Plain dynamic time warping, O(mn);
    ties prefer STEP_AB, then STEP_B, then STEP_A."""
    m, n = w.shape
    cost = np.empty((m, n))
    moves = np.empty((m, n), np.uint8)
    for i in range(m):
        for j in range(n):
            if i == 0 and j == 0:
                cost[0, 0] = w[0, 0]
                moves[0, 0] = STEP_AB
                continue
            best = np.inf
            move = STEP_AB
            if i > 0 and j > 0 and cost[i - 1, j - 1] < best:
                best = cost[i - 1, j - 1]
                move = STEP_AB
            if j > 0 and cost[i, j - 1] < best:
                best = cost[i, j - 1]
                move = STEP_B
            if i > 0 and cost[i - 1, j] < best:
                best = cost[i - 1, j]
                move = STEP_A
            cost[i, j] = best + w[i, j]
            moves[i, j] = move
    path = np.empty((m + n, 2), np.int64)
    i, j, count = m - 1, n - 1, 0
    while True:
        path[count, 0], path[count, 1] = i, j
        count += 1
        if i == 0 and j == 0:
            break
        move = moves[i, j]
        if move != STEP_A:
            j -= 1
        if move != STEP_B:
            i -= 1
    out = np.empty((count, 2), np.int64)
    for k in range(count):
        out[k, 0], out[k, 1] = path[count - 1 - k, 0], path[count - 1 - k, 1]
    return cost[m - 1, n - 1], out
