"""The steering fields of a scene (``turn``, ``turns``, ``arcs``, ``breakdown``; maths §5.13–5.15): each
bad value is one line naming the file and the key path, exit 2, nothing else; drawings take them too."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr

HEAD = 'method = "{method}"\n[[shape]]\nname = "s"\n'
FIRST = '[[shape.key]]\ntime = 0\npoints = [[0, 0], [2, 0], [2, 2], [0, 2]]\nhints = { a = [0, 0] }\n'
LAST = '[[shape.key]]\ntime = 2\npoints = [[7, 1], [7, 3], [5, 3], [5, 1]]\nhints = { a = [7, 1] }\n'

BAD = [
    ("turn = \"clockwise\"", "", "shape[0].key[0].turn (line 8): expected \"cw\", \"ccw\" or \"shortest\", found "
                                 "'clockwise'"),
    ("turn = 1", "", "shape[0].key[0].turn (line 8): expected \"cw\", \"ccw\" or \"shortest\", found 1"),
    ("turns = -1", "", "shape[0].key[0].turns (line 8): expected a whole number of extra turns from 0 to 1000, "
                       "found -1"),
    ("turns = 1.5", "", "shape[0].key[0].turns (line 8): expected a whole number of extra turns"),
    ("arcs = [1, 2]", "", "shape[0].key[0].arcs (line 8): expected a table of hint letters"),
    ("arcs = { a = [1] }", "", "shape[0].key[0].arcs.a: expected an [x, y] point"),
    ("arcs = { B = [1, 2] }", "", "shape[0].key[0].arcs.B: expected a hint letter a–z"),
    ("arcs = { c = [1, 2] }", "", "shape[0].key[0].arcs.c: expected hint c on both keys of the segment, "
                                  "found it on neither"),
    ("", "[[shape.key]]\ntime = 1\nbreakdown = \"half\"\n",
     "shape[0].key[1].breakdown (line 11): expected a favour from -10 to 10"),
    ("", "[[shape.key]]\ntime = 1\nbreakdown = 0.5\npoints = [[0, 0], [1, 0], [0, 1]]\n",
     "shape[0].key[1].points (line 12): expected no points on a breakdown key"),
    ("", "[[shape.key]]\ntime = 1\nbreakdown = 0.5\nhints = { a = [0, 0] }\n",
     "shape[0].key[1].hints (line 12): expected no hints on a breakdown key"),
]


def _write(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "steer.toml"
    path.write_text(text)
    return path


@pytest.mark.parametrize("first, middle, message", BAD)
def test_a_bad_steering_value_is_one_line(cli, tmp_path, first: str, middle: str, message: str) -> None:
    scene = _write(tmp_path, HEAD.format(method="rigid") + FIRST + first + "\n" + middle + LAST)
    code, out, err = cli("check", scene)
    assert code == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err
    assert f"{scene}: {message}" in err


def test_straight_paths_refuse_a_turn(cli, tmp_path) -> None:
    scene = _write(tmp_path, HEAD.format(method="linear") + FIRST + "turns = 1\n" + LAST)
    code, _, err = cli("render", scene, "-o", tmp_path / "x.gif")
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert f"{scene}: shape[0].key[0].turns (line 8): expected no turns under method \"linear\"" in err
    assert not (tmp_path / "x.gif").exists()


@pytest.mark.parametrize("where, first, last", [
    ("shape[0].key[0].breakdown (line 6): expected a key before and a key after a breakdown, found it first",
     "[[shape.key]]\ntime = 0\nbreakdown = 0.5\n", ""),
    ("shape[0].key[2].breakdown (line 14): expected a key before and a key after a breakdown, found it last",
     "", "[[shape.key]]\ntime = 3\nbreakdown = 0.5\n"),
    ("shape[0].key[1].turn (line 12): expected turn on a key that starts a segment, found it on the last key",
     "", 'turn = "cw"\n'),
])
def test_steering_where_it_cannot_act(cli, tmp_path, where: str, first: str, last: str) -> None:
    scene = _write(tmp_path, HEAD.format(method="rigid") + first + FIRST.replace("time = 0", "time = 0.5")
                   + LAST + last)
    code, _, err = cli("check", scene)
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert f"{scene}: {where}" in err


def test_stats_measure_the_long_turn_on_the_thesis_square(cli, tmp_path) -> None:
    """The thesis's square turned +90°, made to turn −270° by ``turn = "cw"``: every method with a rigid frame
    keeps its perimeter (ratio 1.00000) at every t, as a rigid turn does; linear goes straight (cos 45°)."""
    import json

    square = HEAD.format(method="nonlinear") + FIRST.replace('hints = { a = [0, 0] }\n', "") + 'turn = "cw"\n' \
        + LAST.replace('hints = { a = [7, 1] }\n', "")
    code, out, err = cli("stats", _write(tmp_path, square), "--t", "0.1,0.25,0.5,0.75,0.9", "--json")
    assert code == 0, err
    methods = json.loads(out)["shapes"][0]["methods"]
    for name in ("nonlinear", "rigid", "arap", "intrinsic", "injective"):
        assert methods[name]["ratio"] == pytest.approx([1.0] * 5, abs=5e-6), name
    assert methods["linear"]["ratio"][2] == pytest.approx(math.cos(math.pi / 4), abs=1e-5)


def test_every_command_honours_the_fields(cli, tmp_path) -> None:
    """stats, sheet and the vector export go through the same segments: a clockwise turn shows in each."""
    scene = _write(tmp_path, HEAD.format(method="rigid") + FIRST + 'turn = "cw"\n' + LAST)
    plain = tmp_path / "plain.toml"
    plain.write_text(HEAD.format(method="rigid") + FIRST + LAST)
    turned, straight = tr.stats(tr.load_scene(scene), t=(0.5,)), tr.stats(tr.load_scene(plain), t=(0.5,))
    assert turned != straight
    code, _, err = cli("render", scene, "--format", "lottie", "-o", tmp_path / "x.json", "-q")
    assert code == 0, err
    import json
    exported = json.loads((tmp_path / "x.json").read_text())
    code, _, err = cli("render", plain, "--format", "lottie", "-o", tmp_path / "y.json", "-q")
    assert code == 0, err
    assert exported != json.loads((tmp_path / "y.json").read_text())


SVG = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100"><path id="p" d="{d}"/></svg>'


def _drawings(tmp_path: Path) -> tuple[Path, Path]:
    a, b = tmp_path / "a.svg", tmp_path / "b.svg"
    a.write_text(SVG.format(d="M 10 10 L 30 10 L 30 30 L 10 30 Z"))
    b.write_text(SVG.format(d="M 70 50 L 70 70 L 50 70 L 50 50 Z"))  # turned 90° (y down) and moved
    return a, b


def test_drawings_take_turns_and_breakdowns(tmp_path) -> None:
    _drawings(tmp_path)
    entry = '[[drawing]]\ntime = {t}\nsvg = "{name}.svg"\n'
    text = ('method = "rigid"\n' + entry.format(t=0, name="a") + 'turn = "ccw"\nturns = 1\n'
            + entry.format(t=2, name="b"))
    scene = tr.parse_scene(text, tmp_path / "d.toml")
    first = tr.outlines(scene, 0)[0]
    c0, c1 = first.mean(axis=0), tr.outlines(scene, 2)[0].mean(axis=0)
    best = math.atan2(*(tr.outlines(scene, 2)[0][0] - c1)[::-1]) - math.atan2(*(first[0] - c0)[::-1])
    best = (best + math.pi) % (2 * math.pi) - math.pi
    total = best + 2 * math.pi if best < 0 else best
    total += 2 * math.pi  # ccw and one whole turn more
    mid = tr.outlines(scene, 1)[0]
    angle = np.exp(1j * total / 2)
    expected = (0.5 * (c0 + c1)) + np.c_[((first - c0) @ [1, 1j] * angle).real, ((first - c0) @ [1, 1j] * angle).imag]
    np.testing.assert_allclose(mid, expected, atol=1e-9)
    split = 'method = "linear"\n' + entry.format(t=0, name="a") + "[[drawing]]\ntime = 0.5\nbreakdown = 0.25\n" \
        + entry.format(t=2, name="b")
    whole = 'method = "linear"\n' + entry.format(t=0, name="a") + entry.format(t=2, name="b")
    a, b = tr.parse_scene(split, tmp_path / "s.toml"), tr.parse_scene(whole, tmp_path / "w.toml")
    for t in np.linspace(0, 2, 17):
        np.testing.assert_allclose(tr.outlines(a, t)[0], tr.outlines(b, t)[0], atol=1e-12)


@pytest.mark.parametrize("extra, message", [
    ('turn = "left"', 'drawing[0].turn (line 4): expected "cw", "ccw" or "shortest"'),
    ("arcs = { a = [1, 2] }", "drawing[0].arcs.a: expected hint a on this drawing"),
    ("hold = -1", "drawing[0].hold (line 4): expected a hold in seconds from 0"),
])
def test_a_bad_drawing_field_is_one_line(cli, tmp_path, extra: str, message: str) -> None:
    _drawings(tmp_path)
    scene = _write(tmp_path, f'[[drawing]]\ntime = 0\nsvg = "a.svg"\n{extra}\n[[drawing]]\ntime = 1\nsvg = "b.svg"\n')
    code, _, err = cli("check", scene)
    assert code == 2 and len(err.strip().splitlines()) == 1 and f"{scene}: {message}" in err


def test_a_breakdown_drawing_has_no_file(cli, tmp_path) -> None:
    _drawings(tmp_path)
    scene = _write(tmp_path, '[[drawing]]\ntime = 0\nsvg = "a.svg"\n[[drawing]]\ntime = 0.5\nbreakdown = 0.5\n'
                             'svg = "b.svg"\n[[drawing]]\ntime = 1\nsvg = "b.svg"\n')
    code, _, err = cli("check", scene)
    assert code == 2 and f"{scene}: drawing[1].svg (line 7): expected no svg on a breakdown drawing" in err


def test_render_with_linear_alone_refuses_a_turn(cli, tmp_path) -> None:
    scene = _write(tmp_path, HEAD.format(method="rigid") + FIRST + 'turn = "cw"\n' + LAST)
    code, _, err = cli("render", scene, "--method", "linear", "-o", tmp_path / "x.gif")
    assert code == 2 and len(err.strip().splitlines()) == 1 and "Traceback" not in err
    assert "--method: \"linear\" has no rigid frame to turn, but shape 's' key 0 sets turn" in err
    assert not (tmp_path / "x.gif").exists()


def test_check_json_shows_the_fields(cli) -> None:
    import json

    code, out, err = cli("check", Path(__file__).resolve().parents[2] / "scenes" / "steering.toml", "--json")
    assert code == 0, err
    keys = json.loads(out)["shapes"][0]["keys"]
    assert keys[0]["turn"] == "cw" and keys[0]["arcs"] == {"b": [5.5, 2.6]}
    assert keys[1]["breakdown"] == 0.5 and len(keys[1]["points"]) >= 4


def test_a_drawing_arc_is_in_the_svg_units(tmp_path) -> None:
    _drawings(tmp_path)
    text = ('method = "linear"\n[[drawing]]\ntime = 0\nsvg = "a.svg"\nhints = { a = [10, 10] }\n'
            'arcs = { a = [40, 20] }\n[[drawing]]\ntime = 1\nsvg = "b.svg"\nhints = { a = [70, 50] }\n')
    scene = tr.parse_scene(text, tmp_path / "arc.toml")
    assert scene.view == (0.0, -100.0, 100.0, 0.0)  # the view box, y flipped up: (x, y) is (x, −y)
    mid = tr.outlines(scene, 0.5)[0]
    assert np.any(np.all(np.abs(mid - [40, -20]) < 1e-9, axis=1))
    assert not np.any(np.all(np.abs(tr.outlines(tr.parse_scene(text.replace("arcs", "#"), tmp_path / "p.toml"),
                                                0.5)[0] - [40, -20]) < 1e-6, axis=1))
