"""Dash patterns of a run of frames as one array the vector files key: the same count of lengths in
every frame, so that players interpolate them (Lottie's stroke ``d``, SVG's ``stroke-dasharray``).

Each frame's pattern is repeated to the least common count of the run's patterns; a frame drawn solid
amid dashed ones takes its nearest dashed frame's pattern with the gaps closed (as the paint blend
does between a solid key and a dashed one, :mod:`..core.dashes`), which draws solid. A file's contour
starts at its vertex 0 as drawn, where the raster's starts where the pattern does (it slides between the
keys' first vertices): each contour's offset is moved on by the arc length from the start to its vertex 0, and an
open contour whose pattern starts at its last vertex has its pattern read backwards. The pattern's seam
on a closed contour (where a dash is cut short) is then at the file's vertex 0.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from ..core.dashes import closed_up
from ..errors import OptionError
from ..model import Dash, Paint

__all__ = ["MAX_DASH_LENGTHS", "dash_rows", "contour_dashes"]

MAX_DASH_LENGTHS = 64
"""Lengths of one run's keyed pattern at most (players read every one as a property of its own)."""


def dash_rows(paints: list[Paint], scale: float, element: str) -> NDArray[np.float64] | None:
    """Per frame, the dash lengths then the offset, in pixels (``scale`` per scene unit): ``(F, C + 1)``;
    None when no frame is dashed. Refused (naming ``element``) when the common count is over
    :data:`MAX_DASH_LENGTHS`."""
    dashes = [p.dash for p in paints]
    present = [i for i, d in enumerate(dashes) if d is not None]
    if not present:
        return None
    count = math.lcm(*(len(dashes[i].lengths) for i in present))  # type: ignore[union-attr]
    if count > MAX_DASH_LENGTHS:
        raise OptionError(f"element {element!r}: its dash patterns need {count} lengths in common to be keyed, "
                          f"over the vector formats' {MAX_DASH_LENGTHS}; render a video or PNG frames", "format")
    rows = np.empty((len(dashes), count + 1))
    for f, dash in enumerate(dashes):
        if dash is None:
            nearest = dashes[min(present, key=lambda i: abs(i - f))]
            dash = closed_up(nearest)  # type: ignore[arg-type]
        rows[f, :count] = np.resize(np.asarray(dash.lengths, dtype=np.float64), count)
        rows[f, count] = dash.offset
    return rows * scale


def _arcs(points: NDArray[np.float64], closed: bool) -> tuple[NDArray[np.float64], float]:
    """Each vertex's arc length from vertex 0 along ``points (L, 2)``, ``(L,)``, and the whole length."""
    ring = np.vstack([points, points[:1]]) if closed else points
    edges = np.hypot(*np.diff(ring, axis=0).T)
    return np.concatenate([[0.0], np.cumsum(edges)])[:len(points)], float(edges.sum())


def _backwards(row: NDArray[np.float64], length: float) -> NDArray[np.float64]:
    """A pattern row (lengths then offset) laid from a contour's last vertex, as the same dashes laid from
    its first vertex on a contour ``length`` long: the lengths reversed (a dash first) and the offset moved."""
    lengths, offset = row[:-1], float(row[-1])
    reverse = lengths[::-1]  # gap, dash, …, gap, dash: turned to dash first, its gap last
    turned = np.concatenate([reverse[1:], reverse[:1]])
    return np.concatenate([turned, [-offset - length - reverse[0]]])


def contour_dashes(rows: NDArray[np.float64], drawn: list[NDArray[np.float64]], starts: NDArray[np.float64],
                   flips: tuple[bool, ...], closed: tuple[bool, ...]) -> tuple[NDArray[np.float64], ...]:
    """Per contour, its own ``(F, C + 1)`` pattern rows for a file drawing it from its vertex 0: ``rows``
    ``(F, C + 1)`` (:func:`dash_rows`), the contours as drawn ``(F, L_i, 2)`` pixels (reversed where
    ``flips`` says), ``starts (F, n)`` where the raster starts each pattern (``ShapeAt.dash_starts``)."""
    out = []
    for i, (points, flip, shut) in enumerate(zip(drawn, flips, closed)):
        own = rows.copy()
        for f in range(len(rows)):
            share = float(starts[f, i])
            if shut and share:
                balanced = points[f][::-1] if flip else points[f]
                arcs, total = _arcs(balanced, True)
                at = share * total
                # the pattern runs on from the start to the drawn vertex 0, this far along the drawn direction
                own[f, -1] += (at - arcs[-1]) % total if flip else (total - at) % total
            elif not shut and (share == 1.0) != flip:  # the pattern starts at the end drawn last
                own[f] = _backwards(rows[f], _arcs(points[f], False)[1])
        out.append(own)
    return tuple(out)
