"""Contours of a shape meeting, many contours at once: the answers equal brute force (every pair, and
shapely) on small random drawings, and the point-in-polygon work grows with the contours, not with
their pairs."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from tests.core.shapely_tangles import parents as shapely_parents
from tests.core.shapely_tangles import tangled
from tweenrender.core import tangles
from tweenrender.core.tangles import contact_times, held_pairs, parents

T = np.linspace(0.0, 1.0, 11)


def square(x: float, y: float, side: float) -> np.ndarray:
    return np.array([[x, y], [x + side, y], [x + side, y + side], [x, y + side]], dtype=float)


def rings(n: int, shift: float = 0.0) -> list[np.ndarray]:
    """``n`` squares of side 3 on a grid of pitch 5, each with a square hole of side 1 in it: 2 n contours."""
    cols = int(np.ceil(np.sqrt(n)))
    out = []
    for i in range(n):
        x, y = 5.0 * (i % cols) + shift, 5.0 * (i // cols) + shift
        out += [square(x, y, 3.0), square(x + 1.0, y + 1.0, 1.0)[::-1]]
    return out


def straight(k0s: list[np.ndarray], k1s: list[np.ndarray]) -> list[np.ndarray]:
    return [(1.0 - T)[:, None, None] * a + T[:, None, None] * b for a, b in zip(k0s, k1s)]


def test_held_pairs_equal_every_pair_tested() -> None:
    rng = np.random.default_rng(5)
    for _ in range(30):
        lo = rng.integers(0, 6, size=(12, 2)).astype(float)
        boxes = np.concatenate([lo, lo + rng.integers(0, 5, size=(12, 2))], axis=1)
        boxes[rng.integers(0, 12)] = [np.inf, np.inf, -np.inf, -np.inf]  # an empty contour's box
        p, q = held_pairs(boxes)
        real = [i for i in range(12) if boxes[i, 0] <= boxes[i, 2]]
        brute = {(i, j) for i, j in itertools.permutations(real, 2)
                 if boxes[j, 0] >= boxes[i, 0] and boxes[j, 1] >= boxes[i, 1]
                 and boxes[j, 2] <= boxes[i, 2] and boxes[j, 3] <= boxes[i, 3]}
        assert sorted(zip(p.tolist(), q.tolist())) == sorted(brute)


def random_squares(rng: np.random.Generator, n: int) -> list[np.ndarray]:
    """``n`` squares at random places and sizes (some inside others, some crossing)."""
    return [square(*rng.uniform(0.0, 8.0, 2), rng.uniform(0.5, 5.0)) for _ in range(n)]


def test_parents_equal_shapely_on_random_squares() -> None:
    rng = np.random.default_rng(21)
    for _ in range(20):
        contours = random_squares(rng, 7)
        assert parents(contours, [True] * 7) == shapely_parents(contours, [True] * 7)


def test_contact_times_equal_shapely_on_random_moving_squares() -> None:
    rng = np.random.default_rng(8)
    tangled_somewhere = 0
    for _ in range(25):
        k0s, k1s = random_squares(rng, 5), random_squares(rng, 5)
        frames = straight(k0s, k1s)
        crossings, _ = contact_times(frames, [True] * 5, T, k0s, k1s)
        expected = [float(t) for k, t in enumerate(T)
                    if tangled([f[k] for f in frames], k0s, k1s, [True] * 5)[0]]
        assert crossings == expected
        tangled_somewhere += bool(expected) and len(expected) < len(T)
    assert tangled_somewhere >= 5  # the drawings tell tangled from untangled frames


def test_squares_side_by_side_coming_to_lie_one_inside_the_other_tangle() -> None:
    big, small = square(0, 0, 4), square(10, 10, 1)
    k0s, k1s = [big, small], [big, small]
    frames = straight(k0s, k1s)
    frames[1][5] = square(1.5, 1.5, 1)  # jumps inside at t = .5 without crossing at a sampled t
    crossings, _ = contact_times(frames, [True, True], T, k0s, k1s)
    assert crossings == [0.5]


def count_point_tests(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """Count the points set against a polygon (:func:`tangles.point_states`, :func:`tangles._inside`)."""
    counted = [0]
    states, inside = tangles.point_states, tangles._inside

    def counting_states(points: np.ndarray, polygon: np.ndarray) -> np.ndarray:
        counted[0] += int(np.prod(np.shape(points)[:2]))
        return states(points, polygon)

    def counting_inside(point: np.ndarray, polygon: np.ndarray) -> bool:
        counted[0] += 1
        return inside(point, polygon)

    monkeypatch.setattr(tangles, "point_states", counting_states)
    monkeypatch.setattr(tangles, "_inside", counting_inside)
    return counted


def test_point_in_polygon_tests_grow_with_the_contours_not_their_pairs(monkeypatch: pytest.MonkeyPatch) -> None:
    counted = count_point_tests(monkeypatch)
    work = []
    for n in (100, 400):
        k0s, k1s = rings(n), rings(n, shift=0.5)
        counted[0] = 0
        crossings, strokes = contact_times(straight(k0s, k1s), [True] * (2 * n), T, k0s, k1s)
        assert crossings == [] and strokes == []  # every ring and its hole moving together
        work.append(counted[0])
    assert 0 < work[0] and work[1] <= 5 * work[0]  # 4 × the contours: 16 × the pairs


def test_anchors_equal_shapely_on_random_squares() -> None:
    from shapely.geometry import LinearRing, Point, Polygon
    from shapely.ops import nearest_points, unary_union

    from tweenrender.core.contours import anchors

    rng = np.random.default_rng(4)
    for rule in ("evenodd", "nonzero"):
        for _ in range(10):
            partner = [s if rng.random() < 0.5 else s[::-1] for s in random_squares(rng, 6)]
            alone = random_squares(rng, 8)
            found = anchors(alone, [True] * 8, partner, [True] * 6, rule)
            for contour, point in zip(alone, found):
                centre = contour.mean(axis=0)  # a square's centre of area
                hits = [Polygon(p).contains(Point(centre)) for p in partner]
                turns = [1 if LinearRing(p).is_ccw else -1 for p in partner]
                filled = sum(hits) % 2 == 1 if rule == "evenodd" else sum(h * w for h, w in zip(hits, turns)) != 0
                lines = unary_union([LinearRing(p) for p in partner])
                expected = centre if filled else np.array(nearest_points(lines, Point(centre))[0].coords[0])
                assert np.allclose(point, expected, atol=1e-9)


def test_anchors_test_points_against_the_contours_around_them_only(monkeypatch: pytest.MonkeyPatch) -> None:
    from tweenrender.core import contours

    counted = [0]
    inside = contours.inside

    def counting_inside(points: np.ndarray, polygon: np.ndarray) -> np.ndarray:
        counted[0] += len(points)
        return inside(points, polygon)

    monkeypatch.setattr(contours, "inside", counting_inside)
    work = []
    for n in (100, 400):
        partner, alone = rings(n)[::2], [square(5.0 * i + 0.5, 0.5, 2.0) for i in range(n)]
        counted[0] = 0
        found = contours.anchors(alone, [True] * n, partner, [True] * n, "nonzero")
        cols = int(np.ceil(np.sqrt(n)))  # the first row lies within the partner's first row: their own centres
        assert np.array_equal(found[:cols], [[5.0 * i + 1.5, 1.5] for i in range(cols)])
        work.append(counted[0])
    assert 0 < work[0] and work[1] <= 5 * work[0]
