"""Proper crossings and holes leaving their outline, against known shapes and an exact brute force."""

from __future__ import annotations

import numpy as np

from tests.core.exact_tangles import proper_pairs
from tweenrender.core.tangles import SWEEP, linear_tangles, parents, proper_crossings, tangled_times, tangles

SQUARE = np.array([[0, 0], [4, 0], [4, 4], [0, 4]], dtype=float)
INNER = np.array([[1, 1], [1, 3], [3, 3], [3, 1]], dtype=float)


def test_a_figure_eight_crosses_itself() -> None:
    bow = np.array([[0, 0], [2, 2], [2, 0], [0, 2]], dtype=float)
    assert proper_crossings([bow], [True]) == [(0, 0)]
    assert tangles([bow], [True], [None])


def test_touching_is_not_crossing() -> None:
    # a vertex lying on another edge, and an edge running along another: touching, not crossing
    pinched = np.array([[0, 0], [4, 0], [4, 4], [2, 0], [0, 4]], dtype=float)
    assert proper_crossings([pinched], [True]) == []
    folded = np.array([[0, 0], [4, 0], [2, 0], [2, 3]], dtype=float)
    assert proper_crossings([folded], [True]) == []


def test_pieces_may_overlap_but_holes_may_not_leave() -> None:
    other = SQUARE + [2.0, 2.0]
    assert proper_crossings([SQUARE, other], [True, True]) == [(0, 1)]
    assert not tangles([SQUARE, other], [True, True], [None, None])  # two pieces overlapping
    assert parents([SQUARE, INNER], [True, True]) == [None, 0]
    assert not tangles([SQUARE, INNER], [True, True], [None, 0])
    assert tangles([SQUARE, INNER + [2.5, 0.0]], [True, True], [None, 0])  # the hole crosses its outline
    assert tangles([SQUARE, INNER + [10.0, 0.0]], [True, True], [None, 0])  # the hole has left it whole


def test_open_strokes_cross_too() -> None:
    zigzag = np.array([[0, 0], [4, 0], [4, 2], [2, -1]], dtype=float)
    assert proper_crossings([zigzag], [False]) == [(0, 0)]
    assert proper_crossings([zigzag], [True]) == [(0, 0)]
    hook = np.array([[0, 0], [4, 0], [4, 2], [5, -1]], dtype=float)
    assert proper_crossings([hook], [False]) == []


def test_agrees_with_exact_brute_force_on_near_degenerate_polygons() -> None:
    """Vertices a few ulps off the lines through other edges: float signs would often be wrong."""
    rng = np.random.default_rng(7)
    disagreements = 0
    for trial in range(300):
        points = rng.integers(0, 6, (7, 2)).astype(float) * 0.1
        points += rng.integers(-2, 3, points.shape) * np.spacing(points + 1.0)
        if len(np.unique(points, axis=0)) < len(points):
            continue
        expected = proper_pairs(points, points, True, True, True) > 0
        found = proper_crossings([points], [True]) == [(0, 0)]
        disagreements += expected != found
    assert disagreements == 0


def test_tangled_times_and_linear_tangles() -> None:
    # a square whose corner 2 swings through the opposite edge: straight paths cross from some t on
    k0 = SQUARE.copy()
    k1 = SQUARE.copy()
    k1[2] = [-2.0, 2.0]
    found = linear_tangles([k0], [k1], [True])
    frames = (1.0 - SWEEP)[:, None, None] * k0 + SWEEP[:, None, None] * k1
    brute = [float(t) for t, frame in zip(SWEEP, frames) if proper_pairs(frame, frame, True, True, True)]
    assert found == brute and found and found[-1] == 1.0
    assert tangled_times([frames], [True], SWEEP) == brute


def test_orientation_signs_are_exact_where_points_coincide_or_products_underflow() -> None:
    """Coincident points (a balanced key's copies) and differences whose float products underflow to 0,
    against exact rational arithmetic."""
    from fractions import Fraction

    from tweenrender.core.tangles import _sign

    rng = np.random.default_rng(3)
    scale = np.array([1.0, 1e-170, 1e100])  # no product overflows (the loader keeps |x| ≤ 1e9)
    points = rng.integers(-2, 3, size=(4000, 3, 2)).astype(np.float64) * scale[rng.integers(0, 3, size=(4000, 1, 1))]
    points[::3, 1] = points[::3, 0]  # b = a
    points[1::5, 2, 1] = points[1::5, 0, 1]  # c level with a
    points[2::7] *= 1e-160  # tiny: most products underflow
    a, b, c = points[:, 0], points[:, 1], points[:, 2]
    found = _sign(a[:, 0], a[:, 1], b[:, 0], b[:, 1], c[:, 0], c[:, 1])

    def exact(p: np.ndarray) -> int:
        (ax, ay), (bx, by), (cx, cy) = ((Fraction(float(x)), Fraction(float(y))) for x, y in p)
        det = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
        return (det > 0) - (det < 0)

    assert found.tolist() == [exact(p) for p in points]
    assert np.count_nonzero(found == 0) > 500 and np.count_nonzero(found != 0) > 500
