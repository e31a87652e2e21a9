"""SVG's error rules for whole drawings (SVG 1.1 F.2, SVG 2 §9.5.4 and §10): bad geometry data is drawn up to
its first error, and an element SVG does not render (a negative size, a <use> loop) is left out while
the rest of the drawing is drawn. Expected values are read off the specification's rules by hand."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tweenrender.scenefile.svg_pathdata import path_prefix, points_prefix


@pytest.mark.parametrize(("data", "expected"), [
    ("M 10 10 L 20 20 L 30", ("M 10 10 L 20 20", False)),
    ("M10-20L30,40", ("M 10 -20 L 30 40", True)),
    ("M 1 2 3 4 z", ("M 1 2 L 3 4 z", True)),
    ("m 1 2 3 4", ("m 1 2 l 3 4", True)),
    ("M 0 0 L 10 #80 10", ("M 0 0", False)),
    ("A 5 5 0 0 1 50 50", ("", False)),
    ("", ("", True)),
    ("M 100 100 a 25 25 0 1025 -25", ("M 100 100 a 25 25 0 1 0 25 -25", True)),  # flags need no separator
    ("M 100 100 a 25 25 0 -1 0 25 -25 z", ("M 100 100", False)),                   # a flag is 0 or 1
    ("M 0 0 L ,10 10", ("M 0 0", False)),
    ("M 0 0 L 1 1, 2 2", ("M 0 0 L 1 1 L 2 2", True)),
    ("M 0 0 Q 5 5 10 0 T 20 0 30 0", ("M 0 0 Q 5 5 10 0 T 20 0 T 30 0", True)),  # T takes one point
])
def test_path_data_is_read_up_to_its_first_error(data: str, expected: tuple[str, bool]) -> None:
    assert path_prefix(data) == expected


@pytest.mark.parametrize(("points", "expected"), [
    ("10,20 30,40 50", ("10,20 30,40", False)),
    ("10 20,30 40", ("10,20 30,40", True)),
    ("10,20 30,40 text 50,60", ("10,20 30,40", False)),
])
def test_points_are_read_in_whole_pairs_up_to_their_first_error(points: str, expected: tuple[str, bool]) -> None:
    assert points_prefix(points) == expected


def _picture(tmp_path: Path, body: str) -> np.ndarray:
    svg = tmp_path / "d.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" '
                   f'viewBox="0 0 100 100">{body}</svg>')
    return tr.frame(tr.load_scene(svg), 0.0, size=(100, 100), background="#ffffff")[..., :3]


RED, GREEN = [255, 0, 0], [0, 128, 0]


@pytest.mark.parametrize("bad", [
    '<path d="M 10 10 L 90 10 L 90 90 L 10 90 Z L 5" fill="#008000"/>',
    '<polygon points="10,10 90,10 90,90 10,90 5" fill="#008000"/>',
    '<polygon points="10,10 90,10 90,90 10,90 five" fill="#008000"/>',
])
def test_bad_data_draws_up_to_the_error(tmp_path: Path, bad: str) -> None:
    picture = _picture(tmp_path, bad)
    assert (picture[50, 50] == GREEN).all() and (picture[5, 5] == 255).all()


@pytest.mark.parametrize("hidden", [
    '<circle cx="50" cy="50" r="-40" fill="red"/>',
    '<rect x="10" y="10" width="-80" height="80" fill="red"/>',
    '<ellipse cx="50" cy="50" rx="-40" ry="-30" fill="red"/>',
    '<path d="L 10 10 L 90 90 L 10 90" fill="red"/>',
    '<path d="" fill="red"/>',
    ('<defs><g id="g1"><circle cx="50" cy="50" r="40" fill="red"/><use xlink:href="#g1"/></g></defs>'
     '<use xlink:href="#g1"/>'),
    '<use id="u" xlink:href="#u"/>',
    '<use xlink:href="#nowhere"/>',
])
def test_what_svg_does_not_render_is_left_out_and_the_rest_drawn(tmp_path: Path, hidden: str) -> None:
    picture = _picture(tmp_path, hidden + '<rect x="0" y="0" width="10" height="10" fill="#008000"/>')
    assert (picture[5, 5] == GREEN).all()
    assert not (picture == RED).all(axis=-1).any()


def test_a_negative_corner_radius_is_read_as_auto(tmp_path: Path) -> None:
    # SVG 2 §10.2: an invalid rx is auto, so it takes ry's value: both corners round by 20
    picture = _picture(tmp_path, '<rect x="10" y="10" width="80" height="80" rx="-20" ry="20" fill="#008000"/>')
    assert (picture[11, 11] == 255).all() and (picture[50, 50] == GREEN).all()


@pytest.mark.parametrize("radii", ['rx="30"', 'ry="30"', 'rx="30" ry="auto"', 'rx="-5" ry="30"'])
def test_an_ellipse_with_one_radius_takes_it_for_both(tmp_path: Path, radii: str) -> None:
    # SVG 2 §10.4: a missing, auto or invalid rx (ry) is the other radius: a circle of radius 30
    picture = _picture(tmp_path, f'<ellipse cx="50" cy="50" {radii} fill="#008000"/>')
    ink = (picture != 255).any(axis=-1)
    assert ink[50, 22] and ink[50, 77] and ink[22, 50] and ink[77, 50] and not ink[50, 18] and not ink[18, 50]


SKIPPING = ('<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 10 10">\n'
            '<path d="M 1 1 L 9 1 L 9 9 x 3"/>\n<rect width="-2" height="3"/>\n<use xlink:href="#nowhere"/>\n'
            '<circle cx="5" cy="5" r="2"/>\n'
            '<rect x="1" y="1" width="44mmx" height="2"/>\n</svg>\n')


def test_with_v_the_reader_says_in_one_line_what_it_skipped(tmp_path: Path) -> None:
    from tests.helpers import run_module

    bad = tmp_path / "bad.svg"
    bad.write_text(SKIPPING, encoding="utf-8")
    good = tmp_path / "good.svg"
    good.write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><rect width="4" height="4"/></svg>',
                    encoding="utf-8")
    said = run_module("-v", "render", bad, good, "-o", tmp_path / "frames", "--frames", "0:1")
    assert said.returncode == 0, said.stderr
    lines = said.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("tweenrender: warning: bad.svg: drew what is valid, skipped")
    for part in ("the d of <path> from its first error on (line 2)", "<rect> of negative width (line 3)",
                 "a <use> of '#nowhere', nothing (line 4)", "width='44mmx', which is not a length (line 6)"):
        assert part in lines[0], part
    quiet = run_module("render", bad, good, "-o", tmp_path / "frames2", "--frames", "0:1")
    assert quiet.returncode == 0 and quiet.stderr == ""
    clean = run_module("-v", "render", good, good, "-o", tmp_path / "frames3", "--frames", "0:1")
    assert clean.returncode == 0 and clean.stderr == ""


def test_the_library_says_nothing_of_what_it_skipped_unless_asked(tmp_path: Path) -> None:
    import subprocess
    import sys

    bad = tmp_path / "bad.svg"
    bad.write_text(SKIPPING, encoding="utf-8")
    done = subprocess.run([sys.executable, "-c", f"import tweenrender as tr; tr.load_scene([{str(bad)!r}] * 2)"],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0 and done.stderr == "", done.stderr
