"""What a drawing covers, sampled on a grid of square cells: filled areas, stroke bands, and reach.

A cell is covered when its centre is: inside the contours under a fill rule (the winding number of
the centre, counted along its row), or within half a stroke's width of a stroke's line (its edges
and joins as polygons, filled the same way). Sampling at cell centres makes every answer a pure
function of the coordinates and the grid, so it is deterministic, and its cost grows with the
edges times the rows they span plus the cells, never with edges times cells. :func:`dilate` grows a
covered set by a disc: the cells whose centres lie within a distance of a covered cell's centre.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np
from numpy.typing import NDArray

__all__ = ["Grid", "winding", "filled", "by_rule", "band", "bands", "dilate"]

Array = NDArray[np.float64]
Mask = NDArray[np.bool_]


@dataclass(frozen=True, slots=True)
class Grid:
    """``ny × nx`` square cells of side ``cell`` from corner ``(x0, y0)`` (y up); row r, column j has its
    centre at ``(x0 + (j + ½)·cell, y0 + (r + ½)·cell)``."""

    x0: float
    y0: float
    cell: float
    nx: int
    ny: int

    @classmethod
    def over(cls, box: tuple[float, float, float, float], cell: float, most: int = 1024) -> Grid:
        """The grid over ``box (x0, y0, x1, y1)`` with cells of side ``cell``, or larger cells where that
        would make more than ``most`` along a side."""
        x0, y0, x1, y1 = box
        side = max(x1 - x0, y1 - y0, 0.0)
        cell = max(cell, side / most, np.finfo(np.float64).tiny)
        return cls(float(x0), float(y0), float(cell), max(1, math.ceil((x1 - x0) / cell)),
                   max(1, math.ceil((y1 - y0) / cell)))


def winding(grid: Grid, contours: Sequence[Array], layer: Sequence[int] | None = None,
            layers: int = 1) -> NDArray[np.int64]:
    """The winding number of every cell centre about the closed ``contours (N_i, 2)``: ``(ny, nx)``;
    with ``layer`` (one index per contour) ``(layers, ny, nx)``, each layer about its own contours."""
    shut = [(np.asarray(c, dtype=np.float64), k) for k, c in enumerate(contours) if len(c) >= 2]
    which = np.zeros(len(contours), dtype=np.int64) if layer is None else np.asarray(layer, dtype=np.int64)
    if not shut:
        turns = np.zeros((layers, grid.ny, grid.nx), dtype=np.int64)
    else:
        a = np.concatenate([c for c, _ in shut])
        b = np.concatenate([np.roll(c, -1, axis=0) for c, _ in shut])
        turns = _winding(grid, a, b, np.repeat(which[[k for _, k in shut]], [len(c) for c, _ in shut]), layers)
    return turns[0] if layer is None else turns


def _polygons(polygons: Array) -> tuple[Array, Array]:
    """The edges ``a → b`` of closed ``polygons (P, K, 2)``, each ``(P·K, 2)``."""
    return polygons.reshape(-1, 2), np.roll(polygons, -1, axis=1).reshape(-1, 2)


def _winding(grid: Grid, a: Array, b: Array, layer: NDArray[np.int64], layers: int) -> NDArray[np.int64]:
    """The winding number of every cell centre about the edges ``a → b`` (``(E, 2)`` each, closed
    contours together) of each layer (``layer (E,)`` in ``[0, layers)``): ``(layers, ny, nx)``."""
    width = grid.nx + 1
    size = layers * grid.ny * width
    low, high = np.minimum(a[:, 1], b[:, 1]), np.maximum(a[:, 1], b[:, 1])
    # rows whose centre y satisfies low <= y < high (half-open, so a vertex on a row counts once)
    first = np.clip(np.ceil((low - grid.y0) / grid.cell - 0.5), 0, grid.ny).astype(np.int64)
    stop = np.clip(np.ceil((high - grid.y0) / grid.cell - 0.5), 0, grid.ny).astype(np.int64)
    spans = np.maximum(stop - first, 0)
    if len(a) == 0 or spans.sum() == 0:
        return np.zeros((layers, grid.ny, grid.nx), dtype=np.int64)
    edge = np.repeat(np.arange(len(a)), spans)
    row = first[edge] + np.arange(spans.sum()) - np.repeat(np.cumsum(spans) - spans, spans)
    y = grid.y0 + (row + 0.5) * grid.cell
    pa, pb = a[edge], b[edge]
    x = pa[:, 0] + (y - pa[:, 1]) * (pb[:, 0] - pa[:, 0]) / (pb[:, 1] - pa[:, 1])
    up = np.where(pb[:, 1] > pa[:, 1], 1.0, -1.0)
    # the crossing is right of the centres of columns j < m: each of them winds by ``up``
    m = np.clip(np.ceil((x - grid.x0) / grid.cell - 0.5), 0, grid.nx).astype(np.int64)
    start = (layer[edge] * grid.ny + row) * width
    steps = np.bincount(start, weights=up, minlength=size) - np.bincount(start + m, weights=up, minlength=size)
    return np.cumsum(np.rint(steps).astype(np.int64).reshape(layers, grid.ny, width), axis=2)[:, :, :-1]


def filled(grid: Grid, contours: Sequence[Array], rule: str = "nonzero") -> Mask:
    """The cells inside the closed ``contours (N_i, 2)`` as drawn (their windings as given) under the
    fill ``rule`` (``"nonzero"`` or ``"evenodd"``): ``(ny, nx)``."""
    return by_rule(winding(grid, contours), rule)


def by_rule(turns: NDArray[np.int64], rule: str) -> Mask:
    """Where winding numbers ``turns`` (any shape) are inside under the fill ``rule``."""
    return (turns % 2 == 1) if rule == "evenodd" else turns != 0


def band(grid: Grid, lines: Sequence[Array], closed: Sequence[bool], width: float) -> Mask:
    """The cells within ``width / 2`` of the polylines ``lines (N_i, 2)`` (closed ones with their closing
    edge; bevel joins, round caps), at least one cell wide: ``(ny, nx)``."""
    return bands(grid, lines, closed, [width] * len(lines), [0] * len(lines), 1)[0]


def bands(grid: Grid, lines: Sequence[Array], closed: Sequence[bool], widths: Sequence[float],
          layer: Sequence[int], layers: int) -> Mask:
    """:func:`band` of each line at its own width, the lines of each layer together: ``(layers, ny, nx)``.

    Each edge is a rectangle, each turn a triangle filling the gap between its edges' rectangles (a
    bevel join), each open end an octagon (a round cap), all wound counter-clockwise, so their union
    is what ``nonzero`` fills: one :func:`winding` pass."""
    pieces: list[Array] = []  # (P, K, 2) polygons of K corners
    owners: list[NDArray[np.int64]] = []
    for points, shut, width, k in zip(lines, closed, widths, layer):
        for polygons in _pieces(np.asarray(points, dtype=np.float64).reshape(-1, 2), bool(shut),
                                0.5 * max(width, grid.cell)):
            pieces.append(polygons)
            owners.append(np.full(polygons.shape[0] * polygons.shape[1], k, dtype=np.int64))
    if not pieces:
        return np.zeros((layers, grid.ny, grid.nx), dtype=bool)
    edges = [_polygons(polygons) for polygons in pieces]
    return _winding(grid, np.concatenate([a for a, _ in edges]), np.concatenate([b for _, b in edges]),
                    np.concatenate(owners), layers) != 0


_OCTAGON = np.stack([np.cos(np.arange(8) * np.pi / 4 + np.pi / 8),
                     np.sin(np.arange(8) * np.pi / 4 + np.pi / 8)], axis=1) / np.cos(np.pi / 8)


def _pieces(points: Array, closed: bool, half: float) -> list[Array]:
    """The counter-clockwise polygons whose union is the band of half-width ``half`` about the line
    ``points (N, 2)``: rectangles ``(E, 4, 2)``, bevel triangles ``(J, 3, 2)``, octagons ``(C, 8, 2)``."""
    if len(points) > 1:  # a zero-length edge has no direction: drop repeated vertices
        points = points[np.r_[True, np.any(points[1:] != points[:-1], axis=1)]]
        if closed and len(points) > 1 and np.all(points[0] == points[-1]):
            points = points[:-1]
    if len(points) < 2:
        return [points[:, None, :] + half * _OCTAGON[None]]
    a, b = (points, np.roll(points, -1, axis=0)) if closed else (points[:-1], points[1:])
    along = b - a
    normal = half * np.stack([-along[:, 1], along[:, 0]], axis=1) / np.hypot(along[:, 0], along[:, 1])[:, None]
    out = [np.stack([a - normal, b - normal, b + normal, a + normal], axis=1)]
    # at vertex i the edge before is i - 1 (closed: cyclically), the one after is i
    inner = np.arange(len(points)) if closed else np.arange(1, len(points) - 1)
    if len(inner):
        vertex, n1, n2 = points[inner], normal[inner - 1], normal[inner % len(normal)]
        left = (n1[:, 0] * n2[:, 1] - n1[:, 1] * n2[:, 0]) > 0  # turning left: the gap is on the right
        side = np.where(left, -1.0, 1.0)[:, None]
        triangles = np.stack([vertex, vertex + side * n1, vertex + side * n2], axis=1)
        out.append(np.where(left[:, None, None], triangles, triangles[:, ::-1]))
    if not closed:
        out.append(points[[0, -1], None, :] + half * _OCTAGON[None])
    return out


def dilate(mask: Mask, radius: float) -> Mask:
    """``mask (ny, nx)`` grown by a disc: the cells whose centre lies within ``radius`` cells of a set
    cell's centre: ``(ny, nx)``."""
    reach = math.floor(radius)
    if reach <= 0 or not mask.any():
        return mask.copy()
    ny, nx = mask.shape
    # running counts along each row: a cell sees a set cell within w columns when the count rises
    counts = np.zeros((ny, nx + 1), dtype=np.int64)
    counts[:, 1:] = np.cumsum(mask, axis=1)
    rows: dict[int, Mask] = {}
    out = np.zeros_like(mask)
    for dy in range(-min(reach, ny - 1), min(reach, ny - 1) + 1):
        w = math.floor(math.sqrt(max(radius * radius - dy * dy, 0.0)))
        if w not in rows:
            columns = np.arange(nx)
            rows[w] = counts[:, np.minimum(columns + w + 1, nx)] > counts[:, np.maximum(columns - w, 0)]
        grown = rows[w]
        if dy >= 0:
            out[dy:] |= grown[:ny - dy]
        else:
            out[:ny + dy] |= grown[-dy:]
    return out
