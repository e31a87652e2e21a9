"""Gradient fills and clip paths in the vector outputs, as independent players draw them, match the
project's own frames (coverage IoU ≥ 0.98, colour error ≤ 0.03 at every frame checked).

rlottie draws every frame of the Lottie file, ThorVG the sample frames (ten evenly and both sides of
every key), headless Chromium the animated SVG at t = 0, ¼, ½, ¾, 1. The cases: real emoji drawn
with layered linear and radial gradients (elliptical, turned, with transparent stops), morphing into
each other and into a plain fill; a drawing whose linear gradient changes its stop count and
direction, and whose elliptical radial gradient turns, stretches and moves its focus, under a stroke;
a gradient fading to transparent black (stops are blended straight, as the video does, not
premultiplied, as rlottie does);
an element clipped by a moving clip path, clip paths of several contours (one with a hole) under a
group's clip path; linear gradients that repeat and reflect (SVG only: Lottie gradients pad).

Each case is loaded and drawn by the project once for all its players (the ``clip`` fixture), and one
Chromium draws every animated SVG.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

import tweenrender as tr
from tests.helpers import DATA
from tests.vector_players import Clip, PlayerBrowser, lottie_web_missing, module_browser, skottie_missing

EMOJI = [("fluent-emoji/red-circle.svg", "fluent-emoji/egg.svg"),
         ("fluent-emoji/chestnut.svg", "fluent-emoji/drop-of-blood.svg"),
         ("fluent-emoji/egg.svg", "bootstrap/heart-fill.svg")]  # gradients into a plain fill

_HEAD = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 40 20">'
GRADIENTS = (
    _HEAD + """<defs>
<linearGradient id="lin" x1="0" y1="0" x2="1" y2="0.3"><stop offset="0" stop-color="#e74c3c"/>
<stop offset="1" stop-color="#2980b9"/></linearGradient>
<radialGradient id="rad" cx="0" cy="0" r="1" fx="0.4" fy="0.3" gradientUnits="userSpaceOnUse"
gradientTransform="translate(28 10) rotate(-25) scale(10 5)"><stop offset="0.1" stop-color="#f1c40f"/>
<stop offset="0.6" stop-color="#27ae60" stop-opacity="0.8"/><stop offset="1" stop-color="#1b2631"/></radialGradient>
</defs><rect id="bar" x="1" y="2" width="16" height="16" fill="url(#lin)"/>
<ellipse id="blob" cx="28" cy="10" rx="11" ry="8" fill="url(#rad)" stroke="#2c3e50" stroke-width="0.3"/></svg>""",
    _HEAD + """<defs>
<linearGradient id="lin" x1="0" y1="1" x2="0.2" y2="0"><stop offset="0" stop-color="#16a085"/>
<stop offset="0.5" stop-color="#f39c12"/><stop offset="1" stop-color="#c0392b"/></linearGradient>
<radialGradient id="rad" cx="0" cy="0" r="1" fx="-0.3" fy="0" gradientUnits="userSpaceOnUse"
gradientTransform="translate(12 10) rotate(40) scale(11 4)"><stop offset="0" stop-color="#ecf0f1"/>
<stop offset="1" stop-color="#8e44ad"/></radialGradient></defs>
<rect id="bar" x="24" y="1" width="15" height="18" fill="url(#lin)"/>
<ellipse id="blob" cx="12" cy="10" rx="11" ry="9" fill="url(#rad)" stroke="#2c3e50" stroke-width="0.6"/></svg>""")
FADE = tuple(_HEAD + f"""<defs><linearGradient id="fade" x2="{x}" y2="{y}"><stop offset="0" stop-color="#f1c40f"/>
<stop offset="1" stop-color="#000000" stop-opacity="0"/></linearGradient></defs>
<rect id="fade" x="{left}" y="2" width="24" height="16" fill="url(#fade)"/></svg>""" for x, y, left in ((0, 1, 2), (1, 0.4, 14)))
CLIPS = (
    _HEAD + """<defs><clipPath id="two"><circle cx="8" cy="10" r="4"/><rect x="12" y="4" width="6" height="12"/>
</clipPath><clipPath id="hole"><path d="M22 2 H38 V18 H22 Z M26 6 V14 H34 V6 Z"/></clipPath>
<clipPath id="g"><rect x="0" y="0" width="20" height="12"/></clipPath>
<clipPath id="c"><circle cx="30" cy="16" r="3"/></clipPath></defs>
<g clip-path="url(#g)"><rect id="pair" x="3" y="3" width="16" height="14" fill="#2980b9" stroke="#1b2631"
stroke-width="1" clip-path="url(#two)"/></g>
<rect id="ring" x="23" y="3" width="14" height="14" fill="#c0392b" clip-path="url(#hole)"/>
<rect id="clipped" x="26" y="12" width="8" height="8" fill="#f1c40f" clip-path="url(#c)"/></svg>""",
    _HEAD + """<defs><clipPath id="two"><circle cx="10" cy="9" r="5"/><rect x="14" y="2" width="4" height="14"/>
</clipPath><clipPath id="hole"><path d="M21 1 H39 V19 H21 Z M27 5 V13 H35 V5 Z"/></clipPath>
<clipPath id="g"><rect x="2" y="2" width="20" height="16"/></clipPath>
<clipPath id="c"><rect x="9" y="15" width="8" height="4" transform="rotate(20 13 17)"/></clipPath></defs>
<g clip-path="url(#g)"><rect id="pair" x="4" y="1" width="16" height="16" fill="#27ae60" stroke="#1b2631"
stroke-width="1" clip-path="url(#two)"/></g>
<rect id="ring" x="22" y="2" width="16" height="16" fill="#8e44ad" clip-path="url(#hole)"/>
<rect id="clipped" x="8" y="13" width="10" height="7" fill="#d35400" clip-path="url(#c)"/></svg>""")


DRAWN = {"gradients": GRADIENTS, "fade": FADE, "clips": CLIPS}


def _emoji(a: str, b: str) -> tr.Scene:
    return tr.load_scene([DATA / "icons" / a, DATA / "icons" / b])


def _drawings(folder: Path, name: str, texts: tuple[str, ...]) -> tr.Scene:
    paths = []
    for index, text in enumerate(texts):
        path = folder / f"{name}-{index}.svg"
        path.write_text(text)
        paths.append(path)
    return tr.load_scene(paths)


SPREAD = tuple(text.replace('<linearGradient id="lin"', f'<linearGradient id="lin" spreadMethod="{method}"')
               .replace('x2="1" y2="0.3"', 'x2="0.3" y2="0.1"').replace('x2="0.2" y2="0"', 'x2="0.05" y2="0.6"')
               for text, method in zip(GRADIENTS, ("repeat", "reflect")))
EMOJI_CASES = {Path(a).stem + "-" + Path(b).stem: (a, b) for a, b in EMOJI}
CASES: dict[str, Callable[[Path], tr.Scene]] = {
    **{name: (lambda folder, pair=pair: _emoji(*pair)) for name, pair in EMOJI_CASES.items()},
    **{name: (lambda folder, name=name, texts=texts: _drawings(folder, name, texts)) for name, texts in DRAWN.items()},
    "spread": lambda folder: _drawings(folder, "spread", SPREAD),
}
"""Every case the players draw, by name: how to make its scene, given a folder to write into."""


@pytest.fixture(scope="module")
def clip(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Clip:
    """The case named by the test's parameter, drawn by the project once for every test of that case."""
    folder = tmp_path_factory.mktemp(request.param)
    return Clip(CASES[request.param](folder), folder, name=request.param)


@pytest.fixture(scope="module")
def browser() -> Iterator[PlayerBrowser | None]:
    """One headless Chromium for every animated SVG of the module (None: no chromium here)."""
    yield from module_browser()


@pytest.fixture
def _players() -> None:
    pytest.importorskip("rlottie_python", reason="rlottie-python (the test extra) is not installed")
    pytest.importorskip("thorvg_python", reason="thorvg-python (the test extra) is not installed")


def _in_rlottie_and_thorvg(clip: Clip) -> None:
    from tests.lottie_schema import check_folder

    clip.check_rlottie_thorvg()
    assert check_folder(clip.folder) == 1


@pytest.mark.usefixtures("_players")
@pytest.mark.parametrize("clip", list(EMOJI_CASES), indirect=True)
def test_emoji_gradients_in_rlottie_and_thorvg(clip: Clip) -> None:
    _in_rlottie_and_thorvg(clip)


@pytest.mark.usefixtures("_players")
@pytest.mark.parametrize("clip", list(DRAWN), indirect=True)
def test_drawn_gradients_and_clips_in_rlottie_and_thorvg(clip: Clip) -> None:
    _in_rlottie_and_thorvg(clip)


@pytest.mark.parametrize("clip", list(EMOJI_CASES), indirect=True)
def test_emoji_gradients_in_skottie_every_frame(clip: Clip) -> None:
    """Elliptical gradients drawn through a matte of the element's paths, as Skottie plays them."""
    reason = skottie_missing()
    if reason is not None:
        pytest.skip(reason)
    clip.check_skottie()


@pytest.mark.parametrize("clip", list(EMOJI_CASES), indirect=True)
def test_emoji_gradients_in_lottie_web_every_frame(clip: Clip, browser: PlayerBrowser | None) -> None:
    reason = lottie_web_missing()
    if reason is not None:
        pytest.skip(reason)
    assert browser is not None
    clip.check_lottie_web(browser=browser)


@pytest.mark.parametrize("clip", [*EMOJI_CASES, *DRAWN, "spread"], indirect=True)
def test_gradients_and_clips_in_chromium_at_five_times(clip: Clip, browser: PlayerBrowser | None) -> None:
    if browser is None:
        pytest.skip("no chromium on this machine to play the animated SVG")
    clip.check_chromium(browser)
