"""Q-curves, motion classification and the auto method (maths §3), checked against
facts computed directly from the polygons in each test."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tweenrender.core.methods import joints, paths, qcurves

# -- independent helpers -------------------------------------------------------


def turn(points: np.ndarray, phi: float) -> np.ndarray:
    """Counter-clockwise rotation about the origin by a rotation matrix."""
    c, s = np.cos(phi), np.sin(phi)
    return points @ np.array([[c, s], [-s, c]])


def shoelace(points: np.ndarray) -> float:
    x, y = points[:, 0], points[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def star(rng: np.random.Generator, n: int) -> np.ndarray:
    """A random simple counter-clockwise polygon (star-shaped about the origin)."""
    angles = np.sort(rng.uniform(0, 2 * np.pi, n))
    angles += np.arange(n) * 0.2 / n  # keeps angles apart
    radii = rng.uniform(0.5, 2.0, n)
    return np.stack([radii * np.cos(angles), radii * np.sin(angles)], axis=1)


def convex(rng: np.random.Generator, n: int) -> np.ndarray:
    """A random convex counter-clockwise polygon (points on an ellipse)."""
    angles = np.sort(rng.uniform(0, 2 * np.pi, n)) + np.arange(n) * 0.3 / n
    return np.stack([3 * np.cos(angles), 1.5 * np.sin(angles)], axis=1) + rng.normal(size=2)


def size2(*keys: np.ndarray) -> float:
    return max(float(np.max(np.sum((np.roll(k, -1, 0) - k) ** 2, axis=1))) for k in keys)


ROTATIONS_DEG = [-179.0, -135.0, -90.0, -45.0, -10.0, 10.0, 30.0, 45.0, 90.0, 135.0, 170.0]


# -- control points ------------------------------------------------------------


@settings(max_examples=60, deadline=None)
@given(
    n=st.integers(3, 9),
    phi=st.floats(-np.pi, np.pi),
    shift=st.tuples(st.floats(-50, 50), st.floats(-50, 50)),
    seed=st.integers(0, 2**32 - 1),
)
def test_rigid_rotation_gives_q0_eq_q2_and_q1_cos_phi_q0(n, phi, shift, seed):
    k0 = star(np.random.default_rng(seed), n)
    k1 = turn(k0, phi) + np.array(shift)
    q = qcurves.control_points(k0, k1)
    tol = 1e-9 * size2(k0, k1) + 1e-9 * float(np.abs(shift).max()) * np.sqrt(size2(k0))
    np.testing.assert_allclose(q[:, 2], q[:, 0], atol=tol)
    np.testing.assert_allclose(q[:, 1], np.cos(phi) * q[:, 0], atol=tol)


def test_translation_gives_three_coincident_points():
    rng = np.random.default_rng(3)
    k0 = star(rng, 7)
    q = qcurves.control_points(k0, k0 + np.array([12.5, -3.0]))
    np.testing.assert_allclose(q[:, 1], q[:, 0], atol=1e-12)
    np.testing.assert_allclose(q[:, 2], q[:, 0], atol=1e-12)


def test_control_points_are_dot_and_cross_of_the_edges():
    k0 = np.array([[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0]])
    q = qcurves.control_points(k0, k0)
    # Vertex 0 of a counter-clockwise rectangle: F = (4, 0), B = (0, 3); a right angle.
    np.testing.assert_allclose(q[0], [[0.0, 12.0]] * 3)


@pytest.mark.parametrize("seed", range(8))
def test_evaluate_follows_linearly_interpolated_edges(seed):
    rng = np.random.default_rng(seed)
    k0, k1 = rng.normal(size=(6, 2)), rng.normal(size=(6, 2))
    t = np.linspace(0, 1, 9)
    got = qcurves.evaluate(qcurves.control_points(k0, k1), t)
    for i, ti in enumerate(t):
        v = (1 - ti) * k0 + ti * k1
        b, f = np.roll(v, 1, axis=0) - v, np.roll(v, -1, axis=0) - v
        want = np.stack([np.sum(f * b, axis=1), f[:, 0] * b[:, 1] - f[:, 1] * b[:, 0]], axis=1)
        np.testing.assert_allclose(got[i], want, atol=1e-12)


@pytest.mark.parametrize("seed", range(10))
def test_triangle_control_points_are_collinear_with_area_heights(seed):
    rng = np.random.default_rng(seed)
    k0, k1 = rng.normal(size=(3, 2)) * 3, rng.normal(size=(3, 2)) * 3
    q = qcurves.control_points(k0, k1)
    a0, a1 = shoelace(k0), shoelace(k1)
    mixed2 = 4 * shoelace(0.5 * (k0 + k1)) - a0 - a1  # twice the mixed area
    for j, height in enumerate([2 * a0, mixed2, 2 * a1]):
        p = q[:, j]
        np.testing.assert_allclose(p[:, 1], height, atol=1e-9)
        u, v = p[1] - p[0], p[2] - p[0]
        assert abs(u[0] * v[1] - u[1] * v[0]) <= 1e-9 * (1 + np.abs(p).max() ** 2)


def test_quadrilateral_control_points_are_not_collinear():
    # The collinearity above is a property of triangles, not of every polygon.
    k0 = np.array([[0.0, 0.0], [4.0, 0.0], [5.0, 2.0], [0.5, 3.0]])
    q0 = qcurves.control_points(k0, k0)[:, 0]
    u, v = q0[1] - q0[0], q0[2] - q0[0]
    assert abs(u[0] * v[1] - u[1] * v[0]) > 1.0


# -- angles --------------------------------------------------------------------


@pytest.mark.parametrize("seed", range(6))
def test_angle_at_ends_are_the_interior_angles_of_convex_keys(seed):
    rng = np.random.default_rng(seed)
    k0, k1 = convex(rng, 6), convex(rng, 6)
    got = qcurves.angle_at(qcurves.control_points(k0, k1), [0.0, 1.0])
    for row, k in zip(got, (k0, k1)):
        prev, nxt = np.roll(k, 1, axis=0), np.roll(k, -1, axis=0)
        a = np.linalg.norm(prev - k, axis=1)
        b = np.linalg.norm(nxt - k, axis=1)
        c = np.linalg.norm(nxt - prev, axis=1)
        interior = np.arccos((a * a + b * b - c * c) / (2 * a * b))  # law of cosines
        np.testing.assert_allclose(row, interior, atol=1e-9)
        assert np.isclose(row.sum(), (len(k) - 2) * np.pi)


@pytest.mark.parametrize("seed", range(6))
def test_angle_at_ends_are_signed_turns_from_forward_to_backward_edge(seed):
    rng = np.random.default_rng(100 + seed)
    k0, k1 = rng.normal(size=(7, 2)), rng.normal(size=(7, 2))
    got = qcurves.angle_at(qcurves.control_points(k0, k1), [0.0, 1.0])
    for row, k in zip(got, (k0, k1)):
        b, f = np.roll(k, 1, axis=0) - k, np.roll(k, -1, axis=0) - k
        want = np.arctan2(b[:, 1], b[:, 0]) - np.arctan2(f[:, 1], f[:, 0])
        diff = (row - want + np.pi) % (2 * np.pi) - np.pi
        np.testing.assert_allclose(diff, 0.0, atol=1e-9)


def _sampled_fold(k0: np.ndarray, k1: np.ndarray) -> np.ndarray:
    """Per vertex: do its two edges point the same way at some sampled t in (0, 1)?"""
    t = np.linspace(0, 1, 20001)[1:-1, None, None]
    v = (1 - t) * k0 + t * k1
    b, f = np.roll(v, 1, axis=1) - v, np.roll(v, -1, axis=1) - v
    c = f[..., 0] * b[..., 1] - f[..., 1] * b[..., 0]
    d = np.sum(f * b, axis=-1)
    flips = np.sign(c[1:]) != np.sign(c[:-1])
    return (flips & (d[1:] > 0)).any(axis=0)


def test_passes_through_zero_when_two_edges_fold_over_each_other():
    # The edge from vertex 0 to vertex 2 swings down through the edge to vertex 1:
    # at t = 0.5 the triangle is flat with vertex 2 between 0 and 1, so vertices 0
    # and 1 see their edges fold (angle 0) while vertex 2 sees a straight angle.
    k0 = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    k1 = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, -1.0]])
    got = qcurves.passes_through_zero(qcurves.control_points(k0, k1))
    assert got.tolist() == [True, True, False]
    assert got.tolist() == _sampled_fold(k0, k1).tolist()


def test_swinging_the_other_way_passes_through_180_not_zero():
    k0 = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    k1 = np.array([[0.0, 0.0], [1.0, 0.0], [-1.0, -1.0]])
    got = qcurves.passes_through_zero(qcurves.control_points(k0, k1))
    assert got[0] == False  # noqa: E712  (vertex 0 opens through a straight angle)
    assert got.tolist() == _sampled_fold(k0, k1).tolist()


@pytest.mark.parametrize("deg", ROTATIONS_DEG)
def test_rigid_rotation_below_180_never_passes_through_zero(deg):
    k0 = star(np.random.default_rng(int(deg) + 500), 8)
    q = qcurves.control_points(k0, turn(k0, np.radians(deg)) + [3.0, -1.0])
    assert not qcurves.passes_through_zero(q).any()
    assert not qcurves.non_monotonic(q).any()
    assert not qcurves.sweeps_over_180(q).any()


@pytest.mark.parametrize("seed", range(40))
def test_angle_predicates_agree_with_sampled_angles(seed):
    rng = np.random.default_rng(seed)
    k0, k1 = rng.normal(size=(5, 2)), rng.normal(size=(5, 2))
    q = qcurves.control_points(k0, k1)
    t = np.linspace(0, 1, 4001)
    theta = np.unwrap(qcurves.angle_at(q, t), axis=0)
    step = np.diff(theta, axis=0)
    point = qcurves.evaluate(q, t)
    clearance = np.linalg.norm(point, axis=-1).min(axis=0) / np.abs(q).max(axis=(1, 2))
    fold = _sampled_fold(k0, k1)
    non_monotonic = qcurves.non_monotonic(q)
    sweeps = qcurves.sweeps_over_180(q)
    zero = qcurves.passes_through_zero(q)
    for i in range(5):
        if clearance[i] < 1e-2 or np.abs(step[:, i]).min() < 1e-9:
            continue  # too close to the origin or to a stationary angle to sample reliably
        turned_back = bool((np.sign(step[:, i]) != np.sign(step[0, i])).any())
        assert non_monotonic[i] == turned_back
        if not turned_back:
            assert sweeps[i] == (abs(theta[-1, i] - theta[0, i]) > np.pi)
        assert zero[i] == fold[i]


def test_sweeps_over_180_on_a_hand_built_case():
    # B turns +170° while F turns -160°: the angle from F to B opens by 330°.
    def vertex(b: float, f: float) -> np.ndarray:
        return np.array([[0.0, 0.0], [np.cos(f), np.sin(f)], [np.cos(b), np.sin(b)]])

    k0 = vertex(np.radians(0), np.radians(-10))
    k1 = vertex(np.radians(170), np.radians(-170))
    q = qcurves.control_points(k0, k1)
    assert qcurves.sweeps_over_180(q)[0]
    assert not qcurves.non_monotonic(q)[0]


# -- classification ------------------------------------------------------------


@pytest.mark.parametrize("n", [3, 4, 7])
def test_translation_is_classified_as_translation(n):
    k0 = star(np.random.default_rng(n), n)
    m = qcurves.classify(k0, k0 + [40.0, -7.0])
    assert (m.kind, m.rotation_deg, m.why) == ("translation", 0.0, "pure translation")


@pytest.mark.parametrize("n", [3, 4, 6, 11])
@pytest.mark.parametrize("deg", ROTATIONS_DEG + [180.0])
def test_rotation_with_translation_is_classified_as_rotation(n, deg):
    rng = np.random.default_rng(n * 1000 + int(deg) + 180)
    k0 = star(rng, n)
    k1 = turn(k0, np.radians(deg)) + rng.normal(scale=10, size=2)
    m = qcurves.classify(k0, k1)
    assert m.kind == "rotation"
    assert m.rotation_deg == pytest.approx(deg, abs=1e-9)
    assert m.why == f"rigid rotation of {deg:.1f} degrees"
    assert qcurves.vertex_kinds(qcurves.control_points(k0, k1), 1e-9) == ["rotation"] * n


def test_exact_half_turn_reports_plus_180():
    # -k is an exact half turn (no rounding in sin π): the angle is π, never -π.
    k0 = star(np.random.default_rng(9), 5)
    m = qcurves.classify(k0, -k0)
    assert (m.kind, m.rotation_deg, m.why) == ("rotation", 180.0, "rigid rotation of 180.0 degrees")


@pytest.mark.parametrize("seed", range(12))
def test_random_deformations_are_nonrigid(seed):
    rng = np.random.default_rng(seed)
    k0 = star(rng, 6)
    k1 = turn(k0 + rng.normal(scale=0.2, size=k0.shape), rng.uniform(-3, 3)) + rng.normal(size=2)
    m = qcurves.classify(k0, k1)
    assert m.kind == "nonrigid"
    assert m.why.startswith("non-rigid change")


@pytest.mark.parametrize(
    "change",
    [
        lambda k: 1.5 * k,  # uniform scaling
        lambda k: turn(k, 0.7) * 0.8,  # rotation with shrinking
        lambda k: k * [-1.0, 1.0],  # mirror image
        lambda k: k * [1.0, 2.0],  # stretch
    ],
)
def test_similar_but_not_congruent_keys_are_nonrigid(change):
    k0 = star(np.random.default_rng(4), 6)
    assert qcurves.classify(k0, change(k0)).kind == "nonrigid"


def test_nonrigid_why_gives_the_edge_change_in_percent():
    k0 = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    k1 = np.array([[0.0, 0.0], [1.38, 0.0], [1.38, 1.0], [0.0, 1.0]])
    assert qcurves.classify(k0, k1).why == "non-rigid change (edge lengths change by up to 38%)"


@pytest.mark.parametrize("scale", [1e-3, 1.0, 1e3])
@pytest.mark.parametrize(
    "make",
    [
        lambda k: k + [2.0, 1.0],
        lambda k: turn(k, np.radians(60)) + [2.0, 1.0],
        lambda k: turn(k, np.radians(-120)),
        lambda k: k * [1.05, 1.0],
    ],
)
def test_classification_does_not_depend_on_the_units(scale, make):
    k0 = star(np.random.default_rng(21), 7)
    k1 = make(k0)
    want = qcurves.classify(k0, k1)
    got = qcurves.classify(scale * k0, scale * k1)
    assert got.kind == want.kind
    assert got.rotation_deg == pytest.approx(want.rotation_deg, abs=1e-9)
    assert qcurves.auto_choice(scale * k0, scale * k1) == qcurves.auto_choice(k0, k1)


def test_rigidly_rotated_triangle_is_a_rotation():
    k0 = np.array([[0.0, 0.0], [3.0, 0.0], [1.0, 2.0]])
    for deg in (-150.0, -20.0, 5.0, 90.0):
        m = qcurves.classify(k0, turn(k0, np.radians(deg)) + [7.0, 7.0])
        assert (m.kind, round(m.rotation_deg, 9)) == ("rotation", deg)


def test_vertex_kinds_read_each_neighbourhood():
    # Only vertex 2 moves: its own neighbourhood and both neighbours' change shape,
    # while vertex 0, whose edges go to untouched vertices, only translates (stays).
    k0 = np.array([[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [2.0, 5.0], [0.0, 3.0]])
    k1 = k0.copy()
    k1[2] = [5.0, 3.5]
    kinds = qcurves.vertex_kinds(qcurves.control_points(k0, k1), 1e-9)
    assert kinds == ["translation", "nonrigid", "nonrigid", "nonrigid", "translation"]


def test_edges_trading_length_at_a_vertex_are_not_a_rotation():
    # At vertex 0 the forward edge doubles and the backward edge halves: the angle
    # and |F|·|B| are kept, so Q0 = Q2, but Q1 = 1.25·Q0 lies beyond Q0.
    k0 = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    k1 = np.array([[0.0, 0.0], [2.0, 0.0], [0.0, 0.5]])
    q = qcurves.control_points(k0, k1)
    np.testing.assert_allclose(q[0, 2], q[0, 0])
    np.testing.assert_allclose(q[0, 1], 1.25 * q[0, 0])
    assert qcurves.vertex_kinds(q, 1e-9)[0] == "nonrigid"
    hand = np.array([[[0.0, 2.0], [0.0, 1.0], [0.0, 2.0]], [[3.0, 1.0]] * 3])
    assert qcurves.vertex_kinds(hand, 1e-9) == ["rotation", "translation"]
    assert qcurves.vertex_kinds(hand, [1.5, 0.0]) == ["translation", "translation"]


# -- auto ----------------------------------------------------------------------


def test_auto_choice_whole_shape():
    k0 = star(np.random.default_rng(2), 5)
    rot = qcurves.auto_choice(k0, turn(k0, np.radians(90)) + [5.0, 0.0])
    assert rot == qcurves.AutoChoice("nonlinear", "rigid rotation of 90.0 degrees", ("nonlinear",))
    move = qcurves.auto_choice(k0, k0 + 1.0)
    assert move == qcurves.AutoChoice("linear", "pure translation", ("linear",))
    bend = qcurves.auto_choice(k0, 1.2 * k0)
    assert (bend.method, bend.bodies) == ("linear", ("linear",))
    assert bend.why.startswith("non-rigid change")


def test_auto_follows_its_choice():
    k0 = star(np.random.default_rng(8), 6)
    t = np.linspace(0, 1, 11)
    k1 = turn(k0, np.radians(120)) + [1.0, 2.0]
    np.testing.assert_array_equal(qcurves.auto(k0, k1, t), paths.nonlinear(k0, k1, t))
    for k1 in (k0 + [3.0, 4.0], 0.5 * k0):
        np.testing.assert_array_equal(qcurves.auto(k0, k1, t), paths.linear(k0, k1, t))


def _limb_scene(deg: float):
    """A square torso with a long thin limb hinged at vertex 2; the limb swings about it."""
    k0 = np.array([[-2, -2], [2, -2], [2, 1.5], [8, 1.5], [8, 2], [2, 2], [-2, 2]], dtype=float)
    limb = [2, 3, 4, 5]
    k1 = k0.copy()
    k1[limb] = k0[2] + turn(k0[limb] - k0[2], np.radians(deg))
    return k0, k1, [(2, 5)]


def test_auto_choice_per_body():
    k0, k1, joint = _limb_scene(45.0)
    choice = qcurves.auto_choice(k0, k1, joint)
    # Bodies in joints.bodies order: torso [0, 1, 2, 5, 6] (its vertex 5 moves), limb [2..5].
    assert choice.bodies == ("linear", "nonlinear")
    assert choice.method == "jointed"
    assert choice.why == "bodies: non-rigid change / rotation of 45.0 degrees"
    still = qcurves.auto_choice(k0, k0 + 1.0, joint)
    assert still == qcurves.AutoChoice("linear", "bodies: pure translation / pure translation",
                                       ("linear", "linear"))


def _unit_spoke_scale(phi: float, t: np.ndarray) -> np.ndarray:
    """|B(t)| of the thesis's Bézier for a unit spoke turning by phi about a fixed center."""
    p0 = np.array([1.0, 0.0])
    p2 = np.array([np.cos(phi), np.sin(phi)])
    p1 = 2 * np.array([np.cos(phi / 2), np.sin(phi / 2)]) - 0.5 * (p0 + p2)
    s = (1 - t)[:, None]
    return np.linalg.norm(s * s * p0 + 2 * s * t[:, None] * p1 + (t * t)[:, None] * p2, axis=1)


def test_auto_with_joints_uses_each_body_choice():
    k0, k1, joint = _limb_scene(60.0)
    t = np.linspace(0, 1, 7)
    got = qcurves.auto(k0, k1, t, joint)
    torso, limb = [0, 1, 2, 5, 6], [2, 3, 4, 5]
    # The torso (most vertices, linear: it does not turn rigidly) leads on straight paths.
    a = paths.linear(k0[torso], k1[torso], t)
    np.testing.assert_allclose(got[:, [0, 1, 6]], a[:, [0, 1, 4]], atol=1e-12)
    # The limb (nonlinear: a rigid turn) turns about its joint, whose midpoint goes straight...
    np.testing.assert_allclose(got[:, [2, 5]].mean(axis=1), 0.5 * (a[:, 2] + a[:, 3]), atol=1e-12)
    # ...and keeps its shape: every edge, the joint's width included, scales like a spoke of the
    # thesis's Bézier turning 60 degrees about a fixed center.
    def lengths(p: np.ndarray) -> np.ndarray:
        return np.linalg.norm(np.roll(p, -1, axis=-2) - p, axis=-1)

    ratio = lengths(got[:, limb]) / lengths(k0[limb])
    np.testing.assert_allclose(ratio, np.repeat(_unit_spoke_scale(np.radians(60), t)[:, None], 4, 1),
                               atol=1e-12)


def test_auto_rejects_bad_joints():
    k0, k1, _ = _limb_scene(30.0)
    with pytest.raises(joints.JointError):
        qcurves.auto(k0, k1, [0.5], [(2, 3)])


# -- degenerate input ------------------------------------------------------------

DEGENERATE = {
    "collinear": (
        np.array([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0]]),
        np.array([[0.0, 1.0], [0.0, 2.0], [0.0, 3.0], [0.0, 4.0]]),
    ),
    "repeated vertices": (
        np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]),
        np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]) + [1.0, 1.0],
    ),
    "turn of 180 degrees": (
        np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]]),
        -np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]]) + [5.0, 0.0],
    ),
    "a single point": (np.zeros((4, 2)), np.ones((4, 2))),
    "collapse to a point": (np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]), np.zeros((3, 2))),
}


@pytest.mark.filterwarnings("error")
@pytest.mark.parametrize("name", sorted(DEGENERATE))
def test_degenerate_input_gives_no_nan(name):
    k0, k1 = DEGENERATE[name]
    t = np.linspace(0, 1, 21)
    q = qcurves.control_points(k0, k1)
    assert np.isfinite(qcurves.angle_at(q, t)).all()
    for predicate in (qcurves.passes_through_zero, qcurves.non_monotonic, qcurves.sweeps_over_180):
        assert predicate(q).dtype == bool
    m = qcurves.classify(k0, k1)
    assert m.kind in ("translation", "rotation", "nonrigid")
    assert np.isfinite(m.rotation_deg)
    assert "nan" not in m.why
    assert np.isfinite(qcurves.auto(k0, k1, t)).all()


def test_degenerate_classifications():
    assert qcurves.classify(*DEGENERATE["repeated vertices"]).kind == "translation"
    half = qcurves.classify(*DEGENERATE["turn of 180 degrees"])
    assert (half.kind, half.rotation_deg) == ("rotation", 180.0)
    assert qcurves.classify(*DEGENERATE["collinear"]).kind == "rotation"
    assert qcurves.classify(*DEGENERATE["a single point"]).kind == "translation"
    assert qcurves.classify(*DEGENERATE["collapse to a point"]).kind == "nonrigid"


def test_mismatched_keys_are_rejected_with_their_shapes():
    with pytest.raises(ValueError, match=r"\(3, 2\) and \(4, 2\)"):
        qcurves.control_points(np.zeros((3, 2)), np.zeros((4, 2)))


def test_auto_goes_linear_when_only_some_vertices_change():
    """A hexagon turned by 40° with one vertex pushed out by 10%: the three vertices away from it
    still see a rigid turn, its neighbourhood does not; any non-rigid vertex makes the shape
    non-rigid (thesis §2.3), so auto draws the linear paths."""
    from tweenrender.core.methods.registry import interpolate as _interpolate

    angles = np.radians(np.arange(6) * 60.0)
    hexagon = np.column_stack([np.cos(angles), np.sin(angles)]) * 2.0
    a = np.radians(40.0)
    k1 = hexagon @ np.array([[np.cos(a), np.sin(a)], [-np.sin(a), np.cos(a)]]) + [5.0, 1.0]
    center = np.array([5.0, 1.0])
    k1[0] = center + 1.1 * (k1[0] - center)  # vertex 0 pushed out from the center
    kinds = qcurves.vertex_kinds(qcurves.control_points(hexagon, k1), 1e-6)
    assert kinds[2:5] == ["rotation"] * 3 and kinds[0] == "nonrigid"  # the premise: some vertices are rigid
    assert qcurves.classify(hexagon, k1).kind == "nonrigid"
    t = np.array([0.25, 0.5, 0.75])
    assert np.array_equal(_interpolate(hexagon, k1, t, "auto"), _interpolate(hexagon, k1, t, "linear"))
    # and with every vertex unmoved but the turn, auto draws the nonlinear paths
    k1_rigid = hexagon @ np.array([[np.cos(a), np.sin(a)], [-np.sin(a), np.cos(a)]]) + [5.0, 1.0]
    assert np.array_equal(_interpolate(hexagon, k1_rigid, t, "auto"), _interpolate(hexagon, k1_rigid, t, "nonlinear"))
