"""Cubic Bézier fits of exact polylines (``tweenrender.vector.curves``), measured independently: each fitted
contour drawn from the cubic's closed form (tests/vector_curves.py) and its Hausdorff distance to the polyline
taken by shapely, at every frame."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from tweenrender.vector.curves import fit_curves, free_points
from tests.vector_curves import distance, drawn


def _worst(samples: np.ndarray, curves: np.ndarray, closed: bool) -> float:
    return max(distance(drawn(c[:, 1], c[:, 0] - c[:, 1], c[:, 2] - c[:, 1], closed), s, closed)
               for s, c in zip(samples, curves))


def _ellipses(frames: int = 12, count: int = 120) -> np.ndarray:
    """A circle of radius 80 stretching into an ellipse 120 × 40 and moving: ``(F, count, 2)``."""
    angle = np.linspace(0.0, 2 * np.pi, count, endpoint=False)
    s = np.linspace(0.0, 1.0, frames)[:, None]
    rx, ry = 80 + 40 * s, 80 - 40 * s
    return np.stack([200 + 50 * s + rx * np.cos(angle), 150 + ry * np.sin(angle)], axis=-1)


@pytest.mark.parametrize("tolerance", [0.05, 0.25, 1.0])
def test_a_stretching_ellipse_fits_within_the_tolerance_with_few_vertices(tolerance: float) -> None:
    samples = _ellipses()
    breaks, curves, worst = fit_curves(samples, True, tolerance)
    assert curves.shape == (12, len(breaks), 3, 2)
    assert np.all(np.diff(breaks) > 0) and breaks[0] == 0
    assert _worst(samples, curves, True) <= tolerance * 1.01  # shapely's discrete measure, sampled curves
    assert worst <= tolerance
    assert len(breaks) <= 120 // 4  # a smooth outline takes far fewer vertices than its polyline


def test_a_tighter_tolerance_takes_more_vertices() -> None:
    counts = [len(fit_curves(_ellipses(), True, t)[0]) for t in (1.0, 0.25, 0.05)]
    assert counts[0] <= counts[1] < counts[2]


def test_a_polygon_keeps_its_corners_with_straight_edges() -> None:
    square = np.array([[[0, 0], [100, 0], [100, 100], [0, 100]]], dtype=float).repeat(3, axis=0)
    square[1] += 10
    breaks, curves, worst = fit_curves(square, True, 0.25)
    assert breaks.tolist() == [0, 1, 2, 3] and worst == 0.0
    assert np.array_equal(curves[:, :, 1], square)
    assert np.array_equal(curves[:, :, 0], square) and np.array_equal(curves[:, :, 2], square)  # zero tangents
    assert free_points(curves)[:, [0, 2]].sum() == 0  # only the vertices are keyframed


def test_an_open_contour_starts_and_ends_on_its_vertices() -> None:
    x = np.linspace(0.0, 300.0, 60)
    wave = np.stack([x, 100 + 40 * np.sin(x / 40)], axis=-1)[None].repeat(4, axis=0)
    wave[2:, :, 1] += np.linspace(0, 20, 60)
    breaks, curves, _ = fit_curves(wave, False, 0.1)
    assert breaks[0] == 0 and breaks[-1] == 59
    assert np.array_equal(curves[:, 0, 0], wave[:, 0]) and np.array_equal(curves[:, -1, 2], wave[:, -1])
    assert _worst(wave, curves, False) <= 0.1 * 1.01


def test_degenerate_contours_fit_without_nan_or_warnings() -> None:
    """A contour grown from a point (every vertex at one place in the first frame), repeated vertices and a
    contour of two points."""
    grown = _ellipses(6, 40)
    grown[0] = grown[0, :1]
    repeated = np.repeat(_ellipses(3, 20), 3, axis=1)
    line = np.array([[[0, 0], [10, 5]], [[3, 3], [3, 3]]], dtype=float)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for samples, closed in ((grown, True), (repeated, True), (line, False), (line, True)):
            breaks, curves, worst = fit_curves(samples, closed, 0.25)
            assert np.all(np.isfinite(curves)) and worst <= 0.25
            assert _worst(samples, curves, closed) <= 0.25 * 1.01


def _segments_numpy(points: np.ndarray, polyline: np.ndarray) -> np.ndarray:
    """The point-to-segments distance written out over ``(F, P, S, 2)`` arrays, the same products in the same
    order as the compiled loop's."""
    a, b = polyline[:, :-1], polyline[:, 1:]
    ab = b - a
    length = np.maximum(np.sum(ab * ab, axis=-1), 1e-300)
    s = np.clip(np.einsum("fpsd,fsd->fps", points[:, :, None] - a[:, None], ab) / length[:, None], 0.0, 1.0)
    nearest = a[:, None] + s[..., None] * ab[:, None]
    return np.sqrt(np.min(np.sum((points[:, :, None] - nearest) ** 2, axis=-1), axis=-1))


@pytest.mark.parametrize("seed", range(4))
def test_the_distance_to_a_polyline_is_shapelys_and_rounds_as_the_arrays_do(seed: int) -> None:
    """Random points against random polylines (some edges of no length), frame by frame: within 1e-9 of shapely's
    distance, and bit for bit the written-out array computation."""
    import shapely

    from tweenrender.vector.curves import distance_to_polyline

    rng = np.random.default_rng(seed)
    frames, count, ends = 3, 40, 2 + seed * 7
    polyline = rng.normal(size=(frames, ends, 2)) * 50
    polyline[:, ends // 2] = polyline[:, ends // 2 - 1]  # a segment of no length
    points = rng.normal(size=(frames, count, 2)) * 60
    found = distance_to_polyline(points, polyline)
    assert found.shape == (frames, count)
    for f in range(frames):
        line = shapely.LineString(polyline[f])
        expected = shapely.distance(shapely.points(points[f]), line)
        assert np.allclose(found[f], expected, rtol=0, atol=1e-9)
    assert np.array_equal(found, _segments_numpy(points, polyline))
    assert np.array_equal(distance_to_polyline(points, polyline[:, :1]),
                          np.linalg.norm(points - polyline[:, :1], axis=-1))  # one point


def test_a_cubics_points_are_de_casteljaus_and_round_as_einsum_does() -> None:
    """``curve_points`` over leading frames: de Casteljau's construction within 1e-12, and bit for bit
    ``np.einsum`` of the Bernstein weights."""
    from tweenrender.vector.curves import _bernstein, curve_points

    rng = np.random.default_rng(5)
    controls = rng.normal(size=(3, 7, 4, 2)) * 100
    u = np.sort(rng.random(9))
    found = curve_points(controls, u)
    assert found.shape == (3, 7, 9, 2)
    lerp = lambda p, q, t: p + (q - p) * t[:, None]  # noqa: E731
    for f in range(3):
        for c in range(7):
            p = [np.repeat(controls[f, c, k][None], len(u), axis=0) for k in range(4)]
            while len(p) > 1:
                p = [lerp(p[k], p[k + 1], u) for k in range(len(p) - 1)]
            assert np.allclose(found[f, c], p[0], rtol=0, atol=1e-12)
    assert np.array_equal(found, np.einsum("nk,...kd->...nd", _bernstein(u), controls))
    assert curve_points(controls[:0], u).shape == (0, 7, 9, 2)
