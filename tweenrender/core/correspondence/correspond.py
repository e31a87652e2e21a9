"""Vertex correspondence of two keys with different vertex counts (maths §2).

A correspondence is a closed monotone lattice path through the cyclic ``m × n``
grid of vertex pairs ``(i, j)``: every step advances i, j or both by one (j by
minus one when b is walked backwards), the path winds once round each polygon
and closes on its start. Its ``L`` nodes become the ``L`` vertices of both
balanced polygons, ``max(m, n) ≤ L ≤ m + n``.

Path costs, over the path's nodes ``p[k] = (i[k], j[k])``, ``k = 0..L-1``, taken
cyclically (``p[L] = p[0]``, ``p[-1] = p[L-1]``), after the alignment of
``Matching.align`` (``"centroid"``: each polygon's vertex mean moved to the origin):

``distance``
    ``Σ_k |a[i[k]] - b[j[k]]|``: each node once (maths §2, the thesis's work).

``sg``
    ``Σ_k stretch_k + Σ_k bend_k`` (Sederberg–Greenwood, maths §2.1) where

    * ``stretch_k = ks·|l1 - l0|^es / ((1 - cs)·min(l0, l1) + cs·max(l0, l1))``
      for the step ``p[k] → p[k+1]``, with ``l0 = |a[i[k+1]] - a[i[k]]|`` and
      ``l1 = |b[j[k+1]] - b[j[k]]|`` (0 for a polygon the step does not
      advance), and 0 when ``l0 = l1``: L terms;
    * ``bend_k = kb·(Δθ + mb·Δθ*)^eb``, plus ``pb`` if the angle passes through
      zero, from the Q-curve (maths §3) of node k with ``B0 = a[i[k-1]] - a[i[k]]``,
      ``F0 = a[i[k+1]] - a[i[k]]`` and ``B1, F1`` likewise in b (zero vectors
      where a step does not advance that polygon): L terms. ``Δθ = |θ(1) - θ(0)|``
      for the continuous angle θ(t) of ``Q(t)``; ``Δθ*`` is how far θ leaves the
      range between its end values (above plus below); "through zero" is ``Q(t)``
      meeting the positive x-axis for some 0 < t < 1. A zero edge (a duplicated
      vertex) makes an end of the Q-curve vanish; that key's angle is then taken
      as straight, the end being replaced by ``(-r, 0)`` with ``r`` the length of
      the other end (``|Q1|`` if both vanish; no bending if all of Q vanish).

Searches: ``distance`` uses Maes' divide and conquer over the start, exact in
O(mn log n); ``sg`` a dynamic program over (node, entering step) for a start and
closing step, inside a branch and bound over spans of starts (``_sg_search``):
exact, the path of solving every start, in about n² log n time on drawn outlines
(O(m n²) at worst) and O(mn) memory (docs/correspondence.md): ``SG_BYTES_PER_NODE`` a node of the
m × n grid, refused before anything is allocated when that passes ``Matching.max_memory``.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from types import ModuleType

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ...errors import GeometryError
from ...model import ALIGNS, COSTS, Matching, Points
from . import _small_dtw
from ..geometry import centroid, signed_area
from ..memo import Remembered

__all__ = [
    "Correspondence", "work_matrix", "correspond", "naive_correspond", "path_work",
    "is_cyclic_monotone", "correspond_open", "is_open_monotone", "SG_BYTES_PER_NODE", "sg_memory",
    "check_sg_memory", "SearchTooLarge", "forget_correspondences",
]

Pairs = NDArray[np.intp]
"""A correspondence path: ``(L, 2)`` indices ``(i, j)`` into a and b, in path order."""

_DEFAULT = Matching()

SG_BYTES_PER_NODE = 120
"""What the ``sg`` search holds for each node (i, j) of the m × n grid: its cost tables (stretch, 3
float64, and bend, 3 × 3 float64: 96 bytes) and the branch and bound's least energies and steps over
the doubled grid (2 × (8 + 3) bytes), rounded up for the rows and scratch arrays besides (measured
with tracemalloc: 119.2–119.7 bytes a node). The every-start and hinted searches hold less (96 + 3)."""


def sg_memory(m: int, n: int) -> int:
    """Bytes the ``sg`` search of keys of ``m`` and ``n`` vertices holds at its peak (an upper bound to
    within a few rows: what it allocates besides grows as m + n)."""
    return SG_BYTES_PER_NODE * (m + 1) * n


class SearchTooLarge(GeometryError):
    """A correspondence search refused for the memory it would take: the keys or settings are at fault
    (exit code 2), not the drawing of a frame that asked for it."""


def check_sg_memory(m: int, n: int, matching: Matching) -> None:
    """Refuse, before anything is allocated, an ``sg`` search whose tables would pass ``matching.max_memory``
    (:class:`SearchTooLarge`)."""
    need = sg_memory(m, n)
    if need > matching.max_memory:
        raise SearchTooLarge(
            f"the 'sg' correspondence of {m} × {n} vertices needs about {_bytes(need)} for its tables "
            f"({SG_BYTES_PER_NODE} bytes a vertex pair), more than the memory limit of "
            f"{_bytes(matching.max_memory)}; use the 'distance' cost (--cost distance), which needs a few "
            f"MiB, or a higher limit (--max-memory)")


def _bytes(count: int) -> str:
    """``count`` bytes in binary units: ``2.3 GiB``, ``512 MiB``, ``100 KiB``, ``12 B``."""
    for unit, size in (("TiB", 1 << 40), ("GiB", 1 << 30), ("MiB", 1 << 20), ("KiB", 1 << 10)):
        if count >= size:
            return f"{count / size:.3g} {unit}"
    return f"{count} B"


def _kernels() -> ModuleType:
    """The compiled search kernels, imported on first need: numba costs ~0.2 s to import,
    and scenes whose keys agree in vertex count never need it; small searches are done in
    numpy by ``_small_dtw`` (the same answers) while numba is not loaded."""
    from . import _cyclic_dtw

    return _cyclic_dtw


@dataclass(frozen=True, slots=True)
class Correspondence:
    """The chosen closed path and its cost.

    ``pairs (L, 2)`` index the original a and b in path order, ``pairs[0, 0] == 0``;
    ``work`` is the path's cost under the matching asked for; ``reversed`` is True
    when b winds opposite to a and was walked backwards (j steps by -1).
    """

    pairs: Pairs
    work: float
    reversed: bool

    @property
    def balanced(self) -> int:
        """Vertex count ``L`` of both balanced polygons."""
        return int(self.pairs.shape[0])

    def apply(self, a: Points, b: Points) -> tuple[Points, Points]:
        """Both polygons with vertices duplicated along the path: two ``(L, 2)`` arrays."""
        return np.asarray(a)[self.pairs[:, 0]], np.asarray(b)[self.pairs[:, 1]]


def work_matrix(a: Points, b: Points) -> NDArray[np.float64]:
    """``W[i, j] = |a_i - b_j|`` for ``a (m, 2)``, ``b (n, 2)``: ``(m, n)``."""
    return _kernels().distance_matrix(_as_polygon(a, "a"), _as_polygon(b, "b"))


def correspond(a: Points, b: Points, matching: Matching = _DEFAULT) -> Correspondence:
    """The least-cost correspondence of ``a (m, 2)`` and ``b (n, 2)`` over every start.

    Exact for both costs (see the module's docstring for their definitions).
    """
    return _correspond(a, b, matching, exhaustive=False)


def naive_correspond(a: Points, b: Points, matching: Matching = _DEFAULT) -> Correspondence:
    """Reference for ``correspond``: the full dynamic program for every start, O(m n²)
    (for ``sg``, every start and closing step: the search the branch and bound must agree with)."""
    return _correspond(a, b, matching, exhaustive=True)


def path_work(a: Points, b: Points, pairs: ArrayLike, matching: Matching = _DEFAULT, closed: bool = True) -> float:
    """Cost of any path ``pairs (L, 2)`` under ``matching``: what ``correspond`` (``closed``) or
    ``correspond_open`` minimises (open curves always cost distance)."""
    _check_matching(matching)
    if not closed and matching.cost != "distance":
        matching = replace(matching, cost="distance")
    a, b = _aligned(_as_polygon(a, "a"), _as_polygon(b, "b"), matching.align)
    path = np.asarray(pairs)
    if path.ndim != 2 or path.shape[1] != 2 or len(path) == 0:
        raise GeometryError(f"pairs should have shape (L, 2) with L ≥ 1, not {path.shape}")
    if not np.issubdtype(path.dtype, np.integer):
        raise GeometryError(f"pairs should be integer indices, not {path.dtype}")
    if path.min() < 0 or path[:, 0].max() >= len(a) or path[:, 1].max() >= len(b):
        raise GeometryError(f"pairs should index {len(a)} × {len(b)} vertices, "
                         f"not range over {path.min(axis=0).tolist()}..{path.max(axis=0).tolist()}")
    return _aligned_work(a, b, path.astype(np.intp), matching)


def is_cyclic_monotone(pairs: ArrayLike, m: int, n: int, reversed: bool = False) -> bool:
    """Whether ``pairs (L, 2)`` is a closed monotone path winding once round the ``m × n`` grid.

    Each step (the last one closes onto the first pair) advances i by 0 or 1 mod m
    and j by 0 or 1 mod n (by 0 or -1 when ``reversed``), never by nothing; the
    advances add up to exactly m and n, so every vertex of both polygons appears.
    """
    path = np.asarray(pairs)
    if m < 2 or n < 2 or path.ndim != 2 or path.shape[1] != 2 or len(path) == 0:
        return False
    if not np.issubdtype(path.dtype, np.integer):
        return False
    i, j = path[:, 0], path[:, 1]
    if i.min() < 0 or i.max() >= m or j.min() < 0 or j.max() >= n:
        return False
    di = (np.roll(i, -1) - i) % m
    dj = ((j - np.roll(j, -1)) if reversed else (np.roll(j, -1) - j)) % n
    steps_ok = bool(np.all(di <= 1) and np.all(dj <= 1) and np.all(di + dj >= 1))
    return steps_ok and int(di.sum()) == m and int(dj.sum()) == n


def correspond_open(a: Points, b: Points, matching: Matching = _DEFAULT) -> Correspondence:
    """The least-work correspondence of open curves ``a (m, 2)`` and ``b (n, 2)`` (maths §5.7).

    The closed search without its cyclic shift: ends pair with ends, and the path
    is monotone from ``(0, 0)`` to ``(m - 1, n - 1)``. ``b`` is also tried walked
    backwards (``reversed``: ``b``'s last vertex pairs with ``a``'s first), and the
    cheaper is kept. The work is the distance cost after ``matching.align``
    (the Sederberg–Greenwood energy is for closed outlines; ``cost = "sg"`` uses
    distance here too).
    """
    _check_matching(matching)
    matching = replace(matching, cost="distance")
    a, b = _aligned(_as_polygon(a, "a"), _as_polygon(b, "b"), matching.align)
    kernels = _small_dtw if _small_dtw.takes(len(a), len(b), closed=False) else _kernels()
    best: Correspondence | None = None
    for backwards in (False, True):
        walk = np.arange(len(b))[::-1] if backwards else np.arange(len(b))
        work, nodes = kernels.open_search(kernels.distance_matrix(a, np.ascontiguousarray(b[walk])))
        pairs = np.column_stack([nodes[:, 0], walk[nodes[:, 1]]]).astype(np.intp)
        pairs.flags.writeable = False
        if best is None or work < best.work - 1e-12 * max(1.0, abs(best.work)):
            best = Correspondence(pairs, float(work), backwards)
    assert best is not None
    return best


def is_open_monotone(pairs: ArrayLike, m: int, n: int, reversed: bool = False) -> bool:
    """Whether ``pairs (L, 2)`` runs from one end of both curves to the other, each step advancing
    i by 0 or 1 and j by 0 or 1 (by 0 or -1 when ``reversed``), never by nothing."""
    path = np.asarray(pairs)
    if path.ndim != 2 or path.shape[1:] != (2,) or len(path) == 0 or not np.issubdtype(path.dtype, np.integer):
        return False
    i, j = path[:, 0], path[:, 1]
    if reversed:
        j = (n - 1) - j
    di, dj = np.diff(i), np.diff(j)
    ends = i[0] == 0 and j[0] == 0 and i[-1] == m - 1 and j[-1] == n - 1
    return bool(ends and np.all((di >= 0) & (di <= 1) & (dj >= 0) & (dj <= 1) & (di + dj >= 1)))


def _correspond(a: Points, b: Points, matching: Matching, exhaustive: bool) -> Correspondence:
    _check_matching(matching)
    a, b = _as_polygon(a, "a"), _as_polygon(b, "b")
    key = b"|".join((repr((matching, exhaustive, a.shape, b.shape)).encode(), a.tobytes(), b.tobytes()))
    return _found.get(key, lambda: _search(a, b, matching, exhaustive))


_REMEMBERED = 256
"""Correspondences kept, by their keys and matching: a report, its renders, its sheet and its measures all
match the same keys again (a :class:`Correspondence` is read-only, so it is shared)."""
_found: Remembered[Correspondence] = Remembered(_REMEMBERED)


def forget_correspondences() -> None:
    """Forget every correspondence kept, so the next of each is searched again (to time the searches)."""
    _found.clear()


def _search(a: NDArray[np.float64], b: NDArray[np.float64], matching: Matching, exhaustive: bool) -> Correspondence:
    """:func:`_correspond` of checked polygons, searched."""
    a, b = _aligned(a, b, matching.align)
    backwards = _winds_opposite(a, b)
    # b as walked: position k holds vertex walk[k], so a forward step in k is a
    # step of -1 in b when b winds the other way; walk[0] = 0 either way.
    walk = (-np.arange(len(b))) % len(b) if backwards else np.arange(len(b))
    walked_b = np.ascontiguousarray(b[walk])
    work_a, work_b = a, b  # the work is told in the drawing's units
    if matching.cost == "distance":  # searched at unit size: squared distances neither underflow nor overflow
        unit = float(max(np.abs(a).max(), np.abs(b).max())) or 1.0
        a, walked_b = a / unit, walked_b / unit
    small = matching.cost == "distance" and not exhaustive and _small_dtw.takes(len(a), len(b))
    kernels = _small_dtw if small else _kernels()
    if matching.cost == "distance" and not (exhaustive or small):
        from . import _lean_dtw  # the same path as maes_search, in memory n·√m instead of m·n

        _, nodes = _lean_dtw.lean_maes_search(a, walked_b, _lean_dtw.checkpoint_rows(len(a)))
    elif matching.cost == "distance":
        search = kernels.every_start_search if exhaustive else kernels.maes_search
        _, nodes = search(kernels.distance_matrix(a, walked_b))
    else:
        check_sg_memory(len(a), len(b), matching)
        m = matching
        tables = kernels.sg_tables(a, walked_b, m.ks, m.cs, m.es, m.kb, m.eb, m.mb, m.pb)
        if exhaustive:
            _, nodes = kernels.sg_every_start_search(*tables)
        else:
            from ._sg_search import sg_search

            nodes = sg_search(*tables).nodes
    pairs = _pairs_from_nodes(nodes, len(a), walk)
    pairs.flags.writeable = False
    return Correspondence(pairs, _aligned_work(work_a, work_b, pairs, matching), backwards)


def _pairs_from_nodes(nodes: NDArray[np.int64], m: int, walk: NDArray[np.intp]) -> Pairs:
    """Unrolled nodes ``(L + 1, 2)``, end first, as original indices ``(L, 2)``, start first."""
    path = nodes[::-1][:-1]  # start first; the closing node is the start again
    n = len(walk)
    return np.column_stack([path[:, 0] % m, walk[path[:, 1] % n]]).astype(np.intp)


def _aligned_work(a: Points, b: Points, pairs: Pairs, matching: Matching) -> float:
    """Path cost of already aligned polygons (module docstring)."""
    if matching.cost == "distance":
        gap = a[pairs[:, 0]] - b[pairs[:, 1]]
        return float(np.sqrt((gap * gap).sum(axis=1)).sum())
    m = matching
    # A writable int64 copy: a read-only array would be compiled for separately.
    indices = np.array(pairs, dtype=np.int64, order="C", copy=True)
    return float(_kernels().sg_path_energy(a, b, indices, m.ks, m.cs, m.es, m.kb, m.eb, m.mb, m.pb))


def _aligned(a: Points, b: Points, align: str) -> tuple[Points, Points]:
    if align == "centroid":
        return a - centroid(a), b - centroid(b)
    return a, b


def _winds_opposite(a: Points, b: Points) -> bool:
    """True when the signed areas have opposite signs (a zero area counts as either winding)."""
    return bool(float(signed_area(a)) * float(signed_area(b)) < 0.0)


def _as_polygon(points: Points, name: str) -> NDArray[np.float64]:
    """A C-contiguous float64 ``(N, 2)`` copy of ``points``, checked for N ≥ 2 finite vertices.

    Always a writable copy: the kernels would be compiled again for read-only arrays.
    """
    array = np.array(points, dtype=np.float64, order="C", copy=True)
    if array.ndim != 2 or array.shape[1] != 2:
        raise GeometryError(f"polygon {name} should have shape (N, 2), not {array.shape}")
    if array.shape[0] < 2:
        raise GeometryError(f"polygon {name} should have at least 2 vertices, not {array.shape[0]}")
    if not np.all(np.isfinite(array)):
        raise GeometryError(f"polygon {name} has non-finite coordinates")
    return array


def _check_matching(matching: Matching) -> None:
    if matching.cost not in COSTS:
        raise GeometryError(f"matching cost should be one of {', '.join(COSTS)}, not {matching.cost!r}")
    if matching.align not in ALIGNS:
        raise GeometryError(f"matching align should be one of {', '.join(ALIGNS)}, not {matching.align!r}")
    limit = matching.max_memory
    if isinstance(limit, bool) or not isinstance(limit, (int, np.integer)) or limit <= 0:
        raise GeometryError(f"matching max_memory should be a positive number of bytes, not {limit!r}")
