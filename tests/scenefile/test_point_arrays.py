"""Large ``points`` arrays read by numpy give the very scene ``tomllib`` gives, fail the same way, and leave
``tomllib`` only the rest of the text to parse (counted in characters)."""

from __future__ import annotations

import dataclasses
import math
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest

from tweenrender.errors import SceneError
from tweenrender.scenefile import load_scene
from tweenrender.scenefile import point_arrays

from tests.helpers import write_scene

ROOT = Path(__file__).resolve().parents[2]


def _same(a: object, b: object, where: str = "scene") -> None:
    """Field by field, arrays bit for bit (tomllib reads -0 as the integer 0 and -0.0 as -0.0)."""
    if isinstance(a, np.ndarray):
        assert isinstance(b, np.ndarray) and a.dtype == b.dtype and a.tobytes() == b.tobytes(), where  # bit for bit
    elif dataclasses.is_dataclass(a) and not isinstance(a, type):
        assert type(a) is type(b), where
        for field in dataclasses.fields(a):
            _same(getattr(a, field.name), getattr(b, field.name), f"{where}.{field.name}")
    elif isinstance(a, (tuple, list)):
        assert isinstance(b, type(a)) and len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b)):
            _same(x, y, f"{where}[{i}]")
    elif isinstance(a, dict):
        assert isinstance(b, dict) and a.keys() == b.keys(), where
        for key in a:
            _same(a[key], b[key], f"{where}.{key}")
    else:
        assert a == b or (isinstance(a, float) and math.isnan(a) and math.isnan(b)), where


def _read_by_tomllib(path: Path, monkeypatch) -> object:
    with monkeypatch.context() as patch:
        patch.setattr(point_arrays, "SMALLEST_LIFTED", 10**9)
        return load_scene(path)


def _ring(count: int, radius: float, formats: tuple[str, ...] = ("{:.6f}",), seed: int = 0) -> str:
    rng = np.random.default_rng(seed)
    points = []
    for k in range(count):
        angle = 2 * math.pi * k / count
        r = radius * (1 + 0.2 * rng.uniform(-1, 1))
        form = formats[k % len(formats)]
        x, y = r * math.cos(angle), r * math.sin(angle)
        if form == "int":  # whole numbers, as TOML integers
            points.append(f"[{round(100 * x)}, {round(100 * y)}]")
        else:
            points.append(f"[{form.format(x)}, {form.format(y)}]")
    return "[" + ", ".join(points) + "]"


def _scene(first: str, second: str, extra: str = "") -> str:
    return ("size = [320, 240]\nview = [-3, -3, 3, 3]\n" + extra + "[[shape]]\nfill = \"#336699\"\n"
            f"[[shape.key]]\ntime = 0\npoints = {first}\n[[shape.key]]\ntime = 1\npoints = {second}\n")


@pytest.mark.parametrize("formats", [("{:.6f}",), ("{:.17g}",), ("{:+.3e}", "int", "{:.2E}", "{:.1f}")])
def test_lifted_arrays_give_tomllibs_scene(tmp_path: Path, monkeypatch, formats: tuple[str, ...]) -> None:
    first, second = _ring(300, 2.0, formats, 1), _ring(420, 1.5, formats, 2)
    path = write_scene(tmp_path, _scene(first.replace("], [", "],\n  [", 7), second))
    lifted, arrays = point_arrays.lift_point_arrays(path.read_text(), 1e9)
    assert len(arrays) == 2 and len(lifted) < 300  # tomllib sees the rest only
    assert lifted.count("\n") == path.read_text().count("\n")  # every line keeps its number
    _same(load_scene(path), _read_by_tomllib(path, monkeypatch))


def test_every_shipped_scene_reads_as_before(monkeypatch) -> None:
    for path in sorted((ROOT / "scenes").glob("*.toml")):
        _same(load_scene(path), _read_by_tomllib(path, monkeypatch), path.name)


def test_a_detailed_scene_reads_as_before_and_tomllib_parses_little(monkeypatch) -> None:
    shapes = []
    for s in range(40):  # 40 shapes x 3 keys x 500 vertices, written as the benchmark's stroked scene is
        keys = "".join(f"[[shape.key]]\ntime = {k}\npoints = {_ring(500, 1 + s / 40, ('{:.4f}',), 3 * s + k)}\n"
                       for k in range(3))
        shapes.append(f'[[shape]]\nname = "s{s}"\nfill = "#3b6fd8"\nstroke = "#1d2b50"\nstroke_width = 2.0\n{keys}')
    text = "size = [640, 360]\nview = [-3, -3, 3, 3]\n" + "\n".join(shapes)
    parsed: list[int] = []
    original = tomllib.loads

    def counted(source: str, **options: object) -> object:
        parsed.append(len(source))
        return original(source, **options)

    monkeypatch.setattr(tomllib, "loads", counted)
    from tweenrender.scenefile.load import parse_scene

    fast = parse_scene(text, "detailed.toml")
    assert parsed == [parsed[0]] and parsed[0] < len(text) / 100  # 120 arrays out of 1.2 MB of text
    with monkeypatch.context() as patch:
        patch.setattr(point_arrays, "SMALLEST_LIFTED", 10**9)
        _same(fast, parse_scene(text, "detailed.toml"))


def _error(path: Path, monkeypatch) -> tuple[str, str]:
    with pytest.raises(SceneError) as fast:
        load_scene(path)
    with pytest.raises(SceneError) as slow:
        _read_by_tomllib(path, monkeypatch)
    return str(fast.value), str(slow.value)


@pytest.mark.parametrize("damage", ["out of range", "an integer of 40 digits", "bad TOML after", "a pair of three",
                                    "a string inside", "too few keys"])
def test_a_scene_with_lifted_arrays_fails_as_tomllib_and_the_checks_make_it(tmp_path: Path, monkeypatch,
                                                                             damage: str) -> None:
    first, second = _ring(200, 2.0, seed=3), _ring(200, 1.5, seed=4)
    text = {
        "out of range": _scene(re.sub(r"^\[\[[^,]+,", "[[1e30,", first), second),
        "an integer of 40 digits": _scene(first, second.replace("]]", "], [1" + "0" * 39 + ", 1]]")),
        "bad TOML after": _scene(first, second) + "\nfps = = 3\n",
        "a pair of three": _scene(first.replace("]]", ", 4.0]]"), second),
        "a string inside": _scene(first, second.replace("[", "[\"x\", ", 2).replace("[\"x\", ", "[", 1)),
        "too few keys": _scene(first, second).replace("time = 1", "time = 0"),
    }[damage]
    fast, slow = _error(write_scene(tmp_path, text), monkeypatch)
    assert fast == slow


def test_a_points_line_inside_a_string_is_left_to_tomllib(tmp_path: Path, monkeypatch) -> None:
    ring = _ring(100, 2.0, seed=5)
    text = _scene(ring, _ring(100, 1.0, seed=6), extra=f'title = """a note\npoints = {ring}\n"""\n')
    path = write_scene(tmp_path, text)
    scene = load_scene(path)
    assert scene.title is not None and ring in scene.title
    _same(scene, _read_by_tomllib(path, monkeypatch))


def test_negative_zeros_read_as_tomllib_reads_them(tmp_path: Path, monkeypatch) -> None:
    for zero in ("-0", "-0.0", "0", "+0.0"):
        ring = _ring(100, 2.0, seed=7).replace("[", f"[{zero}, ", 2).replace(f"[{zero}, ", "[", 1)
        ring = ring.replace(f"[{zero}, ", f"[{zero}, 0.5], [", 1)
        path = write_scene(tmp_path, _scene(ring, _ring(120, 1.0, seed=8)))
        _same(load_scene(path), _read_by_tomllib(path, monkeypatch), zero)
