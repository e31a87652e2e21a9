"""The descent toward target triangles that never turns one over (maths §5.16), against closed forms."""

from __future__ import annotations

import numpy as np

from tweenrender.core.methods.mesh_distortion import least_distortion, symmetric_dirichlet

RING = np.column_stack([np.cos(np.arange(6) * np.pi / 3), np.sin(np.arange(6) * np.pi / 3)])
FAN = np.array([[6, k, (k + 1) % 6] for k in range(6)])  # counter-clockwise round the centre, vertex 6


def _rest(points: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    e = np.stack([points[triangles[:, 1]] - points[triangles[:, 0]], points[triangles[:, 2]] - points[triangles[:, 0]]],
                 axis=-1)
    return np.linalg.inv(e)


def _orientations(points: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    a, b = points[triangles[:, 1]] - points[triangles[:, 0]], points[triangles[:, 2]] - points[triangles[:, 0]]
    return a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]


def test_a_free_centre_returns_to_where_every_triangle_is_its_rest_shape() -> None:
    # rest: the regular hexagon's fan; the ring held where it is, the centre starts off to one side (valid):
    # every triangle is its rest shape exactly when the centre is back at the origin (energy 4 each)
    start = np.vstack([RING, [[0.55, 0.2]]])
    rest = _rest(np.vstack([RING, [[0.0, 0.0]]]), FAN)
    out = least_distortion(start, FAN, rest, np.ones(6), np.array([6]), rounds=40)
    assert np.hypot(*out[6]) < 5e-3  # the descent stops once a round gains under 1e-4 of the energy
    np.testing.assert_array_equal(out[:6], RING)
    assert np.all(_orientations(out, FAN) > 0)


def test_no_triangle_turns_over_on_the_way_to_targets_that_would_turn_some() -> None:
    # the targets ask for a fan squashed flat through its centre: the least-squares fit would put the centre
    # past the ring's edge; the descent keeps every triangle counter-clockwise and lowers the energy
    squashed = np.vstack([RING * [1.0, 0.05], [[0.0, 0.0]]])
    rest = _rest(squashed, FAN)
    start = np.vstack([RING, [[0.0, 0.8]]])  # valid, near the top edge (at 0.866)
    e = np.stack([start[FAN[:, 1]] - start[FAN[:, 0]], start[FAN[:, 2]] - start[FAN[:, 0]]], axis=-1)
    before = symmetric_dirichlet(e @ rest).sum()
    out = least_distortion(start, FAN, rest, np.ones(6), np.array([6]), rounds=40)
    e = np.stack([out[FAN[:, 1]] - out[FAN[:, 0]], out[FAN[:, 2]] - out[FAN[:, 0]]], axis=-1)
    assert np.all(_orientations(out, FAN) > 0)
    assert symmetric_dirichlet(e @ rest).sum() < before
    # by symmetry of the hexagon and its squashed rest, the best centre is the origin
    assert np.hypot(*out[6]) < 0.05


def test_the_energy_is_four_for_a_rotation_and_infinite_for_a_flip() -> None:
    turn = np.array([[[0.0, -1.0], [1.0, 0.0]]])
    flip = np.array([[[1.0, 0.0], [0.0, -1.0]]])
    stretch = np.array([[[2.0, 0.0], [0.0, 1.0]]])
    assert symmetric_dirichlet(turn)[0] == 4.0
    assert np.isinf(symmetric_dirichlet(flip)[0])
    assert np.isclose(symmetric_dirichlet(stretch)[0], 4 + 1 + 0.25 + 1)  # s1² + s2² + s1⁻² + s2⁻²
