"""Dash patterns between keys: lengths and offset blended linearly, and where on a closed contour they start.

Two patterns of different counts are each repeated to their least common count first (a pattern
repeated is the same pattern). A key without dashes blends as the other key's pattern with its gaps
closed (each dash as long as its dash and gap together, each gap 0), which draws a solid stroke:
between the keys the gaps open from nothing (or close up) while the period stays the same.

A closed contour's pattern starts at its key's first vertex, which need not be vertex 0 of the balanced
contour the in-betweens are made of: between keys the start slides, as a share of the perimeter, from
where the first key's first vertex lies to where the second key's lies (the shorter way round), so that
the dashes move with the outline and land on each key's own. Balancing's repeated vertices are dropped
before dashing (skia would count each edge of no length as a dash of its own).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

from ..model import Dash

__all__ = ["MAX_BLENDED_COUNT", "closed_up", "blend_dashes", "start_share", "starting_at", "without_repeats"]

MAX_BLENDED_COUNT = 256
"""Lengths of a blended pattern at most; two patterns whose common count is larger blend as the first
repeated to this count against the second's own (the pattern then slips a little between the keys)."""


def closed_up(dash: Dash) -> Dash:
    """``dash`` with every gap closed into the dash before it: the same period, drawn solid."""
    lengths = dash.lengths
    merged: list[float] = []
    for i in range(0, len(lengths), 2):
        merged += [lengths[i] + lengths[i + 1], 0.0]
    return Dash(tuple(merged), dash.offset)


def _repeated(lengths: tuple[float, ...], count: int) -> np.ndarray:
    """``lengths`` repeated to ``count`` entries, ``(count,)``."""
    return np.resize(np.asarray(lengths, dtype=np.float64), count)


def blend_dashes(d0: Dash | None, d1: Dash | None, t: ArrayLike) -> list[Dash | None]:
    """The dash pattern at each of ``t (T,)`` between keys dashed ``d0`` and ``d1`` (``None``: solid)."""
    t = np.atleast_1d(np.asarray(t, dtype=np.float64))
    if d0 == d1:
        return [d0] * len(t)
    a = closed_up(d1) if d0 is None else d0  # type: ignore[arg-type]
    b = closed_up(d0) if d1 is None else d1  # type: ignore[arg-type]
    count = math.lcm(len(a.lengths), len(b.lengths))
    if count > MAX_BLENDED_COUNT:
        count = max(len(a.lengths), len(b.lengths))
    la, lb = _repeated(a.lengths, count), _repeated(b.lengths, count)
    lengths = np.maximum((1.0 - t)[:, None] * la + t[:, None] * lb, 0.0)  # (T, count)
    offsets = (1.0 - t) * a.offset + t * b.offset
    out: list[Dash | None] = [Dash(tuple(float(v) for v in row), float(o)) for row, o in zip(lengths, offsets)]
    return [d0 if x == 0.0 else d1 if x == 1.0 else o for x, o in zip(t.tolist(), out)]


def _shares(points: np.ndarray) -> np.ndarray:
    """Each vertex of the closed contour ``points (L, 2)`` as its arc length from vertex 0 over the perimeter,
    ``(L,)`` in [0, 1) (all 0 for a contour of no length)."""
    edges = np.hypot(*np.diff(np.vstack([points, points[:1]]), axis=0).T)
    total = float(edges.sum())
    if not (total > 0 and math.isfinite(total)):
        return np.zeros(len(points))
    return np.concatenate([[0.0], np.cumsum(edges[:-1])]) / total


def start_share(k0: np.ndarray, k1: np.ndarray, first0: np.ndarray, first1: np.ndarray, now: np.ndarray,
                t: float) -> float:
    """Where the pattern of a closed contour starts at ``t`` in [0, 1]: a share of the perimeter of ``now``
    ``(L, 2)`` (the in-between of the balanced ``k0`` and ``k1``, ``(L, 2)`` each), from its vertex 0. The
    keys' own first vertices ``first0``, ``first1`` ``(2,)`` are found among the balanced ones."""
    i0 = int(np.argmin(np.hypot(*(k0 - first0).T)))
    i1 = int(np.argmin(np.hypot(*(k1 - first1).T)))
    shares = _shares(now)
    a, b = float(shares[i0]), float(shares[i1])
    b = a + ((b - a + 0.5) % 1.0 - 0.5)  # the shorter way round
    return ((1.0 - t) * a + t * b) % 1.0


def starting_at(points: np.ndarray, share: float, reverse: bool) -> np.ndarray:
    """The closed contour ``points (L, 2)`` from the point ``share`` of its perimeter along (a vertex put
    there), drawn reversed when ``reverse``: ``(L or L + 1, 2)``."""
    if share == 0.0 or len(points) < 2:
        return points[::-1] if reverse else points
    shares = _shares(points)
    i = int(np.searchsorted(shares, share, side="right")) - 1
    edge_end = points[(i + 1) % len(points)]
    following = shares[i + 1] if i + 1 < len(points) else 1.0
    span = following - shares[i]
    u = (share - shares[i]) / span if span > 0 else 0.0
    if u <= 0.0:
        rolled = np.roll(points, -i, axis=0)
    else:
        cut = points[i] + u * (edge_end - points[i])
        rolled = np.vstack([cut[None], points[i + 1:], points[:i + 1]])
    if reverse:  # from the cut, the other way round
        rolled = np.vstack([rolled[:1], rolled[:0:-1]])
    return rolled


def without_repeats(points: np.ndarray, closed: bool) -> np.ndarray:
    """``points (L, 2)`` without consecutive repeats (nor, ``closed``, a last vertex repeating the first):
    the copies balancing puts on a vertex are edges of no length, which skia's dashing would count as
    dashes of their own."""
    if len(points) < 2:
        return points
    kept = points[np.concatenate([[True], np.any(points[1:] != points[:-1], axis=1)])]
    while closed and len(kept) > 1 and np.all(kept[-1] == kept[0]):
        kept = kept[:-1]
    return kept
