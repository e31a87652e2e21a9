"""``contours``: every drawn contour with what a caller needs to draw or test it — open or closed,
hole or not, its element, fill rule and paint — read against the SVG files' own text."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tests.helpers import DATA
from tweenrender.model import DrawnContour
from tweenrender.pipeline.library import contours

ICONS = DATA / "icons"


def test_an_open_polyline_is_an_open_stroke_in_drawing_units() -> None:
    # feather's check: <polyline points="20 6 9 17 4 12"/>, stroke="currentColor" stroke-width="2", fill="none"
    (check,) = contours(tr.load_scene(ICONS / "feather" / "check.svg"), 0.0)
    assert isinstance(check, DrawnContour)
    assert not check.closed and not check.hole and check.fill is None
    assert check.stroke == (0.0, 0.0, 0.0, 1.0) and check.stroke_width == pytest.approx(2.0)
    assert check.element == "polyline1"
    # y up: the SVG's (20, 6) is (20, -6)
    assert np.allclose(check.points[0], [20, -6]) and np.allclose(check.points[-1], [4, -12])


def test_holes_fill_rule_and_ids_of_a_drawing(tmp_path: Path) -> None:
    svg = tmp_path / "ring.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">'
                   '<path id="ring" fill-rule="evenodd" fill="#ff8000" d="M0 0H10V10H0Z M3 3H7V7H3Z"/>'
                   '<circle cx="5" cy="5" r="1" fill="none" stroke="#0000ff" stroke-width="0.5" opacity="0.5"/></svg>')
    outer, hole, dot = contours(tr.load_scene(svg), 0.0)
    assert (outer.element, outer.hole, outer.fill_rule) == ("ring", False, "evenodd")
    assert (hole.element, hole.hole) == ("ring", True)
    assert outer.fill == pytest.approx((1.0, 128 / 255, 0.0, 1.0))
    assert dot.closed and dot.fill is None and dot.stroke == (0.0, 0.0, 1.0, 1.0)
    assert dot.stroke_width == pytest.approx(0.5) and dot.opacity == pytest.approx(0.5)
    assert [c.points.shape for c in contours(tr.load_scene(svg), 0.0)] == [p.shape for p in tr.outlines(tr.load_scene(svg), 0.0)]


def test_a_scene_files_pixel_stroke_width_in_scene_units(tmp_path: Path) -> None:
    scene_file = tmp_path / "s.toml"
    scene_file.write_text('size = [200, 100]\nview = [0, 0, 20, 10]\n[[shape]]\nname = "box"\nstroke = "#000000"\n'
                          'stroke_width = 4.0\n[[shape.key]]\ntime = 0.0\npoints = [[1, 1], [3, 1], [3, 3]]\n')
    (box,) = contours(tr.load_scene(scene_file), 0.0)
    assert box.element == "box" and box.stroke_width == pytest.approx(0.4)  # 10 px a unit


def test_the_second_key_of_a_reversed_partner_is_flagged() -> None:
    # at the last key, a contour whose balanced points run against its own SVG contour says so
    scene = tr.load_scene([ICONS / "mdi" / "check-circle-outline.svg", ICONS / "mdi" / "alpha-o-box.svg"])
    last = contours(scene, scene.duration)
    assert sum(c.hole for c in last) == 1 and len(last) == 3
    from tweenrender.core.geometry import signed_area

    # each contour wound as drawn: the hole against the box, the O's counter with the box (nonzero)
    wound = [np.sign(signed_area(c.points[::-1] if c.reversed else c.points)) for c in last]
    assert wound[0] != wound[1] or wound[0] != wound[2]


def test_nothing_of_an_element_without_a_partner_is_drawn_at_a_key(tmp_path: Path) -> None:
    # b has a stroked circle that a has not: at a's key it is not there at all (no dot), halfway it is
    # there at half its area (SPEC §5.17): √½ its size, with √½ its stroke width
    a, b = tmp_path / "a.svg", tmp_path / "b.svg"
    square = '<rect id="sq" x="2" y="2" width="6" height="6" fill="#000000"/>'
    a.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 40 40">{square}</svg>')
    b.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 40 40">{square}'
                 '<circle id="ring" cx="30" cy="30" r="5" fill="none" stroke="#ff0000" stroke-width="2"/></svg>')
    scene = tr.load_scene([a, b])
    assert [c.element for c in contours(scene, 0.0)] == ["sq"]
    (ring,) = [c for c in contours(scene, 0.5, method="linear") if c.element == "ring"]
    assert ring.stroke_width == pytest.approx(2.0 * np.sqrt(0.5))
    assert np.ptp(ring.points[:, 0]) == pytest.approx(10.0 * np.sqrt(0.5), rel=0.02)
    assert [c.element for c in contours(scene, 1.0)] == ["sq", "ring"]


def test_a_hole_that_only_an_evenodd_key_has_stays_a_hole_under_the_other_keys_nonzero(tmp_path: Path) -> None:
    # a's hole winds as its outline does (a hole only by even-odd); b is one square under nonzero. From halfway the
    # in-betweens take b's rule: the shrinking hole must still show, its area falling evenly (SPEC §5.17), where it
    # used to fill in at once. Read from the drawn frames: the pixels left uncovered inside the square.
    a, b = tmp_path / "a.svg", tmp_path / "b.svg"
    a.write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">'
                 '<path fill-rule="evenodd" d="M0 0H10V10H0Z M3 3H7V7H3Z"/></svg>')
    b.write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><path d="M0.5 0.5H9.5V9.5H0.5Z"/></svg>')
    scene = tr.load_scene([a, b])
    uncovered = []
    for t in (0.3, 0.45, 0.55, 0.7):
        picture = tr.frame(scene, t, size=(100, 100), method="linear", background="#ffffff")
        inner = picture[30:70, 30:70, :3].astype(float).mean(axis=2)  # the hole's square in a, in pixels
        uncovered.append(float((inner > 127).mean()))
    # the hole's share of its own square: 1 - t by area, give or take its shrinking toward its anchor
    assert all(u > 0.5 * (1 - t) for u, t in zip(uncovered, (0.3, 0.45, 0.55, 0.7))), uncovered
    assert uncovered[2] > 0.6 * uncovered[1], uncovered
