"""SVG masks drawn at keys and carried with their element, against librsvg's pictures and closed forms."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tests.helpers import run_main
from tests.scenefile.test_icons import needs_rsvg
from tests.scenefile.test_key_frames import measures, reference
from tweenrender.core.mask_motion import box_map, carried, masks_at
from tweenrender.errors import OptionError
from tweenrender.model import Mask

HEAD = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 40 40">'
GRADIENT = ('<linearGradient id="g"><stop offset="0" stop-color="white"/><stop offset="1" stop-color="#333"/>'
            '</linearGradient>')
CASES = {
    "luminance-of-a-gradient": GRADIENT + '<mask id="m"><rect x="4" y="4" width="32" height="32" fill="url(#g)"/>'
                               '</mask><rect width="40" height="40" fill="#cc3300" mask="url(#m)"/>',
    "alpha-type": '<mask id="m" mask-type="alpha"><circle cx="20" cy="20" r="14" fill="#000" fill-opacity="0.8"/>'
                  '</mask><rect x="2" y="2" width="36" height="36" fill="#1166cc" mask="url(#m)"/>',
    "on-a-group-with-transforms": '<mask id="m"><circle cx="20" cy="20" r="12" fill="white"/>'
                                  '<rect x="10" y="18" width="20" height="4" fill="black"/></mask>'
                                  '<g mask="url(#m)" transform="rotate(15 20 20)"><rect x="2" y="2" width="36" '
                                  'height="36" fill="#228833"/><circle cx="28" cy="12" r="7" fill="#ffcc00"/></g>',
    "bounding-box-units": '<mask id="m" maskContentUnits="objectBoundingBox" x="0" y="0" width="0.5" height="1">'
                          '<rect width="1" height="1" fill="white"/></mask>'
                          '<rect x="6" y="10" width="28" height="20" fill="#884499" mask="url(#m)"/>',
    "a-thick-stroke": '<mask id="m" maskUnits="userSpaceOnUse" x="0" y="0" width="40" height="40">'
                      '<rect width="40" height="40" fill="white"/></mask><path d="M8 32 L20 8 L32 32" fill="none" '
                      'stroke="#333333" stroke-width="7" stroke-linejoin="round" stroke-linecap="square" '
                      'mask="url(#m)"/>',
    "user-space-region": '<mask id="m" maskUnits="userSpaceOnUse" x="0" y="20" width="40" height="20">'
                         '<rect width="40" height="40" fill="white"/></mask>'
                         '<circle cx="20" cy="20" r="15" fill="#dd5500" mask="url(#m)"/>',
    "mask-on-the-mask-and-on-its-content": '<mask id="inner"><rect x="0" y="0" width="22" height="40" fill="white"/>'
                                           '</mask><mask id="m" mask="url(#inner)"><circle cx="20" cy="20" r="15" '
                                           'fill="white"/><rect x="14" y="0" width="6" height="40" fill="black" '
                                           'mask="url(#inner)"/></mask>'
                                           '<rect width="40" height="40" fill="#005577" mask="url(#m)"/>',
}


def _svg(tmp_path: Path, name: str, body: str) -> Path:
    svg = tmp_path / f"{name}.svg"
    svg.write_text(HEAD + body + "</svg>")
    return svg


def _picture(svg: Path | list[Path], time: float = 0.0) -> np.ndarray:
    scene = tr.load_scene(svg)
    return tr.frame(scene, time, method="linear", size=(256, 256), background="#ffffff")[..., :3].astype(float)


@needs_rsvg
@pytest.mark.parametrize("name", sorted(CASES))
def test_masks_mask_as_librsvg_does(name: str, tmp_path: Path) -> None:
    svg = _svg(tmp_path, name, CASES[name])
    iou, error = measures(_picture(svg), reference(svg))
    assert iou >= 0.99 and error <= 0.01, (iou, error)


@pytest.mark.parametrize("mask_type, expected", [("luminance", 255 * (1 - 0.2125)), ("alpha", 0.0)])
def test_a_red_mask_lets_through_its_luminance_or_its_alpha(tmp_path: Path, mask_type: str, expected: float) -> None:
    """Black through pure red: SVG's luminance of red is 0.2125 (CSS Masking §7.1), its alpha 1."""
    svg = _svg(tmp_path, "red", f'<mask id="m" mask-type="{mask_type}"><rect width="40" height="40" fill="red"/>'
                                '</mask><rect width="40" height="40" fill="black" mask="url(#m)"/>')
    picture = _picture(svg)
    assert np.abs(picture[64:192, 64:192] - expected).max() <= 1.5



def _srgb_to_linear(value: np.ndarray) -> np.ndarray:
    return np.where(value <= 0.04045, value / 12.92, ((value + 0.055) / 1.055) ** 2.4)


@pytest.mark.parametrize("interpolation", ["sRGB", "linearRGB"])
def test_a_fading_gradient_mask_lets_through_luminance_times_alpha_within_rounding(
        tmp_path: Path, interpolation: str) -> None:
    """Transparent white to opaque black across x = 4 … 36: at ``s`` along it the colour is ``1 − s``, the
    alpha ``s`` (stops interpolated unpremultiplied), so the mask lets through ``L(1 − s) · s`` where ``L``
    is the identity (sRGB) or the sRGB transfer function's inverse (``color-interpolation="linearRGB"``);
    green over white is then ``255 (1 − mask)`` in red. Every pixel within 1.5 levels of that: the 8-bit
    roundings of the gradient's colour and alpha, the mask and the composite (resvg's reference pictures of
    the same drawings are 1.5 levels off at most, too; the key-frame measure calls a pixel ink beyond 32
    levels from white, and this curve runs near that line for many columns, so one level there changes
    many pixels' verdict)."""
    svg = _svg(tmp_path, "fade", '<linearGradient id="g"><stop offset="0" stop-color="white" stop-opacity="0"/>'
                                 '<stop offset="1" stop-color="black"/></linearGradient>'
                                 f'<mask id="m" color-interpolation="{interpolation}"><rect x="4" y="4" width="32" '
                                 'height="32" fill="url(#g)"/></mask>'
                                 '<rect width="40" height="40" fill="#008000" mask="url(#m)"/>')
    red = _picture(svg)[128, :, 0]  # 256 px for 40 units: 6.4 px a unit
    columns = np.arange(40, 216)  # inside x = 4 … 36 by a pixel and more
    s = ((columns + 0.5) / 6.4 - 4) / 32
    colour = _srgb_to_linear(1 - s) if interpolation == "linearRGB" else 1 - s
    expected = 255 * (1 - colour * s)
    assert np.abs(red[columns] - expected).max() <= 1.5, np.abs(red[columns] - expected).max()
def test_an_element_whose_mask_needs_a_box_it_has_not_is_not_drawn(tmp_path: Path) -> None:
    svg = _svg(tmp_path, "line", '<mask id="m"><rect width="40" height="40" fill="white"/></mask>'
                                 '<line x1="0" y1="20" x2="40" y2="20" stroke="black" stroke-width="4" '
                                 'mask="url(#m)"/><line x1="20" y1="0" x2="20" y2="10" stroke="black"/>')
    ink = (_picture(svg) < 200).any(axis=-1)
    assert ink[:60].any() and not ink[100:].any()  # the unmasked line alone


def test_masks_in_loops_are_ignored_and_a_missing_one_leaves_its_element_unmasked(tmp_path: Path) -> None:
    """As Chromium draws resvg's tests ``recursive`` and ``invalid-FuncIRI``: a mask on itself is a plain mask;
    a reference to no mask draws the element as if unmasked."""
    looped = _svg(tmp_path, "looped", '<mask id="m" mask="url(#m)"><rect width="20" height="40" fill="white"/></mask>'
                                      '<rect width="40" height="40" fill="black" mask="url(#m)"/>')
    ink = (_picture(looped) < 128).any(axis=-1)
    assert ink[:, :120].all() and not ink[:, 136:].any()
    missing = _svg(tmp_path, "missing", '<rect width="40" height="40" fill="black" mask="url(#nothing)"/>')
    assert (_picture(missing) < 128).all()


@needs_rsvg
def test_a_mask_moves_and_grows_with_its_element(tmp_path: Path) -> None:
    """A square masked by the white disc inscribed in it moves from (2, 2), side 10 to (18, 14), side 20: halfway
    it is the square at (10, 8), side 15, masked by its own inscribed disc."""
    def masked(name: str, x: float, y: float, side: float) -> Path:
        return _svg(tmp_path, name, f'<mask id="m" maskUnits="userSpaceOnUse"><circle cx="{x + side / 2}" '
                                    f'cy="{y + side / 2}" r="{side / 2}" fill="white"/></mask><rect id="box" '
                                    f'x="{x}" y="{y}" width="{side}" height="{side}" fill="#dd5500" mask="url(#m)"/>')

    halfway = _picture([masked("a", 2, 2, 10), masked("b", 18, 14, 20)], 0.5)
    iou, error = measures(halfway, reference(masked("middle", 10, 8, 15)))
    assert iou >= 0.99 and error <= 0.01, (iou, error)


@needs_rsvg
def test_a_mask_turns_with_its_element(tmp_path: Path) -> None:
    """A triangle and its mask (its left part) turned by 0° and 60° about the triangle's centre: halfway, under
    the rigid method, the triangle and its mask are turned by 30°."""
    def turned(name: str, angle: float) -> Path:
        return _svg(tmp_path, name, f'<mask id="m" maskUnits="userSpaceOnUse"><rect x="4" y="4" width="18" '
                                    f'height="32" fill="white"/></mask><g transform="rotate({angle} 16 20)" '
                                    f'mask="url(#m)"><polygon id="arrow" points="8,10 32,20 8,30" '
                                    f'fill="#1166cc"/></g>')

    scene = tr.load_scene([turned("a", 0), turned("b", 60)])
    halfway = tr.frame(scene, 0.5, method="rigid", size=(256, 256), background="#ffffff")[..., :3].astype(float)
    iou, error = measures(halfway, reference(turned("middle", 30)))
    assert iou >= 0.99 and error <= 0.01, (iou, error)


def test_a_mask_is_carried_by_the_affine_map_of_its_element() -> None:
    rng = np.random.default_rng(3)
    source = rng.normal(size=(12, 2))
    move = np.array([[1.5, -0.4, 3.0], [0.7, 0.9, -2.0], [0.0, 0.0, 1.0]])
    target = source @ move[:2, :2].T + move[:2, 2]
    assert np.allclose(carried(source, target), move)
    line = np.column_stack([np.linspace(0.0, 2.0, 5), np.full(5, 1.0)])  # on a line: the boxes' map
    assert np.allclose(carried(line, line * 3.0) @ [2.0, 1.0, 1.0], [6.0, 3.0, 1.0])
    assert np.allclose(box_map((0.0, 0.0, 2.0, 4.0), (10.0, 20.0, 16.0, 22.0)) @ [2.0, 4.0, 1.0], [16.0, 22.0, 1.0])


def test_between_keys_the_two_keys_masks_are_weighed_by_t() -> None:
    mask = Mask((), ())
    (w0, m0, _), (w1, m1, _) = masks_at((mask,), (), np.eye(3), np.eye(3), 0.25)
    assert (w0, w1) == (0.75, 0.25) and m0 == (mask,) and m1 == ()  # a key without masks lets all through
    assert masks_at((), (), np.eye(3), np.eye(3), 0.5) == ()


def test_a_masked_drawing_is_refused_by_the_vector_formats_in_one_line(tmp_path: Path) -> None:
    a = _svg(tmp_path, "a", CASES["user-space-region"])
    b = _svg(tmp_path, "b", CASES["user-space-region"].replace('r="15"', 'r="10"'))
    with pytest.raises(OptionError, match="mask"):
        tr.write(tr.load_scene([a, b]), tmp_path / "x.json")
    for target in (tmp_path / "x.json", tmp_path / "x.svg"):
        done = run_main("render", a, b, "-o", target, "-q", cwd=tmp_path)
        lines = done.stderr.strip().splitlines()
        assert done.returncode == 2 and len(lines) == 1 and "mask" in lines[0] and "Traceback" not in done.stderr
        assert not target.exists()


def test_an_unreadable_region_is_its_default_and_a_collapsed_mask_hides_without_nan(tmp_path: Path) -> None:
    unreadable = _svg(tmp_path, "bad", '<mask id="m" x="left" width="wide"><rect width="40" height="40" '
                                       'fill="white"/></mask><rect width="40" height="40" fill="black" '
                                       'mask="url(#m)"/>')
    assert (_picture(unreadable) < 128).all()  # x -10 %, width 120 %: the whole square
    collapsed = _svg(tmp_path, "flat", '<mask id="m" maskUnits="userSpaceOnUse"><rect width="40" height="40" '
                                       'fill="white" transform="scale(0)"/></mask><g transform="scale(1 0)" '
                                       'mask="url(#m)"><rect width="40" height="40"/></g><rect width="40" '
                                       'height="40" fill="black" mask="url(#m)"/><rect x="1" y="1" width="2" '
                                       'height="2"/>')
    picture = _picture(collapsed)
    assert np.isfinite(picture).all() and (picture[128, 64:] == 255).all() and (picture[12, 12] < 128).all()
