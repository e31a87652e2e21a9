"""Contours of one shape meeting (DESIGN turn 4 ``crossings`` and ``stroke_crossings``): motions whose answer
is known by construction, each checked against shapely too, and exact point tests against rational arithmetic."""

from __future__ import annotations

from fractions import Fraction

import numpy as np

from tests.core.shapely_tangles import tangled
from tweenrender.core.tangles import SWEEP, apart_in_keys, contact_times, point_states, proper_crossings

SQUARE = np.array([[0, 0], [4, 0], [4, 4], [0, 4]], dtype=float)
BIG = np.array([[0, 0], [10, 0], [10, 10], [0, 10]], dtype=float)
SMALL = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)


def straight(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Straight paths from ``a`` to ``b`` over :data:`SWEEP`: ``(T, N, 2)``."""
    return (1.0 - SWEEP)[:, None, None] * a + SWEEP[:, None, None] * b


def shapely_times(frames: list[np.ndarray], closed: list[bool]) -> tuple[list[float], list[float]]:
    """The swept t at which shapely finds the closed contours, and the strokes, tangled."""
    keys0, keys1 = [f[0] for f in frames], [f[-1] for f in frames]
    found = [tangled([f[k] for f in frames], keys0, keys1, closed) for k in range(len(SWEEP))]
    return ([float(t) for t, (shut, _) in zip(SWEEP, found) if shut],
            [float(t) for t, (_, stroke) in zip(SWEEP, found) if stroke])


def test_two_squares_swapping_places_meet_while_they_overlap() -> None:
    a0, b0 = SQUARE, 0.75 * SQUARE + [10.0, 1.0]  # sides 4 and 3 whose lower left corners swap
    a1, b1 = SQUARE + [10.0, 1.0], 0.75 * SQUARE
    frames = [straight(a0, a1), straight(b0, b1)]
    crossings, strokes = contact_times(frames, [True, True], SWEEP, [a0, b0], [a1, b1])
    # a spans x = 10t .. 10t + 4, b x = 10 - 10t .. 13 - 10t: they overlap for 0.3 < t < 0.65 (at
    # t = 0.5 b lies inside a, corner on corner, and no edge crosses)
    assert crossings == [float(t) for t in SWEEP if 0.3 + 1e-9 < t < 0.65 - 1e-9]
    assert 0.5 in crossings
    assert strokes == []
    # shapely also counts the two t at which they only touch, side on side
    touching = {float(SWEEP[30]), float(SWEEP[65])}
    assert crossings == [t for t in shapely_times(frames, [True, True])[0] if t not in touching]


def test_a_piece_passing_through_another_counts_while_it_is_inside_too() -> None:
    s0, s1 = SMALL + [-3.0, 4.5], SMALL + [12.0, 4.5]
    frames = [straight(BIG, BIG), straight(s0, s1)]
    crossings, _ = contact_times(frames, [True, True], SWEEP, [BIG, s0], [BIG, s1])
    # the small square's left side runs at x = -3 + 15t: it overlaps the big one while -1 < x < 10
    assert crossings == [float(t) for t in SWEEP if 2 / 15 + 1e-9 < t < 13 / 15 - 1e-9]
    middle = int(np.flatnonzero(SWEEP == 0.5)[0])
    assert proper_crossings([f[middle] for f in frames], [True, True]) == []  # wholly inside: no edge crosses
    assert 0.5 in crossings
    assert crossings == shapely_times(frames, [True, True])[0]


def test_a_hole_sliding_out_of_its_outline_tangles_from_where_it_crosses() -> None:
    h0, h1 = SMALL + [4.0, 4.0], SMALL + [14.0, 4.0]
    frames = [straight(BIG, BIG), straight(h0, h1)]
    crossings, _ = contact_times(frames, [True, True], SWEEP, [BIG, h0], [BIG, h1])
    # the hole's right side runs at x = 5 + 10t: it touches the outline at t = 0.5, crosses after
    assert crossings == [float(t) for t in SWEEP if t > 0.5]
    assert apart_in_keys([BIG, h0], [BIG, h1], [True, True]).parent == (None, 0)


def test_a_hole_passing_out_through_its_outline_where_it_only_touches_it_tangles() -> None:
    # a diamond hole bulging right by 16 t (1 - t): at t = 0.5 its top and bottom corners lie on the
    # outline's right side, its right corner outside: no edge crosses properly, yet it is partly out
    diamond = np.array([[4.0, 5.0], [6.0, 3.0], [8.0, 5.0], [6.0, 7.0]])
    bulge = (16.0 * SWEEP * (1.0 - SWEEP))[:, None, None] * np.array([1.0, 0.0])
    frames = [straight(BIG, BIG), straight(diamond, diamond) + bulge]
    middle = int(np.flatnonzero(SWEEP == 0.5)[0])
    assert proper_crossings([f[middle] for f in frames], [True, True]) == []
    crossings, _ = contact_times(frames, [True, True], SWEEP, [BIG, diamond], [BIG, diamond])
    # out from where the right corner passes x = 10: 8 + 16 t (1 - t) > 10
    assert crossings == [float(t) for t in SWEEP if 16.0 * t * (1.0 - t) > 2.0 + 1e-9]
    assert 0.5 in crossings and crossings == shapely_times(frames, [True, True])[0]


def test_a_hole_passing_into_a_notch_corner_to_corner_tangles() -> None:
    # an outline with a notch cut into its right side (x 6 to 10, y 4 to 6) and a diamond hole moving
    # right by 10 t (1 - t) - 2.5: at t = 0.5 its top and bottom corners are the notch's inner corners
    # and its right corner lies in the notch; no edge crosses properly, its box stays in the outline's
    notched = np.array([[0, 0], [10, 0], [10, 4], [6, 4], [6, 6], [10, 6], [10, 10], [0, 10]], dtype=float)
    diamond = np.array([[4.0, 5.0], [6.0, 4.0], [8.0, 5.0], [6.0, 6.0]])
    shift = (10.0 * SWEEP * (1.0 - SWEEP) - 2.5)[:, None, None] * np.array([1.0, 0.0])
    frames = [straight(notched, notched), straight(diamond, diamond) + shift]
    key = diamond - [2.5, 0.0]
    middle = int(np.flatnonzero(SWEEP == 0.5)[0])
    assert proper_crossings([f[middle] for f in frames], [True, True]) == []
    crossings, _ = contact_times(frames, [True, True], SWEEP, [notched, key], [notched, key])
    # in the notch from where the right corner passes x = 6: 8 + 10 t (1 - t) - 2.5 > 6
    assert crossings == [float(t) for t in SWEEP if 10.0 * t * (1.0 - t) > 0.5 + 1e-9]
    assert 0.5 in crossings and crossings == shapely_times(frames, [True, True])[0]


def shrinking(points: np.ndarray, centre: np.ndarray, stop: float) -> np.ndarray:
    """``points (N, 2)`` scaled about ``centre (2,)`` from 1 at t = 0 to 0 at ``stop``, one point after it:
    ``(T, N, 2)`` over :data:`SWEEP`."""
    scale = np.clip(1.0 - SWEEP / stop, 0.0, 1.0)[:, None, None]
    return centre + scale * (points - centre)


def test_a_contour_shrinking_to_a_point_across_another_tangles_wherever_its_point_ends() -> None:
    # a piece beside the big square shrinks about a centre while it slides into the square: its point in
    # the last key lies inside the square, outside in the first; it is drawn while it lasts, so the pair
    # is apart in the only key that draws both, and its crossing the square's side is a tangle
    piece = SMALL * 2.0 + [11.0, 4.0]  # x 11 .. 13, y 4 .. 6
    slide = (-6.0 * SWEEP)[:, None, None] * np.array([1.0, 0.0])
    frames = [straight(BIG, BIG), shrinking(piece, np.array([12.0, 5.0]), 0.6) + slide]
    k0s, k1s = [BIG, piece], [BIG, frames[1][-1]]
    assert np.ptp(k1s[1], axis=0).max() == 0.0  # one point, inside the square
    crossings, _ = contact_times(frames, [True, True], SWEEP, k0s, k1s)
    # its left side at 12 - 6t - (1 - t / 0.6): on x = 10 at t = 1 / (6 - 1 / 0.6) = 0.2308; its right side
    # at 12 - 6t + (1 - t / 0.6) passes x = 10 at t = 3 / (6 + 1 / 0.6) = 0.3913; from then it is inside
    # the square, a piece of it still there until t = 0.6
    left, right = 1.0 / (6.0 - 1.0 / 0.6), 3.0 / (6.0 + 1.0 / 0.6)
    expected = [float(t) for t in SWEEP if left + 1e-9 < t < 0.6 - 1e-9]
    assert crossings == expected and float(SWEEP[30]) in crossings and right < 0.6
    assert crossings == shapely_times(frames, [True, True])[0]


def test_a_contour_shrinking_to_a_point_clear_of_the_others_never_tangles() -> None:
    # the same piece shrinking where it is: its point lies outside the square in the last key, and the
    # square moving over that point after the piece is gone is no tangle
    piece = SMALL * 2.0 + [11.0, 4.0]
    frames = [straight(BIG, BIG + [4.0, 0.0]), shrinking(piece, np.array([12.0, 5.0]), 0.3)]
    k0s, k1s = [BIG, piece], [BIG + [4.0, 0.0], frames[1][-1]]
    assert contact_times(frames, [True, True], SWEEP, k0s, k1s) == ([], [])
    assert shapely_times(frames, [True, True]) == ([], [])


def test_pieces_touching_in_a_key_may_overlap_but_pieces_apart_may_not() -> None:
    bulge = 2.0 * np.sin(np.pi * SWEEP)[:, None, None] * np.array([-1.0, 0.0])
    for gap, meet in ((0.0, False), (0.5, True)):
        b = SQUARE + [4.0 + gap, 1.0]
        frames = [straight(SQUARE, SQUARE), straight(b, b) + bulge]
        crossings, _ = contact_times(frames, [True, True], SWEEP, [SQUARE, b], [SQUARE, b])
        # b slides 2 sin(πt) towards a: they overlap once that is more than the gap
        expected = [float(t) for t in SWEEP if 2.0 * np.sin(np.pi * t) > gap + 1e-9] if meet else []
        assert crossings == expected, gap
        if meet:
            assert crossings == shapely_times(frames, [True, True])[0]


def test_pieces_moving_together_never_meet() -> None:
    a, b = SQUARE, SQUARE + [6.0, 0.0]
    frames = [straight(a, a + [3.0, 7.0]), straight(b, b + [3.0, 7.0])]
    assert contact_times(frames, [True, True], SWEEP, [a, b], [a + [3, 7], b + [3, 7]]) == ([], [])


def test_strokes_crossing_are_counted_apart() -> None:
    line0, line1 = np.array([[-6.0, 2.0], [-4.0, 2.0]]), np.array([[8.0, 2.0], [10.0, 2.0]])
    frames = [straight(SQUARE, SQUARE), straight(line0, line1)]
    crossings, strokes = contact_times(frames, [True, False], SWEEP, [SQUARE, line0], [SQUARE, line1])
    # the line runs from x = -6 + 14t to x + 2: it crosses x = 0 and x = 4, and lies inside between
    x = -6.0 + 14.0 * SWEEP
    expected = [float(t) for t, at in zip(SWEEP, x) if at < 0 < at + 2 or at < 4 < at + 2]
    assert crossings == [] and strokes == expected
    assert 0.5 not in strokes  # wholly inside the square: a stroke has no inside to come into
    assert shapely_times(frames, [True, False]) == ([], strokes)


def test_a_contour_crossing_itself_goes_to_its_own_list() -> None:
    bow0 = np.array([[0, 0], [2, 0], [2, 2], [0, 2]], dtype=float)
    bow1 = np.array([[0, 0], [2, 2], [2, 0], [0, 2]], dtype=float)  # a figure eight
    crossings, strokes = contact_times([straight(bow0, bow1)], [True], SWEEP, [bow0], [bow1])
    assert crossings and crossings[-1] == 1.0 and strokes == []
    crossings, strokes = contact_times([straight(bow0, bow1)], [False], SWEEP, [bow0], [bow1])
    assert crossings == [] and strokes and strokes[-1] == 1.0


def _exact_state(point: np.ndarray, polygon: np.ndarray) -> int:
    """1 inside (even-odd), -1 outside, 0 on the outline, in rational arithmetic."""
    x, y = (Fraction(float(v)) for v in point)
    inside = False
    for a, b in zip(polygon, np.roll(polygon, -1, axis=0)):
        (ax, ay), (bx, by) = (Fraction(float(v)) for v in a), (Fraction(float(v)) for v in b)
        side = (bx - ax) * (y - ay) - (by - ay) * (x - ax)
        if side == 0 and min(ax, bx) <= x <= max(ax, bx) and min(ay, by) <= y <= max(ay, by):
            return 0
        if (ay > y) != (by > y) and x < ax + (y - ay) * (bx - ax) / (by - ay):
            inside = not inside
    return 1 if inside else -1


def test_point_states_are_exact_on_and_a_few_ulps_off_the_outline() -> None:
    rng = np.random.default_rng(11)
    disagreements = checked = 0
    for _ in range(60):
        polygon = rng.integers(0, 8, (6, 2)) * 0.1 + rng.integers(0, 3, (6, 2)) * 0.7
        a, b = polygon, np.roll(polygon, -1, axis=0)
        share = rng.choice([0.0, 0.25, 0.5, 0.75], (6, 1))
        points = a + share * (b - a)  # on the edges' lines, or within rounding of them
        points = np.concatenate([points, points + rng.integers(-2, 3, points.shape) * np.spacing(points + 1.0)])
        found = point_states(points[None], polygon[None])[0]
        for p, state in zip(points, found):
            checked += 1
            disagreements += int(state) != _exact_state(p, polygon)
    assert checked == 720 and disagreements == 0
