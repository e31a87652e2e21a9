"""Keyframes for players that move every value on a straight line between them (maths §5.12).

Lottie and SMIL interpolate each path vertex, colour channel and width linearly between
keyframes. Given a value's exact samples at every frame, :func:`greedy_keyframes` picks keyframes
greedily: from the last keyframe ``a`` it takes the farthest frame ``b`` such that the straight
chord from ``a`` to ``b`` stays within the tolerance of every frame between them, at every vertex.
:func:`chord_deviation` measures that distance.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

__all__ = ["chord_deviation", "greedy_keyframes", "max_deviation", "paint_channels"]

Array = NDArray[np.float64]
_BLOCK_ELEMENTS = 1 << 22  # floats per vectorised block of candidate chords


def chord_deviation(values: Array, a: int, b: int) -> float:
    """The largest distance, over frames ``a..b`` and vertices, between ``values (F, N, D)`` and
    the straight chord from frame ``a`` to frame ``b`` (Euclidean over the last axis)."""
    if b <= a + 1:
        return 0.0
    s = (np.arange(a, b + 1) - a) / (b - a)
    chord = values[a] + s[:, None, None] * (values[b] - values[a])
    return float(np.sqrt(np.max(np.sum((values[a:b + 1] - chord) ** 2, axis=-1))))


def max_deviation(values: Array, keys: list[int] | NDArray[np.intp]) -> float:
    """The largest distance between ``values (F, N, D)`` and the straight interpolation through
    frames ``keys`` (increasing, the first 0, the last F - 1), over every frame and vertex."""
    keys = [int(k) for k in keys]
    return max((chord_deviation(values, a, b) for a, b in zip(keys, keys[1:])), default=0.0)


def greedy_keyframes(values: Array, tolerance: float) -> list[int]:
    """Keyframes of ``values (F, N, D)`` (F frames, N vertices or channels, D coordinates) such that
    straight interpolation between them stays within ``tolerance`` of every frame: increasing frame
    indices, the first 0 and the last F - 1 (one ``[0]`` when every frame is the first).

    From the last keyframe ``a`` the next is the farthest ``b`` whose chord is within the tolerance
    at every frame ``a..b`` (``a + 1`` always is). Non-finite values are never within tolerance of
    anything but the same frame, so they become keyframes of their own.
    """
    values = np.asarray(values, dtype=np.float64)
    frames = len(values)
    if frames == 0:
        return []
    flat = values.reshape(frames, -1, values.shape[-1]) if values.ndim >= 2 else values.reshape(frames, 1, 1)
    if frames == 1 or np.array_equal(flat, np.broadcast_to(flat[:1], flat.shape)):
        return [0]
    keys = [0]
    a = 0
    while a < frames - 1:
        a = _farthest(flat, a, tolerance)
        keys.append(a)
    return keys


def _farthest(values: Array, a: int, tolerance: float) -> int:
    """The farthest ``b > a`` whose chord from ``a`` is within ``tolerance`` of every frame between."""
    frames, vertices, dims = values.shape
    limit = tolerance * tolerance
    span = frames - 1 - a
    block = max(1, _BLOCK_ELEMENTS // max(1, span * vertices * dims))
    stop = frames - 1
    while stop > a + 1:  # candidates b in [start, stop], farthest first
        start = max(a + 2, stop - block + 1)
        ends = np.arange(start, stop + 1)  # (B,)
        inner = np.arange(a + 1, stop)  # frames strictly between a and the farthest candidate
        s = (inner[None, :] - a) / (ends[:, None] - a)  # (B, M); beyond its end a chord is not checked
        with np.errstate(invalid="ignore", over="ignore"):
            chords = values[a] + s[:, :, None, None] * (values[ends] - values[a])[:, None]  # (B, M, N, D)
            d2 = np.sum((values[inner][None] - chords) ** 2, axis=-1).max(axis=-1)  # (B, M)
        ok = (d2 <= limit) | (inner[None, :] >= ends[:, None])
        good = np.flatnonzero(ok.all(axis=1) & np.all(np.isfinite(values[ends]), axis=(1, 2))
                              & bool(np.all(np.isfinite(values[a]))))
        if len(good):
            return int(ends[good[-1]])
        stop = start - 1
    return a + 1


def paint_channels(fill: Array, stroke: Array, width: Array, opacity: Array, width_tolerance: float) -> Array:
    """Paint per frame as ``(F, 10, 1)`` channels in units of their tolerance, for
    :func:`greedy_keyframes` with tolerance 1: ``fill``/``stroke (F, 4)`` straight RGBA and
    ``opacity (F,)`` in [0, 1] count in 1/255 steps (each channel as a player
    interpolates it), ``width (F,)`` pixels in ``width_tolerance``."""
    channels = np.concatenate([fill * 255.0, stroke * 255.0, opacity[:, None] * 255.0,
                               width[:, None] / width_tolerance], axis=1)
    return channels[:, :, None]

