"""The scene loader: the documented format, and errors that name file, place and expectation."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from tweenrender.errors import SceneError
from tweenrender.scenefile import load_scene, parse_scene
from tweenrender.scenefile.locate import line_of

from tests.helpers import SCENES, SQUARE

FULL = """title = "t"
size = [640, 360]
fps = 30
background = "#102030"
view = [-1, -1, 9, 5]
method = "rigid"
compare = ["linear", "rigid"]

[correspondence]
cost = "sg"
align = "none"
kb = 2.5

[[shape]]
name = "a"
fill = "#abc"
stroke = "#11223344"
stroke_width = 3.5
method = "linear"

[[shape.key]]
time = 0.5
points = [[0, 0], [2, 0], [2, 2], [0, 2]]
ease = "in-out"

[[shape.key]]
time = 2
points = [[6, 2], [6, 4], [4, 4], [4, 2]]

[[shape]]
name = "b"
[[shape.key]]
time = 0
points = [[0, 0], [1, 0], [0, 1]]
"""


def test_every_field_is_read(tmp_path: Path) -> None:
    path = tmp_path / "full.toml"
    path.write_text(FULL)
    scene = load_scene(path)
    assert scene.title == "t" and scene.size == (640, 360) and scene.fps == 30.0
    assert scene.background == (0x10, 0x20, 0x30, 255)
    assert scene.view == (-1, -1, 9, 5) and scene.method == "rigid" and scene.compare == ("linear", "rigid")
    assert scene.matching.cost == "sg" and scene.matching.align == "none" and scene.matching.kb == 2.5
    a, b = scene.shapes
    assert a.fill == (0xAA, 0xBB, 0xCC, 255) and a.stroke == (0x11, 0x22, 0x33, 0x44)
    assert a.paint.stroke_width == 3.5 and a.method == "linear" and b.method is None
    assert [k.time for k in a.keys] == [0.5, 2.0] and a.keys[0].ease == "in-out"
    assert a.keys[1].points.dtype == np.float64 and a.keys[1].points.shape == (4, 2)
    assert scene.duration == 2.0 and scene.method_of(b) == "rigid"


def test_points_are_read_only(tmp_path: Path) -> None:
    scene = parse_scene(SQUARE, tmp_path / "s.toml")
    with pytest.raises(ValueError):
        scene.shapes[0].keys[0].points[0, 0] = 5.0


def test_json_is_the_same_structure(tmp_path: Path) -> None:
    import tomllib

    data = tomllib.loads(FULL)
    path = tmp_path / "full.json"
    path.write_text(json.dumps(data))
    toml_path = tmp_path / "full.toml"
    toml_path.write_text(FULL)
    a, b = load_scene(path), load_scene(toml_path)
    assert a.shapes[0].name == b.shapes[0].name
    assert np.array_equal(a.shapes[0].keys[1].points, b.shapes[0].keys[1].points)


@pytest.mark.parametrize("scene", sorted(SCENES.glob("*.toml")), ids=lambda p: p.name)
def test_shipped_scenes_load(scene: Path) -> None:
    assert load_scene(scene).shapes


def _replace(old: str, new: str) -> str:
    assert old in SQUARE
    return SQUARE.replace(old, new, 1)


BAD = [
    # (scene text, where (substring of the message), expected words)
    ("size = [320, 240]\nsise = 3\n", "sise (line 2)", "did you mean 'size'"),
    (_replace('name = "sq"', 'name = "sq"\nfil = "#fff"'), "shape[0].fil (line 5)", "did you mean 'fill'"),
    (_replace("time = 2", "time = 2\nease = \"inout\""), "shape[0].key[1].ease (line 10)", "did you mean 'in-out'"),
    (_replace('name = "sq"', 'name = "sq"\nmethod = "nonlinaer"'), "shape[0].method (line 5)", "did you mean 'nonlinear'"),
    (_replace("[7, 1], [7, 3], [5, 3], [5, 1]", "[7, 1], [7, 3]"), "shape[0].key[1].points (line 10)", "at least 3"),
    (_replace("[7, 1], [7, 3]", "[7, 1, 2], [7, 3]"), "shape[0].key[1].points[0]", "[x, y] pair"),
    (_replace("[7, 1], [7, 3]", "[7, \"a\"], [7, 3]"), "shape[0].key[1].points[0][1]", "found a string"),
    (_replace("time = 2", "time = 0"), "shape[0].key[1].time (line 9)", "strictly increase"),
    (_replace("time = 2", "time = -1"), "shape[0].key[1].time", "from 0"),
    (_replace("time = 2", "time = nan"), "shape[0].key[1].time", "finite"),
    (_replace("time = 2", "time = true"), "shape[0].key[1].time", "found a boolean"),
    (_replace("[7, 1], [7, 3]", "[7, 1e12], [7, 3]"), "shape[0].key[1].points[0][1]", "1e+09"),
    (_replace("[7, 1], [7, 3]", "[7, inf], [7, 3]"), "shape[0].key[1].points[0][1]", "finite"),
    ("size = [320, 240]\n", "shape", "at least one [[shape]]"),
    (_replace("size = [320, 240]", "size = [320, 0]"), "size[1] (line 1)", "from 1 to 16384"),
    (_replace("size = [320, 240]", "size = [99999, 240]"), "size[0]", "from 1 to 16384"),
    (_replace("size = [320, 240]", "size = [320]"), "size (line 1)", "[width, height]"),
    (_replace("size = [320, 240]", "size = [320, 240]\nfps = 0"), "fps (line 2)", "from 1 to 240"),
    (_replace("size = [320, 240]", "size = [320, 240]\nfps = 1000"), "fps", "from 1 to 240"),
    (_replace("view = [-2, -2, 10, 7]", "view = [10, -2, -2, 7]"), "view (line 2)", "xmax > xmin"),
    (_replace("size = [320, 240]", "size = [320, 240]\nbackground = \"white\""), "background (line 2)", "#rrggbb"),
    (_replace('name = "sq"', 'name = "sq"\nfill = "#12345"'), "shape[0].fill", "#rgb"),
    (_replace('name = "sq"', 'name = "sq"\nmethod = "jointed"'), "shape[0].method", "needs joints"),
    (_replace('name = "sq"', 'name = "sq"\njoints = [[0, 9]]'), "shape[0].joints[0][1]", "from 0 to 3"),
    (SQUARE + '[[shape]]\nname = "sq"\n[[shape.key]]\ntime = 0\npoints = [[0,0],[1,0],[0,1]]\n',
     "shape[1].name (line 12)", "unique"),
    (_replace("size = [320, 240]", "size = [320, 240]\ncompare = [\"linear\", \"rigd\"]"), "compare[1]", "did you mean 'rigid'"),
    (SQUARE + "[correspondence]\ncost = \"energy\"\n", "correspondence.cost (line 12)",
     "expected one of distance, sg"),
    ("size = [320 240]\n", "line 1", "not valid TOML"),
    (_replace("[[shape.key]]\ntime = 2", "[[shape.key]]\ntim = 2"), "shape[0].key[1].tim (line 9)", "did you mean 'time'"),
]


@pytest.mark.parametrize("text, where, words", BAD, ids=[b[1] for b in BAD])
def test_bad_scene_is_refused_with_its_place(tmp_path: Path, text: str, where: str, words: str) -> None:
    path = tmp_path / "bad.toml"
    path.write_text(text)
    with pytest.raises(SceneError) as caught:
        load_scene(path)
    message = str(caught.value)
    assert message.startswith(str(path) + ": ")
    assert where in message and words in message
    assert "\n" not in message


def test_missing_and_unreadable_files(tmp_path: Path) -> None:
    with pytest.raises(SceneError, match="no such file"):
        load_scene(tmp_path / "nope.toml")
    with pytest.raises(SceneError, match="is a folder"):
        load_scene(tmp_path)
    binary = tmp_path / "b.toml"
    binary.write_bytes(b"\xff\xfe\x00bad")
    with pytest.raises(SceneError, match=r"b\.toml: line 1: expected UTF-8 text, found byte 0xff"):
        load_scene(binary)


def test_json_errors_name_line(tmp_path: Path) -> None:
    path = tmp_path / "bad.json"
    path.write_text('{\n"size": [320, 240],\n}')
    with pytest.raises(SceneError, match=r"bad\.json: line 3: not valid JSON"):
        load_scene(path)


def test_line_locator_on_nested_tables() -> None:
    text = "a = 1\n[[shape]]\n[[shape.key]]\n[[shape.key]]\npoints = 1\n[[shape]]\n[[shape.key]]\npoints = 2\n"
    assert line_of(text, "a") == 1
    assert line_of(text, "shape[0].key[1].points") == 5
    assert line_of(text, "shape[1].key[0].points") == 8
    assert line_of(text, "shape[1]") == 6
    assert line_of(text, "shape[2]") is None
