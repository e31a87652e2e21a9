"""Pattern paints drawn as repeated tiles, compared with librsvg's pictures of the same files: each attribute in
turn (units of the tile and of its content, ``viewBox``, ``patternTransform``, ``href``, strokes, opacity), and
between keys (the tile carried by the element's motion, as a gradient is)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tests.scenefile.test_icons import needs_rsvg
from tests.scenefile.test_key_frames import measures, reference

HEAD = '<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 40 40">'
TILE = '<rect width="4" height="4" fill="#cc3300"/><circle cx="6" cy="6" r="1.8" fill="#0033cc"/>'
CASES = {
    "user-space": f'<defs><pattern id="p" patternUnits="userSpaceOnUse" width="8" height="8">{TILE}</pattern></defs>'
                  '<rect x="4" y="6" width="30" height="26" fill="url(#p)"/>',
    "bounding-box-with-offset": f'<defs><pattern id="p" x="0.1" y="0.05" width="0.5" height="0.4">{TILE}</pattern>'
                                '</defs><rect x="4" y="6" width="32" height="28" fill="url(#p)"/>',
    "content-in-bounding-box": '<defs><pattern id="p" width="0.25" height="0.25" '
                               'patternContentUnits="objectBoundingBox">'
                               '<rect width="0.125" height="0.125" fill="#cc3300"/></pattern></defs>'
                               '<rect x="4" y="4" width="32" height="32" fill="url(#p)"/>',
    "view-box-and-transform": '<defs><pattern id="p" patternUnits="userSpaceOnUse" width="6" height="6" '
                              'viewBox="0 0 3 3" '
                              'patternTransform="rotate(20 20 20)"><rect width="1.5" height="1.5" fill="#006633"/>'
                              '</pattern></defs><circle cx="20" cy="20" r="16" fill="url(#p)"/>',
    "href-stroke-and-opacity": f'<defs><pattern id="base" patternUnits="userSpaceOnUse" width="8" height="8">{TILE}'
                               '</pattern><pattern id="p" xlink:href="#base" x="1"/></defs>'
                               '<rect x="6" y="6" width="28" height="28" fill="url(#p)" fill-opacity="0.5" '
                               'stroke="url(#p)" stroke-width="4"/>',
}


def _ours(svg: Path, t: float = 0.0, scene: tr.Scene | None = None) -> np.ndarray:
    scene = scene if scene is not None else tr.load_scene(svg)
    return tr.frame(scene, t, method="linear", size=(320, 320), background="#ffffff")[..., :3].astype(float)


@needs_rsvg
@pytest.mark.parametrize("name", sorted(CASES))
def test_each_pattern_attribute_as_librsvg_draws_it(name: str, tmp_path: Path) -> None:
    svg = tmp_path / f"{name}.svg"
    svg.write_text(HEAD + CASES[name] + "</svg>")
    iou, error = measures(_ours(svg), reference(svg, 320))
    # 0.98: a tile is drawn once and resampled, so edges at fractional pixels are softened by up to a pixel
    # (a tile out of place by a tenth of its size scores below 0.9)
    assert iou >= 0.98 and error <= 0.02, (iou, error)


def _square(folder: Path, name: str, x: float, y: float, side: float) -> Path:
    svg = folder / f"{name}.svg"
    svg.write_text(HEAD + f'<defs><pattern id="p" width="0.5" height="0.5">{TILE}</pattern></defs>'
                   f'<rect id="box" x="{x}" y="{y}" width="{side}" height="{side}" fill="url(#p)"/></svg>')
    return svg


@needs_rsvg
def test_an_inbetween_pattern_moves_with_its_element(tmp_path: Path) -> None:
    """A square filled with a bounding-box pattern moves from (2, 2) to (18, 14), side 16, on straight paths:
    a third of the way it is the square at (7.33, 6), which librsvg draws with its tile in place."""
    a, b = _square(tmp_path, "a", 2, 2, 16), _square(tmp_path, "b", 18, 14, 16)
    middle = _square(tmp_path, "middle", 2 + 16 / 3, 6, 16)
    third = _ours(a, 1 / 3, tr.load_scene([a, b]))
    iou, error = measures(third, reference(middle, 320))
    assert iou >= 0.99 and error <= 0.02, (iou, error)


def test_a_patterned_drawing_morphed_into_itself_stays_still(tmp_path: Path) -> None:
    """Two keys of the same file (each read on its own: equal patterns, distinct objects) draw the key at
    every time between them."""
    svg = tmp_path / "same.svg"
    svg.write_text(HEAD + CASES["href-stroke-and-opacity"] + "</svg>")
    scene = tr.load_scene([svg, svg])
    key = _ours(svg, 0.0, scene)
    assert np.abs(_ours(svg, 0.5, scene) - key).max() <= 1.0


def test_a_pattern_fades_in_as_its_plain_colour_would(tmp_path: Path) -> None:
    """A red square becomes one filled with a tile of solid blue: the tile is cross-faded in by the share of its
    key, t, over the plain colour the square would have (turning to the tile's mean colour), so a frame is
    ``(1 - t) × that + t × blue``; it used to stay plain until half-way and then show the tile whole at once."""
    square = '<rect x="8" y="8" width="24" height="24" fill="{}"/>'
    plain, blue, patterned = tmp_path / "plain.svg", tmp_path / "blue.svg", tmp_path / "patterned.svg"
    plain.write_text(HEAD + square.format("#ff0000") + "</svg>")
    blue.write_text(HEAD + square.format("#0000ff") + "</svg>")
    patterned.write_text(HEAD + '<defs><pattern id="p" patternUnits="userSpaceOnUse" width="4" height="4">'
                         '<rect width="4" height="4" fill="#0000ff"/></pattern></defs>' + square.format("url(#p)")
                         + "</svg>")

    def middles(scene: tr.Scene) -> np.ndarray:
        return np.array([tr.frame(scene, k / 24, method="linear", size=(80, 80), background="#ffffff")[40, 40, :3]
                         for k in range(25)], dtype=float)

    fading, turning = middles(tr.load_scene([plain, patterned], step=1.0)), middles(tr.load_scene([plain, blue], step=1.0))
    t = np.arange(25)[:, None] / 24
    expected = (1 - t) * turning + t * np.array([0.0, 0.0, 255.0])
    assert np.abs(fading - expected).max() <= 2.0, np.abs(fading - expected).max(axis=1).tolist()


def test_a_pattern_used_inside_its_own_tile_paints_nothing_there(tmp_path: Path) -> None:
    """SVG: a reference that leads back to the pattern being drawn is in error; what names it paints nothing,
    so each tile here holds only its green outline (read off the rule by hand)."""
    from tweenrender.scenefile.svg import read_drawing

    path = tmp_path / "recursive.svg"
    path.write_text(HEAD + '<pattern id="a" patternUnits="userSpaceOnUse" width="10" height="10">'
                    '<rect width="10" height="10" fill="url(#b)" stroke="#008000"/></pattern>'
                    '<pattern id="b" patternUnits="userSpaceOnUse" width="10" height="10">'
                    '<rect width="10" height="10" fill="url(#a)" stroke="#008000"/></pattern>'
                    '<rect id="ra" width="40" height="20" fill="url(#a)"/>'
                    '<rect id="rb" y="20" width="40" height="20" fill="url(#b)"/></svg>', encoding="utf-8")
    for element in read_drawing(path).elements:
        tile = element.paint.pattern
        assert tile is not None and [(s.paint.fill, s.paint.stroke) for s in tile.shapes] == \
            [(None, (0, 128, 0, 255))], element.id
