"""Stray: how much of an in-between lies far from both keys (maths §5.16, ``stats``' ``stray_max``).

The *stray* of an in-between is the share of its area farther than ``reach`` (``stats``: 12 % of the
view's larger side) from both keys' drawn areas. Areas are those the closed contours enclose as
drawn, under their fill rule (a stroke's width is not counted).

It is measured on a grid (:mod:`.coverage`) laid over every frame and both keys, of cells at most
``reach / 24`` wide and at most 1/192 of the grid's larger side (1024 cells along it at most). Each
key's area is filled once and grown by the reach: a disc about each cell inside it, and the cells
just past the disc's rim decided by their exact distance to the key's edges. Each in-between is
filled, and the share is that of its cells (their centres) outside both grown keys: a cell's width
over the width of the straying part is the error, a few thousandths on real drawings.

Chosen over exact distances from area-weighted sample points because those cost every sample against
every key edge, while here a frame costs its edges times the rows they span (exact distances only
for a thin ring of cells, once per key), and the answer is deterministic (cell centres, no random
samples).
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from numpy.typing import NDArray

from .coverage import Grid, by_rule, dilate, filled, winding

__all__ = ["Area", "STRAY_REACH", "stray_shares", "stroke_stray_shares"]

Array = NDArray[np.float64]

Area = tuple[Sequence[Array], str]
"""A drawn area: closed contours ``(N_i, 2)`` winding as drawn, and the fill rule (``"nonzero"``, ``"evenodd"``)."""

STRAY_REACH = 0.12
"""``stats``' reach: this share of the view's larger side."""

_PER_REACH = 24  # cells across the reach, at least ...
_PER_SIDE = 192  # ... and across the larger side of everything measured, at least
_MOST = 1024  # cells along the grid's larger side, at most (an in-between flung far makes cells larger)


def stray_shares(frames: Sequence[Area], key0: Area, key1: Area, reach: float) -> Array:
    """The share of each in-between's area ``frames[k]`` lying farther than ``reach`` from both keys'
    areas: ``(T,)`` in [0, 1] (0 for an in-between of no area, or a reach of 0)."""
    out = np.zeros(len(frames))
    grid = _grid([c for area in (*frames, key0, key1) for c in area[0]], reach)
    if grid is None:
        return out
    near = _near(grid, key0, reach) | _near(grid, key1, reach)
    contours = [c for area in frames for c in area[0]]
    layer = np.repeat(np.arange(len(frames)), [len(area[0]) for area in frames])
    turns = winding(grid, contours, layer, len(frames))
    for k, area in enumerate(frames):
        inside = by_rule(turns[k], area[1])
        total = np.count_nonzero(inside)
        if total:
            out[k] = np.count_nonzero(inside & ~near) / total
    return out


def stroke_stray_shares(strokes: Sequence[Sequence[Array]], key0: Area, key1: Area,
                        lines: Sequence[tuple[Array, bool]], reach: float) -> Array:
    """The share of the length of each in-between's open strokes ``strokes[k]`` (``(L_i, 2)`` each) lying
    farther than ``reach`` from both keys: from their areas ``key0``, ``key1`` and their contours ``lines``
    (``(points (N, 2), closed)``, both keys'): ``(T,)`` in [0, 1] (0 for an in-between of no stroke length,
    or a reach of 0). Each edge is read at the middles of pieces at most a cell of the grid of
    :func:`stray_shares` long; a middle is near where its cell is near the areas, else where its exact
    distance to the contours' edges is within the reach."""
    out = np.zeros(len(strokes))
    grid = _grid([c for frame in strokes for c in frame] + [c for area in (key0, key1) for c in area[0]]
                 + [c for c, _ in lines], reach)
    if grid is None:
        return out
    near = _near(grid, key0, reach) | _near(grid, key1, reach)
    drawn = [np.asarray(c, dtype=np.float64).reshape(-1, 2) for c, _ in lines]
    ends = [(c, np.roll(c, -1, axis=0) if shut and len(c) >= 3 else np.vstack([c[1:], c[-1:]]))
            for c, (_, shut) in zip(drawn, lines) if len(c) >= 1]
    a = np.concatenate([e[0] for e in ends]) if ends else np.zeros((0, 2))
    b = np.concatenate([e[1] for e in ends]) if ends else np.zeros((0, 2))
    for k, frame in enumerate(strokes):
        middles, lengths = _pieces_of([np.asarray(c, dtype=np.float64).reshape(-1, 2) for c in frame], grid.cell)
        total = float(lengths.sum())
        if not total > 0:
            continue
        column = np.clip(((middles[:, 0] - grid.x0) / grid.cell).astype(np.int64), 0, grid.nx - 1)
        row = np.clip(((middles[:, 1] - grid.y0) / grid.cell).astype(np.int64), 0, grid.ny - 1)
        close = near[row, column]
        if len(a):
            rest = np.flatnonzero(~close)
            close[rest] = _within(middles[rest], a, b, reach)
        out[k] = float(lengths[~close].sum()) / total
    return out


def _grid(contours: Sequence[Array], reach: float) -> Grid | None:
    """The grid over every finite point of ``contours (L_i, 2)``, cells at most ``reach / 24`` and 1/192 of its
    larger side wide; None where there is no point or no reach."""
    every = [np.asarray(c, dtype=np.float64).reshape(-1, 2) for c in contours]
    points = np.concatenate(every) if every else np.zeros((0, 2))
    points = points[np.all(np.isfinite(points), axis=1)]
    if len(points) == 0 or not reach > 0:
        return None
    (x0, y0), (x1, y1) = points.min(axis=0), points.max(axis=0)
    side = float(max(x1 - x0, y1 - y0))
    return Grid.over((float(x0), float(y0), float(x1), float(y1)), min(reach / _PER_REACH, side / _PER_SIDE), _MOST)


def _pieces_of(lines: Sequence[Array], cell: float) -> tuple[Array, Array]:
    """The middles ``(P, 2)`` and lengths ``(P,)`` of the open polylines' ``lines (L_i, 2)`` edges cut into
    equal pieces at most ``cell`` long (at most 256 an edge)."""
    a = np.concatenate([c[:-1] for c in lines if len(c) >= 2] or [np.zeros((0, 2))])
    b = np.concatenate([c[1:] for c in lines if len(c) >= 2] or [np.zeros((0, 2))])
    keep = np.all(np.isfinite(a), axis=1) & np.all(np.isfinite(b), axis=1)
    a, b = a[keep], b[keep]
    length = np.hypot(*(b - a).T)
    count = np.clip(np.ceil(length / cell), 1, 256).astype(np.int64)
    edge = np.repeat(np.arange(len(a)), count)
    start = np.cumsum(count) - count
    share = (np.arange(int(count.sum())) - np.repeat(start, count) + 0.5) / np.repeat(count, count)
    middles = a[edge] + share[:, None] * (b - a)[edge]
    return middles, (length / count)[edge]


_CHUNK = 1 << 21  # cell-edge distances worked out at once


def _near(grid: Grid, area: Area, reach: float) -> NDArray[np.bool_]:
    """The cells whose centre lies within ``reach`` of ``area``: ``(ny, nx)``.

    The cells within the reach of a cell inside the area surely are; those up to ¾ cell farther are
    measured exactly, by their distance to the area's edges (a point of the area lies within √½ cell
    of a centre inside it, where the area is a cell thick)."""
    inside = filled(grid, *area)
    radius = reach / grid.cell
    near = dilate(inside, radius)
    rows, columns = np.nonzero(dilate(inside, radius + 0.75) & ~near)
    shut = [np.asarray(c, dtype=np.float64) for c in area[0] if len(c) >= 2]
    if len(rows) == 0 or not shut:
        return near
    a = np.concatenate(shut)
    b = np.concatenate([np.roll(c, -1, axis=0) for c in shut])
    centres = np.stack([grid.x0 + (columns + 0.5) * grid.cell, grid.y0 + (rows + 0.5) * grid.cell], axis=1)
    near[rows, columns] = _within(centres, a, b, reach)
    return near


def _within(points: Array, a: Array, b: Array, reach: float) -> NDArray[np.bool_]:
    """Whether each of ``points (P, 2)`` lies within ``reach`` of one of the segments ``a → b`` (``(E, 2)`` each,
    E ≥ 1): ``(P,)``, :data:`_CHUNK` point-segment distances at a time."""
    out = np.zeros(len(points), dtype=bool)
    step = max(1, _CHUNK // len(a))
    for start in range(0, len(points), step):
        out[start:start + step] = _distance(points[start:start + step], a, b) <= reach
    return out


def _distance(points: Array, a: Array, b: Array) -> Array:
    """The distance from each of ``points (P, 2)`` to the nearest of the segments ``a → b`` (``(E, 2)``
    each): ``(P,)``."""
    along = b - a
    length = np.maximum((along * along).sum(axis=1), np.finfo(np.float64).tiny)
    offset = points[:, None, :] - a[None]  # (P, E, 2)
    share = np.clip((offset * along[None]).sum(axis=2) / length[None], 0.0, 1.0)
    gap = offset - share[..., None] * along[None]
    return np.sqrt((gap * gap).sum(axis=2).min(axis=1))
