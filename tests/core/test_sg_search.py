"""The Sederberg–Greenwood search by branch and bound (``_sg_search``): node for node the path of
the search that solves every start and closing step (``sg_every_start_search``, itself checked
against brute force over every closed path in test_correspond), ties and rounding included, while
solving few starts on real keys."""

from __future__ import annotations

import numpy as np
import pytest

from tests.core.test_correspond import brute_force, close, closed_paths, shoelace, small_pair, star
from tests.helpers import DATA
from tweenrender.core.correspondence import _cyclic_dtw
from tweenrender.core.correspondence._sg_search import _tilt, sg_search
from tweenrender.core.correspondence.correspond import (
    _aligned, _as_polygon, _winds_opposite, correspond, is_cyclic_monotone, naive_correspond, path_work,
)
from tweenrender.model import Matching


def tables(a: np.ndarray, b: np.ndarray, matching: Matching = Matching(cost="sg")) -> tuple[np.ndarray, np.ndarray]:
    """The stretching ``(m, n, 3)`` and bending ``(m, n, 3, 3)`` tables ``correspond`` searches."""
    a, b = _aligned(_as_polygon(a, "a"), _as_polygon(b, "b"), matching.align)
    walk = (-np.arange(len(b))) % len(b) if _winds_opposite(a, b) else np.arange(len(b))
    mt = matching
    return _cyclic_dtw.sg_tables(a, np.ascontiguousarray(b[walk]), mt.ks, mt.cs, mt.es, mt.kb, mt.eb, mt.mb, mt.pb)


def assert_same_search(stretch: np.ndarray, bend: np.ndarray) -> None:
    found = sg_search(stretch, bend)
    work, nodes = _cyclic_dtw.sg_every_start_search(stretch, bend)
    assert found.work == work or (np.isinf(found.work) and np.isinf(work))
    assert np.array_equal(found.nodes, nodes)


def ngon(k: int, phase: float = 0.0) -> np.ndarray:
    angles = phase + 2 * np.pi * np.arange(k) / k
    return np.column_stack([np.cos(angles), np.sin(angles)])


def blob(n: int, seed: int) -> np.ndarray:
    """A smooth random outline of ``n`` vertices (a few harmonics of the radius)."""
    rng = np.random.default_rng(seed)
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    radius = 1 + sum(rng.normal(0, 0.25 / k) * np.cos(k * t + rng.uniform(0, 2 * np.pi)) for k in range(1, 6))
    return np.column_stack([radius * np.cos(t), radius * np.sin(t)])


# -- the same path as every start ------------------------------------------------------------


@pytest.mark.parametrize("seed", range(60))
def test_random_tables(seed: int) -> None:
    rng = np.random.default_rng(seed)
    for kind in range(4):
        m, n = (int(v) for v in rng.integers(2, 14, 2))
        if kind == 0:  # small integers: many paths of exactly equal energy, so the tie rules decide
            stretch = rng.integers(0, 3, (m, n, 3)).astype(float)
            bend = rng.integers(0, 3, (m, n, 3, 3)).astype(float)
        elif kind == 1:  # zeros and infinities (cs = 0 makes a step that stretches from nothing cost +inf)
            stretch, bend = rng.random((m, n, 3)), rng.random((m, n, 3, 3))
            stretch[rng.random(stretch.shape) < 0.1] = np.inf
            bend[rng.random(bend.shape) < 0.05] = np.inf
            stretch[rng.random(stretch.shape) < 0.2] = 0.0
            bend[rng.random(bend.shape) < 0.2] = 0.0
        elif kind == 2:  # every path free, or every path infinite
            stretch = np.zeros((m, n, 3)) if seed % 2 else np.full((m, n, 3), np.inf)
            bend = rng.integers(0, 2, (m, n, 3, 3)).astype(float)
        else:
            stretch, bend = rng.random((m, n, 3)) ** 3 * 10, rng.random((m, n, 3, 3)) ** 3 * 10
        assert_same_search(stretch, bend)


@pytest.mark.parametrize("seed", range(30))
def test_larger_keys_with_near_ties(seed: int) -> None:
    """Regular polygons, their rotations and multiples, blobs and grid points: many starts whose energies
    agree but for rounding, which the bounds' allowances must not mistake for ties or gaps."""
    rng = np.random.default_rng(1000 + seed)
    m, n = (int(v) for v in rng.integers(8, 60, 2))
    kind = seed % 5
    if kind == 0:
        a, b = ngon(m), ngon(n, float(rng.uniform(0, 1)))
    elif kind == 1:
        a, b = ngon(m), ngon(2 * m if m < 30 else m)
    elif kind == 2:
        a, b = blob(m, seed), blob(n, seed + 1)
    elif kind == 3:
        a, b = rng.integers(0, 4, (m, 2)).astype(float), rng.integers(0, 4, (n, 2)).astype(float)
    else:
        a, b = star(rng, m), star(rng, n)[::-1].copy()
    assert_same_search(*tables(a, b))
    assert_same_search(*tables(a, b, Matching(cost="sg", align="none", mb=0.0, pb=0.0)))


@pytest.mark.parametrize("seed", range(40))
def test_correspond_against_every_start_and_brute_force(seed: int) -> None:
    rng = np.random.default_rng(2000 + seed)
    a, b = small_pair(rng, seed % 3)
    if seed % 4 == 1:
        b = b[::-1].copy()  # the other winding: b is walked backwards
    constants = [{}, {"cs": 0.0}, {"mb": 0.0, "pb": 0.0}, {"kb": 0.0}][seed % 4]
    matching = Matching(cost="sg", align=("none", "centroid")[seed % 2], **constants)
    found, expected = correspond(a, b, matching), naive_correspond(a, b, matching)
    assert np.array_equal(found.pairs, expected.pairs)
    assert found.work == expected.work or (np.isinf(found.work) and np.isinf(expected.work))
    assert found.reversed == expected.reversed == (shoelace(a) * shoelace(b) < 0)
    assert is_cyclic_monotone(found.pairs, len(a), len(b), found.reversed)
    least = brute_force(a, b, matching, found.reversed)
    assert close(found.work, least) or (np.isinf(found.work) and np.isinf(least))


def test_equal_counts_match_one_to_one() -> None:
    polygon = star(np.random.default_rng(5), 40)
    stretch, bend = tables(polygon, polygon.copy())
    result = sg_search(stretch, bend)
    assert result.work == 0.0
    assert np.array_equal(result.nodes[::-1, 1] - result.nodes[-1, 1], np.arange(41))
    assert result.solved == 3 and result.bounded <= 4  # the first guess is exact; nothing else can beat 0


def test_keys_whose_every_path_is_infinite_still_get_a_closed_path() -> None:
    """cs = 0 makes stretching from a zero length cost +inf, and different counts need such steps;
    the path traced back then used to leave the grid."""
    square, pentagon = ngon(4), ngon(5, 0.2)
    for a, b in ((square, pentagon), (pentagon, square)):
        result = correspond(a, b, Matching(cost="sg", cs=0.0))
        assert np.isinf(result.work)
        assert is_cyclic_monotone(result.pairs, len(a), len(b))
        assert np.array_equal(result.pairs, naive_correspond(a, b, Matching(cost="sg", cs=0.0)).pairs)
        assert np.isinf(path_work(a, b, result.pairs, Matching(cost="sg", cs=0.0)))


def test_negative_constants_search_every_start() -> None:
    a, b = star(np.random.default_rng(8), 9), star(np.random.default_rng(9), 12)
    stretch, bend = tables(a, b, Matching(cost="sg", kb=-1.0))
    result = sg_search(stretch, bend)
    assert (result.solved, result.bounded) == (3 * 12, 0)
    assert_same_search(stretch, bend)


# -- the work it saves ------------------------------------------------------------------------


def outline(name: str, count: int) -> np.ndarray:
    """The first contour of an icon, resampled to ``count`` vertices evenly along its length."""
    import tweenrender as tr

    points = np.asarray(tr.load_scene(DATA / "icons" / name).shapes[0].keys[0].contours[0].points)
    closed = np.vstack([points, points[:1]])
    at = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(closed, axis=0).T))])
    u = np.linspace(0.0, at[-1], count, endpoint=False)
    return np.column_stack([np.interp(u, at, closed[:, 0]), np.interp(u, at, closed[:, 1])])


@pytest.mark.parametrize(("a", "b"), [
    (lambda: blob(200, 1), lambda: blob(220, 2)),
    (lambda: outline("heroicons/heart.svg", 200), lambda: outline("heroicons/star.svg", 220)),
    (lambda: outline("mdi/heart.svg", 200), lambda: outline("mdi/weather-night.svg", 207)),
], ids=["blobs", "heart-star", "heart-moon"])
def test_few_starts_are_solved_on_real_keys(a, b) -> None:
    """The every-start search solves 3n (start, closing step) pairs; here a few dozen at most are
    solved, and some tens of spans bounded (measured: 7–17 pairs of 600–660, 19–37 spans)."""
    stretch, bend = tables(a(), b())
    n = stretch.shape[1]
    result = sg_search(stretch, bend)
    assert result.solved <= 40 < 3 * n
    assert result.bounded <= 100
    work, nodes = _cyclic_dtw.sg_every_start_search(stretch, bend)
    assert result.work == work and np.array_equal(result.nodes, nodes)


def test_tilt_is_the_slope_at_the_own_end() -> None:
    offsets = np.arange(-5, 6, dtype=float)
    assert _tilt(3.0 + 0.25 * offsets) == pytest.approx(0.25)
    assert _tilt(np.abs(offsets) + 0.5 * offsets) == pytest.approx(0.5)  # slopes -0.5 and 1.5: the middle
    assert _tilt(np.full(11, np.inf)) == 0.0
