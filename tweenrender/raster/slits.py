"""Slits taken out before a fill is drawn.

A contour that walks an edge there and back (two pieces or a hole joined into one contour, maths
§5.17) encloses nothing along that edge, but an antialiasing rasteriser covers each of the two
coincident edges on its own and leaves a faint seam. Drawn as the loops the slit joins, the fill is
the same (every winding number is kept) and has no seam.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

__all__ = ["unslit"]

Array = NDArray[np.float64]


def unslit(points: Array) -> list[Array]:
    """Closed contour ``points (N, 2)`` split at every edge it walks there and back (exactly, the
    same two vertices), into the loops it joins: a list of ``(N_k, 2)`` arrays; ``[points]`` unchanged
    where it has none."""
    if len(points) < 8:  # two loops of three joined by a slit walked both ways take eight
        return [points]
    keep = np.any(points != np.roll(points, 1, axis=0), axis=1)  # repeated vertices once
    distinct = points[keep] if keep.any() else points[:1]
    if len(distinct) < 4 or len(np.unique(distinct, axis=0)) == len(distinct):
        return [points]
    out: list[Array] = []
    pending = [distinct]
    while pending:
        loop = pending.pop()
        cut = _slit_in(loop)
        if cut is None:
            out.append(loop)
            continue
        i, j = cut  # edge i → i + 1 walked back as j → j + 1
        n = len(loop)
        inner = loop[i + 1:j]
        outer = np.concatenate([loop[:i + 1], loop[j + 2:]]) if j + 2 <= n else loop[(j + 2) % n:i + 1]
        pending.extend(part for part in (outer, inner) if len(part) >= 3)
    return out


def _slit_in(loop: Array) -> tuple[int, int] | None:
    """The first edge ``i → i+1`` of closed ``loop (N, 2)`` that it walks back later as ``j → j+1``
    (``i < j``), or None."""
    n = len(loop)
    ahead = np.roll(loop, -1, axis=0)
    seen: dict[bytes, int] = {}
    for k in range(n):
        seen.setdefault(loop[k].tobytes() + ahead[k].tobytes(), k)
    for j in range(n):
        i = seen.get(ahead[j].tobytes() + loop[j].tobytes())
        if i is not None and i < j:
            return i, j
    return None
