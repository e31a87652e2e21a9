"""Triangulations: they tile the polygon, wind counter-clockwise, and carry over to the other key."""

from __future__ import annotations

import numpy as np
import pytest

from tweenrender.core.geometry import rotate, signed_area
from tweenrender.core.methods.mesh import MeshError, compatible_mesh, ear_clip, edge_matrix, triangulate


def random_star(rng: np.random.Generator, n: int) -> np.ndarray:
    """A simple polygon: vertices at increasing angles, random radii (star-shaped about the origin)."""
    angles = np.sort(rng.uniform(0, 2 * np.pi, n))
    radii = rng.uniform(0.3, 1.0, n)
    return np.column_stack([radii * np.cos(angles), radii * np.sin(angles)])


def areas(points: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    return 0.5 * np.linalg.det(edge_matrix(points, triangles))


def test_ear_clipping_tiles_random_simple_polygons() -> None:
    rng = np.random.default_rng(3)
    for _ in range(50):
        polygon = random_star(rng, int(rng.integers(3, 40)))
        triangles = ear_clip(polygon)
        assert len(triangles) == len(polygon) - 2
        assert np.all(areas(polygon, triangles) > 0)
        assert areas(polygon, triangles).sum() == pytest.approx(float(signed_area(polygon)), rel=1e-12)


@pytest.mark.parametrize("clockwise", [False, True])
def test_refined_triangulation_tiles_the_polygon(clockwise: bool) -> None:
    rng = np.random.default_rng(11)
    for _ in range(10):
        polygon = random_star(rng, int(rng.integers(5, 60)))
        if clockwise:
            polygon = polygon[::-1]
        points, triangles, places = triangulate(polygon)
        n = len(polygon)
        assert np.array_equal(points[:n], polygon)
        assert np.all(areas(points, triangles) > 0)
        assert areas(points, triangles).sum() == pytest.approx(abs(float(signed_area(polygon))), rel=1e-9)
        # vertices added on the boundary lie on the edge they name, at the fraction they name
        on = np.flatnonzero(places[:, 0] >= 0)
        edge, fraction = places[on, 0].astype(int), places[on, 1]
        where = (1 - fraction)[:, None] * polygon[edge] + fraction[:, None] * polygon[(edge + 1) % n]
        assert np.abs(where - points[on]).max() < 1e-12
        # every vertex is used, and interior vertices were added
        assert set(np.unique(triangles)) == set(range(len(points)))


def test_rigid_copy_carries_every_vertex_rigidly() -> None:
    polygon = random_star(np.random.default_rng(5), 25)
    moved = rotate(polygon, 2.0) + [3.0, -1.0]
    mesh = compatible_mesh(polygon, moved)
    assert mesh.folds == 0
    assert np.abs(mesh.p1 - (rotate(mesh.p0, 2.0) + [3.0, -1.0])).max() < 1e-9


@pytest.mark.parametrize("polygon", [
    [[0, 0], [2, 2], [2, 0], [0, 2]],     # crosses itself
    [[0, 0], [1, 0], [2, 0]],             # no area
    [[0, 0], [1, 0], [1, 0], [0, 1]],     # a repeated vertex
])
def test_polygons_that_cannot_be_triangulated_are_refused(polygon: list) -> None:
    with pytest.raises(MeshError):
        triangulate(np.array(polygon, dtype=np.float64))


@pytest.mark.parametrize("exponent", [-200, -400, -520])
def test_a_tiny_polygon_is_triangulated_as_its_unit_copy(exponent: int) -> None:
    # triangulating commutes with scaling, and a power of two scales exactly; at these scales an
    # area squared times a squared length underflows to zero (the refinement's quality test divides by it)
    rng = np.random.default_rng(5)
    polygon = random_star(rng, 9)
    scale = 2.0 ** exponent
    with np.errstate(all="ignore"):  # underflow of a product is no error; its division by zero was
        tiny_points, tiny_triangles, tiny_places = triangulate(polygon * scale)
    points, triangles, places = triangulate(polygon)
    assert np.array_equal(tiny_triangles, triangles)
    assert np.allclose(tiny_points / scale, points, rtol=1e-9, atol=1e-12)
    assert np.array_equal(tiny_points[:len(polygon)], polygon * scale)  # the polygon's own vertices exactly
