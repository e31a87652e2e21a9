"""Contours and elements without a partner come and go without a pop (SPEC §5.17).

Such a contour grows from (shrinks to) the point of its partner's side nearest its own centre of
area over the whole segment, its area linear in the eased parameter, so each frame adds (takes) an
equal share; its stroke width scales with it. Areas, centres and nearest points are worked out here
from first principles (shoelace, polygon centroid, point-to-segment distance), not by the project.
"""

from __future__ import annotations

import itertools
from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tests.helpers import write_scene

SQUARE = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]]
# an L whose vertices crowd along its bottom edge: its vertex mean is not its centre of area
ELL = [[6.0, 0.0], [6.25, 0.0], [6.5, 0.0], [6.75, 0.0], [7.0, 0.0], [7.25, 0.0], [9.0, 0.0], [9.0, 1.0],
       [7.0, 1.0], [7.0, 3.0], [6.0, 3.0]]
TIMES = np.linspace(0.0, 1.0, 25)


def area(points: np.ndarray) -> float:
    """|Shoelace area| of a closed polygon ``(N, 2)``."""
    x, y = points[:, 0], points[:, 1]
    return abs(0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)))


def centre_of_area(points: np.ndarray) -> np.ndarray:
    """The centroid of the region a simple polygon ``(N, 2)`` encloses."""
    x, y = points[:, 0], points[:, 1]
    x1, y1 = np.roll(x, -1), np.roll(y, -1)
    cross = x * y1 - x1 * y
    six_area = 3.0 * float(cross.sum())
    return np.array([((x + x1) * cross).sum(), ((y + y1) * cross).sum()]) / six_area


def nearest_on_edges(point: np.ndarray, polygons: list[np.ndarray]) -> np.ndarray:
    """Brute force: the point of the closed polygons' edges nearest ``point``."""
    best, best_d = None, np.inf
    for poly in polygons:
        for a, b in zip(poly, np.roll(poly, -1, axis=0)):
            s = float(np.clip(np.dot(point - a, b - a) / np.dot(b - a, b - a), 0.0, 1.0))
            foot = a + s * (b - a)
            d = float(np.hypot(*(foot - point)))
            if d < best_d:
                best, best_d = foot, d
    return np.asarray(best)


def shape_scene(tmp_path: Path, first: list, second: list, ease: str = "linear", extra: str = "") -> tr.Scene:
    text = (f'[[shape]]\nname = "s"\nmethod = "linear"\nfill = "#3b6fd8"\n{extra}'
            f'[[shape.key]]\ntime = 0\ncontours = {first}\nease = "{ease}"\n'
            f'[[shape.key]]\ntime = 1\ncontours = {second}\n')
    return tr.load_scene(write_scene(tmp_path, text))


def drawn(scene: tr.Scene, time: float, method: str | None = None) -> list:
    """Every shape as it is drawn at ``time`` (its contours, stroke width and each contour's share of it)."""
    from tweenrender.pipeline.frames import Frames
    from tweenrender.plan.job import RenderJob

    return Frames(RenderJob(scene)).shapes_at(method, time)


def by_name(scene: tr.Scene, time: float, method: str | None = None) -> dict:
    return {shape.name: at for shape, at in zip(scene.shapes, drawn(scene, time, method))}


@pytest.mark.parametrize("grows", [True, False])
def test_the_area_of_a_contour_without_partner_is_linear_in_t(tmp_path: Path, grows: bool) -> None:
    both, one = [SQUARE, ELL], [SQUARE]
    scene = shape_scene(tmp_path, one if grows else both, both if grows else one)
    key = area(np.array(ELL))
    for t in TIMES[1:-1]:
        (at,) = drawn(scene, float(t))
        square, alone = at.contours
        assert area(square) == pytest.approx(16.0, rel=1e-12)
        share = t if grows else 1.0 - t  # each of the 24 frames adds (takes) 1/24 of it
        assert area(alone) == pytest.approx(share * key, rel=1e-9), t
    (end,) = drawn(scene, 1.0 if grows else 0.0)
    np.testing.assert_array_equal(end.contours[1], np.array(ELL))  # the key, exactly


@pytest.mark.parametrize("grows", [True, False])
def test_at_its_keys_the_drawing_is_exactly_the_key(tmp_path: Path, grows: bool) -> None:
    """Coordinates that scaling by 1 about a point would round (p + (q - p) is not always q)."""
    odd = (0.3 * np.array(ELL) + 0.1).tolist()
    square = (0.7 * np.array(SQUARE) + 0.1).tolist()
    both, one = [square, odd], [square]
    scene = shape_scene(tmp_path, one if grows else both, both if grows else one)
    for time, key in ((0.0, one if grows else both), (1.0, both if grows else one)):
        got = tr.outlines(scene, time)
        assert len(got) == len(key)
        for points, want in zip(got, key):
            np.testing.assert_array_equal(points, np.array(want))


@pytest.mark.parametrize("ease, curve", [("in", lambda u: u * u), ("in-out", lambda u: 3 * u * u - 2 * u ** 3)])
def test_with_an_ease_the_area_follows_the_eased_fraction(tmp_path: Path, ease: str, curve) -> None:  # type: ignore[no-untyped-def]
    scene = shape_scene(tmp_path, [SQUARE], [SQUARE, ELL], ease)
    key = area(np.array(ELL))
    for u in TIMES[1:-1]:
        (at,) = drawn(scene, float(u))
        assert area(at.contours[1]) == pytest.approx(curve(u) * key, rel=1e-9), u


def grown_from(at_quarter: np.ndarray, key: np.ndarray) -> np.ndarray:
    """The point a contour is scaled about, from the contour at t = 1/4 (scale 1/2) and at its key."""
    points = 2.0 * at_quarter - key  # c + (k - c) / 2 = q  =>  c = 2q - k, the same for every vertex
    np.testing.assert_allclose(points, np.broadcast_to(points[0], points.shape), atol=1e-12)
    return points[0]


def test_a_contour_outside_its_partner_grows_from_the_partners_nearest_point(tmp_path: Path) -> None:
    ring = [[[-6.0, -6.0], [4.0, -6.0], [4.0, 4.0], [-6.0, 4.0]], [[-1.0, -1.0], [-1.0, 2.0], [2.0, 2.0], [2.0, -1.0]]]
    # the L's centre of area lies outside the first key's drawing, to the right of it
    scene = shape_scene(tmp_path, ring, [*ring, ELL])
    (at,) = drawn(scene, 0.25)
    centre = centre_of_area(np.array(ELL))
    point = nearest_on_edges(centre, [np.array(c) for c in ring])
    np.testing.assert_allclose(grown_from(at.contours[2], np.array(ELL)), point, atol=1e-9)
    assert not np.allclose(point, nearest_on_edges(np.mean(ELL, axis=0), [np.array(c) for c in ring]))


def edges_meet(p: np.ndarray, q: np.ndarray) -> bool:
    """Brute force: whether any edge of closed polygon ``p`` shares a point with any edge of ``q``
    (orientations of every pair of edges, collinear overlaps included)."""
    def orient(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> float:
        return float(np.sign((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])))

    def on(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> bool:
        return bool(min(a[0], b[0]) <= c[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= c[1] <= max(a[1], b[1]))

    for a, b in zip(p, np.roll(p, -1, axis=0)):
        for c, d in zip(q, np.roll(q, -1, axis=0)):
            o1, o2, o3, o4 = orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b)
            if o1 * o2 < 0 and o3 * o4 < 0:
                return True
            if (o1 == 0 and on(a, b, c)) or (o2 == 0 and on(a, b, d)) or (o3 == 0 and on(c, d, a)) \
                    or (o4 == 0 and on(c, d, b)):
                return True
    return False


def test_a_hole_its_partners_shrinking_hole_would_pass_over_grows_once_it_is_clear(tmp_path: Path) -> None:
    """A second hole whose nearest point on the first key's drawing lies on a hole that shrinks over it:
    grown from there over the whole segment the shrinking hole's edge would cut it. It grows instead,
    its area still linear in t, from a time when it can do so without meeting any other contour. (The
    element is stroked: a filled one's hole is joined to its outline instead, the next test.)"""
    outer = [[-2.0, -2.0], [14.0, -2.0], [14.0, 8.0], [-2.0, 8.0]]
    hole = [[0.0, 0.0], [0.0, 4.0], [7.5, 4.0], [7.5, 0.0]]  # clockwise
    small = [[0.0, 0.0], [0.0, 4.0], [4.0, 4.0], [4.0, 0.0]]
    ell_hole = np.array([list(p) for p in ELL[::-1]])
    scene = shape_scene(tmp_path, [outer, hole], [outer, small, ell_hole.tolist()],
                        extra='stroke = "#000000"\nstroke_width = 0.1\n')
    key = area(ell_hole)
    times = np.linspace(0.0, 1.0, 201)
    moving = [(1 - t) * np.array(hole) + t * np.array(small) for t in times]  # the straight paths of linear
    # grown from the old hole's nearest point over the whole segment, it would cross the shrinking hole
    point = nearest_on_edges(centre_of_area(ell_hole), [np.array(outer), np.array(hole)])
    assert any(edges_meet(point + np.sqrt(t) * (ell_hole - point), m) for t, m in zip(times[1:-1], moving[1:-1]))
    shares = []
    for t, m in zip(times[1:-1], moving[1:-1]):
        (at,) = drawn(scene, float(t))
        np.testing.assert_allclose(at.contours[1], m, atol=1e-12)
        grown = at.contours[2]
        if area(grown) > 0:
            assert not edges_meet(grown, m) and not edges_meet(grown, np.array(outer)), t
        shares.append(area(grown) / key)
    # its area is linear in t from its start on: share = (t - start) / (1 - start)
    shares = np.array(shares)
    started = times[1:-1][shares > 0]
    start = started[0] - shares[shares > 0][0] * (1 - started[0]) / (1 - shares[shares > 0][0])
    assert 0.0 < start < 0.9
    np.testing.assert_allclose(shares, np.clip((times[1:-1] - start) / (1 - start), 0, None), atol=1e-9)
    (end,) = drawn(scene, 1.0)
    np.testing.assert_array_equal(end.contours[2], ell_hole)


def test_a_hole_inside_its_partners_drawing_grows_from_its_centre_of_area(tmp_path: Path) -> None:
    outer = [[-2.0, -2.0], [14.0, -2.0], [14.0, 8.0], [-2.0, 8.0]]
    ell_hole = [list(p) for p in ELL[::-1]]
    scene = shape_scene(tmp_path, [outer], [outer, ell_hole])
    (at,) = drawn(scene, 0.25)
    np.testing.assert_allclose(grown_from(at.contours[1], np.array(ell_hole)), centre_of_area(np.array(ell_hole)),
                               atol=1e-9)


@pytest.mark.parametrize("grows", [True, False])
def test_a_growing_contours_stroke_width_scales_with_it(tmp_path: Path, grows: bool) -> None:
    both, one = [SQUARE, ELL], [SQUARE]
    scene = shape_scene(tmp_path, one if grows else both, both if grows else one,
                        extra='stroke = "#000000"\nstroke_width = 3.0\n')
    for t in TIMES:
        (at,) = drawn(scene, float(t))
        share = t if grows else 1.0 - t
        assert at.widths[0] == 1.0 and at.paint.stroke_width == 3.0
        assert at.widths[1] == pytest.approx(np.sqrt(share), rel=1e-12, abs=1e-15), t  # a band of area ∝ t


def drawings(tmp_path: Path) -> tuple[Path, Path]:
    box = '<rect id="box" x="1" y="1" width="4" height="4" fill="#3b6fd8"/>'
    ell = "M " + " L ".join(f"{x + 4} {20 - y}" for x, y in ELL) + " Z"  # the L in SVG units (y down)
    a = tmp_path / "a.svg"
    b = tmp_path / "b.svg"
    a.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 24">{box}</svg>')
    b.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 24">{box}'
                 f'<path id="ell" d="{ell}" fill="#2e9e44"/>'
                 '<polyline id="zig" points="4 16 10 20 16 16" fill="none" stroke="#000" stroke-width="2"/></svg>')
    return a, b


@pytest.mark.parametrize("method", ["linear", "nonlinear", "arap", "injective", "auto"])
def test_an_element_grows_from_its_centre_of_area_its_area_linear_in_t(tmp_path: Path, method: str) -> None:
    a, b = drawings(tmp_path)
    for forwards in (True, False):
        scene = tr.load_scene([a, b] if forwards else [b, a])
        key = by_name(scene, 1.0 if forwards else 0.0, method)
        ell_area = area(key["ell"].contours[0])
        zig_length = float(np.hypot(*np.diff(key["zig"].contours[0], axis=0).T).sum())
        for t in TIMES[1:-1]:
            now = by_name(scene, float(t), method)
            share = t if forwards else 1.0 - t
            assert area(now["ell"].contours[0]) == pytest.approx(share * ell_area, rel=1e-9), (t, forwards)
            # the stroke's width and length both scale by √share: its band's area is share × the key's
            zig = now["zig"]
            length = float(np.hypot(*np.diff(zig.contours[0], axis=0).T).sum())
            assert length == pytest.approx(np.sqrt(share) * zig_length, rel=1e-9)
            width = zig.paint.stroke_width * (zig.widths[0] if zig.widths else 1.0)
            assert width == pytest.approx(np.sqrt(share) * key["zig"].paint.stroke_width, rel=1e-9)
            (reported,) = [c.stroke_width for c in tr.contours(scene, float(t), method) if c.element == "zig"]
            assert reported == pytest.approx(width, rel=1e-12)  # the library reports the width drawn
    scene = tr.load_scene([a, b])
    ell_key = by_name(scene, 1.0, method)["ell"].contours[0]
    quarter = by_name(scene, 0.25, method)["ell"].contours[0]
    np.testing.assert_allclose(grown_from(quarter, ell_key), centre_of_area(ell_key), atol=1e-9)


def test_an_element_is_painted_in_its_place_while_it_grows(tmp_path: Path) -> None:
    """An element that appears takes, at the key where it is hidden, the place in the paint order it has at
    its own key: b paints the new dot over the face, so the dot is not hidden under the face until the
    paint order switches (late, where the face and the old element that now goes over it overlap least);
    nor is a second new dot, painted over the first in b, put under it."""
    face = '<circle id="face" cx="12" cy="12" r="9" fill="#ffcc4d"/>'
    a = tmp_path / "a.svg"
    b = tmp_path / "b.svg"
    a.write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 24">'
                 f'<rect id="bar" x="8" y="12" width="8" height="3" fill="#664500"/>{face}</svg>')
    b.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 24">{face}'  # the bar slides half out
                 '<rect id="bar" x="8" y="19.5" width="8" height="3" fill="#664500"/>'
                 '<circle id="dot" cx="12" cy="8" r="1" fill="#2e9e44"/>'
                 '<circle id="other" cx="13" cy="8" r="1" fill="#3b6fd8"/></svg>')
    scene = tr.load_scene([a, b])
    for time in (0.25, 0.5, 0.75):
        img = tr.frame(scene, time, size=(240, 240))
        assert tuple(img[80, 117, :3]) == (0x2E, 0x9E, 0x44), time  # the dot, 10 px a unit
        if time > 0.25:  # where the two overlap (radius √t)
            assert tuple(img[80, 125, :3]) == (0x3B, 0x6F, 0xD8), time


def test_an_element_that_comes_is_painted_over_one_that_goes(tmp_path: Path) -> None:
    """A page goes and a cross comes in its place (no key has both): the cross is painted over the page, so
    it shows as it grows rather than only as the page shrinks away from over it."""
    dot = '<circle id="dot" cx="3" cy="3" r="1" fill="#ff0000"/>'
    a = tmp_path / "a.svg"
    b = tmp_path / "b.svg"
    a.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 24">{dot}'
                 '<rect id="page" x="6" y="6" width="12" height="12" fill="#ccd6dd"/></svg>')
    b.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 24">{dot}'
                 '<path id="cross" d="M8 8 L16 16 M16 8 L8 16" stroke="#000" stroke-width="2" fill="none"/></svg>')
    scene = tr.load_scene([a, b])
    keys = {shape.name: shape.keys for shape in scene.shapes}
    assert keys["page"][-1].hidden and keys["cross"][0].hidden  # no partners
    for time in (0.25, 0.5, 0.75):
        img = tr.frame(scene, time, size=(240, 240))
        assert tuple(img[120, 120, :3]) == (0, 0, 0), time  # the cross's middle, 10 px a unit


def test_a_piece_that_would_pass_through_an_outline_to_reach_its_partner_goes_and_another_comes(
        tmp_path: Path) -> None:
    """A ring holding a small square in its hole becomes a disc with a small square beside it. Paired as
    they sit and size (outer with outer), the squares would have to cross the ring's outline on the way;
    the pairs are nested differently in the two keys, so the square in the hole shrinks away and the one
    outside grows, and no two contours meet at any t (brute force over every pair of edges)."""
    outer = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]
    hole = [[2.0, 2.0], [2.0, 8.0], [8.0, 8.0], [8.0, 2.0]]
    inner = [[4.0, 4.0], [6.0, 4.0], [6.0, 6.0], [4.0, 6.0]]
    disc = [[1.0, 1.0], [9.0, 1.0], [9.0, 9.0], [1.0, 9.0]]
    beside = [[12.0, 4.0], [14.0, 4.0], [14.0, 6.0], [12.0, 6.0]]
    scene = shape_scene(tmp_path, [outer, hole, inner], [disc, beside])
    for t in np.linspace(0.0, 1.0, 101)[1:-1]:
        (at,) = drawn(scene, float(t))
        shown = [np.asarray(c) for c in at.contours if np.ptp(c, axis=0).max() > 0]
        for i, j in itertools.combinations(range(len(shown)), 2):
            assert not edges_meet(shown[i], shown[j]), (t, i, j)
    (middle,) = drawn(scene, 0.5)
    sizes = sorted(float(np.ptp(c, axis=0).max()) for c in middle.contours)
    # the inner square at half its side's share (√0.5 · 2) and the new one likewise, not one square moving
    assert sum(abs(s - np.sqrt(0.5) * 2.0) < 1e-9 for s in sizes) == 2


def test_a_stroke_whose_ends_meet_morphs_into_a_closed_outline(tmp_path: Path) -> None:
    """Tabler's heart is one open path whose end stops 0.006 short of its start (round caps and joins:
    it is drawn as a closed heart); Feather's heart is closed. They are one heart to the eye, so the one
    becomes the other: at every in-between one contour is drawn, its area between the keys' areas (no
    heart shrinking away while another grows inside it)."""
    from tests.helpers import DATA

    icons = DATA / "icons"
    scene = tr.load_scene([icons / "tabler" / "heart.svg", icons / "feather" / "heart.svg"], step=1.0)
    (first,), (last,) = drawn(scene, 0.0), drawn(scene, 1.0)
    areas = [area(c) for c in (*first.contours, *last.contours) if len(c) >= 3]
    for t in (0.1, 0.25, 0.5, 0.75, 0.9):
        (at,) = drawn(scene, t)
        shown = [c for c in at.contours if np.ptp(c, axis=0).max() > 0]
        assert len(shown) == 1, t
        assert 0.9 * min(areas) <= area(shown[0]) <= 1.1 * max(areas), t


def test_a_filled_elements_hole_without_room_to_grow_opens_from_its_outline(tmp_path: Path) -> None:
    """The same keys filled and not stroked: the hole that had no room until late is joined to the outer
    by a slit (maths §5.17) and opens with it over the whole segment. Checked with shapely: no in-between's
    contour crosses itself or the other, and the drawn area (shoelace, here) changes evenly."""
    import shapely

    outer = [[-2.0, -2.0], [14.0, -2.0], [14.0, 8.0], [-2.0, 8.0]]
    hole = [[0.0, 0.0], [0.0, 4.0], [7.5, 4.0], [7.5, 0.0]]
    small = [[0.0, 0.0], [0.0, 4.0], [4.0, 4.0], [4.0, 0.0]]
    ell_hole = [list(p) for p in ELL[::-1]]
    scene = shape_scene(tmp_path, [outer, hole], [outer, small, ell_hole])
    areas = []
    for t in np.linspace(0.0, 1.0, 25):
        (at,) = drawn(scene, float(t))
        if 0.0 < t < 1.0:
            assert len(at.contours) == 2  # the outer, with the new hole joined to it; the moving hole
            # the joined contour may touch itself along the slit, never cross: what it covers (shapely's
            # repair) is what its shoelace says; and it never meets the moving hole
            polygons = [shapely.Polygon(c) for c in at.contours]
            for c, polygon in zip(at.contours, polygons):
                assert shapely.make_valid(polygon).area == pytest.approx(area(np.asarray(c)), rel=1e-9), t
            assert not polygons[0].boundary.intersects(polygons[1].boundary), t
        areas.append(sum(area(np.asarray(c)) * (1 if k == 0 else -1) for k, c in enumerate(at.contours[:2])))
    steps = np.abs(np.diff(areas))
    assert steps.max() <= 3.0 * np.median(steps)
    assert areas[-1] == pytest.approx(16 * 10 - 16 - area(np.array(ELL)))


def test_a_piece_an_outline_sweeps_over_at_once_is_joined_to_it_not_crossed(tmp_path: Path) -> None:
    """A piece (key 0 only) that the growing outline reaches in the first tenth of the segment has no room to
    shrink at any start the search tries; it was left at its anchor over the whole segment and the outline's
    edge crossed it. Joined to the outline by a slit, it is carried with it: checked with shapely, no
    in-between's contours meet, and the drawn area (shoelace) changes evenly."""
    import shapely

    outline0 = [[0.0, 0.0], [1.0, 0.0], [1.0, 4.0], [0.0, 4.0]]
    piece = [[1.2, 1.5], [2.0, 1.5], [2.0, 2.5], [1.2, 2.5]]
    outline1 = [[0.0, 0.0], [10.0, 0.0], [10.0, 4.0], [0.0, 4.0]]
    scene = shape_scene(tmp_path, [outline0, piece], [outline1])
    areas = []
    for t in np.linspace(0.0, 1.0, 25):
        (at,) = drawn(scene, float(t))
        rings = [np.asarray(c) for c in at.contours if len(c) >= 3 and area(np.asarray(c)) > 1e-12]
        if 0.0 < t < 1.0:
            for i, j in itertools.combinations(range(len(rings)), 2):
                a, b = shapely.LinearRing(rings[i]), shapely.LinearRing(rings[j])
                assert not a.intersects(b), (t, i, j)
        areas.append(sum(area(r) for r in rings))
    steps = np.abs(np.diff(areas))
    assert steps.max() <= 3.0 * np.median(steps)
    assert areas[0] == pytest.approx(4.8) and areas[-1] == pytest.approx(40.0)


def test_injective_paths_carry_a_new_hole_in_their_mesh_over_the_whole_segment(tmp_path: Path) -> None:
    """A big hole crosses its outline from left to right where a small new hole appears. The injective
    paths hold the new hole in their mesh (a stand-in in the first key), so it grows from the first
    in-between on and the moving hole goes round it: checked with shapely, no two contours meet at any
    in-between, the new hole is a point at the first key and exactly its drawing at the last."""
    import shapely

    outline = [[0.0, 0.0], [10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]
    moving0 = [[1.0, 4.0], [1.0, 6.0], [3.0, 6.0], [3.0, 4.0]]
    moving1 = [[7.0, 4.0], [7.0, 6.0], [9.0, 6.0], [9.0, 4.0]]
    new = [[4.75, 4.75], [4.75, 5.25], [5.25, 5.25], [5.25, 4.75]]
    text = ('[[shape]]\nname = "s"\nmethod = "injective"\nfill = "#3b6fd8"\n'
            f'[[shape.key]]\ntime = 0\ncontours = {[outline, moving0]}\n'
            f'[[shape.key]]\ntime = 1\ncontours = {[outline, moving1, new]}\n')
    scene = tr.load_scene(write_scene(tmp_path, text))
    small = area(np.asarray(new))
    grown = []
    for t in np.linspace(0.0, 1.0, 25):
        (at,) = drawn(scene, float(t))
        rings = [np.asarray(c) for c in at.contours]
        smallest = min(rings, key=lambda r: area(r) if len(r) >= 3 else 0.0)
        grown.append(area(smallest) if len(smallest) >= 3 else 0.0)
        if 0.0 < t < 1.0:
            live = [r for r in rings if len(r) >= 3 and area(r) > 1e-12]
            assert len(live) == 3, t
            for i, j in itertools.combinations(range(3), 2):
                assert not shapely.LinearRing(live[i]).intersects(shapely.LinearRing(live[j])), (t, i, j)
    assert grown[0] == 0.0 and grown[-1] == pytest.approx(small)
    assert all(0.0 < g for g in grown[1:]), "it grows from the first in-between on, not once the hole has passed"


@pytest.mark.parametrize("method", ["linear", "auto"])
def test_in_a_stroked_drawing_an_outline_grows_over_the_whole_segment_across_a_stroke_that_goes(
        tmp_path: Path, method: str) -> None:
    """An element drawn only by its stroke (no fill): a zigzag stroke goes while a square outline comes
    around it. Lines crossing lines are no tangle (open strokes' crossings are counted apart), so the
    square does not wait until the zigzag is out of its way and then appear in the last frames: each of
    the 24 frames adds an equal share of its area, from the first in-between on."""
    zig = '<path d="M11 8 L13 11 L11 13 L13 16" fill="none" stroke="#000" stroke-width="1"/>'
    box = '<rect x="4" y="4" width="16" height="16" fill="none" stroke="#000" stroke-width="1"/>'
    a, b = tmp_path / "a.svg", tmp_path / "b.svg"
    a.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 24">{zig}</svg>')
    b.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 24">{box}</svg>')
    scene = tr.load_scene([a, b])
    (end,) = [c.points for c in tr.contours(scene, 1.0, method) if c.closed]
    for t in TIMES[1:-1]:
        squares = [c.points for c in tr.contours(scene, float(t), method) if c.closed]
        grown = area(squares[0]) if squares else 0.0  # a contour not yet begun is not reported
        assert len(squares) <= 1 and grown == pytest.approx(t * area(end), rel=1e-9), t
