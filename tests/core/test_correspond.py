"""Vertex correspondence (maths §2): the optimum is checked against an exhaustive
enumeration of closed paths written here, and the fast search against the
try-every-start reference."""

from __future__ import annotations

import math
import os
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tweenrender.core.correspondence._cyclic_dtw import angle_change, bend_work
from tweenrender.core.correspondence.correspond import (
    Correspondence, correspond, is_cyclic_monotone, naive_correspond, path_work, work_matrix,
)
from tweenrender.model import Matching, frozen_points

ROOT = Path(__file__).resolve().parents[2]
MATCHINGS = [
    Matching(cost=cost, align=align) for cost in ("distance", "sg") for align in ("none", "centroid")
]


# -- independent helpers -------------------------------------------------------


def star(rng: np.random.Generator, n: int, center: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
    """A random counter-clockwise polygon, star-shaped about ``center``."""
    angles = np.sort(rng.uniform(0, 2 * np.pi, n)) + np.arange(n) * 0.1 / n
    radii = rng.uniform(0.5, 1.5, n)
    return np.column_stack([radii * np.cos(angles), radii * np.sin(angles)]) + center


def shoelace(points: np.ndarray) -> float:
    x, y = points[:, 0], points[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def closed_paths(m: int, n: int, backwards: bool) -> Iterator[list[tuple[int, int]]]:
    """Every closed monotone path winding once round the cyclic m × n grid.

    Unrolled: from (0, s) to (m, s + n) by steps (1,0), (0,1), (1,1), for every
    start s; the last node is the first again and is dropped. Backwards, a step
    in the column goes one vertex back round b.
    """

    def walk(i: int, c: int, end: tuple[int, int], path: list[tuple[int, int]]) -> Iterator[list]:
        if (i, c) == end:
            yield path[:-1]
            return
        for di, dc in ((1, 0), (0, 1), (1, 1)):
            if i + di <= end[0] and c + dc <= end[1]:
                path.append((i + di, c + dc))
                yield from walk(i + di, c + dc, end, path)
                path.pop()

    for s in range(n):
        for path in walk(0, s, (m, s + n), [(0, s)]):
            yield [(i % m, (-c) % n if backwards else c % n) for i, c in path]


def brute_force_distance(a: np.ndarray, b: np.ndarray, align: str, backwards: bool) -> float:
    if align == "centroid":
        a, b = a - a.mean(axis=0), b - b.mean(axis=0)
    best = math.inf
    for path in closed_paths(len(a), len(b), backwards):
        i, j = np.array(path).T
        best = min(best, float(np.sqrt(((a[i] - b[j]) ** 2).sum(axis=1)).sum()))
    return best


def brute_force(a: np.ndarray, b: np.ndarray, matching: Matching, backwards: bool) -> float:
    if matching.cost == "distance":
        return brute_force_distance(a, b, matching.align, backwards)
    return min(path_work(a, b, path, matching) for path in closed_paths(len(a), len(b), backwards))


def close(x: float, y: float, rel: float = 1e-9) -> bool:
    return abs(x - y) <= rel * max(1.0, abs(x), abs(y))


def small_pair(rng: np.random.Generator, kind: int) -> tuple[np.ndarray, np.ndarray]:
    """Two polygons of 2..5 vertices: random points, stars, or points on a small integer grid (ties)."""
    m, n = (int(k) for k in rng.integers(2, 6, size=2))
    if kind == 0:
        return rng.normal(size=(m, 2)), rng.normal(size=(n, 2)) + rng.normal(size=2)
    if kind == 1:
        return star(rng, m), star(rng, n, center=(0.7, -0.3))
    return rng.integers(0, 3, (m, 2)).astype(float), rng.integers(0, 3, (n, 2)).astype(float)


# -- the optimum ------------------------------------------------------------------


@pytest.mark.parametrize("matching", MATCHINGS, ids=lambda mt: f"{mt.cost}-{mt.align}")
@pytest.mark.parametrize("seed", range(12))
def test_optimum_equals_exhaustive_search(matching: Matching, seed: int) -> None:
    rng = np.random.default_rng(seed)
    a, b = small_pair(rng, seed % 3)
    result = correspond(a, b, matching)
    backwards = shoelace(a) * shoelace(b) < 0
    assert result.reversed == backwards
    assert is_cyclic_monotone(result.pairs, len(a), len(b), backwards)
    expected = brute_force(a, b, matching, backwards)
    assert close(result.work, expected), (result.work, expected)


def test_enumerator_counts_paths() -> None:
    # The unrolled paths from (0, s) to (m, s + n) are counted by the Delannoy number D(m, n).
    delannoy = {(2, 2): 13, (2, 3): 25, (3, 3): 63, (4, 5): 681}
    for (m, n), count in delannoy.items():
        assert sum(1 for _ in closed_paths(m, n, False)) == n * count


@pytest.mark.parametrize("seed", range(30))
def test_fast_search_equals_every_start_reference(seed: int) -> None:
    rng = np.random.default_rng(100 + seed)
    m, n = (int(k) for k in rng.integers(3, 81, size=2))
    m = min(m, 60)
    kind = seed % 3
    if kind == 0:
        a, b = star(rng, m), star(rng, n, center=(2.0, 1.0))
    elif kind == 1:
        a, b = rng.normal(size=(m, 2)), rng.normal(size=(n, 2))
    else:  # a coarse grid: many exactly equal path costs
        a, b = np.round(star(rng, m) * 2) / 2, np.round(star(rng, n) * 2) / 2
    for align in ("none", "centroid"):
        matching = Matching(align=align)
        fast, slow = correspond(a, b, matching), naive_correspond(a, b, matching)
        assert close(fast.work, slow.work), (fast.work, slow.work)
        assert fast.reversed == slow.reversed
        assert is_cyclic_monotone(fast.pairs, m, n, fast.reversed)


@settings(max_examples=150, deadline=None)
@given(
    st.lists(st.tuples(st.integers(0, 3), st.integers(0, 3)), min_size=2, max_size=25),
    st.lists(st.tuples(st.integers(0, 3), st.integers(0, 3)), min_size=2, max_size=25),
)
def test_fast_search_on_tied_grids(a: list, b: list) -> None:
    a_points, b_points = np.array(a, dtype=float), np.array(b, dtype=float)
    fast = correspond(a_points, b_points, Matching(align="none"))
    slow = naive_correspond(a_points, b_points, Matching(align="none"))
    assert close(fast.work, slow.work)
    assert is_cyclic_monotone(fast.pairs, len(a), len(b), fast.reversed)


def test_large_pair_against_reference() -> None:
    rng = np.random.default_rng(7)
    a, b = star(rng, 150), star(rng, 210, center=(0.3, 0.1))
    assert close(correspond(a, b).work, naive_correspond(a, b).work)


@pytest.mark.parametrize("seed", range(4))
def test_sg_reference_agrees(seed: int) -> None:
    rng = np.random.default_rng(200 + seed)
    a, b = star(rng, 9 + seed), star(rng, 12)
    matching = Matching(cost="sg")
    assert close(correspond(a, b, matching).work, naive_correspond(a, b, matching).work)


# -- the returned path ------------------------------------------------------------


@pytest.mark.parametrize("matching", MATCHINGS, ids=lambda mt: f"{mt.cost}-{mt.align}")
def test_result_contract(matching: Matching) -> None:
    rng = np.random.default_rng(3)
    a, b = star(rng, 12), star(rng, 17)
    result = correspond(a, b, matching)
    m, n = len(a), len(b)
    assert isinstance(result, Correspondence)
    assert result.pairs.dtype == np.intp and result.pairs.shape == (result.balanced, 2)
    assert result.pairs[0, 0] == 0
    assert max(m, n) <= result.balanced <= m + n
    assert is_cyclic_monotone(result.pairs, m, n, result.reversed)
    assert close(result.work, path_work(a, b, result.pairs, matching))
    a2, b2 = result.apply(a, b)
    assert a2.shape == b2.shape == (result.balanced, 2)
    assert np.array_equal(a2, a[result.pairs[:, 0]]) and np.array_equal(b2, b[result.pairs[:, 1]])
    with pytest.raises(ValueError):
        result.pairs[0, 0] = 1  # read-only


def test_distance_work_is_sum_of_work_matrix() -> None:
    rng = np.random.default_rng(4)
    a, b = star(rng, 8), star(rng, 11, center=(3.0, 0.0))
    result = correspond(a, b, Matching(align="none"))
    w = work_matrix(a, b)
    assert w.shape == (8, 11)
    assert np.allclose(w, np.linalg.norm(a[:, None, :] - b[None, :, :], axis=-1))
    assert close(result.work, float(w[result.pairs[:, 0], result.pairs[:, 1]].sum()))


@pytest.mark.parametrize(
    ("pairs", "m", "n", "reversed"),
    [
        ([[0, 0], [1, 1], [2, 2]], 3, 3, False),
        ([[0, 0], [1, 0], [1, 1], [2, 2], [2, 3]], 3, 4, False),
        ([[0, 2], [1, 2], [2, 0], [0, 1]], 3, 3, False),
        ([[0, 0], [1, 2], [2, 1]], 3, 3, True),
        ([[0, 0], [0, 1], [1, 1]], 2, 2, False),
    ],
)
def test_is_cyclic_monotone_accepts(pairs: list, m: int, n: int, reversed: bool) -> None:
    assert is_cyclic_monotone(np.array(pairs), m, n, reversed)


@pytest.mark.parametrize(
    ("pairs", "m", "n", "reversed"),
    [
        ([[0, 0], [1, 1], [2, 2]], 3, 3, True),            # winds the wrong way for the flag
        ([[0, 0], [2, 2], [1, 1]], 3, 3, False),           # steps backwards
        ([[0, 0], [1, 1], [1, 1], [2, 2]], 3, 3, False),   # a step that advances nothing
        ([[0, 0], [2, 1], [2, 2]], 3, 3, False),           # skips vertex 1 of a
        ([[0, 0], [1, 1], [2, 2], [0, 0], [1, 1], [2, 2]], 3, 3, False),  # winds twice
        ([[0, 0], [1, 1], [2, 3]], 3, 3, False),           # index out of range
        ([[0, 0], [1, 1]], 3, 2, False),                   # does not close: a's last step jumps
        ([], 3, 3, False),                                 # empty
        ([[0, 0, 0]], 3, 3, False),                        # wrong shape
        ([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]], 3, 3, False),  # not indices
    ],
)
def test_is_cyclic_monotone_rejects(pairs: list, m: int, n: int, reversed: bool) -> None:
    assert not is_cyclic_monotone(np.array(pairs), m, n, reversed)


# -- invariances ------------------------------------------------------------------


@pytest.mark.parametrize("matching", MATCHINGS, ids=lambda mt: f"{mt.cost}-{mt.align}")
@pytest.mark.parametrize("seed", range(3))
def test_relabelling_start_vertex_keeps_work(matching: Matching, seed: int) -> None:
    rng = np.random.default_rng(300 + seed)
    a, b = star(rng, 14), star(rng, 19, center=(0.5, 0.5))
    base = correspond(a, b, matching).work
    for shift_a, shift_b in ((3, 0), (0, 7), (5, 11)):
        rolled = correspond(np.roll(a, shift_a, axis=0), np.roll(b, shift_b, axis=0), matching)
        assert close(rolled.work, base), (shift_a, shift_b, rolled.work, base)


@pytest.mark.parametrize("matching", MATCHINGS, ids=lambda mt: f"{mt.cost}-{mt.align}")
def test_opposite_winding_is_walked_backwards(matching: Matching) -> None:
    rng = np.random.default_rng(11)
    a, b = star(rng, 10), star(rng, 13, center=(1.0, 0.0))
    forward = correspond(a, b, matching)
    backward = correspond(a, b[::-1].copy(), matching)
    assert not forward.reversed and backward.reversed
    assert close(backward.work, forward.work)
    assert is_cyclic_monotone(backward.pairs, 10, 13, reversed=True)
    assert not is_cyclic_monotone(backward.pairs, 10, 13, reversed=False)
    # Both windings flipped: the same orientation again.
    both = correspond(a[::-1].copy(), b[::-1].copy(), matching)
    assert not both.reversed and close(both.work, forward.work)


@pytest.mark.parametrize(
    ("cost", "n"), [("distance", 3), ("distance", 4), ("distance", 25), ("distance", 300),
                    ("sg", 3), ("sg", 4), ("sg", 25)],
)
def test_identical_polygons_match_one_to_one(cost: str, n: int) -> None:
    polygon = star(np.random.default_rng(n), n)
    result = correspond(polygon, polygon.copy(), Matching(cost=cost))
    assert result.balanced == n
    assert np.array_equal(result.pairs, np.column_stack([np.arange(n), np.arange(n)]))
    assert result.work == 0.0 and not result.reversed


def test_alignment_removes_translation() -> None:
    rng = np.random.default_rng(12)
    a = star(rng, 9)
    b = star(rng, 7)
    moved = b + np.array([50.0, -20.0])
    aligned = correspond(a, b, Matching(align="centroid")).work
    assert close(correspond(a, moved, Matching(align="centroid")).work, aligned)
    assert correspond(a, moved, Matching(align="none")).work > 20 * aligned


# -- degenerate but legal input ---------------------------------------------------


DEGENERATE = {
    "duplicate vertices": (np.array([[0, 0], [0, 0], [1, 0], [1, 1], [1, 1], [0, 1.0]]),
                           np.array([[0, 0], [2, 0], [2, 2], [2, 2.0]])),
    "collinear": (np.array([[0, 0], [1, 0], [2, 0], [3, 0.0]]), np.array([[0, 0], [1, 1], [2, 2.0]])),
    "all one point": (np.zeros((4, 2)), np.array([[0, 0], [1, 0], [0, 1.0]])),
    "two vertices": (np.array([[0, 0], [1, 0.0]]), np.array([[0, 0], [1, 0], [1, 1], [0, 1.0]])),
    "spike": (np.array([[0, 0], [2, 0], [0, 0.001], [1, 1.0]]), np.array([[0, 0], [1, 0], [0, 1.0]])),
}


@pytest.mark.parametrize("matching", MATCHINGS, ids=lambda mt: f"{mt.cost}-{mt.align}")
@pytest.mark.parametrize("name", DEGENERATE)
def test_degenerate_input_gives_a_valid_path(matching: Matching, name: str) -> None:
    a, b = DEGENERATE[name]
    for first, second in ((a, b), (b, a)):
        result = correspond(first, second, matching)
        assert math.isfinite(result.work)
        assert is_cyclic_monotone(result.pairs, len(first), len(second), result.reversed)
        assert close(result.work, brute_force(first, second, matching, result.reversed))


@pytest.mark.parametrize(
    ("a", "message"),
    [
        (np.zeros((1, 2)), "at least 2 vertices"),
        (np.zeros((4, 3)), "shape"),
        (np.array([[0, 0], [1, np.nan], [1, 1]]), "non-finite"),
    ],
)
def test_bad_polygons_are_refused(a: np.ndarray, message: str) -> None:
    with pytest.raises(ValueError, match=message):
        correspond(a, np.eye(3, 2))


def test_unknown_matching_is_refused() -> None:
    with pytest.raises(ValueError, match="cost"):
        correspond(np.eye(3, 2), np.eye(3, 2), Matching(cost="area"))
    with pytest.raises(ValueError, match="align"):
        correspond(np.eye(3, 2), np.eye(3, 2), Matching(align="rotation"))


# -- Sederberg–Greenwood energy ------------------------------------------------------


def sampled_angle_change(q0: np.ndarray, q1: np.ndarray, q2: np.ndarray) -> tuple[float, float, float]:
    """(Δθ, Δθ*, closest approach to the origin), from Q(t) sampled densely and its angle unwrapped."""
    t = np.linspace(0.0, 1.0, 20_001)[:, None]
    q = (1 - t) ** 2 * q0 + 2 * t * (1 - t) * q1 + t**2 * q2
    theta = np.unwrap(np.arctan2(q[:, 1], q[:, 0]))
    theta -= theta[0]
    sweep = abs(theta[-1])
    overshoot = (theta.max() - max(0.0, theta[-1])) + (min(0.0, theta[-1]) - theta.min())
    return sweep, overshoot, float(np.linalg.norm(q, axis=1).min())


def test_angle_change_matches_sampling() -> None:
    rng = np.random.default_rng(21)
    checked = 0
    for _ in range(300):
        q0, q1, q2 = rng.normal(size=(3, 2))
        sweep, overshoot, nearest = sampled_angle_change(q0, q1, q2)
        if nearest < 0.05:
            continue  # the angle is ill-conditioned near the origin
        got_sweep, got_overshoot, _ = angle_change(*q0, *q1, *q2)
        assert abs(got_sweep - sweep) < 1e-3 and abs(got_overshoot - overshoot) < 1e-3
        checked += 1
    assert checked > 150


def test_through_zero_is_crossing_the_positive_x_axis() -> None:
    # y goes +1 → -1 while x stays positive: the angle passes through zero.
    assert angle_change(1.0, 1.0, 1.0, 0.0, 1.0, -1.0)[2]
    # y goes +1 → -1 on the negative x side: through 180°, not zero.
    assert not angle_change(-1.0, 1.0, -1.0, 0.0, -1.0, -1.0)[2]
    # touching the axis at x > 0 counts, staying above it does not.
    assert angle_change(1.0, 1.0, 1.0, -1.0, 1.0, 1.0)[2]
    assert not angle_change(1.0, 1.0, 1.0, 0.5, 1.0, 1.0)[2]


def test_bending_of_a_right_angle_closing_to_45_degrees() -> None:
    # Backward edge along +x, forward edge along +y (90°), then at 45°: a monotone 45° change.
    b0, f0 = (1.0, 0.0), (0.0, 1.0)
    b1, f1 = (1.0, 0.0), (1.0, 1.0)
    assert math.isclose(bend_work(*b0, *f0, *b1, *f1, 1.0, 2.0, 10.0, 1000.0), (math.pi / 4) ** 2)
    # The same change is scale-free.
    assert math.isclose(bend_work(*b0, *f0, 3.0, 0.0, 5.0, 5.0, 1.0, 2.0, 10.0, 1000.0),
                        (math.pi / 4) ** 2)


def test_sg_energy_of_known_motions() -> None:
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1.0]])
    identity = np.column_stack([np.arange(4), np.arange(4)])
    matching = Matching(cost="sg", align="none")
    # A rigid rotation below 180° keeps every edge's length and every vertex's angle.
    c, s = math.cos(1.0), math.sin(1.0)
    turned = square @ np.array([[c, s], [-s, c]]) + 3.0
    assert path_work(square, turned, identity, matching) == pytest.approx(0.0, abs=1e-12)
    # Doubling the size: every edge goes 1 → 2, (2 - 1)² / (0.5·1 + 0.5·2) each; angles unchanged.
    assert path_work(square, 2 * square, identity, matching) == pytest.approx(4 / 1.5)
    # The stiffness constant scales its term.
    stiffer = Matching(cost="sg", align="none", ks=3.0)
    assert path_work(square, 2 * square, identity, stiffer) == pytest.approx(3 * 4 / 1.5)


def test_sg_prefers_corners_to_corners() -> None:
    # A square against a square with one extra vertex in the middle of an edge:
    # the corners must pair with corners, the extra vertex with a duplicate.
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1.0]])
    five = np.array([[0, 0], [1, 0], [1, 0.5], [1, 1], [0, 1.0]])
    result = correspond(square, five, Matching(cost="sg"))
    corners = {(0, 0), (1, 1), (2, 3), (3, 4)}
    assert corners <= {tuple(p) for p in result.pairs.tolist()}


# -- inputs and environment ---------------------------------------------------------


def test_read_only_keys_are_accepted() -> None:
    rng = np.random.default_rng(13)
    a, b = frozen_points(star(rng, 7)), frozen_points(star(rng, 9))
    for matching in MATCHINGS:
        assert close(correspond(a, b, matching).work, correspond(a.copy(), b.copy(), matching).work)


@pytest.mark.parametrize(
    ("pairs", "message"),
    [([[0, 0], [1, 5]], "index"), ([[0, 0, 0]], "shape"), ([[0.0, 0.0]], "integer")],
)
def test_path_work_refuses_bad_pairs(pairs: list, message: str) -> None:
    with pytest.raises(ValueError, match=message):
        path_work(np.eye(3, 2), np.eye(4, 2), np.array(pairs))


def test_kernels_run_without_a_cache_folder() -> None:
    # No cache locator at all (as with a read-only install and no writable home):
    # the kernels are compiled in memory instead of failing at import.
    code = (
        "import numpy as np\n"
        "from tweenrender.core.correspondence import _cyclic_dtw\n"
        "from tweenrender.core.correspondence.correspond import correspond\n"
        "assert type(_cyclic_dtw.maes_search._cache).__name__ == 'NullCache'\n"
        "print(correspond(np.eye(3, 2), np.eye(4, 2) + 1).balanced)\n"
    )
    env = dict(os.environ, NUMBA_CACHE_LOCATOR_CLASSES="IPythonCacheLocator",
               PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env,
                          timeout=300)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "4"


@pytest.mark.parametrize("scale", [1e-300, 1e-160, 1e150])
def test_the_least_distance_pairing_does_not_depend_on_the_drawings_scale(scale: float) -> None:
    # the summed distances of every pairing scale by the same factor, so the least one is the same
    # whatever the unit; squares of sub-1e-154 distances underflow to zero unless the search works at unit size
    triangle = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    notched = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.5, 0.5]])
    unit = correspond(triangle, notched)
    scaled = correspond(triangle * scale, notched * scale)
    assert scaled.pairs.tolist() == unit.pairs.tolist()
    assert scaled.work == pytest.approx(unit.work * scale, rel=1e-9)
