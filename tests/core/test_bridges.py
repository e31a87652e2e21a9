"""Contours without a partner joined by a slit (maths §5.17): the joined contour draws what its parts
drew. Winding numbers are counted here by summing the turning angle of each contour round the point
(independent of the package's ray casting); slits are checked against the blocking contour with shapely."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from tweenrender.core.timing.bridges import join_alone
from tweenrender.raster.slits import unslit


def square(x: float, y: float, side: float, clockwise: bool = False) -> np.ndarray:
    corners = np.array([[x, y], [x + side, y], [x + side, y + side], [x, y + side]], dtype=float)
    return corners[::-1].copy() if clockwise else corners


def winding(point: np.ndarray, contour: np.ndarray) -> int:
    """How many times ``contour`` turns round ``point``: the sum of the angles its edges subtend."""
    a = contour - point
    b = np.roll(a, -1, axis=0)
    angles = np.arctan2(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0], (a * b).sum(axis=1))
    return int(round(angles.sum() / (2 * np.pi)))


def shoelace(points: np.ndarray) -> float:
    x, y = points[:, 0], points[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


GRID = np.stack(np.meshgrid(np.linspace(-3.03, 23.07, 53), np.linspace(-3.01, 13.09, 37)), axis=-1).reshape(-1, 2)


def windings(contours: list[np.ndarray]) -> np.ndarray:
    return np.array([sum(winding(p, c) for c in contours) for p in GRID])


@pytest.mark.parametrize("evenodd", [False, True])
def test_a_joined_piece_and_hole_cover_what_they_covered(evenodd: bool) -> None:
    outer = square(0, 0, 10)
    hole = square(3, 3, 4, clockwise=True)
    piece = square(13, 2, 5, clockwise=True)  # winds the other way: walked backwards, clear of the rest
    kept = square(13, 9, 2)  # has a partner: left alone
    contours = [outer, hole, piece, kept]
    out, joined = join_alone(contours, [True] * 4, [True, False, False, True], [1, 2], evenodd)
    assert joined == [False, True, True, False]
    left = [c for c, gone in zip(out, joined) if not gone]
    before, after = windings(contours), windings(left)
    if evenodd:
        np.testing.assert_array_equal(before % 2, after % 2)
    else:
        np.testing.assert_array_equal(before != 0, after != 0)
    # the hole is in the outer's contour; the piece joins the nearest outline that has a partner (2 away
    # from the small square, 3 from the outer), walked the small square's way round
    assert [shoelace(c) for c in left] == [pytest.approx(100 - 16), pytest.approx(4 + 25)]


def test_the_slit_goes_round_a_contour_in_its_way() -> None:
    outer, piece = square(0, 0, 10), square(13, 4, 2)
    low_wall = np.array([[11, -2], [12, -2], [12, 7], [11, 7]], dtype=float)  # blocks the joins from below
    out, joined = join_alone([outer, low_wall, piece], [True] * 3, [True, False, False], [2], False)  # the wall: no target
    assert joined == [False, False, True]
    assert not shapely.LineString(np.vstack([out[0], out[0][:1]])).intersects(shapely.Polygon(low_wall))
    tall_wall = np.array([[11, -2], [12, -2], [12, 12], [11, 12]], dtype=float)  # blocks every join
    out, joined = join_alone([outer, tall_wall, piece], [True] * 3, [True, False, False], [2], False)  # the wall: no target
    assert joined == [False, False, False]
    np.testing.assert_array_equal(out[0], outer)


def test_a_piece_that_overlaps_another_is_not_walked_backwards_under_nonzero() -> None:
    outer = square(0, 0, 10)
    piece = square(12, 0, 6, clockwise=True)
    other = square(15, 3, 6)  # overlaps the piece: reversing it would change the overlap's winding
    out, joined = join_alone([outer, piece, other], [True] * 3, [True, False, True], [1], False)
    assert not joined[1]
    np.testing.assert_array_equal(out[1], piece)


def test_a_slit_is_taken_out_before_drawing() -> None:
    outer, hole = square(0, 0, 10), square(3, 3, 4, clockwise=True)
    keyhole = np.concatenate([outer[:1], hole[0:], hole[:1], outer[0:]])  # outer[0] → hole → back → outer
    loops = unslit(keyhole)
    assert len(loops) == 2
    assert sorted(round(abs(shapely.Polygon(p).area)) for p in loops) == [16, 100]
    np.testing.assert_array_equal(windings(loops), windings([outer, hole]))
    plain = square(0, 0, 3)
    assert unslit(plain)[0] is plain


def test_a_joined_contour_is_not_triangulated_to_learn_it_has_no_injective_paths() -> None:
    """A slit walks its ends twice, so a joined contour's key has coincident vertices and no compatible
    triangulation; saying so needs no Delaunay triangulation (whose library import alone cost a two-icon
    morph most of a second). Counted in a fresh interpreter: scipy.spatial is never imported."""
    import subprocess
    import sys

    code = (
        "import sys\n"
        "import numpy as np\n"
        "from tweenrender.core.methods.injective import injective_fallback\n"
        "slit = np.array([[0, 0], [4, 0], [4, 2], [6, 2], [6, 3], [7, 3], [6, 2], [4, 2], [4, 4], [0, 4]], float)\n"
        "print(injective_fallback([slit], [slit * 1.5], [True]))\n"
        "print('scipy.spatial' in sys.modules)\n"
    )
    found = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split("\n")
    assert found[:2] == ["the key has coincident vertices", "False"], found


def _element_area(scene: object, t: float, element: str) -> float:
    from tests.core.shapely_areas import drawn_area
    import tweenrender as tr

    drawn = [c for c in tr.contours(scene, t, points=True) if c.closed and c.element == element]
    return drawn_area([c.points[::-1] if c.reversed else c.points for c in drawn], drawn[0].fill_rule).area


def test_a_ring_whose_partner_is_an_arch_opens_along_a_slit_instead_of_filling_in() -> None:
    """octicons' smiley ring (an outline and its hole) becomes tabler's letter A, whose arch (its stroke's band)
    has no hole. The hole finds no room to shrink as the outline narrows into the arch, and where it went early
    the ring filled into a solid blob (its area, by shapely, up to 1.54 times the larger key's off the straight
    blend of the keys' areas). Joined to the outline by a slit where the arch opens, the ring opens into it."""
    import tweenrender as tr
    from tests.helpers import DATA

    scene = tr.load_scene([DATA / "icons" / "octicons" / "smiley-24.svg", DATA / "icons" / "tabler" / "letter-a.svg"])
    ring = max(tr.contours(scene, 0.0), key=lambda c: float(np.ptp(c.points, axis=0).max())).element  # the face's
    first, last = _element_area(scene, 0.0, ring), _element_area(scene, 1.0, ring)
    off = [abs(_element_area(scene, t, ring) - ((1 - t) * first + t * last)) / max(first, last)
           for t in np.linspace(0.05, 0.95, 19)]
    assert max(off) <= 0.25, [round(x, 3) for x in off]
