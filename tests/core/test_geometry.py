"""Polygon measures against shapes whose answers are known by hand."""

from __future__ import annotations

import numpy as np
import pytest

from tweenrender.core.geometry import (area, hull_area, best_fit_rotation, centroid, edge_lengths, perimeter, rotate,
                                       signed_area)

SQUARE = np.array([[0, 0], [2, 0], [2, 2], [0, 2]], float)  # counter-clockwise
RIGHT_TRIANGLE = np.array([[0, 0], [3, 0], [0, 4]], float)


def test_areas() -> None:
    assert signed_area(SQUARE) == pytest.approx(4.0)
    assert signed_area(SQUARE[::-1]) == pytest.approx(-4.0)  # clockwise
    assert area(SQUARE[::-1]) == pytest.approx(4.0)
    assert signed_area(RIGHT_TRIANGLE) == pytest.approx(6.0)  # half of 3 × 4
    stacked = np.stack([SQUARE, 3 * SQUARE])
    assert signed_area(stacked) == pytest.approx([4.0, 36.0])


def test_lengths_and_center() -> None:
    assert edge_lengths(RIGHT_TRIANGLE) == pytest.approx([3.0, 5.0, 4.0])
    assert perimeter(RIGHT_TRIANGLE) == pytest.approx(12.0)
    assert centroid(RIGHT_TRIANGLE) == pytest.approx([1.0, 4.0 / 3.0])  # the vertex mean


def test_rotation() -> None:
    assert rotate(np.array([1.0, 0.0]), np.pi / 2) == pytest.approx([0.0, 1.0])
    turned = rotate(SQUARE - 1.0, np.radians(30.0)) + [5.0, -2.0]
    assert float(best_fit_rotation(SQUARE, turned)) == pytest.approx(np.radians(30.0))
    assert float(best_fit_rotation(SQUARE, rotate(SQUARE - 1.0, np.pi))) == pytest.approx(np.pi)


@pytest.mark.parametrize("count", [3, 4, 7, 50, 500])
def test_hull_area_is_shapelys_convex_hull(count: int) -> None:
    """Against shapely's convex hull (GEOS), on random clouds, points on a line, and a ring's vertices twice."""
    from shapely.geometry import MultiPoint

    rng = np.random.default_rng(count)
    for _ in range(20):
        points = rng.normal(size=(count, 2)) * rng.uniform(0.01, 100.0, size=2)
        assert hull_area(points) == pytest.approx(MultiPoint(points).convex_hull.area, rel=1e-12)
    line = np.linspace(0.0, 1.0, count)[:, None] * np.array([[3.0, 2.0]])
    assert hull_area(line) == pytest.approx(0.0, abs=1e-12)  # rounding alone
    t = np.linspace(0.0, 2.0 * np.pi, count, endpoint=False)
    ring = np.c_[np.cos(t), np.sin(t)]
    doubled = np.vstack([ring, 0.5 * ring[::-1], ring])
    assert hull_area(doubled) == pytest.approx(MultiPoint(ring).convex_hull.area, rel=1e-12)
