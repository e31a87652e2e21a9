"""As-rigid-as-possible paths: exact on rigid turns, the articulated scenes without joints, degenerate keys."""

from __future__ import annotations

import numpy as np
import pytest

from tweenrender.core.methods import arap as arap_module
from tweenrender.core import measures
from tweenrender.core.methods.arap import arap
from tweenrender.core.crossings import self_crossing, self_crossings
from tweenrender.core.geometry import edge_lengths, perimeter, rotate, signed_area
from tweenrender.core.methods.registry import interpolate
from tweenrender.core.timing.timeline import build_track
from tweenrender.scenefile import load_scene

from ..helpers import SCENES

# non-convex, with a reflex corner and an acute tip
SHAPE = np.array([[0, 0], [4, 0], [4, 1], [1.5, 1.2], [2.5, 3], [0.2, 3.6]], dtype=np.float64)
T = np.linspace(0.0, 1.0, 21)


def expected_rigid(k0: np.ndarray, shift: np.ndarray, phi: float, t: np.ndarray) -> np.ndarray:
    """The rigid motion itself: the vertex mean straight from c0 to c0 + shift, turned by t·φ."""
    c0 = k0.mean(axis=0)
    return np.array([c0 + s * shift + rotate(k0 - c0, s * phi) for s in t])


@pytest.mark.parametrize("degrees", [0.0, 30.0, -75.0, 90.0, 135.0, 179.0, 180.0, -180.0])
@pytest.mark.parametrize("variant", ["outline", "paper"])
def test_rigid_turns_are_exact_at_every_t(degrees: float, variant: str) -> None:
    phi = np.radians(degrees)
    shift = np.array([5.0, -2.0])
    k1 = rotate(SHAPE - SHAPE.mean(axis=0), phi) + SHAPE.mean(axis=0) + shift
    frames = arap(SHAPE, k1, T, variant=variant)
    assert np.all(np.isfinite(frames))
    assert np.abs(edge_lengths(frames) - edge_lengths(SHAPE)).max() < 1e-9
    assert np.abs(perimeter(frames) - perimeter(SHAPE)).max() < 1e-9
    assert np.abs(signed_area(frames) - signed_area(SHAPE)).max() < 1e-9
    if abs(degrees) != 180.0:  # a half turn may go either way; both are rigid
        assert np.abs(frames - expected_rigid(SHAPE, shift, phi, T)).max() < 1e-9


def test_keys_are_hit_and_the_vertex_mean_moves_straight() -> None:
    k1 = SHAPE * [1.3, 0.8] + [2.0, 1.0]
    frames = interpolate(SHAPE, k1, T, "arap")
    assert np.array_equal(frames[0], SHAPE) and np.array_equal(frames[-1], k1)
    means = frames.mean(axis=1)
    straight = (1 - T)[:, None] * SHAPE.mean(axis=0) + T[:, None] * k1.mean(axis=0)
    assert np.abs(means - straight).max() < 1e-12


def _segments(name: str, balance: str = "copies"):
    scene = load_scene(SCENES / f"{name}.toml")
    for shape in scene.shapes:
        yield from build_track(shape, scene.matching, balance=balance).segments


@pytest.mark.parametrize("name", ["walk", "hinge", "roofbox"])
def test_articulated_scenes_keep_edges_and_perimeter_without_joints(name: str) -> None:
    at = np.array([0.25, 0.5, 0.75])
    for segment in _segments(name):
        frames = arap(segment.k0, segment.k1, at)
        assert np.nanmax(measures.edge_error(frames, segment.k0, segment.k1, at)) <= 0.05
        ratio = measures.perimeter_ratio(frames, segment.k0, segment.k1, at)
        assert np.all(np.abs(ratio - 1.0) <= 0.025), ratio


def _winding(points: np.ndarray) -> float:
    return float(np.sign(signed_area(points)))


def test_no_self_intersection_where_the_keys_are_simple_and_wind_alike() -> None:
    tried = 0
    for path in sorted(SCENES.glob("*.toml")):
        for segment in _segments(path.stem):
            k0, k1 = np.asarray(segment.k0), np.asarray(segment.k1)
            if self_crossing(k0) is not None or self_crossing(k1) is not None:
                continue
            if _winding(k0) != _winding(k1):
                # keys of opposite winding: the signed area must pass through 0, so every
                # continuous blend crosses itself somewhere (braces.toml in its drawn order)
                continue
            crossings = self_crossings(arap(k0, k1, measures.SWEEP))
            assert all(c is None for c in crossings), (path.stem, segment.start)
            tried += 1
    assert tried >= 20


@pytest.mark.parametrize("k0, k1", [
    ([[0, 0], [1, 0], [2, 0], [3, 0]], [[0, 1], [1, 2], [2, 3], [3, 4]]),          # collinear keys
    ([[0, 0], [0, 0], [0, 0]], [[1, 1], [2, 1], [1, 2]]),                            # a key at one point
    ([[0, 0], [2, 2], [2, 0], [0, 2]], [[0, 0], [2, 0], [2, 2], [0, 2]]),            # key 0 crosses itself
    ([[0, 0], [2, 2], [2, 0], [0, 2]], [[5, 0], [7, 2], [7, 0], [5, 2]]),            # both cross themselves
    ([[0, 0], [2, 0], [2, 0], [2, 2], [0, 2]], [[0, 0], [1, 0], [2, 0], [2, 2], [0, 2]]),  # copies
    ([[0, 0], [2, 0], [2, 2], [0, 2]], [[0, 2], [2, 2], [2, 0], [0, 0]]),            # mirrored: all folds
])
def test_degenerate_keys_give_finite_inbetweens(k0: list, k1: list) -> None:
    a, b = np.array(k0, dtype=np.float64), np.array(k1, dtype=np.float64)
    frames = interpolate(a, b, T, "arap")
    assert frames.shape == (len(T), len(a), 2) and np.all(np.isfinite(frames))


def test_copies_keep_the_drawn_outline_near_the_first_key() -> None:
    k0 = np.array([[0, 0], [2, 0], [2, 0], [2, 2], [0, 2]], dtype=np.float64)
    k1 = np.array([[0, 0], [1, 0], [2, 0], [2, 2], [0, 2]], dtype=np.float64) + [0.0, 0.0]
    frame = arap(k0, k1, [1e-9])[0]
    assert abs(float(signed_area(frame)) - 4.0) < 1e-6 and abs(float(perimeter(frame)) - 8.0) < 1e-6


def test_a_pair_of_keys_is_factored_once(monkeypatch: pytest.MonkeyPatch) -> None:
    from tests.helpers import count_calls

    built = count_calls(monkeypatch, arap_module, "arap_paths")
    k1 = SHAPE * [1.2, 0.9] + [0.5, 3.0]
    first = arap(SHAPE, k1, T[:10])
    second = arap(SHAPE, k1, T[10:])
    assert len(built) == 1
    assert np.allclose(np.concatenate([first, second]), arap(SHAPE, k1, T))
