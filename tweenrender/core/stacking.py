"""Paint order between keys that stack their elements differently (the stacking switch of docs/artwork.md).

Every key of a drawing knows its element's place in that drawing's paint order (``Key.layer``).
At a key the scene is painted in that key's order. Between two keys whose orders differ the
order switches once, at the ``t = k / 32`` (``0 < k < 32``) of the segment where the elements
that change places overlap least: the sum, over every pair of shapes whose order differs and shows
(:func:`order_shows`: not two of one opaque colour), of the area where both are drawn. Ties go to
the t nearest 0.5. The areas are counted on a grid of :data:`GRID` × :data:`GRID` points over the
pair's common bounding box, with each shape's own fill rule and windings (strokes as the points
within half their width of the outline), so the switch does not depend on the frame rate, the
picture's size or how frames are split into chunks.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Sequence

import numpy as np
from numpy.typing import NDArray

from ..model import Color, Shape
from .timing.timeline import ShapeAt

__all__ = ["SWEEP", "GRID", "Switch", "layered", "key_order", "swapped_pairs", "plain_ink", "order_shows", "coverage",
           "overlap_area", "choose_switch", "stacking_plan", "order_at", "order_at_key"]

Array = NDArray[np.float64]
SWEEP = np.arange(1, 32) / 32.0
"""The t of a segment where the order may switch (never at a key)."""
GRID = 48


@dataclass(frozen=True, slots=True)
class Switch:
    """Where the paint order changes between keys at ``start`` and ``end`` seconds.

    ``before`` and ``after`` are the keys' orders (shape indices, painted first to last); ``t`` the
    fraction of the segment from which ``after`` is painted, ``time`` the same in seconds;
    ``areas`` the summed overlap at each t of :data:`SWEEP`; ``pairs`` the shapes that change places.
    """

    start: float
    end: float
    t: float
    before: tuple[int, ...]
    after: tuple[int, ...]
    pairs: tuple[tuple[int, int], ...]
    areas: tuple[float, ...]

    @property
    def time(self) -> float:
        return self.start + self.t * (self.end - self.start)


def layered(shapes: Sequence[Shape]) -> bool:
    """Whether any key knows its place in a drawing's paint order (a scene of whole drawings)."""
    return any(key.layer is not None for shape in shapes for key in shape.keys)


def key_order(shapes: Sequence[Shape], time: float) -> tuple[int, ...]:
    """The paint order at a key ``time``: the shapes shown there by their ``layer``, every other shape
    put right after the shape it follows in the scene's order (or first)."""
    shown = []
    for index, shape in enumerate(shapes):
        for key in shape.keys:
            if key.time == time and not key.hidden and key.layer is not None:
                shown.append((key.layer, index))
    order = [index for _, index in sorted(shown)]
    placed = set(order)
    cursor = -1
    for index in range(len(shapes)):
        if index in placed:
            cursor = order.index(index)
        else:
            order.insert(cursor + 1, index)
            cursor += 1
    return tuple(order)


def swapped_pairs(before: Sequence[int], after: Sequence[int]) -> list[tuple[int, int]]:
    """Pairs ``(a, b)`` painted a-below-b in ``before`` and b-below-a in ``after``."""
    rank = {s: i for i, s in enumerate(after)}
    return [(a, b) for i, a in enumerate(before) for b in before[i + 1:] if rank[a] > rank[b]]


def plain_ink(at: ShapeAt) -> Color | None:
    """The one opaque colour ``at`` draws everything in (fill and stroke alike, at full opacity, no gradient,
    pattern, mask nor cross-fade), else None."""
    paint = at.paint
    if paint.opacity != 1.0 or at.fade is not None or at.masks or any(
            p is not None for p in (paint.gradient, paint.stroke_gradient, paint.pattern, paint.stroke_pattern)):
        return None
    drawn = {colour for colour in (paint.fill, paint.stroke if paint.stroke_width > 0 else None)
             if colour is not None and colour[3] > 0}
    return drawn.pop() if len(drawn) == 1 and next(iter(drawn))[3] == 255 else None


def order_shows(a: ShapeAt, b: ShapeAt) -> bool:
    """Whether painting ``a`` over ``b`` may look otherwise than ``b`` over ``a``: not when either draws nothing,
    nor when both draw one opaque colour, the same (source-over of one opaque colour is symmetric)."""
    if not (a.visible and a.paint.visible and b.visible and b.paint.visible):
        return False
    ink = plain_ink(a)
    return ink is None or ink != plain_ink(b)


def _winding(points: Array, polygon: Array) -> NDArray[np.int64]:
    """The winding number of ``polygon (N, 2)`` about each of ``points (P, 2)``: ``(P,)``."""
    x, y = points[:, 0:1], points[:, 1:2]
    x0, y0 = polygon[:, 0], polygon[:, 1]
    x1, y1 = np.roll(x0, -1), np.roll(y0, -1)
    side = (x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)  # (P, N): > 0 where the point is left of the edge
    up = (y0 <= y) & (y1 > y) & (side > 0)
    down = (y0 > y) & (y1 <= y) & (side < 0)
    return up.sum(axis=1) - down.sum(axis=1)


def _near(points: Array, polyline: Array, closed: bool, reach: float) -> NDArray[np.bool_]:
    """Whether each of ``points (P, 2)`` lies within ``reach`` of the polyline ``(N, 2)``: ``(P,)``."""
    starts = polyline if closed else polyline[:-1]
    ends = np.roll(polyline, -1, axis=0) if closed else polyline[1:]
    if len(starts) == 0:
        return np.hypot(*(points - polyline[0]).T) <= reach
    edge = ends - starts
    length2 = np.maximum((edge * edge).sum(axis=1), 1e-300)
    s = np.clip(((points[:, None] - starts[None]) * edge[None]).sum(axis=-1) / length2, 0.0, 1.0)
    foot = starts[None] + s[..., None] * edge[None]
    return (np.hypot(*(foot - points[:, None]).transpose(2, 0, 1)) <= reach).any(axis=1)


def coverage(at: ShapeAt, fill_rule: str, points: Array, stroke_width: float) -> NDArray[np.bool_]:
    """Where the shape drawn as ``at`` covers each of ``points (P, 2)`` (scene units): ``(P,)``.

    ``stroke_width`` in scene units (0: no stroke)."""
    covered = np.zeros(len(points), dtype=bool)
    if not at.visible:
        return covered
    contours = [c[::-1] if at.reversed and at.reversed[i] else c for i, c in enumerate(at.contours)]
    if at.paint.fill is not None:
        winding = np.zeros(len(points), dtype=np.int64)
        for c in contours:
            if len(c) >= 3:
                winding += _winding(points, c)
        covered |= (winding % 2 == 1) if fill_rule == "evenodd" else (winding != 0)
    if at.paint.stroke is not None and stroke_width > 0:
        for c, shut in zip(contours, at.closed):
            if len(c):
                covered |= _near(points, c, shut, stroke_width / 2)
    return covered


def _box(at: ShapeAt, reach: float) -> Array | None:
    """``[[xmin, ymin], [xmax, ymax]]`` of what the shape draws, or None."""
    if not at.visible or not at.contours:
        return None
    every = np.concatenate(at.contours)
    if not np.all(np.isfinite(every)):
        return None
    return np.array([every.min(axis=0) - reach, every.max(axis=0) + reach])


def overlap_area(a: ShapeAt, a_rule: str, a_width: float, b: ShapeAt, b_rule: str, b_width: float) -> float:
    """The area (scene units²) where both shapes draw, counted on a :data:`GRID`² grid over their common box."""
    box_a, box_b = _box(a, a_width / 2), _box(b, b_width / 2)
    if box_a is None or box_b is None:
        return 0.0
    low, high = np.maximum(box_a[0], box_b[0]), np.minimum(box_a[1], box_b[1])
    if np.any(high <= low):
        return 0.0
    cells = (np.arange(GRID) + 0.5) / GRID
    xs, ys = np.meshgrid(low[0] + cells * (high[0] - low[0]), low[1] + cells * (high[1] - low[1]))
    points = np.column_stack([xs.ravel(), ys.ravel()])
    both = coverage(a, a_rule, points, a_width) & coverage(b, b_rule, points, b_width)
    return float(both.sum() * np.prod(high - low) / GRID**2)


def choose_switch(areas: Array) -> float:
    """The t of :data:`SWEEP` with the least of ``areas (31,)``; ties to the t nearest 0.5."""
    least = np.flatnonzero(areas <= areas.min() * (1 + 1e-9) + 1e-300)
    return float(SWEEP[least[np.argmin(np.abs(SWEEP[least] - 0.5))]])


def stacking_plan(shapes: Sequence[Shape], shapes_at: Callable[[int, Array], list[ShapeAt]]) -> tuple[Switch, ...]:
    """Every switch of paint order of a scene: one per pair of consecutive key times whose orders differ.

    ``shapes_at(i, times)`` gives shape ``i`` at ``times (T,)`` seconds as it is drawn.
    """
    times = sorted({key.time for shape in shapes for key in shape.keys if key.layer is not None})
    plan = []
    for start, end in zip(times, times[1:]):
        before, after = key_order(shapes, start), key_order(shapes, end)
        if before == after:
            continue
        pairs = swapped_pairs(before, after)
        sweep = start + SWEEP * (end - start)
        involved = sorted({s for pair in pairs for s in pair})
        drawn = {s: shapes_at(s, sweep) for s in involved}
        areas = np.zeros(len(SWEEP))
        for k in range(len(SWEEP)):
            for a, b in pairs:
                at_a, at_b = drawn[a][k], drawn[b][k]
                if order_shows(at_a, at_b):
                    areas[k] += overlap_area(at_a, _rule(shapes[a], at_a), _width(shapes[a], at_a),
                                             at_b, _rule(shapes[b], at_b), _width(shapes[b], at_b))
        plan.append(Switch(start, end, choose_switch(areas), before, after, tuple(pairs), tuple(areas.tolist())))
    return tuple(plan)


def _rule(shape: Shape, at: ShapeAt) -> str:
    return (at.key.fill_rule if at.key is not None else None) or shape.fill_rule


def _width(shape: Shape, at: ShapeAt) -> float:
    """The stroke width in scene units (widths in pixels, of TOML shapes, are not counted)."""
    return at.paint.stroke_width if shape.stroke_scales and at.paint.stroke is not None else 0.0


def order_at_key(shapes: Sequence[Shape], time: float) -> tuple[int, ...] | None:
    """The paint order at ``time`` seconds where it is a key time of the drawings, without the plan: what
    :func:`order_at` gives with it, since every switch falls strictly between two key times (the keys'
    own order there, or the scene's where no two keys' orders differ and so there is no switch); None at
    any other time."""
    times = sorted({key.time for shape in shapes for key in shape.keys if key.layer is not None})
    if time not in times:
        return None
    if len({key_order(shapes, t) for t in times}) == 1:
        return tuple(range(len(shapes)))
    return key_order(shapes, time)


def order_at(plan: Sequence[Switch], shapes: Sequence[Shape], time: float) -> tuple[int, ...]:
    """The paint order at ``time`` seconds: the scene's order, unless ``plan`` says otherwise."""
    if not plan:
        return tuple(range(len(shapes)))
    for switch in plan:
        if switch.start <= time <= switch.end:
            return switch.before if time < switch.time else switch.after
    times = sorted({key.time for shape in shapes for key in shape.keys if key.layer is not None})
    settled = max((t for t in times if t <= time), default=times[0])
    return key_order(shapes, settled)
