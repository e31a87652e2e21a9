"""Gradient strokes drawn as gradients, compared with librsvg's pictures of the same files, at keys and
between them (the gradient carried by the element's motion, as a gradient fill is)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tests.scenefile.test_icons import needs_rsvg
from tests.scenefile.test_key_frames import measures, reference

HEAD = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 40 40">'
STOPS = '<stop offset="0" stop-color="#ff3300"/><stop offset="0.5" stop-color="#ffee00"/>' \
        '<stop offset="1" stop-color="#0033cc"/>'
CASES = {
    "bounding-box": f'<defs><linearGradient id="g" x2="1" y2="0.4">{STOPS}</linearGradient></defs>'
                    '<rect x="6" y="8" width="28" height="22" fill="none" stroke="url(#g)" stroke-width="4"/>',
    "radial-with-opacity": f'<defs><radialGradient id="g">{STOPS}</radialGradient></defs>'
                           '<circle cx="20" cy="20" r="14" fill="#cccccc" stroke="url(#g)" stroke-width="6" '
                           'stroke-opacity="0.6"/>',
    "user-space-on-a-path": f'<defs><linearGradient id="g" gradientUnits="userSpaceOnUse" x1="4" y1="0" x2="36" '
                            f'y2="0">{STOPS}</linearGradient></defs><path d="M4 30 C 10 2, 30 2, 36 30" fill="none" '
                            'stroke="url(#g)" stroke-width="5" stroke-linecap="round"/>',
}


def _ours(svg: Path, t: float = 0.0, scene: tr.Scene | None = None) -> np.ndarray:
    scene = scene if scene is not None else tr.load_scene(svg)
    return tr.frame(scene, t, method="linear", size=(256, 256), background="#ffffff")[..., :3].astype(float)


@needs_rsvg
@pytest.mark.parametrize("name", sorted(CASES))
def test_a_gradient_stroke_as_librsvg_draws_it(name: str, tmp_path: Path) -> None:
    svg = tmp_path / f"{name}.svg"
    svg.write_text(HEAD + CASES[name] + "</svg>")
    iou, error = measures(_ours(svg), reference(svg))
    assert iou >= 0.99 and error <= 0.01, (iou, error)


def _ring(folder: Path, name: str, x: float, y: float, side: float) -> Path:
    svg = folder / f"{name}.svg"
    svg.write_text(HEAD + f'<defs><linearGradient id="g" x2="1" y2="0.4">{STOPS}</linearGradient></defs>'
                   f'<rect id="box" x="{x}" y="{y}" width="{side}" height="{side}" fill="none" stroke="url(#g)" '
                   'stroke-width="2"/></svg>')
    return svg


@needs_rsvg
def test_an_inbetween_gradient_stroke_moves_and_grows_with_its_element(tmp_path: Path) -> None:
    """A square stroked with a bounding-box gradient moves from (4, 4), side 10 to (18, 14), side 20 on
    straight paths with its width fixed: halfway it is the square at (11, 9), side 15, which librsvg draws."""
    a, b = _ring(tmp_path, "a", 4, 4, 10), _ring(tmp_path, "b", 18, 14, 20)
    middle = _ring(tmp_path, "middle", 11, 9, 15)
    halfway = _ours(a, 0.5, tr.load_scene([a, b]))
    iou, error = measures(halfway, reference(middle))
    assert iou >= 0.99 and error <= 0.01, (iou, error)
    assert len(np.unique(halfway.reshape(-1, 3), axis=0)) > 100  # a gradient, not one mean colour
