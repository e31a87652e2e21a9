"""The Sederberg–Greenwood closed search by branch and bound over spans of starts (maths §2.1).

Grid, steps, energies and tie rules are those of ``_dtw_grid`` and ``_sg_kernel``; the result is, path
for path, that of ``_sg_kernel.sg_every_start_search``, which solves each of the n starts for each of the
three closing steps (O(27 m n²)). Here a *span*, starts ``first .. first + width - 1`` with a
closing step, is bounded from below by one relaxed dynamic program (``sg_forward``): the closed
paths of all its starts at once, a path being allowed to end at another start of the span than
its own. Spans are taken lowest bound first and halved; one whose bound exceeds the best energy
found cannot hold the answer and is dropped; a span of one start is solved exactly. The
relaxation's least energies forwards and backwards also confine a span's halves to the columns
of each row that a path no dearer than the best found can use (its *band*). The first
relaxation, over every start and closing step, gives the first closed path to solve (its own
start) and the tilt. docs/correspondence.md gives the argument that the answer is exact, its
rounding, and the measurements.
"""

from __future__ import annotations

import heapq
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from ._dtw_grid import STEP_A, STEP_AB, STEP_B
from ._sg_kernel import sg_every_start_search, sg_forward, sg_trace
from ..jit import cached_jit as _jit

__all__ = ["SgSearch", "sg_search"]


class SgSearch(NamedTuple):
    """What :func:`sg_search` found and what it cost."""

    work: float
    """The least energy, as ``sg_every_start_search`` sums it."""
    nodes: NDArray[np.int64]
    """``(L + 1, 2)`` in unrolled coordinates, end first, as ``sg_every_start_search`` returns them."""
    solved: int
    """(start, closing step) pairs solved exactly; the every-start search solves all 3n."""
    bounded: int
    """Relaxations solved (each for a span of starts and a closing step, or the first for all of them)."""


def sg_search(stretch: NDArray[np.float64], bend: NDArray[np.float64]) -> SgSearch:
    """The least-energy closed path over every start and closing step, for ``stretch (m, n, 3)``
    and ``bend (m, n, 3, 3)`` of ``_sg_kernel.sg_tables``: the result of ``sg_every_start_search``.

    Tables with a negative or NaN entry (constants outside the scene file's range) are searched
    start by start: the rounding allowances below assume non-negative energies.
    """
    m, n = stretch.shape[0], stretch.shape[1]
    if not (stretch.min() >= 0.0 and bend.min() >= 0.0):  # NaN fails too
        work, nodes = sg_every_start_search(stretch, bend)
        return SgSearch(float(work), nodes, 3 * n, 0)
    return _BranchAndBound(stretch, bend).run()


_Span = tuple[float, int, int, int, NDArray[np.int64], NDArray[np.int64]]
"""(lower bound, first start, closing step or -1 for any, width, lo, hi): ``lo, hi (m + 1,)`` are each
row's first and last column (offsets from the first start) that the span's paths may use."""


class _BranchAndBound:
    """One search's tables, scratch arrays, best closed path so far and counts."""

    def __init__(self, stretch: NDArray[np.float64], bend: NDArray[np.float64]) -> None:
        self.stretch, self.bend = stretch, bend
        m, n = self.m, self.n = stretch.shape[0], stretch.shape[1]
        self.energy = np.empty((2, 2 * n, 3))
        self.back = np.empty((2, 2 * n, 3))
        self.least = np.empty((m + 1, 2 * n))  # each node's least energy in a relaxation, for its band
        self.choice = np.zeros((m + 1, 2 * n, 3), np.int8)  # the first relaxation's steps, then the answer's
        self.no_choice, self.no_least = np.zeros((1, 1, 3), np.int8), np.zeros((1, 1))
        # Relative rounding of a path's energy summed forwards, or forwards to a node and backwards
        # from it: at most 2(m + n) u each way for m + n steps of two non-negative terms (u = eps/2).
        self.rounding = 8.0 * (m + n + 2) * float(np.finfo(np.float64).eps)
        self.tilt = 0.0
        self.best, self.best_start, self.best_closing = np.inf, 0, STEP_AB  # as sg_every_start_search
        self.solved: set[tuple[int, int]] = set()
        self.bounded = 0

    def run(self) -> SgSearch:
        m, n = self.m, self.n
        heap: list[_Span] = [(-np.inf, 0, -1, n, np.zeros(m + 1, np.int64), np.full(m + 1, 2 * n - 1, np.int64))]
        while heap:  # live spans hold disjoint (start, closing) pairs: (bound, first, closing) has no ties
            span = heapq.heappop(heap)
            if self._promising(*span[:3]):
                for child in self._branch(*span):
                    heapq.heappush(heap, child)
        start, closing = self.best_start, self.best_closing
        sg_forward(self.stretch, self.bend, start, 1, closing, *_whole(m, n), self.energy, self.choice, self.no_least)
        return SgSearch(float(self.best), sg_trace(self.choice, start, 1, n, closing), len(self.solved),
                        self.bounded)

    def _promising(self, bound: float, first: int, closing: int) -> bool:
        """Whether a span from ``first`` whose energies are at least ``bound`` may hold the answer:
        a lower energy, or an equal one earlier (the every-start search keeps the first start,
        then the first closing step)."""
        return bound < self.best or (bound == self.best < np.inf
                                     and (first, max(closing, 0)) < (self.best_start, self.best_closing))

    def _solve(self, start: int, closing: int, lo: NDArray[np.int64], hi: NDArray[np.int64]) -> None:
        """Solve one closed path's energy in columns ``lo..hi`` and keep it if it is the best so far."""
        if (start, closing) in self.solved:
            return
        self.solved.add((start, closing))
        value = sg_forward(self.stretch, self.bend, start, 1, closing, lo, hi, self.energy,
                           self.no_choice, self.no_least)
        if value < self.best or (value == self.best < np.inf
                                 and (start, closing) < (self.best_start, self.best_closing)):
            self.best, self.best_start, self.best_closing = value, start, closing

    def _branch(self, bound: float, first: int, closing: int, width: int, lo: NDArray[np.int64],
                hi: NDArray[np.int64]) -> list[_Span]:
        """Solve a span of one start and closing step, or return the parts of a span (bounded first,
        unless it has two starts: bounding them costs as much as solving them)."""
        if width == 1 and closing >= 0:
            self._solve(first, closing, lo, hi)
            return []
        if width == 2 and closing >= 0:
            return self._halves(bound, first, closing, width, lo, hi)
        s, b, m, n, tilt = self.stretch, self.bend, self.m, self.n, self.tilt
        guess = self.best == np.inf  # no closed path yet: the relaxation's own start is solved first
        choice = self.choice if guess else self.no_choice
        bound = sg_forward(s, b, first, width, closing, lo, hi, self.energy, choice, self.least, tilt)
        self.bounded += 1
        if guess and bound < np.inf:
            self._guess(first, width, lo, hi)
        allowance = self.rounding * (self.best + 2.0 * abs(tilt) * width)  # rounding, and the tilt's
        bound -= allowance
        if not self._promising(bound, first, closing):
            return []
        narrow_lo, narrow_hi = lo.copy(), hi.copy()
        if not _band(s, b, first, width, closing, lo, hi, self.least, self.best + allowance, tilt, self.back,
                     narrow_lo, narrow_hi):
            return []
        if closing < 0:  # the first relaxation: then each closing step on its own
            return [(bound, first, step, width, narrow_lo, narrow_hi) for step in range(3)]
        return self._halves(bound, first, closing, width, narrow_lo, narrow_hi)

    def _halves(self, bound: float, first: int, closing: int, width: int, lo: NDArray[np.int64],
                hi: NDArray[np.int64]) -> list[_Span]:
        """The span's two halves, each with the columns of ``lo..hi`` it can use."""
        halves = []
        half = width // 2
        for child, child_width in ((first, half), (first + half, width - half)):
            child_lo = np.maximum(lo - (child - first), 0)
            child_hi = np.minimum(hi - (child - first), self.n + child_width - 1)
            if np.all(child_lo <= child_hi):
                halves.append((bound, child, closing, child_width, child_lo, child_hi))
        return halves

    def _guess(self, first: int, width: int, lo: NDArray[np.int64], hi: NDArray[np.int64]) -> None:
        """Solve the start of the least path of the relaxation just solved (its steps in ``choice``),
        then set the tilt from that start's relaxed paths."""
        m, n = self.m, self.n
        first_end = max(n, int(lo[m]))
        ends = self.energy[m % 2, first_end:min(n + width - 1, int(hi[m])) + 1]  # inside the band
        end, into = np.unravel_index(int(np.argmin(ends)), ends.shape)
        start = int(sg_trace(self.choice, first, width, first_end + int(end), int(into))[-1, 1])
        for closing in range(3):
            self._solve(start, closing, *_whole(m, n))
        reach = min(n - 1, max(4, n // 32))
        wide_lo, wide_hi = _whole(m, n)
        wide_hi += reach
        sg_forward(self.stretch, self.bend, start, 1, -1, wide_lo, wide_hi, self.energy, self.no_choice, self.no_least)
        self.tilt = _tilt(self.energy[m % 2, n - reach:n + reach + 1].min(axis=1))


def _whole(m: int, n: int) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Every column of a single start's grid: ``lo, hi (m + 1,)``."""
    return np.zeros(m + 1, np.int64), np.full(m + 1, n, np.int64)


def _tilt(ends: NDArray[np.float64]) -> float:
    """The tilt under which one start's relaxed paths gain least by ending early or late.

    ``ends (2r + 1,)``: the least energies from the start to the ends ``d = -r..r`` columns from
    its own. Returns the ``t`` that maximises ``min_d (ends[d] - t·d)`` (the slope of the lower
    convex hull of the ends at ``d = 0``; the middle one where several do), 0 without two finite ends.
    """
    reach = len(ends) // 2
    offsets = np.arange(-reach, reach + 1, dtype=np.float64)
    finite = np.isfinite(ends)
    offsets, ends = offsets[finite], ends[finite]
    before, after = np.meshgrid(np.flatnonzero(offsets <= 0), np.flatnonzero(offsets >= 0), indexing="ij")
    pairs = offsets[before] != offsets[after]
    if not pairs.any():
        return 0.0
    i, j = before[pairs], after[pairs]
    slopes = (ends[j] - ends[i]) / (offsets[j] - offsets[i])
    worst = (ends[None, :] - slopes[:, None] * offsets[None, :]).min(axis=1)
    best = slopes[worst >= worst.max()]
    return float(np.median(best))


@_jit
def _band(stretch: np.ndarray, bend: np.ndarray, first: int, width: int, closing: int, lo: np.ndarray,
          hi: np.ndarray, least: np.ndarray, limit: float, tilt: float, back: np.ndarray,
          new_lo: np.ndarray, new_hi: np.ndarray) -> bool:
    """Each row's first and last column, into ``new_lo, new_hi (m + 1,)``, of the nodes on some path
    of a span's relaxation whose energy is at most ``limit``; False when a row has none.

    ``least (m + 1, C)`` holds each node's least forward energy (``sg_forward``, with ``tilt``); each
    state's least energy from it to an end (an end at offset ``k`` adding ``-tilt·(k - n)``) is found
    backwards here, two rows at a time in ``back (2, C, 3)``, and a node is kept when its least
    energies forwards and backwards add up to at most ``limit``.
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
                if i == m and n <= k < n + width and (closing < 0 or into == closing):  # an end
                    best = min(best, -tilt * (k - n))
                here[k, into] = best
                lowest = min(lowest, best)
            if least[i, k] + lowest <= limit:
                new_lo[i] = k
                new_hi[i] = max(new_hi[i], k)
        if new_hi[i] < new_lo[i]:
            return False
    return True
