"""Where a closed contour's dash pattern starts, by hand on a 4 × 2 rectangle (perimeter 12)."""

from __future__ import annotations

import numpy as np

from tweenrender.core.dashes import start_share, starting_at, without_repeats

RECT = np.array([[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [0.0, 2.0]])


def test_a_contour_starts_where_the_share_of_its_perimeter_lies() -> None:
    assert np.array_equal(starting_at(RECT, 0.5, False), RECT[[2, 3, 0, 1]])  # 6 of 12: the third corner
    cut = starting_at(RECT, 1 / 6, False)  # 2 of 12: halfway along the first edge, a vertex put there
    assert np.allclose(cut, [[2, 0], [4, 0], [4, 2], [0, 2], [0, 0]])
    back = starting_at(RECT, 1 / 6, True)  # the same point, the other way round
    assert np.allclose(back, [[2, 0], [0, 0], [0, 2], [4, 2], [4, 0]])


def test_the_start_slides_the_shorter_way_from_one_keys_first_vertex_to_the_others() -> None:
    first0, first1 = RECT[0], RECT[3]  # shares 0 and 10/12: the shorter way is back by 2/12
    assert start_share(RECT, RECT, first0, first1, RECT, 0.0) == 0.0
    assert np.isclose(start_share(RECT, RECT, first0, first1, RECT, 0.5), 11 / 12)
    assert np.isclose(start_share(RECT, RECT, first0, first1, RECT, 1.0), 10 / 12)


def test_repeated_vertices_are_dropped() -> None:
    copies = np.repeat(RECT, [3, 1, 2, 1], axis=0)
    assert np.array_equal(without_repeats(np.vstack([copies, RECT[:1]]), True), RECT)
