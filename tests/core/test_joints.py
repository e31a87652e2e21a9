"""Joints, local bodies and jointed nonlinear paths (maths §5.1)."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from tweenrender.core.methods import joints, paths


def turn(points: np.ndarray, phi: float) -> np.ndarray:
    c, s = np.cos(phi), np.sin(phi)
    return points @ np.array([[c, s], [-s, c]])


def octagon() -> np.ndarray:
    angles = np.arange(8) * np.pi / 4
    return np.stack([np.cos(angles), np.sin(angles)], axis=1) * [3.0, 2.0]


# -- validation ----------------------------------------------------------------


@pytest.mark.parametrize(
    "bad, words",
    [
        ((0, 8), "out of range"),
        ((-1, 3), "out of range"),
        ((5, 5), "to itself"),
        ((1, 2), "neighbouring"),
        ((7, 0), "neighbouring"),  # neighbours across the wrap-around
        ((2, 6), "crosses joint 0"),
        ((4, 0), "repeats joint 0"),
        ((0, 4), "repeats joint 0"),
        ((1,), "pair of vertex indices"),
        ((1.5, 4), "pair of vertex indices"),
    ],
)
def test_bad_joint_raises_with_its_index(bad, words):
    good = [(0, 4), (4, 6)]  # share vertex 4: allowed
    joints.validate_joints(8, good)
    for position in (1, 2):
        listed = list(good)
        listed.insert(position, bad)
        with pytest.raises(joints.JointError, match=words) as caught:
            joints.validate_joints(8, listed)
        assert caught.value.index == position
        assert isinstance(caught.value, ValueError)


def test_error_message_carries_the_numbers():
    with pytest.raises(joints.JointError) as caught:
        joints.validate_joints(6, [(1, 2)])
    assert str(caught.value) == (
        "joint 0 [1, 2] joins neighbouring vertices: each side of a joint needs at least 3 vertices"
    )
    with pytest.raises(joints.JointError, match=r"polygon of 6 vertices has indices 0\.\.5"):
        joints.validate_joints(6, [(0, 3), (2, 6)])


def test_no_joint_fits_a_triangle():
    for a, b in itertools.permutations(range(3), 2):
        with pytest.raises(joints.JointError):
            joints.validate_joints(3, [(a, b)])


# -- bodies --------------------------------------------------------------------


def test_one_chord_splits_into_two_runs():
    got = joints.bodies(8, [(6, 2)])
    assert [b.tolist() for b in got] == [[0, 1, 2, 6, 7], [2, 3, 4, 5, 6]]
    assert [b.tolist() for b in joints.bodies(5, [])] == [[0, 1, 2, 3, 4]]


@pytest.mark.parametrize(
    "n, chords",
    [
        (8, [(0, 4)]),
        (8, [(0, 2), (0, 4), (0, 6)]),  # a fan sharing vertex 0
        (10, [(1, 4), (4, 8), (8, 1), (5, 7)]),
        (12, [(0, 6), (1, 5), (7, 11), (2, 4)]),
    ],
)
def test_bodies_cover_every_vertex_in_a_fixed_order(n, chords):
    got = joints.bodies(n, chords)
    assert len(got) == len(chords) + 1
    ends = {v for chord in chords for v in chord}
    counts = np.bincount(np.concatenate(got), minlength=n)
    assert (counts >= 1).all()
    assert all(counts[v] == 1 for v in range(n) if v not in ends)
    assert all(counts[v] >= 2 for v in ends)
    assert counts.sum() == n + 2 * len(chords)  # each chord adds its two ends once more
    assert all(len(b) >= 3 for b in got)
    for chord in chords:  # every chord is an edge of exactly two bodies
        assert sum(set(chord) <= set(b.tolist()) for b in got) == 2
    for order in itertools.permutations(chords):
        again = joints.bodies(n, [tuple(reversed(c)) for c in order])
        assert [b.tolist() for b in again] == [b.tolist() for b in got]


# -- jointed paths ---------------------------------------------------------------


def test_without_joints_jointed_is_nonlinear():
    k0 = octagon()
    k1 = turn(k0, 1.1) + [4.0, 1.0]
    t = np.linspace(0, 1, 9)
    np.testing.assert_array_equal(joints.jointed_paths(k0, k1, t, []), paths.nonlinear(k0, k1, t))


def test_keys_are_hit_exactly_even_at_vertices_of_three_bodies():
    rng = np.random.default_rng(5)
    k0 = octagon()
    k1 = rng.normal(size=(8, 2)) * 0.3 + 0.7
    # Vertices 0 and 4 each belong to three bodies; 0.1 + 0.1 + 0.1 is not 3 × 0.1 in
    # floating point, so a plain sum-then-divide mean would miss these keys.
    k0[0], k0[4], k1[0], k1[4] = [3.1, 0.1], [-3.1, 0.1], [0.1, 0.7], [0.7, 0.1]
    chords = [(0, 2), (0, 4), (4, 6)]
    assert [len(b) for b in joints.bodies(8, chords)] == [3, 4, 4, 3]
    got = joints.jointed_paths(k0, k1, [0.0, 1.0], chords)
    assert np.array_equal(got[0], k0)
    assert np.array_equal(got[1], k1)


def test_joint_vertex_is_the_mean_of_its_bodies_paths():
    k0 = octagon()
    k1 = octagon()
    k1[[5, 6, 7]] = turn(octagon()[[5, 6, 7]] - k0[4], -0.8) + k0[4]
    chords = [(0, 4), (4, 6)]
    t = np.linspace(0, 1, 11)
    got = joints.jointed_paths(k0, k1, t, chords, rule="mean")
    assert np.isfinite(got).all()
    parts = {0: [0, 1, 2, 3, 4], 1: [0, 4, 6, 7], 2: [4, 5, 6]}  # worked out by hand
    own = {b: paths.nonlinear(k0[v], k1[v], t) for b, v in parts.items()}
    for vertex in range(8):
        where = [own[b][:, parts[b].index(vertex)] for b in parts if vertex in parts[b]]
        np.testing.assert_allclose(got[:, vertex], np.mean(where, axis=0), atol=1e-12)


def test_body_paths_one_per_body_or_one_for_all():
    k0 = octagon()
    k1 = turn(k0, 0.5)
    t = np.linspace(0, 1, 5)
    linear_all = joints.jointed_paths(k0, k1, t, [(0, 4)], body_paths=paths.linear)
    np.testing.assert_allclose(linear_all, paths.linear(k0, k1, t), atol=1e-12)
    mixed = joints.jointed_paths(k0, k1, t, [(0, 4)], body_paths=[paths.linear, paths.nonlinear], rule="mean")
    np.testing.assert_allclose(mixed[:, 1:4], paths.linear(k0, k1, t)[:, 1:4], atol=1e-12)
    second = [0, 4, 5, 6, 7]
    np.testing.assert_allclose(
        mixed[:, 5:], paths.nonlinear(k0[second], k1[second], t)[:, 2:], atol=1e-12
    )
    with pytest.raises(ValueError, match="2 bodies need 2 path functions, found 1"):
        joints.jointed_paths(k0, k1, t, [(0, 4)], body_paths=[paths.linear])


def _worst_edge_error(frames: np.ndarray, k0: np.ndarray, k1: np.ndarray, t: np.ndarray) -> float:
    """Max over t and edges of |L(t) / lerp(L0, L1, t) - 1| for the closed polygon ``frames``."""

    def lengths(p: np.ndarray) -> np.ndarray:
        return np.linalg.norm(np.roll(p, -1, axis=-2) - p, axis=-1)

    reference = (1 - t)[:, None] * lengths(k0) + t[:, None] * lengths(k1)
    return float(np.abs(lengths(frames) / reference - 1).max())


@pytest.mark.parametrize("deg", [45.0, 90.0, -90.0, 135.0])
def test_a_swinging_limb_keeps_its_length_best_when_jointed(deg):
    # A square torso; a 6 x 0.5 limb hinged at vertex 2 swings about that vertex.
    k0 = np.array([[-2, -2], [2, -2], [2, 1.5], [8, 1.5], [8, 2], [2, 2], [-2, 2]], dtype=float)
    limb = [2, 3, 4, 5]
    k1 = k0.copy()
    k1[limb] = k0[2] + turn(k0[limb] - k0[2], np.radians(deg))
    t = np.linspace(0, 1, 101)

    def error(frames: np.ndarray) -> float:
        return _worst_edge_error(frames[:, limb], k0[limb], k1[limb], t)

    hinged = error(joints.jointed_paths(k0, k1, t, [(2, 5)]))
    whole = error(paths.nonlinear(k0, k1, t))
    straight = error(paths.linear(k0, k1, t))
    assert hinged < whole
    assert hinged < straight


# -- degenerate input ------------------------------------------------------------

_LINE = np.stack([np.arange(6.0), np.zeros(6)], axis=1)
_REPEATS = np.array([[0, 0], [1, 0], [1, 0], [1, 1], [1, 1], [0, 1]], dtype=float)


@pytest.mark.filterwarnings("error")
@pytest.mark.parametrize(
    "k0, k1",
    [
        (_LINE, _LINE[:, ::-1]),  # collinear, mirrored onto the y-axis
        (_REPEATS, 2 * _REPEATS),
        (octagon()[:6], -octagon()[:6]),  # a turn of 180 degrees for every body
        (np.zeros((6, 2)), np.zeros((6, 2))),
    ],
    ids=["collinear", "repeated vertices", "turn of 180", "all at one point"],
)
def test_degenerate_input_gives_finite_paths(k0, k1):
    t = np.linspace(0, 1, 21)
    got = joints.jointed_paths(k0, k1, t, [(0, 3), (3, 5)])
    assert np.isfinite(got).all()
    assert np.array_equal(got[0], k0) and np.array_equal(got[-1], k1)


# -- the chain rule (the default) -------------------------------------------------


def _spoke_scale(phi: float, t: np.ndarray) -> np.ndarray:
    """|B(t)| of the thesis's Bézier for a unit spoke turning by phi about a fixed center."""
    p0, p2 = np.array([1.0, 0.0]), np.array([np.cos(phi), np.sin(phi)])
    p1 = 2 * np.array([np.cos(phi / 2), np.sin(phi / 2)]) - 0.5 * (p0 + p2)
    s = (1 - t)[:, None]
    return np.linalg.norm(s * s * p0 + 2 * s * t[:, None] * p1 + (t * t)[:, None] * p2, axis=1)


@pytest.mark.parametrize("deg", [30.0, 90.0, -120.0])
def test_pivoted_turns_about_the_origin_through_the_arc_midpoint(deg):
    u0 = np.array([[2.0, 0.0], [0.0, 1.0], [-1.0, -1.0]])
    phi = np.radians(deg)
    t = np.linspace(0, 1, 11)
    got = joints.pivoted(u0, turn(u0, phi), t)
    np.testing.assert_allclose(got[5], turn(u0, phi / 2), atol=1e-12)  # t = 0.5 on the arc
    radius = np.linalg.norm(got, axis=-1) / np.linalg.norm(u0, axis=-1)
    np.testing.assert_allclose(radius, np.repeat(_spoke_scale(phi, t)[:, None], 3, 1), atol=1e-12)


def test_pivoted_half_turn_goes_counter_clockwise():
    u0 = np.array([[1.0, 0.0], [0.0, 2.0]])
    got = joints.pivoted(u0, -u0, [0.5])
    np.testing.assert_allclose(got[0], [[0.0, 1.0], [-2.0, 0.0]], atol=1e-12)


def test_misfit_is_zero_for_rigid_motion_and_grows_with_a_stretch():
    k0 = octagon()
    assert joints.misfit(k0, turn(k0, 2.0) + [5.0, -3.0]) < 1e-12
    stretched = k0 * [1.2, 1.0]
    assert joints.misfit(k0, stretched) > 0.05
    # Unitless: the same change at another scale gives the same number.
    assert joints.misfit(10 * k0, 10 * stretched) == pytest.approx(joints.misfit(k0, stretched))


def test_root_is_the_body_with_most_vertices_then_the_one_that_turns_least():
    k0 = octagon()
    k1 = k0.copy()
    k1[[5, 6, 7]] = turn(k0[[5, 6, 7]] - k0[4], 0.8) + k0[4]
    parts = joints.bodies(8, [(0, 4), (4, 6)])  # [0..4] (5 vertices), [0, 4, 6, 7], [4, 5, 6]
    assert joints.root_body(k0, k1, parts) == 0
    even = joints.bodies(8, [(0, 4)])  # two bodies of 5; the second turns
    assert joints.root_body(k0, k1, even) == 0
    assert joints.root_body(k1, k0, even) == 0


@pytest.mark.parametrize("deg", [45.0, 90.0, -90.0, 135.0])
def test_a_rigid_limb_keeps_its_shape_as_a_spoke_of_the_bezier(deg):
    # The limb [2, 3, 4, 5] is rigid in the keys: with the chain rule it turns about its
    # joint, so its outline, the joint's width included, scales like one spoke.
    k0 = np.array([[-2, -2], [2, -2], [2, 1.5], [8, 1.5], [8, 2], [2, 2], [-2, 2]], dtype=float)
    limb = [2, 3, 4, 5]
    k1 = k0.copy()
    k1[limb] = k0[2] + turn(k0[limb] - k0[2], np.radians(deg))
    t = np.linspace(0, 1, 101)
    got = joints.jointed_paths(k0, k1, t, [(2, 5)])

    def lengths(p: np.ndarray) -> np.ndarray:
        return np.linalg.norm(np.roll(p, -1, axis=-2) - p, axis=-1)

    ratio = lengths(got[:, limb]) / lengths(k0[limb])
    np.testing.assert_allclose(ratio, np.repeat(_spoke_scale(np.radians(deg), t)[:, None], 4, 1),
                               atol=1e-12)
    # The old rule (every body about its own center, joints on the mean) bends it more.
    old = joints.jointed_paths(k0, k1, t, [(2, 5)], rule="mean")
    assert np.abs(lengths(old[:, limb]) / lengths(k0[limb]) - 1).max() > 2 * np.abs(ratio - 1).max()


def test_a_chain_of_three_bodies_bends_less_than_under_any_other_rule():
    # A thigh, a shin and a foot (bars joined end to end): shin and foot swing about the
    # knee, the foot swings back about the ankle, and the whole leg turns and moves.
    k0 = np.array([[0, 0], [4, 0], [8, 0], [11, 0], [11, 0.6], [8, 0.6], [4, 0.6], [0, 0.6]], dtype=float)
    chords = [(1, 6), (2, 5)]
    k1 = k0.copy()
    k1[1:7] = k0[1] + turn(k0[1:7] - k0[1], 0.7)
    k1[2:6] = k1[2] + turn(k1[2:6] - k1[2], -1.1)
    k1 = turn(k1, 0.3) + [2.0, 1.0]
    t = np.linspace(0, 1, 101)
    got = joints.jointed_paths(k0, k1, t, chords)
    assert np.array_equal(got[0], k0) and np.array_equal(got[-1], k1)
    thigh, shin, foot = ([0, 1, 6, 7], [1, 2, 5, 6], [2, 3, 4, 5])

    def outline_errors(frames: np.ndarray) -> list[float]:
        return [_worst_edge_error(frames[:, b], k0[b], k1[b], t) for b in (thigh, shin, foot)]

    chain = outline_errors(got)
    # The foot is rigid in the keys and turns least (-0.1 rad): it leads, and keeps its
    # shape as well as the Bézier's spoke does for that turn.
    assert chain[2] <= 1 - _spoke_scale(-0.1, t).min() + 1e-12
    for other in (joints.jointed_paths(k0, k1, t, chords, rule="mean"), paths.linear(k0, k1, t),
                  paths.nonlinear(k0, k1, t)):
        assert max(chain) < max(outline_errors(other)) / 5


def test_unknown_rule_is_refused():
    with pytest.raises(ValueError, match="unknown joint rule 'crack'"):
        joints.jointed_paths(octagon(), octagon(), [0.5], [(0, 4)], rule="crack")
