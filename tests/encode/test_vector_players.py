"""The vector outputs as independent players draw them match the project's own frames.

Lottie JSON is drawn by rlottie and by ThorVG (pip wheels with the players inside) — every frame of
the icon pairs and the paint scene, and for the shipped scenes (1280 × 720) ten frames evenly and
the frames on both sides of every key — by Skottie (npm ``canvaskit-wasm`` run by node, where
``.ci/run`` installed it; every frame of the icon pairs, the sample of the shipped scenes) and by
lottie-web (npm ``lottie-web``, its SVG renderer in headless Chromium; every frame of the icon pairs and
the paint and timed scenes, the sample of the shipped scenes), the animated
SVG by headless Chromium paused at t = 0, ¼, ½, ¾, 1 of the clip (at frame times). Each picture
is compared with ``tr.frame`` at the same time: coverage IoU ≥ 0.98 and mean colour error ≤ 0.03
(DESIGN, "Measures used in acceptance"), for the shipped scenes, real icon pairs (holes, strokes,
several coloured elements, a paint order that switches), every method, a scene whose paint changes,
and drawings held between moves on a CSS easing with their elements staggered.
"""

from __future__ import annotations

from pathlib import Path

import pytest

import tweenrender as tr
from tweenrender.core.methods.registry import METHODS
from tests.helpers import DATA, SCENES, write_scene
from tests.vector_players import (check_chromium, check_lottie_players, check_lottie_web, check_skottie,
                                  lottie_web_missing, skottie_missing)

SHIPPED = sorted(SCENES.glob("*.toml"))
ICONS = DATA / "icons"
ICON_PAIRS = [("mdi/alpha-a.svg", "mdi/alpha-b.svg"),  # holes
              ("mdi/alpha-o.svg", "mdi/alpha-o-box.svg"),  # a hole in a hole
              ("feather/heart.svg", "feather/star.svg"),  # strokes
              ("feather/smile.svg", "feather/sun.svg"),  # open strokes, pieces that appear
              ("lucide/moon.svg", "lucide/sun.svg"),
              ("twemoji/1f600.svg", "twemoji/1f60e.svg"),  # several elements, their own colours
              ("heroicons/heart.svg", "heroicons/star.svg"),
              ("bootstrap/emoji-smile.svg", "bootstrap/sun-fill.svg"),
              ("tabler/letter-a.svg", "tabler/heart.svg"),
              ("twemoji/1f4c4.svg", "twemoji/1f69a.svg"),  # a page becomes a truck: the paint order switches
              ("heroicons/check-circle.svg", "octicons/sun-24.svg"),  # even-odd, pieces that appear
              ("simple-icons/github.svg", "lucide/apple.svg")]
PAINT = """size = [480, 270]
fps = 12
view = [0, 0, 16, 9]
method = "nonlinear"
[[shape]]
name = "changes"
fill = "#c0392b"
stroke = "#1d2b50"
stroke_width = 2
[[shape.key]]
time = 0
ease = "in-out"
contours = [[[2, 2], [7, 2], [7, 7], [2, 7]], [[3, 3], [3, 5], [5, 5], [5, 3]]]
[[shape.key]]
time = 1.5
fill = "#2e86de"
stroke = "#f39c12"
stroke_width = 9
opacity = 0.6
contours = [[[12, 1], [15, 5], [12, 8], [9, 5]], [[11.5, 4.5], [11.5, 5.5], [12.5, 5.5], [12.5, 4.5]]]
[[shape]]
name = "fills-in"
stroke = "#0b5345"
stroke_width = 4
[[shape.key]]
time = 0
fill = "#16a08500"
points = [[1, 8], [4, 8.5], [7, 7]]
[[shape.key]]
time = 1.5
fill = "#16a085"
points = [[8, 1], [11, 0.5], [14, 2]]
[[shape]]
name = "open"
stroke = "#8e44ad"
stroke_width = 3
closed = false
[[shape.key]]
time = 0
points = [[1, 1], [3, 1.5], [5, 1]]
[[shape.key]]
time = 1.5
stroke = "#e67e22"
stroke_width = 6
points = [[10, 8], [12, 8.5], [14, 7]]
"""


def _icons(a: str, b: str) -> tr.Scene:
    return tr.load_scene([ICONS / a, ICONS / b])


def _paint_scene(tmp_path: Path) -> tr.Scene:
    return tr.load_scene(write_scene(tmp_path, PAINT))


@pytest.fixture(autouse=True)
def _players() -> None:
    pytest.importorskip("rlottie_python", reason="rlottie-python (the test extra) is not installed")
    pytest.importorskip("thorvg_python", reason="thorvg-python (the test extra) is not installed")


@pytest.mark.parametrize("scene_path", SHIPPED, ids=lambda p: p.stem)
def test_shipped_scenes_in_rlottie_and_thorvg(scene_path: Path, tmp_path: Path) -> None:
    check_lottie_players(tr.load_scene(scene_path), tmp_path, every_frame=False)


@pytest.mark.parametrize("pair", ICON_PAIRS, ids=lambda p: p[0].split("/")[0] + "-" + Path(p[0]).stem)
def test_icon_pairs_in_rlottie_and_thorvg(pair: tuple[str, str], tmp_path: Path) -> None:
    check_lottie_players(_icons(*pair), tmp_path)


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("pair", [ICON_PAIRS[0], ICON_PAIRS[2]], ids=["holes", "strokes"])
def test_every_method_in_rlottie_and_thorvg(method: str, pair: tuple[str, str], tmp_path: Path) -> None:
    check_lottie_players(_icons(*pair), tmp_path, method, every_frame=False)


def _skottie() -> None:
    reason = skottie_missing()
    if reason is not None:
        pytest.skip(reason)


@pytest.mark.parametrize("pair", ICON_PAIRS, ids=lambda p: p[0].split("/")[0] + "-" + Path(p[0]).stem)
def test_icon_pairs_in_skottie_every_frame(pair: tuple[str, str], tmp_path: Path) -> None:
    _skottie()
    check_skottie(_icons(*pair), tmp_path)


def test_shipped_scenes_and_curved_methods_in_skottie(tmp_path: Path) -> None:
    """The shipped scenes (1280 × 720) at the sample frames, the rest at every frame."""
    _skottie()
    for scene_path in SHIPPED:
        check_skottie(tr.load_scene(scene_path), tmp_path, every_frame=False)
    for method in ("nonlinear", "arap"):
        check_skottie(_icons(*ICON_PAIRS[0]), tmp_path, method)
    check_skottie(_timed(), tmp_path)
    check_skottie(_paint_scene(tmp_path), tmp_path)


def _lottie_web() -> None:
    reason = lottie_web_missing()
    if reason is not None:
        pytest.skip(reason)


@pytest.mark.parametrize("pair", ICON_PAIRS, ids=lambda p: p[0].split("/")[0] + "-" + Path(p[0]).stem)
def test_icon_pairs_in_lottie_web_every_frame(pair: tuple[str, str], tmp_path: Path) -> None:
    _lottie_web()
    check_lottie_web(_icons(*pair), tmp_path)


def test_shipped_scenes_and_curved_methods_in_lottie_web(tmp_path: Path) -> None:
    """The shipped scenes (1280 × 720) at the sample frames, the rest at every frame."""
    _lottie_web()
    for scene_path in SHIPPED:
        check_lottie_web(tr.load_scene(scene_path), tmp_path, every_frame=False)
    for method in ("nonlinear", "arap"):
        check_lottie_web(_icons(*ICON_PAIRS[0]), tmp_path, method)
    check_lottie_web(_timed(), tmp_path)
    check_lottie_web(_paint_scene(tmp_path), tmp_path)


def _timed() -> tr.Scene:
    """Three drawings, each held a quarter second, moving on CSS's ease-in-out, elements staggered."""
    faces = [ICONS / "twemoji/1f600.svg", ICONS / "twemoji/1f60e.svg", ICONS / "twemoji/1f600.svg"]
    return tr.load_scene(faces, step=1.0, ease="ease-in-out", hold=0.25, stagger=0.05)


def test_holds_css_easing_and_stagger_in_rlottie_and_thorvg(tmp_path: Path) -> None:
    check_lottie_players(_timed(), tmp_path)


def test_paint_changes_in_rlottie_and_thorvg(tmp_path: Path) -> None:
    check_lottie_players(_paint_scene(tmp_path), tmp_path)


def test_svg_in_chromium_at_five_times(tmp_path: Path) -> None:
    """Every shipped scene, the icon pairs, the paint scene and curved methods on icons, one browser."""
    from tests.browser import chromium

    if chromium() is None:
        pytest.skip("no chromium on this machine to play the animated SVG")
    cases: list[tuple[str, tr.Scene, str | None]] = [(p.stem, tr.load_scene(p), None) for p in SHIPPED]
    cases += [(a.replace("/", "-"), _icons(a, b), None) for a, b in ICON_PAIRS]
    cases += [("paint", _paint_scene(tmp_path), None), ("timed", _timed(), None)]
    cases += [(f"holes-{m}", _icons(*ICON_PAIRS[0]), m) for m in ("nonlinear", "arap", "intrinsic")]
    check_chromium(cases, tmp_path)
