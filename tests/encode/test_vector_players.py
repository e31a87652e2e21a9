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

Each scene is loaded, written and drawn by the project once (the ``clip`` fixture, one scene at a time: the
tests of one scene run together), and one Chromium draws every picture the browser players take.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

import tweenrender as tr
from tests.helpers import DATA, SCENES, overlapping_squares, same_wound_rings, write_scene
from tests.vector_players import (
    Clip,
    PlayerBrowser,
    module_browser,
    lottie_web_missing,
    skottie_missing,
)
from tweenrender.core.methods.registry import METHODS

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
              ("simple-icons/github.svg", "lucide/apple.svg"),
              ("octicons/smiley-24.svg", "tabler/letter-a.svg"),  # black elements change places: one layer each
              ("octicons/heart-24.svg", "heroicons/check-circle.svg"),  # the fill rule switches inside a layer
              ("mdi/weather-night.svg", "bootstrap/sun-fill.svg")]  # windings change where contours lie apart
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


def _timed() -> tr.Scene:
    """Three drawings, each held a quarter second, moving on CSS's ease-in-out, elements staggered."""
    faces = [ICONS / "twemoji/1f600.svg", ICONS / "twemoji/1f60e.svg", ICONS / "twemoji/1f600.svg"]
    return tr.load_scene(faces, step=1.0, ease="ease-in-out", hold=0.25, stagger=0.05)


def _pair_name(pair: tuple[str, str]) -> str:
    return pair[0].split("/")[0] + "-" + Path(pair[0]).stem


SVG_PIECES = {"cut-moon-heart": ("tabler/moon.svg", "mdi/heart.svg"),  # a hole shrinking inside its outline: a mask
              "cut-alpha-python": ("mdi/alpha-b.svg", "simple-icons/python.svg"),  # the python's eyes growing
              "apart-sun-heart": ("heroicons/sun.svg", "mdi/heart.svg"),  # rays shrinking apart from the rest
              "cut-rule-switch": ("bootstrap/heart-fill.svg", "lucide/moon.svg"),  # a hole cut as the rule switches
              "move-check-apple": ("feather/check.svg", "simple-icons/apple.svg")}  # a leaf growing over the check
"""Pairs whose animated SVG draws its pieces as paths of their own and cuts holes with masks (Chromium plays them)."""

SceneMaker = Callable[[Path], tr.Scene]
CASES: dict[str, tuple[SceneMaker, str | None]] = {
    **{f"scene-{p.stem}": ((lambda folder, p=p: tr.load_scene(p)), None) for p in SHIPPED},
    **{f"pair-{_pair_name(pair)}": ((lambda folder, pair=pair: _icons(*pair)), None) for pair in ICON_PAIRS},
    **{f"{kind}-{method}": ((lambda folder, pair=pair: _icons(*pair)), method)
       for kind, pair in (("holes", ICON_PAIRS[0]), ("strokes", ICON_PAIRS[2])) for method in METHODS},
    **{f"svg-{name}": ((lambda folder, pair=pair: _icons(*pair)), None) for name, pair in SVG_PIECES.items()},
    "timed": ((lambda folder: _timed()), None),
    "paint": ((lambda folder: tr.load_scene(write_scene(folder, PAINT))), None),
    "rule-switch": ((lambda folder: tr.load_scene(overlapping_squares(folder))), None),
    "evenodd-ring": ((lambda folder: tr.load_scene(same_wound_rings(folder))), None),
}
"""Every scene the players draw, by name: how to make it (given a folder to write into) and the method."""
SCENE_CASES = [f"scene-{p.stem}" for p in SHIPPED]
PAIR_CASES = [f"pair-{_pair_name(pair)}" for pair in ICON_PAIRS] + ["rule-switch", "evenodd-ring"]
SKOTTIE_PAIR_CASES = [pytest.param(case, marks=pytest.mark.xfail(
    strict=True, reason="Skottie (canvaskit-wasm 0.39.1) fills even-odd as nonzero: two squares wound alike that "
    "overlap cannot be wound so that nonzero leaves their overlap empty")) if case == "rule-switch" else case
    for case in PAIR_CASES]
CURVED_TIMED_PAINT = ["holes-nonlinear", "holes-arap", "timed", "paint"]


def _ids(case: str) -> str:
    return case.split("-", 1)[1] if case.startswith(("scene-", "pair-")) else case


@pytest.fixture(scope="module")
def clip(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Clip:
    """The scene named by the test's parameter, written as Lottie (valid by the schema) and drawn by the project
    once for every test of that scene."""
    from tests.lottie_schema import check_folder

    make, method = CASES[request.param]
    folder = tmp_path_factory.mktemp(request.param)
    made = Clip(make(folder), folder, method)
    made.lottie  # noqa: B018 - written now, and checked against the schema
    assert check_folder(folder) == 1
    return made


@pytest.fixture(scope="module")
def browser() -> Iterator[PlayerBrowser | None]:
    """One headless Chromium for every picture of the module's browser players (None: no chromium here)."""
    yield from module_browser()


@pytest.fixture(autouse=True)
def _players() -> None:
    pytest.importorskip("rlottie_python", reason="rlottie-python (the test extra) is not installed")
    pytest.importorskip("thorvg_python", reason="thorvg-python (the test extra) is not installed")


def _cases(names: list[str]):  # type: ignore[no-untyped-def]
    return pytest.mark.parametrize("clip", names, ids=_ids, indirect=True)


@_cases(SCENE_CASES)
def test_shipped_scenes_in_rlottie_and_thorvg(clip: Clip) -> None:
    clip.check_rlottie_thorvg(every_frame=False)


@_cases(PAIR_CASES)
def test_icon_pairs_in_rlottie_and_thorvg(clip: Clip) -> None:
    clip.check_rlottie_thorvg()


@_cases([f"{kind}-{method}" for kind in ("holes", "strokes") for method in METHODS])
def test_every_method_in_rlottie_and_thorvg(clip: Clip) -> None:
    clip.check_rlottie_thorvg(every_frame=False)


@_cases(["timed"])
def test_holds_css_easing_and_stagger_in_rlottie_and_thorvg(clip: Clip) -> None:
    clip.check_rlottie_thorvg()


@_cases(["paint"])
def test_paint_changes_in_rlottie_and_thorvg(clip: Clip) -> None:
    clip.check_rlottie_thorvg()


def _skottie() -> None:
    reason = skottie_missing()
    if reason is not None:
        pytest.skip(reason)


@_cases(SKOTTIE_PAIR_CASES)
def test_icon_pairs_in_skottie_every_frame(clip: Clip) -> None:
    _skottie()
    clip.check_skottie()


@_cases(SCENE_CASES)
def test_shipped_scenes_in_skottie(clip: Clip) -> None:
    """The shipped scenes (1280 × 720) at the sample frames."""
    _skottie()
    clip.check_skottie(every_frame=False)


@_cases(CURVED_TIMED_PAINT)
def test_curved_methods_timing_and_paint_in_skottie_every_frame(clip: Clip) -> None:
    _skottie()
    clip.check_skottie()


def _lottie_web(browser: PlayerBrowser | None) -> PlayerBrowser:
    reason = lottie_web_missing()
    if reason is not None:
        pytest.skip(reason)
    assert browser is not None
    return browser


@_cases(PAIR_CASES)
def test_icon_pairs_in_lottie_web_every_frame(clip: Clip, browser: PlayerBrowser | None) -> None:
    clip.check_lottie_web(browser=_lottie_web(browser))


@_cases(SCENE_CASES)
def test_shipped_scenes_in_lottie_web(clip: Clip, browser: PlayerBrowser | None) -> None:
    """The shipped scenes (1280 × 720) at the sample frames."""
    clip.check_lottie_web(every_frame=False, browser=_lottie_web(browser))


@_cases(CURVED_TIMED_PAINT)
def test_curved_methods_timing_and_paint_in_lottie_web_every_frame(clip: Clip, browser: PlayerBrowser | None) -> None:
    clip.check_lottie_web(browser=_lottie_web(browser))


@_cases(SCENE_CASES + PAIR_CASES + ["paint", "timed", "holes-nonlinear", "holes-arap", "holes-intrinsic"]
        + [f"svg-{name}" for name in SVG_PIECES])
def test_svg_in_chromium_at_five_times(clip: Clip, browser: PlayerBrowser | None) -> None:
    """Every shipped scene, the icon pairs, the paint scene and curved methods on icons."""
    if browser is None:
        pytest.skip("no chromium on this machine to play the animated SVG")
    clip.check_chromium(browser)
