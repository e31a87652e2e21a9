"""Greedy keyframes for straight-line players (maths §5.12), against brute force and closed forms."""

from __future__ import annotations

import math

import numpy as np
import pytest

from tweenrender.core.keyframes import chord_deviation, greedy_keyframes, max_deviation, paint_channels


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
