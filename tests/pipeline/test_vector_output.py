"""Vector output (Lottie JSON, animated SVG): what the files hold, read back independently of the writer.

The bound is checked by playing the keyframes as a player does (np.interp per coordinate) against
the exact outlines ``tr.outlines`` gives, mapped to pixels by hand (each scene's view fills its
frame exactly, so a scene unit is a known number of pixels, y flipped).
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tweenrender.errors import OptionError
from tests.helpers import run_module, write_scene

# 400 × 300 pixels over the view [0, 0, 40, 30]: 10 pixels a unit, pixel = (10 x, 300 - 10 y)
TURN = """size = [400, 300]
fps = 20
view = [0, 0, 40, 30]
background = "#ffffff"
method = "{method}"
[[shape]]
name = "bar"
fill = "#3366cc"
fill_rule = "{rule}"
[[shape.key]]
time = 0
ease = "{ease}"
contours = [[[10, 13], [30, 13], [30, 17], [10, 17]], [[12, 14], [14, 14], [14, 16], [12, 16]]]
[[shape.key]]
time = 2
contours = [[[22, 5], [22, 25], [18, 25], [18, 5]], [[21, 7], [21, 9], [19, 9], [19, 7]]]
"""


def _pixels(points: np.ndarray) -> np.ndarray:
    return np.stack([10 * points[:, 0], 300 - 10 * points[:, 1]], axis=1)


def _turn(tmp_path: Path, method: str = "rigid", ease: str = "linear", rule: str = "evenodd") -> tr.Scene:
    return tr.load_scene(write_scene(tmp_path, TURN.format(method=method, ease=ease, rule=rule)))


def _shape_layers(document: dict) -> list[dict]:
    return [layer for layer in document["layers"] if layer["nm"] != "background"]


def _items(layer: dict, kind: str) -> list[dict]:
    return [item for item in layer["shapes"][0]["it"] if item["ty"] == kind]


def _played(prop: dict, frame: int) -> np.ndarray:
    """A path property's vertices at ``frame``, interpolated straight between keyframes (hold outside)."""
    if prop["a"] == 0:
        return np.array(prop["k"]["v"], dtype=float)
    keys = prop["k"]
    times = [k["t"] for k in keys]
    values = np.array([k["s"][0]["v"] for k in keys], dtype=float)  # (K, L, 2)
    out = np.empty(values.shape[1:])
    for index in np.ndindex(values.shape[1:]):
        out[index] = np.interp(frame, times, values[(slice(None), *index)])
    return out


@pytest.mark.parametrize("method", ["rigid", "nonlinear", "arap"])
def test_baked_paths_stay_within_the_bound_at_every_frame(tmp_path: Path, method: str) -> None:
    scene = _turn(tmp_path, method)
    target = tr.write(scene, tmp_path / "turn.json")
    document = json.loads(target.read_text())
    assert (document["w"], document["h"], document["fr"], document["ip"], document["op"]) == (400, 300, 20, 0, 41)
    (layer,) = _shape_layers(document)
    paths = _items(layer, "sh")
    assert len(paths) == 2  # the outline and its hole, siblings in one group
    worst = 0.0
    for frame in range(41):
        exact = tr.outlines(scene, frame / 20, method=method)
        for path, contour in zip(paths, exact):
            worst = max(worst, float(np.linalg.norm(_played(path["ks"], frame) - _pixels(contour), axis=1).max()))
    assert worst <= 0.25 + 0.001  # the bound, plus the thousandth the file rounds to
    keyframes = len(paths[0]["ks"]["k"])
    assert 2 < keyframes <= 41 // 2  # a quarter turn is curved, yet at least 2× fewer keyframes than frames
    for path in paths:  # one vertex count over all the path's keyframes
        assert len({len(k["s"][0]["v"]) for k in path["ks"]["k"]}) == 1


def test_a_tighter_bound_takes_more_keyframes_and_holds(tmp_path: Path) -> None:
    scene = _turn(tmp_path, "rigid")
    counts = {}
    for bound in (1.0, 0.05):
        document = json.loads(tr.write(scene, tmp_path / f"t{bound}.json", max_error=bound).read_text())
        path = _items(_shape_layers(document)[0], "sh")[0]
        counts[bound] = len(path["ks"]["k"])
        worst = max(float(np.linalg.norm(_played(path["ks"], f) - _pixels(tr.outlines(scene, f / 20)[0]),
                                         axis=1).max()) for f in range(41))
        assert worst <= bound + 0.001
    assert counts[0.05] > counts[1.0]


@pytest.mark.parametrize("ease, handles", [("linear", (0, 0, 1, 1)), ("in-out", (1 / 3, 0, 2 / 3, 1)),
                                           ("in", (1 / 3, 0, 2 / 3, 1 / 3))])
def test_linear_two_keys_export_one_keyframe_per_key_with_the_easing_as_handles(tmp_path: Path, ease: str,
                                                                                handles: tuple) -> None:
    scene = _turn(tmp_path, "linear", ease)
    document = json.loads(tr.write(scene, tmp_path / "lin.json").read_text())
    for path in _items(_shape_layers(document)[0], "sh"):
        keys = path["ks"]["k"]
        assert [k["t"] for k in keys] == [0, 40]
        x1, y1, x2, y2 = handles
        assert keys[0]["o"]["x"][0] == pytest.approx(x1) and keys[0]["o"]["y"][0] == pytest.approx(y1)
        assert keys[0]["i"]["x"][0] == pytest.approx(x2) and keys[0]["i"]["y"][0] == pytest.approx(y2)
    # the handles draw the easing: cubic-bezier(x1, y1, x2, y2) at x = 0.3 against the closed form
    def bezier(u: float, p1: float, p2: float) -> float:
        return 3 * (1 - u) ** 2 * u * p1 + 3 * (1 - u) * u ** 2 * p2 + u ** 3

    low, high = 0.0, 1.0
    for _ in range(60):  # bisection for x(u) = 0.3
        mid = (low + high) / 2
        low, high = (mid, high) if bezier(mid, x1, x2) < 0.3 else (low, mid)
    y = bezier(low, y1, y2)
    x = 0.3
    closed_form = {"linear": x, "in-out": x * x * (3 - 2 * x), "in": x * x}[ease]
    assert y == pytest.approx(closed_form)
    svg = tr.write(scene, tmp_path / "lin.svg").read_text()
    d = re.search(r'<animate attributeName="d"[^>]*>', svg).group(0)
    assert len(re.search(r'values="([^"]*)"', d).group(1).split(";")) == 3  # the two keys, the last held to the end
    if ease != "linear":
        assert 'calcMode="spline"' in d and " ".join(f"{v:.4f}".rstrip("0").rstrip(".") for v in handles) in d


def test_fill_rule_holes_and_paint(tmp_path: Path) -> None:
    for rule, code in (("evenodd", 2), ("nonzero", 1)):
        scene = _turn(tmp_path, "rigid", rule=rule)
        document = json.loads(tr.write(scene, tmp_path / f"{rule}.json").read_text())
        (fill,) = _items(_shape_layers(document)[0], "fl")
        assert fill["r"] == code
        assert fill["c"]["k"][:3] == pytest.approx([0x33 / 255, 0x66 / 255, 0xcc / 255], abs=1e-4)
        assert f'fill-rule="{rule}"' in tr.write(scene, tmp_path / f"{rule}.svg").read_text()


def test_background_layer_unless_none(tmp_path: Path) -> None:
    scene = _turn(tmp_path)
    with_background = json.loads(tr.write(scene, tmp_path / "a.json").read_text())
    assert with_background["layers"][-1]["nm"] == "background"  # the last layer is drawn first
    without = json.loads(tr.write(scene, tmp_path / "b.json", background="none").read_text())
    assert all(layer["nm"] != "background" for layer in without["layers"])
    assert "<rect" in tr.write(scene, tmp_path / "a.svg").read_text()
    assert "<rect" not in tr.write(scene, tmp_path / "b.svg", background="none").read_text()


def test_frames_a_to_b_start_the_clip_at_zero(tmp_path: Path) -> None:
    scene = _turn(tmp_path)
    document = json.loads(tr.write(scene, tmp_path / "part.json", frames="10:30").read_text())
    assert (document["ip"], document["op"]) == (0, 20)
    path = _items(_shape_layers(document)[0], "sh")[0]
    for frame in (0, 7, 19):
        exact = _pixels(tr.outlines(scene, (frame + 10) / 20)[0])
        assert np.linalg.norm(_played(path["ks"], frame) - exact, axis=1).max() <= 0.251
    svg = tr.write(scene, tmp_path / "part.svg", frames="10:30").read_text()
    assert 'dur="1s"' in svg  # 20 frames at 20 fps


def test_several_keys_split_layers_at_the_keys(tmp_path: Path) -> None:
    text = TURN.format(method="linear", ease="linear", rule="nonzero") + """[[shape.key]]
time = 3
contours = [[[10, 13], [30, 13], [30, 17], [10, 17]], [[12, 14], [14, 14], [14, 16], [12, 16]]]
"""
    scene = tr.load_scene(write_scene(tmp_path, text))
    document = json.loads(tr.write(scene, tmp_path / "keys.json").read_text())
    layers = _shape_layers(document)
    # about half a frame early (rlottie rounds ip and op, and draws frame op; lottie-web and ThorVG do not)
    assert sorted((layer["ip"], layer["op"]) for layer in layers) == [(0, 40 - 0.501), (40 - 0.499, 61)]
    for layer in layers:  # each segment exact: its own two keys
        assert [len(p["ks"]["k"]) for p in _items(layer, "sh")] == [2, 2]


def test_cli_writes_what_the_library_writes(tmp_path: Path) -> None:
    scene_path = write_scene(tmp_path, TURN.format(method="rigid", ease="in-out", rule="evenodd"))
    for suffix, fmt in ((".json", "lottie"), (".svg", "svg")):
        by_cli = tmp_path / f"cli{suffix}"
        done = run_module("render", scene_path, "--format", fmt, "-o", by_cli, "-q", cwd=tmp_path)
        assert done.returncode == 0, done.stderr
        by_library = tr.write(tr.load_scene(scene_path), tmp_path / f"lib{suffix}")
        assert by_cli.read_text().replace("cli", "lib") == by_library.read_text()
    done = run_module("render", scene_path, "--format", "lottie", "-q", cwd=tmp_path)
    assert done.returncode == 0 and (tmp_path / "output" / "scene.json").is_file()
    done = run_module("render", scene_path, "--format", "svg", "-q", cwd=tmp_path)
    assert done.returncode == 0 and (tmp_path / "output" / "scene.svg").is_file()


@pytest.mark.parametrize("flag", [["--compare"], ["--paths"], ["--onion", "2"], ["--strip"], ["--workers", "2"],
                                  ["--cluster", "local:1"]])
@pytest.mark.parametrize("suffix", [".json", ".svg"])
def test_flags_a_vector_file_cannot_carry_are_usage_errors(tmp_path: Path, flag: list[str], suffix: str) -> None:
    scene_path = write_scene(tmp_path, TURN.format(method="rigid", ease="linear", rule="evenodd"))
    target = tmp_path / f"out{suffix}"
    done = run_module("render", scene_path, "-o", target, "-q", *flag, cwd=tmp_path)
    assert done.returncode == 2
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and flag[0] in lines[0] and "Traceback" not in done.stderr
    assert not target.exists() and list(tmp_path.iterdir()) == [scene_path]


def test_library_refusals_name_the_option(tmp_path: Path) -> None:
    scene = _turn(tmp_path)
    with pytest.raises(OptionError, match="compare="):
        tr.write(scene, tmp_path / "x.json", compare=["linear", "rigid"])
    with pytest.raises(OptionError, match="workers="):
        tr.write(scene, tmp_path / "x.svg", workers=2)
    with pytest.raises(OptionError, match="max_error"):
        tr.write(scene, tmp_path / "x.svg", max_error=0.0)
    with pytest.raises(OptionError, match="max_error"):
        tr.write(scene, tmp_path / "x.mp4", max_error=1.0)
    with pytest.raises(OptionError, match=r"format=.*\.svg.*lottie"):
        tr.write(scene, tmp_path / "x.svg", format="lottie")
    assert list(tmp_path.iterdir()) == [tmp_path / "scene.toml"]


def test_max_error_flag_is_checked(tmp_path: Path) -> None:
    scene_path = write_scene(tmp_path, TURN.format(method="rigid", ease="linear", rule="evenodd"))
    for value in ("0", "-1", "nan", "x"):
        done = run_module("render", scene_path, "-o", tmp_path / "x.json", "--max-error", value, cwd=tmp_path)
        assert done.returncode == 2 and "--max-error" in done.stderr and len(done.stderr.strip().splitlines()) == 1
    done = run_module("render", scene_path, "-o", tmp_path / "x.mp4", "--max-error", "1", cwd=tmp_path)
    assert done.returncode == 2 and "--max-error" in done.stderr


def test_cross_fading_contours_are_refused_naming_the_shape(tmp_path: Path) -> None:
    text = TURN.format(method="rigid", ease="linear", rule="evenodd").replace(
        'method = "rigid"', 'method = "rigid"\nunmatched = "fade"').replace(
        "contours = [[[22, 5], [22, 25], [18, 25], [18, 5]], [[21, 7], [21, 9], [19, 9], [19, 7]]]",
        "contours = [[[22, 5], [22, 25], [18, 25], [18, 5]]]")
    scene = tr.load_scene(write_scene(tmp_path, text))
    with pytest.raises(OptionError, match="'bar'.*fade"):
        tr.write(scene, tmp_path / "x.json")
    assert not (tmp_path / "x.json").exists()


def test_linear_keys_off_whole_frames_are_baked(tmp_path: Path) -> None:
    text = TURN.format(method="linear", ease="in-out", rule="evenodd").replace("time = 2\n", "time = 1.97\n")
    scene = tr.load_scene(write_scene(tmp_path, text))
    document = json.loads(tr.write(scene, tmp_path / "x.json").read_text())
    path = _items(_shape_layers(document)[0], "sh")[0]
    frames = document["op"]
    assert frames == math.ceil(1.97 * 20 - 1e-9) + 1 or frames == round(1.97 * 20) + 1
    worst = max(float(np.linalg.norm(_played(path["ks"], f) - _pixels(tr.outlines(scene, f / 20)[0]), axis=1).max())
                for f in range(frames))
    assert worst <= 0.251


def test_a_baked_layer_runs_on_to_the_key_where_the_next_takes_over(tmp_path: Path) -> None:
    """Between frames 39 and 40 a player moves the first layer towards the key drawn at frame 40."""
    text = TURN.format(method="rigid", ease="linear", rule="nonzero") + """[[shape.key]]
time = 3
contours = [[[10, 13], [30, 13], [30, 17], [10, 17]], [[12, 14], [14, 14], [14, 16], [12, 16]]]
"""
    scene = tr.load_scene(write_scene(tmp_path, text))
    document = json.loads(tr.write(scene, tmp_path / "keys.json").read_text())
    first = min(_shape_layers(document), key=lambda layer: layer["ip"])
    outline, hole = _items(first, "sh")
    assert outline["ks"]["k"][-1]["t"] == 40
    key = np.array([[22, 5], [22, 25], [18, 25], [18, 5]], dtype=float)
    assert np.array(outline["ks"]["k"][-1]["s"][0]["v"]) == pytest.approx(_pixels(key), abs=1e-3)
    for frame in range(40):
        exact = _pixels(tr.outlines(scene, frame / 20)[0])
        assert np.linalg.norm(_played(outline["ks"], frame) - exact, axis=1).max() <= 0.251


def test_svg_keytimes_played_by_hand_stay_within_the_bound(tmp_path: Path) -> None:
    """The ``d`` animation read as SMIL plays it (calcMode linear): values at keyTimes, straight between;
    frame f is at keyTime f / F."""
    scene = _turn(tmp_path, "nonlinear")
    svg = tr.write(scene, tmp_path / "turn.svg").read_text()
    animate = re.search(r'<animate attributeName="d"[^>]*>', svg).group(0)
    assert 'calcMode="spline"' not in animate
    times = [float(t) for t in re.search(r'keyTimes="([^"]*)"', animate).group(1).split(";")]
    values = [[[float(v) for v in pair.split(",")] for pair in re.findall(r"-?[\d.]+,-?[\d.]+", d)]
              for d in re.search(r'values="([^"]*)"', animate).group(1).split(";")]
    assert times[0] == 0 and times[-1] == 1 and times == sorted(times)
    coords = np.array(values)  # (K, outline + hole vertices, 2)
    assert float(re.search(r'dur="([\d.]+)s"', animate).group(1)) == pytest.approx(41 / 20)
    worst = 0.0
    for frame in range(41):
        played = np.array([[np.interp(frame / 41, times, coords[:, v, c]) for c in range(2)]
                           for v in range(coords.shape[1])])
        exact = np.concatenate([_pixels(c) for c in tr.outlines(scene, frame / 20, method="nonlinear")])
        worst = max(worst, float(np.linalg.norm(played - exact, axis=1).max()))
    assert worst <= 0.251
    assert len(times) - 1 <= 41 // 2  # far fewer keyframes than frames


@pytest.mark.parametrize("suffix", [".json", ".svg"])
def test_a_reel_to_a_vector_file_is_a_usage_error(tmp_path: Path, suffix: str) -> None:
    scene_path = write_scene(tmp_path, TURN.format(method="rigid", ease="linear", rule="evenodd"))
    done = run_module("reel", scene_path, "-o", tmp_path / f"reel{suffix}", "-q", cwd=tmp_path)
    assert done.returncode == 2 and "reel" in done.stderr and len(done.stderr.strip().splitlines()) == 1
    assert not (tmp_path / f"reel{suffix}").exists()
