"""Pops (DESIGN turn 4, ``stats``' ``pops``): a frame's change is the share of the view whose coverage changed,
checked against shapely's exact areas; a piece appearing in one frame pops, one growing over frames does not."""

from __future__ import annotations

import numpy as np
import pytest
from shapely import unary_union
from shapely.geometry import LineString, Polygon

from tweenrender.core.coverage import Grid
from tweenrender.core.pops import changes, pops
from tweenrender.core.timing.timeline import ShapeAt
from tweenrender.model import Paint

SQUARE = np.array([[0, 0], [4, 0], [4, 4], [0, 4]], dtype=float)
VIEW = (-2.0, -2.0, 14.0, 14.0)
GRID = Grid.over(VIEW, 16.0 / 128)
FILLED = Paint(fill=(0, 0, 0, 255))


def _clip(piece_from: int | None, grow: bool = False, frames: int = 25) -> list[ShapeAt]:
    """A square moving 0.1 right a frame; from frame ``piece_from`` a second square at (8, 8), whole at
    once, or (``grow``) growing about its centre so that its area rises evenly until the last frame."""
    out = []
    for f in range(frames):
        contours = [SQUARE + [0.1 * f, 0.0]]
        if piece_from is not None and f >= piece_from:
            scale = np.sqrt((f - piece_from + 1) / (frames - piece_from)) if grow else 1.0
            contours.append((SQUARE - 2.0) * scale * 0.5 + [10.0, 10.0])
        out.append(ShapeAt(tuple(contours), (True,) * len(contours), FILLED))
    return out


def _exact_changes(clip: list[ShapeAt]) -> np.ndarray:
    """Shapely's share of the view whose coverage changed from each frame to the next."""
    regions = [unary_union([Polygon(c) for c in at.contours]) for at in clip]
    view = GRID.nx * GRID.ny * GRID.cell ** 2
    return np.array([0.0] + [a.symmetric_difference(b).area / view for a, b in zip(regions[1:], regions)])


@pytest.mark.parametrize("piece_from, grow", [(None, False), (12, False), (12, True)])
def test_the_change_of_a_frame_is_the_share_of_the_view_that_changed(piece_from: int | None, grow: bool) -> None:
    clip = _clip(piece_from, grow)
    ours = changes(GRID, clip, ["nonzero"] * len(clip))
    exact = _exact_changes(clip)
    # cell centres sample the motion: each side of the moving square may show one column of cells more or
    # less than it moved (a column is 32 cells of the view's 128 x 128); over the clip it averages out
    column = 32 / GRID.nx / GRID.ny
    assert np.abs(ours - exact).max() <= 2 * column, np.c_[ours, exact]
    assert ours.sum() == pytest.approx(exact.sum(), rel=0.05)


def test_a_piece_appearing_in_one_frame_pops_and_one_growing_does_not() -> None:
    assert pops(changes(GRID, _clip(12), ["nonzero"] * 25)) == [12]
    assert pops(changes(GRID, _clip(12, grow=True), ["nonzero"] * 25)) == []
    assert pops(changes(GRID, _clip(None), ["nonzero"] * 25)) == []


def test_a_stroke_appearing_in_one_frame_pops() -> None:
    line = np.array([[2.0, 9.0], [9.0, 11.0]])
    clip = [ShapeAt((line,), (False,), Paint(fill=None, stroke=(0, 0, 0, 255), stroke_width=0.8),
                    visible=f >= 7) for f in range(20)]
    change = changes(GRID, clip, ["nonzero"] * len(clip))
    view = GRID.nx * GRID.ny * GRID.cell ** 2
    assert change[7] == pytest.approx(LineString(line).buffer(0.4).area / view, rel=0.1)
    assert pops(change) == [7]


def test_a_frame_pops_over_three_times_the_median_change_and_over_the_floor() -> None:
    assert pops(np.array([0.0, 0.01, 0.01, 0.031, 0.01, 0.029])) == [3]
    assert pops(np.array([0.0, 0.0, 0.0, 0.0019, 0.0])) == []
    assert pops(np.array([0.0, 0.0, 0.0, 0.0021, 0.0])) == [3]
