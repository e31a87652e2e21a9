"""Keyframes for players that move every value on a straight line between them (maths §5.12).

Lottie and SMIL interpolate each path vertex, colour channel and width linearly between
keyframes, through the keyframe's cubic-Bézier timing. Given a value's exact samples at every
frame:

* :func:`greedy_keyframes` picks keyframes through the exact samples greedily: from the last
  keyframe ``a``, the farthest frame ``b`` whose straight chord stays within the tolerance of every
  frame between them, at every vertex (:func:`chord_deviation` measures that distance). Paint uses it.
* :func:`fit_keyframes` lets each keyframe's values move off the samples (within the tolerance of
  its own frame) and gives each span its own timing, so one span covers more frames; the first and
  last keyframes stay exact. Paths use it. :meth:`Keyframes.played` is what a player draws.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = ["EASED_SHARE", "Keyframes", "STRAIGHT_EASE", "chord_deviation", "fit_keyframes", "greedy_keyframes",
           "max_deviation", "paint_channels", "timing"]

Array = NDArray[np.float64]

STRAIGHT_EASE = (1 / 3, 2 / 3)
"""The timing handles ``(p, q)`` of even timing: ``timing(u) = u``."""

EASED_SHARE = 0.8
"""The share of the tolerance a span with a timing of its own keeps to: its timing moves every vertex
along its way alike, so its misses add up over the outline (a whole edge a little behind), which a
player's coverage shows more than the same distance at a few vertices (maths §5.12)."""

_COARSE = np.array([(p, q) for p in np.linspace(0.0, 1.0, 5) for q in np.linspace(0.0, 1.0, 5)])
"""Where the search for a span's timing starts: ``(25, 2)`` handles ``(p, q)``."""

_MOVES = np.array([(1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1)], dtype=np.float64)
_FINEST = 1 / 256  # the search for a span's timing stops at this step
_BISECTIONS = 30  # halvings in the search for a keyframe's values that miss by least
_SCREEN = 24
"""Frames of a long span the search for its timing measures before checking the timing found at every frame."""
_REACH_SHARE = 1 / 16
"""The search for a span's end stops when the gap between the farthest end that fits and the nearest that
fails beyond it is this share of the span: the span is then at most that much shorter than it might be."""


def timing(u: Array, ease: Array) -> Array:
    """The fraction of the way along a span at time fraction ``u (..., M)`` for the timing handles
    ``ease (..., 2)`` = ``(p, q)``: the CSS ``cubic-bezier(1/3, p, 2/3, q)``, whose x(u) is u, so
    y(u) = 3u(1 - u)²·p + 3u²(1 - u)·q + u³ (in [0, 1] for p, q in [0, 1])."""
    p, q = ease[..., 0:1], ease[..., 1:2]
    return 3 * u * (1 - u) ** 2 * p + 3 * u * u * (1 - u) * q + u ** 3


@dataclass(frozen=True)
class Keyframes:
    """Keyframes of a value: ``frames (K,)`` increasing frame indices, ``values (K, N, D)`` and
    ``eases (K - 1, 2)`` each span's timing handles ``(p, q)`` (see :func:`timing`)."""

    frames: tuple[int, ...]
    values: Array
    eases: Array

    def handles(self) -> tuple[tuple[float, float, float, float], ...]:
        """Each span's CSS ``cubic-bezier(x1, y1, x2, y2)``; even timing as ``(0, 0, 1, 1)``."""
        return tuple((0.0, 0.0, 1.0, 1.0) if (p, q) == STRAIGHT_EASE else (1 / 3, p, 2 / 3, q)
                     for p, q in self.eases.tolist())

    def played(self, count: int) -> Array:
        """What a player draws at frames ``0 .. count - 1``: ``(count, N, D)``, held before the first
        keyframe and after the last."""
        frames = np.asarray(self.frames)
        at = np.arange(count)
        index = np.clip(np.searchsorted(frames, at, side="right") - 1, 0, len(frames) - 1)
        following = np.minimum(index + 1, len(frames) - 1)
        span = np.maximum(frames[following] - frames[index], 1)
        u = np.clip((at - frames[index]) / span, 0.0, 1.0)
        eases = np.concatenate([self.eases, [STRAIGHT_EASE]])[index]  # (count, 2)
        s = timing(u[:, None], eases)[:, :, None]  # (count, 1, 1)
        start = self.values[index]
        with np.errstate(invalid="ignore", over="ignore"):
            return np.where(s == 0, start, start + s * (self.values[following] - start))  # a keyframe: its own


def chord_deviation(values: Array, a: int, b: int) -> float:
    """The largest distance, over frames ``a..b`` and vertices, between ``values (F, N, D)`` and
    the straight chord from frame ``a`` to frame ``b`` (Euclidean over the last axis)."""
    if b <= a + 1:
        return 0.0
    s = (np.arange(a, b + 1) - a) / (b - a)
    chord = values[a] + s[:, None, None] * (values[b] - values[a])
    return float(np.sqrt(np.max(np.sum((values[a:b + 1] - chord) ** 2, axis=-1))))


def max_deviation(values: Array, keys: Keyframes | list[int] | NDArray[np.intp]) -> float:
    """The largest distance between ``values (F, N, D)`` and what ``keys`` play (frame indices: straight
    through the exact values there), over every frame and vertex where both are finite."""
    values = _flat(values)
    if not isinstance(keys, Keyframes):
        keys = _interpolating(values, [int(k) for k in keys])
    with np.errstate(invalid="ignore", over="ignore"):
        distance = np.linalg.norm(keys.played(len(values)) - values, axis=-1)
    distance = distance[np.isfinite(distance)]
    return float(distance.max()) if distance.size else 0.0


def greedy_keyframes(values: Array, tolerance: float) -> list[int]:
    """Keyframes of ``values (F, N, D)`` (F frames, N vertices or channels, D coordinates) such that
    straight interpolation between them stays within ``tolerance`` of every frame: increasing frame
    indices, the first 0 and the last F - 1 (one ``[0]`` when every frame is the first).

    From the last keyframe ``a`` the next is the farthest ``b`` whose chord is within the tolerance
    at every frame ``a..b`` (``a + 1`` always is). Non-finite values are never within tolerance of
    anything but the same frame, so they become keyframes of their own.
    """
    flat = _flat(values)
    frames = len(flat)
    if frames == 0:
        return []
    if _still(flat):
        return [0]
    keys = [0]
    a = 0
    while a < frames - 1:
        a = _farthest(flat, a, tolerance)
        keys.append(a)
    return keys


def _flat(values: Array) -> Array:
    """``values`` as ``(F, N, D)`` floats."""
    values = np.asarray(values, dtype=np.float64)
    frames = len(values)
    if values.ndim < 2:
        return values.reshape(frames, 1, 1)
    return values.reshape(frames, int(np.prod(values.shape[1:-1])), values.shape[-1])


def _still(values: Array) -> bool:
    """Whether every frame of ``values (F, N, D)`` is the first."""
    return len(values) == 1 or bool(np.array_equal(values, np.broadcast_to(values[:1], values.shape)))


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


def fit_keyframes(values: Array, tolerance: float, eased: bool = True) -> Keyframes:
    """Keyframes of ``values (F, N, D)`` whose played values (:meth:`Keyframes.played`) stay within
    ``tolerance`` of every frame at every vertex: frames increasing from 0 to F - 1 (one keyframe
    when every frame is the first), the first and last keyframes' values exact.

    From the last keyframe ``a`` (values ``z_a``) a span reaches as far as some end values ``z_b``,
    within the tolerance of frame ``b``, put every frame between within the tolerance (:func:`_room`),
    evenly timed, or else (with ``eased``) within :data:`EASED_SHARE` of it under some :func:`timing`
    (searched); the end is found by doubling steps and halving gaps (:func:`_reach`), so the work grows
    linearly with the frames. ``z_b`` is then the end that misses the span's frames by least
    (:func:`_knot`). Non-finite values are keyframes of their own, exact, as are the frames after them.
    Should rounding ever let the result stray past the tolerance, :func:`greedy_keyframes` answers instead.
    """
    flat = _flat(values)
    frames = len(flat)
    if frames == 0:
        return Keyframes((), flat, np.zeros((0, 2)))
    if _still(flat):
        return Keyframes((0,), flat[:1], np.zeros((0, 2)))
    limit = tolerance * (1 - 1e-9)
    finite = np.all(np.isfinite(flat), axis=(1, 2))
    keys, knots, eases = [0], [flat[0]], []
    while keys[-1] < frames - 1:
        b, knot, ease = _span(flat, finite, keys[-1], knots[-1], limit, eased)
        keys.append(b)
        knots.append(knot)
        eases.append(ease)
    fitted = Keyframes(tuple(keys), np.array(knots), np.array(eases))
    if max_deviation(flat, fitted) <= tolerance:
        return fitted
    return _interpolating(flat, greedy_keyframes(flat, tolerance))


def _interpolating(values: Array, keys: list[int]) -> Keyframes:
    """Keyframes at frames ``keys`` through the exact ``values (F, N, D)``, evenly timed."""
    return Keyframes(tuple(keys), values[keys], np.tile(STRAIGHT_EASE, (max(len(keys) - 1, 0), 1)))


@dataclass(frozen=True)
class _Room:
    """Spans from one keyframe to ``C`` ends: the end values ``x_b + λ·unit`` with λ in
    ``[lo, hi] (C, N)`` keep every frame between within the limit (none when lo > hi); ``unit
    (C, N, D)`` is the direction of the least-squares end correction and ``least (C, N)`` its size."""

    lo: Array
    hi: Array
    unit: Array
    least: Array


def _room(values: Array, a: int, start: Array, ends: NDArray[np.intp], eases: Array,
          limit: float | Array, between: NDArray[np.intp] | None = None) -> _Room:
    """The room of spans from frame ``a`` (values ``start (N, D)``) to each of ``ends (C,)``, timed by
    ``eases (C, 2)``, in ``values (F, N, D)``, for ``limit`` (or one per vertex, ``(N,)``), measured at
    the frames ``between (M,)`` (each after ``a``; by default every frame up to the farthest end).

    At a frame between, at fraction s of the way (timed), the end correction λ·unit moves the played
    point by s·λ·unit from the chord's point c: it is within the limit r of x when
    |s·λ·unit - (x - c)|² ≤ r², an interval of λ (a quadratic); the room is their intersection with
    the end's own [-r, r].
    """
    from ._room_kernel import room_bounds

    if between is None:
        between = a + 1 + np.arange(int(ends.max()) - a - 1)  # (M,)
    u = (between[None, :] - a) / (ends[:, None] - a)  # (C, M)
    inside = u < 1.0
    s = np.where(inside, timing(np.minimum(u, 1.0), eases), 0.0)  # (C, M), > 0 inside
    limits = np.broadcast_to(np.asarray(limit, dtype=np.float64), (values.shape[1],))
    lo, hi, unit, size = room_bounds(values, np.ascontiguousarray(start, dtype=np.float64),
                                     np.ascontiguousarray(ends, dtype=np.intp), np.ascontiguousarray(between, dtype=np.intp),
                                     np.ascontiguousarray(s), np.ascontiguousarray(inside), np.ascontiguousarray(limits))
    return _Room(lo, hi, unit, size)


def _shortfall(room: _Room, exact: NDArray[np.bool_]) -> Array:
    """How far each span misses its room, ``(C,)`` (≤ 0: it fits): the largest lo - hi over vertices;
    where ``exact (C,)``, the end must keep its values (λ = 0)."""
    with np.errstate(invalid="ignore"):
        missed = np.where(exact[:, None], np.maximum(room.lo, -room.hi), room.lo - room.hi)
        return np.where(np.isnan(missed), np.inf, missed).max(axis=-1)


def _knot(values: Array, a: int, start: Array, b: int, ease: tuple[float, float], limit: float) -> Array:
    """The end values ``(N, D)`` at frame ``b`` of a span that fits within ``limit`` from frame ``a``
    (values ``start``), timed by ``ease``: per vertex, the least-squares end in the room of the smallest
    limit that still has one (bisection), so the span misses each vertex's frames by as little as it
    can; the exact values at the last frame."""
    if b == len(values) - 1:
        return values[b]
    ends, eases = np.array([b]), np.array([ease])
    low, high = np.zeros(values.shape[1]), np.full(values.shape[1], limit)  # (N,): no room at low, room at high
    for _ in range(_BISECTIONS):
        middle = (low + high) / 2
        room = _room(values, a, start, ends, eases, middle)
        fits = room.lo[0] <= room.hi[0]
        low, high = np.where(fits, low, middle), np.where(fits, middle, high)
    room = _room(values, a, start, ends, eases, high)
    offset = np.clip(room.least[0], room.lo[0], room.hi[0])  # (N,)
    return values[b] + offset[:, None] * room.unit[0]


def _outward(values: Array, b: int, limit: float) -> Array:
    """Frame ``b``'s values ``(N, D)`` moved by ``limit`` against their second difference, away from the
    side a chord over the frames around bends to: the start that lets the next span reach furthest
    on a steady bend."""
    bend = values[b - 1] - 2 * values[b] + values[b + 1]  # (N, D)
    size = np.linalg.norm(bend, axis=-1, keepdims=True)
    return values[b] - limit * bend / np.where(size > 0, size, np.inf)


def _span(values: Array, finite: NDArray[np.bool_], a: int, start: Array, limit: float, eased: bool,
          ahead: bool = True) -> tuple[int, Array, tuple[float, float]]:
    """The keyframe after frame ``a`` (values ``start (N, D)``) in ``values (F, N, D)`` (``finite (F,)``
    where every value is): its frame, values ``(N, D)`` (:func:`_knot`) and the span's timing handles
    ``(p, q)``. The end is searched by :func:`_reach`, evenly timed, then further with a timing of its own
    (with ``eased``). A span of one frame ends at the exact values, or (looking ``ahead``) at
    :func:`_outward`'s where the next span then reaches further."""
    frames = len(values)
    if a + 2 > frames - 1 or not (finite[a] and finite[a + 1] and np.all(np.isfinite(start))):
        return a + 1, values[a + 1], STRAIGHT_EASE
    stop = a + 2 + int(np.argmin(np.append(finite[a + 2:], False)))  # the first non-finite frame after a + 1
    exact_end = frames - 1

    def even(b: int) -> tuple[float, float] | None:
        room = _room(values, a, start, np.array([b]), np.array([STRAIGHT_EASE]), limit)
        return STRAIGHT_EASE if _shortfall(room, np.array([b == exact_end]))[0] <= 0 else None

    end, ease = _reach(a, a + 1, STRAIGHT_EASE, stop, even)
    if eased and end + 1 < stop:
        end, ease = _reach(a, end, ease, stop, lambda b: _eased(values, a, start, b, limit * EASED_SHARE))
    if end > a + 1:
        return end, _knot(values, a, start, end, ease, limit if ease == STRAIGHT_EASE else limit * EASED_SHARE), ease
    knot = values[a + 1]
    if ahead and stop > a + 2:
        outward = _outward(values, a + 1, limit)
        if (_span(values, finite, a + 1, outward, limit, eased, False)[0]
                > _span(values, finite, a + 1, knot, limit, eased, False)[0]):
            knot = outward
    return a + 1, knot, STRAIGHT_EASE


def _reach(a: int, end: int, ease: tuple[float, float], stop: int,
           fits: Callable[[int], tuple[float, float] | None]) -> tuple[int, tuple[float, float]]:
    """The farthest end found before ``stop`` of a span from frame ``a`` that ``fits`` (its timing, else
    ``None``), starting from ``end`` (which fits, timed by ``ease``): ends tried at steps doubling from
    ``end`` (from twice :data:`_REACH_SHARE` of the span so far, or one frame; the last before ``stop``) up
    to the first that fails, then halving the gap between the last that fits and it down to
    :data:`_REACH_SHARE` of the span (one frame on short spans). Every step is a share of the
    span, so the same motion sampled more finely takes as many tries, each measuring the span's frames:
    a span of n frames costs a bounded multiple of n measures, not n²; a span is kept only where it fits."""
    failed, step = stop, max(1, int((end - a) * _REACH_SHARE * 2))
    while end < stop - 1:
        candidate = min(end + step, stop - 1)
        found = fits(candidate)
        if found is None:
            failed = candidate
            break
        end, ease, step = candidate, found, 2 * step
    while failed - end > max(1, int((end - a) * _REACH_SHARE)):
        middle = (end + failed) // 2
        found = fits(middle)
        if found is None:
            failed = middle
        else:
            end, ease = middle, found
    return end, ease


def _near(values: Array, a: int, start: Array, b: int, limit: float) -> bool:
    """Whether every frame between ``a`` (values ``start``) and ``b`` is within twice ``limit`` of the
    segment from ``start`` to frame ``b``'s values, at every vertex: whatever the timing (in [0, 1]) and
    the end values (within ``limit`` of frame ``b``), a span's played points are within ``limit`` of
    that segment, so a span that fits passes."""
    chord = values[b] - start  # (N, D)
    offset = values[a + 1:b] - start  # (M, N, D)
    along = np.clip(np.sum(offset * chord, axis=-1) / np.maximum(np.sum(chord * chord, axis=-1), 1e-300), 0.0, 1.0)
    return bool(np.all(np.sum((offset - along[..., None] * chord) ** 2, axis=-1) <= 4 * limit * limit))


def _eased(values: Array, a: int, start: Array, b: int, limit: float) -> tuple[float, float] | None:
    """A timing ``(p, q)`` in [0, 1]² under which the span from frame ``a`` (values ``start``) to ``b``
    fits its room; ``None`` if the search finds none. A long span is searched at :data:`_SCREEN` frames
    of it spread evenly (fewer constraints: every timing that fits all its frames fits those), the
    timing found then checked at every frame, and searched at every frame from there if it misses."""
    if not _near(values, a, start, b, limit):
        return None
    exact = b == len(values) - 1
    if b - a - 1 <= _SCREEN:
        return _timing_search(values, a, start, b, limit, exact, None, None)
    screen = np.unique(np.rint(np.linspace(a + 1, b - 1, _SCREEN)).astype(np.intp))
    found = _timing_search(values, a, start, b, limit, exact, screen, None)
    if found is None:
        return None
    return _timing_search(values, a, start, b, limit, exact, None, np.array([found]))


def _timing_search(values: Array, a: int, start: Array, b: int, limit: float, exact: bool,
                   between: NDArray[np.intp] | None, first: Array | None) -> tuple[float, float] | None:
    """The search of :func:`_eased`, measured at the frames ``between`` (``None``: every one): from the best
    of ``first (C, 2)`` timings (by default even timing and a 5 × 5 grid), it moves to the best of the eight
    neighbours at a step (1/8, or 1/64 from a given start) while that misses by less, else halves the step,
    down to 1/256; ``None`` if none fits."""

    def shortfall(eases: Array) -> Array:
        room = _room(values, a, start, np.full(len(eases), b), eases, limit, between)
        return _shortfall(room, np.full(len(eases), exact))

    candidates = np.vstack([[STRAIGHT_EASE], _COARSE]) if first is None else first
    short = shortfall(candidates)
    centre, missed = candidates[int(np.argmin(short))], float(short.min())
    step = 1 / 8 if first is None else 1 / 64
    while missed > 0:
        if step < _FINEST:
            return None
        near = np.clip(centre + step * _MOVES, 0.0, 1.0)
        short = shortfall(near)
        if short.min() < missed:
            centre, missed = near[int(np.argmin(short))], float(short.min())
        else:
            step /= 2
    return float(centre[0]), float(centre[1])


def paint_channels(fill: Array, stroke: Array, width: Array, opacity: Array, width_tolerance: float) -> Array:
    """Paint per frame as ``(F, 10, 1)`` channels in units of their tolerance, for
    :func:`greedy_keyframes` with tolerance 1: ``fill``/``stroke (F, 4)`` straight RGBA and
    ``opacity (F,)`` in [0, 1] count in 1/255 steps (each channel as a player
    interpolates it), ``width (F,)`` pixels in ``width_tolerance``."""
    channels = np.concatenate([fill * 255.0, stroke * 255.0, opacity[:, None] * 255.0,
                               width[:, None] / width_tolerance], axis=1)
    return channels[:, :, None]
