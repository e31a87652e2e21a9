"""The root viewport: ``width`` × ``height`` is the picture, the ``viewBox`` placed in it by
``preserveAspectRatio`` (SVG 1.1 §7.8). Where the square lands is worked out by hand from the rule."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr


def _ink(tmp_path: Path, par: str) -> tuple[int, int, int, int]:
    """(left, top, right, bottom) pixel bounds of the green square in a 200 × 100 picture."""
    svg = tmp_path / "p.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="200" height="100" viewBox="0 0 100 100" '
                   f'preserveAspectRatio="{par}"><rect x="0" y="0" width="100" height="100" fill="#008000"/></svg>')
    picture = tr.frame(tr.load_scene(svg), 0.0, size=(200, 100), background="#ffffff")
    ys, xs = np.nonzero((picture[..., :3] != 255).any(axis=-1))
    return int(xs.min()), int(ys.min()), int(xs.max()) + 1, int(ys.max()) + 1


@pytest.mark.parametrize(("par", "bounds"), [
    ("xMidYMid meet", (50, 0, 150, 100)),
    ("xMinYMin meet", (0, 0, 100, 100)),
    ("xMaxYMax", (100, 0, 200, 100)),
    ("none", (0, 0, 200, 100)),
    ("xMidYMid slice", (0, 0, 200, 100)),
])
def test_the_view_box_is_placed_by_preserve_aspect_ratio(tmp_path: Path, par: str,
                                                         bounds: tuple[int, int, int, int]) -> None:
    assert _ink(tmp_path, par) == bounds


# -- nested viewports: a nested <svg>, a <symbol> through <use>, an <svg> through <use> ----------------
# (bounds worked out by hand from SVG 1.1 §7.9 and §5.6; headless Chromium draws each the same)

NESTED = {
    "nested svg: its rectangle clips": (
        '<svg x="20" y="10" width="40" height="30"><circle r="100" fill="#008000"/></svg>', (20, 10, 60, 40)),
    "nested svg: its viewBox placed by xMidYMid meet": (
        '<svg width="40" height="20" viewBox="0 0 10 10"><rect width="10" height="10" fill="#008000"/></svg>',
        (10, 0, 30, 20)),
    "nested svg: xMinYMax slice": (
        '<svg width="40" height="20" viewBox="0 0 10 10" preserveAspectRatio="xMinYMax slice">'
        '<rect width="5" height="10" fill="#008000"/></svg>', (0, 0, 20, 20)),
    "nested svg: overflow hidden clips to the viewport": (
        '<svg width="40" height="20" viewBox="0 0 10 10"><rect x="-5" y="-5" width="20" height="20" '
        'fill="#008000"/></svg>', (0, 0, 40, 20)),
    "nested svg: overflow visible does not clip": (
        '<svg width="40" height="20" viewBox="0 0 10 10" overflow="visible"><rect x="-5" y="-5" width="20" '
        'height="20" fill="#008000"/></svg>', (0, 0, 40, 30)),
    "nested svg: overflow visible set by a style sheet": (
        '<style>svg svg { overflow: visible }</style><svg width="40" height="20" viewBox="0 0 10 10">'
        '<rect x="-5" y="-5" width="20" height="20" fill="#008000"/></svg>', (0, 0, 40, 30)),
    "nested svg: percentages are of the nested viewport": (
        '<svg x="50" y="50" width="50%" height="50"><rect width="50%" height="100%" fill="#008000"/></svg>',
        (50, 50, 75, 100)),
    "nested svg: zero width draws nothing": (
        '<svg width="0" height="50"><rect width="50" height="50" fill="#ff0000"/></svg>'
        '<rect x="90" y="90" width="10" height="10" fill="#008000"/>', (90, 90, 100, 100)),
    "symbol: its viewBox in the use's width and height": (
        '<symbol id="s" viewBox="0 0 10 10"><rect width="10" height="10" fill="#008000"/></symbol>'
        '<use href="#s" x="50" y="50" width="20" height="20"/>', (50, 50, 70, 70)),
    "symbol: clipped to the use's width and height": (
        '<symbol id="s"><rect width="100" height="100" fill="#008000"/></symbol>'
        '<use href="#s" x="10" y="20" width="30" height="40"/>', (10, 20, 40, 60)),
    "symbol: its own opacity": (
        '<symbol id="s" opacity="0"><rect width="100" height="100" fill="#ff0000"/></symbol><use href="#s"/>'
        '<rect x="90" y="90" width="10" height="10" fill="#008000"/>', (90, 90, 100, 100)),
    "use of an svg: the use's width replaces the svg's": (
        '<defs><svg id="s" x="5" width="10" height="10"><rect width="100" height="100" fill="#008000"/></svg>'
        '</defs><use href="#s" x="10" width="30"/>', (15, 0, 45, 10)),
}


def _ink_of(tmp_path: Path, body: str) -> tuple[int, int, int, int]:
    """(left, top, right, bottom) pixel bounds of the ink of a 100 × 100 drawing."""
    svg = tmp_path / "n.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100" viewBox="0 0 100 100">'
                   f'{body}</svg>')
    picture = tr.frame(tr.load_scene(svg), 0.0, size=(100, 100), background="#ffffff")
    ys, xs = np.nonzero((np.abs(picture[..., :3].astype(int) - 255) > 32).any(axis=-1))
    return int(xs.min()), int(ys.min()), int(xs.max()) + 1, int(ys.max()) + 1


@pytest.mark.parametrize("name", list(NESTED))
def test_a_nested_viewport_places_and_clips_its_content(tmp_path: Path, name: str) -> None:
    body, bounds = NESTED[name]
    assert _ink_of(tmp_path, body) == bounds
