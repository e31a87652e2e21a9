"""Style sheets as browsers apply them: selectors, specificity, ``!important``, the cascade order and
``transform`` as a CSS property.

Each drawing is made so that the CSS rules paint its square green and any misreading paints it red
(or leaves it white); headless Chromium, an independent renderer, draws each the same way.
"""

from __future__ import annotations

import shutil
import warnings
from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tests.browser import svg_screenshots

GREEN, RED, WHITE = (0, 128, 0), (255, 0, 0), (255, 255, 255)
SIZE = 40
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")

CASES = {
    "attribute selector over a presentation attribute":
        ('[data-k="v"] { fill: green }', '<rect data-k="v" fill="red" width="40" height="40"/>'),
    "child combinator, more specific than a type selector":
        ("g > rect { fill: green } rect { fill: red }", '<g><rect width="40" height="40"/></g>'),
    "descendant combinator":
        ("svg g rect { fill: green } rect { fill: red }", '<g><g><rect width="40" height="40"/></g></g>'),
    "first child":
        ("rect:first-child { fill: green } rect { fill: red }", '<g><rect width="40" height="40"/></g>'),
    "next sibling":
        ("circle + rect { fill: green } rect { fill: red }", '<circle r="0"/><rect width="40" height="40"/>'),
    "negation":
        ("rect:not(.x) { fill: green } rect.x { fill: red }", '<rect class="y" width="40" height="40"/>'),
    "id over class, whatever their order":
        ("#r { fill: green } .c { fill: red }", '<rect id="r" class="c" width="40" height="40"/>'),
    "a later rule of equal specificity wins":
        (".a { fill: red } .b { fill: green }", '<rect class="b a" width="40" height="40"/>'),
    "important over the style attribute":
        (".c { fill: green !important }", '<rect class="c" style="fill: red" width="40" height="40"/>'),
    "important over a more specific rule":
        ("rect { fill: green !important } #r.c { fill: red }", '<rect id="r" class="c" width="40" height="40"/>'),
    "the style attribute's important over the sheet's":
        (".c { fill: red !important }", '<rect class="c" style="fill: green !important" width="40" height="40"/>'),
    "the style attribute over the sheet":
        ("#r { fill: red }", '<rect id="r" style="fill: green" width="40" height="40"/>'),
    "comments in the style attribute":
        ("", '<rect style="/* fill: red; */ fill: /* x */ green" width="40" height="40"/>'),
    "a sheet of another type is not read":
        ("rect { fill: red }", '<rect fill="green" width="40" height="40"/>'),
    "an invalid selector drops its rule only":
        ("rect:unknown-thing { fill: red } rect { fill: green }", '<rect width="40" height="40"/>'),
    "each sheet on its own: an unclosed block ends with its sheet":
        ("rect { fill: red </style><style> rect { fill: green }", '<rect width="40" height="40"/>'),
    "rules inside @media":
        ("@media all { rect { fill: green } }", '<rect fill="red" width="40" height="40"/>'),
    "transform as a CSS property replaces the attribute":
        ("#r { transform: translate(20px, 0) }",
         '<rect id="r" fill="green" transform="translate(100 0)" width="20" height="40"/>'),
}
SHEET_TYPE = {"a sheet of another type is not read": ' type="text/plain"'}
EXPECTED_LEFT = {"transform as a CSS property replaces the attribute": WHITE}  # its left half stays empty


def _drawing(folder: Path, name: str) -> Path:
    sheet, body = CASES[name]
    svg = folder / "case.svg"
    svg.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" width="{SIZE}" height="{SIZE}" '
                   f'viewBox="0 0 {SIZE} {SIZE}"><style{SHEET_TYPE.get(name, "")}>{sheet}</style>'
                   f'{body}</svg>')
    return svg


def _ours(svg: Path) -> np.ndarray:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        picture = tr.frame(tr.load_scene(svg), 0.0, size=(SIZE, SIZE), background="#ffffff")
    return picture[..., :3].astype(int)


def _chromium(svgs: list[Path], folder: Path) -> list[np.ndarray]:
    """Chromium's pictures of ``svgs``, each drawn as an ``<img>``, all in one screenshot."""
    return [p.astype(int) for p in svg_screenshots(svgs, [(SIZE, SIZE)] * len(svgs), SIZE, folder)]


def _colour_at(picture: np.ndarray, x: int, y: int) -> tuple[int, ...]:
    return tuple(int(v) for v in picture[y, x])


def _assert_drawn_as_meant(picture: np.ndarray, name: str) -> None:
    right, left = _colour_at(picture, 3 * SIZE // 4, SIZE // 2), _colour_at(picture, SIZE // 4, SIZE // 2)
    assert np.abs(np.subtract(right, GREEN)).max() <= 2, right
    assert np.abs(np.subtract(left, EXPECTED_LEFT.get(name, GREEN))).max() <= 2, left


@pytest.mark.parametrize("name", list(CASES))
def test_the_sheet_paints_as_a_browser_does(tmp_path: Path, name: str) -> None:
    _assert_drawn_as_meant(_ours(_drawing(tmp_path, name)), name)


@pytest.mark.skipif(CHROMIUM is None, reason="chromium (Debian package chromium) is not installed")
def test_chromium_paints_every_case_the_same_way(tmp_path: Path) -> None:
    """The cases' meaning checked by an independent renderer, a browser."""
    svgs = []
    for number, name in enumerate(CASES):
        (tmp_path / str(number)).mkdir()
        svgs.append(_drawing(tmp_path / str(number), name))
    for name, picture in zip(CASES, _chromium(svgs, tmp_path)):
        _assert_drawn_as_meant(picture, name)
