"""``auto`` chooses by measured quality (maths §5.16): never a method that tangles where another does not.

Tangles are checked here with shapely (contours as rings and polygons), not with the package's own
crossing tests.
"""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("shapely", reason="shapely (the test extra) checks crossings independently")
from shapely.geometry import LineString, Polygon  # noqa: E402

from tweenrender.core.methods.qcurves import QUALITY_T, auto_choice_contours  # noqa: E402
from tweenrender.core.timing.timeline import build_track, pair_paths  # noqa: E402
from tweenrender.model import Contour, Key, Matching, Shape  # noqa: E402


def _square(x: float, y: float, side: float = 1.0) -> np.ndarray:
    return np.array([[x, y], [x + side, y], [x + side, y + side], [x, y + side]], dtype=float)


def _meet(a: np.ndarray, b: np.ndarray) -> bool:
    return Polygon(a).intersects(Polygon(b))


def test_two_pieces_that_trade_places_keep_straight_paths_rather_than_sweep_round() -> None:
    # one element, two squares trading places: straight paths carry each through the other, and the only way
    # round swings the pair far from both keys; auto keeps the straight paths and says why
    k0 = [_square(0, 0), _square(3, 0.2)]
    k1 = [_square(3, 0.2), _square(0, 0)]
    assert any(_meet((1 - t) * k0[0] + t * k1[0], (1 - t) * k0[1] + t * k1[1]) for t in QUALITY_T)
    choice = auto_choice_contours(k0, k1)
    assert choice.method == "linear" and choice.balance == "spread"
    assert "linear: tangled at" in choice.why and "injective: tangled at 0 of 19 t" in choice.why


def test_a_stroke_that_would_cross_itself_takes_the_way_round() -> None:
    # an open stroke whose straight paths cross it (the keys are simple): injective paths, which never do
    k0 = np.array([[0, 0], [4, 0], [4, 4], [1, 4], [1, 1]], dtype=float)
    k1 = np.array([[6, -3], [2, 4], [1, 7], [7, 6], [2, 6]], dtype=float)
    assert any(not LineString((1 - t) * k0 + t * k1).is_simple for t in QUALITY_T)
    choice = auto_choice_contours([], [], [k0], [k1])
    assert choice.method == "injective", choice.why
    shape = Shape(name="stroke", keys=(Key(time=0.0, contours=(Contour(k0, closed=False),)),
                                       Key(time=1.0, contours=(Contour(k1, closed=False),))))
    frames = pair_paths(build_track(shape, Matching()).segments[0], QUALITY_T, "auto")[0]
    assert all(LineString(f).is_simple for f in frames)


def test_pieces_that_stay_apart_keep_straight_paths() -> None:
    k0 = [_square(0, 0), _square(3, 0)]
    k1 = [_square(0, 2, 1.5), _square(3, 2, 0.5)]
    choice = auto_choice_contours(k0, k1)
    assert choice.method == "linear" and choice.balance == "spread"
    assert "tangled" not in choice.why  # the first reason stands where it passes
