"""Stand-ins of contours without a partner (maths §5.17, injective paths): checked with shapely.

A stand-in sits in the key that lacks its contour, inside exactly the partnered contours the contour is
inside in its own key, apart from every contour, and small; contours without a partner nested in one
another keep their nesting.
"""

from __future__ import annotations

import numpy as np
import shapely

from tweenrender.core.methods.stand_ins import stand_ins


def _ring(x0: float, y0: float, x1: float, y1: float, clockwise: bool = False) -> np.ndarray:
    ring = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
    return ring[::-1].copy() if clockwise else ring


def _inside(point: np.ndarray, ring: np.ndarray) -> bool:
    return shapely.Polygon(ring).contains(shapely.Point(point))


def test_a_new_hole_and_a_new_piece_with_its_hole_sit_where_they_nest_apart_from_everything() -> None:
    outline0, outline1 = _ring(0, 0, 10, 10), _ring(20, 0, 34, 10)
    hole0, hole1 = _ring(1, 1, 4, 9, True), _ring(21, 1, 25, 9, True)  # the partnered hole moves with it
    new_hole = _ring(29, 4, 31, 6, True)  # in key 1 only, inside the outline, beside the hole
    piece, piece_hole = _ring(40, 0, 46, 6), _ring(42, 2, 44, 4, True)  # in key 1 only, outside everything
    paired = [(outline0, outline1), (hole0, hole1)]
    found = stand_ins(paired, [True, True], [new_hole, piece, piece_hole], [True, True, True], [True, True, True])
    assert found is not None
    stand_hole, stand_piece, stand_piece_hole = found
    for stand, drawn in zip(found, (new_hole, piece, piece_hole)):  # a small copy, the same way round
        assert 0.0 < shapely.Polygon(stand).area < 0.01 * shapely.Polygon(drawn).area
        scale = float(np.ptp(stand[:, 0]) / np.ptp(drawn[:, 0]))
        assert scale > 0 and np.allclose(stand - stand.mean(axis=0), scale * (drawn - drawn.mean(axis=0)))
    # key 0's faces: the new hole in the outline's material, the piece outside every contour
    assert all(_inside(p, outline0) and not _inside(p, hole0) for p in stand_hole)
    assert all(not _inside(p, outline0) for p in stand_piece)
    assert all(_inside(p, stand_piece) for p in stand_piece_hole)  # nested as drawn
    rings = [shapely.LinearRing(r) for r in (outline0, hole0, stand_hole, stand_piece, stand_piece_hole)]
    for i in range(len(rings)):
        for j in range(i + 1, len(rings)):
            assert not rings[i].intersects(rings[j]), (i, j)


def test_a_contour_with_no_face_to_sit_in_has_no_stand_in() -> None:
    # a new hole inside the outline of key 1, but key 0's outline is all hole: no material to sit in
    outline0, outline1 = _ring(0, 0, 10, 10), _ring(0, 0, 10, 10)
    hole0, hole1 = _ring(1e-9, 1e-9, 10 - 1e-9, 10 - 1e-9, True), _ring(1, 1, 3, 3, True)
    new_hole = _ring(6, 6, 8, 8, True)
    assert stand_ins([(outline0, outline1), (hole0, hole1)], [True, True], [new_hole], [True], [True]) is None
