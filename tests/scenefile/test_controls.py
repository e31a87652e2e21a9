"""The animator's controls in scene files: each bad ease, spacing, hint or stagger is one line naming
the file, the key path and what was expected; drawings take hints in their own units, stagger their
elements and hold."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tweenrender.errors import SceneError

SQ = [[0, 0], [4, 0], [4, 4], [0, 4]]
SQ2 = [[10, 0], [14, 0], [14, 4], [10, 4]]


def _scene(tmp_path: Path, key0: str = "", key1: str = "", top: str = "", contours: bool = False) -> Path:
    if contours:
        ring = [SQ, [[1, 1], [1, 3], [3, 3], [3, 1]]]
        first, second = f"contours = {ring}", f"contours = {[[[x + 10, y] for x, y in c] for c in ring]}"
    else:
        first, second = f"points = {SQ}", f"points = {SQ2}"
    text = (f'{top}\n[[shape]]\nname = "s"\n'
            f'[[shape.key]]\ntime = 0\n{first}\n{key0}\n'
            f'[[shape.key]]\ntime = 2\n{second}\n{key1}\n')
    path = tmp_path / "scene.toml"
    path.write_text(text)
    return path


BAD = [
    # (key0, key1, top, contours), where, expected words
    (('ease = "cubic-bezier(1.5, 0, 0.5, 1)"', "", "", False), "shape[0].key[0].ease (line 7)",
     "expected x1 and x2 from 0 to 1"),
    (('ease = "cubic-bezier(0.5, 0, 0.5)"', "", "", False), "shape[0].key[0].ease", "four numbers"),
    (('ease = "steps(0)"', "", "", False), "shape[0].key[0].ease", "n from 1 to 10000"),
    (('ease = "steps(2, jump-middle)"', "", "", False), "shape[0].key[0].ease", "jump-start, jump-end"),
    (('ease = "ease-inn"', "", "", False), "shape[0].key[0].ease", "did you mean 'ease-in'"),
    (("ease = 3", "", "", False), "shape[0].key[0].ease", "expected an easing"),
    (("", "", 'ease = "bouncy"', False), "ease (line 1)", "unknown easing"),
    (('ease = "in"\nspacing = [0, 1]', "", "", False), "shape[0].key[0].spacing", "either ease or spacing"),
    (("spacing = [0, 0.5, 0.4, 1]", "", "", False), "shape[0].key[0].spacing[2]", "non-decreasing"),
    (("spacing = [0.1, 1]", "", "", False), "shape[0].key[0].spacing", "0 first and 1 last"),
    (('spacing = ["a"]', "", "", False), "shape[0].key[0].spacing", "list of positions"),
    (("hints = { a = [2, 1] }", "hints = { a = [12, 0] }", "", False), "shape[0].key[0].hints.a",
     "within 0.113137 of the key's outline (2 % of its bounding box's diagonal), found one 1 away"),
    (("hints = { a = [2, 0], c = [4, 4] }", "hints = { a = [12, 0] }", "", False), "shape[0].key[0].hints.c",
     "expected hint c on the key before or after too, found it on neither"),
    (("hints = { a = [2, 0], b = [4, 2], c = [0, 4] }", "hints = { a = [12, 0], b = [10, 2], c = [14, 4] }", "",
      False), "shape[0].key[1].hints", "in the same cyclic order on both keys' outlines"),
    (("hints = { a = [2, 0] }", "hints = { a = [11, 2] }", "", True), "shape[0].key[1].hints.a",
     "expected hint a to pair like contours, found an outer contour with a hole"),
    (("hints = { a = [2, 0], b = [2, 0] }", "hints = { a = [12, 0], b = [13, 0] }", "", False),
     "shape[0].key[0].hints.b", "expected each hint on its own point, found a and b on one point"),
    (("hints = { A = [2, 0] }", "", "", False), "shape[0].key[0].hints.A", "expected a hint letter a–z"),
    (("hints = { a = [2] }", "", "", False), "shape[0].key[0].hints.a", "expected an [x, y] point"),
    (("hints = [1, 2]", "", "", False), "shape[0].key[0].hints", "expected a table of hints"),
    (("", "", "stagger = -1", False), "stagger (line 1)", "expected a stagger in seconds from 0"),
]


@pytest.mark.parametrize("parts, where, expected", BAD, ids=[b[1] + ":" + b[2][:20] for b in BAD])
def test_bad_controls_are_one_line_naming_file_place_and_expectation(tmp_path, parts, where, expected) -> None:
    key0, key1, top, contours = parts
    path = _scene(tmp_path, key0, key1, top, contours)
    with pytest.raises(SceneError) as caught:
        tr.load_scene(path)
    message = str(caught.value)
    assert "\n" not in message
    assert message.startswith(f"{path}: {where}"), message
    assert expected in message, message


def test_cli_prints_the_line_and_exits_2(tmp_path) -> None:
    path = _scene(tmp_path, 'ease = "cubic-bezier(2, 0, 0, 1)"')
    run = subprocess.run([sys.executable, "-m", "tweenrender", "check", str(path)], capture_output=True, text=True,
                         cwd=Path(__file__).parents[2])
    assert run.returncode == 2
    assert run.stderr.strip().splitlines() == [run.stderr.strip()]
    assert "shape[0].key[0].ease" in run.stderr and "x1 and x2 from 0 to 1" in run.stderr
    assert "Traceback" not in run.stderr


def test_hint_on_an_edge_inserts_a_vertex_and_keeps_the_outline(tmp_path) -> None:
    scene = tr.load_scene(_scene(tmp_path, "hints = { a = [2, 0.01] }", "hints = { a = [12, 0] }"))
    key = scene.shapes[0].keys[0]
    assert key.points.tolist() == [[0, 0], [2, 0], [4, 0], [4, 4], [0, 4]]
    assert [(h.letter, h.contour, h.vertex) for h in key.hints] == [("a", 0, 1)]
    assert key.ease == "linear"


def test_joints_keep_naming_the_drawn_vertices(tmp_path) -> None:
    path = _scene(tmp_path, "hints = { a = [2, 0] }", "hints = { a = [12, 0] }")
    path.write_text(path.read_text().replace('name = "s"', 'name = "s"\nmethod = "jointed"\njoints = [[1, 3]]'))
    scene = tr.load_scene(path)
    shape = scene.shapes[0]
    (i, j), = shape.joints
    assert shape.keys[0].points[i].tolist() == [4, 0] and shape.keys[0].points[j].tolist() == [0, 4]


def test_check_json_carries_the_easing_as_written(tmp_path) -> None:
    scene = tr.load_scene(_scene(tmp_path, 'ease = "cubic-bezier(0.1, -0.5, 0.2, 1.4)"'))
    from tweenrender.reports.check_report import scene_dict

    described = scene_dict(scene, (0, 0, 1, 1))
    assert described["shapes"][0]["keys"][0]["ease"] == "cubic-bezier(0.1, -0.5, 0.2, 1.4)"


# -- drawings ---------------------------------------------------------------------------------------


def _svg(path: Path, body: str, box: str = "0 0 100 100") -> Path:
    path.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{box}">{body}</svg>')
    return path


def _three_boxes(tmp_path: Path) -> tuple[Path, Path]:
    a = _svg(tmp_path / "a.svg", '<rect id="r0" x="0" y="0" width="10" height="10"/>'
                                 '<rect id="r1" x="30" y="0" width="10" height="10"/>'
                                 '<rect id="r2" x="60" y="0" width="10" height="10"/>')
    b = _svg(tmp_path / "b.svg", '<rect id="r0" x="0" y="80" width="10" height="10"/>'
                                 '<rect id="r1" x="30" y="80" width="10" height="10"/>'
                                 '<rect id="r2" x="60" y="80" width="10" height="10"/>')
    return a, b


def _bottom(scene: tr.Scene, time: float) -> list[float]:
    """Each element's lowest y (world units, y up) at ``time``, in paint order."""
    return [float(c[:, 1].min()) for c in tr.outlines(scene, time, method="linear")]


def test_stagger_starts_element_i_later_and_arrives_on_time(tmp_path) -> None:
    a, b = _three_boxes(tmp_path)
    scene = tr.load_scene([a, b], step=1.0, stagger=0.25)
    start, end = _bottom(scene, 0.0), _bottom(scene, 1.0)
    for i in range(3):
        begins = 0.25 * i
        for time in np.linspace(0, 1, 41):
            u = min(max((time - begins) / (1.0 - begins), 0.0), 1.0)
            want = start[i] + u * (end[i] - start[i])
            assert _bottom(scene, float(time))[i] == pytest.approx(want, abs=1e-9)


def test_stagger_must_fit_in_the_segment(tmp_path) -> None:
    a, b = _three_boxes(tmp_path)
    with pytest.raises(SceneError, match=r"stagger × \(elements − 1\) shorter than the segment \(1 s\), "
                                         r"found 0.5 × 2 = 1 s"):
        tr.load_scene([a, b], step=1.0, stagger=0.5)


def test_hold_shows_each_drawing_then_moves_for_step(tmp_path) -> None:
    a, b = _three_boxes(tmp_path)
    scene = tr.load_scene([a, b], step=1.0, hold=0.5, ease="in")
    assert scene.duration == pytest.approx(2.0)  # hold 0.5, move 1, hold 0.5
    start, end = _bottom(scene, 0.0), _bottom(scene, 1.5)
    assert start != end
    assert _bottom(scene, 0.5) == start and _bottom(scene, 2.0) == end
    u = 0.5
    for i in range(3):
        assert _bottom(scene, 0.5 + 1.0 * u)[i] == pytest.approx(start[i] + u * u * (end[i] - start[i]), abs=1e-9)


def test_drawing_hints_are_in_svg_units_and_pair_elements(tmp_path) -> None:
    """Two circles-like squares swap places when hinted; the hint is given in the SVG's own units (y down)."""
    a = _svg(tmp_path / "a.svg", '<rect x="0" y="0" width="10" height="10" fill="red"/>'
                                 '<rect x="60" y="0" width="10" height="10" fill="blue"/>', "0 0 200 100")
    b = _svg(tmp_path / "b.svg", '<rect x="0" y="0" width="10" height="10" fill="red"/>'
                                 '<rect x="60" y="0" width="10" height="10" fill="blue"/>', "0 0 200 100")
    text = (f'[[drawing]]\ntime = 0\nsvg = "a.svg"\nhints = {{ a = [0, 0] }}\n'
            f'[[drawing]]\ntime = 1\nsvg = "b.svg"\nhints = {{ a = [60, 10] }}\n')
    path = tmp_path / "d.toml"
    path.write_text(text)
    scene = tr.load_scene(path)
    red = next(s for s in scene.shapes if s.keys[0].paint.fill[:3] == (255, 0, 0))
    assert red.keys[1].paint.fill[:3] == (0, 0, 255)  # the red square goes where the blue one is
    start = red.keys[0].points
    end = red.keys[1].points
    world_a = start[[h.vertex for h in red.keys[0].hints if h.letter == "a"][0]]
    world_b = end[[h.vertex for h in red.keys[1].hints if h.letter == "a"][0]]
    assert world_a.tolist() == [0, 0] and world_b.tolist() == [60, -10]  # y flipped: 10 down is -10


def test_drawing_hint_far_from_every_element(tmp_path) -> None:
    a = _svg(tmp_path / "a.svg", '<rect x="0" y="0" width="10" height="10"/>')
    b = _svg(tmp_path / "b.svg", '<rect x="50" y="50" width="10" height="10"/>')
    path = tmp_path / "d.toml"
    path.write_text('[[drawing]]\ntime = 0\nsvg = "a.svg"\nhints = { q = [5, 50] }\n'
                    '[[drawing]]\ntime = 1\nsvg = "b.svg"\nhints = { q = [50, 50] }\n')
    with pytest.raises(SceneError, match=r"drawing\[0\]\.hints\.q.*found one 40 away"):
        tr.load_scene(path)


def test_shape_stagger_starts_contour_i_later(tmp_path) -> None:
    pieces = [[[0, 0], [2, 0], [2, 2], [0, 2]], [[5, 0], [7, 0], [7, 2], [5, 2]], [[10, 0], [12, 0], [12, 2], [10, 2]]]
    moved = [[[x, y + 10] for x, y in c] for c in pieces]
    path = tmp_path / "s.toml"
    path.write_text(f'[[shape]]\nname = "s"\nmethod = "linear"\nstagger = 0.5\n'
                    f'[[shape.key]]\ntime = 0\ncontours = {pieces}\n[[shape.key]]\ntime = 2\ncontours = {moved}\n')
    scene = tr.load_scene(path)
    for time in np.linspace(0, 2, 33):
        lows = [float(c[:, 1].min()) for c in tr.outlines(scene, float(time))]
        for i in range(3):
            begins = 0.5 * i
            u = min(max((time - begins) / (2 - begins), 0.0), 1.0)
            assert lows[i] == pytest.approx(10 * u, abs=1e-9)


def test_shape_stagger_must_fit(tmp_path) -> None:
    pieces = [[[0, 0], [2, 0], [2, 2], [0, 2]], [[5, 0], [7, 0], [7, 2], [5, 2]], [[10, 0], [12, 0], [12, 2], [10, 2]]]
    path = tmp_path / "s.toml"
    path.write_text(f'[[shape]]\nname = "s"\nstagger = 1\n'
                    f'[[shape.key]]\ntime = 0\ncontours = {pieces}\n[[shape.key]]\ntime = 2\ncontours = {pieces}\n')
    with pytest.raises(SceneError, match=r"s\.toml: shape\[0\]\.stagger \(line 3\): expected stagger × \(elements − 1\) "
                                         r"shorter than the segment \(2 s\), found 1 × 2 = 2 s \(the segment from "
                                         r"shape\[0\]\.key\[0\]\)"):
        tr.load_scene(path)


def test_check_json_carries_spacing_and_snapped_hints(tmp_path) -> None:
    from tweenrender.reports.check_report import scene_dict

    scene = tr.load_scene(_scene(tmp_path, "spacing = [0, 0.3, 1]\nhints = { a = [2, 0.05] }", "hints = { a = [12, 0] }"))
    key = scene_dict(scene, (0, 0, 1, 1))["shapes"][0]["keys"][0]
    assert key["ease"] == "spacing" and key["spacing"] == [0, 0.3, 1]
    assert key["hints"] == {"a": [2.0, 0.0]}


def test_json_scenes_take_the_controls_and_name_the_line(tmp_path) -> None:
    import json

    data = {"ease": "ease-out", "shape": [{"name": "s", "key": [
        {"time": 0, "points": SQ, "hints": {"a": [2, 0]}, "spacing": [0, 0.5, 1]},
        {"time": 2, "points": SQ2, "hints": {"a": [13, 0]}, "ease": "steps(3)"}]}]}
    path = tmp_path / "s.json"
    path.write_text(json.dumps(data, indent=1))
    scene = tr.load_scene(path)
    keys = scene.shapes[0].keys
    assert keys[0].ease == "spacing" and keys[1].ease == "steps(3)"
    data["shape"][0]["key"][1]["hints"] = {"a": [13, 3]}
    path.write_text(json.dumps(data, indent=1))
    with pytest.raises(SceneError, match=r"s\.json: shape\[0\]\.key\[1\]\.hints\.a \(line \d+\): expected a point "
                                         r"within 0\.113137"):
        tr.load_scene(path)


def test_drawing_hints_out_of_order(tmp_path) -> None:
    box = '<rect x="10" y="10" width="80" height="80"/>'
    _svg(tmp_path / "a.svg", box)
    _svg(tmp_path / "b.svg", box)
    path = tmp_path / "d.toml"
    path.write_text('[[drawing]]\ntime = 0\nsvg = "a.svg"\nhints = { a = [10, 10], b = [90, 10], c = [90, 90] }\n'
                    '[[drawing]]\ntime = 1\nsvg = "b.svg"\nhints = { a = [10, 10], b = [90, 90], c = [90, 10] }\n')
    with pytest.raises(SceneError, match=r"d\.toml: drawing\[1\]\.hints\.[abc]: expected hints [abc] and [abc] in the "
                                         r"same cyclic order on both keys' outlines \(counter-clockwise\), found them "
                                         r"swapped"):
        tr.load_scene(path)


def test_drawing_letter_on_neither_neighbour(tmp_path) -> None:
    box = '<rect x="10" y="10" width="80" height="80"/>'
    _svg(tmp_path / "a.svg", box)
    _svg(tmp_path / "b.svg", box)
    path = tmp_path / "d.toml"
    path.write_text('[[drawing]]\ntime = 0\nsvg = "a.svg"\nhints = { a = [10, 10] }\n'
                    '[[drawing]]\ntime = 1\nsvg = "b.svg"\nhints = { z = [10, 10] }\n')
    with pytest.raises(SceneError, match=r"drawing\[0\]\.hints\.a: expected hint a on the drawing before or after "
                                         r"too, found it on neither"):
        tr.load_scene(path)
