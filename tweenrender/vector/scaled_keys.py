"""A contour that only grows, shrinks and moves, keyed as one still path under a keyed scale and position.

A contour without a partner grows from (or shrinks to) a point, its area linear in t (maths §5.17): every
frame is its largest frame scaled about a point, ``x_f = c_f + s_f · (x_r - a)`` (``a`` the largest frame's
centre, ``c_f`` frame f's, ``s_f ≥ 0``). Keyed vertex by vertex, it needs a keyframe every few frames, each
holding every vertex (the scale is √t, not straight in t); keyed as its largest frame's cubic path, still,
under a transform whose position and scale are keyed, it holds its vertices once. Both ways a player moves
the drawn points straight between keyframes (a point's image is linear in ``(c, s)``), so the keyframes of
``(c_x, c_y, s·R)`` within ``e/√2`` play every point within ``R`` of ``a`` within ``e`` (Cauchy–Schwarz:
``|Δc + Δs·(x - a)| ≤ √2·|(Δc, Δs·R)|``). Where ``(c, s·R)`` keeps to one straight line (a scale about a fixed
point), one span on a timing free in both handles often follows √t where even timings need several
(:mod:`.free_timing`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .curves import fit_curves
from .free_timing import free_span
from .keyframes import fit_keyframes
from ..encode.vector_data import SCALE_DIGITS, ContourMove

__all__ = ["ScaledContour", "homothety", "scaled_contour", "HOMOTHETY_SLACK"]

Array = NDArray[np.float64]

HOMOTHETY_SLACK = 1e-6
"""Pixels a frame may miss its largest frame scaled about a point and still count as that (float arithmetic)."""

_VERTEX_CHARS = 42  # about the characters one vertex of one path keyframe takes (vertex and two tangents)
_KEY_CHARS = 90  # about those a keyframe takes besides its values (frame, timing)
_MOVE_CHARS = 2 * _KEY_CHARS + 40  # one keyframe of position and scale
_GROUP_CHARS = 160  # the group and its transform


@dataclass(frozen=True)
class ScaledContour:
    """A contour as a still cubic path ``curve (1, M, 3, 2)`` (its largest frame's, pixels) under ``move``, and the
    distance the path's fit reached."""

    curve: Array
    move: ContourMove
    error: float


def homothety(samples: Array) -> tuple[int, Array, Array, Array] | None:
    """Whether every frame of ``samples (F, L, 2)`` is one frame scaled about a point: the largest frame ``r``, its
    centre ``a (2,)``, each frame's centre ``c (F, 2)`` and scale ``s (F,)`` (``x_f = c_f + s_f (x_r - a)`` within
    :data:`HOMOTHETY_SLACK`), or ``None`` (a turn, a stretch, any change of shape; or a still contour)."""
    if samples.shape[1] < 2 or not np.all(np.isfinite(samples)):
        return None
    centres = samples.mean(axis=1)  # (F, 2)
    spread = samples - centres[:, None]  # (F, L, 2)
    sizes = np.sum(spread * spread, axis=(1, 2))  # (F,)
    r = int(np.argmax(sizes))
    if sizes[r] <= 0.0:
        return None
    scales = np.sum(spread * spread[r], axis=(1, 2)) / sizes[r]  # least squares, (F,)
    miss = spread - scales[:, None, None] * spread[r]
    if np.any(scales < 0.0) or float(np.sqrt(np.max(np.sum(miss * miss, axis=-1)))) > HOMOTHETY_SLACK:
        return None
    if np.all(scales == 1.0) and np.all(centres == centres[r]):
        return None
    return r, centres[r], centres, scales


def scaled_contour(samples: Array, closed: bool, curve_tolerance: float, key_tolerance: Callable[[float], float],
                   own_keyframes: int) -> ScaledContour | None:
    """``samples (F, L, 2)`` as a still path under keyed position and scale, when every frame is one frame scaled
    about a point (:func:`homothety`) and that takes fewer characters than ``own_keyframes`` (more than two) keyframes of
    the path:
    the largest frame fitted within ``curve_tolerance`` (scaled down, the fit only comes nearer) and the transform
    keyed within ``key_tolerance(the fit's distance)`` less the written scale's rounding; frames from 0."""
    found = homothety(samples) if own_keyframes > 2 else None  # two: straight already, the keys exact
    if found is None:
        return None
    r, anchor, centres, scales = found
    _, curve, error = fit_curves(samples[r:r + 1], closed, curve_tolerance)
    reach = float(np.linalg.norm(curve[0] - anchor, axis=-1).max())  # R: every point of the path lies within it
    tolerance = key_tolerance(error) - HOMOTHETY_SLACK - reach * 0.5 * 10.0 ** -(SCALE_DIGITS + 2)
    if reach <= 0.0 or tolerance <= 0.0:
        return None
    values = np.concatenate([centres, scales[:, None] * reach], axis=1)  # (F, 3)
    keys = fit_keyframes(values[:, None], tolerance / np.sqrt(2.0))
    frames, keyed, handles = keys.frames, keys.values[:, 0], keys.handles()
    if len(frames) > 2:  # one span on a timing of its own, where the centre moves with the scale
        span = free_span(values, tolerance / np.sqrt(2.0))
        if span is not None and len(span.frames) < len(frames):
            frames, keyed, handles = span.frames, span.values, span.eases
    vertices = curve.shape[1]
    moved_chars = _GROUP_CHARS + len(frames) * _MOVE_CHARS + vertices * _VERTEX_CHARS
    if moved_chars >= own_keyframes * (vertices * _VERTEX_CHARS + _KEY_CHARS):
        return None
    move = ContourMove(frames, keyed[:, :2], keyed[:, 2] / reach, handles, anchor)
    return ScaledContour(curve, move, error)
