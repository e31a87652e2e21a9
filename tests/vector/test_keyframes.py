"""Keyframes for straight-line players (maths §5.12), against brute force and closed forms: the greedy
interpolating chords (paint) and the fitted keyframes with free values and timed spans (paths)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tweenrender.vector.keyframes import (EASED_SHARE, Keyframes, chord_deviation, fit_keyframes, greedy_keyframes,
                                        max_deviation, paint_channels, timing)
from tests.vector_players import bezier_timing


def _played(values: np.ndarray, keys: list[int]) -> np.ndarray:
    """What a player draws at every frame: each coordinate interpolated linearly between keyframes
    (np.interp, one scalar series at a time)."""
    frames = np.arange(len(values))
    out = np.empty_like(values)
    for index in np.ndindex(values.shape[1:]):
        series = values[(slice(None), *index)]
        out[(slice(None), *index)] = np.interp(frames, keys, series[keys])
    return out


def _brute_worst(values: np.ndarray, keys: list[int]) -> float:
    """The largest distance at any frame and vertex between ``values`` and the played keyframes."""
    return float(np.linalg.norm(values - _played(values, keys), axis=-1).max())


def _wobble(frames: int, vertices: int, seed: int) -> np.ndarray:
    """A contour that turns, breathes and drifts on curved paths: ``(frames, vertices, 2)`` pixels."""
    rng = np.random.default_rng(seed)
    t = np.linspace(0.0, 1.0, frames)[:, None]
    angle = np.linspace(0, 2 * np.pi, vertices, endpoint=False)[None, :]
    radius = 40 + 10 * rng.random(vertices)[None, :] * (1 + np.sin(3 * np.pi * t))
    turn = 2.5 * t ** 2
    x = 200 + 60 * np.sin(2 * t) + radius * np.cos(angle + turn)
    y = 150 + 30 * t ** 3 + radius * np.sin(angle + turn)
    return np.stack([x, y], axis=-1)


@pytest.mark.parametrize("seed", [0, 1, 2])
@pytest.mark.parametrize("tolerance", [0.1, 0.25, 1.0])
def test_every_frame_within_tolerance_by_brute_force(seed: int, tolerance: float) -> None:
    values = _wobble(61, 12, seed)
    keys = greedy_keyframes(values, tolerance)
    assert keys[0] == 0 and keys[-1] == 60 and keys == sorted(set(keys))
    assert _brute_worst(values, keys) <= tolerance + 1e-9
    assert max_deviation(values, keys) == pytest.approx(_brute_worst(values, keys), abs=1e-9)
    assert len(keys) < 61  # curved, but far fewer than every frame


def test_each_keyframe_is_the_farthest_whose_chord_holds() -> None:
    values = _wobble(40, 6, 3)
    tolerance = 0.25
    keys = greedy_keyframes(values, tolerance)
    for a, b in zip(keys, keys[1:]):
        for later in range(b + 1, 40):  # every farther frame breaks the chord somewhere (brute force)
            assert _brute_worst(values[a:later + 1], [0, later - a]) > tolerance


def test_linear_motion_needs_two_keyframes() -> None:
    start = np.array([[0.0, 0.0], [10.0, 0.0], [5.0, 8.0]])
    end = np.array([[300.0, 40.0], [250.0, 90.0], [100.0, 120.0]])
    s = np.linspace(0.0, 1.0, 97)[:, None, None]
    assert greedy_keyframes((1 - s) * start + s * end, 1e-6) == [0, 96]


def test_still_values_need_one_keyframe() -> None:
    assert greedy_keyframes(np.ones((20, 4, 2)), 0.25) == [0]
    assert greedy_keyframes(np.ones((1, 4, 2)), 0.25) == [0]


@pytest.mark.parametrize("radius, step_degrees, tolerance", [(100.0, 2.0, 0.25), (300.0, 1.0, 0.25),
                                                               (50.0, 3.0, 1.0)])
def test_rotation_keyframes_match_the_closed_form_span(radius: float, step_degrees: float,
                                                       tolerance: float) -> None:
    """A point turning at a steady rate: every span of k frames deviates alike, the largest distance
    from the chord of e^{i·0} … e^{i·kω} to the points e^{ijω} (complex numbers); the greedy spans
    are the longest k within the tolerance, so there are ceil((F - 1) / k) + 1 keyframes."""
    omega = math.radians(step_degrees)
    frames = 181
    turns = np.exp(1j * omega * np.arange(frames)) * radius
    values = np.stack([turns.real, turns.imag], axis=-1)[:, None, :]

    def deviation(k: int) -> float:
        j = np.arange(k + 1)
        arc = np.exp(1j * omega * j)
        chord = 1 + j / k * (np.exp(1j * omega * k) - 1)
        return float(np.abs(arc - chord).max() * radius)

    longest = max(k for k in range(1, frames) if deviation(k) <= tolerance)
    keys = greedy_keyframes(values, tolerance)
    assert len(keys) == math.ceil((frames - 1) / longest) + 1
    # and by hand: a chord over k steps sags r·(1 - cos(kω/2)) at its middle, so k ≤ 2·acos(1 - tol/r)/ω
    bound = 2 * math.acos(1 - tolerance / radius) / omega
    assert longest <= bound + 1
    assert len(keys) >= (frames - 1) / (bound + 1) + 1


def test_chord_deviation_closed_form() -> None:
    # a point on a parabola y = x², sampled at x = 0, 1, 2: the chord from 0 to 2 misses x = 1 by 1
    values = np.array([[[0.0, 0.0]], [[1.0, 1.0]], [[2.0, 4.0]]])
    assert chord_deviation(values, 0, 2) == pytest.approx(1.0)
    assert chord_deviation(values, 0, 1) == 0.0


def test_non_finite_frames_are_keyframes_of_their_own() -> None:
    values = np.linspace(0, 1, 10)[:, None, None] * np.ones((10, 2, 2))
    values[4] = np.nan
    keys = greedy_keyframes(values, 0.25)
    assert 3 in keys and 4 in keys and 5 in keys


def test_paint_channels_count_in_tolerance_units() -> None:
    fill = np.array([[1.0, 0.0, 0.0, 1.0], [0.0, 0.0, 1.0, 1.0]])
    stroke = np.zeros((2, 4))
    channels = paint_channels(fill, stroke, np.array([2.0, 3.0]), np.array([1.0, 0.5]), 0.25)
    assert channels.shape == (2, 10, 1)
    assert channels[1, 0, 0] - channels[0, 0, 0] == pytest.approx(-255.0)
    assert channels[0, 8, 0] - channels[1, 8, 0] == pytest.approx(127.5)
    assert channels[1, 9, 0] - channels[0, 9, 0] == pytest.approx(4.0)


# -- fitted keyframes: values free within the tolerance, each span timed by a cubic Bézier ---------------

def _replayed(keys: Keyframes, frames: int) -> np.ndarray:
    """What a player draws from ``keys`` at every frame, frame by frame: the span's fraction of time
    through its CSS handles, then straight between the span's keyframe values."""
    out = np.empty((frames, *keys.values.shape[1:]))
    for (a, b), handles, start, end in zip(zip(keys.frames, keys.frames[1:]), keys.handles(), keys.values,
                                           keys.values[1:]):
        s = bezier_timing((np.arange(a, b + 1) - a) / (b - a), handles)
        out[a:b + 1] = start + s[:, None, None] * (end - start)
    out[list(keys.frames)] = keys.values  # at a keyframe, its own values (whatever the next holds)
    if len(keys.frames) == 1:
        out[:] = keys.values[0]
    return out


def _fitted_worst(values: np.ndarray, keys: Keyframes) -> float:
    """The largest distance at any finite frame and vertex between ``values`` and the replayed keyframes."""
    with np.errstate(invalid="ignore"):
        distance = np.linalg.norm(_replayed(keys, len(values)) - values, axis=-1)
    assert np.all(np.isfinite(distance) | ~np.all(np.isfinite(values), axis=-1))
    return float(distance[np.isfinite(distance)].max())


def _rough(frames: int, vertices: int, seed: int) -> np.ndarray:
    """Not smooth: a random walk with jumps, corners and still stretches: ``(frames, vertices, 2)``."""
    rng = np.random.default_rng(seed)
    steps = rng.normal(0, 1.5, (frames, vertices, 2)) * (rng.random((frames, 1, 1)) < 0.7)
    steps[rng.random(frames) < 0.1] *= 20  # jumps
    return 100 + np.cumsum(steps, axis=0)


def _check_fit(values: np.ndarray, tolerance: float, **options: bool) -> Keyframes:
    keys = fit_keyframes(values, tolerance, **options)
    frames = len(values)
    assert keys.frames[0] == 0 and keys.frames[-1] == frames - 1 and list(keys.frames) == sorted(set(keys.frames))
    assert keys.values.shape == (len(keys.frames), *values.shape[1:]) and keys.eases.shape == (len(keys.frames) - 1, 2)
    assert np.all((keys.eases >= 0) & (keys.eases <= 1))  # SMIL's keySplines stay within [0, 1]
    assert np.array_equal(keys.values[0], values[0], equal_nan=True)  # the first and last keyframes are exact
    assert np.array_equal(keys.values[-1], values[-1], equal_nan=True)
    assert _fitted_worst(values, keys) <= tolerance * (1 + 1e-9)
    with np.errstate(invalid="ignore"):
        distance = np.linalg.norm(_replayed(keys, frames) - values, axis=-1)  # (F, N)
    for (a, b), handles in zip(zip(keys.frames, keys.frames[1:]), keys.handles()):
        if handles != (0.0, 0.0, 1.0, 1.0):  # a timed span keeps to its share of the tolerance after its start
            assert np.nanmax(distance[a + 1:b + 1]) <= EASED_SHARE * tolerance * (1 + 1e-9)
    assert max_deviation(values, keys) == pytest.approx(_fitted_worst(values, keys), abs=1e-6)
    return keys


@pytest.mark.parametrize("seed", [0, 1, 2])
@pytest.mark.parametrize("tolerance", [0.1, 0.25, 1.0])
def test_fitted_keyframes_hold_the_tolerance_at_every_frame(seed: int, tolerance: float) -> None:
    smooth = _wobble(61, 12, seed)
    keys = _check_fit(smooth, tolerance)
    straight = _check_fit(smooth, tolerance, eased=False)
    assert np.all(straight.eases == (1 / 3, 2 / 3))
    # free values reach further than chords through the exact samples on smooth motion
    assert len(keys.frames) <= len(straight.frames) < len(greedy_keyframes(smooth, tolerance))
    _check_fit(_rough(70, 5, seed), tolerance)
    _check_fit(_rough(70, 5, seed), tolerance, eased=False)


def test_fitted_keyframes_of_still_and_tiny_inputs() -> None:
    assert fit_keyframes(np.ones((20, 4, 2)), 0.25).frames == (0,)
    assert fit_keyframes(np.ones((1, 4, 2)), 0.25).frames == (0,)
    assert fit_keyframes(np.zeros((0, 4, 2)), 0.25).frames == ()
    two = np.array([[[0.0, 0.0]], [[5.0, 1.0]]])
    assert _check_fit(two, 0.25).frames == (0, 1)
    # held, then moving on a straight line at a steady pace: two spans, the hold exact
    hold = np.concatenate([np.zeros((10, 3, 2)), np.linspace(0, 1, 30)[1:, None, None] * np.array([[40.0, 9.0]] * 3)])
    keys = _check_fit(hold, 1e-6, eased=False)
    assert keys.frames == (0, 9, 38)


def test_non_finite_frames_are_exact_keyframes_of_their_own() -> None:
    values = _wobble(40, 4, 5)
    values[12, 1] = np.nan
    values[25] = np.inf
    keys = _check_fit(values, 0.25)
    for bad in (12, 25):
        index = keys.frames.index(bad)
        assert keys.frames[index - 1] == bad - 1 and keys.frames[index + 1] == bad + 1
        assert np.array_equal(keys.values[index], values[bad], equal_nan=True)
        assert np.array_equal(keys.values[index + 1], values[bad + 1])  # the first after starts exact


@pytest.mark.parametrize("radius, step_degrees, tolerance", [(100.0, 2.0, 0.25), (300.0, 1.0, 0.25),
                                                               (50.0, 3.0, 1.0), (200.0, 1.0, 0.1)])
def test_free_values_on_a_turn_match_the_closed_form_span(radius: float, step_degrees: float,
                                                          tolerance: float) -> None:
    """A point turning at a steady rate. Through the exact points a chord over k steps may span
    k_exact (the rotation test above); with both ends moved out to radius R + d (d ≤ tolerance) its
    frames stay within the tolerance of the arc for the longest k_free over d, about √2·k_exact
    (the sag 2·tolerance instead of one: R(1 - cos(kω/2)) ≤ 2·tol). The fitted keyframes span k_free
    between the first span (from the exact start) and the last (to the exact end)."""
    omega = math.radians(step_degrees)
    frames = 181
    turns = np.exp(1j * omega * np.arange(frames)) * radius
    values = np.stack([turns.real, turns.imag], axis=-1)[:, None, :]

    def deviation(k: int, out: float) -> float:
        j = np.arange(k + 1)
        chord = (radius + out) * (1 + j / k * (np.exp(1j * omega * k) - 1))
        return float(np.abs(np.exp(1j * omega * j) * radius - chord).max())

    exact_span = max(k for k in range(1, frames) if deviation(k, 0.0) <= tolerance)
    free_span = max(k for k in range(1, frames)
                    if min(deviation(k, d) for d in np.linspace(0.0, tolerance, 401)) <= tolerance)
    assert free_span > exact_span
    assert free_span <= 2 * math.acos(1 - 2 * tolerance / radius) / omega + 1  # the sag bound
    keys = _check_fit(values, tolerance, eased=False)
    spans = np.diff(keys.frames)
    assert np.all(spans[1:-1] == free_span) and free_span - 1 <= spans[0] <= free_span
    assert len(keys.frames) <= math.ceil((frames - 1) / free_span) + 2
    assert len(greedy_keyframes(values, tolerance)) == math.ceil((frames - 1) / exact_span) + 1


def test_a_straight_accelerating_motion_is_one_eased_span() -> None:
    """x(t) = A + (B - A)·(t / T)², a straight line at a growing pace: the timing u² is the CSS
    cubic-bezier(1/3, 0, 2/3, 1/3), so one span holds it, while even timing needs many."""
    u = np.linspace(0.0, 1.0, 41)[:, None, None]
    start, end = np.array([[10.0, 20.0], [0.0, 0.0]]), np.array([[90.0, 60.0], [30.0, -40.0]])
    values = start + u ** 2 * (end - start)
    keys = _check_fit(values, 0.25)
    assert keys.frames == (0, 40)
    assert len(_check_fit(values, 0.25, eased=False).frames) > 4
    assert keys.handles()[0][::2] == (1 / 3, 2 / 3)


def test_timing_is_the_css_bezier_it_names() -> None:
    u = np.linspace(0.0, 1.0, 101)
    for p, q in [(0.0, 1 / 3), (1.0, 0.0), (0.2, 0.9), (1 / 3, 2 / 3)]:
        keys = Keyframes((0, 1), np.zeros((2, 1, 1)), np.array([[p, q]]))
        (handles,) = keys.handles()
        assert timing(u, np.array([p, q])) == pytest.approx(bezier_timing(u, handles), abs=1e-9)
    assert Keyframes((0, 1), np.zeros((2, 1, 1)), np.array([[1 / 3, 2 / 3]])).handles() == ((0.0, 0.0, 1.0, 1.0),)


@pytest.mark.parametrize("seed", range(3))
def test_a_spans_room_is_every_end_correction_that_keeps_its_frames_within_the_limit(seed: int) -> None:
    """The room of spans (``keyframes._room``) against brute force: an end moved by λ along the room's direction
    keeps every frame between within the limit (the player's point ``start + s·(end + λ·unit - start)``) exactly
    when λ lies in ``[lo, hi]``, tried for λ across and just outside the room."""
    from tweenrender.vector.keyframes import _room

    rng = np.random.default_rng(seed)
    frames, vertices = 14, 5
    values = np.cumsum(rng.normal(size=(frames, vertices, 2)), axis=0)
    a, ends = 2, np.array([6, 9, 13])
    eases = np.array([[1 / 3, 2 / 3], [0.2, 0.9], [0.6, 0.1]])
    limit = np.array([0.8, 1.5, 3.0, 6.0, 12.0])
    start = values[a] + 0.1
    room = _room(values, a, start, ends, eases, limit)
    for c, (b, ease) in enumerate(zip(ends, eases)):
        s = bezier_timing((np.arange(a + 1, b) - a) / (b - a), (1 / 3, ease[0], 2 / 3, ease[1]))  # (M,)
        for n in range(vertices):
            lo, hi = room.lo[c, n], room.hi[c, n]
            tried = np.linspace(-limit[n] - 1, limit[n] + 1, 401)
            if lo <= hi:
                tried = np.concatenate([tried, [lo + 1e-9, hi - 1e-9, lo - 1e-6, hi + 1e-6]])
            for lam in tried:
                end = values[b, n] + lam * room.unit[c, n]
                played = start[n] + s[:, None] * (end - start[n])
                keeps = np.all(np.linalg.norm(played - values[a + 1:b, n], axis=-1) <= limit[n]) \
                    and abs(lam) <= limit[n]
                assert keeps == (lo <= lam <= hi), (c, n, lam, lo, hi)
