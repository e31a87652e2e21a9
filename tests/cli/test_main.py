"""The command line: the documented contracts, exit codes, output naming, untouched outputs on error."""

from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np
import pytest

from tests.helpers import SCENES, SQUARE, run_module, write_scene


def test_stats_json_reproduces_the_thesis_table(cli) -> None:
    code, out, err = cli("stats", SCENES / "square.toml", "--json")
    assert code == 0, err
    shape = json.loads(out)["shapes"][0]
    assert shape["vertices"] == [4, 4] and shape["balanced"] == 4 and shape["times"] == [0.0, 2.0]
    methods = shape["methods"]
    assert round(methods["linear"]["ratio"][0], 5) == 0.70711
    assert round(methods["nonlinear"]["ratio"][0], 5) == 1.00000
    assert methods["linear"]["perimeter_keys"] == [8.0, 8.0] and methods["linear"]["perimeter_mean"] == 8.0
    assert methods["linear"]["ratio_min"] == pytest.approx(np.sqrt(0.5)) and methods["linear"]["ratio_max"] == 1.0
    assert methods["linear"]["edge_error_max"] == pytest.approx(1 - np.sqrt(0.5))
    assert methods["rigid"]["ratio_min"] == pytest.approx(1.0)
    # linear at mid-turn: a square of side √2, area 2 of the keys' 4; nonlinear keeps the area
    assert methods["linear"]["area_ratio"] == [pytest.approx(0.5)]
    assert methods["nonlinear"]["area_ratio"] == [pytest.approx(1.0)]


def test_stats_text_speaks_like_the_thesis(cli) -> None:
    code, out, _ = cli("stats", SCENES / "rectangle.toml")
    assert code == 0
    assert "LINEAR METHOD" in out and "NONLINEAR METHOD" in out
    assert "Perimeter of Left Polygon  = 14.00000" in out
    assert "Ratio of Inbetween to Average = 0.70711" in out
    assert "Ratio of Inbetween to Average = 1.00000" in out


def test_stats_at_several_times(cli) -> None:
    code, out, _ = cli("stats", SCENES / "square.toml", "--json", "--t", "0,0.5,1")
    linear = json.loads(out)["shapes"][0]["methods"]["linear"]
    assert linear["t"] == [0.0, 0.5, 1.0]
    assert linear["ratio"][0] == pytest.approx(1.0) and linear["ratio"][2] == pytest.approx(1.0)


def test_check_json_shows_the_scene_as_loaded(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE)
    code, out, _ = cli("check", scene, "--json")
    data = json.loads(out)
    assert code == 0 and data["size"] == [320, 240] and data["fps"] == 24.0 and data["view"] == [-2, -2, 10, 7]
    key = data["shapes"][0]["keys"][1]
    assert key["time"] == 2.0 and key["points"] == [[7, 1], [7, 3], [5, 3], [5, 1]]
    assert data["balance"] == "copies" and data["shapes"][0]["balance"] == "copies"


def test_check_json_gives_each_shapes_balance(cli, tmp_path: Path) -> None:
    second = SQUARE[SQUARE.index("[[shape]]"):].replace('name = "sq"', 'name = "sq2"\nbalance = "copies"')
    two = SQUARE + second
    scene = write_scene(tmp_path, 'balance = "spread"\n' + two)
    data = json.loads(cli("check", scene, "--json")[1])
    assert data["balance"] == "spread"
    assert [shape["balance"] for shape in data["shapes"]] == ["spread", "copies"]


def test_check_many(cli) -> None:
    code, out, _ = cli("check", *sorted(SCENES.glob("*.toml")))
    assert code == 0 and out.count(": ok") == len(list(SCENES.glob("*.toml")))


def test_render_png_frames(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE)
    out = tmp_path / "frames"
    code, printed, err = cli("render", scene, "--format", "png", "-o", out, "-q")
    assert code == 0, err
    names = sorted(p.name for p in out.glob("*.png"))
    assert names == [f"frame_{i:04d}.png" for i in range(49)]  # 2 s at 24 fps, both keys included
    assert printed.strip() == str(out)
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]  # no temporaries left


def test_render_default_output_names(tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE, "sq.toml")
    result = run_module("render", scene, "--compare", "--frames", "0:3", "-q", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == os.path.join("output", "sq-compare.mp4")
    assert (tmp_path / "output" / "sq-compare.mp4").stat().st_size > 0
    result = run_module("render", scene, "--format", "png", "--frames", "5", "-q", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert sorted(p.name for p in (tmp_path / "output" / "sq").glob("*.png")) == ["frame_0000.png"]


BAD_USAGE = [
    ("render", "{scene}", "--method", "nonlinaer"),
    ("render", "{scene}", "--compare", "linear,bogus"),
    ("render", "{scene}", "--size", "12x"),
    ("render", "{scene}", "--size", "20000x100"),
    ("render", "{scene}", "--fps", "0"),
    ("render", "{scene}", "--frames", "100:200"),
    ("render", "{scene}", "--frames", "a:b"),
    ("render", "{scene}", "-o", "{tmp}/x.avi"),
    ("render", "{scene}", "--size", "321x240", "-o", "{tmp}/odd.mp4"),
    ("render", "{scene}", "--max-frames", "10"),
    ("stats", "{scene}", "--t", "2"),
    ("render", "{tmp}/missing.toml"),
    ("frobnicate",),
]


@pytest.mark.parametrize("args", BAD_USAGE, ids=[" ".join(a[:1] + a[2:]) for a in BAD_USAGE])
def test_bad_usage_exits_2_without_traceback(cli, tmp_path: Path, args: tuple[str, ...]) -> None:
    scene = write_scene(tmp_path, SQUARE)
    argv = [a.format(scene=scene, tmp=tmp_path) for a in args]
    code, _, err = cli(*argv, "-q") if argv[0] == "render" else cli(*argv)
    assert code == 2, err
    assert "Traceback" not in err and err.startswith("tweenrender: error: ") and err.count("\n") == 1


def test_bad_scene_leaves_existing_output_untouched(tmp_path: Path) -> None:
    good = write_scene(tmp_path, SQUARE, "good.toml")
    target = tmp_path / "movie.mp4"
    assert run_module("render", good, "-o", target, "--frames", "0:2", "-q").returncode == 0
    before = target.read_bytes()
    bad = write_scene(tmp_path, SQUARE.replace("time = 2", "time = -2"), "bad.toml")
    result = run_module("render", bad, "-o", target, "-q")
    assert result.returncode == 2
    assert "bad.toml: shape[0].key[1].time (line 9)" in result.stderr and "Traceback" not in result.stderr
    assert target.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.toml", "good.toml", "movie.mp4"]


def test_encoder_failure_exits_1_and_keeps_the_old_file(cli, tmp_path: Path, monkeypatch) -> None:
    scene = write_scene(tmp_path, SQUARE)
    target = tmp_path / "movie.mp4"
    target.write_bytes(b"precious")
    from dataclasses import replace

    from tweenrender.encode import formats

    broken = replace(formats.TABLE["mp4"], ffmpeg=("-c:v", "no-such-codec", "-f", "mp4"))
    monkeypatch.setitem(formats.TABLE, "mp4", broken)
    code, _, err = cli("render", scene, "-o", target, "--frames", "0:2", "-q")
    assert code == 1
    assert "ffmpeg" in err and "no-such-codec" in err
    assert target.read_bytes() == b"precious"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["movie.mp4", "scene.toml"]


def test_help_imports_neither_skia_nor_ffmpeg() -> None:
    import subprocess
    import sys

    code = ("import sys; from tweenrender.cli.main import main\n"
            "try:\n    main(['--help'])\nexcept SystemExit:\n    pass\n"
            "print(sorted(m for m in ('skia', 'imageio_ffmpeg', 'imageio', 'numba') if m in sys.modules))")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert result.stdout.strip().splitlines()[-1] == "[]"


def test_check_reports_every_bad_scene_and_goes_on(cli, tmp_path: Path) -> None:
    good = write_scene(tmp_path, SQUARE, "good.toml")
    bad = write_scene(tmp_path, SQUARE.replace("time = 2", "time = -2"), "bad.toml")
    worse = write_scene(tmp_path, "size = [1, 2, 3]\n", "worse.toml")
    code, out, err = cli("check", bad, good, worse)
    assert code == 2
    assert out.strip() == f"{good}: ok (1 shape, 2 keys, 2 s at 24 fps)"
    assert err.count("tweenrender: error: ") == 2 and "bad.toml: shape[0].key[1].time" in err
    assert "worse.toml: size (line 1)" in err
