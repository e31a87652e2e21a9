"""Self-intersection against an exact brute force on small polygons, and known shapes."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

from tweenrender.core.crossings import distinct_outline, self_crossing


def _exact_meet(p: tuple, p2: tuple, q: tuple, q2: tuple) -> bool:
    """Closed segments p–p2 and q–q2 share a point: parametric solve in exact rationals."""
    def sub(a, b):
        return (a[0] - b[0], a[1] - b[1])

    def cross(a, b):
        return a[0] * b[1] - a[1] * b[0]

    r, w, d = sub(p2, p), sub(q2, q), sub(q, p)
    denominator = cross(r, w)
    if denominator != 0:
        s = Fraction(cross(d, w), denominator)
        u = Fraction(cross(d, r), denominator)
        return 0 <= s <= 1 and 0 <= u <= 1
    if cross(d, r) != 0:  # parallel, on different lines
        return False
    rr = r[0] * r[0] + r[1] * r[1]
    t0 = Fraction(d[0] * r[0] + d[1] * r[1], rr)
    t1 = t0 + Fraction(w[0] * r[0] + w[1] * r[1], rr)
    return max(min(t0, t1), 0) <= min(max(t0, t1), 1)


def _brute_force(points: list[tuple[int, int]]) -> bool:
    """The outline (coincident neighbours merged) crosses or touches itself, by exact pair tests."""
    merged: list[tuple[int, int]] = []
    for point in points:
        if not merged or merged[-1] != point:
            merged.append(point)
    while len(merged) > 1 and merged[0] == merged[-1]:
        merged.pop()
    n = len(merged)
    if n < 3:
        return False
    segments = [(merged[i], merged[(i + 1) % n]) for i in range(n)]
    for i in range(n):
        for j in range(i + 1, n):
            neighbours = j == i + 1 or (i == 0 and j == n - 1)
            if neighbours:
                # they share one vertex; anything more is a fold back along one line
                a, b = segments[i], segments[j]
                shared = a[1] if a[1] in b else a[0]
                ua = (a[0][0] - shared[0], a[0][1] - shared[1]) if a[1] == shared else \
                    (a[1][0] - shared[0], a[1][1] - shared[1])
                ub = (b[1][0] - shared[0], b[1][1] - shared[1]) if b[0] == shared else \
                    (b[0][0] - shared[0], b[0][1] - shared[1])
                if ua[0] * ub[1] - ua[1] * ub[0] == 0 and ua[0] * ub[0] + ua[1] * ub[1] > 0:
                    return True
            elif _exact_meet(*segments[i], *segments[j]):
                return True
    return False


def test_brute_force_agrees_on_random_small_polygons() -> None:
    rng = np.random.default_rng(7)
    crossing = simple = 0
    for _ in range(3000):
        n = int(rng.integers(3, 8))
        points = [tuple(int(v) for v in p) for p in rng.integers(0, 5, size=(n, 2))]
        expected = _brute_force(points)
        where = self_crossing(np.array(points, dtype=np.float64))
        assert (where is not None) == expected, points
        crossing += expected
        simple += not expected
        if where is not None:
            outline = distinct_outline(np.array(points, dtype=np.float64))
            # the point given lies on the outline
            a, b = outline, np.roll(outline, -1, axis=0)
            ab, ap = b - a, where - a
            s = np.clip((ap * ab).sum(1) / np.maximum((ab * ab).sum(1), 1e-300), 0, 1)
            assert np.min(np.linalg.norm(a + s[:, None] * ab - where, axis=1)) < 1e-9
    assert crossing > 300 and simple > 300  # both kinds were really tried


@pytest.mark.parametrize("points, expected", [
    ([[0, 0], [2, 0], [2, 2], [0, 2]], None),                         # square
    ([[0, 0], [2, 2], [2, 0], [0, 2]], (1.0, 1.0)),                   # bow tie: crosses at its middle
    ([[0, 0], [4, 0], [4, 4], [2, 0.0], [0, 4]], (2.0, 0.0)),         # a vertex touching an edge
    ([[0, 0], [2, 0], [2, 0], [2, 2], [0, 2]], None),                 # a copy: a zero-length edge is no edge
    ([[0, 0], [2, 0], [1, 0], [1, 2]], (2.0, 0.0)),                   # folds back along one line
    ([[0, 0], [1, 0], [2, 0]], (2.0, 0.0)),                           # flat: folds back at its end
])
def test_known_outlines(points: list, expected: tuple | None) -> None:
    where = self_crossing(np.array(points, dtype=np.float64))
    if expected is None:
        assert where is None
    else:
        assert where is not None and np.allclose(where, expected)


def test_large_outline_is_checked_in_blocks() -> None:
    # a 3000-vertex circle is simple; pushing one vertex across the middle makes it cross
    theta = np.linspace(0, 2 * np.pi, 3000, endpoint=False)
    circle = np.column_stack([np.cos(theta), np.sin(theta)])
    assert self_crossing(circle) is None
    circle[1500] = [2.0, 0.0]
    assert self_crossing(circle) is not None


def _lowest_meeting_pair(points: list[tuple[int, int]]) -> tuple[int, int] | None:
    """The lowest-numbered pair (i, j) of edges, not neighbours, of the outline (no coincident neighbours)
    that share a point, by exact pair tests."""
    n = len(points)
    segments = [(points[i], points[(i + 1) % n]) for i in range(n)]
    for i in range(n):
        for j in range(i + 2, n):
            if not (i == 0 and j == n - 1) and _exact_meet(*segments[i], *segments[j]):
                return i, j
    return None


def _on_segment(point: np.ndarray, a: tuple, b: tuple) -> bool:
    a_, b_ = np.array(a, float), np.array(b, float)
    ab, ap = b_ - a_, point - a_
    s = np.clip(ap @ ab / max(ab @ ab, 1e-300), 0.0, 1.0)
    return bool(np.linalg.norm(a_ + s * ab - point) < 1e-9)


@pytest.mark.parametrize("loop, rows, block", [("compiled", 0, 0), ("numpy", 64, 1 << 18), ("numpy", 2, 16)])
def test_the_point_given_is_on_the_lowest_pair_of_edges_that_meet(monkeypatch, loop: str, rows: int,
                                                                   block: int) -> None:
    import tweenrender.core.crossings as crossings

    if loop == "numpy":  # blocks of rows, down to two edges at a time
        monkeypatch.setattr(crossings, "_first_meeting", crossings._first_meeting_numpy)
        monkeypatch.setattr(crossings, "_ROWS", rows)
        monkeypatch.setattr(crossings, "_BLOCK", block)
    else:
        monkeypatch.setattr(crossings, "_NUMPY_PAIRS", 0)
    rng = np.random.default_rng(11)
    checked = 0
    for _ in range(400):
        n = int(rng.integers(4, 30))
        points = [tuple(int(v) for v in p) for p in rng.integers(0, 9, size=(n, 2))]
        if any(points[k] == points[(k + 1) % n] for k in range(n)):
            continue
        if any((lambda u, v: u[0] * v[1] - u[1] * v[0] == 0 and u[0] * v[0] + u[1] * v[1] < 0)(
                (points[k][0] - points[k - 1][0], points[k][1] - points[k - 1][1]),
                (points[(k + 1) % n][0] - points[k][0], points[(k + 1) % n][1] - points[k][1])) for k in range(n)):
            continue  # a fold back: reported at its own neighbouring pair
        pair = _lowest_meeting_pair(points)
        where = crossings.self_crossing(np.array(points, dtype=np.float64))
        assert (where is None) == (pair is None), points
        if pair is not None:
            i, j = pair
            assert _on_segment(where, points[i], points[(i + 1) % n]), (points, pair, where)
            assert _on_segment(where, points[j], points[(j + 1) % n]), (points, pair, where)
            checked += 1
    assert checked > 100


def test_a_sweep_of_outlines_is_each_outline_checked() -> None:
    rng = np.random.default_rng(5)
    frames = rng.integers(0, 5, size=(30, 7, 2)).astype(np.float64)
    expected = [self_crossing(frame) for frame in frames]
    from tweenrender.core.crossings import self_crossings

    for _ in range(2):  # the second time from what was remembered: the same answers
        found = self_crossings(frames)
        assert [w is None for w in found] == [w is None for w in expected]
        assert all(w is None or np.array_equal(w, e) for w, e in zip(found, expected))


def _float_pair_test(points: np.ndarray) -> tuple[int, int] | None:
    """The lowest pair of edges, not neighbours, that the float orientation test says meet: each cross
    product of the coordinate differences in Python floats (IEEE double, no fused multiply-add), one pair
    at a time."""
    n = len(points)
    a = [tuple(map(float, p)) for p in points]
    b = [a[(k + 1) % n] for k in range(n)]

    def cross(ux, uy, vx, vy):
        return ux * vy - uy * vx

    def sign(x):
        return (x > 0) - (x < 0)

    for i in range(n - 2):
        for j in range(i + 2, n):
            if i == 0 and j == n - 1:
                continue
            ex, ey = b[j][0] - a[j][0], b[j][1] - a[j][1]
            d1 = cross(ex, ey, a[i][0] - a[j][0], a[i][1] - a[j][1])
            d2 = cross(ex, ey, b[i][0] - a[j][0], b[i][1] - a[j][1])
            fx, fy = b[i][0] - a[i][0], b[i][1] - a[i][1]
            d3 = cross(fx, fy, a[j][0] - a[i][0], a[j][1] - a[i][1])
            d4 = cross(fx, fy, b[j][0] - a[i][0], b[j][1] - a[i][1])
            if d1 == d2 == d3 == d4 == 0.0:
                if all(max(min(a[i][c], b[i][c]), min(a[j][c], b[j][c])) <=
                       min(max(a[i][c], b[i][c]), max(a[j][c], b[j][c])) for c in (0, 1)):
                    return i, j
            elif sign(d1) * sign(d2) <= 0 and sign(d3) * sign(d4) <= 0:
                return i, j
    return None


@pytest.mark.parametrize("loop", ["compiled", "numpy"])
def test_the_float_test_is_made_with_the_same_rounding_on_nearly_collinear_outlines(loop: str) -> None:
    # points a hair off one line, far apart: the float signs of the products decide, rounding and all
    from tweenrender.core import _crossing_kernel, crossings

    def _first_meeting(a: np.ndarray, b: np.ndarray) -> tuple[int, int] | None:
        if loop == "numpy":
            return crossings._first_meeting_numpy(a, b)
        i, j = _crossing_kernel.first_meeting(a[:, 0].copy(), a[:, 1].copy(), b[:, 0].copy(), b[:, 1].copy())
        return None if i < 0 else (i, j)

    rng = np.random.default_rng(3)
    found = {None: 0, "pair": 0}
    for _ in range(300):
        n = int(rng.integers(4, 12))
        s = np.sort(rng.uniform(-1e3, 1e3, n))
        rng.shuffle(s)
        points = np.column_stack([s, 0.1 * s + rng.normal(0, 1e-13, n) * rng.integers(0, 2, n)])
        points = distinct_outline(points)
        if len(points) < 4:
            continue
        expected = _float_pair_test(points)
        assert _first_meeting(points, np.roll(points, -1, axis=0)) == expected, points.tolist()
        found["pair" if expected else None] += 1
    assert found["pair"] > 30
