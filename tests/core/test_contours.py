"""Contours: holes by nesting, pairing by position and size, anchors, open-curve correspondence
(against brute force), and paint in OKLab (against an independent colour library)."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from tweenrender.core.contours import anchor, pair_contours, roles
from tweenrender.core.correspondence.correspond import correspond_open, is_open_monotone
from tweenrender.core.paint import blend_colors, blend_paints
from tweenrender.model import Paint


def square(x: float, y: float, side: float, clockwise: bool = False) -> np.ndarray:
    points = np.array([[x, y], [x + side, y], [x + side, y + side], [x, y + side]], dtype=float)
    return points[::-1].copy() if clockwise else points


def test_roles_by_nesting_whatever_the_winding() -> None:
    outer, hole, island = square(0, 0, 10), square(2, 2, 6), square(4, 4, 2)
    for windings in itertools.product([False, True], repeat=3):
        contours = [square(0, 0, 10, windings[0]), square(2, 2, 6, windings[1]), square(4, 4, 2, windings[2])]
        assert roles(contours, [True, True, True]) == ["outer", "hole", "outer"]
    assert roles([outer, hole, square(20, 0, 3)], [True, True, False]) == ["outer", "hole", "open"]
    assert roles([island, outer], [True, True]) == ["hole", "outer"]


def test_roles_pass_over_the_copies_balancing_stacks_on_a_vertex() -> None:
    """Balancing by copies stacks vertices (a zero-length first edge); the outline of a ring stays the
    outer one though its vertex mean lies in the hole."""
    outer = np.array([[0, 0], [0, 0], [0, 0], [10, 0], [10, 10], [0, 10]], dtype=float)
    hole = square(3, 3, 4, clockwise=True)
    assert roles([outer, hole], [True, True]) == ["outer", "hole"]
    assert roles([hole, outer[::-1]], [True, True]) == ["hole", "outer"]


def test_contours_pair_by_position_not_drawing_order() -> None:
    left, right = square(0, 0, 2), square(10, 0, 4)
    a = [left, right]
    b = [square(10.5, 0.2, 4), square(0.1, 0, 2)]  # drawn the other way round
    assert pair_contours(a, [True, True], b, [True, True]) == [(0, 1), (1, 0)]


def test_holes_pair_with_holes_and_the_rest_has_no_partner() -> None:
    a = [square(0, 0, 10), square(2, 2, 3), square(6, 6, 2)]  # an outline with two holes
    b = [square(0, 0, 10), square(5.5, 5.5, 2.5)]  # one hole, where a's second was
    assert roles(a, [True] * 3) == ["outer", "hole", "hole"]
    assert pair_contours(a, [True] * 3, b, [True] * 2) == [(0, 0), (1, None), (2, 1)]
    assert pair_contours(b, [True] * 2, a, [True] * 3) == [(0, 0), (1, 2), (None, 1)]


def test_a_ring_drawn_as_one_contour_pairs_with_the_outline_it_is_drawn_like() -> None:
    """A square outline drawn as an outer and its hole, a small square in the middle; the other key draws a
    thin ring as one contour (out round the outside, in through a notch, back round the inside, as some
    icon sets draw outlines). The ring's own area (24² − 22², about 92) is that of a square of side 9.6,
    close to the small square's 8; to the eye it is nearer its 24 × 24 hull (the geometric mean of the two
    areas, a square of side 15.2), and the outline of side 18 is its partner: paired the other way, the small
    square grows out through the outline it sits in."""
    a = [square(3, 3, 18), square(5, 5, 14, clockwise=True), square(8, 8, 8)]
    ring = np.array([[0, 0], [24, 0], [24, 24], [0, 24], [0, 1], [1, 1], [1, 23], [23, 23], [23, 1], [2, 1]],
                    dtype=float)
    assert roles(a, [True] * 3) == ["outer", "hole", "outer"] and roles([ring], [True]) == ["outer"]
    assert pair_contours(a, [True] * 3, [ring], [True]) == [(0, 0), (1, None), (2, None)]


def test_anchor_is_the_centre_inside_the_partner_else_its_nearest_outline_point() -> None:
    partner = [square(0, 0, 10)]
    inside = square(4, 4, 1)
    assert anchor(inside, partner, [True], "nonzero").tolist() == [4.5, 4.5]
    outside = square(14, 4, 2)  # centre (15, 5): nearest point of the partner is (10, 5)
    assert anchor(outside, partner, [True], "nonzero").tolist() == [10.0, 5.0]
    ring = [square(0, 0, 10), square(2, 2, 6, clockwise=True)]  # the centre (5, 4) is in the hole
    assert anchor(square(4, 3, 2), ring, [True, True], "nonzero").tolist() == [5.0, 2.0]


def _brute_open(a: np.ndarray, b: np.ndarray) -> float:
    """The least work over every monotone path from (0, 0) to (m-1, n-1), b forwards or backwards."""
    m, n = len(a), len(b)
    a = a - a.mean(axis=0)
    best = np.inf
    for walked in (b - b.mean(axis=0), (b - b.mean(axis=0))[::-1]):
        w = np.linalg.norm(a[:, None] - walked[None], axis=-1)

        def paths(i: int, j: int):  # type: ignore[no-untyped-def]
            if (i, j) == (m - 1, n - 1):
                yield w[i, j]
                return
            for di, dj in ((1, 1), (0, 1), (1, 0)):
                if i + di < m and j + dj < n:
                    for rest in paths(i + di, j + dj):
                        yield w[i, j] + rest

        best = min(best, min(paths(0, 0)))
    return float(best)


@pytest.mark.parametrize("seed", range(12))
def test_open_correspondence_is_the_least_work_of_all_paths(seed: int) -> None:
    rng = np.random.default_rng(seed)
    m, n = rng.integers(2, 6, size=2)
    a, b = rng.normal(size=(m, 2)), rng.normal(size=(n, 2))
    found = correspond_open(a, b)
    assert is_open_monotone(found.pairs, m, n, found.reversed)
    assert found.work == pytest.approx(_brute_open(a, b), rel=1e-12, abs=1e-12)


def test_open_correspondence_walks_a_reversed_stroke_backwards() -> None:
    a = np.array([[0.0, 0], [1, 0], [2, 0], [3, 0]])
    found = correspond_open(a, a[::-1] + [0, 0.1])
    assert found.reversed and found.pairs.tolist() == [[0, 3], [1, 2], [2, 1], [3, 0]]


def test_colours_blend_in_oklab_premultiplied() -> None:
    from coloraide import Color

    red, blue = (255, 0, 0, 255), (0, 0, 255, 255)
    t = np.array([0.0, 0.25, 0.5, 0.75, 1.0])
    ours = blend_colors(red, blue, t)
    mix = Color.interpolate([Color("srgb", [1, 0, 0]), Color("srgb", [0, 0, 1])], space="oklab")
    for got, x in zip(ours, t):
        expected = [round(255 * c) for c in mix(float(x)).convert("srgb").coords()]
        assert got is not None and max(abs(g - e) for g, e in zip(got[:3], expected)) <= 1 and got[3] == 255
    assert ours[2][:3] == (140, 83, 162)  # purple, not sRGB's dark (128, 0, 128)
    assert ours[0] == red and ours[-1] == blue


def test_a_missing_fill_fades_in_its_own_colour() -> None:
    blue = (0, 0, 255, 255)
    out = blend_colors(None, blue, [0.0, 0.5, 1.0])
    assert out[0] is None and out[1] == (0, 0, 255, 128) and out[2] == blue
    paints = blend_paints(Paint(None, (0, 0, 0, 255), 4.0), Paint(blue, None, 1.0, 0.5), [0.0, 0.5, 1.0])
    assert paints[0] == Paint(None, (0, 0, 0, 255), 4.0) and paints[2] == Paint(blue, None, 1.0, 0.5)
    assert paints[1].stroke == (0, 0, 0, 128) and paints[1].stroke_width == 4.0 and paints[1].opacity == 0.75


def test_a_contour_keeps_its_partner_of_its_own_size_when_the_two_swap_places() -> None:
    """A small and a big square trade places: by position alone each would pair with the other's
    shape (centres 1.5 apart against 7.5, relative to each key's centre); the size term of the
    documented cost (0.7 · |ln 4| ≈ 0.97 a pair, against 6 / 9.4 ≈ 0.64 of position) keeps small with small."""
    a = [square(-3.5, -0.5, 1), square(1, -2, 4)]  # small at (-3, 0), big at (3, 0)
    b = [square(-5, -2, 4), square(2.5, -0.5, 1)]  # big at (-3, 0), small at (3, 0)
    assert pair_contours(a, [True, True], b, [True, True]) == [(0, 1), (1, 0)]


def test_roles_of_many_small_squares_test_only_the_contours_whose_box_holds_the_probe(monkeypatch) -> None:  # type: ignore[no-untyped-def]
    """300 unit squares inside one frame around them all: each square is a hole (inside exactly one),
    the frame an outer — found with a point test per square, not one per pair."""
    import tweenrender.core.contours as contours_module

    squares = [np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float) + [3 * (i % 20) + 1, 3 * (i // 20) + 1]
               for i in range(300)]
    frame = np.array([[0, 0], [61, 0], [61, 46], [0, 46]], dtype=float)
    calls = [0]
    inside = contours_module.inside

    def counted(points: np.ndarray, polygon: np.ndarray) -> np.ndarray:
        calls[0] += 1
        return inside(points, polygon)

    monkeypatch.setattr(contours_module, "inside", counted)
    assert roles([frame, *squares], [True] * 301) == ["outer"] + ["hole"] * 300
    assert calls[0] <= 2 * 301


def test_nesting_of_many_small_squares_is_tested_where_boxes_nest(monkeypatch) -> None:  # type: ignore[no-untyped-def]
    """400 unit squares inside one frame, each moving a little: the exact nesting test runs only on the
    pairs whose bounding boxes lie one within the other (the frame with each square), not on every pair
    (79 800), and nothing is parted."""
    import tweenrender.core.contours as contours_module

    a = [np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float) + [3 * (i % 20) + 1, 3 * (i // 20) + 1]
         for i in range(400)]
    b = [s + [0.5, 0.25] for s in a]
    frame = np.array([[0, 0], [62, 0], [62, 62], [0, 62]], dtype=float)
    calls = [0]
    nested = contours_module._nested

    def counted(c: np.ndarray, d: np.ndarray) -> int:
        calls[0] += 1
        return nested(c, d)

    monkeypatch.setattr(contours_module, "_nested", counted)
    partners = [(i, i) for i in range(401)]
    assert contours_module.keep_nesting(partners, [frame, *a], [True] * 401, [frame, *b], [True] * 401) == partners
    assert calls[0] <= 2 * 401


@pytest.mark.parametrize("seed", range(6))
def test_misnested_pairs_match_every_pair_tested(seed: int) -> None:
    """Random squares, some nested, some swapping nesting between the keys: the pairs found nested differently
    are those a test of every pair finds (brute force: shapely's containment)."""
    import shapely

    from tweenrender.core.contours import _misnested

    rng = np.random.default_rng(seed)
    count = 24
    a = [square(*rng.uniform(0, 10, 2), rng.choice([0.5, 2.0, 6.0])) for _ in range(count)]
    b = [c + rng.uniform(-1.5, 1.5, 2) if rng.random() < 0.5 else c.copy() for c in a]
    pairs = [(i, i) for i in range(count)]
    found = {frozenset(pq) for pq in _misnested(pairs, a, b)}

    def relation(key: list[np.ndarray], p: int, q: int) -> int | None:
        sp, sq = shapely.Polygon(key[p]), shapely.Polygon(key[q])
        if sp.boundary.intersects(sq.boundary):
            return None  # they meet: not apart
        return 1 if sq.contains(sp) else -1 if sp.contains(sq) else 0

    expected = set()
    for p, q in itertools.combinations(range(count), 2):
        ra, rb = relation(a, p, q), relation(b, p, q)
        if ra is not None and rb is not None and ra != rb:
            expected.add(frozenset({(p, p), (q, q)}))
    assert found == expected
