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
    """The farthest ``b > a`` whose chord from ``a`` is within ``tolerance`` of every frame between.

    Candidates are first screened at three frames each (a quarter, half and three quarters of the
    way), a test every valid chord passes; only those left are checked at every frame, farthest first.
    """
    frames = len(values)
    if frames - 1 <= a + 1 or not np.all(np.isfinite(values[a])):
        return a + 1
    ends = np.arange(a + 2, frames)  # (B,)
    limit = tolerance * tolerance
    with np.errstate(invalid="ignore", over="ignore"):
        passed = np.all(np.isfinite(values[ends]), axis=(1, 2))
        for q in (0.25, 0.5, 0.75):
            middle = a + np.clip(np.rint((ends - a) * q).astype(np.intp), 1, ends - a - 1)  # (B,)
            s = (middle - a) / (ends - a)
            chord = values[a] + s[:, None, None] * (values[ends] - values[a])
            passed &= np.sum((values[middle] - chord) ** 2, axis=-1).max(axis=-1) <= limit
    for b in ends[passed][::-1]:
        if _within(values, a, int(b), limit):
            return int(b)
    return a + 1


def _within(values: Array, a: int, b: int, limit: float) -> bool:
    """Whether the chord from frame ``a`` to ``b`` is within ``sqrt(limit)`` of every frame between."""
    s = (np.arange(a + 1, b) - a) / (b - a)
    with np.errstate(invalid="ignore", over="ignore"):
        chord = values[a] + s[:, None, None] * (values[b] - values[a])
        return bool(np.all(np.sum((values[a + 1:b] - chord) ** 2, axis=-1) <= limit))


def paint_channels(fill: Array, stroke: Array, width: Array, opacity: Array, width_tolerance: float) -> Array:
    """Paint per frame as ``(F, 10, 1)`` channels in units of their tolerance, for
    :func:`greedy_keyframes` with tolerance 1: ``fill``/``stroke (F, 4)`` straight RGBA and
    ``opacity (F,)`` in [0, 1] count in 1/255 steps (each channel as a player
    interpolates it), ``width (F,)`` pixels in ``width_tolerance``."""
    channels = np.concatenate([fill * 255.0, stroke * 255.0, opacity[:, None] * 255.0,
                               width[:, None] / width_tolerance], axis=1)
    return channels[:, :, None]

