"""Keys → segments → polygons at any time (maths §5.3).

A shape's keys split its life into segments, one per consecutive pair of keys,
each with its own correspondence (maths §2) and easing. Frame ``f`` is drawn at
``time = f / fps``; before the first key a shape holds its first key, after its
last key it holds the last one.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..errors import GeometryError
from ..model import Matching, Points, Shape, frozen_points
from .balance import spread
from .correspond import Correspondence, correspond
from .methods import interpolate

__all__ = ["ease", "frame_count", "Segment", "Track", "build_track"]

Array = NDArray[np.float64]


def ease(t: Array, kind: str) -> Array:
    """Reparametrise ``t (T,)`` in [0, 1]: ``linear``, ``in`` (t²), ``out``, ``in-out`` (smoothstep).

    Every easing maps 0 → 0 and 1 → 1 exactly, so keys are hit exactly.
    """
    if kind == "linear":
        return t
    if kind == "in":
        return t * t
    if kind == "out":
        return 1.0 - (1.0 - t) ** 2
    if kind == "in-out":
        return t * t * (3.0 - 2.0 * t)
    raise GeometryError(f"unknown easing {kind!r}")


def frame_count(duration: float, fps: float) -> int:
    """Frames from time 0 to the frame nearest ``duration``, both included: ``round(duration · fps) + 1``.

    The last frame is the last key's (or lies within half a frame of it, holding the last key).
    """
    return round(duration * fps) + 1


@dataclass(frozen=True, slots=True)
class Segment:
    """Two corresponding keys: ``k0``, ``k1`` are ``(L, 2)`` after balancing."""

    start: float
    end: float
    k0: Points
    k1: Points
    ease: str
    joints: tuple[tuple[int, int], ...]  # in balanced vertex indices
    counts: tuple[int, int]  # vertex counts of the two keys as drawn
    correspondence: Correspondence | None  # None when the counts agree (the drawn order is kept)

    def local_t(self, times: Array) -> Array:
        """Eased parameter in [0, 1] of ``times (T,)`` seconds within this segment."""
        span = self.end - self.start
        t = np.clip((times - self.start) / span, 0.0, 1.0)
        return ease(t, self.ease)


@dataclass(frozen=True, slots=True)
class Track:
    """A shape's segments, ready to be sampled at any time."""

    name: str
    segments: tuple[Segment, ...]
    still: Points  # the only key of a static shape (unused when there are segments)

    def segment_index(self, times: Array) -> NDArray[np.intp]:
        """The segment each of ``times (F,)`` seconds falls in: ``(F,)`` (the first before, the last after)."""
        starts = np.array([s.start for s in self.segments])
        return np.clip(np.searchsorted(starts, times, side="right") - 1, 0, len(self.segments) - 1)

    def at(self, times: Array, method: str) -> list[Points]:
        """The shape's polygon at each of ``times (F,)`` seconds: a list of ``(N_f, 2)`` arrays.

        Frames are grouped by segment so each segment's paths are evaluated in
        one vectorised call.
        """
        times = np.atleast_1d(np.asarray(times, dtype=np.float64))
        if not self.segments:
            return [self.still] * len(times)
        index = self.segment_index(times)
        out: list[Points] = [self.still] * len(times)
        for s in np.unique(index):
            seg = self.segments[s]
            picked = np.flatnonzero(index == s)
            polygons = interpolate(seg.k0, seg.k1, seg.local_t(times[picked]), method, seg.joints)
            for slot, polygon in zip(picked, polygons):
                out[slot] = polygon
        return out


def build_track(shape: Shape, matching: Matching, balance: str = "copies") -> Track:
    """Balance every consecutive pair of ``shape``'s keys and carry its joints through.

    ``balance`` places the copies balancing makes: ``"copies"`` stacks them on their
    vertex (the thesis), ``"spread"`` spreads them along its edges (maths §5.6).
    """
    keys = shape.keys
    joints = tuple(shape.joints)  # indices into the current key's vertices
    segments = []
    for before, after in zip(keys, keys[1:]):
        a, b = before.points, after.points
        if len(a) == len(b) and matching.equal_counts == "drawn":
            k0, k1, found, balanced_joints = a, b, None, joints
            carried = joints
        else:
            found = correspond(a, b, matching)
            k0, k1 = found.apply(a, b)
            if balance == "spread":
                k0, k1 = (frozen_points(k) for k in spread(k0, k1))
            first_of = _first_occurrence(found.pairs[:, 0], len(a))
            balanced_joints = tuple((int(first_of[i]), int(first_of[j])) for i, j in joints)
            carried = tuple((int(found.pairs[p, 1]), int(found.pairs[q, 1])) for p, q in balanced_joints)
        segments.append(Segment(before.time, after.time, k0, k1, before.ease,
                                balanced_joints, (len(a), len(b)), found))
        joints = carried
    return Track(shape.name, tuple(segments), keys[0].points)


def _first_occurrence(indices: NDArray[np.intp], count: int) -> NDArray[np.intp]:
    """For each value 0..count-1, the first position where it occurs in ``indices``."""
    first = np.full(count, -1, dtype=np.intp)
    values, positions = np.unique(indices, return_index=True)
    first[values] = positions
    return first
