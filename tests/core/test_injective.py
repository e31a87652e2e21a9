"""Injective paths (maths §5.9): in-betweens of simple keys never tangle, checked by an exact brute force.

Every check here is independent of the code under test: the crossing test is :mod:`tests.core.exact_tangles`
(all pairs of edges, rational arithmetic), triangle orientations are decided in exact rationals, a rigid
turn is compared with its closed form, and mean-value weights with the identity they must satisfy.
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tests.core.exact_tangles import parents_of, tangled
from tests.helpers import DATA
from tweenrender.core.geometry import rotate
from tweenrender.core.methods.injective import _PACE as PACE, _paths_of, injective, injective_contours, injective_mesh
from tweenrender.core.methods.tutte import mean_value_weights
from tweenrender.core.methods.registry import interpolate
from tweenrender.core.methods.qcurves import auto_choice
from tweenrender.core.timing.timeline import build_track, pair_paths

T = np.round(np.arange(1, 20) * 0.05, 2)  # t = .05 … .95

ICONS = DATA / "icons"
# unrelated real icons: single outlines, and outlines with holes (alpha-b, check-circle-outline, weather-*)
ICON_PAIRS = [
    ("feather/moon", "octicons/heart-24"),
    ("simple-icons/apple", "lucide/star"),
    ("twemoji/1f319", "heroicons/check-circle"),
    ("heroicons/moon", "feather/heart"),
    ("lucide/star", "simple-icons/python"),
    ("tabler/sun", "bootstrap/apple"),
    ("mdi/alpha-b", "mdi/alpha-o"),
    ("mdi/check-circle-outline", "octicons/check-circle-24"),
    ("mdi/weather-sunny", "bootstrap/apple"),
    ("mdi/weather-night", "heroicons/face-smile"),
]


def _moving_segments(a: str, b: str):
    scene = tr.load_scene([ICONS / f"{a}.svg", ICONS / f"{b}.svg"])
    for shape in scene.shapes:
        track = build_track(shape, scene.matching, unmatched=scene.unmatched, balance=scene.balance_of(shape))
        for segment in track.segments:
            moving = [k for k, p in enumerate(segment.pairs) if p.moving]
            if all(segment.shown) and moving:
                yield segment, moving


def _exact_orientations(points: np.ndarray, triangles: np.ndarray) -> list[int]:
    signs = []
    for a, b, c in triangles.tolist():
        (ax, ay), (bx, by), (cx, cy) = ((Fraction(float(x)), Fraction(float(y))) for x, y in points[[a, b, c]])
        value = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
        signs.append((value > 0) - (value < 0))
    return signs


def _check_never_tangles(k0s: list[np.ndarray], k1s: list[np.ndarray], closed: list[bool],
                         frames: list[np.ndarray]) -> None:
    parent = parents_of(k0s, closed)
    assert not tangled(k0s, closed, parent) and not tangled(k1s, closed, parent), "the keys must be simple"
    for k, t in enumerate(T):
        assert not tangled([f[k] for f in frames], closed, parent), f"tangled at t = {t}"


@pytest.mark.parametrize("a, b", ICON_PAIRS, ids=[f"{a}->{b}" for a, b in ICON_PAIRS])
def test_real_icon_pairs_never_tangle_and_their_mesh_is_positive_in_both_keys(a: str, b: str) -> None:
    checked = 0
    for segment, moving in _moving_segments(a, b):
        pairs = [segment.pairs[k] for k in moving]
        k0s, k1s, closed = [p.k0 for p in pairs], [p.k1 for p in pairs], [p.closed for p in pairs]
        mesh = injective_mesh(k0s, k1s, closed)
        assert mesh is not None, "the keys are simple: they must be meshed, not left to the rigid paths"
        assert _exact_orientations(mesh.p0, mesh.triangles) == [1] * len(mesh.triangles)
        assert _exact_orientations(mesh.p1, mesh.triangles) == [1] * len(mesh.triangles)
        frames = pair_paths(segment, T, "injective")
        _check_never_tangles(k0s, k1s, closed, [frames[k] for k in moving])
        checked += 1
    assert checked


def _band(centre: np.ndarray, width: float) -> np.ndarray:
    """A closed outline around an open centre line ``(M, 2)``: one side out, the other back."""
    tangent = np.gradient(centre, axis=0)
    normal = np.column_stack([-tangent[:, 1], tangent[:, 0]])
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    return np.vstack([centre + width * normal, (centre - width * normal)[::-1]])


def _spiral_and_star() -> tuple[np.ndarray, np.ndarray]:
    s = np.linspace(0.0, 3.0 * np.pi, 40)
    spiral = _band(np.column_stack([(1 + s) * np.cos(s), (1 + s) * np.sin(s)]), 0.25)
    n = len(spiral)
    angle = np.pi * np.arange(n) / (n // 2)
    radius = np.where(np.arange(n) % 2 == 0, 5.0, 2.0)
    star = np.column_stack([radius * np.cos(angle), radius * np.sin(angle)])
    return star, _counter_clockwise(spiral)


def _counter_clockwise(points: np.ndarray) -> np.ndarray:
    x, y = points[:, 0], points[:, 1]
    return points if np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y) > 0 else points[::-1].copy()


def _c_and_s() -> tuple[np.ndarray, np.ndarray]:
    u = np.linspace(0.0, 1.0, 41)
    c = _band(np.column_stack([np.cos(np.pi * (0.25 + 1.5 * u)), np.sin(np.pi * (0.25 + 1.5 * u))]), 0.15)
    upper = np.column_stack([np.cos(3 * np.pi * u[:21]), 1 + np.sin(3 * np.pi * u[:21])])
    lower = np.column_stack([np.cos(np.pi * (0.5 - 3 * u[1:21])), -1 + np.sin(np.pi * (0.5 - 3 * u[1:21]))])
    s = _band(np.vstack([upper, lower]) * 0.6, 0.1)
    return _counter_clockwise(c), _counter_clockwise(s)


def _hook_and_mirror() -> tuple[np.ndarray, np.ndarray]:
    hook = np.array([[0, 0], [4, 0], [4, 1], [1, 1], [1, 3], [3, 3], [3, 2], [2, 2], [2, 2.5], [1.5, 2.5],
                     [1.5, 1.5], [3.5, 1.5], [3.5, 3.5], [0, 3.5]], dtype=float)
    mirror = hook * [-1.0, 1.0]
    # a correspondence keeps the winding: the mirror is walked the other way round
    return hook, np.roll(mirror[::-1], 1, axis=0)


HARD = {"spiral-to-star": _spiral_and_star, "c-to-s": _c_and_s, "hook-to-mirror": _hook_and_mirror}


@pytest.mark.parametrize("name", sorted(HARD))
def test_hand_made_hard_pairs_never_tangle(name: str) -> None:
    k0, k1 = HARD[name]()
    assert len(k0) == len(k1)
    frames = interpolate(k0, k1, T, "injective")
    _check_never_tangles([k0], [k1], [True], [frames])
    mesh = injective_mesh([k0], [k1], [True])
    assert mesh is not None
    assert set(_exact_orientations(mesh.p0, mesh.triangles)) == {1}
    assert set(_exact_orientations(mesh.p1, mesh.triangles)) == {1}


@pytest.mark.parametrize("name", sorted(HARD))
def test_straight_paths_do_tangle_on_the_hard_pairs(name: str) -> None:
    """The hard pairs are hard: the linear in-betweens cross (so the test above means something)."""
    k0, k1 = HARD[name]()
    frames = interpolate(k0, k1, T, "linear")
    parent = parents_of([k0], [True])
    assert any(tangled([frame], [True], parent) for frame in frames)


def test_keys_come_back_bit_for_bit() -> None:
    k0, k1 = _c_and_s()
    frames = interpolate(k0, k1, [0.0, 0.5, 1.0], "injective")
    assert np.array_equal(frames[0], k0) and np.array_equal(frames[2], k1)
    contours = injective_contours([k0[:10], k0], [k1[:10] * 0.1, k1], [False, True], [0.0, 1.0])
    assert np.array_equal(contours[1][0], k0) and np.array_equal(contours[1][1], k1)


def test_a_rigid_turn_stays_rigid() -> None:
    k0, _ = _hook_and_mirror()
    turn = 1.1
    k1 = rotate(k0 - k0.mean(axis=0), turn) + [7.0, -3.0]
    frames = injective(k0, k1, T)
    centre0, centre1 = k0.mean(axis=0), k1.mean(axis=0)
    for frame, t in zip(frames, T):
        exact = rotate(k0 - centre0, t * turn) + (1 - t) * centre0 + t * centre1
        assert np.abs(frame - exact).max() < 1e-9 * np.ptp(k0)


def test_weights_beyond_the_segment_are_clamped() -> None:
    k0, k1 = _spiral_and_star()
    frames = injective(k0, k1, [1.0, 1.5])
    # the rigid part overshoots, the shape itself stays key 1's: the overshoot is a rigid motion of key 1
    rigid = frames[1] - frames[1].mean(axis=0)
    key = k1 - k1.mean(axis=0)
    assert np.allclose(np.linalg.norm(rigid, axis=1), np.linalg.norm(key, axis=1), atol=1e-9 * np.ptp(k1))


def test_mean_value_weights_reproduce_each_inner_vertex() -> None:
    rng = np.random.default_rng(3)
    ring = np.column_stack([np.cos(np.linspace(0, 2 * np.pi, 9)[:-1]), np.sin(np.linspace(0, 2 * np.pi, 9)[:-1])])
    inner = rng.uniform(-0.3, 0.3, (1, 2))
    points = np.vstack([ring, inner])
    triangles = np.array([[k, (k + 1) % 8, 8] for k in range(8)])
    rows, cols, w = mean_value_weights(points, triangles)
    mine = rows == 8
    assert np.all(w[mine] > 0) and np.isclose(w[mine].sum(), 1.0)
    assert np.allclose((w[mine, None] * points[cols[mine]]).sum(axis=0), inner[0], atol=1e-12)


def test_auto_takes_injective_paths_only_where_straight_ones_cross() -> None:
    star, spiral = _spiral_and_star()
    choice = auto_choice(star, spiral)
    assert choice.method == "injective", choice
    frames = interpolate(star, spiral, T, "auto")
    _check_never_tangles([star], [spiral], [True], [frames])
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    assert auto_choice(square, square * [2.0, 1.0]).method == "linear"
    assert auto_choice(square, rotate(square, 1.0)).method == "nonlinear"


def test_keys_that_cross_take_the_rigid_paths_without_error() -> None:
    bow = np.array([[0, 0], [2, 2], [2, 0], [0, 2]], dtype=float)
    square = np.array([[0, 0], [2, 0], [2, 2], [0, 2]], dtype=float)
    frames = interpolate(bow, square, T, "injective")
    assert np.all(np.isfinite(frames))
    assert injective_mesh([bow], [square], [True]) is None


def test_a_hole_that_changes_sides_is_refused_cleanly(tmp_path: Path) -> None:
    outer = np.array([[0, 0], [10, 0], [10, 10], [0, 10]], dtype=float)
    hole = np.array([[4, 4], [4, 6], [6, 6], [6, 4]], dtype=float)
    assert injective_mesh([outer, hole], [outer, hole + [20.0, 0.0]], [True, True]) is None
    mesh = injective_mesh([outer, hole], [outer * 1.5, hole + [1.0, 2.0]], [True, True])
    assert mesh is not None


def test_an_open_stroke_with_repeated_vertices_stays_inside_its_outline() -> None:
    outline0 = np.array([[0, 0], [10, 0], [10, 10], [0, 10]], dtype=float)
    outline1 = np.array([[0, 0], [12, -2], [8, 9], [-1, 7]], dtype=float)
    smile0 = np.array([[2, 6], [4, 3], [4, 3], [4, 3], [6, 3], [8, 6]], dtype=float)
    smile1 = np.array([[7, 2], [6, 2], [3, 4], [2, 6], [2, 6], [5, 7]], dtype=float)
    k0s, k1s, closed = [outline0, smile0], [outline1, smile1], [True, False]
    assert injective_mesh(k0s, k1s, closed) is not None
    frames = injective_contours(k0s, k1s, closed, T)
    _check_never_tangles(k0s, k1s, closed, frames)


def test_past_the_steiner_cap_the_rigid_paths_take_over(monkeypatch: pytest.MonkeyPatch) -> None:
    from tweenrender.core.methods import compatible

    k0, k1 = _spiral_and_star()
    assert injective_mesh([k0], [k1], [True]).steiner > 0  # type: ignore[union-attr]
    monkeypatch.setattr(compatible, "STEINER_CAP", 0)
    assert injective_mesh([k0], [k1 + 0.5], [True]) is None  # fresh keys: a mesh is kept by its keys
    frames = injective_contours([k0], [k1 + 0.25], [True], [0.5])  # fresh keys: not from the cache
    assert np.all(np.isfinite(frames[0]))


@pytest.mark.parametrize("size", [1e-300, 1e300])
def test_keys_near_the_ends_of_the_float_range_make_no_warning(size: float) -> None:
    import warnings

    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float) * size
    kite = np.array([[0, 0], [1, 0], [0.5, 1], [0, 1]], dtype=float) * size
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        frames = interpolate(square, kite, T, "injective")
        assert injective_mesh([square], [kite], [True]) is not None
    assert np.all(np.isfinite(frames))
    _check_never_tangles([square], [kite], [True], [frames])


def test_auto_keeps_an_open_stroke_from_crossing_itself() -> None:
    from tweenrender.model import Contour, Key, Matching, Shape

    # the way round stays near the keys here (auto takes no way round that carries a stroke further from them
    # than straight paths do: tests/core/test_auto_quality.py)
    k0 = np.array([[0, 0], [4, 0], [4, 4], [1, 4], [1, 1]], dtype=float)
    k1 = np.array([[2, 1], [4, 0], [3, 4], [1, 8], [2, 0]], dtype=float)
    straight = interpolate(k0, k1, T, "linear")
    assert any(tangled([f], [False], [None]) for f in straight)  # straight paths do cross here
    shape = Shape(name="stroke", keys=(Key(time=0.0, contours=(Contour(k0, closed=False),)),
                                       Key(time=1.0, contours=(Contour(k1, closed=False),))))
    segment = build_track(shape, Matching()).segments[0]
    frames = pair_paths(segment, T, "auto")[0]
    _check_never_tangles([k0], [k1], [False], [frames])


def test_each_t_is_solved_once_whatever_set_of_t_asks_for_it(monkeypatch: pytest.MonkeyPatch) -> None:
    """A frame depends on its t alone: asked again within another set of t it is the same, bit for bit,
    and its shape-keeping solve is not run again (counted; the first call also solves the samples the paths
    are paced by, once)."""
    from tweenrender.core.methods import bounded_distortion

    solves: list[float] = []
    original = bounded_distortion.ShapeKeepingSolve.__call__

    def counted(self, s):  # type: ignore[no-untyped-def]
        solves.append(s)
        return original(self, s)

    monkeypatch.setattr(bounded_distortion.ShapeKeepingSolve, "__call__", counted)
    k0, k1 = _spiral_and_star()
    k0, k1 = k0 * 1.0001, k1  # keys of their own: no earlier test's paths remembered
    alone = injective(k0, k1, [0.5, 0.25])
    first = list(solves)
    assert len(first) == len(set(first)) == len(PACE) + 2  # the pacing's samples and the two asked for
    solves.clear()
    sweep = injective(k0, k1, T)  # .05 … .95, 0.25 and 0.5 among them
    assert len(solves) == len(set(solves)) == len(T) - 2 and not set(solves) & set(first)
    assert np.array_equal(sweep[list(T).index(0.5)], alone[0])
    assert np.array_equal(sweep[list(T).index(0.25)], alone[1])


def _square_ring(centre: tuple[float, float], radius: float, corners: int, clockwise: bool) -> np.ndarray:
    angle = np.linspace(0.0, 2.0 * np.pi, corners, endpoint=False) + np.pi / 4
    ring = np.column_stack([centre[0] + radius * np.cos(angle), centre[1] + radius * np.sin(angle)])
    return ring[::-1].copy() if clockwise else ring


@pytest.mark.parametrize("order", [(1, 2, 3, 0), (2, 3, 0, 1), (1, 0, 3, 2), (3, 2, 1, 0)])
def test_holes_that_trade_places_are_meshed_through_bridges_of_new_points(order: tuple[int, ...]) -> None:
    # four holes in an octagon, each moving to another's place: no edge from a hole to another boundary is
    # an edge of both keys' triangulations, so bridges must be made of new points threaded through triangles
    places = [(-4.0, -4.0), (4.0, -4.0), (4.0, 4.0), (-4.0, 4.0)]
    outline = _square_ring((0.0, 0.0), 10.0, 8, clockwise=False)
    k0s = [outline] + [_square_ring(p, 1.0, 4, clockwise=True) for p in places]
    k1s = [outline] + [_square_ring(places[j], 1.0, 4, clockwise=True) for j in order]
    closed = [True] * 5
    mesh = injective_mesh(k0s, k1s, closed)
    assert mesh is not None, "simple keys that nest alike must be meshed"
    assert _exact_orientations(mesh.p0, mesh.triangles) == [1] * len(mesh.triangles)
    assert _exact_orientations(mesh.p1, mesh.triangles) == [1] * len(mesh.triangles)
    _check_never_tangles(k0s, k1s, closed, injective_contours(k0s, k1s, closed, T))


def test_pieces_wound_either_way_keep_the_area_they_enclose() -> None:
    # two pieces of one element (nonzero fill draws both whichever way each winds): one anticlockwise, one
    # clockwise that grows from a speck to the other's size; their in-betweens must enclose about the keys'
    # interpolated area at the path's own s (the frame at t is the path at s, paced), not a signed sum in
    # which the clockwise piece cancels the other
    big0, big1 = _square_ring((0.0, 0.0), 2.0, 4, clockwise=False), _square_ring((1.0, 0.0), 2.5, 4, clockwise=False)
    small0, small1 = _square_ring((6.0, 0.0), 0.01, 4, clockwise=True), _square_ring((7.0, 1.0), 2.5, 4, clockwise=True)
    frames = injective_contours([big0, small0], [big1, small1], [True, True], T)
    paths = _paths_of([big0, small0], [big1, small1], [True, True])[2]
    assert paths is not None

    def enclosed(ring: np.ndarray) -> float:
        x, y = ring[:, 0], ring[:, 1]
        return abs(0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)))

    for k, t in enumerate(T):
        s = paths._paced(float(t))
        assert 0.0 < s < 1.0
        expected = (1 - s) * (enclosed(big0) + enclosed(small0)) + s * (enclosed(big1) + enclosed(small1))
        assert enclosed(frames[0][k]) + enclosed(frames[1][k]) == pytest.approx(expected, rel=0.02), t


def test_outlines_touching_at_a_corner_are_meshed_and_come_apart_without_crossing() -> None:
    # two squares of one element share a corner in the first key (drawn that way: they touch); the mesh needs
    # its contours apart, so the shared vertex is moved a millionth into the smaller one, and the in-betweens,
    # checked with shapely, never meet
    import shapely

    a0 = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    b0 = np.array([[1.0, 1.0], [1.8, 1.0], [1.8, 1.8], [1.0, 1.8]])
    a1, b1 = a0 + [-0.5, 0.2], b0 + [0.6, -0.3]
    mesh = injective_mesh([a0, b0], [a1, b1], [True, True])
    assert mesh is not None, "touching outlines must be meshed, not left to the rigid paths"
    frames = injective_contours([a0, b0], [a1, b1], [True, True], T)
    for k, t in enumerate(T):
        assert not shapely.LinearRing(frames[0][k]).intersects(shapely.LinearRing(frames[1][k])), t
    start = injective_contours([a0, b0], [a1, b1], [True, True], [0.0])  # the key itself, touching as drawn
    assert np.array_equal(start[0][0], a0) and np.array_equal(start[1][0], b0)


def _square(x0: float, x1: float, per_side: int, clockwise: bool) -> np.ndarray:
    corners = np.array([(x0, x0), (x1, x0), (x1, x1), (x0, x1)])
    steps = np.arange(per_side)[:, None] / per_side
    ring = np.concatenate([a + steps * (b - a) for a, b in zip(corners, np.roll(corners, -1, axis=0))])
    return ring[::-1].copy() if clockwise else ring


def test_each_frame_step_changes_the_picture_alike() -> None:
    """A thin square ring filling in to a square with a small hole: the solve's path moves fastest at the start
    (the frame step after key 0 changed 4.2 × the median step before the paths were paced). Each step of a
    24-frame clip now changes the drawn region (shapely's symmetric difference of consecutive frames) by at
    most 2 × the median step, and the clip still starts and ends on its keys."""
    shapely = pytest.importorskip("shapely", reason="shapely (the test extra) measures the change independently")
    k0 = [_square(0.0, 10.0, 8, False), _square(1.0, 9.0, 8, True)]
    k1 = [_square(0.0, 10.0, 8, False), _square(4.5, 5.5, 8, True)]
    t = np.arange(25) / 24
    outline, hole = injective_contours(k0, k1, [True, True], t)
    drawn = [shapely.Polygon(outline[f], [hole[f]]) for f in range(len(t))]
    assert all(p.is_valid for p in drawn)
    change = np.array([drawn[f].symmetric_difference(drawn[f - 1]).area for f in range(1, len(t))])
    assert change.max() <= 2.0 * np.median(change), np.round(change, 2)
    assert np.array_equal(outline[0], k0[0]) and np.array_equal(hole[-1], k1[1])
