"""Dashed strokes in the vector files, as independent players draw them: Lottie's stroke ``d`` in ThorVG,
Skottie and lottie-web, the animated SVG's ``stroke-dasharray`` in headless Chromium, each frame
within the acceptance measures of ``tr.frame``."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import tweenrender as tr
from tests.vector_players import (check_chromium, check_lottie_web, check_pictures, check_skottie,
                                  lottie_web_missing, sample_frames, skottie_missing, thorvg_frames)

HEAD = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 120" width="200" height="120">'


def _dashed(folder: Path) -> tr.Scene:
    """A dashed ring and a dashed open path morphing: the pattern's count, lengths and offset all change, and
    one key of the line is solid. (Each ring's first vertex is its rightmost point, so the files' contours
    start where the pattern does; see docs/artwork.md on the pattern's seam.)"""
    a = folder / "a.svg"
    a.write_text(HEAD + '<circle id="ring" cx="50" cy="60" r="35" fill="none" stroke="#c0392b" stroke-width="8" '
                 'stroke-dasharray="12 6" stroke-dashoffset="3"/>'
                 '<path id="line" d="M 110 20 L 190 40 L 120 100" fill="none" stroke="#1d2b50" stroke-width="6"/>'
                 "</svg>")
    b = folder / "b.svg"
    b.write_text(HEAD + '<ellipse id="ring" cx="55" cy="60" rx="40" ry="25" fill="none" stroke="#2e86de" '
                 'stroke-width="6" stroke-dasharray="20 5 4 5" stroke-dashoffset="-10"/>'
                 '<path id="line" d="M 110 100 L 150 20 L 190 100" fill="none" stroke="#1d2b50" stroke-width="6" '
                 'stroke-dasharray="16 8"/></svg>')
    return tr.load_scene([a, b])


def test_a_dashed_stroke_is_lottie_d_and_svg_dasharray(tmp_path: Path) -> None:
    scene = _dashed(tmp_path)
    lottie = json.loads(tr.write(scene, tmp_path / "clip.json").read_text())
    strokes = [item for layer in lottie["layers"] for group in layer.get("shapes", [])
               for item in group.get("it", []) if item.get("ty") == "st"]
    kinds = [[d["n"] for d in s["d"]] for s in strokes if "d" in s]
    assert ["d", "g", "d", "g", "o"] in kinds and ["d", "g", "o"] in kinds
    svg = tr.write(scene, tmp_path / "clip.svg").read_text()
    assert 'attributeName="stroke-dasharray"' in svg and 'attributeName="stroke-dashoffset"' in svg


def test_dashes_in_thorvg(tmp_path: Path) -> None:
    """ThorVG at the sample frames. (rlottie is left out: it lays a closed contour's dashes from elsewhere
    than the other three players and Chromium, which agree with the project's frames.)"""
    pytest.importorskip("thorvg_python", reason="thorvg-python (the test extra) is not installed")
    from tweenrender.plan.job import total_frames

    scene = _dashed(tmp_path)
    target = tr.write(scene, tmp_path / "clip.json")
    frames = sample_frames(scene, total_frames(scene))
    check_pictures(scene, thorvg_frames(target, frames, scene.size), frames, None, "ThorVG")


def test_dashes_in_skottie(tmp_path: Path) -> None:
    reason = skottie_missing()
    if reason:
        pytest.skip(reason)
    check_skottie(_dashed(tmp_path), tmp_path)


def test_dashes_in_lottie_web(tmp_path: Path) -> None:
    reason = lottie_web_missing()
    if reason:
        pytest.skip(reason)
    check_lottie_web(_dashed(tmp_path), tmp_path)


def test_dashes_in_the_animated_svg_in_chromium(tmp_path: Path) -> None:
    from tests.browser import chromium

    if chromium() is None:
        pytest.skip("no chromium on this machine to play the animated SVG")
    check_chromium([("dashed", _dashed(tmp_path), None)], tmp_path)


def test_patterns_too_many_lengths_in_common_are_refused_in_one_line(tmp_path: Path) -> None:
    from tests.helpers import run_module

    def drawing(name: str, count: int) -> Path:
        lengths = " ".join(str(3 + k % 5) for k in range(count))  # an odd count: read twice over
        svg = tmp_path / f"{name}.svg"
        svg.write_text(HEAD + f'<path id="p" d="M 20 60 H 180" stroke="black" stroke-width="4" '
                       f'stroke-dasharray="{lengths}"/></svg>')
        return svg

    a, b = drawing("a", 17), drawing("b", 19)  # 34 and 38 lengths: 646 in common
    scene = tr.load_scene([a, b])
    assert tr.frame(scene, 0.5 * scene.duration).shape[:2] == (scene.size[1], scene.size[0])  # drawn
    done = run_module("render", a, b, "-o", tmp_path / "out.json")
    assert done.returncode == 2 and not (tmp_path / "out.json").exists()
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and "'p'" in lines[0] and "646" in lines[0], done.stderr
