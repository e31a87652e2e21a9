"""The descent toward target triangles that never turns one over (maths §5.16), against closed forms."""

from __future__ import annotations

import numpy as np
import pytest

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


def test_the_fits_normal_matrix_is_gt_c_g_entry_for_entry() -> None:
    """The normal matrix summed from each triangle's share equals ``Gᵀ diag(c_rq) G`` block by block, built
    from the gradient operator with scipy's sparse products, on a grid mesh with a held border and random
    weights (symmetric 2 × 2 per triangle, some zero)."""
    from scipy.sparse import bmat, diags

    from tweenrender.core.methods.mesh_distortion import NormalPattern, gradient_operator

    rng = np.random.default_rng(5)
    n = 6
    points = np.array([[i, j] for j in range(n) for i in range(n)], float) + rng.uniform(-0.2, 0.2, (n * n, 2))
    tri = np.array([t for j in range(n - 1) for i in range(n - 1) for t in
                    ([j * n + i, j * n + i + 1, (j + 1) * n + i + 1], [j * n + i, (j + 1) * n + i + 1, (j + 1) * n + i])])
    rest = _rest(points, tri)
    border = {v for v in range(n * n) if v % n in (0, n - 1) or v // n in (0, n - 1)}
    free = np.array([v for v in range(n * n) if v not in border])
    a = rng.normal(size=(len(tri), 2, 2))
    weight = a @ a.transpose(0, 2, 1)
    weight[rng.random(len(tri)) < 0.2] = 0.0
    g = gradient_operator(tri, rest, n * n).tocsc()[:, free]
    blocks = [[g.T @ diags(np.repeat(weight[:, r, q], 2)) @ g for q in range(2)] for r in range(2)]
    expected = bmat(blocks).toarray()
    expected += 1e-12 * expected.diagonal().mean() * np.eye(len(expected))
    got = NormalPattern(tri, rest, free, n * n).matrix(weight).toarray()
    assert np.allclose(got, expected, rtol=1e-12, atol=1e-12 * np.abs(expected).max())


def _grid_pattern(seed: int):  # noqa: ANN202 - the pattern and what builds its matrices
    from tweenrender.core.methods.mesh_distortion import NormalPattern

    rng = np.random.default_rng(seed)
    n = 7
    points = np.array([[i, j] for j in range(n) for i in range(n)], float) + rng.uniform(-0.2, 0.2, (n * n, 2))
    tri = np.array([t for j in range(n - 1) for i in range(n - 1) for t in
                    ([j * n + i, j * n + i + 1, (j + 1) * n + i + 1], [j * n + i, (j + 1) * n + i + 1, (j + 1) * n + i])])
    border = {v for v in range(n * n) if v % n in (0, n - 1) or v // n in (0, n - 1)}
    free = np.array([v for v in range(n * n) if v not in border])
    return NormalPattern(tri, _rest(points, tri), free, n * n), rng, len(tri)


@pytest.mark.parametrize("ldlt", [True, False])
def test_each_rounds_solve_is_the_dense_solve_of_its_own_normal_matrix(ldlt: bool, monkeypatch) -> None:
    """Three rounds on one pattern, each with new weights (positive definite 2 × 2 per triangle, some
    triangles left out), so the factorisation is refactored in place: each solution equals numpy's dense
    solve of that round's matrix. Without the ``qdldl`` package the sparse LU gives the same."""
    import builtins

    if not ldlt:
        real_import = builtins.__import__

        def no_qdldl(name, *args, **kwargs):  # noqa: ANN001, ANN202
            if name == "qdldl":
                raise ImportError(name)
            return real_import(name, *args, **kwargs)

        monkeypatch.setattr(builtins, "__import__", no_qdldl)
    pattern, rng, faces = _grid_pattern(11)
    for _ in range(3):
        a = rng.normal(size=(faces, 2, 2))
        weight = a @ a.transpose(0, 2, 1) + 0.1 * np.eye(2)
        weight[rng.random(faces) < 0.2] = 0.0
        rhs = rng.normal(size=pattern.size)
        expected = np.linalg.solve(pattern.matrix(weight).toarray(), rhs)
        got = pattern.solve(weight, rhs)
        assert got is not None
        assert np.allclose(got, expected, rtol=1e-9, atol=1e-9 * np.abs(expected).max())

