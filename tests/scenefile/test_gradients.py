"""Gradient fills drawn as gradients, compared with librsvg's pictures of the same files: real icons
(Fluent Emoji: radial and linear gradients, transforms) and small files that take each attribute
in turn (units, transform, spread, focus, percentages, href inheritance)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tests.helpers import DATA
from tests.scenefile.test_icons import needs_rsvg
from tests.scenefile.test_key_frames import measures, reference

FLUENT = sorted((DATA / "icons" / "fluent-emoji").glob("*.svg"))

HEAD = '<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 40 40">'
CASES = {
    "bounding-box": '<defs><linearGradient id="g"><stop offset="0" stop-color="#ff0000"/>'
                    '<stop offset="1" stop-color="#0000ff"/></linearGradient></defs>'
                    '<rect x="5" y="8" width="30" height="20" fill="url(#g)"/>',
    "user-space-transform-reflect": '<defs><linearGradient id="g" gradientUnits="userSpaceOnUse" x1="10" y1="0" '
                                    'x2="16" y2="0" gradientTransform="rotate(30 20 20)" spreadMethod="reflect">'
                                    '<stop offset="0" stop-color="#ffcc00"/><stop offset="1" stop-color="#006633"/>'
                                    '</linearGradient></defs><circle cx="20" cy="20" r="17" fill="url(#g)"/>',
    "repeat-percent": '<defs><linearGradient id="g" x1="0%" y1="0%" x2="25%" y2="25%" spreadMethod="repeat">'
                      # stops at 0 and 1: cairo (librsvg) blends a repeat's last stop into the next
                      # period's first, where SVG and Chromium keep the last colour up to the period's end
                      '<stop offset="0" stop-color="#ffffff"/><stop offset="1" stop-color="#330066"/>'
                      '</linearGradient></defs><rect x="2" y="2" width="36" height="36" fill="url(#g)"/>',
    "radial-focus": '<defs><radialGradient id="g" cx="0.5" cy="0.5" r="0.5" fx="0.3" fy="0.35">'
                    '<stop offset="0" stop-color="#ffffff"/><stop offset="0.6" stop-color="#ff6600"/>'
                    '<stop offset="1" stop-color="#660000"/></radialGradient></defs>'
                    '<ellipse cx="20" cy="20" rx="18" ry="12" fill="url(#g)"/>',
    "href-and-transform": '<defs><linearGradient id="base"><stop offset="0" stop-color="#00ccff" stop-opacity="0.5"/>'
                          '<stop offset="1" stop-color="#000066"/></linearGradient>'
                          '<radialGradient id="g" xlink:href="#base" gradientUnits="userSpaceOnUse" cx="0" cy="0" '
                          'r="10" gradientTransform="translate(20 20) scale(1.5 1)"/></defs>'
                          '<g transform="translate(2 3) scale(0.9)"><rect x="0" y="0" width="40" height="36" '
                          'fill="url(#g)"/></g>',
    # userSpaceOnUse without coordinates: x2 100 %, cx cy r 50 % of the viewport (editors write these)
    "user-space-defaults": '<defs><linearGradient id="g" gradientUnits="userSpaceOnUse">'
                           '<stop offset="0" stop-color="#ffcc00"/><stop offset="1" stop-color="#006633"/>'
                           '</linearGradient><radialGradient id="h" gradientUnits="userSpaceOnUse" fx="30%">'
                           '<stop offset="0" stop-color="#ffffff"/><stop offset="1" stop-color="#660066"/>'
                           '</radialGradient></defs><rect x="2" y="2" width="36" height="16" fill="url(#g)"/>'
                           '<rect x="2" y="20" width="36" height="18" fill="url(#h)"/>',
}


def _ours(svg: Path, size: int = 256) -> np.ndarray:
    scene = tr.load_scene(svg)
    return tr.frame(scene, 0.0, size=(size, size), background="#ffffff")[..., :3].astype(float)


@needs_rsvg
@pytest.mark.parametrize("svg", FLUENT, ids=[p.stem for p in FLUENT])
def test_real_gradient_icons_look_as_librsvg_draws_them(svg: Path) -> None:
    assert "Gradient" in svg.read_text()
    iou, error = measures(_ours(svg), reference(svg))
    assert iou >= 0.99 and error <= 0.01, (iou, error)


@needs_rsvg
@pytest.mark.parametrize("name", sorted(CASES))
def test_each_gradient_attribute_as_librsvg_draws_it(name: str, tmp_path: Path) -> None:
    svg = tmp_path / f"{name}.svg"
    svg.write_text(HEAD + CASES[name] + "</svg>")
    iou, error = measures(_ours(svg), reference(svg))
    assert iou >= 0.99 and error <= 0.01, (iou, error)


def _rect_with_gradient(folder: Path, name: str, x: float, y: float, side: float, stops: str) -> Path:
    svg = folder / f"{name}.svg"
    svg.write_text(HEAD + f'<defs><linearGradient id="g" x1="0" y1="0" x2="1" y2="0.4">{stops}</linearGradient>'
                   f'</defs><rect id="box" x="{x}" y="{y}" width="{side}" height="{side}" fill="url(#g)"/></svg>')
    return svg


@needs_rsvg
def test_an_inbetween_gradient_moves_and_grows_with_its_element(tmp_path: Path) -> None:
    """A square with a bounding-box gradient moves from (2, 2), side 10 to (18, 14), side 20 on straight
    paths: halfway it is the square at (10, 8), side 15 — whose picture, gradient and all, librsvg draws."""
    stops = '<stop offset="0" stop-color="#ff3300"/><stop offset="0.5" stop-color="#ffee00"/>' \
            '<stop offset="1" stop-color="#0033cc"/>'
    a = _rect_with_gradient(tmp_path, "a", 2, 2, 10, stops)
    b = _rect_with_gradient(tmp_path, "b", 18, 14, 20, stops)
    middle = _rect_with_gradient(tmp_path, "middle", 10, 8, 15, stops)
    scene = tr.load_scene([a, b])
    halfway = tr.frame(scene, 0.5, method="linear", size=(256, 256), background="#ffffff")[..., :3].astype(float)
    iou, error = measures(halfway, reference(middle))
    assert iou >= 0.99 and error <= 0.01, (iou, error)
    flat = tr.frame(scene, 0.5, method="linear", size=(256, 256), background="#ffffff")
    assert len(np.unique(flat[..., :3].reshape(-1, 3), axis=0)) > 100  # a gradient, not one mean colour


def test_a_radial_gradient_of_radius_zero_paints_its_last_stop(tmp_path: Path) -> None:
    # SVG 1.1 §13.2.3 (and Chromium, resvg): r = 0 paints the area in the last stop's colour and opacity
    svg = tmp_path / "zero.svg"
    svg.write_text(HEAD + '<defs><radialGradient id="g" r="0"><stop offset="0" stop-color="#ffffff"/>'
                   '<stop offset="1" stop-color="#0066cc" stop-opacity="0.5"/></radialGradient></defs>'
                   '<rect x="5" y="5" width="30" height="30" fill="url(#g)"/></svg>')
    picture = _ours(svg, 40)
    expected = 0.5 * np.array([0, 102, 204]) + 0.5 * 255
    assert np.abs(picture[20, 20] - expected).max() <= 1.5 and (picture[1, 1] == 255).all()
