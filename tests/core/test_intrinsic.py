"""Intrinsic paths: exact on rigid turns; the paper's closing tweak is the least weighted change."""

from __future__ import annotations

import numpy as np
import pytest

from tweenrender.core import measures
from tweenrender.core.geometry import edge_lengths, edges, perimeter, rotate, signed_area
from tweenrender.core.methods.intrinsic import closure_tweak, intrinsic
from tweenrender.core.methods.registry import interpolate
from tweenrender.core.timing.timeline import build_track
from tweenrender.scenefile import load_scene

from ..helpers import SCENES

SHAPE = np.array([[0, 0], [4, 0], [4, 1], [1.5, 1.2], [2.5, 3], [0.2, 3.6]], dtype=np.float64)
T = np.linspace(0.0, 1.0, 21)


@pytest.mark.parametrize("degrees", [0.0, 45.0, -120.0, 179.0, 180.0, -180.0])
@pytest.mark.parametrize("closure", ["paper", "length"])
def test_rigid_turns_are_exact_at_every_t(degrees: float, closure: str) -> None:
    k1 = rotate(SHAPE, np.radians(degrees)) + [3.0, 7.0]
    frames = intrinsic(SHAPE, k1, T, closure)
    assert np.abs(edge_lengths(frames) - edge_lengths(SHAPE)).max() < 1e-9
    assert np.abs(perimeter(frames) - perimeter(SHAPE)).max() < 1e-9
    assert np.abs(signed_area(frames) - signed_area(SHAPE)).max() < 1e-9
    assert np.abs(frames[-1] - k1).max() < 1e-9 and np.abs(frames[0] - SHAPE).max() < 1e-9
    assert closure_tweak(SHAPE, k1, T, closure).max() < 1e-12


def _blend() -> tuple[np.ndarray, np.ndarray]:
    k1 = SHAPE.copy()
    k1[2] = [4.5, 1.6]  # edges 1 and 2 change length, the others keep theirs
    return SHAPE, rotate(k1, 0.4) + [1.0, 1.0]


@pytest.mark.parametrize("closure", ["paper", "length"])
def test_the_walk_keeps_every_interpolated_angle_and_closes(closure: str) -> None:
    k0, k1 = _blend()
    frames = intrinsic(k0, k1, T, closure)
    # the closing tweak changes lengths only: each turning angle is its shorter change, exactly
    assert np.nanmax(measures.angle_error(frames, k0, k1, T)) < 1e-7
    means = frames.mean(axis=1)
    assert np.allclose(means, (1 - T)[:, None] * k0.mean(axis=0) + T[:, None] * k1.mean(axis=0))


def test_the_papers_tweak_is_the_least_weighted_change() -> None:
    # Optimality of min Σ S_i²/w_i subject to Σ (L_i + S_i)·u_i = 0: S_i / w_i = u_i·λ for one λ.
    k0, k1 = _blend()
    t = np.array([0.3, 0.5, 0.8])
    frames = intrinsic(k0, k1, t, "paper")
    l0, l1 = edge_lengths(k0), edge_lengths(k1)
    change = np.abs(l0 - l1)
    weight = np.maximum(change, 1e-4 * change.max()) ** 2  # the paper's L_AB, L_tol = 10⁻⁴ · max
    for frame, s in zip(frames, t):
        vectors = edges(frame)
        lengths = np.linalg.norm(vectors, axis=1)
        units = vectors / lengths[:, None]
        tweak = lengths - ((1 - s) * l0 + s * l1)
        lam, residual, *_ = np.linalg.lstsq(units, tweak / weight, rcond=None)
        assert np.abs(units @ lam - tweak / weight).max() < 1e-6 * np.abs(tweak / weight).max()
        # the unchanged edges keep their lengths (to L_tol): the error lands on edges 1 and 2
        assert np.abs(tweak[[0, 3, 4, 5]]).max() < 1e-6 * np.abs(tweak).max()


def test_the_papers_weights_put_the_walk_out_of_proportion() -> None:
    # Known behaviour of the paper's weights on the walk: all the closing error lands on the few
    # edges that change, so the perimeter swells; the length-weighted closing spreads it.
    scene = load_scene(SCENES / "walk.toml")
    segment = build_track(scene.shapes[0], scene.matching).segments[0]
    at = measures.SWEEP
    paper = measures.perimeter_ratio(intrinsic(segment.k0, segment.k1, at, "paper"), segment.k0, segment.k1, at)
    length = measures.perimeter_ratio(intrinsic(segment.k0, segment.k1, at, "length"), segment.k0, segment.k1,
                                      at)
    assert paper.max() > 1.25
    assert np.abs(length - 1).max() < 0.01


@pytest.mark.parametrize("k0, k1", [
    ([[0, 0], [0, 0], [0, 0]], [[1, 1], [2, 1], [1, 2]]),                            # grows from a point
    ([[0, 0], [0, 0], [0, 0]], [[1, 1], [1, 1], [1, 1]]),                            # points both
    ([[0, 0], [1, 0], [2, 0], [3, 0]], [[0, 1], [1, 2], [2, 3], [3, 4]]),            # collinear
    ([[0, 0], [2, 0], [2, 0], [2, 2], [0, 2]], [[0, 0], [1, 0], [2, 0], [2, 2], [0, 2]]),  # copies
])
@pytest.mark.parametrize("method", ["intrinsic", "intrinsic-length"])
def test_degenerate_keys_give_finite_inbetweens(k0: list, k1: list, method: str) -> None:
    a, b = np.array(k0, dtype=np.float64), np.array(k1, dtype=np.float64)
    frames = interpolate(a, b, T, method)
    assert np.all(np.isfinite(frames))
