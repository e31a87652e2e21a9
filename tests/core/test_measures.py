"""Quality measures against closed forms: a rigid turn drawn linearly, a vertex pair swapped."""

from __future__ import annotations

import numpy as np
import pytest

from tweenrender.core import measures
from tweenrender.core.geometry import rotate

L_SHAPE = np.array([[0, 0], [3, 0], [3, 1], [1, 1], [1, 3], [0, 3]], dtype=np.float64)


@pytest.mark.parametrize("degrees", [30.0, 90.0, 150.0])
def test_linear_rigid_turn_has_closed_form_measures(degrees: float) -> None:
    phi = np.radians(degrees)
    k1 = rotate(L_SHAPE, phi) + [4.0, 1.0]
    report = measures.report(L_SHAPE, k1, "linear", [0.5])
    # the mid-frame is the shape scaled by cos(φ/2) (and turned by φ/2): lengths shrink, angles stay
    assert report.perimeter_ratio[0] == pytest.approx(np.cos(phi / 2), abs=1e-12)
    assert report.area_ratio[0] == pytest.approx(np.cos(phi / 2) ** 2, abs=1e-12)
    assert report.edge_error_max == pytest.approx(1 - np.cos(phi / 2), abs=1e-12)
    assert report.angle_error_max == pytest.approx(0.0, abs=1e-9)
    assert report.self_intersects == ()


def test_rigid_method_is_exact_on_a_rigid_turn() -> None:
    k1 = rotate(L_SHAPE, np.radians(120)) - [2.0, 5.0]
    curves = measures.curves(L_SHAPE, k1, "rigid")
    assert np.allclose(curves.perimeter_ratio, 1.0, atol=1e-12)
    assert np.allclose(curves.area_ratio, 1.0, atol=1e-12)
    assert np.max(curves.edge_error) < 1e-12 and np.max(curves.angle_error) < 1e-9
    assert curves.self_intersects == []


def test_swapping_two_vertices_crosses_after_they_meet() -> None:
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=np.float64)
    swapped = square[[0, 1, 3, 2]]
    report = measures.report(square, swapped, "linear", [0.25])
    # vertices 2 and 3 meet at t = 0.5 (a triangle, simple) and cross after: t = 0.51 .. 1.00
    assert report.self_intersects == tuple(round(0.51 + 0.01 * k, 2) for k in range(50)) or \
        np.allclose(report.self_intersects, np.linspace(0.51, 1.0, 50))
    assert len(report.self_intersection_points) == 50
    # the swapped key is a bow tie of signed area 0: area(t) = 1 - t, exactly its reference
    assert report.area_ratio[0] == pytest.approx(1.0)


def test_area_ratio_is_signed() -> None:
    flipped = L_SHAPE * [-1.0, 1.0]  # same vertex order, mirrored: opposite winding, area -A0
    t = np.array([0.25, 0.5, 0.75])
    frames = np.array([(1 - s) * L_SHAPE + s * flipped for s in t])
    # x shrinks by 1 - 2t: area (1 - 2t)·A0, exactly the signed reference (1 where that is 0)
    assert np.allclose(measures.area_ratio(frames, L_SHAPE, flipped, t), 1.0)



def test_report_is_plain_json() -> None:
    import json

    k1 = rotate(L_SHAPE, 1.0)
    data = measures.report(L_SHAPE, k1, "nonlinear", [0.25, 0.5]).as_dict()
    text = json.dumps(data, allow_nan=False)
    for name in ("area_ratio", "angle_error_max", "self_intersects", "edge_error_max", "ratio"):
        assert name in json.loads(text)
