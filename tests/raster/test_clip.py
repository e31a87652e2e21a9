"""Cutting outlines to a box far around the canvas changes nothing drawn on the canvas."""

from __future__ import annotations

import numpy as np
import pytest

from tweenrender.raster.clip import clip_to_box


def winding(polygon: np.ndarray, points: np.ndarray) -> np.ndarray:
    """Winding number of closed ``polygon (N, 2)`` around each of ``points (M, 2)``, by brute force."""
    a = polygon[None, :, :] - points[:, None, :]
    b = np.roll(polygon, -1, axis=0)[None, :, :] - points[:, None, :]
    angles = np.arctan2(a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0], (a * b).sum(axis=-1))
    return np.rint(angles.sum(axis=1) / (2 * np.pi)).astype(int)


def distance_to_polyline(line: np.ndarray, points: np.ndarray) -> np.ndarray:
    a, b = line[:-1][None], line[1:][None]
    p = points[:, None, :]
    ab = b - a
    t = np.clip(((p - a) * ab).sum(-1) / np.maximum((ab * ab).sum(-1), 1e-300), 0.0, 1.0)
    return np.linalg.norm(a + t[..., None] * ab - p, axis=-1).min(axis=1)


def test_an_outline_inside_the_box_is_returned_as_it_is() -> None:
    square = np.array([[0.0, 0.0], [100.0, 0.0], [100.0, 100.0], [0.0, 100.0]])
    assert clip_to_box(square) is square


def test_a_huge_square_becomes_the_box() -> None:
    square = np.array([[-1e300, -1e300], [1e300, -1e300], [1e300, 1e300], [-1e300, 1e300]])
    clipped = clip_to_box(square, far=10.0)
    x, y = clipped.T
    assert 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))) == pytest.approx(400.0)
    assert np.abs(clipped).max() == 10.0


def test_an_outline_wholly_outside_is_empty() -> None:
    far_away = np.array([[1e9, 1e9], [2e9, 1e9], [2e9, 2e9]])
    assert len(clip_to_box(far_away, far=1e6)) == 0


@pytest.mark.parametrize("seed", range(40))
def test_winding_numbers_inside_the_box_are_kept(seed: int) -> None:
    """Random self-intersecting outlines with vertices up to 10^300 away: around every sample point
    inside the box, the cut outline winds exactly as often as the original (so fills are equal)."""
    rng = np.random.default_rng(seed)
    count = int(rng.integers(3, 12))
    radius = 10.0 ** rng.uniform(0, 300, size=count)
    polygon = rng.normal(size=(count, 2)) * radius[:, None] + rng.uniform(-50, 50, size=2)
    samples = rng.uniform(-90, 90, size=(400, 2))
    clipped = clip_to_box(polygon, far=100.0)
    assert np.abs(clipped).max(initial=0.0) <= 100.0
    before = winding(polygon / 1e150, samples / 1e150)  # scaled so that no product overflows
    after = winding(clipped, samples) if len(clipped) else np.zeros(len(samples), int)
    assert np.array_equal(before, after)


@pytest.mark.parametrize("seed", range(20))
def test_an_open_line_keeps_every_point_inside_the_box(seed: int) -> None:
    rng = np.random.default_rng(seed)
    line = rng.normal(size=(8, 2)) * 10.0 ** rng.uniform(0, 6, size=(8, 1))
    clipped = clip_to_box(line, closed=False, far=100.0)
    t = rng.uniform(size=(2000, 1))
    segment = rng.integers(0, 7, size=2000)
    on_line = line[segment] + t * (line[segment + 1] - line[segment])
    inside = on_line[np.abs(on_line).max(axis=1) < 99.0]
    if len(inside):
        assert distance_to_polyline(clipped, inside).max() < 1e-6 * (1 + np.abs(line).max())
