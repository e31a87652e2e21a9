"""Clip paths between keys: each key's clip region carried by its element's motion.

Like gradients (:mod:`.gradient_blend`), a key's clip contours are taken relative to its
element's bounding box; an inbetween places them through its own bounding box, blending the
two keys' relative contours where both keys have clips of the same make (as many regions,
contours and vertices), else taking the nearer key's. At a key the clip is the key's own.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from numpy.typing import NDArray

from ..model import Contour
from .gradient_blend import Box

__all__ = ["Clips", "clips_at"]

Clips = tuple[tuple[NDArray[np.float64], ...], ...]
"""Clip regions, each a tuple of closed contours ``(N_i, 2)`` in world units (nonzero), intersected."""


def _relative(clips: Sequence[Sequence[Contour]], box: Box) -> list[list[NDArray[np.float64]]] | None:
    x0, y0, x1, y1 = box
    w, h = x1 - x0, y1 - y0
    if w <= 0 or h <= 0:
        return None
    scale, origin = np.array([w, h]), np.array([x0, y0])
    return [[(c.points - origin) / scale for c in region] for region in clips]


def _same_make(a: list[list[NDArray[np.float64]]], b: list[list[NDArray[np.float64]]]) -> bool:
    return len(a) == len(b) and all(len(ra) == len(rb) and all(p.shape == q.shape for p, q in zip(ra, rb))
                                    for ra, rb in zip(a, b))


def clips_at(c0: Sequence[Sequence[Contour]], c1: Sequence[Sequence[Contour]], box0: Box, box1: Box, box: Box,
             t: float) -> Clips:
    """The clip regions at eased ``t`` in (0, 1) of an element whose keys are clipped by ``c0`` (its box
    ``box0``) and ``c1`` (``box1``) and whose inbetween spans ``box``."""
    near, far, near_box, far_box = (c0, c1, box0, box1) if t < 0.5 else (c1, c0, box1, box0)
    if not near:
        return ()
    relative = _relative(near, near_box)
    if relative is None:  # a point (an element growing from its centre): the other key's
        relative = _relative(far, far_box) if far else None
        if relative is None:
            return tuple(tuple(c.points for c in region) for region in near)
    other = _relative(far, far_box) if far else None
    if other is not None and _same_make(relative, other):
        weight = t if t < 0.5 else 1.0 - t  # the far key's share
        relative = [[(1.0 - weight) * p + weight * q for p, q in zip(ra, rb)] for ra, rb in zip(relative, other)]
    x0, y0, x1, y1 = box
    scale, origin = np.array([x1 - x0, y1 - y0]), np.array([x0, y0])
    return tuple(tuple(p * scale + origin for p in region) for region in relative)
