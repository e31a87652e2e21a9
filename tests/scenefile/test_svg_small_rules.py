"""Small SVG rules drawn as a browser draws them: ``clip-rule`` on a clip path's children, lengths in
viewport units (``vw``, ``vh``, ``vmin``, ``vmax``) and ``ch``, ``transform-origin``, ``paint-order``.

Each case is drawn by tweenrender and by headless Chromium, an independent renderer (each drawing as an
``<img>`` at its own size, all in one screenshot), and compared by the key-frame measure.
"""

from __future__ import annotations

import shutil
import warnings
from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tests.browser import svg_screenshots
from tests.scenefile.test_key_frames import measures

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
SIZE = 100

_STAR = "M 50 5 L 80 95 L 5 40 L 95 40 L 20 95 Z"
CASES: dict[str, str] = {
    # clip-rule: the star's middle pentagon is outside its clip region under evenodd
    "clip-rule evenodd on the child":
        f'<clipPath id="c"><path d="{_STAR}" clip-rule="evenodd"/></clipPath>'
        '<rect width="100" height="100" fill="green" clip-path="url(#c)"/>',
    "clip-rule inherited from the clipPath's parent":
        f'<g clip-rule="evenodd"><clipPath id="c"><path d="{_STAR}"/></clipPath></g>'
        '<rect width="100" height="100" fill="green" clip-path="url(#c)"/>',
    "clip-rule on the clipPath itself":
        f'<clipPath id="c" clip-rule="evenodd"><path d="{_STAR}"/></clipPath>'
        '<rect width="100" height="100" fill="green" clip-path="url(#c)"/>',
    "clip-rule evenodd and nonzero children, their union":
        '<clipPath id="c"><path d="M 5 5 H 60 V 60 H 5 Z M 15 15 H 50 V 50 H 15 Z" clip-rule="evenodd"/>'
        '<path d="M 95 95 H 30 V 30 H 95 Z M 85 85 H 40 V 40 H 85 Z"/></clipPath>'
        '<rect width="100" height="100" fill="green" clip-path="url(#c)"/>',
    "clip-rule evenodd of overlapping subpaths under a transform":
        '<clipPath id="c" transform="rotate(10 50 50)"><path d="M 10 10 H 70 V 70 H 10 Z M 30 30 H 90 V 90 H 30 Z" '
        'clip-rule="evenodd"/></clipPath><rect width="100" height="100" fill="green" clip-path="url(#c)"/>',
    "fill-rule is not clip-rule":
        f'<clipPath id="c"><path d="{_STAR}" fill-rule="evenodd"/></clipPath>'
        '<rect width="100" height="100" fill="green" clip-path="url(#c)"/>',
    # viewport units: of the outermost <svg>'s viewport (100 × 50 CSS px), as px in the user space
    "vw and vh": '<rect x="10vw" y="10vh" width="30vw" height="60vh" fill="green"/>',
    "vmin and vmax": '<rect x="10vmin" y="10vmin" width="30vmax" height="40vmin" fill="green"/>',
    "viewport units in a nested viewport and a transform":
        '<svg x="10" y="5" width="50" height="30" viewBox="0 0 25 15"><rect width="10vw" height="10vh" '
        'fill="green" transform="translate(2 2)"/></svg>',
    # transform-origin: keywords, lengths and percentages of the viewport (transform-box view-box)
    "transform-origin keywords": '<rect x="20" y="20" width="30" height="20" fill="green" transform="rotate(30)" '
                                 'transform-origin="right bottom"/>',
    "transform-origin one keyword": '<rect x="30" y="30" width="40" height="20" fill="green" '
                                    'transform="scale(0.5 1.5)" transform-origin="top"/>',
    "transform-origin length and percentage": '<rect x="30" y="30" width="40" height="20" fill="green" '
                                              'transform="rotate(-20)" transform-origin="40px 75%"/>',
    "transform-origin keyword then length": '<g transform="rotate(25)" transform-origin="left 2em" font-size="10">'
                                            '<rect x="40" y="10" width="40" height="30" fill="green"/></g>',
    "transform-origin as a CSS property": '<style>rect { transform-origin: 50% 50% }</style><rect x="30" y="30" '
                                          'width="40" height="40" fill="green" transform="rotate(45)"/>',
    "transform-origin of a clip path's transform":
        f'<clipPath id="c" transform="rotate(36)" transform-origin="center"><path d="{_STAR}"/></clipPath>'
        '<rect width="100" height="100" fill="green" clip-path="url(#c)"/>',
    # paint-order: the stroke under the fill shows only its outer half
    "paint-order stroke": '<rect x="20" y="20" width="60" height="60" fill="green" stroke="#0000ff" '
                          'stroke-width="16" paint-order="stroke"/>',
    "paint-order stroke, markers, fill, inherited": '<g paint-order="stroke markers fill"><circle cx="50" cy="50" '
                                                     'r="30" fill="green" stroke="#0000ff" stroke-width="20"/></g>',
    "paint-order markers keeps the fill under the stroke": '<rect x="20" y="20" width="60" height="60" fill="green" '
                                                           'stroke="#0000ff" stroke-width="16" paint-order="markers"/>',
    "paint-order with an unknown word is normal": '<rect x="20" y="20" width="60" height="60" fill="green" '
                                                  'stroke="#0000ff" stroke-width="16" paint-order="stroke fill x"/>',
    "paint-order as a CSS property, on an open path": '<style>path { paint-order: stroke }</style><path '
                                                      'd="M 10 80 L 50 10 L 90 80" fill="green" stroke="#0000ff" '
                                                      'stroke-width="14" stroke-linejoin="round"/>',
    # stroke-miterlimit above 1 keeps the miters (as Illustrator's stroke-miterlimit="10" everywhere asks)
    "stroke-miterlimit 10": '<path d="M 10 10 L 35 60 H 65 L 30 10" fill="none" stroke="#000" stroke-width="8" '
                            'stroke-miterlimit="10"/>',
    "stroke-miterlimit from a style, below the joins' ratio": '<path d="M 10 90 L 50 20 L 90 90" fill="none" '
                                                              'stroke="#000" stroke-width="10" '
                                                              'style="stroke-miterlimit: 1.5"/>',
}
SIZES = {"vw and vh": (100, 50, "0 0 50 25"), "vmin and vmax": (100, 50, "0 0 50 25"),
         "viewport units in a nested viewport and a transform": (100, 50, "0 0 50 25")}


def _size(name: str) -> tuple[int, int, str]:
    """The case's drawing size in pixels and its viewBox."""
    return SIZES.get(name, (SIZE, SIZE, f"0 0 {SIZE} {SIZE}"))


def _svg(folder: Path, name: str) -> Path:
    svg = folder / f"{list(CASES).index(name)}.svg"
    width, height, box = _size(name)
    svg.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="{box}">'
                   + CASES[name] + "</svg>")
    return svg


def _ours(svg: Path, name: str) -> np.ndarray:
    width, height, _ = _size(name)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        picture = tr.frame(tr.load_scene(svg), 0.0, size=(width, height), background="#ffffff")
    return picture[..., :3].astype(float)


def _chromium(svgs: list[Path], sizes: list[tuple[int, int]], folder: Path) -> list[np.ndarray]:
    """Chromium's pictures of ``svgs``, each drawn as an ``<img>`` of its size in a SIZE × SIZE slot, all in
    one screenshot."""
    return svg_screenshots(svgs, sizes, SIZE, folder)


@pytest.fixture(scope="module")
def browser_pictures(tmp_path_factory: pytest.TempPathFactory) -> dict[str, np.ndarray]:
    if CHROMIUM is None:
        pytest.skip("chromium (Debian package chromium) is not installed")
    folder = tmp_path_factory.mktemp("small-rules")
    svgs = [_svg(folder, name) for name in CASES]
    return dict(zip(CASES, _chromium(svgs, [_size(name)[:2] for name in CASES], folder)))


@pytest.mark.parametrize("name", list(CASES))
def test_drawn_as_chromium_draws_it(name: str, browser_pictures: dict[str, np.ndarray], tmp_path: Path) -> None:
    iou, error = measures(_ours(_svg(tmp_path, name), name), browser_pictures[name])
    assert iou >= 0.99 and error <= 0.02, (iou, error)


def test_ch_is_half_an_em(tmp_path: Path) -> None:
    """Without the font's metrics ``ch`` is half an ``em`` (CSS Values 4 §6.1.1: the font's "0" cannot be
    measured here): at font-size 10, a rectangle from 2ch = 10 to 2ch + 6ch = 40 across, 1ch = 5 to 25 down."""
    svg = tmp_path / "ch.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="50" height="50" viewBox="0 0 50 50" '
                   'font-size="10"><rect x="2ch" y="1ch" width="6ch" height="4ch" fill="green"/></svg>')
    ink = (tr.frame(tr.load_scene(svg), 0.0, size=(50, 50), background="#ffffff")[..., :3] != 255).any(axis=-1)
    rows, columns = np.nonzero(ink)
    assert (columns.min(), columns.max(), rows.min(), rows.max()) == (10, 39, 5, 24)



def test_ex_is_half_an_em(tmp_path: Path) -> None:
    """Without the font's x-height ``ex`` is half an ``em`` (CSS Values 4 §6.1.1): at font-size 10 the same
    rectangle as above, 10 to 40 across and 5 to 25 down."""
    svg = tmp_path / "ex.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="50" height="50" viewBox="0 0 50 50" '
                   'font-size="10"><rect x="2ex" y="1ex" width="6ex" height="4ex" fill="green"/></svg>')
    ink = (tr.frame(tr.load_scene(svg), 0.0, size=(50, 50), background="#ffffff")[..., :3] != 255).any(axis=-1)
    rows, columns = np.nonzero(ink)
    assert (columns.min(), columns.max(), rows.min(), rows.max()) == (10, 39, 5, 24)


def test_q_is_a_quarter_millimetre(tmp_path: Path) -> None:
    """``1Q`` is a quarter of a millimetre (CSS Values 3 §6.2), 96 px to 25.4 mm: 127Q = 31.75 mm = 1.25 in
    = 120 px, and 63.5Q = 60 px."""
    svg = tmp_path / "q.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200" viewBox="0 0 200 200">'
                   '<rect x="0" y="0" width="127Q" height="63.5Q" fill="green"/></svg>')
    ink = (tr.frame(tr.load_scene(svg), 0.0, size=(200, 200), background="#ffffff")[..., :3] != 255).any(axis=-1)
    rows, columns = np.nonzero(ink)
    assert (columns.min(), columns.max(), rows.min(), rows.max()) == (0, 119, 0, 59)



def test_rem_is_the_root_elements_font_size(tmp_path: Path) -> None:
    """``rem`` is the root element's ``font-size`` wherever it is written (CSS Values 3 §6.1.1), ``em`` the
    element's own: inside a group at font-size 20 under a root at 10, 1rem = 10 and 1em = 20."""
    svg = tmp_path / "rem.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="50" height="50" viewBox="0 0 50 50" '
                   'font-size="10"><g font-size="20"><rect x="1rem" y="0.5em" width="3rem" height="1em" '
                   'fill="green"/></g></svg>')
    ink = (tr.frame(tr.load_scene(svg), 0.0, size=(50, 50), background="#ffffff")[..., :3] != 255).any(axis=-1)
    rows, columns = np.nonzero(ink)
    assert (columns.min(), columns.max(), rows.min(), rows.max()) == (10, 39, 10, 29)


def test_a_stroke_width_in_em_is_of_the_elements_font_size(tmp_path: Path) -> None:
    """``stroke-width="0.5em"`` at font-size 20 is 10 units (CSS Values 3 §6.1.1, as any length): a line along
    y = 25 inks rows 20 to 29, as ``stroke-width="10"`` does; before, it was read as 0.5."""
    svg = tmp_path / "em-stroke.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="50" height="50" viewBox="0 0 50 50" '
                   'font-size="20"><path d="M 5 25 H 45" stroke="#000" stroke-width="0.5em"/></svg>')
    ink = (tr.frame(tr.load_scene(svg), 0.0, size=(50, 50), background="#ffffff")[..., :3] < 128).any(axis=-1)
    rows, columns = np.nonzero(ink)
    assert (columns.min(), columns.max(), rows.min(), rows.max()) == (5, 44, 20, 29)


def test_a_nested_view_box_origin_moves_its_content(tmp_path: Path) -> None:
    """A nested ``<svg>``'s ``viewBox="50 50 100 100"`` in a 50 × 50 viewport at (10, 20) maps user point
    (50, 50) to (10, 20) at scale 1/2 (SVG 1.1 §7.7): a square from 50 to 150 lands on 10–60 × 20–70."""
    svg = tmp_path / "nested.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100" viewBox="0 0 100 100">'
                   '<svg x="10" y="20" width="50" height="50" viewBox="50 50 100 100">'
                   '<rect x="50" y="50" width="100" height="100" fill="green"/></svg></svg>')
    ink = (tr.frame(tr.load_scene(svg), 0.0, size=(100, 100), background="#ffffff")[..., :3] != 255).any(axis=-1)
    rows, columns = np.nonzero(ink)
    assert (columns.min(), columns.max(), rows.min(), rows.max()) == (10, 59, 20, 69)


def _winding(contours: list[np.ndarray], points: np.ndarray) -> np.ndarray:
    """Winding numbers of ``points (P, 2)`` about closed ``contours`` (each ``(N, 2)``), by crossings of a ray."""
    total = np.zeros(len(points), dtype=int)
    for c in contours:
        a, b = c, np.roll(c, -1, axis=0)
        px, py = points[:, None, 0], points[:, None, 1]
        up = (a[None, :, 1] <= py) & (b[None, :, 1] > py)
        down = (a[None, :, 1] > py) & (b[None, :, 1] <= py)
        (ax, ay), (bx, by) = (a[None, :, 0], a[None, :, 1]), (b[None, :, 0], b[None, :, 1])
        side = (bx - ax) * (py - ay) - (px - ax) * (by - ay)
        total += (up & (side > 0)).sum(axis=1) - (down & (side < 0)).sum(axis=1)
    return total


def test_an_evenodd_child_becomes_contours_of_winding_zero_or_one() -> None:
    """Brute force on a grid: the contours made for an even-odd child wind once exactly where the child's
    own contours cross an odd number of times (a self-crossing star and two overlapping squares)."""
    from tweenrender.scenefile.svg_clip_rule import evenodd_as_nonzero

    star = np.array([[50, 5], [80, 95], [5, 40], [95, 40], [20, 95]], dtype=float)
    squares = [np.array([[10, 10], [70, 10], [70, 70], [10, 70]], dtype=float),
               np.array([[30, 30], [30, 90], [90, 90], [90, 30]], dtype=float)]  # the other way round
    grid = np.stack(np.meshgrid(np.arange(0.5, 100), np.arange(0.5, 100)), axis=-1).reshape(-1, 2) + 0.013
    for contours in ([star], squares, [star, *squares]):
        made = evenodd_as_nonzero(contours)
        wound = _winding(made, grid)
        assert set(np.unique(wound)) <= {0, 1}
        assert np.array_equal(wound == 1, _winding(contours, grid) % 2 == 1)
