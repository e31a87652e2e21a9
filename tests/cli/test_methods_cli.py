"""The new methods and --balance through the command line and the library, as a user would name them."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tweenrender.core.methods.registry import METHODS

from ..helpers import SCENES, SQUARE, decode, run_main, write_scene


def test_stats_json_measures_every_method_with_the_documented_fields() -> None:
    done = run_main("stats", SCENES / "walk.toml", "--t", "0.25,0.5", "--json")
    assert done.returncode == 0, done.stderr
    stats = json.loads(done.stdout)
    fields = {"t", "perimeter", "perimeter_keys", "perimeter_mean", "ratio", "ratio_min", "ratio_max",
              "edge_error_max", "area_ratio", "angle_error_max", "self_intersects"}
    for entry in stats["shapes"]:
        assert set(entry["methods"]) == set(METHODS)  # the walk has joints: jointed too
        for method, measured in entry["methods"].items():
            assert fields <= set(measured), method
            assert len(measured["area_ratio"]) == 2 and isinstance(measured["self_intersects"], list)
        assert "closure_tweak_max" in entry["methods"]["intrinsic"]


def test_a_scene_without_joints_is_measured_without_jointed() -> None:
    stats = json.loads(run_main("stats", SCENES / "square.toml", "--json").stdout)
    assert set(stats["shapes"][0]["methods"]) == set(METHODS) - {"jointed"}


@pytest.mark.parametrize("method", ["arap", "intrinsic", "intrinsic-length"])
def test_render_with_a_new_method(tmp_path: Path, method: str) -> None:
    scene = write_scene(tmp_path, SQUARE)
    target = tmp_path / f"{method}.mp4"
    done = run_main("render", scene, "--method", method, "-o", target, "-q", "--fps", "6")
    assert done.returncode == 0, done.stderr
    meta, frames = decode(target)
    assert len(frames) == 13 and frames[0].shape == (240, 320, 3)


def test_sheet_rows_and_compare_panels_take_the_new_methods(tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE.replace("size = [320, 240]",
                                                 'size = [320, 240]\ncompare = ["arap", "intrinsic"]'))
    assert run_main("sheet", scene, "--methods", "linear,arap,intrinsic", "-o", tmp_path / "s.png").returncode == 0
    done = run_main("render", scene, "--compare", "-o", tmp_path / "c.mp4", "-q", "--fps", "4")
    assert done.returncode == 0, done.stderr
    assert decode(tmp_path / "c.mp4")[1][0].shape == (240, 640, 3)


def test_a_misspelt_balance_is_a_usage_error(tmp_path: Path) -> None:
    done = run_main("render", write_scene(tmp_path, SQUARE), "--balance", "spred", "-q")
    assert done.returncode == 2 and "--balance" in done.stderr and "Traceback" not in done.stderr


def test_balance_changes_what_is_drawn_and_keeps_the_keys(tmp_path: Path) -> None:
    scene = tr.load_scene(SCENES / "eight-to-three.toml")
    copies = tr.outlines(scene, 1.0, method="linear")[0]
    from tweenrender.plan.options import MatchSettings

    spread = tr.outlines(MatchSettings(balance="spread").over(scene), 1.0, method="linear")[0]
    assert not np.allclose(copies, spread)
    # at the last key the outline is the key as drawn, whichever rule placed the copies
    last_copies = tr.outlines(scene, 2.0)[0]
    last_spread = tr.outlines(MatchSettings(balance="spread").over(scene), 2.0)[0]
    from tweenrender.core.geometry import perimeter, signed_area

    assert float(perimeter(last_copies)) == pytest.approx(float(perimeter(last_spread)))
    assert float(signed_area(last_copies)) == pytest.approx(float(signed_area(last_spread)))
    target = tr.write(scene, tmp_path / "spread.gif", balance="spread", fps=4)
    assert target.is_file()
    with pytest.raises(tr.TweenrenderError, match="balance"):
        tr.write(scene, tmp_path / "x.gif", balance="spred")
