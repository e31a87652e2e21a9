"""The JSON reports on shapes of several contours: check carries contours and closed flags,
correspond and stats one entry per contour, each naming its contour."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.helpers import write_scene

RING = """
[[shape]]
name = "ring"
[[shape.key]]
time = 0
contours = [[[0, 0], [4, 0], [4, 4], [0, 4]], [[1, 1], [1, 3], [3, 3], [3, 1]]]
[[shape.key]]
time = 2
contours = [[[10, 0], [14, 0], [14, 4], [10, 4]], [[11, 1], [11, 3], [13, 3], [12, 1], [13, 1.5]]]

[[shape]]
name = "tick"
closed = false
stroke = "#000000"
[[shape.key]]
time = 0
points = [[0, 6], [1, 5], [3, 8]]
[[shape.key]]
time = 2
points = [[10, 6], [11, 5], [13, 8]]

[[shape]]
name = "plain"
[[shape.key]]
time = 0
points = [[0, 10], [1, 10], [1, 11]]
"""


@pytest.fixture
def ring(tmp_path: Path) -> Path:
    return write_scene(tmp_path, RING)


def test_check_json_carries_contours_and_closed_only_where_needed(cli, ring: Path) -> None:
    import json

    code, out, err = cli("check", ring, "--json")
    assert code == 0, err
    shapes = {s["name"]: s for s in json.loads(out)["shapes"]}
    key = shapes["ring"]["keys"][0]
    assert key["contours"][1] == [[1, 1], [1, 3], [3, 3], [3, 1]] and key["closed"] == [True, True]
    assert key["points"] == [[0, 0], [4, 0], [4, 4], [0, 4]]
    assert shapes["tick"]["keys"][1]["closed"] == [False] and shapes["tick"]["keys"][1]["fill"] is None
    assert "contours" not in shapes["plain"]["keys"][0] and shapes["plain"]["keys"][0]["fill"] == "#3b6fd8ff"


def test_correspond_json_has_an_entry_per_contour(cli, ring: Path) -> None:
    import json

    code, out, err = cli("correspond", ring, "--json")
    assert code == 0, err
    entries = json.loads(out)["shapes"]
    ring_entries = [e for e in entries if e["name"] == "ring"]
    assert [e["contour"] for e in ring_entries] == [0, 1]
    assert ring_entries[1]["counts"] == [4, 5] and ring_entries[1]["key_contours"] == [1, 1]
    assert ring_entries[1]["balanced"] == len(ring_entries[1]["pairs"]) >= 5
    tick = next(e for e in entries if e["name"] == "tick")
    assert "contour" not in tick and tick["closed"] is False
    # a translated stroke: vertex i goes with vertex i, 10 units each after centring → work 0
    assert tick["pairs"] == [[0, 0], [1, 1], [2, 2]] and tick["minimal_work"] == pytest.approx(0.0, abs=1e-9)


def test_stats_measures_each_closed_contour(cli, ring: Path) -> None:
    import json

    code, out, err = cli("stats", ring, "--json")
    assert code == 0, err
    entries = json.loads(out)["shapes"]
    assert [(e["name"], e.get("contour")) for e in entries] == [("ring", 0), ("ring", 1)]
    outer = entries[0]["methods"]["linear"]
    assert outer["perimeter_keys"] == [16.0, 16.0] and outer["ratio"] == [pytest.approx(1.0)]  # a slide


def test_stats_measure_a_contour_as_it_is_drawn(cli, tmp_path: Path) -> None:
    """An off-centre hole that grows while its shape turns a quarter: its perimeter in stats is that of
    the hole the renderer draws (moving about the whole shape's center), not of the hole on its own."""
    import json

    import numpy as np

    import tweenrender as tr

    scene = write_scene(tmp_path, """method = "nonlinear"
[[shape]]
name = "plate"
[[shape.key]]
time = 0
contours = [[[0, 0], [6, 0], [6, 4], [0, 4]], [[4, 1], [4, 3], [5, 3], [5, 1]]]
[[shape.key]]
time = 1
contours = [[[0, 0], [0, 6], [-4, 6], [-4, 0]], [[-1, 3], [-3.5, 3], [-3.5, 5.5], [-1, 5.5]]]
""", "plate.toml")
    code, out, err = cli("stats", scene, "--json", "--t", "0.3")
    assert code == 0, err
    hole = next(e for e in json.loads(out)["shapes"] if e.get("contour") == 1)
    drawn = tr.outlines(tr.load_scene(scene), 0.3, method="nonlinear")[1]
    assert hole["methods"]["nonlinear"]["perimeter"][0] == pytest.approx(
        float(np.linalg.norm(np.roll(drawn, -1, axis=0) - drawn, axis=1).sum()), rel=1e-12)
