"""Masks between keys: each key's masks carried by its element's motion, the two keys' cross-faded.

A key's masks are moved by the affine map that takes the element's vertices at that key onto its
vertices in the inbetween, fitted by least squares (exact for an element that moves, turns, scales or
shears as a whole); where the vertices do not fix one (all on a line, or at a point), by the map of the
key's bounding box onto the inbetween's (a scale and a shift per axis). What an inbetween at eased ``t``
lets through is ``(1 − t)`` × what the first key's masks let through (so moved) plus ``t`` × the second
key's: a key without masks lets everything through. At a key the masks are the key's own, unmoved.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

from ..model import Mask
from .gradient_blend import Box, box_of

__all__ = ["MaskBlend", "box_map", "carried", "masks_at", "masks_at_key"]

MaskBlend = tuple[tuple[float, tuple[Mask, ...], NDArray[np.float64]], ...]
"""Weighted alternatives ``(weight, masks, move)``: what is let through is the sum over them of ``weight`` ×
the product of ``masks`` moved by the world ``move (3, 3)``; ``()`` lets everything through."""


def masks_at_key(masks: Sequence[Mask]) -> MaskBlend:
    """A key's own masks, unmoved."""
    return ((1.0, tuple(masks), np.eye(3)),) if masks else ()


def box_map(source: Box, target: Box) -> NDArray[np.float64]:
    """The world ``(3, 3)`` map of box ``source`` onto box ``target`` (per axis a scale and a shift; along an
    axis where either box is flat, the shift of the centre alone)."""
    move = np.eye(3)
    for axis in (0, 1):
        s0, s1, t0, t1 = source[axis], source[axis + 2], target[axis], target[axis + 2]
        span = s1 - s0
        scale = (t1 - t0) / span if span > 0 and t1 > t0 else 1.0
        move[axis, axis] = scale
        move[axis, 2] = 0.5 * (t0 + t1) - scale * 0.5 * (s0 + s1)
    return move


def carried(source: NDArray[np.float64], target: NDArray[np.float64]) -> NDArray[np.float64]:
    """The world ``(3, 3)`` affine map that best takes vertices ``source (N, 2)`` onto ``target (N, 2)`` (least
    squares); :func:`box_map` of their boxes where the vertices do not fix an affine map."""
    if source.shape == target.shape and len(source) >= 3 and np.all(np.isfinite(source)) \
            and np.all(np.isfinite(target)):
        centre = source.mean(axis=0)
        spread = np.abs(source - centre).max()
        if spread > 0:
            rows = np.column_stack([(source - centre) / spread, np.ones(len(source))])  # well scaled
            singular = np.linalg.svd(rows, compute_uv=False)
            if singular[-1] > 1e-9 * singular[0]:
                solution = np.linalg.lstsq(rows, target, rcond=None)[0]  # (3, 2)
                normalise = np.array([[1 / spread, 0.0, -centre[0] / spread], [0.0, 1 / spread, -centre[1] / spread],
                                      [0.0, 0.0, 1.0]])
                move = np.vstack([solution.T, [0.0, 0.0, 1.0]]) @ normalise
                if np.all(np.isfinite(move)):
                    return move
    if len(source) == 0 or len(target) == 0:
        return np.eye(3)
    return box_map(box_of([source]), box_of([target]))


def masks_at(m0: Sequence[Mask], m1: Sequence[Mask], move0: NDArray[np.float64], move1: NDArray[np.float64],
             t: float) -> MaskBlend:
    """The masks at eased ``t`` in (0, 1) of an element whose keys are masked by ``m0`` and ``m1``, each key's
    carried into the inbetween by the world map ``move0`` and ``move1`` ``(3, 3)`` (:func:`carried`)."""
    if not m0 and not m1:
        return ()
    return ((1.0 - t, tuple(m0), move0), (t, tuple(m1), move1))
