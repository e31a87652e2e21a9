"""Pops: the frames where the picture jumps (``stats``' ``pops``, docs/methods.md).

Each shape's *ink* in a frame is, per cell of a grid over the view (:mod:`.coverage`), how much of
it the shape covers: its fill's alpha inside its filled area (its closed contours as drawn, under
its fill rule), its stroke's alpha within its stroke band (each contour at its share of the width),
the stroke over the fill, times the paint's opacity; a cross-fade weighs the two keys' pictures as
it is drawn, and an invisible shape has none. The *change* of frame f is the mean over the grid's
cells of the sum over shapes of ``|ink(f) − ink(f − 1)|``: the share of the view whose coverage
changed, counted once per shape that changed it (frame 0 changes by 0). Colours and clip regions
are not looked at, nor what one shape hides of another.

Smooth motion changes a frame by the slivers its outlines sweep in one frame; a shape or a piece
of one appearing, vanishing or jumping in one frame changes it by its whole area at once. A frame
*pops* when its change is more than ``3 ×`` the clip's median change and more than ``0.002``.
"""

from __future__ import annotations

import hashlib
from typing import Sequence

import numpy as np
from numpy.typing import NDArray

from .coverage import Grid, bands, by_rule, winding
from .timing.timeline import ShapeAt

__all__ = ["inks", "changes", "frames_digest", "pops", "POP_FACTOR", "POP_FLOOR"]

Array = NDArray[np.float64]

POP_FACTOR = 3.0
"""A frame pops when its change is over this many times the clip's median change ..."""
POP_FLOOR = 0.002
"""... and over this share of the view."""

_BLOCK = 48  # frames whose inks are held at once


def inks(grid: Grid, frames: Sequence[ShapeAt], rules: Sequence[str], width_scale: float = 1.0) -> Array:
    """How much of each cell the shape covers in each of ``frames``: ``(F, ny, nx)`` in [0, 1]. ``rules``
    are the fill rules it is drawn with, one per frame; ``width_scale`` turns its stroke width into
    world units. The frames are worked out together (one winding pass for fills, one for strokes)."""
    pictures: list[tuple[int, float, ShapeAt, list[int]]] = []  # frame, weight, shape, which contours
    for f, at in enumerate(frames):
        if not at.visible:
            continue
        if at.fade is None or not at.sides:
            pictures.append((f, at.paint.opacity, at, list(range(len(at.contours)))))
            continue
        w = float(at.fade)
        pictures.append((f, (1.0 - w) * at.paint.opacity, at, [i for i, side in enumerate(at.sides) if side <= 0]))
        pictures.append((f, w * at.paint.opacity, at, [i for i, side in enumerate(at.sides) if side >= 0]))
    shut, shut_layer, lines, line_closed, line_width, line_layer = [], [], [], [], [], []
    fill_alpha, stroke_alpha = np.zeros(len(pictures)), np.zeros(len(pictures))
    for k, (_, _, at, which) in enumerate(pictures):
        paint = at.paint
        fill_alpha[k] = 1.0 if paint.gradient is not None else paint.fill[3] / 255.0 if paint.fill is not None else 0.0
        stroke_alpha[k] = paint.stroke[3] / 255.0 if paint.stroke is not None and paint.stroke_width > 0 else 0.0
        turned = at.reversed or (False,) * len(at.contours)
        shares = at.widths or (1.0,) * len(at.contours)
        for i in which:
            if fill_alpha[k] > 0 and at.closed[i] and len(at.contours[i]) >= 3:
                shut.append(at.contours[i][::-1] if turned[i] else at.contours[i])
                shut_layer.append(k)
            if stroke_alpha[k] > 0 and shares[i] > 0:
                lines.append(at.contours[i])
                line_closed.append(at.closed[i])
                line_width.append(paint.stroke_width * width_scale * shares[i])
                line_layer.append(k)
    turns = winding(grid, shut, shut_layer, len(pictures))
    inside = np.stack([by_rule(turns[k], rules[f]) for k, (f, _, _, _) in enumerate(pictures)]) if pictures else turns
    stroked = bands(grid, lines, line_closed, line_width, line_layer, len(pictures))
    # stroke over fill: what shows through is what each lets through
    cover = 1.0 - (1.0 - fill_alpha[:, None, None] * inside) * (1.0 - stroke_alpha[:, None, None] * stroked)
    out = np.zeros((len(frames), grid.ny, grid.nx))
    for k, (f, weight, _, _) in enumerate(pictures):
        out[f] += weight * cover[k]
    return out


def frames_digest(frames: Sequence[ShapeAt], rules: Sequence[str]) -> bytes:
    """A digest of everything :func:`inks` reads of a shape's ``frames``, drawn with fill ``rules``: frames with
    one digest have one ink, and so one :func:`changes`."""
    digest = hashlib.blake2b(digest_size=32)
    for at, rule in zip(frames, rules):
        paint = at.paint
        looks = (paint.opacity, paint.gradient is not None, paint.fill and paint.fill[3], paint.stroke and paint.stroke[3],
                 paint.stroke_width)
        digest.update(repr((at.visible, at.fade, at.sides, at.closed, at.reversed, at.widths, looks, rule,
                            [c.shape for c in at.contours])).encode())
        for c in at.contours:
            digest.update(np.ascontiguousarray(c, dtype=np.float64).tobytes())
    return digest.digest()


def changes(grid: Grid, frames: Sequence[ShapeAt], rules: Sequence[str], width_scale: float = 1.0,
            block: int = _BLOCK) -> Array:
    """One shape's share of each frame's change: the mean over the cells of ``|ink(f) − ink(f − 1)|``
    (:func:`inks`, worked out ``block`` frames at a time): ``(F,)``, 0 for the first frame. A clip's
    change is the sum of its shapes'."""
    out = np.zeros(len(frames))
    before: Array | None = None
    for start in range(0, len(frames), block):
        now = inks(grid, frames[start:start + block], rules[start:start + block], width_scale)
        joined = now if before is None else np.concatenate([before[None], now])
        out[start + (before is None):start + len(now)] = np.abs(np.diff(joined, axis=0)).mean(axis=(1, 2))
        before = now[-1]
    return out


def pops(change: Array, factor: float = POP_FACTOR, floor: float = POP_FLOOR) -> list[int]:
    """The frames (indices ≥ 1) whose ``change (F,)`` is over ``factor ×`` the median of the clip's
    changes (frames 1 on) and over ``floor``."""
    change = np.asarray(change, dtype=np.float64)
    if len(change) < 2:
        return []
    limit = max(factor * float(np.median(change[1:])), floor)
    return [int(f) for f in np.flatnonzero(change > limit) if f >= 1]
