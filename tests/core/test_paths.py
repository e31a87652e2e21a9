"""Vertex paths against closed-form facts and the thesis's ch. 6 table."""

from __future__ import annotations

import numpy as np
import pytest

from tweenrender.core.methods import paths
from tweenrender.core.methods.registry import interpolate
from tweenrender.core.geometry import best_fit_rotation, edge_lengths, perimeter

SQUARE = np.array([[0, 0], [2, 0], [2, 2], [0, 2]], float)
SQUARE_TURNED = np.array([[7, 1], [7, 3], [5, 3], [5, 1]], float)
RECTANGLE = np.array([[0, 0], [4, 0], [4, 3], [0, 3]], float)
RECTANGLE_TURNED = np.array([[10.5, 0.5], [10.5, 4.5], [7.5, 4.5], [7.5, 0.5]], float)


def turned(points: np.ndarray, degrees: float, shift=(0.0, 0.0)) -> np.ndarray:
    a = np.radians(degrees)
    rotation = np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])
    center = points.mean(axis=0)
    return (points - center) @ rotation.T + center + np.asarray(shift)


def ratio(frames: np.ndarray, k0: np.ndarray, k1: np.ndarray) -> np.ndarray:
    return perimeter(frames) / (0.5 * (perimeter(k0) + perimeter(k1)))


@pytest.mark.parametrize("k0, k1", [(SQUARE, SQUARE_TURNED), (RECTANGLE, RECTANGLE_TURNED)],
                         ids=["square", "rectangle"])
def test_thesis_table(k0: np.ndarray, k1: np.ndarray) -> None:
    # Thesis ch. 6: 0.70711 linear, 1.00000 nonlinear, at t = 0.5.
    assert round(float(ratio(paths.linear(k0, k1, 0.5), k0, k1)[0]), 5) == 0.70711
    assert round(float(ratio(paths.nonlinear(k0, k1, 0.5), k0, k1)[0]), 5) == 1.00000


def test_thesis_perimeters() -> None:
    assert perimeter(SQUARE) == pytest.approx(8.0)
    assert perimeter(RECTANGLE) == pytest.approx(14.0)
    assert float(perimeter(paths.linear(RECTANGLE, RECTANGLE_TURNED, 0.5)[0])) == pytest.approx(9.89950, abs=1e-5)


@pytest.mark.parametrize("degrees", [10, 45, 90, 135, 170, -60, -150])
def test_linear_shrinks_by_cos_half_angle(degrees: float) -> None:
    rng = np.random.default_rng(int(degrees) + 360)
    k0 = rng.normal(size=(7, 2)) * 3
    k1 = turned(k0, degrees, shift=(4.0, -1.0))
    mid = paths.linear(k0, k1, 0.5)[0]
    expected = np.cos(np.radians(degrees) / 2) * edge_lengths(k0)
    assert np.allclose(edge_lengths(mid), expected, rtol=1e-9)


@pytest.mark.parametrize("method", [paths.linear, paths.nonlinear, paths.rigid])
def test_paths_reach_the_keys(method) -> None:
    rng = np.random.default_rng(7)
    k0, k1 = rng.normal(size=(9, 2)), rng.normal(size=(9, 2)) + 5
    frames = method(k0, k1, np.array([0.0, 1.0]))
    assert np.allclose(frames[0], k0, atol=1e-12)
    assert np.allclose(frames[1], k1, atol=1e-12)


@pytest.mark.parametrize("method", ["linear", "nonlinear", "rigid", "jointed", "auto"])
def test_interpolate_hits_keys_exactly(method: str) -> None:
    rng = np.random.default_rng(8)
    k0, k1 = rng.normal(size=(9, 2)), rng.normal(size=(9, 2)) + 5
    frames = interpolate(k0, k1, np.array([0.0, 0.5, 1.0]), method, ())
    assert np.array_equal(frames[0], k0) and np.array_equal(frames[2], k1)


@pytest.mark.parametrize("degrees", [30, 90, 179, 180, -120])
def test_rigid_keeps_rigid_motion_at_every_t(degrees: float) -> None:
    rng = np.random.default_rng(3)
    k0 = rng.normal(size=(6, 2))
    k1 = turned(k0, degrees, shift=(2.0, 3.0))
    t = np.linspace(0, 1, 21)
    frames = paths.rigid(k0, k1, t)
    # every pairwise distance is kept
    d0 = np.linalg.norm(k0[:, None] - k0[None], axis=-1)
    d = np.linalg.norm(frames[:, :, None] - frames[:, None], axis=-1)
    assert np.allclose(d, d0, atol=1e-9)
    # the center travels in a straight line and the angle grows linearly
    assert np.allclose(frames.mean(axis=1), (1 - t)[:, None] * k0.mean(0) + t[:, None] * k1.mean(0))
    angles = np.array([best_fit_rotation(k0, f) for f in frames])
    assert np.allclose(angles, np.radians(degrees) * t, atol=1e-9)


@pytest.mark.parametrize("degrees", [90, 45, -90])
def test_nonlinear_keeps_rigid_motion_at_half(degrees: float) -> None:
    rng = np.random.default_rng(11)
    k0 = rng.normal(size=(8, 2))
    k1 = turned(k0, degrees, shift=(5.0, 1.0))
    mid = paths.nonlinear(k0, k1, 0.5)[0]
    expected = turned(k0, degrees / 2, shift=(2.5, 0.5))
    assert np.allclose(mid, expected, atol=1e-9)


def test_nonlinear_dips_only_slightly_before_half() -> None:
    # maths §4: for a 90° turn the quadratic path is only nearly circular; the
    # ratio dips to about 0.989 in each half and is symmetric about t = 0.5.
    t = np.linspace(0, 1, 101)
    r = ratio(paths.nonlinear(SQUARE, SQUARE_TURNED, t), SQUARE, SQUARE_TURNED)
    assert 0.985 < r.min() < 0.995
    assert np.allclose(r, r[::-1], atol=1e-12)
    assert 0.05 < t[np.argmin(r[:50])] < 0.35


def test_half_turn_is_finite_and_keeps_size() -> None:
    k1 = turned(SQUARE, 180.0, shift=(3.0, 0.0))
    frames = paths.nonlinear(SQUARE, k1, np.linspace(0, 1, 11))
    assert np.all(np.isfinite(frames))
    assert ratio(frames[5:6], SQUARE, k1)[0] == pytest.approx(1.0)
    # exactly 180° turns counter-clockwise: at t = 0.5 vertex 0 is a quarter turn on.
    mid = frames[5]
    spoke0 = SQUARE[0] - SQUARE.mean(0)
    spoke = mid[0] - mid.mean(0)
    turn = np.arctan2(spoke0[0] * spoke[1] - spoke0[1] * spoke[0], spoke0 @ spoke)
    assert np.degrees(turn) == pytest.approx(90.0)


def test_vertex_at_center_of_mass_follows_the_center() -> None:
    k0 = np.array([[0, 0], [2, 0], [1, 1], [2, 2], [0, 2]], float)  # vertex 2 at the vertex mean
    assert np.allclose(k0.mean(0), k0[2])
    k1 = turned(k0, 90.0, shift=(4.0, 0.0))
    frames = paths.nonlinear(k0, k1, np.linspace(0, 1, 9))
    assert np.all(np.isfinite(frames))
    assert np.allclose(frames[:, 2], frames.mean(axis=1), atol=1e-9)


@pytest.mark.parametrize("method", [paths.linear, paths.nonlinear, paths.rigid])
def test_degenerate_input_is_finite(method) -> None:
    collinear = np.array([[0, 0], [1, 0], [2, 0], [3, 0]], float)
    repeated = np.array([[1, 1], [1, 1], [1, 1], [1, 1]], float)
    for k0, k1 in [(collinear, collinear[::-1] + 1), (repeated, repeated), (repeated, collinear),
                   (collinear, turned(collinear, 180.0))]:
        assert np.all(np.isfinite(method(k0, k1, np.linspace(0, 1, 7))))


def test_rigid_between_keys_that_are_not_congruent() -> None:
    """Maths §5.2 at intermediate t, in complex numbers: a 2×2 square to a 4×1 rectangle turned by 70°
    and moved. φ = arg Σ conj(u0)·u1 (the least-squares turn), and
    V(t) = lerp(C0, C1, t) + e^{itφ}·((1 − t)·u0 + t·e^{−iφ}·u1); the vertex mean moves straight."""
    k0 = SQUARE
    rectangle = np.array([[0, 0], [4, 0], [4, 1], [0, 1]], float)
    k1 = turned(rectangle, 70.0, shift=(6.0, -2.0))
    z0, z1 = k0 @ [1, 1j], k1 @ [1, 1j]
    c0, c1 = z0.mean(), z1.mean()
    u0, u1 = z0 - c0, z1 - c1
    phi = np.angle(np.sum(np.conj(u0) * u1))
    t = np.array([0.2, 0.5, 0.7])
    expected = ((1 - t) * c0 + t * c1)[:, None] + np.exp(1j * t * phi)[:, None] * (
        (1 - t)[:, None] * u0 + t[:, None] * np.exp(-1j * phi) * u1)
    got = interpolate(k0, k1, t, "rigid")
    assert np.allclose(got[..., 0] + 1j * got[..., 1], expected, atol=1e-12)
    assert np.allclose(got.mean(axis=1), ((1 - t)[:, None] * k0.mean(axis=0) + t[:, None] * k1.mean(axis=0)))
    # the change of shape is spread evenly: the spokes' lengths move straight from one key's to the other's
    assert not np.allclose(got, interpolate(k0, k1, t, "linear"))
