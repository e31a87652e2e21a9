"""Dashed strokes: ``stroke-dasharray`` and ``stroke-dashoffset`` drawn as librsvg draws them at keys, and
between keys a pattern blended linearly and laid along the in-between outline (closed forms of its ink)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tests.scenefile.test_icons import needs_rsvg
from tests.scenefile.test_key_frames import measures, reference

HEAD = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 200" width="200" height="200">'
FRAME = '<rect x="1" y="1" width="198" height="198" fill="none" stroke="black"/>'
CASES = {
    "open-path-with-offset": '<path d="M 20 40 H 180 V 160" fill="none" stroke="green" stroke-width="12" '
                             'stroke-dasharray="25 10" stroke-dashoffset="7"/>',
    "odd-count-repeated": '<polyline points="20,100 100,30 180,100" fill="none" stroke="navy" stroke-width="8" '
                          'stroke-dasharray="5 10 20"/>',
    "percentages-and-negative-offset": '<rect x="40" y="40" width="120" height="120" fill="#fc0" stroke="green" '
                                       'stroke-width="10" stroke-dasharray="10% 5%" stroke-dashoffset="-33"/>',
    "round-caps-on-a-circle": '<circle cx="100" cy="100" r="60" fill="none" stroke="purple" stroke-width="24" '
                              'stroke-linecap="round" stroke-dasharray="0 40"/>',
    "inherited-from-a-group": '<g stroke-dasharray="30,10" stroke-dashoffset="1em" font-size="10">'
                              '<line x1="20" y1="60" x2="180" y2="140" stroke="red" stroke-width="14"/></g>',
    "a-negative-length-is-solid": '<line x1="20" y1="100" x2="180" y2="100" stroke="teal" stroke-width="10" '
                                  'stroke-dasharray="20 -5"/>',
    "a-zero-sum-is-solid": '<line x1="20" y1="100" x2="180" y2="100" stroke="teal" stroke-width="10" '
                           'stroke-dasharray="0 0"/>',
    "scaled-by-its-transform": '<g transform="translate(20 20) scale(2)"><path d="M 0 10 H 80" stroke="black" '
                               'stroke-width="5" stroke-dasharray="7 3"/></g>',
}


def _svg(folder: Path, name: str, body: str, frame: str = FRAME) -> Path:
    svg = folder / f"{name}.svg"
    svg.write_text(HEAD + body + frame + "</svg>")
    return svg


def _picture(scene: tr.Scene, time: float, size: int = 200) -> np.ndarray:
    return tr.frame(scene, time, method="linear", size=(size, size), background="#ffffff")[..., :3].astype(float)


@needs_rsvg
@pytest.mark.parametrize("name", sorted(CASES))
def test_dashes_draw_as_librsvg_draws_them(name: str, tmp_path: Path) -> None:
    svg = _svg(tmp_path, name, CASES[name])
    iou, error = measures(_picture(tr.load_scene(svg), 0.0), reference(svg, 200))
    assert iou >= 0.99 and error <= 0.02, (iou, error)


def _line(folder: Path, name: str, y: float, dash: str | None) -> Path:
    dashes = f' stroke-dasharray="{dash}"' if dash else ""
    return _svg(folder, name, f'<path d="M 20 {y} H 180" stroke="black" stroke-width="10"{dashes}/>', frame="")


def _ink(picture: np.ndarray) -> float:
    """Ink of a black-on-white picture: the sum of darkness, in pixels."""
    return float((255.0 - picture).mean(axis=-1).sum() / 255.0)


def _duty(pattern: list[float], length: float = 160.0) -> float:
    """The share of ``length`` that ``pattern`` (dash, gap, …) laid from its start inks, counted dash by dash."""
    inked, at, k = 0.0, 0.0, 0
    while at < length:
        if k % 2 == 0:
            inked += min(pattern[k % len(pattern)], length - at)
        at += pattern[k % len(pattern)]
        k += 1
    return inked / length


@pytest.mark.parametrize("dashes, halfway", [(("10 30", "30 10"), [20, 20]),
                                             ((None, "10 30"), [25, 15]),  # the solid key as 40 0
                                             (("6 2 10 22", "10 30"), [8, 16, 10, 26])])  # 10 30 repeated
def test_halfway_a_dashed_line_inks_the_blended_patterns_duty(tmp_path: Path, dashes: tuple, halfway: list) -> None:
    """A 160-unit line moving down, dashed differently at its keys: halfway its ink is the duty of the
    halfway pattern over the line times the ink of the same line undashed (butt caps)."""
    dashed = tr.load_scene([_line(tmp_path, "a", 60, dashes[0]), _line(tmp_path, "b", 140, dashes[1])])
    solid = tr.load_scene([_line(tmp_path, "c", 60, None), _line(tmp_path, "d", 140, None)])
    half = 0.5 * dashed.duration
    expected = _duty([float(v) for v in halfway]) * _ink(_picture(solid, half))
    assert _ink(_picture(dashed, half)) == pytest.approx(expected, rel=0.02)


def test_the_dashes_move_with_the_outline(tmp_path: Path) -> None:
    """A dashed square moved by 40 units: halfway its picture is the key's shifted by 20 units (as drawn)."""
    def square(name: str, x: float) -> Path:
        return _svg(tmp_path, name, f'<rect x="{x}" y="50" width="80" height="80" fill="none" stroke="black" '
                                    'stroke-width="8" stroke-dasharray="15 7" stroke-dashoffset="3"/>')

    scene = tr.load_scene([square("a", 30), square("b", 70)])
    first, half = _picture(scene, 0.0), _picture(scene, 0.5 * scene.duration)
    inner = (slice(10, 190), slice(10, 150))  # off the frame rectangle
    shifted = first[inner[0], inner[1]]
    moved = half[inner[0], 30:170]
    iou, error = measures(moved, shifted)
    assert iou >= 0.98 and error <= 0.02, (iou, error)


def test_patterns_of_different_counts_blend_repeated_to_a_common_count() -> None:
    from tweenrender.core.dashes import blend_dashes
    from tweenrender.model import Dash

    a, b = Dash((2.0, 4.0), 1.0), Dash((1.0, 2.0, 3.0, 4.0), 3.0)
    assert blend_dashes(a, b, [0.0, 0.5, 1.0]) == [a, Dash((1.5, 3.0, 2.5, 4.0), 2.0), b]
    assert blend_dashes(None, Dash((10.0, 30.0)), [0.25]) == [Dash((32.5, 7.5), 0.0)]  # from (40, 0)
    assert blend_dashes(None, None, [0.5]) == [None]


def test_a_dash_array_is_read_in_world_units(tmp_path: Path) -> None:
    from tweenrender.model import Dash
    from tweenrender.scenefile.svg import read_drawing

    drawing = read_drawing(_svg(tmp_path, "x", CASES["odd-count-repeated"] + CASES["scaled-by-its-transform"]))
    dashes = [e.paint.dash for e in drawing.elements]
    assert dashes[0] == Dash((5.0, 10.0, 20.0, 5.0, 10.0, 20.0), 0.0)
    assert dashes[1] == Dash((14.0, 6.0), 0.0)
    assert dashes[2] is None


@needs_rsvg
def test_each_key_starts_its_pattern_at_its_own_first_vertex(tmp_path: Path) -> None:
    """A dashed circle morphing into a dashed rectangle, whose first vertex (its top-left corner) the
    balanced in-between does not start at: the last frame is librsvg's picture of the rectangle."""
    circle = _svg(tmp_path, "circle", '<circle cx="100" cy="100" r="60" fill="none" stroke="#c0392b" '
                  'stroke-width="16" stroke-dasharray="40 20" stroke-dashoffset="3"/>', frame="")
    rect = _svg(tmp_path, "rect", '<rect x="40" y="60" width="120" height="90" fill="none" stroke="#2e86de" '
                'stroke-width="8" stroke-dasharray="20 5 4 5" stroke-dashoffset="-10"/>', frame="")
    scene = tr.load_scene([circle, rect])
    for svg, time in ((circle, 0.0), (rect, scene.duration)):
        iou, error = measures(_picture(scene, time, 400), reference(svg, 400))  # edges weigh less at 400
        assert iou >= 0.99 and error <= 0.02, (svg.stem, iou, error)


def test_a_path_length_measures_the_pattern_in_its_units(tmp_path: Path) -> None:
    """``pathLength="10"`` on a 160-unit line: ``1 1`` is dashes of 16 (SVG 2), five of them, half the ink."""
    from scipy import ndimage

    def line(name: str, extra: str) -> tr.Scene:
        return tr.load_scene(_svg(tmp_path, name, f'<path d="M 20 100 H 180" stroke="black" stroke-width="20"'
                                                  f'{extra}/>', frame=""))

    dashed = _picture(line("dashed", ' pathLength="10" stroke-dasharray="1 1"'), 0.0)
    solid = _picture(line("solid", ""), 0.0)
    assert ndimage.label(dashed.mean(axis=-1) < 128)[1] == 5
    assert _ink(dashed) == pytest.approx(0.5 * _ink(solid), rel=0.02)
