"""Gradient fills between keys: stops blended in OKLab, geometry carried by the element's motion.

A key's gradient is re-expressed relative to its element's bounding box at that key
(``R = B⁻¹ · M``, with ``B`` the map of the unit square onto the box); an inbetween takes the
blend of the two keys' relative gradients through its own bounding box, so the gradient moves,
turns and stretches with the element and is each key's own gradient at its key. A plain colour
blends as a gradient of that one colour, and a key without fill as the other key's gradient at alpha 0
(each stop's alpha times the other key's share, as a plain colour blends with none); gradients of different
kinds (linear, radial) or spreads take the nearer key's. Gradient strokes blend the same way, with the stroke's colour as a key's plain colour.
Patterns (and pictures) are carried by the element's box likewise, the second key's over the first's by ``t``
(a key without one: its plain colour).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from numpy.typing import NDArray

from ..model import Color, Gradient, Paint, Pattern
from .paint import blend_stop_colours

__all__ = ["Box", "box_of", "blend_gradient", "blend_stroke_gradient", "carry_pattern", "color_at", "colors_at"]

Box = tuple[float, float, float, float]
"""``(xmin, ymin, xmax, ymax)`` in world units."""
_FLAT = 1e-12


def box_of(contours: list[NDArray[np.float64]]) -> Box:
    """The bounding box of the contours ``(N_i, 2)``."""
    every = np.concatenate(contours)
    (x0, y0), (x1, y1) = every.min(axis=0), every.max(axis=0)
    return float(x0), float(y0), float(x1), float(y1)


def _frame(box: Box) -> NDArray[np.float64] | None:
    """The 3x3 map of the unit square onto ``box``, or None for a flat box."""
    x0, y0, x1, y1 = box
    w, h = x1 - x0, y1 - y0
    if w <= _FLAT * max(1.0, abs(x0), abs(x1)) or h <= _FLAT * max(1.0, abs(y0), abs(y1)):
        return None
    return np.array([[w, 0.0, x0], [0.0, h, y0], [0.0, 0.0, 1.0]])


def _matrix(gradient: Gradient) -> NDArray[np.float64]:
    a, b, c, d, e, f = gradient.matrix
    return np.array([[a, c, e], [b, d, f], [0.0, 0.0, 1.0]])


def colors_at(gradient: Gradient, offsets: NDArray[np.float64]) -> NDArray[np.int64]:
    """The gradient's colours at ``offsets (S,)`` in [0, 1]: ``(S, 4)`` straight RGBA, interpolated as SVG
    does, in sRGB, rounded."""
    stops = np.array([o for o, _ in gradient.stops])
    colours = np.array([c for _, c in gradient.stops], dtype=float)
    at = np.asarray(offsets, dtype=np.float64)
    return np.rint(np.column_stack([np.interp(at, stops, colours[:, k]) for k in range(4)])).astype(np.int64)


def color_at(gradient: Gradient, offset: float) -> Color:
    """The gradient's colour at ``offset`` in [0, 1] (straight RGBA, interpolated as SVG does, in sRGB)."""
    return tuple(int(v) for v in colors_at(gradient, np.array([offset]))[0])  # type: ignore[return-value]


def _as_gradient(paint: Paint, like: Gradient) -> Gradient | None:
    if paint.gradient is not None:
        return paint.gradient
    if paint.fill is None:
        return None
    return Gradient(like.kind, like.geometry, like.matrix, ((0.0, paint.fill), (1.0, paint.fill)), like.spread)


def blend_gradient(p0: Paint, p1: Paint, box0: Box, box1: Box, box: Box, t: float) -> Gradient | None:
    """The gradient fill at eased ``t`` (between 0 and 1, or beyond with an overshoot) between keys painted ``p0`` (element's box ``box0``) and
    ``p1`` (``box1``), for an inbetween whose box is ``box``; None when neither key has a gradient."""
    like = p0.gradient or p1.gradient
    if like is None:
        return None
    g0, g1 = _as_gradient(p0, like), _as_gradient(p1, like)
    if g0 is None or g1 is None:  # no fill on one side: the other's gradient at that side's alpha 0
        only, share = (g0, 1.0 - t) if g1 is None else (g1, t)
        assert only is not None
        return _faded(only, share)
    near, far = (g0, g1) if t < 0.5 else (g1, g0)
    near_box, far_box = (box0, box1) if t < 0.5 else (box1, box0)
    frames = _frame(near_box), _frame(far_box), _frame(box)
    if frames[0] is None or frames[2] is None:
        return near
    relative_near = np.linalg.solve(frames[0], _matrix(near))
    same = near.kind == far.kind and len(near.geometry) == len(far.geometry)
    if same and frames[1] is not None:
        relative_far = np.linalg.solve(frames[1], _matrix(far))
        weight = t if near is g0 else 1.0 - t  # the far key's share
        relative = (1.0 - weight) * relative_near + weight * relative_far
        geometry = tuple(float(a + weight * (b - a)) for a, b in zip(near.geometry, far.geometry))
    else:
        relative, geometry = relative_near, near.geometry
    placed = frames[2] @ relative
    offsets = sorted({o for o, _ in g0.stops} | {o for o, _ in g1.stops})
    at = np.array(offsets)
    stops = tuple(zip(offsets, blend_stop_colours(colors_at(g0, at), colors_at(g1, at), t)))
    return Gradient(near.kind, geometry,
                    (float(placed[0, 0]), float(placed[1, 0]), float(placed[0, 1]), float(placed[1, 1]),
                     float(placed[0, 2]), float(placed[1, 2])), stops, near.spread)  # type: ignore[arg-type]


def _faded(gradient: Gradient, share: float) -> Gradient:
    """``gradient`` with each stop's alpha times ``share`` (clamped to [0, 1]; an overshoot does not brighten it)."""
    share = min(max(float(share), 0.0), 1.0)
    if share == 1.0:
        return gradient
    stops = tuple((o, (r, g, b, int(round(a * share)))) for o, (r, g, b, a) in gradient.stops)
    return Gradient(gradient.kind, gradient.geometry, gradient.matrix, stops, gradient.spread)  # type: ignore[arg-type]


def blend_stroke_gradient(p0: Paint, p1: Paint, box0: Box, box1: Box, box: Box, t: float) -> Gradient | None:
    """The gradient stroke at eased ``t`` between keys painted ``p0`` and ``p1``, as :func:`blend_gradient`
    blends fills; None when neither key strokes with a gradient."""
    if p0.stroke_gradient is None and p1.stroke_gradient is None:
        return None
    return blend_gradient(Paint(p0.stroke, None, gradient=p0.stroke_gradient),
                          Paint(p1.stroke, None, gradient=p1.stroke_gradient), box0, box1, box, t)


def carry_pattern(pattern0: Pattern | None, pattern1: Pattern | None, box0: Box, box1: Box, box: Box, t: float
                  ) -> Pattern | None:
    """The pattern at eased ``t`` between keys painted with ``pattern0`` (element's box ``box0``) and
    ``pattern1`` (``box1``), for an inbetween whose box is ``box``, each placed relative to the inbetween's box
    as it was to its key's: where both keys have one, the second over the first by ``t`` (its
    :attr:`~tweenrender.model.Pattern.share`, the first :attr:`~tweenrender.model.Pattern.beneath` it); where
    one has, that one fading in (out) with ``t`` over the paint's plain colour; None where neither has one."""
    if pattern0 is not None and pattern1 is not None:
        if t <= 0.0 or t >= 1.0:
            return _carried(pattern0, box0, box, 1.0) if t <= 0.0 else _carried(pattern1, box1, box, 1.0)
        return replace(_carried(pattern1, box1, box, t), beneath=_carried(pattern0, box0, box, 1.0))
    if pattern1 is not None:
        share = min(max(t, 0.0), 1.0)
        return _carried(pattern1, box1, box, share) if share > 0.0 else None
    if pattern0 is not None:
        share = min(max(1.0 - t, 0.0), 1.0)
        return _carried(pattern0, box0, box, share) if share > 0.0 else None
    return None


def _carried(pattern: Pattern, key_box: Box, box: Box, share: float) -> Pattern:
    """``pattern``, placed relative to its key's element box ``key_box``, placed so relative to ``box``."""
    frames = _frame(key_box), _frame(box)
    if frames[0] is None or frames[1] is None:
        return replace(pattern, share=share)
    a, b, c, d, e, f = pattern.matrix
    placed = frames[1] @ np.linalg.solve(frames[0], np.array([[a, c, e], [b, d, f], [0.0, 0.0, 1.0]]))
    return replace(pattern, matrix=(float(placed[0, 0]), float(placed[1, 0]), float(placed[0, 1]),
                                    float(placed[1, 1]), float(placed[0, 2]), float(placed[1, 2])), share=share)
