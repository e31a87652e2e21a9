"""Intrinsic paths (Sederberg, Gao, Wang, Mu, SIGGRAPH 1993; maths §5.5).

A polygon is described by what it is made of rather than where it stands: its
edge lengths ``L_i`` and the turning angle ``θ_i`` at each vertex (from edge
``i - 1`` to edge ``i``). At ``t`` each length is ``(1-t)·L0_i + t·L1_i`` and each
turning angle ``θ0_i + t·Δθ_i``, ``Δθ_i`` its shorter change; the outline is
walked from vertex 0 with edge 0's heading turned by its own change (taken on
the branch nearest the shape's best-fit rotation φ, maths §5.2, so that a half
turn goes the way the whole shape goes).

The walk rarely closes. As the paper does, the lengths are then tweaked by the
``S_i`` of least ``Σ S_i² / w_i`` that closes it, ``Σ (L_i + S_i)·u_i = 0`` with
``u_i`` the edges' directions — two linear constraints, solved in closed form
with a 2 × 2 system. The paper's weights (``closure="paper"``) are
``w_i = max(|L0_i - L1_i|, L_tol)²`` with ``L_tol = 10⁻⁴ · max_i |L0_i - L1_i|``:
edges whose length does not change keep it, and the whole closing error lands
on the edges that do. ``closure="length"`` weighs by ``w_i = L_i(t)²`` instead,
which spreads the error over every edge in proportion to its length. The result
is placed so that its vertex mean moves on a straight line between the keys'.

Rigid motions are exact at every t (every length and angle is kept, the walk
closes by itself). Degenerate keys do not raise and give no NaN: a zero-length
edge takes the heading of the edge before it (so its turn is 0); both keys with
all vertices at one point move on straight lines, one such key takes the
other's directions; when the edge directions are all
parallel the closing system is solved by least squares and any remaining gap
is left to the last edge.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..angles import headings, wrap
from ..geometry import best_fit_rotation, centroid, edge_lengths
from .paths import as_times, linear

__all__ = ["CLOSURES", "intrinsic", "closure_tweak"]

Array = NDArray[np.float64]

CLOSURES: tuple[str, ...] = ("paper", "length")
_TOLERANCE = 1e-4  # the paper's L_tol, relative to the largest change of an edge's length


def intrinsic(k0: Array, k1: Array, t: ArrayLike, closure: str = "paper") -> Array:
    """Intrinsic inbetweens of corresponding keys ``(N, 2)`` at ``t (T,)``: ``(T, N, 2)``."""
    return _walk(k0, k1, t, closure)[0]


def closure_tweak(k0: Array, k1: Array, t: ArrayLike, closure: str = "paper") -> Array:
    """How much closing the walk changed the lengths at each ``t (T,)``: ``Σ|S_i| / Σ L_i(t)``, ``(T,)``."""
    return _walk(k0, k1, t, closure)[1]


def _filled_headings(points: Array) -> Array | None:
    """Edge headings ``(N,)``, a zero-length edge taking the heading of the edge before it;
    None when every edge has zero length."""
    angle = headings(points)
    known = np.flatnonzero(~np.isnan(angle))
    if len(known) == 0:
        return None
    # each edge takes the last known heading at or before it (cyclically)
    n = len(angle)
    index = np.arange(n)
    last = np.maximum.accumulate(np.where(np.isnan(angle), -1, index))
    last = np.where(last < 0, known[-1], last)
    return angle[last]


def _walk(k0: Array, k1: Array, t: ArrayLike, closure: str) -> tuple[Array, Array]:
    if closure not in CLOSURES:
        raise ValueError(f"unknown closure {closure!r}; expected one of {', '.join(CLOSURES)}")
    k0 = np.asarray(k0, dtype=np.float64)
    k1 = np.asarray(k1, dtype=np.float64)
    t = as_times(t)
    h0, h1 = _filled_headings(k0), _filled_headings(k1)
    if h0 is None and h1 is None:
        return linear(k0, k1, t), np.zeros(len(t))
    # a key shrunk to one point has no directions: it takes the other key's (the shape grows)
    h0 = h1 if h0 is None else h0
    h1 = h0 if h1 is None else h1
    turn0 = wrap(h0 - np.roll(h0, 1))  # θ at each vertex, from edge i - 1 to edge i
    turn1 = wrap(h1 - np.roll(h1, 1))
    change = wrap(turn1 - turn0)
    phi = float(best_fit_rotation(k0, k1))
    first = phi + wrap(h1[0] - h0[0] - phi)  # edge 0's own change, on the branch nearest φ

    tt = t[:, None]
    turning = turn0 + tt * change  # (T, N)
    turning[:, 0] = 0.0
    heading = h0[0] + tt * first + np.cumsum(turning, axis=1)  # (T, N)
    direction = np.stack([np.cos(heading), np.sin(heading)], axis=-1)  # (T, N, 2)

    l0, l1 = edge_lengths(k0), edge_lengths(k1)
    lengths = (1.0 - tt) * l0 + tt * l1  # (T, N)
    if closure == "paper":
        spread = np.abs(l0 - l1)
        largest = float(spread.max())
        weight = np.broadcast_to(np.maximum(spread, _TOLERANCE * largest) ** 2 if largest > 0
                                 else np.ones_like(spread), lengths.shape)
    else:
        weight = lengths ** 2
    gap = np.einsum("tn,tnk->tk", lengths, direction)  # (T, 2): where the walk ends
    system = np.einsum("tn,tni,tnj->tij", weight, direction, direction)  # (T, 2, 2)
    multiplier = np.stack([np.linalg.lstsq(m, -g, rcond=None)[0] for m, g in zip(system, gap)])
    tweak = weight * np.einsum("tnk,tk->tn", direction, multiplier)  # (T, N)

    steps = (lengths + tweak)[..., None] * direction
    frames = np.concatenate([np.zeros((len(t), 1, 2)), np.cumsum(steps[:, :-1], axis=1)], axis=1)
    center = (1.0 - tt) * centroid(k0) + tt * centroid(k1)
    frames += (center - frames.mean(axis=1))[:, None, :]
    total = lengths.sum(axis=1)
    size = np.divide(np.abs(tweak).sum(axis=1), total, out=np.zeros(len(t)), where=total > 0)
    return frames, size
