"""The loader against hostile input: odd structures, huge numbers, odd files, and fuzzing.

Whatever the bytes, ``load_scene`` returns a scene or raises a ``TweenrenderError``
whose one-line message names the file and, where there is one, the place.
"""

from __future__ import annotations

import json
import os
import time
import tomllib
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tweenrender.errors import SceneError, TweenrenderError
from tweenrender.scenefile import LIMITS, load_scene, parse_scene

from tests.helpers import SCENES, SQUARE, unprivileged

SECOND_KEY = "[[7, 1], [7, 3], [5, 3], [5, 1]]"


def _replace(old: str, new: str) -> str:
    assert old in SQUARE
    return SQUARE.replace(old, new, 1)


def _ring(count: int) -> str:
    return "[" + ", ".join(f"[{i % 7}, {i % 5}]" for i in range(count)) + "]"


# (file name, text, where (substring of the message), expected words)
MORE_BAD = [
    ("empty.toml", "", "shape", "at least one [[shape]] or [[drawing]], found none"),
    ("comments.toml", "# nothing\n\n", "shape", "at least one [[shape]]"),
    ("array-top.toml", "[[size]]\nw = 1\n", "size (line 1)", "found an array of 1 table"),
    ("shape-table.toml", '[shape]\nname = "a"\n', "shape (line 1)", "found a table of 1 key"),
    ("shape-string.toml", 'shape = "square"\n', "shape (line 1)", "found a string 'square'"),
    ("key-table.toml", '[[shape]]\nname = "a"\n[shape.key]\ntime = 0\n', "shape[0].key (line 3)",
     "expected a list of [[shape.key]] tables, found a table"),
    ("key-missing.toml", '[[shape]]\nname = "a"\n', "shape[0] (line 1)", "at least one [[shape.key]]"),
    ("inf-fps.toml", "fps = 1e400\n" + SQUARE, "fps (line 1)", "found inf"),
    ("bigint-fps.toml", "fps = " + "9" * 40 + "\n" + SQUARE, "fps (line 1)", "an integer of 40 digits"),
    ("bigint-time.toml", _replace("time = 2", "time = " + "9" * 400), "shape[0].key[1].time (line 9)",
     "an integer of 400 digits"),
    ("longint.toml", _replace("[7, 1]", "[7, " + "9" * 5000 + "]"), "longint.toml: not valid TOML",
     "digits"),
    ("deep.toml", "a = " + "[" * 5000 + "]" * 5000 + "\n", "deep.toml: not valid TOML", "nested too deeply"),
    ("nested-points.toml", _replace(SECOND_KEY, "[[[[[1]]]]]"), "shape[0].key[1].points[0] (line 10)",
     "expected an [x, y] pair, found a list of 1 item"),
    ("points-table.toml", _replace(SECOND_KEY, "{ x = 1 }"), "shape[0].key[1].points.x",
     "unknown key 'x'"),
    ("svg-no-file.toml", _replace(SECOND_KEY, '{ svg = "missing.svg", id = "a" }'),
     "shape[0].key[1].points (line 10)", "missing.svg#a"),
    ("svg-misspelt.toml", _replace(SECOND_KEY, '{ svg = "a.svg", idd = "a" }'), "shape[0].key[1].points.idd",
     "did you mean 'id'"),
    ("svg-no-id.toml", _replace(SECOND_KEY, '{ svg = "a.svg" }'), "shape[0].key[1].points (line 10)",
     'expected { svg = "file.svg", id = "element" }'),
    ("date-time.toml", _replace("time = 2", "time = 1979-05-27"), "shape[0].key[1].time (line 9)",
     "found date"),
    ("duplicate.toml", "fps = 3\nfps = 4\n" + SQUARE, "line 2", "not valid TOML"),
    ("nul.toml", SQUARE + "\x00", "line 11", "not valid TOML"),
    ("time-late.toml", _replace("time = 2", "time = 2e7"), "shape[0].key[1].time", "from 0 to 1e+07"),
    ("stroke.toml", _replace('name = "sq"', 'name = "sq"\nstroke_width = -1'), "shape[0].stroke_width (line 5)",
     "from 0 to 1000, found -1"),
    ("correspondence-array.toml", SQUARE + "[[correspondence]]\ncost = \"sg\"\n", "correspondence (line 11)",
     "expected a table, found an array of 1 table"),
    ("constant.toml", SQUARE + "[correspondence]\nkb = -1\n", "correspondence.kb (line 12)", "from 0 to"),
    ("align.toml", SQUARE + "[correspondence]\nalign = \"centriod\"\n", "correspondence.align (line 12)",
     "did you mean 'centroid'"),
    ("joints-table.toml", _replace('name = "sq"', 'name = "sq"\njoints = { a = 1 }'), "shape[0].joints (line 5)",
     "found a table of 1 key"),
    ("joint-pair.toml", _replace('name = "sq"', 'name = "sq"\njoints = [[0, 1, 2]]'), "shape[0].joints[0] (line 5)",
     "found a list of 3"),
    ("too-many.toml", _replace(SECOND_KEY, _ring(LIMITS["vertices"] + 1)), "shape[0].key[1].points (line 10)",
     f"at most {LIMITS['vertices']} vertices"),
    ("sg-effort.toml", SQUARE.replace(SECOND_KEY, _ring(600)).replace("[[0, 0], [2, 0], [2, 2], [0, 2]]", _ring(500))
     + "[correspondence]\ncost = \"sg\"\n", "shape[0].key[1].points (line 10)", 'cost = "distance"'),
    ("title.toml", "title = [1]\n" + SQUARE, "title (line 1)", "expected a string, found a list of 1 item"),
]


@pytest.mark.parametrize("name, text, where, words", MORE_BAD, ids=[b[0] for b in MORE_BAD])
def test_more_bad_scenes(tmp_path: Path, name: str, text: str, where: str, words: str) -> None:
    path = tmp_path / name
    path.write_text(text)
    with pytest.raises(SceneError) as caught:
        load_scene(path)
    message = str(caught.value)
    assert message.startswith(f"{path}: ") and "\n" not in message, message
    assert where in message and words in message, message


JSON_BAD = [
    ("[1, 2]", "expected a table, found a list of 2 items"),
    ('{"fps": 24, "fps": 30}', "found 'fps' twice"),
    ('{\n"fps": 24,\n"size": [1, 2,]\n}', "line 3: not valid JSON"),
    ('{"fps": ' + "9" * 5000 + "}", "not valid JSON"),
    ("[" * 100000 + "]" * 100000, "not valid JSON"),
    ('{"fps": NaN, "shape": []}', "fps (line 1): expected frames per second (finite), found nan"),
    ('{"shape": [{"key": [{"time": 0, "points": [[0, 0], [1, 0], [0, null]]}]}]}',
     "shape[0].key[0].points[2][1] (line 1): expected a coordinate, found null"),
    ('{\n "shape": [\n  {"key": [\n   {"time": 0,\n    "points": [[0, 0],\n     [1, 0], [0, 1]]},\n'
     '   {"time": 1,\n    "pionts": []}]}]}', "shape[0].key[1].pionts (line 8): unknown key 'pionts' (did you mean 'points'?)"),
    ('{\n "shape": [\n  {"key": [\n   {"time": 0,\n    "points": [[0, 0],\n     [1, 0], [0, 1]]},\n'
     '   {"time": 1,\n    "points": [[0, 0],\n     [1, 0], [0, "1"]]}]}]}',
     "shape[0].key[1].points[2][1] (line 9): expected a coordinate, found a string '1'"),
]


@pytest.mark.parametrize("text, words", JSON_BAD, ids=[w for _, w in JSON_BAD])
def test_bad_json(tmp_path: Path, text: str, words: str) -> None:
    path = tmp_path / "bad.json"
    path.write_text(text)
    with pytest.raises(SceneError) as caught:
        load_scene(path)
    assert str(caught.value).startswith(f"{path}: ") and words in str(caught.value), str(caught.value)


def test_a_fifo_is_refused_without_opening_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    fifo = tmp_path / "scene.toml"
    os.mkfifo(fifo)  # nobody will ever write to it: reading would block for ever
    opened = []
    real_open = os.open

    def counted(path, *args, **kwargs):  # type: ignore[no-untyped-def]
        opened.append(str(path))
        return real_open(path, *args, **kwargs)

    monkeypatch.setattr(os, "open", counted)
    with pytest.raises(SceneError, match=r"scene\.toml: is a pipe \(FIFO\), expected a scene file"):
        load_scene(fifo)
    assert str(fifo) not in opened


@pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="no /dev/zero")
def test_an_endless_device_is_refused() -> None:
    with pytest.raises(SceneError, match="is a character device"):
        load_scene("/dev/zero")


def test_a_file_too_large_is_refused_before_parsing(tmp_path: Path) -> None:
    path = tmp_path / "big.toml"
    with path.open("wb") as file:  # sparse: costs no disk
        file.truncate(LIMITS["file_bytes"] + 1)
    with pytest.raises(SceneError, match=r"big\.toml: expected a scene of at most 16 MiB"):
        load_scene(path)


def test_ten_million_points_are_refused_before_parsing(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # 10 million pairs would take tomllib minutes and gigabytes; the bracket count refuses them first
    text = "[[shape]]\n[[shape.key]]\ntime = 0\npoints = [" + "[0,0]," * 2_000_000 + "]\n"
    parsed = []
    monkeypatch.setattr(tomllib, "loads", lambda *args, **kwargs: parsed.append(args))
    with pytest.raises(SceneError, match=r"expected at most 1000000 \[x, y\] pairs in one scene, found about"):
        parse_scene(text, tmp_path / "many.toml")
    assert parsed == []  # refused by counting brackets, before tomllib spends minutes and gigabytes


def test_an_unreadable_file(open_tmp_path: Path) -> None:
    """As an unprivileged user (root reads any file, so a root run drops to ``nobody`` first)."""
    path = open_tmp_path / "secret.toml"
    path.write_text(SQUARE)
    path.chmod(0)

    def load() -> str:
        try:
            load_scene(path)
        except SceneError as error:
            return str(error)
        return "loaded"

    assert unprivileged(load) == f"{path}: cannot be read (permission denied)"


def test_non_utf8_names_line_and_byte(tmp_path: Path) -> None:
    path = tmp_path / "latin.toml"
    path.write_bytes(SQUARE.replace('"sq"', '"caf\xe9"').encode("latin-1"))
    with pytest.raises(SceneError, match=r"latin\.toml: line 4: expected UTF-8 text, found byte 0xe9"):
        load_scene(path)


# -- fuzzing: nothing but TweenrenderError may escape ---------------------------------------------

SHIPPED = {path.name: path.read_text() for path in sorted(SCENES.glob("*.toml"))}
_FUZZ = settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _survives(text: str, path: Path, fmt: str) -> None:
    try:
        parse_scene(text, path, fmt)
    except TweenrenderError as error:
        assert "\n" not in str(error), str(error)


@_FUZZ
@given(name=st.sampled_from(sorted(SHIPPED)), data=st.data())
def test_mutated_shipped_scenes(name: str, data: st.DataObject) -> None:
    text = SHIPPED[name]
    for _ in range(data.draw(st.integers(1, 4), label="edits")):
        at = data.draw(st.integers(0, len(text)), label="at")
        cut = data.draw(st.integers(0, 12), label="cut")
        insert = data.draw(st.sampled_from(["", "[", "]", "[[", "{", "}", "=", '"', ",", "\n", "-", "1e400", "nan",
                                            "0", "9" * 30, "x", "#", ".", "[[shape]]\n", "[[shape.key]]\n",
                                            "time = 1\n", "joints = [[0, 2]]\n", 'method = "jointed"\n']),
                           label="insert")
        text = text[:at] + insert + text[at + cut:]
    _survives(text, SCENES / name, "toml")


def _json_values(leaves: st.SearchStrategy) -> st.SearchStrategy:
    return st.recursive(leaves, lambda inner: st.lists(inner, max_size=5)
                        | st.dictionaries(st.sampled_from(["shape", "key", "time", "points", "size", "fps",
                                                           "view", "method", "joints", "name", "fill", "svg",
                                                           "id", "ease", "compare", "correspondence", "cost"]),
                                          inner, max_size=5), max_leaves=30)


_LEAVES = (st.none() | st.booleans() | st.integers(-10**20, 10**20) | st.floats(allow_nan=True)
           | st.sampled_from(["linear", "nonlinear", "rigid", "jointed", "auto", "#fff", "in-out", "sg", "x.svg"])
           | st.text(max_size=8))


@_FUZZ
@given(value=_json_values(_LEAVES))
def test_random_json_documents(value: object) -> None:
    _survives(json.dumps(value), Path("fuzz.json"), "json")


_TOKENS = list('[]{}=,."#\n 019ae-+_xtsp') + ["shape", "key", "time", "points", "[[shape]]", "[[shape.key]]"]


@_FUZZ
@given(tokens=st.lists(st.sampled_from(_TOKENS), max_size=60))
def test_random_toml_ish_text(tokens: list[str]) -> None:
    _survives("".join(tokens), Path("fuzz.toml"), "toml")
