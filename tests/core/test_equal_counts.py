"""Keys of equal vertex counts: the drawn order by default, the least-work search on request."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from tweenrender.core.geometry import area
from tweenrender.core.timing.timeline import build_track
from tweenrender.errors import SceneError
from tweenrender.scenefile import load_scene

from tests.helpers import SCENES, SQUARE, write_scene


def _mid_frame_area_ratio(scene_path: Path, equal_counts: str) -> float:
    scene = load_scene(scene_path)
    shape = scene.shapes[0]
    track = build_track(shape, replace(scene.matching, equal_counts=equal_counts))
    mid = track.at(np.array([0.5 * (shape.keys[0].time + shape.keys[1].time)]), "linear")[0].contours[0]
    keys = 0.5 * (area(shape.keys[0].points) + area(shape.keys[1].points))
    return float(area(mid) / keys)


def test_mirrored_brace_flattens_in_drawn_order_and_not_when_matched() -> None:
    # Each vertex of the left brace is drawn against its mirror image: the linear
    # mid-frame of mirror pairs lies on the mirror's axis, a shape of no area.
    assert _mid_frame_area_ratio(SCENES / "braces.toml", "drawn") == pytest.approx(0.0, abs=1e-9)
    assert _mid_frame_area_ratio(SCENES / "braces.toml", "match") > 0.3


def test_drawn_order_is_the_default_and_keeps_the_thesis_turn(cli) -> None:
    code, out, _ = cli("correspond", SCENES / "square.toml", "--json")
    entry = json.loads(out)["shapes"][0]
    assert code == 0 and entry["matched"] == "drawn order" and entry["equal_counts"] == "drawn"
    assert entry["pairs"] == [[0, 0], [1, 1], [2, 2], [3, 3]]


def test_match_searches_equal_counts_too(cli) -> None:
    # Centroid-aligned, the turned square coincides with the first one shifted by one
    # vertex: the least-work path pairs each vertex with the one at the same place (work 0).
    code, out, _ = cli("correspond", SCENES / "square.toml", "--json", "--equal-counts", "match")
    entry = json.loads(out)["shapes"][0]
    assert code == 0 and entry["matched"] == "minimal work" and entry["work"] == pytest.approx(0.0, abs=1e-12)
    a = np.array([[0, 0], [2, 0], [2, 2], [0, 2]], float)
    b = np.array([[7, 1], [7, 3], [5, 3], [5, 1]], float)
    pairs = np.array(entry["pairs"])
    assert np.allclose(a[pairs[:, 0]] - a.mean(0), b[pairs[:, 1]] - b.mean(0))


def test_scene_key_and_its_errors(tmp_path: Path) -> None:
    good = write_scene(tmp_path, SQUARE + "[correspondence]\nequal_counts = \"match\"\n", "good.toml")
    assert load_scene(good).matching.equal_counts == "match"
    bad = write_scene(tmp_path, SQUARE + "[correspondence]\nequal_counts = \"mach\"\n", "bad.toml")
    with pytest.raises(SceneError, match=r"correspondence\.equal_counts \(line 12\).*did you mean 'match'"):
        load_scene(bad)


def test_render_flag(cli, tmp_path: Path) -> None:
    target = tmp_path / "frames"
    code, _, err = cli("render", SCENES / "braces.toml", "--equal-counts", "match", "--frames", "24",
                       "--format", "png", "-o", target, "-q", "--size", "160x90")
    assert code == 0, err
    assert [p.name for p in target.glob("frame_*.png")] == ["frame_0000.png"]
