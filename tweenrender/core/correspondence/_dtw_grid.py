"""The grid every compiled correspondence kernel walks (numba): its steps, and copying a path's nodes.

The grid is *unrolled*: row ``i`` in ``0..m`` is vertex ``i mod m`` of polygon a,
column ``c`` in ``0..2n-1`` is vertex ``c mod n`` of polygon b (walked forwards).
A closed path through the cyclic grid that starts at ``(0, s)`` is a monotone
path from ``(0, s)`` to ``(m, s + n)``; its last node is its first.

A step is named by what it advances (the order is the tie preference, see
``_cyclic_dtw.solve_start``)::

    STEP_B   (0, +1)  b only: a's vertex is duplicated
    STEP_AB  (+1, +1) both
    STEP_A   (+1, 0)  a only: b's vertex is duplicated
"""

from __future__ import annotations

import numpy as np

from ..jit import cached_jit as _jit

__all__ = ["STEP_B", "STEP_AB", "STEP_A", "copy_nodes"]

STEP_B, STEP_AB, STEP_A = 0, 1, 2


@_jit
def copy_nodes(source: np.ndarray, target: np.ndarray, count: int) -> np.ndarray:
    """Copy the first ``count`` nodes; returns ``target``.

    An explicit loop: numba compiles a 2-D slice assignment for seconds.
    """
    for k in range(count):
        target[k, 0], target[k, 1] = source[k, 0], source[k, 1]
    return target
