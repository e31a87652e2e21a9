"""The preview's edits applied to a scene's TOML text: what each op writes (read back with tomllib), that
nothing else of the file changes (the user's comments byte for byte), that the loader checks the result,
and that a hint placed by an edit forces the correspondence it names (the project's own correspond)."""

from __future__ import annotations

import difflib
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest

from tests.helpers import SCENES
from tweenrender import api
from tweenrender.errors import SceneError
from tweenrender.scenefile.scene_edits import apply_edits

ARROW = SCENES / "arrow-hints.toml"

SQUARES = """# two squares; the comments are the user's
title = "squares"   # a title
method = "linear"

[[shape]]   # the only shape
name = "box"
fill = "#3b6fd8"

# the first key
[[shape.key]]
time = 0.0
points = [[0, 0], [4, 0], [4, 4], [0, 4]]   # counter-clockwise
{extra0}
[[shape.key]]
time = {t1}
points = [[8, 0], [12, 0], [12, 4], [8, 4]]
{extra1}"""


def _squares(tmp_path: Path, extra0: str = "", extra1: str = "", t1: str = "2.0") -> tuple[str, Path]:
    path = tmp_path / "squares.toml"
    text = SQUARES.format(extra0=extra0, extra1=extra1, t1=t1)
    path.write_text(text)
    return text, path


def _unhinted_arrow() -> str:
    return re.sub(r"^hints = .*\n", "", ARROW.read_text(), flags=re.M)


def _only_insertions(before: str, after: str) -> list[str]:
    """The lines ``after`` adds to ``before``; fails when any line of ``before`` changed or went."""
    matcher = difflib.SequenceMatcher(a=before.splitlines(keepends=True), b=after.splitlines(keepends=True),
                                      autojunk=False)
    added = []
    for tag, i1, i2, j1, j2 in matcher.get_opcodes():
        assert tag in ("equal", "insert"), (tag, before.splitlines()[i1:i2], after.splitlines()[j1:j2])
        if tag == "insert":
            added.extend(after.splitlines()[j1:j2])
    return added


def test_a_hint_on_both_keys_is_written_and_every_other_byte_kept() -> None:
    text = _unhinted_arrow()
    ops = [{"op": "hint", "shape": "arrow", "key": 0, "letter": "a", "point": [2.5714, 0]},
           {"op": "hint", "shape": "arrow", "key": 1, "letter": "a", "point": [6.7731, 1.2857]}]
    edited = api.edit_scene_text(text, ARROW, ops)
    added = _only_insertions(text, edited)
    assert len(added) == 2 and all(line.startswith("hints = ") for line in added)
    keys = tomllib.loads(edited)["shape"][0]["key"]
    assert keys[0]["hints"] == {"a": [2.5714, 0]} and keys[1]["hints"] == {"a": [6.7731, 1.2857]}
    assert text.splitlines()[:5] == edited.splitlines()[:5]  # the file's comment block, byte for byte


def _pairs(text: str) -> set[tuple[int, int]]:
    report = api.correspondence(api.parse_scene(text, ARROW))
    return {tuple(pair) for pair in report["shapes"][0]["pairs"]}


def test_hints_placed_by_edits_force_the_correspondence_they_name() -> None:
    text = _unhinted_arrow()
    # the scene file's own coordinates: the tip is vertex 3 of key 0 and vertex 4 of key 1; the tail's
    # corners are vertices 0 and 6 of key 0, vertices 0 and 7 of key 1
    tip = (3, 4)
    assert tip not in _pairs(text)  # unhinted, the least-work pairing takes the tip elsewhere
    ops = []
    for letter, first, second in (("a", [2.5714, 0], [6.7731, 1.2857]), ("b", [-2.4286, -0.5], [11.3532, -0.7813]),
                                  ("c", [-2.4286, 0.5], [10.8532, -1.6473])):
        ops += [{"op": "hint", "shape": "arrow", "key": 0, "letter": letter, "point": first},
                {"op": "hint", "shape": "arrow", "key": 1, "letter": letter, "point": second}]
    pairs = _pairs(api.edit_scene_text(text, ARROW, ops))
    assert {tip, (0, 0), (6, 7)} <= pairs


def test_unhint_takes_back_exactly_what_hint_wrote() -> None:
    text = _unhinted_arrow()
    placed = api.edit_scene_text(text, ARROW, [
        {"op": "hint", "shape": "arrow", "key": k, "letter": "q", "point": p}
        for k, p in ((0, [2.5714, 0]), (1, [6.7731, 1.2857]))])
    removed = api.edit_scene_text(placed, ARROW, [{"op": "unhint", "shape": "arrow", "key": k, "letter": "q"}
                                                  for k in (0, 1)])
    assert removed == text



def test_unhint_takes_its_arc_with_it(tmp_path: Path) -> None:
    """An arc belongs to its hint (DESIGN, "The preview edits"): unhinting the letter leaves no arc of it."""
    hinted = "hints = {a = [4, 0], b = [0, 4]}\narcs = {a = [6, 3]}\n"
    text, path = _squares(tmp_path, extra0=hinted, extra1="hints = {a = [12, 0], b = [8, 4]}\n")
    edited = api.edit_scene_text(text, path, [{"op": "unhint", "shape": "box", "key": k, "letter": "a"}
                                              for k in (0, 1)])
    first, second = tomllib.loads(edited)["shape"][0]["key"]
    assert first["hints"] == {"b": [0, 4]} and second["hints"] == {"b": [8, 4]} and "arcs" not in first


def test_moving_a_hint_rewrites_its_point_only() -> None:
    text = ARROW.read_text()
    moved = api.edit_scene_text(text, ARROW, [{"op": "hint", "shape": "arrow", "key": 0, "letter": "a",
                                               "point": [1.5714, 0.75]}])
    changed = [(a, b) for a, b in zip(text.splitlines(), moved.splitlines()) if a != b]
    assert len(changed) == 1 and len(text.splitlines()) == len(moved.splitlines())
    assert tomllib.loads(moved)["shape"][0]["key"][0]["hints"] == {"a": [1.5714, 0.75], "b": [-2.4286, -0.5],
                                                                   "c": [-2.4286, 0.5]}


def test_ease_replaces_a_spacing_chart_and_the_loader_checks_it(tmp_path: Path) -> None:
    text, path = _squares(tmp_path, extra0="spacing = [0, 0.1, 0.5, 1]   # my chart\n")
    edited = api.edit_scene_text(text, path, [{"op": "ease", "shape": "box", "key": 0,
                                               "ease": "cubic-bezier(0.3, 0, 0.2, 1.4)"}])
    key = tomllib.loads(edited)["shape"][0]["key"][0]
    assert key["ease"] == "cubic-bezier(0.3, 0, 0.2, 1.4)" and "spacing" not in key
    assert api.parse_scene(edited, path).shapes[0].keys[0].ease == "cubic-bezier(0.3, 0, 0.2, 1.4)"
    with pytest.raises(SceneError) as refused:
        api.edit_scene_text(text, path, [{"op": "ease", "shape": "box", "key": 0, "ease": "cubic-bezier(1.5, 0, 0, 1)"}])
    message = str(refused.value)
    assert "\n" not in message and "squares.toml" in message and "shape[0].key[0].ease" in message


@pytest.mark.parametrize("favour", [0.25, 0.5, 1.0])
def test_bake_writes_the_linear_in_between_at_the_favour(tmp_path: Path, favour: float) -> None:
    """Two squares apart by (8, 0) under `linear`: the in-between at f is the keys' weighted mean."""
    text, path = _squares(tmp_path, extra0="ease = \"in-out\"   # baked without it\n",
                          extra1="\n[[shape.key]]\ntime = 3.0\npoints = [[8, 0], [12, 0], [12, 4], [8, 4]]\n",
                          t1=f"1.0\nbreakdown = {favour}\n\n[[shape.key]]\ntime = 2.0")
    # the breakdown key (index 1) splits the first segment; baking it needs no loader support for it
    edited = api.edit_scene_text(text, path, [{"op": "bake", "shape": "box", "key": 1}])
    key = tomllib.loads(edited)["shape"][0]["key"][1]
    assert "breakdown" not in key
    a = np.array([[0, 0], [4, 0], [4, 4], [0, 4]], float)
    expected = (1 - favour) * a + favour * (a + [8, 0])
    got = np.array(key["points"], float)
    assert got.shape == (4, 2)
    rolled = [np.roll(got, s, axis=0) for s in range(4)]  # the same outline, whichever vertex comes first
    assert min(np.abs(r - expected).max() for r in rolled) < 1e-9
    assert _only_insertions(text.replace(f"breakdown = {favour}\n", ""), edited) == [f"points = {key_line(key)}"]


def test_a_baked_breakdown_keeps_a_shared_hint_where_it_falls_between_its_two_places(tmp_path: Path) -> None:
    """Hint a sits at the middle of the bottom edge in both keys, (2, 0) and (10, 0); baked at favour 0.5, the
    square is [4, 8] × [0, 4] and the hint the baked outline's point nearest (6, 0): (6, 0) itself."""
    text, path = _squares(tmp_path, extra0="hints = {a = [2, 0]}\n", extra1="hints = {a = [10, 0]}\n",
                          t1="1.0\nbreakdown = 0.5\n\n[[shape.key]]\ntime = 2.0")
    edited = api.edit_scene_text(text, path, [{"op": "bake", "shape": "box", "key": 1}])
    key = tomllib.loads(edited)["shape"][0]["key"][1]
    assert np.allclose(key["hints"]["a"], [6.0, 0.0], atol=1e-9), key["hints"]


def key_line(key: dict) -> str:
    return "[" + ", ".join(f"[{_n(x)}, {_n(y)}]" for x, y in key["points"]) + "]"


def _n(value: float) -> str:
    return str(int(value)) if float(value).is_integer() else repr(value)


def test_the_steering_fields_are_written_as_design_names_them(tmp_path: Path) -> None:
    """Text only: ``turn``/``turns``, ``arcs`` and a breakdown key (the loader checks them where it knows them)."""
    text, path = _squares(tmp_path)
    edited = apply_edits(text, path, [
        {"op": "hint", "shape": "box", "key": 0, "letter": "a", "point": [4, 4]},
        {"op": "arc", "shape": "box", "key": 0, "letter": "a", "point": [7, 9]},
        {"op": "turn", "shape": "box", "key": 0, "turn": "cw", "turns": 1},
        {"op": "breakdown", "shape": "box", "key": 0, "time": 0.5, "breakdown": 0.75}])
    keys = tomllib.loads(edited)["shape"][0]["key"]
    assert keys[0]["arcs"] == {"a": [7, 9]} and keys[0]["turn"] == "cw" and keys[0]["turns"] == 1
    assert keys[1] == {"time": 0.5, "breakdown": 0.75}
    assert [k["time"] for k in keys] == [0.0, 0.5, 2.0]
    _only_insertions(text, edited)
    again = apply_edits(edited, path, [{"op": "turn", "shape": "box", "key": 0, "turn": "shortest", "turns": 0},
                                       {"op": "arc", "shape": "box", "key": 0, "letter": "a", "point": None},
                                       {"op": "breakdown", "shape": "box", "key": 1, "breakdown": 1.25}])
    keys = tomllib.loads(again)["shape"][0]["key"]
    assert not {"turn", "turns", "arcs"} & keys[0].keys() and keys[1]["breakdown"] == 1.25


@pytest.mark.parametrize("op, where", [
    ({"op": "hnt", "shape": "box", "key": 0}, "ops[0].op"),
    ({"op": "hint", "shape": 3, "key": 0}, "ops[0].shape"),
    ({"op": "hint", "shape": "box", "key": "0"}, "ops[0].key"),
    ({"op": "hint", "shape": "box", "key": 9, "letter": "a", "point": [0, 0]}, "ops[0].key"),
    ({"op": "hint", "shape": "box", "key": 2, "letter": "a", "point": [0, 0]}, "ops[0].key"),  # keys 0 and 1
    ({"op": "hint", "shape": "box", "key": -1, "letter": "a", "point": [0, 0]}, "ops[0].key"),
    ({"op": "hint", "shape": "box", "key": 0, "letter": "A", "point": [0, 0]}, "ops[0].letter"),
    ({"op": "hint", "shape": "box", "key": 0, "letter": "ab", "point": [0, 0]}, "ops[0].letter"),
    ({"op": "hint", "shape": "box", "key": 0, "letter": "a", "point": [0, float("nan")]}, "ops[0].point"),
    ({"op": "unhint", "shape": "box", "key": 0, "letter": "z"}, "ops[0].letter"),
    ({"op": "turn", "shape": "box", "key": 0, "turn": "left"}, "ops[0].turn"),
    ({"op": "turn", "shape": "box", "key": 0, "turn": "cw", "turns": -1}, "ops[0].turns"),
    ({"op": "bake", "shape": "box", "key": 0}, "ops[0].key"),
    ({"op": "breakdown", "shape": "box", "key": 0, "time": "soon", "breakdown": 0.5}, "ops[0].time"),
    ("hint", "ops[0]"),
])
def test_an_op_that_is_not_one_is_one_line_naming_it(tmp_path: Path, op: object, where: str) -> None:
    text, path = _squares(tmp_path)
    with pytest.raises(SceneError) as refused:
        api.edit_scene_text(text, path, [op])
    message = str(refused.value)
    assert "\n" not in message and message.startswith(f"{path}: {where}:"), message


def test_no_ops_and_json_scenes_are_refused(tmp_path: Path) -> None:
    text, path = _squares(tmp_path)
    for ops in ([], None, {"op": "hint"}):
        with pytest.raises(SceneError, match="ops"):
            api.edit_scene_text(text, path, ops)
    with pytest.raises(SceneError, match="JSON"):
        api.edit_scene_text("{}", tmp_path / "scene.json", [{"op": "ease"}])



def test_the_scene_of_drawings_reads_back_its_names_and_times_exactly(tmp_path: Path) -> None:
    """The names ``init`` writes are read back by TOML as the files' own (quotes and backslashes
    included), relative to the scene's folder; the times are i × (step + hold) to the last bit."""
    folder = tmp_path / "art"
    folder.mkdir()
    names = ['say "hi".svg', "back\\slash.svg", "plain.svg"]
    svgs = [folder / name for name in names]
    step, hold = 1.0 / 3.0, 0.1
    data = tomllib.loads(api.drawings_scene_text(svgs, tmp_path, step, hold=hold))
    assert [d["svg"] for d in data["drawing"]] == [f"art/{name}" for name in names]
    assert [d["time"] for d in data["drawing"]] == [i * (step + hold) for i in range(3)]
    assert [d["hold"] for d in data["drawing"]] == [hold] * 3


def test_the_scene_of_drawings_draws_what_the_command_line_draws(tmp_path: Path) -> None:
    svgs = [SCENES / "svg" / name for name in sorted(p.name for p in (SCENES / "svg").glob("*.svg"))[:2]]
    for timing in ({}, {"ease": "in-out", "stagger": 0.1}):
        text = api.drawings_scene_text(svgs, tmp_path, 1.5, **timing)
        written = api.parse_scene(text, tmp_path / "scene.toml")
        given = api.load_scene(svgs, 1.5, **timing)
        assert written.duration == pytest.approx(given.duration)
        for time in np.linspace(0, given.duration, 7):
            a, b = api.outlines(written, float(time)), api.outlines(given, float(time))
            assert len(a) == len(b)
            assert max(np.abs(p - q).max() for p, q in zip(a, b)) < 1e-9, (timing, time)
