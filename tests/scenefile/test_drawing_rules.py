"""Rules of SVG drawing the loader must keep, each checked against the SVG specification's closed form:
a nested ``<svg>`` fits its viewBox with ``xMidYMid meet`` (the smaller scale, centred), and an element
with ``display: none`` (by attribute, style, style sheet or an ancestor) is not drawn."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tweenrender.scenefile import svg


def _drawing(tmp_path: Path, body: str) -> Path:
    path = tmp_path / "d.svg"
    path.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="-100 -100 300 300">{body}</svg>')
    return path


def _boxes(path: Path) -> dict[str, tuple[float, float, float, float]]:
    """Each drawn element's box in user units (x0, y0, x1, y1), y down as in the file."""
    boxes = {}
    for element in svg.read_drawing(path).elements:
        every = np.concatenate([c.points for c in element.contours])
        x0, x1 = every[:, 0].min(), every[:, 0].max()
        y0, y1 = -every[:, 1].max(), -every[:, 1].min()  # world y is up: flip back
        boxes[element.id] = (float(x0), float(y0), float(x1), float(y1))
    return boxes


@pytest.mark.parametrize("width, height, expected", [
    # viewBox 10 x 10 into 20 x 40: scale min(2, 4) = 2, 20 units of height left, half above
    (20, 40, (0.0, 10.0, 20.0, 30.0)),
    # into 40 x 20: scale min(4, 2) = 2, 20 units of width left, half to the left
    (40, 20, (10.0, 0.0, 30.0, 20.0)),
])
def test_a_nested_svg_fits_its_view_box_meet(tmp_path: Path, width: int, height: int,
                                             expected: tuple[float, ...]) -> None:
    path = _drawing(tmp_path, f'<svg x="0" y="0" width="{width}" height="{height}" viewBox="0 0 10 10">'
                              '<rect id="r" x="0" y="0" width="10" height="10"/></svg>')
    np.testing.assert_allclose(_boxes(path)["r"], expected, atol=1e-9)


@pytest.mark.parametrize("hidden", [
    '<rect id="h" display="none" x="50" y="50" width="10" height="10"/>',
    '<rect id="h" style="fill: red; display : none" x="50" y="50" width="10" height="10"/>',
    '<style>.gone { display: none }</style><rect id="h" class="gone" x="50" y="50" width="10" height="10"/>',
    '<g display="none"><rect id="h" x="50" y="50" width="10" height="10"/></g>',
])
def test_an_element_with_display_none_is_not_drawn(tmp_path: Path, hidden: str) -> None:
    path = _drawing(tmp_path, '<rect id="shown" x="0" y="0" width="10" height="10"/>' + hidden)
    assert list(_boxes(path)) == ["shown"]
