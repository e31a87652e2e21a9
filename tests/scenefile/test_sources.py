"""``Scene.sources``: every file a scene was read from (what the preview watches)."""

from __future__ import annotations

from pathlib import Path

from tweenrender.scenefile import load_scene

SVG = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><path id="p" d="M1 1 H9 V9 H1 Z"/></svg>'


def test_a_scene_lists_itself_its_svg_keys_and_drawings_once_each(tmp_path: Path) -> None:
    (tmp_path / "art").mkdir()
    for name in ("a", "b", "c"):
        (tmp_path / "art" / f"{name}.svg").write_text(SVG)
    scene = tmp_path / "scene.toml"
    scene.write_text('[[drawing]]\ntime = 0\nsvg = "art/a.svg"\n[[drawing]]\ntime = 1\nsvg = "art/b.svg"\n'
                     '[[shape]]\nname = "s"\n'
                     '[[shape.key]]\ntime = 0\npoints = { svg = "art/c.svg", id = "p" }\n'
                     '[[shape.key]]\ntime = 1\npoints = { svg = "art/c.svg", id = "p" }\n')
    sources = load_scene(scene).sources
    assert sources[0] == scene
    assert len(sources) == 4
    assert {p.resolve() for p in sources} == {scene.resolve(), *(tmp_path / "art" / f"{n}.svg" for n in "abc")}


def test_drawings_given_as_a_list_are_their_own_sources(tmp_path: Path) -> None:
    files = [tmp_path / "a.svg", tmp_path / "b.svg"]
    for file in files:
        file.write_text(SVG)
    assert list(load_scene(files).sources) == files


def test_a_plain_scene_lists_only_itself(tmp_path: Path) -> None:
    scene = tmp_path / "s.toml"
    scene.write_text('[[shape]]\nname = "s"\n[[shape.key]]\ntime = 0\npoints = [[0, 0], [1, 0], [0, 1]]\n')
    assert load_scene(scene).sources == (scene,)
