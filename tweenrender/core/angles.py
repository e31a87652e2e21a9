"""Headings and turning angles of polygons, vectorised over any leading axes.

A polygon is ``(..., N, 2)`` float64, closed implicitly. Edge ``i`` runs from
vertex ``i`` to vertex ``i + 1``; the turning angle at vertex ``i`` is the angle
from edge ``i - 1`` to edge ``i``, in (−π, π], positive to the left.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from .geometry import cross, edges

__all__ = ["wrap", "headings", "turning_angles", "shorter_change"]

Array = NDArray[np.float64]


def wrap(angle: Array | float) -> Array:
    """``angle`` brought into (−π, π] (the shorter way round)."""
    wrapped = np.mod(np.asarray(angle, dtype=np.float64) + np.pi, 2.0 * np.pi) - np.pi
    return np.where(wrapped <= -np.pi, np.pi, wrapped)


def headings(points: Array) -> Array:
    """Direction of each edge, ``atan2`` of its vector: ``(..., N)``; NaN for a zero-length edge."""
    vectors = edges(points)
    angle = np.arctan2(vectors[..., 1], vectors[..., 0])
    zero = (vectors[..., 0] == 0.0) & (vectors[..., 1] == 0.0)
    return np.where(zero, np.nan, angle)


def turning_angles(points: Array) -> Array:
    """Turning angle at each vertex, from edge ``i - 1`` to edge ``i``: ``(..., N)`` in (−π, π].

    NaN where either edge has zero length (the angle is undefined there).
    """
    forward = edges(points)
    backward = np.roll(forward, 1, axis=-2)
    angle = np.arctan2(cross(backward, forward), (backward * forward).sum(axis=-1))
    angle = np.where(angle <= -np.pi, np.pi, angle)
    zero = ~np.any(forward != 0.0, axis=-1) | ~np.any(backward != 0.0, axis=-1)
    return np.where(zero, np.nan, angle)


def shorter_change(before: Array, after: Array) -> Array:
    """The change from angle ``before`` to ``after`` taken the shorter way: ``wrap(after - before)``."""
    return wrap(np.asarray(after) - np.asarray(before))
