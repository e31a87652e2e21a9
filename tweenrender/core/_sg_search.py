"""The Sederberg–Greenwood closed search by branch and bound over spans of starts (maths §2.1).

Grid, steps, energies and tie rules are those of ``_cyclic_dtw`` (``sg_forward``); the
result is, path for path, that of ``_cyclic_dtw.sg_every_start_search``, which solves all
n starts (O(27 m n²)). Here a *span* of starts ``first .. first + width - 1`` is first
bounded from below by one relaxed dynamic program (``sg_forward`` with ``closing < 0``: any
start of the span, any end of the span, the closing step free), whose sums are the exact
search's, in the same order, so the bound holds as rounded too. Spans are taken cheapest
bound first and halved; a span whose bound exceeds the best energy found cannot hold the
answer and is dropped; a single start is solved exactly. The relaxation's forward and
backward energies also confine each span's paths to the columns of every row that a path
no dearer than the best found can use (its *band*), so that a span's descendants are solved
in those columns only. docs/correspondence.md gives the argument and the measurements.
"""

from __future__ import annotations

import heapq
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from ._cyclic_dtw import STEP_A, STEP_AB, STEP_B, sg_every_start_search, sg_forward, sg_trace
from .jit import cached_jit as _jit

__all__ = ["SgSearch", "sg_search"]


class SgSearch(NamedTuple):
    """What :func:`sg_search` found and what it cost."""

    work: float
    nodes: NDArray[np.int64]
    """``(L + 1, 2)`` in unrolled coordinates, end first, as ``sg_every_start_search`` returns them."""
    solved: int
    """Starts solved exactly (each for its three closing steps); the every-start search solves n."""
    bounded: int
    """Spans of starts bounded by a relaxation."""


def sg_search(stretch: NDArray[np.float64], bend: NDArray[np.float64]) -> SgSearch:
    """The least-energy closed path over every start and closing step, for ``stretch (m, n, 3)``
    and ``bend (m, n, 3, 3)`` of ``_cyclic_dtw.sg_tables``: the result of ``sg_every_start_search``.

    Tables with a negative or NaN entry (constants outside the scene file's range) are searched
    start by start: the bands' rounding margin assumes non-negative energies.
    """
    m, n = stretch.shape[0], stretch.shape[1]
    if not (np.all(stretch >= 0.0) and np.all(bend >= 0.0)):
        work, nodes = sg_every_start_search(stretch, bend)
        return SgSearch(float(work), nodes, n, 0)
    return _BranchAndBound(stretch, bend).run()


class _BranchAndBound:
    """One search's tables, scratch arrays, best closed path so far and counts."""

    def __init__(self, stretch: NDArray[np.float64], bend: NDArray[np.float64]) -> None:
        self.stretch, self.bend = stretch, bend
        m, n = self.m, self.n = stretch.shape[0], stretch.shape[1]
        self.energy = np.empty((2, 2 * n, 3))
        self.least = np.empty((m + 1, 2 * n))  # each node's least energy in a span's relaxation
        self.choice = np.zeros((m + 1, 2 * n, 3), np.int8)  # the first relaxation's, then the answer's steps
        self.back = np.empty((2, 2 * n, 3))
        self.no_choice, self.no_least = np.zeros((1, 1, 3), np.int8), np.zeros((1, 1))
        # Relative rounding of a path's energy summed forwards, or forwards to a node and backwards
        # from it: at most 2(m + n) u each way for m + n steps of two non-negative terms (u = eps/2).
        self.slack = 1.0 + 8.0 * (m + n + 2) * float(np.finfo(np.float64).eps)
        self.best, self.best_start, self.best_closing = np.inf, 0, STEP_AB
        self.solved: set[int] = set()
        self.bounded = 0

    def run(self) -> SgSearch:
        m, n = self.m, self.n
        heap: list[tuple[float, int, int, NDArray[np.int64], NDArray[np.int64]]] = [
            (-np.inf, 0, n, np.zeros(m + 1, np.int64), np.full(m + 1, 2 * n - 1, np.int64))]
        while heap:  # live spans are disjoint, so (bound, first) orders them without ties
            bound, first, width, lo, hi = heapq.heappop(heap)
            if self._promising(bound, first):
                for child in self._branch(first, width, lo, hi):
                    heapq.heappush(heap, child)
        lo, hi = _full_band(m, n)
        start, closing = self.best_start, self.best_closing
        sg_forward(self.stretch, self.bend, start, 1, closing, lo, hi, self.energy, self.choice, self.no_least)
        nodes = sg_trace(self.choice, start, 1, n, closing)
        return SgSearch(float(self.best), nodes, len(self.solved), self.bounded)

    def _promising(self, bound: float, first: int) -> bool:
        """Whether a span from ``first`` whose energies are at least ``bound`` may hold the answer:
        a lower energy, or an equal one at an earlier start (the every-start search keeps the first)."""
        return bound < self.best or (bound == self.best < np.inf and first < self.best_start)

    def _solve(self, start: int, lo: NDArray[np.int64], hi: NDArray[np.int64]) -> None:
        """Solve ``start`` for each closing step in columns ``lo..hi`` (offsets from it)."""
        if start in self.solved:
            return
        self.solved.add(start)
        for closing in range(3):
            value = sg_forward(self.stretch, self.bend, start, 1, closing, lo, hi, self.energy,
                               self.no_choice, self.no_least)
            if value < self.best or (value == self.best < np.inf and start < self.best_start):
                self.best, self.best_start, self.best_closing = value, start, closing

    def _branch(self, first: int, width: int, lo: NDArray[np.int64], hi: NDArray[np.int64]
                ) -> list[tuple[float, int, int, NDArray[np.int64], NDArray[np.int64]]]:
        """Solve a single start, or bound the span and return its two halves with their bands."""
        if width == 1:
            self._solve(first, lo, hi)
            return []
        s, b, m, n = self.stretch, self.bend, self.m, self.n
        guess = self.best == np.inf  # no closed path yet: the relaxation's own start is solved first
        choice = self.choice if guess else self.no_choice
        bound = sg_forward(s, b, first, width, -1, lo, hi, self.energy, choice, self.least)
        self.bounded += 1
        if guess and bound < np.inf:
            first_end = max(n, int(lo[m]))
            ends = self.energy[m % 2, first_end:min(n + width - 1, int(hi[m])) + 1]  # inside the band
            end, closing = np.unravel_index(int(np.argmin(ends)), ends.shape)
            path = sg_trace(choice, first, width, first_end + int(end), int(closing))
            self._solve(int(path[-1, 1]), *_full_band(m, n))
        if not self._promising(bound, first):
            return []
        narrow_lo, narrow_hi = lo.copy(), hi.copy()
        if not _band(s, b, first, width, lo, hi, self.least, self.best * self.slack, self.back, narrow_lo, narrow_hi):
            return []
        children = []
        half = width // 2
        for child, child_width in ((first, half), (first + half, width - half)):
            shift = child - first
            child_lo = np.maximum(narrow_lo - shift, 0)
            child_hi = np.minimum(narrow_hi - shift, n + child_width - 1)
            if np.all(child_lo <= child_hi):
                children.append((bound, child, child_width, child_lo, child_hi))
        return children


def _full_band(m: int, n: int) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Every column of a single start's grid: ``lo, hi (m + 1,)``."""
    return np.zeros(m + 1, np.int64), np.full(m + 1, n, np.int64)


@_jit
def _band(stretch: np.ndarray, bend: np.ndarray, first: int, width: int, lo: np.ndarray, hi: np.ndarray,
          least: np.ndarray, limit: float, back: np.ndarray, new_lo: np.ndarray, new_hi: np.ndarray) -> bool:
    """Each row's first and last column, into ``new_lo, new_hi (m + 1,)``, of the nodes on some path
    of a span's relaxation whose energy is at most ``limit``; False when a row has none.

    ``least (m + 1, C)`` holds each node's least forward energy (``sg_forward``); each state's least
    energy from it to an end is found backwards here, two rows at a time in ``back (2, C, 3)``,
    and a node is kept when its least energies forwards and backwards add up to at most ``limit``.
    """
    m, n = stretch.shape[0], stretch.shape[1]
    for i in range(m, -1, -1):
        here = back[i % 2]
        node_i = i if i < m else 0
        new_lo[i], new_hi[i] = hi[i] + 1, lo[i] - 1
        for k in range(hi[i], lo[i] - 1, -1):
            j = (first + k) % n
            lowest = np.inf
            for into in range(3):
                best = np.inf
                for step in range(3):
                    ni = i if step == STEP_B else i + 1
                    nk = k if step == STEP_A else k + 1
                    if ni > m or nk < lo[ni] or nk > hi[ni]:
                        continue
                    value = bend[node_i, j, into, step] + stretch[node_i, j, step] + back[ni % 2, nk, step]
                    if value < best:
                        best = value
                if i == m and n <= k < n + width:  # an end
                    best = min(best, 0.0)
                here[k, into] = best
                lowest = min(lowest, best)
            if least[i, k] + lowest <= limit:
                new_lo[i] = k
                new_hi[i] = max(new_hi[i], k)
        if new_hi[i] < new_lo[i]:
            return False
    return True
