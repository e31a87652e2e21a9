"""Never write over an input: every command compares what it writes (the file, the frames or report folder
and what goes in it) with every file it reads (the scene, its SVG keys and drawings), through links.

A clash is one line naming both, exit 2, before any work, and every byte of the folder is as it was.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from tests.helpers import SQUARE, run_main

SVG = ('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">'
       '<path id="p" d="M1 1 L{x} 1 L{x} 9 Z"/></svg>')
KEYED = """size = [64, 48]
[[shape]]
name = "s"
[[shape.key]]
time = 0
points = { svg = "key.svg", id = "p" }
[[shape.key]]
time = 0.5
points = [[1, -1], [8, -1], [8, -9]]
"""
DRAWN = 'size = [64, 48]\n[[drawing]]\ntime = 0\nsvg = "d0.svg"\n[[drawing]]\ntime = 0.5\nsvg = "d1.svg"\n'
SMALL = SQUARE.replace("size = [320, 240]", "size = [64, 48]").replace("time = 2\n", "time = 0.5\n")


def _tree(folder: Path) -> dict[str, bytes | None]:
    return {str(p.relative_to(folder)): (p.read_bytes() if p.is_file() else None) for p in sorted(folder.rglob("*"))}


def _folder(tmp_path: Path) -> Path:
    for name, x in (("a.svg", 9), ("b.svg", 7), ("key.svg", 8), ("d0.svg", 9), ("d1.svg", 6)):
        (tmp_path / name).write_text(SVG.format(x=x))
    (tmp_path / "keyed.toml").write_text(KEYED)
    (tmp_path / "drawn.toml").write_text(DRAWN)
    for name in ("s.png", "s.mp4", "scene.toml"):
        (tmp_path / name).write_text(SMALL)  # a scene file whatever its name
    return tmp_path


def _refused(tmp_path: Path, *args: str, names: tuple[str, ...]) -> None:
    before = _tree(tmp_path)
    done = run_main(*args, cwd=tmp_path)
    assert done.returncode == 2, (args, done.stderr)
    assert done.stderr.startswith("tweenrender: error: ") and done.stderr.count("\n") == 1, done.stderr
    assert "unexpected" not in done.stderr
    for name in names:
        assert name in done.stderr, (name, done.stderr)
    assert _tree(tmp_path) == before


@pytest.mark.parametrize("fmt", ["mp4", "webm", "mov", "gif", "png"])
def test_render_does_not_write_over_a_drawing_it_reads(tmp_path: Path, fmt: str) -> None:
    _folder(tmp_path)
    _refused(tmp_path, "render", "a.svg", "b.svg", "-o", "b.svg", "--format", fmt, "-q", names=("b.svg",))


@pytest.mark.parametrize("fmt", ["mp4", "gif"])
@pytest.mark.parametrize("scene, svg", [("keyed.toml", "key.svg"), ("drawn.toml", "d1.svg")])
def test_render_does_not_write_over_a_scenes_svg(tmp_path: Path, fmt: str, scene: str, svg: str) -> None:
    _folder(tmp_path)
    _refused(tmp_path, "render", scene, "-o", svg, "--format", fmt, "-q", names=(svg,))


@pytest.mark.parametrize("args, names", [
    (("sheet", "s.png", "-o", "s.png"), ("s.png",)),
    (("correspond", "s.png", "-o", "s.png"), ("s.png",)),
    (("qcurves", "s.png", "-o", "s.png"), ("s.png",)),
    (("reel", "s.mp4", "-o", "s.mp4", "-q"), ("s.mp4",)),
    (("reel", "scene.toml", "s.mp4", "-o", "s.mp4", "-q"), ("s.mp4",)),
])
def test_pictures_and_reels_do_not_write_over_their_scene(tmp_path: Path, args: tuple[str, ...],
                                                          names: tuple[str, ...]) -> None:
    _folder(tmp_path)
    _refused(tmp_path, *args, names=names)


def test_a_link_to_an_input_is_refused_as_the_input(tmp_path: Path) -> None:
    _folder(tmp_path)
    (tmp_path / "soft.gif").symlink_to(tmp_path / "b.svg")
    os.link(tmp_path / "b.svg", tmp_path / "hard.gif")
    _refused(tmp_path, "render", "a.svg", "b.svg", "-o", "soft.gif", "-q", names=("soft.gif", "b.svg"))
    _refused(tmp_path, "render", "a.svg", "b.svg", "-o", "hard.gif", "-q", names=("hard.gif", "b.svg"))


def test_a_frames_folder_that_holds_the_scene_is_refused_naming_it(tmp_path: Path) -> None:
    (tmp_path / "frames").mkdir()
    (tmp_path / "frames" / "scene.toml").write_text(SMALL)
    _refused(tmp_path, "render", "frames/scene.toml", "-o", "frames", "-q", names=("frames", "scene.toml"))


def test_a_report_folder_that_holds_the_scene_is_refused_naming_it(tmp_path: Path) -> None:
    (tmp_path / "report").mkdir()
    (tmp_path / "report" / "scene.toml").write_text(SMALL)
    _refused(tmp_path, "report", "report/scene.toml", "--compare", "linear", "-o", "report", "-q",
             names=("report", "scene.toml"))


def test_a_report_folder_whose_index_is_a_link_to_the_scene_is_refused(tmp_path: Path) -> None:
    (tmp_path / "scene.toml").write_text(SMALL)
    (tmp_path / "report").mkdir()
    (tmp_path / "report" / "index.html").symlink_to(tmp_path / "scene.toml")
    _refused(tmp_path, "report", "scene.toml", "--compare", "linear", "-o", "report", "-q", names=("scene.toml",))


def test_writing_next_to_an_input_is_fine(tmp_path: Path) -> None:
    _folder(tmp_path)
    done = run_main("render", "a.svg", "b.svg", "-o", "ab.gif", "-q", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "b.svg").read_text() == SVG.format(x=7)
