"""Compact curved vector output, by counted facts: a contour that moves straight between two keys exports as
exactly those two keyframes (timed by the keys' own easing) with far fewer cubics than its polyline's
vertices, and the replayed paths stay within the bound at every frame, measured independently (each Lottie path
drawn from the cubic's closed form and compared with ``tr.outlines`` by shapely, tests/vector_curves.py)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import tweenrender as tr
from tweenrender.core.view import Viewport
from tweenrender.pipeline.library import render_job
from tweenrender.plan.job import scene_view, tracks_of
from tweenrender.plan.options import RenderOptions
from tests.helpers import DATA
from tests.vector_curves import lottie_error

CIRCLE = ('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100"><path id="disc" fill="#3060c0" '
          'd="M{x0} {y} C{x0} {a} {b} {t} {cx} {t} C{c} {t} {x1} {a} {x1} {y} C{x1} {d} {c} {bt} {cx} {bt} '
          'C{b} {bt} {x0} {d} {x0} {y} Z"/></svg>')


def _circle(path: Path, cx: float, cy: float, r: float) -> Path:
    """An SVG disc drawn as four cubics (the usual 0.5523 handles)."""
    k = 0.5523 * r
    path.write_text(CIRCLE.format(x0=cx - r, x1=cx + r, y=cy, a=cy - k, d=cy + k, b=cx - k, c=cx + k, cx=cx,
                                  t=cy - r, bt=cy + r))
    return path


def _paths(document: dict) -> list[dict]:
    return [item for layer in document["layers"] if layer["nm"] != "background" for group in layer["shapes"]
            for item in group.get("it", []) if item["ty"] == "sh"]


def _worst(scene: tr.Scene, document: dict, method: str | None) -> float:
    """The largest distance, over every frame and contour, of the Lottie's paths from ``tr.outlines`` in pixels."""
    options = RenderOptions.create(method=method) if method else RenderOptions.create()
    job = render_job(scene, options)
    viewport = Viewport(scene_view(scene, tracks_of(scene), job.methods), *job.panel_size)
    worst = 0.0
    paths = _paths(document)
    for frame in range(document["op"]):
        named = {"method": method} if method else {}
        exact = tr.outlines(scene, frame / document["fr"], **named)
        for path, contour in zip(paths, exact):
            pixels = viewport.to_pixels(contour)
            worst = max(worst, lottie_error(path["ks"], frame, pixels), lottie_error(path["ks"], frame, pixels[::-1]))
    return worst


@pytest.mark.parametrize("ease", ["linear", "cubic-bezier(0.42, 0, 0.58, 1)"])
def test_a_linear_morph_of_two_cubic_circles_is_two_keyframes(tmp_path: Path, ease: str) -> None:
    a, b = _circle(tmp_path / "a.svg", 40, 50, 30), _circle(tmp_path / "b.svg", 60, 55, 30)  # one vertex count
    scene = tr.load_scene([a, b], ease=ease) if ease != "linear" else tr.load_scene([a, b])
    document = json.loads(tr.write(scene, tmp_path / "disc.json", method="linear").read_text())
    (path,) = _paths(document)
    keys = path["ks"]["k"]
    assert [k["t"] for k in keys] == [0, document["op"] - 1]  # exactly the two keys
    cubics = len(keys[0]["s"][0]["v"])
    assert cubics == len(keys[1]["s"][0]["v"])
    drawn = tr.outlines(scene, 0.0, method="linear")[0]
    assert cubics <= len(drawn) // 4  # far fewer than the flattened circle's vertices
    handles = (keys[0]["o"]["x"][0], keys[0]["o"]["y"][0], keys[0]["i"]["x"][0], keys[0]["i"]["y"][0])
    assert handles == ((0.0, 0.0, 1.0, 1.0) if ease == "linear" else (0.42, 0.0, 0.58, 1.0))  # the keys' own easing
    assert _worst(scene, document, "linear") <= 0.25


def test_straight_paths_that_spread_copies_stay_two_keyframes(tmp_path: Path) -> None:
    """``auto``'s straight paths open a vertex's coincident copies out along its edges just after the key: the
    keys are still the only keyframes, and the bound holds at every frame."""
    icons = DATA / "icons" / "octicons"
    scene = tr.load_scene([icons / "moon-24.svg", icons / "star-24.svg"])
    document = json.loads(tr.write(scene, tmp_path / "moon.json").read_text())
    paths = _paths(document)
    assert paths and all(len(p["ks"]["k"]) == 2 for p in paths)
    assert _worst(scene, document, None) <= 0.25


def test_stroke_ends_of_a_key_that_strokes_nothing_start_no_layer(tmp_path: Path) -> None:
    """Two filled discs, the second key's element saying round caps and joins but drawing no stroke: the
    picture never changes its stroke ends, so the element is one layer (one path, two keyframes)."""
    a, b = _circle(tmp_path / "a.svg", 40, 50, 30), _circle(tmp_path / "b.svg", 60, 55, 30)
    b.write_text(b.read_text().replace('fill="#3060c0"', 'fill="#3060c0" stroke-linecap="round" '
                                                         'stroke-linejoin="round"'))
    scene = tr.load_scene([a, b])
    document = json.loads(tr.write(scene, tmp_path / "disc.json", method="linear").read_text())
    layers = [layer for layer in document["layers"] if layer["nm"] != "background"]
    assert len(layers) == 1
    (path,) = _paths(document)
    assert len(path["ks"]["k"]) == 2
