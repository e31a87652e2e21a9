"""Drawings that draw nothing, as renderers take them: no shapes, a root ``width`` or ``height`` of zero (which
disables rendering, SVG 1.1 §7.2) or below zero (an error: nothing drawn). They load as scenes of no shapes,
whose every frame is the background, and the command line renders them without complaint."""

from __future__ import annotations

from pathlib import Path

import imageio.v3 as iio
import numpy as np
import pytest

import tweenrender as tr

RECT = '<rect x="20" y="20" width="160" height="160" fill="green"/>'
DRAWINGS = {
    "no-children": '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 200"><title>none</title></svg>',
    "zero-width": f'<svg xmlns="http://www.w3.org/2000/svg" width="0" height="200">{RECT}</svg>',
    "zero-size": f'<svg xmlns="http://www.w3.org/2000/svg" width="0" height="0">{RECT}</svg>',
    "negative-size": f'<svg xmlns="http://www.w3.org/2000/svg" width="-50" height="-100">{RECT}</svg>',
    "hidden-root": f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 200" display="none">{RECT}</svg>',
    "zero-width-viewBox": f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 0 200" width="200" height="200">{RECT}</svg>',
    "zero-viewBox-alone": f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 0">{RECT}</svg>',
}


@pytest.mark.parametrize("name", sorted(DRAWINGS))
def test_a_drawing_of_nothing_is_its_background(name: str, tmp_path: Path) -> None:
    svg = tmp_path / f"{name}.svg"
    svg.write_text(DRAWINGS[name])
    scene = tr.load_scene(svg)
    assert scene.shapes == ()
    picture = tr.frame(scene, 0.0, size=(64, 64), background="#336699")
    assert (picture[..., :3] == (0x33, 0x66, 0x99)).all()


@pytest.mark.parametrize("box", ["0 0 -200 200", "0 0 200 -1", "0 0 200", "a b c d", "0 0 1e400 200"])
def test_a_viewBox_in_error_is_ignored_as_browsers_do(box: str, tmp_path: Path) -> None:
    """A negative size or an unreadable list invalidates ``viewBox`` (SVG 1.1 §7.7): the drawing is laid out by its
    ``width`` and ``height`` alone, so the rect covers the same pixels as without the attribute."""
    plain = tmp_path / "plain.svg"
    plain.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">{RECT}</svg>')
    broken = tmp_path / "broken.svg"
    broken.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{box}" width="200" height="200">{RECT}</svg>')
    expected = tr.frame(tr.load_scene(plain), 0.0, size=(50, 50))
    picture = tr.frame(tr.load_scene(broken), 0.0, size=(50, 50))
    assert np.array_equal(picture, expected)
    assert (expected[25, 25, :3] == (0, 128, 0)).all()


def test_an_unreadable_width_does_not_hide_the_drawing(tmp_path: Path) -> None:
    svg = tmp_path / "auto.svg"
    svg.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" width="auto" height="200" viewBox="0 0 200 200">'
                   f'{RECT}</svg>')
    assert len(tr.load_scene(svg).shapes) == 1


def test_the_command_line_renders_a_drawing_of_nothing(cli, tmp_path: Path) -> None:
    svg = tmp_path / "empty.svg"
    svg.write_text(DRAWINGS["no-children"])
    out = tmp_path / "empty.gif"
    code, _, err = cli("render", svg, svg, "-o", out, "-q")
    assert code == 0 and err == "", err
    frames = iio.imread(out, index=None)
    assert len(frames) >= 1 and np.all(frames[..., :3] == 255)
