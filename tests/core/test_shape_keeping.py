"""Injective in-betweens keep near their keys and keep their shape (maths §5.16), checked with shapely.

The stray share is measured here with shapely's polygon buffers and differences, not with the
package's own measures; the closed forms are a triangle's turn-and-stretch and the keys themselves.
"""

from __future__ import annotations

import numpy as np
import pytest

shapely = pytest.importorskip("shapely", reason="shapely (the test extra) checks areas independently")
from shapely.geometry import Polygon  # noqa: E402
from shapely.ops import unary_union  # noqa: E402

import tweenrender as tr  # noqa: E402
from tests.helpers import DATA, count_calls  # noqa: E402
from tweenrender.core.methods.bounded_distortion import ShapeKeepingSolve  # noqa: E402
from tweenrender.core.methods.injective import injective_mesh  # noqa: E402

ICONS = DATA / "icons"
T = np.round(np.arange(1, 20) * 0.05, 2)
# pairs whose convex-combination in-betweens balloon out of the keys or slide off centre
WANDERING = [("octicons/check-circle-24", "heroicons/check-circle"), ("heroicons/star", "feather/x-circle"),
             ("mdi/weather-sunny", "twemoji/1f3a8")]


def _area(contours: list) -> Polygon:
    filled = [Polygon(c.points).buffer(0) for c in contours if c.closed and len(c.points) >= 3]
    return unary_union(filled) if filled else Polygon()


@pytest.mark.parametrize("a, b", WANDERING, ids=[f"{a}->{b}" for a, b in WANDERING])
def test_injective_in_betweens_stay_near_their_keys(a: str, b: str) -> None:
    scene = tr.load_scene([ICONS / f"{a}.svg", ICONS / f"{b}.svg"])
    k0, k1 = tr.contours(scene, 0.0, method="injective"), tr.contours(scene, 1.0, method="injective")
    points = np.concatenate([c.points for c in k0 + k1])
    near = unary_union([_area(k0), _area(k1)]).buffer(0.12 * float(np.ptp(points, axis=0).max()))
    for t in T:
        drawn = _area(tr.contours(scene, float(t), method="injective"))
        assert drawn.difference(near).area <= 0.02 * drawn.area, f"t = {t}"


def _solve_for(a: str, b: str) -> tuple[ShapeKeepingSolve, object]:
    scene = tr.load_scene([ICONS / f"{a}.svg", ICONS / f"{b}.svg"])
    from tweenrender.core.timing.timeline import build_track

    for shape in scene.shapes:
        track = build_track(shape, scene.matching, unmatched=scene.unmatched, balance=scene.balance_of(shape))
        for segment in track.segments:
            moving = [p for p in segment.pairs if p.moving]
            if moving:
                mesh = injective_mesh([p.k0 for p in moving], [p.k1 for p in moving], [p.closed for p in moving])
                if mesh is not None:
                    return ShapeKeepingSolve(mesh, np.ones(len(mesh.triangles), dtype=bool)), mesh
    raise AssertionError("no mesh")


def test_each_target_turns_and_stretches_by_a_share_of_its_triangles_change() -> None:
    solve, mesh = _solve_for("heroicons/star", "feather/x-circle")
    p0, p1, tri = mesh.p0, mesh.p1, mesh.triangles
    j = int(np.flatnonzero(solve.good)[0])
    e0 = np.column_stack([p0[tri[j, 1]] - p0[tri[j, 0]], p0[tri[j, 2]] - p0[tri[j, 0]]])
    e1 = np.column_stack([p1[tri[j, 1]] - p1[tri[j, 0]], p1[tri[j, 2]] - p1[tri[j, 0]]])
    change = e1 @ np.linalg.inv(e0)
    # polar decomposition by the closed form of a 2x2 matrix: R is the rotation nearest to it
    angle = np.arctan2(change[1, 0] - change[0, 1], change[0, 0] + change[1, 1])
    turn = np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]])
    stretch = turn.T @ change
    for s in (0.0, 0.3, 1.0):
        half = np.array([[np.cos(s * angle), -np.sin(s * angle)], [np.sin(s * angle), np.cos(s * angle)]])
        expected = half @ ((1 - s) * np.eye(2) + s * stretch)
        np.testing.assert_allclose(solve.targets(s)[j], expected, atol=1e-9)


def test_the_solve_gives_the_keys_at_the_ends_and_every_triangle_its_orientation_between() -> None:
    solve, mesh = _solve_for("octicons/check-circle-24", "heroicons/check-circle")
    np.testing.assert_array_equal(solve(0.0), mesh.p0)
    np.testing.assert_array_equal(solve(1.0), mesh.p1)
    tri = mesh.triangles
    for s in (0.25, 0.5, 0.75):
        x = solve(s)
        a, b = x[tri[:, 1]] - x[tri[:, 0]], x[tri[:, 2]] - x[tri[:, 0]]
        assert np.all((a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0])[solve.good] > 0), s


def _shoelace(contours: list[np.ndarray]) -> float:
    return sum(0.5 * float(np.sum(c[:, 0] * np.roll(c[:, 1], -1) - np.roll(c[:, 0], -1) * c[:, 1])) for c in contours)


def test_a_stretched_key_is_reached_through_the_blended_stretch() -> None:
    # key 1 is key 0 (a five-lobed outline with a hole) under a symmetric stretch S: every triangle's change
    # is S, so the in-between at t is key 0 under (1 − t)·I + t·S, then sized to the keys' blended area
    from tweenrender.core.methods.injective import injective_contours

    angle = np.linspace(0, 2 * np.pi, 40, endpoint=False)
    radius = 1 + 0.3 * np.cos(5 * angle)
    outer = np.column_stack([radius * np.cos(angle), radius * np.sin(angle)])
    hole = 0.3 * np.column_stack([np.cos(angle[::-1]), np.sin(angle[::-1])]) + [0.2, 0.1]
    stretch = np.array([[2.0, 0.3], [0.3, 0.8]])
    k0, k1 = [outer, hole], [outer @ stretch.T, hole @ stretch.T]
    for t in (0.25, 0.5, 0.75):
        found = np.concatenate([f[0] for f in injective_contours(k0, k1, [True, True], np.array([t]))])
        blended = [c @ ((1 - t) * np.eye(2) + t * stretch).T for c in k0]
        goal = (1 - t) * _shoelace(k0) + t * _shoelace(k1)
        expected = np.concatenate(blended)
        expected = (expected - expected.mean(axis=0)) * np.sqrt(goal / _shoelace(blended))
        # within 0.4 % of the outline's size (the blended weights of a convex-combination solve miss by 1 %)
        assert np.abs((found - found.mean(axis=0)) - expected).max() < 0.01, t


# pairs whose shape-keeping targets cannot all keep their orientation at once: the in-between must still
# keep close to them, not fall back to the convex-combination solve (edges stretched 30–47 % off the rest)
UNKEPT = [("lucide/moon", "lucide/star"), ("lucide/smile", "mdi/weather-sunny"), ("lucide/heart", "octicons/moon-24")]


def _edge_spread(key0: list, now: list, key1: list, t: float) -> float:
    """How unevenly the edges stretch: each edge's log length at ``t`` over the blend of its key lengths,
    the length-weighted mean distance of those logs from their mean (a similarity scores 0)."""
    logs, weights = [], []
    side = float(np.ptp(np.concatenate([c.points for c in key0 + key1]), axis=0).max())
    for a, m, b in zip(key0, now, key1):
        rings = [np.vstack([c.points, c.points[:1]]) if c.closed else c.points for c in (a, m, b)]
        l0, lt, l1 = (np.hypot(*np.diff(r, axis=0).T) for r in rings)
        blend = (1 - t) * l0 + t * l1
        use = blend > 1e-4 * side
        logs.append(np.log(lt[use] / blend[use]))
        weights.append(blend[use])
    w, x = np.concatenate(weights), np.concatenate(logs)
    return float(np.sum(w * np.abs(x - np.sum(w * x) / w.sum())) / w.sum())


@pytest.mark.parametrize("a, b", UNKEPT, ids=[f"{a}->{b}" for a, b in UNKEPT])
def test_where_no_solve_keeps_every_target_the_in_betweens_still_keep_their_shape(a: str, b: str) -> None:
    scene = tr.load_scene([ICONS / f"{a}.svg", ICONS / f"{b}.svg"])
    ends = [tr.contours(scene, t, method="injective", points=True) for t in (1e-6, 1 - 1e-6)]
    assert [len(c.points) for c in ends[0]] == [len(c.points) for c in ends[1]]
    for t in T:
        now = tr.contours(scene, float(t), method="injective", points=True)
        assert _edge_spread(ends[0], now, ends[1], float(t)) <= 0.15, f"t = {t}"


def test_the_descent_keeps_within_its_work_bound(monkeypatch: pytest.MonkeyPatch) -> None:
    # counted work, not seconds: every SLIM round of a mesh's grid points and in-betweens is counted; a mesh
    # whose grid points would pass the bound takes fewer rounds each, and one too large for a single round
    # takes the convex-combination solve as it is
    from tweenrender.core.methods import bounded_distortion as bd
    from tweenrender.core.methods import mesh_distortion as md

    rounds = count_calls(monkeypatch, md, "_slim_goal")
    solve, mesh = _solve_for("lucide/moon", "lucide/star")
    triangles = len(mesh.triangles)
    for s in T:
        solve(float(s))
    per_link = min(bd._LINK, bd._WORK // (2 * (bd._GRID - 1) * triangles))
    assert 0 < len(rounds) <= 2 * (bd._GRID - 1) * per_link  # the in-betweens blend the grid points: no rounds of their own
    monkeypatch.setattr(bd, "_WORK", 2 * (bd._GRID - 1) * triangles - 1)  # not one round per grid point
    solve, mesh = _solve_for("lucide/moon", "lucide/star")
    rounds.clear()
    from tweenrender.core.methods.tutte import mean_value_weights

    w0, w1 = mean_value_weights(mesh.p0, mesh.triangles)[2], mean_value_weights(mesh.p1, mesh.triangles)[2]
    for s in (0.3, 0.5, 0.7):  # the convex-combination solve: the keys' weights blended
        np.testing.assert_array_equal(solve(s), solve.embedding((1 - s) * w0 + s * w1))
    assert rounds == []


def _region(contours: list) -> Polygon:
    """The area the closed contours draw, even-odd (a hole inside an outline is left out)."""
    region = Polygon()
    for c in contours:
        if c.closed and len(c.points) >= 3:
            region = region.symmetric_difference(Polygon(c.points).buffer(0))
    return region


# injective in-betweens whose descent from key 0 could not keep up with its targets: the last grid point lay
# far from key 1 and was chosen as the nearer to its targets, so the drawing jumped to key 1 in the last
# frame step (the pops of the design, the whole python's lower half at once)
JUMPING = [("tabler/mood-smile", "simple-icons/python")]


@pytest.mark.parametrize("a, b", JUMPING, ids=[f"{a}->{b}" for a, b in JUMPING])
def test_injective_in_betweens_reach_their_keys_without_a_jump(a: str, b: str) -> None:
    """The area swept between consecutive frames (shapely's symmetric difference of the drawn regions, 24
    frames a second) is nowhere over 3 × its median: the pops rule of the design."""
    scene = tr.load_scene([ICONS / f"{a}.svg", ICONS / f"{b}.svg"])
    regions = [_region(tr.contours(scene, f / 24, method="injective")) for f in range(25)]
    steps = np.array([p.symmetric_difference(q).area for p, q in zip(regions, regions[1:])])
    assert steps.max() <= 3.0 * np.median(steps), (int(steps.argmax()) + 1, steps.max() / np.median(steps))


def test_the_descents_of_one_mesh_order_its_normal_matrix_once(monkeypatch) -> None:
    """Every grid point's descent fits the same mesh, so its normal matrices share one sparsity: the LDLᵀ
    factorisation's ordering and elimination tree are worked out once for all of them (counted), each round
    of every descent refactoring in place (it took one ordering a descent)."""
    qdldl = pytest.importorskip("qdldl", reason="the counted factorisation is qdldl's")
    made: list[int] = []
    real = qdldl.Solver

    def counted(*args, **kwargs):  # noqa: ANN002, ANN003, ANN202
        made.append(1)
        return real(*args, **kwargs)

    monkeypatch.setattr(qdldl, "Solver", counted)
    solve, _ = _solve_for("mdi/weather-sunny", "twemoji/1f3a8")
    descended = [s for s in (0.3, 0.5, 0.7) if not np.all(solve(s) == solve.convex(s))]
    assert descended and solve._sides, "the pair no longer takes the descents"
    assert len(made) == 1, len(made)


# injective in-betweens that blend the grid points' kept vertices: alpha-a → alpha-b takes the descents at
# most t, check-circle → star the direct fits
CORNERED = [("mdi/alpha-a", "mdi/alpha-b"), ("octicons/check-circle-24", "heroicons/check-circle")]


def _turns(scene: tr.Scene, frames: int) -> tuple[np.ndarray, np.ndarray]:
    """The angle (radians) each vertex's path turns through between two frame steps, ``frames`` steps over the
    segment, 90th percentile over the vertices of each frame, with the frames' t: two ``(frames - 3,)``.
    Vertices barely moving (under 1/1000 of the drawing's size a step) are left out: their direction is
    rounding."""
    t = np.arange(1, frames) / frames
    paths = np.stack([np.concatenate([c.points for c in tr.contours(scene, float(s), method="injective",
                                                                   points=True)]) for s in t])  # (T, V, 2)
    steps = np.diff(paths, axis=0)  # (T - 1, V, 2)
    size = float(np.ptp(paths.reshape(-1, 2), axis=0).max())
    a, b = steps[:-1], steps[1:]
    moving = (np.linalg.norm(a, axis=-1) > 1e-3 * size / frames) & (np.linalg.norm(b, axis=-1) > 1e-3 * size / frames)
    turn = np.abs(np.arctan2(a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0], np.sum(a * b, axis=-1)))
    return np.array([np.percentile(row[keep], 90) if keep.any() else 0.0 for row, keep in zip(turn, moving)]), t[1:-1]


@pytest.mark.parametrize("a, b", CORNERED, ids=[f"{a}->{b}" for a, b in CORNERED])
def test_injective_vertex_paths_turn_no_corners(a: str, b: str) -> None:
    """A vertex's path is smooth: sampled twice as finely, it turns about half as sharply between two steps
    about each frame (a corner turns through its whole angle however finely it is sampled). Checked from the
    second sixteenth of the segment to the fifteenth: next to a key the chain of grid points from the other
    key comes in, a bend sharper than a sixteenth's samples resolve."""
    scene = tr.load_scene([ICONS / f"{a}.svg", ICONS / f"{b}.svg"])
    coarse, at = _turns(scene, 96)
    fine, _ = _turns(scene, 192)
    # the fine frames about each coarse one: coarse frame i is at t = (i + 2) / 96 = (2i + 4) / 192, fine frame 2i + 2
    near = np.max(np.stack([fine[1::2][:len(coarse)], fine[2::2][:len(coarse)], fine[3::2][:len(coarse)]]), axis=0)
    inner = (at > 1 / 16) & (at < 15 / 16)
    assert near[inner].max() <= 0.7 * coarse[inner].max(), (coarse[inner].max(), near[inner].max())
