"""Clip paths' children (their own clip paths, what is not a valid child), ``clip-path: circle()`` and group
opacity, against brute-force winding numbers and closed forms."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tests.helpers import run_main
from tweenrender.errors import OptionError
from tweenrender.scenefile.svg_clip_children import intersection, region

HEAD = '<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 40 40">'
STAR = np.array([[20.0, 2.0], [30.0, 34.0], [4.0, 14.0], [36.0, 14.0], [10.0, 34.0]])  # a pentagram: its
# centre pentagon has winding 2, so nonzero fills it and even-odd does not


def _svg(tmp_path: Path, name: str, body: str) -> Path:
    svg = tmp_path / f"{name}.svg"
    svg.write_text(HEAD + body + "</svg>")
    return svg


def _picture(svg: Path | list[Path]) -> np.ndarray:
    return tr.frame(tr.load_scene(svg), 0.0, size=(200, 200), background="#ffffff")[..., :3].astype(float)


def _brute_winding(points: np.ndarray, polygon: np.ndarray) -> np.ndarray:
    """Winding numbers of ``polygon (N, 2)`` around ``points (P, 2)`` by summed signed angles."""
    total = np.zeros(len(points))
    for a, b in zip(polygon, np.roll(polygon, -1, axis=0)):
        u, v = a - points, b - points
        total += np.arctan2(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0], (u * v).sum(axis=1))
    return np.rint(total / (2 * np.pi)).astype(int)


def _inside_nonzero(points: np.ndarray, contours: list[np.ndarray]) -> np.ndarray:
    return sum((_brute_winding(points, c) for c in contours), np.zeros(len(points), dtype=int)) != 0


@pytest.mark.parametrize("rule", ["nonzero", "evenodd"])
def test_a_star_cut_by_a_square_is_the_points_inside_both(rule: str) -> None:
    grid = np.stack(np.meshgrid(np.linspace(0.3, 39.7, 61), np.linspace(0.3, 39.7, 61)), axis=-1).reshape(-1, 2)
    square = np.array([[12.0, 8.0], [12.0, 30.0], [32.0, 30.0], [32.0, 8.0]])  # clockwise: winding -1 inside
    winding = _brute_winding(grid, STAR)
    in_star = winding % 2 != 0 if rule == "evenodd" else winding != 0
    expected = in_star & (_brute_winding(grid, square) != 0)
    out = intersection([STAR], rule, [[square]])
    assert np.array_equal(_inside_nonzero(grid, out), expected)
    assert set(np.unique(sum(_brute_winding(grid, c) for c in out))) <= {0, 1}  # winding 0 or 1 only
    assert region([STAR], rule).area == pytest.approx(
        (in_star.sum() / len(grid)) * 39.4 ** 2, rel=0.05)  # the grid's share of the plane it covers


def test_a_childs_own_clip_path_cuts_it_and_a_group_child_is_ignored(tmp_path: Path) -> None:
    """The clip path is its left half-square child cut by a circle of radius 10 at (20, 20); the <g> child
    (a full square) does not count, so the right half stays white."""
    svg = _svg(tmp_path, "clip", '<clipPath id="round"><circle cx="20" cy="20" r="10"/></clipPath>'
                                 '<clipPath id="c"><rect width="20" height="40" clip-path="url(#round)"/>'
                                 '<g><rect width="40" height="40"/></g></clipPath>'
                                 '<rect width="40" height="40" fill="black" clip-path="url(#c)"/>')
    ink = (_picture(svg) < 128).any(axis=-1)
    ys, xs = np.mgrid[0:200, 0:200] + 0.5
    distance = np.hypot(xs / 5 - 20, ys / 5 - 20)
    expected = (distance < 10) & (xs / 5 < 20)
    sure = (np.abs(distance - 10) > 0.4) & (np.abs(xs / 5 - 20) > 0.4)  # away from the edges
    assert np.array_equal(ink[sure], expected[sure])


def test_clip_path_circle_is_the_circle_of_the_closest_side_of_the_box(tmp_path: Path) -> None:
    """``circle()`` on a 30 × 20 rectangle at (5, 10): centre (20, 20), radius 10 (its closest side);
    ``circle(50%)`` of ``view-box``: radius half of √((40² + 40²) / 2) = 20."""
    for value, radius in (("circle()", 10.0), ("circle(50%) view-box", 20.0), ("circle(6 at 20 20) fill-box", 6.0)):
        svg = _svg(tmp_path, "circle", f'<rect x="5" y="10" width="30" height="20" fill="black" '
                                       f'clip-path="{value}"/>' if "view-box" not in value else
                   f'<rect width="40" height="40" fill="black" clip-path="{value}"/>')
        ink = (_picture(svg) < 128).any(axis=-1)
        ys, xs = np.mgrid[0:200, 0:200] + 0.5
        centre = (25.0, 30.0) if value == "circle(6 at 20 20) fill-box" else (20.0, 20.0)
        distance = np.hypot(xs / 5 - centre[0], ys / 5 - centre[1])
        inside_box = ((xs / 5 > 5) & (xs / 5 < 35) & (ys / 5 > 10) & (ys / 5 < 30)) if "view-box" not in value \
            else np.ones_like(xs, dtype=bool)
        sure = np.abs(distance - radius) > 0.4
        assert np.array_equal(ink[sure], ((distance < radius) & inside_box)[sure]), value


OVERLAPPING = ('<g opacity="0.5"><rect x="4" y="4" width="20" height="20" fill="#ff0000"/>'
               '<rect x="16" y="16" width="20" height="20" fill="#0000ff"/></g>')


def test_a_groups_opacity_composites_its_children_once(tmp_path: Path) -> None:
    """Over white at opacity ½: the red square alone is (255, 127.5, 127.5); where the blue square covers it,
    blue alone shows, (127.5, 127.5, 255) — not blue at ½ over red at ½ over white."""
    picture = _picture(_svg(tmp_path, "group", OVERLAPPING))
    assert np.abs(picture[50, 50] - (255, 127.5, 127.5)).max() <= 1.5  # (10, 10): red alone
    assert np.abs(picture[100, 100] - (127.5, 127.5, 255)).max() <= 1.5  # (20, 20): both, blue on top
    assert np.abs(picture[150, 150] - (127.5, 127.5, 255)).max() <= 1.5  # (30, 30): blue alone
    percent = _svg(tmp_path, "percent", '<rect width="40" height="40" fill="#000000" opacity="50%"/>')
    assert np.abs(_picture(percent)[100, 100] - 127.5).max() <= 1.5


def test_a_group_of_apart_children_stays_plain_and_exports(tmp_path: Path) -> None:
    """Children that do not overlap are drawn the same either way: the group's opacity is theirs, and the
    vector formats carry it; overlapping ones are refused by them in one line."""
    apart = _svg(tmp_path, "apart", '<g opacity="0.5"><rect x="2" y="2" width="10" height="10"/>'
                                    '<rect x="20" y="20" width="10" height="10"/></g>')
    elements = tr.load_scene(apart).shapes
    assert all(not key.groups and key.paint.opacity == pytest.approx(0.5) for s in elements for key in s.keys)
    tr.write(tr.load_scene(apart), tmp_path / "apart.json")
    overlapping = _svg(tmp_path, "overlapping", OVERLAPPING)
    with pytest.raises(OptionError, match="opacity"):
        tr.write(tr.load_scene(overlapping), tmp_path / "x.json")
    for target in (tmp_path / "x.json", tmp_path / "x.svg"):
        done = run_main("render", overlapping, overlapping, "-o", target, "-q", cwd=tmp_path)
        lines = done.stderr.strip().splitlines()
        assert done.returncode == 2 and len(lines) == 1 and "opacity" in lines[0] and "Traceback" not in done.stderr
        assert not target.exists()


def test_a_bounding_box_clip_path_on_a_moved_group_is_of_the_groups_box(tmp_path: Path) -> None:
    """The group's box is its invisible square's, (0, 0)–(20, 20), moved by (10, 10): the clip is the disc of
    radius 10 at (20, 20), over the black square (12, 12)–(28, 28)."""
    svg = _svg(tmp_path, "box", '<clipPath id="c" clipPathUnits="objectBoundingBox"><circle cx="0.5" cy="0.5" '
                                'r="0.5"/></clipPath><g transform="translate(10 10)" clip-path="url(#c)">'
                                '<rect width="20" height="20" fill="red" opacity="0"/>'
                                '<rect x="2" y="2" width="16" height="16" fill="black"/></g>')
    ink = (_picture(svg) < 128).any(axis=-1)
    ys, xs = np.mgrid[0:200, 0:200] / 5 + 0.1
    distance = np.hypot(xs - 20, ys - 20)
    square = (xs > 12) & (xs < 28) & (ys > 12) & (ys < 28)
    sure = (np.abs(distance - 10) > 0.4) & (np.minimum(np.abs(xs - 20), np.abs(ys - 20)) < 7.6)
    assert np.array_equal(ink[sure], ((distance < 10) & square)[sure])
