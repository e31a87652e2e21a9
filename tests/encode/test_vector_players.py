"""The vector outputs as independent players draw them match the project's own frames.

Lottie JSON is drawn by rlottie and by ThorVG (pip wheels with the players inside) — every frame of
the icon pairs and the paint scene, and for the shipped scenes (1280 × 720) ten frames evenly and
the frames on both sides of every key — the animated
SVG by headless Chromium paused at t = 0, ¼, ½, ¾, 1 of the clip (at frame times). Each picture
is compared with ``tr.frame`` at the same time: coverage IoU ≥ 0.98 and mean colour error ≤ 0.03
(DESIGN, "Measures used in acceptance"), for the shipped scenes, real icon pairs (holes, strokes,
several coloured elements), every method, and a scene whose paint changes.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tweenrender.core.methods import METHODS
from tweenrender.pipeline.job import total_frames
from tests.helpers import DATA, SCENES, write_scene
from tests.vector_players import chromium_svg_frames, measures, over

SIZE = None  # each scene's own size: the video's
IOU, COLOUR = 0.98, 0.03
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
              ("tabler/letter-a.svg", "tabler/heart.svg")]
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


def _background(scene: tr.Scene) -> tuple[int, int, int]:
    return scene.background[:3] if scene.background[3] == 255 else (255, 255, 255)


def _check(scene: tr.Scene, pictures: list[np.ndarray], frames: list[int], method: str | None, fps: float,
           player: str) -> None:
    background = _background(scene)
    for frame, picture in zip(frames, pictures):
        ours = over(tr.frame(scene, frame / fps, method=method, size=SIZE), background)
        theirs = over(picture, background) if picture.shape[-1] == 4 else picture
        iou, error = measures(ours, theirs, background)
        assert iou >= IOU and error <= COLOUR, f"{player}, frame {frame}: IoU {iou:.4f}, colour error {error:.4f}"


def _lottie_players(scene: tr.Scene, tmp_path: Path, method: str | None = None, every_frame: bool = True) -> None:
    from tests.vector_players import rlottie_frames, thorvg_frames

    target = tr.write(scene, tmp_path / "clip.json", method=method, size=SIZE)
    size = SIZE or scene.size
    count = total_frames(scene)
    sample = _sample(scene, count)
    rlottie_picked = list(range(count)) if every_frame else sample
    _check(scene, rlottie_frames(target, rlottie_picked, size), rlottie_picked, method, scene.fps, "rlottie")
    _check(scene, thorvg_frames(target, sample, size), sample, method, scene.fps, "ThorVG")


def _sample(scene: tr.Scene, count: int) -> list[int]:
    """Ten frames evenly from the first to the last, and the frames on both sides of every key
    (where the layers of consecutive segments hand over)."""
    keys = {round(key.time * scene.fps) for shape in scene.shapes for key in shape.keys}
    around = {f + d for f in keys for d in (-1, 0) if 0 <= f + d < count}
    return sorted({0, count - 1, *np.linspace(0, count - 1, 10).round().astype(int).tolist(), *around})


@pytest.fixture(autouse=True)
def _players() -> None:
    pytest.importorskip("rlottie_python", reason="rlottie-python (the test extra) is not installed")
    pytest.importorskip("thorvg_python", reason="thorvg-python (the test extra) is not installed")


@pytest.mark.parametrize("scene_path", SHIPPED, ids=lambda p: p.stem)
def test_shipped_scenes_in_rlottie_and_thorvg(scene_path: Path, tmp_path: Path) -> None:
    _lottie_players(tr.load_scene(scene_path), tmp_path, every_frame=False)


@pytest.mark.parametrize("pair", ICON_PAIRS, ids=lambda p: p[0].split("/")[0] + "-" + Path(p[0]).stem)
def test_icon_pairs_in_rlottie_and_thorvg(pair: tuple[str, str], tmp_path: Path) -> None:
    _lottie_players(_icons(*pair), tmp_path)


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("pair", [ICON_PAIRS[0], ICON_PAIRS[2]], ids=["holes", "strokes"])
def test_every_method_in_rlottie_and_thorvg(method: str, pair: tuple[str, str], tmp_path: Path) -> None:
    _lottie_players(_icons(*pair), tmp_path, method, every_frame=False)


def test_paint_changes_in_rlottie_and_thorvg(tmp_path: Path) -> None:
    _lottie_players(_paint_scene(tmp_path), tmp_path)


def test_svg_in_chromium_at_five_times(tmp_path: Path) -> None:
    """Every shipped scene, the icon pairs, the paint scene and curved methods on icons, one browser."""
    from tests.browser import chromium

    if chromium() is None:
        pytest.skip("no chromium on this machine to play the animated SVG")
    cases: list[tuple[str, tr.Scene, str | None]] = [(p.stem, tr.load_scene(p), None) for p in SHIPPED]
    cases += [(a.replace("/", "-"), _icons(a, b), None) for a, b in ICON_PAIRS]
    cases += [("paint", _paint_scene(tmp_path), None)]
    cases += [(f"holes-{m}", _icons(*ICON_PAIRS[0]), m) for m in ("nonlinear", "arap", "intrinsic")]
    files, picks = [], []
    for name, scene, method in cases:
        target = tr.write(scene, tmp_path / f"{name}.svg", method=method, size=SIZE)
        count = total_frames(scene)
        frames = sorted({round(q * (count - 1)) for q in (0, 0.25, 0.5, 0.75, 1)})
        files.append((target, [f / scene.fps for f in frames], SIZE or scene.size))
        picks.append(frames)
    shots = chromium_svg_frames(files)
    for (name, scene, method), frames, pictures in zip(cases, picks, shots):
        _check(scene, pictures, frames, method, scene.fps, f"Chromium, {name}")

