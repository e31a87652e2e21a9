"""The library API (``import tweenrender as tr``) against closed forms, decoded video and the CLI."""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tests.helpers import ROOT, SQUARE, decode, write_scene

# SQUARE: a 2 × 2 square from (0..2, 0..2) to (5..7, 1..3), turned 90°, in 2 s, view [-2, -2, 10, 7]
SCALE = min(320 / 12, 240 / 9)  # pixels per world unit in a 320 × 240 frame


@pytest.fixture
def scene(tmp_path: Path) -> tr.Scene:
    return tr.load_scene(write_scene(tmp_path, SQUARE))


def covered(img: np.ndarray) -> float:
    """Pixels covered by the blue square, counting antialiased edges by how blue they are."""
    red = img[..., 0].astype(float)
    return float(((255.0 - red) / (255.0 - 59.0)).clip(0, 1).sum())  # fill #3b6fd8 on white


def test_frame_is_a_fresh_rgba_array_of_the_asked_size(scene: tr.Scene) -> None:
    a = tr.frame(scene, 0.0, size=(64, 48))
    b = tr.frame(scene, 2.0, size=(64, 48))
    assert a.shape == (48, 64, 4) and a.dtype == np.uint8
    assert not np.shares_memory(a, b) and not np.array_equal(a, b)
    again = tr.frame(scene, 0.0, size=(64, 48))
    assert np.array_equal(a, again) and not np.shares_memory(a, again)
    a[:] = 0  # the caller owns it: changing it changes no later frame
    assert np.array_equal(tr.frame(scene, 0.0, size=(64, 48)), again)


@pytest.mark.parametrize("method, area", [("linear", 2.0), ("nonlinear", 4.0), ("rigid", 4.0)])
def test_mid_turn_area_is_the_closed_form(scene: tr.Scene, method: str, area: float) -> None:
    """At mid-turn linear shrinks the square by cos 45° a side (area 2), the others keep 4."""
    img = tr.frame(scene, 1.0, method=method)
    assert img.shape == (240, 320, 4)
    assert covered(img) == pytest.approx(area * SCALE**2, rel=0.01)


def test_background_option(scene: tr.Scene) -> None:
    img = tr.frame(scene, 0.0, size=(32, 24), background="#00000000")
    assert tuple(img[0, 0]) == (0, 0, 0, 0)
    img = tr.frame(scene, 0.0, size=(32, 24), background=(10, 20, 30, 255))
    assert tuple(img[0, 0]) == (10, 20, 30, 255)


def test_outlines_before_at_and_after_the_keys(scene: tr.Scene) -> None:
    first = [[0, 0], [2, 0], [2, 2], [0, 2]]
    last = [[7, 1], [7, 3], [5, 3], [5, 1]]
    for time, expected in ((-1.0, first), (0.0, first), (2.0, last), (9.0, last)):
        (outline,) = tr.outlines(scene, time)
        assert outline.tolist() == expected
    (mid,) = tr.outlines(scene, 1.0, method="rigid")
    assert mid.mean(axis=0) == pytest.approx([3.5, 1.5])  # the center moves straight
    sides = np.linalg.norm(np.roll(mid, -1, axis=0) - mid, axis=1)
    assert sides == pytest.approx([2.0] * 4)
    (mid,) = tr.outlines(scene, 1.0, method="linear")
    assert np.linalg.norm(mid[1] - mid[0]) == pytest.approx(2 * math.cos(math.pi / 4))
    mid[:] = 0  # a fresh array: the next call is unchanged
    assert tr.outlines(scene, 1.0, method="linear")[0][0].tolist() != [0.0, 0.0]


def test_frames_count_spacing_and_freshness(scene: tr.Scene) -> None:
    every = list(tr.frames(scene, size=(64, 48)))
    assert len(every) == round(2.0 * 24) + 1
    assert all(not np.shares_memory(every[0], f) for f in every[1:])
    assert np.array_equal(every[24], tr.frame(scene, 1.0, size=(64, 48)))
    assert len(list(tr.frames(scene, size=(16, 12), fps=10))) == 21
    # a last key between frames: its frame is the nearest one, round(2.04 · 24) = 49
    late = tr.load_scene(write_scene(scene.path.parent, SQUARE.replace("time = 2\n", "time = 2.04\n"), "late.toml"))
    times = list(tr.frames(late, size=(16, 12)))
    assert len(times) == 50


def test_write_gives_what_the_cli_gives(scene: tr.Scene, tmp_path: Path, cli) -> None:
    library = tr.write(scene, tmp_path / "lib.mp4", compare=["linear", "nonlinear"])
    assert library == tmp_path / "lib.mp4"
    code, out, err = cli("render", scene.path, "--compare", "linear,nonlinear", "-o", tmp_path / "cli.mp4", "-q")
    assert code == 0, err
    meta_a, frames_a = decode(library)
    meta_b, frames_b = decode(tmp_path / "cli.mp4")
    assert meta_a["size"] == meta_b["size"] == (640, 240) and len(frames_a) == len(frames_b) == 49
    assert max(np.abs(a.astype(int) - b.astype(int)).max() for a, b in zip(frames_a, frames_b)) <= 2


def test_write_png_frames_and_a_range(scene: tr.Scene, tmp_path: Path) -> None:
    folder = tr.write(scene, tmp_path / "frames", frames="10:13", size=(32, 24))
    assert sorted(p.name for p in folder.glob("*.png")) == ["frame_0000.png", "frame_0001.png", "frame_0002.png"]


@pytest.mark.parametrize("call, words", [
    (lambda s, d: tr.write(s, d / "x.avi"), "cannot tell the format from .avi"),
    (lambda s, d: tr.write(s, d / "x.mp4", format="mov3"), "unknown format 'mov3'"),
    (lambda s, d: tr.write(s, d / "x.mp4", method="linear", compare=True), "do not go together"),
    (lambda s, d: tr.write(s, d / "x.mp4", frames="40:30"), "no frames selected"),
    (lambda s, d: tr.write(s, s.path, format="mp4"), "is the scene file itself"),
    (lambda s, d: tr.frame(s, float("nan")), "finite"),
    (lambda s, d: tr.frame(s, 0.0, method="liner"), "did you mean 'linear'"),
    (lambda s, d: tr.frame(s, 0.0, size=(0, 10)), "size"),
    (lambda s, d: tr.frame(s, 0.0, background="blue-ish"), "background"),
    (lambda s, d: tr.load_scene(d / "none.toml"), "no such file"),
])
def test_every_refusal_is_a_tweenrender_error(scene: tr.Scene, tmp_path: Path, call, words: str) -> None:
    before = sorted(os.listdir(tmp_path))
    with pytest.raises(tr.TweenrenderError, match=words.replace("(", r"\(").replace(".", r"\.")):
        call(scene, tmp_path)
    assert sorted(os.listdir(tmp_path)) == before


def test_a_library_refusal_is_the_line_the_cli_prints(scene: tr.Scene, tmp_path: Path, cli) -> None:
    with pytest.raises(tr.TweenrenderError) as caught:
        tr.write(scene, tmp_path / "x.avi")
    code, _, err = cli("render", scene.path, "-o", tmp_path / "x.avi")
    assert code == caught.value.exit_code == 2
    assert err == f"tweenrender: error: {caught.value}\n"


def test_the_readme_example_runs_as_written(tmp_path: Path) -> None:
    text = (ROOT / "README.md").read_text()
    start = text.index("## From Python")
    block = text[text.index("```python\n", start) + len("```python\n"):]
    code = block[:block.index("```")]
    (tmp_path / "scenes").symlink_to(ROOT / "scenes")
    (tmp_path / "tests").symlink_to(ROOT / "tests")
    done = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert lines[0] == "(360, 640, 4) uint8"
    assert lines[-1] == "no-such-scene.toml: no such file"
    assert (tmp_path / "output" / "square.mp4").stat().st_size > 0
    meta, frames = decode(tmp_path / "output" / "square.mp4")
    assert len(frames) == 49 and meta["size"] == (2560, 720)
    assert lines[-3] == "output/apple-pear.webm" and (tmp_path / "output" / "apple-pear.webm").stat().st_size > 0
    assert lines[-2] == "output/apple-pear.json"
    # two drawings 1 s apart, each held 0.25 s: 1.5 s at 24 fps, 37 frames in the Lottie file as in the video
    assert json.loads((tmp_path / "output" / "apple-pear.json").read_text())["op"] == 37
