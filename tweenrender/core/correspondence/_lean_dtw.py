"""The distance cost's closed search in memory that grows as ``n·√m``, not ``m·n`` (numba).

``_cyclic_dtw.maes_search`` takes the distance matrix ``(m, n)`` (8 bytes a node) and keeps
every node's arriving step ``(m + 1, 2n)`` (1 byte) to trace the path back: 10 000 vertices
each cost 1 GB. Here a node's distance is computed when it is visited (the same
``sqrt(dx·dx + dy·dy)``, so the same sums), and each start's dynamic program keeps its row
of costs only at every ``K``-th row (``K ≈ √(8m)``): tracing back recomputes the rows of one
stretch of ``K`` rows at a time from the checkpoint above it, keeping their steps (a start
whose band is narrow, as most of ``maes_search``'s are, keeps its band's steps at once). The rows
recomputed are the very rows of the first pass (the same arithmetic on the same inputs), so
the path is the one ``maes_search`` returns, node for node, for about twice the work of a row.
Grid, steps and tie rules are those of ``_dtw_grid`` and ``_cyclic_dtw``.
"""

from __future__ import annotations

import math

import numpy as np

from ._cyclic_dtw import maes_slots, middle_band, push_halves, start_again
from ._dtw_grid import STEP_A, STEP_AB, STEP_B, copy_nodes
from ..jit import cached_jit as _jit

__all__ = ["lean_maes_search", "checkpoint_rows"]


def checkpoint_rows(m: int) -> int:
    """Rows between checkpoints: balances the checkpoints' ``8·(2n + 1)·m / K`` bytes against the
    ``2n·K`` bytes of one stretch's steps."""
    return max(8, int(math.sqrt(8.0 * (m + 1))))


@_jit
def _row(a: np.ndarray, b: np.ndarray, i: int, lo: np.ndarray, hi: np.ndarray,
         prev: np.ndarray, cur: np.ndarray, row_moves: np.ndarray, at: int) -> None:
    """Row ``i ≥ 1`` of the dynamic program into ``cur`` from row ``i - 1`` in ``prev``, exactly as
    ``_cyclic_dtw.solve_start`` computes it (column ``c`` at ``c + 1``); column ``c``'s step goes
    to ``row_moves[at + c]``."""
    m, n = a.shape[0], b.shape[0]
    first, last = lo[i], hi[i]
    for c in range(first - 1, lo[i - 1]):
        prev[c + 1] = np.inf
    for c in range(hi[i - 1] + 1, last + 1):
        prev[c + 1] = np.inf
    r = i if i < m else 0
    ax, ay = a[r, 0], a[r, 1]
    left = np.inf
    for part in range(2):
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
            dx, dy = ax - b[c - shift, 0], ay - b[c - shift, 1]
            left = best + math.sqrt(dx * dx + dy * dy)
            cur[c + 1] = left
            row_moves[at + c] = move


@_jit
def _first_row(a: np.ndarray, b: np.ndarray, lo: np.ndarray, hi: np.ndarray, cur: np.ndarray) -> None:
    n = b.shape[0]
    s = lo[0]
    cur[0] = np.inf
    cur[s + 1] = 0.0
    ax, ay = a[0, 0], a[0, 1]
    for c in range(s + 1, hi[0] + 1):
        j = c - n if c >= n else c
        dx, dy = ax - b[j, 0], ay - b[j, 1]
        cur[c + 1] = cur[c] + math.sqrt(dx * dx + dy * dy)


@_jit
def _solve_and_trace(a: np.ndarray, b: np.ndarray, lo: np.ndarray, hi: np.ndarray, every: int,
                     checkpoints: np.ndarray, moves: np.ndarray, band: np.ndarray, at: np.ndarray,
                     prev: np.ndarray, cur: np.ndarray,
                     row_first: np.ndarray, row_last: np.ndarray, nodes: np.ndarray) -> tuple[float, int]:
    """``solve_start`` then ``trace_back`` of ``_cyclic_dtw`` for the start ``lo[0]``: returns the cost
    and the number of nodes written to ``nodes`` (end first).

    A band of at most ``len(band)`` nodes keeps every node's step there, row ``i`` from
    ``at[i]`` on; a wider one (the first starts' of ``maes_search``) is solved with checkpoints.
    """
    m, n = a.shape[0], b.shape[0]
    s = lo[0]
    total = 0
    for i in range(m + 1):
        at[i] = total - lo[i]
        total += hi[i] - lo[i] + 1
    kept = total <= band.shape[0]
    prev[0] = np.inf
    _first_row(a, b, lo, hi, cur)
    checkpoints[0, :] = cur
    for i in range(1, m + 1):
        prev, cur = cur, prev
        if kept:
            _row(a, b, i, lo, hi, prev, cur, band, at[i])
        else:
            _row(a, b, i, lo, hi, prev, cur, moves[0], 0)  # steps not kept on this pass
            if i % every == 0:
                checkpoints[i // every, :] = cur
    value = cur[s + n + 1]

    i, c = m, s + n
    row_last[i] = c
    count = 0
    loaded = -1  # the stretch whose steps are in ``moves``: rows loaded*every + 1 .. its top
    while True:
        nodes[count, 0] = i
        nodes[count, 1] = c
        count += 1
        row_first[i] = c
        if i == 0 and c == s:
            return value, count
        if i == 0:
            move = STEP_B
        elif kept:
            move = band[at[i] + c]
        else:
            stretch = (i - 1) // every
            if stretch != loaded:  # recompute rows stretch*every + 1 .. i from the checkpoint above
                base = stretch * every
                prev[:] = checkpoints[stretch, :]
                for r in range(base + 1, i + 1):
                    _row(a, b, r, lo, hi, prev, cur, moves[r - base - 1], 0)
                    prev, cur = cur, prev
                loaded = stretch
            move = moves[i - stretch * every - 1, c]
        if move != STEP_A:
            c -= 1
        if move != STEP_B:
            i -= 1
            row_last[i] = c


@_jit
def lean_maes_search(a: np.ndarray, b: np.ndarray, every: int) -> tuple[float, np.ndarray]:
    """What ``_cyclic_dtw.maes_search(distance_matrix(a, b))`` returns, for ``a (m, 2)``, ``b (n, 2)``,
    in ``O(n·m / every + n·every + m + n)`` memory (``every``: rows between checkpoints)."""
    m, n = a.shape[0], b.shape[0]
    moves = np.empty((every, 2 * n), np.uint8)
    checkpoints = np.empty((m // every + 1, 2 * n + 1))
    band = np.empty(8 * checkpoints.size, np.uint8)  # as many bytes as the checkpoints
    at = np.empty(m + 1, np.int64)
    prev = np.empty(2 * n + 1)
    cur = np.empty(2 * n + 1)
    lo = np.empty(m + 1, np.int64)
    hi = np.empty(m + 1, np.int64)
    nodes = np.empty((m + n + 1, 2), np.int64)
    best_nodes = np.empty((m + n + 1, 2), np.int64)
    row_first, row_last, stack = maes_slots(m, n)

    for i in range(m + 1):
        lo[i], hi[i] = 0, n
    best, best_count = _solve_and_trace(a, b, lo, hi, every, checkpoints, moves, band, at, prev, cur,
                                        row_first[0], row_last[0], best_nodes)
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
        slot = 2 + depth
        value, count = _solve_and_trace(a, b, lo, hi, every, checkpoints, moves, band, at, prev, cur,
                                        row_first[slot], row_last[slot], nodes)
        if value < best:
            best, best_count = value, count
            copy_nodes(nodes, best_nodes, count)
        top = push_halves(stack, top, s_lo, mid, s_hi, slot_lo, slot, slot_hi, depth)
    return best, copy_nodes(best_nodes, np.empty((best_count, 2), np.int64), best_count)
