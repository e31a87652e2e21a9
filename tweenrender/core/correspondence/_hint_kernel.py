"""Compiled kernel of the hinted Sederberg–Greenwood search (numba); the API is in ``hint_search.py``.

A *piece* of a hinted correspondence runs from one hinted pair to the next through the grid of
``rows (R + 1,)`` vertices of a and ``cols (C + 1,)`` vertices of b (walked), from node (0, 0) to
node (R, C). Steps are named as in ``_dtw_grid``: STEP_B (0, +1), STEP_AB (+1, +1), STEP_A (+1, 0).
"""

from __future__ import annotations

import numpy as np

from ._dtw_grid import STEP_A, STEP_B
from ..jit import cached_jit as _jit

__all__ = ["sg_piece", "trace_piece"]


@_jit
def sg_piece(stretch: np.ndarray, bend: np.ndarray, rows: np.ndarray, cols: np.ndarray, start_step: int,
             choice: np.ndarray) -> np.ndarray:
    """Least energy from (0, 0), entered by ``start_step``, to (R, C), for each step entering (R, C): ``(3,)``.

    ``stretch (m, n, 3)`` and ``bend (m, n, 3, 3)`` are ``_sg_kernel.sg_tables``'; a node's bending
    is paid when the path leaves it (the start's with ``start_step`` as its entering step), the end's
    is left to the next piece. ``choice (R + 1, C + 1, 3)`` receives, per node and entering step, the
    step that entered its predecessor, for :func:`trace_piece`.
    """
    last_r, last_c = rows.shape[0] - 1, cols.shape[0] - 1
    energy = np.full((last_r + 1, last_c + 1, 3), np.inf)
    energy[0, 0, start_step] = 0.0
    for r in range(last_r + 1):
        for c in range(last_c + 1):
            if r == 0 and c == 0:
                continue
            for step in range(3):
                pr = r if step == STEP_B else r - 1
                pc = c if step == STEP_A else c - 1
                if pr < 0 or pc < 0:
                    continue
                ni, nj = rows[pr], cols[pc]
                best, best_into = np.inf, 0
                for into in range(3):
                    value = energy[pr, pc, into] + bend[ni, nj, into, step]
                    if value < best:
                        best, best_into = value, into
                energy[r, c, step] = best + stretch[ni, nj, step]
                choice[r, c, step] = best_into
    out = np.empty(3)
    for step in range(3):
        out[step] = energy[last_r, last_c, step]
    return out


@_jit
def trace_piece(choice: np.ndarray, end_step: int) -> np.ndarray:
    """The piece's nodes ``(L, 2)`` in piece coordinates, start first, ending at (R, C) entered by ``end_step``."""
    r, c, step = choice.shape[0] - 1, choice.shape[1] - 1, end_step
    nodes = np.empty((r + c + 1, 2), np.int64)
    count = 0
    while True:
        nodes[count, 0], nodes[count, 1] = r, c
        count += 1
        if r == 0 and c == 0:
            break
        into = choice[r, c, step]
        if step != STEP_A:
            c -= 1
        if step != STEP_B:
            r -= 1
        step = into
    out = np.empty((count, 2), np.int64)
    for k in range(count):
        out[k, 0], out[k, 1] = nodes[count - 1 - k, 0], nodes[count - 1 - k, 1]
    return out
