"""The least-work correspondence among those that honour shape hints (maths §5.10).

Hinted vertex pairs ``(i, j)`` must be nodes of the closed path. Taken in a's order they cut it
into k pieces, each a monotone path from one hinted pair to the next: k open searches, each the
dynamic programme of the unhinted search with both ends fixed, whose costs add. So the minimum
over every hint-honouring path is exact, and cheaper than the cyclic search over every start.

* ``distance``: node costs add; each piece is :func:`._cyclic_dtw.open_search` on its block of
  the work matrix, a hinted node counted once.
* ``sg``: a node's bending depends on the steps entering and leaving it, so a piece's cost
  depends on the step that entered its first hinted node: each piece is solved for each of the
  three (the hinted pair is the search's start, with that step as how it was entered), giving a
  3 × 3 table of costs between entering steps at its two ends, and the pieces' tables are
  chained round the loop (min-plus), which is exact again.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from numpy.typing import NDArray

from ...errors import GeometryError
from dataclasses import replace

from ...model import Matching, Points
from .correspond import (Correspondence, _aligned, _aligned_work, _as_polygon, _check_matching, _kernels,
                         _winds_opposite, check_sg_memory)

__all__ = ["correspond_hinted", "correspond_hinted_open"]

_DEFAULT = Matching()


def correspond_hinted(a: Points, b: Points, hinted: Sequence[tuple[int, int]],
                      matching: Matching = _DEFAULT) -> Correspondence:
    """The least-cost closed correspondence of ``a (m, 2)`` and ``b (n, 2)`` whose nodes include every
    hinted pair ``(i, j)`` (distinct i, distinct j, in the same cyclic order on both once b is walked
    the way a winds). Same cost and path conventions as :func:`.correspond.correspond`."""
    _check_matching(matching)
    a, b = _aligned(_as_polygon(a, "a"), _as_polygon(b, "b"), matching.align)
    m, n = len(a), len(b)
    if not hinted:
        raise GeometryError("expected at least one hinted pair of vertices, found none")
    backwards = _winds_opposite(a, b)
    walk = (-np.arange(n)) % n if backwards else np.arange(n)
    walked_b = np.ascontiguousarray(b[walk])
    position = (lambda j: (-j) % n) if backwards else (lambda j: j)
    ends = sorted((int(i), int(position(int(j)))) for i, j in hinted)
    pieces = _pieces(ends, m, n)
    kernels = _kernels()
    if matching.cost == "distance":
        w = kernels.distance_matrix(a, walked_b)
        nodes = []
        for rows, cols in pieces:
            _, local = kernels.open_search(np.ascontiguousarray(w[np.ix_(rows, cols)]))
            nodes.append(np.column_stack([rows[local[:, 0]], cols[local[:, 1]]]))
    else:
        nodes = _sg_pieces(a, walked_b, pieces, matching)
    path = np.concatenate([piece[:-1] for piece in nodes])  # each piece's end is the next one's start
    first = int(np.flatnonzero((path[:, 0] == 0) & (np.roll(path[:, 0], 1) != 0))[0])
    path = np.roll(path, -first, axis=0)
    pairs = np.column_stack([path[:, 0], walk[path[:, 1]]]).astype(np.intp)
    pairs.flags.writeable = False
    return Correspondence(pairs, _aligned_work(a, b, pairs, matching), backwards)


def correspond_hinted_open(a: Points, b: Points, hinted: Sequence[tuple[int, int]],
                           matching: Matching = _DEFAULT) -> Correspondence:
    """The least-work correspondence of open curves ``a (m, 2)`` and ``b (n, 2)`` (ends with ends, maths
    §5.7) whose nodes include every hinted pair ``(i, j)``: pieces from one end through the hints to
    the other. b is walked forwards or backwards as the hints' order says (both tried for one hint);
    the work is the distance after ``matching.align``, as :func:`.correspond.correspond_open`'s."""
    _check_matching(matching)
    matching = replace(matching, cost="distance")
    a, b = _aligned(_as_polygon(a, "a"), _as_polygon(b, "b"), matching.align)
    m, n = len(a), len(b)
    ends = sorted((int(i), int(j)) for i, j in hinted)
    kernels = _kernels()
    best: Correspondence | None = None
    for backwards in (False, True):
        walk = np.arange(n)[::-1] if backwards else np.arange(n)
        position = [(i, (n - 1 - j) if backwards else j) for i, j in ends]
        stops = [(0, 0), *position, (m - 1, n - 1)]
        if any(q[0] < p[0] or q[1] < p[1] for p, q in zip(stops, stops[1:])):
            continue  # the hints do not run this way along b
        w = kernels.distance_matrix(a, np.ascontiguousarray(b[walk]))
        nodes = []
        for (i0, j0), (i1, j1) in zip(stops, stops[1:]):
            rows, cols = np.arange(i0, i1 + 1), np.arange(j0, j1 + 1)
            _, local = kernels.open_search(np.ascontiguousarray(w[np.ix_(rows, cols)]))
            nodes.append(np.column_stack([rows[local[:, 0]], cols[local[:, 1]]]))
        path = np.concatenate([piece[:-1] for piece in nodes] + [nodes[-1][-1:]])
        pairs = np.column_stack([path[:, 0], walk[path[:, 1]]]).astype(np.intp)
        pairs.flags.writeable = False
        found = Correspondence(pairs, _aligned_work(a, b, pairs, matching), backwards)
        if best is None or found.work < best.work - 1e-12 * max(1.0, abs(best.work)):
            best = found
    if best is None:
        raise GeometryError("expected hinted pairs in the same order along both strokes")
    return best


def _pieces(ends: list[tuple[int, int]], m: int, n: int) -> list[tuple[NDArray[np.intp], NDArray[np.intp]]]:
    """Each piece's vertices of a and of walked b, ``(R + 1,)`` and ``(C + 1,)``, from one hinted pair
    to the next (round the whole loop for a single hint)."""
    if len({i for i, _ in ends}) != len(ends) or len({p for _, p in ends}) != len(ends):
        raise GeometryError("expected hinted pairs on distinct vertices of each key")
    pieces = []
    total = 0
    for q, (i, p) in enumerate(ends):
        i_next, p_next = ends[(q + 1) % len(ends)]
        rise = (i_next - i) % m or m
        run = (p_next - p) % n or n
        total += run
        pieces.append(((i + np.arange(rise + 1)) % m, (p + np.arange(run + 1)) % n))
    if total != n:
        raise GeometryError("expected hinted pairs in the same cyclic order on both keys")
    return pieces


def _sg_pieces(a: NDArray[np.float64], walked_b: NDArray[np.float64],
               pieces: list[tuple[NDArray[np.intp], NDArray[np.intp]]], matching: Matching) -> list[NDArray[np.int64]]:
    """The pieces' nodes ``(L_q, 2)`` of the least S&G energy loop through them (module docstring)."""
    from ._hint_kernel import sg_piece, trace_piece

    mt = matching
    check_sg_memory(len(a), len(walked_b), mt)
    stretch, bend = _kernels().sg_tables(a, walked_b, mt.ks, mt.cs, mt.es, mt.kb, mt.eb, mt.mb, mt.pb)
    grids = [(np.ascontiguousarray(rows, np.int64), np.ascontiguousarray(cols, np.int64)) for rows, cols in pieces]
    tables = []
    for rows, cols in grids:
        choice = np.zeros((len(rows), len(cols), 3), np.int8)
        tables.append(np.array([sg_piece(stretch, bend, rows, cols, e, choice) for e in range(3)]))  # (3 in, 3 out)
    k = len(grids)
    best, best_steps = np.inf, [0] * (k + 1)
    for first in range(3):  # the step entering the first hinted pair, which the last piece must end with
        cost = np.full(3, np.inf)
        cost[first] = 0.0
        came = []
        for table in tables:
            total = cost[:, None] + table  # (from, to)
            came.append(np.argmin(total, axis=0))
            cost = total.min(axis=0)
        if cost[first] < best:
            steps = [first]
            for q in range(k - 1, 0, -1):
                steps.append(int(came[q][steps[-1]]))
            best, best_steps = float(cost[first]), [first] + steps[1:][::-1] + [first]
    if not np.isfinite(best):
        raise GeometryError("found no correspondence through the hinted pairs")
    out = []
    for q, (rows, cols) in enumerate(grids):
        choice = np.zeros((len(rows), len(cols), 3), np.int8)
        sg_piece(stretch, bend, rows, cols, best_steps[q], choice)
        local = trace_piece(choice, best_steps[q + 1])
        out.append(np.column_stack([rows[local[:, 0]], cols[local[:, 1]]]))
    return out
