"""The ch. 6 measures against closed forms: perimeter and area ratios, their extremes over the clip."""

from __future__ import annotations

import numpy as np
import pytest

from tweenrender.core.measures import report

SQUARE = np.array([[0, 0], [2, 0], [2, 2], [0, 2]], float)
SQUARE_TURNED = np.array([[7, 1], [7, 3], [5, 3], [5, 1]], float)


def test_area_ratio_of_the_turning_square() -> None:
    """Linear at mid-turn: a square of side 2·cos 45° = √2, area 2 of the keys' 4; nonlinear and rigid keep 4."""
    assert report(SQUARE, SQUARE_TURNED, "linear", [0.5]).area_ratio == pytest.approx((0.5,))
    assert report(SQUARE, SQUARE_TURNED, "nonlinear", [0.5]).area_ratio == pytest.approx((1.0,))
    assert report(SQUARE, SQUARE_TURNED, "rigid", [0.25, 0.5, 0.75]).area_ratio == pytest.approx((1.0,) * 3)
    # at t: the linear square's side is 2·|(1 - t, t)| = 2·√((1-t)² + t²), so its area is 4·((1-t)² + t²)
    t = np.array([0.1, 0.3, 0.8])
    assert report(SQUARE, SQUARE_TURNED, "linear", t).area_ratio == pytest.approx(tuple((1 - t) ** 2 + t ** 2))


def test_area_ratio_of_a_growing_square() -> None:
    """Side 2 to side 4, not turning: at t = 0.5 the side is 3, area 9 over the keys' mean area (4 + 16)/2 = 10,
    and the perimeter 12 over the mean (8 + 16)/2 = 12."""
    big = 2.0 * SQUARE + 5.0
    measured = report(SQUARE, big, "linear", [0.5])
    assert measured.area_ratio == pytest.approx((0.9,))
    assert measured.ratio == pytest.approx((1.0,)) and measured.perimeter == pytest.approx((12.0,))
    assert measured.perimeter_keys == pytest.approx((8.0, 16.0)) and measured.perimeter_mean == pytest.approx(12.0)


def test_ratio_extremes_over_the_clip() -> None:
    """Linear's ratio √((1-t)² + t²) is least at mid-turn, cos 45°, and 1 at the keys."""
    measured = report(SQUARE, SQUARE_TURNED, "linear", [0.5])
    assert measured.ratio_min == pytest.approx(np.sqrt(0.5)) and measured.ratio_max == pytest.approx(1.0)
    assert measured.ratio == pytest.approx((np.sqrt(0.5),))
