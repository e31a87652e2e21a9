"""Vector output (Lottie JSON, animated SVG): what the files hold, read back independently of the writer.

The bound is checked by playing the keyframes as a player does (straight between keyframes, through
each keyframe's cubic-bezier timing, solved here by bisection) against the exact outlines
``tr.outlines`` gives, mapped to pixels by hand (each scene's view fills its frame exactly, so a
scene unit is a known number of pixels, y flipped).
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
from tests.helpers import overlapping_squares, run_main, write_scene
from tests.vector_curves import distance, lottie_error, svg_path_points

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


def _bezier(u: float, p1: float, p2: float) -> float:
    return 3 * (1 - u) ** 2 * u * p1 + 3 * (1 - u) * u ** 2 * p2 + u ** 3


def _timing(x: float, handles: tuple[float, ...]) -> float:
    """CSS ``cubic-bezier(x1, y1, x2, y2)`` at ``x``: y(u) where x(u) = x, u by bisection."""
    x1, y1, x2, y2 = handles
    low, high = 0.0, 1.0
    for _ in range(60):
        mid = (low + high) / 2
        low, high = (mid, high) if _bezier(mid, x1, x2) < x else (low, mid)
    return _bezier(low, y1, y2)


def _played_between(times: list[float], values: np.ndarray, splines: list[tuple[float, ...]],
                    at: float) -> np.ndarray:
    """``values (K, L, 2)`` at keyframe ``times`` played at ``at``: straight from one keyframe to the next
    through that span's cubic-bezier ``splines``, held outside."""
    if at <= times[0] or at >= times[-1]:
        return values[0] if at <= times[0] else values[-1]
    index = int(np.searchsorted(times, at, side="right")) - 1
    s = _timing((at - times[index]) / (times[index + 1] - times[index]), splines[index])
    return values[index] + s * (values[index + 1] - values[index])


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
            worst = max(worst, lottie_error(path["ks"], frame, _pixels(contour)))
    assert worst <= 0.25 + 0.002  # the bound (the hundredths the file rounds to are inside it)
    keyframes = len(paths[0]["ks"]["k"])
    assert 2 < keyframes <= 41 // 2  # a quarter turn is curved, yet at least 2× fewer keyframes than frames
    for path in paths:  # one vertex count over all the path's keyframes
        assert len({len(k["s"][0][name]) for k in path["ks"]["k"] for name in "vio"}) == 1


def test_a_tighter_bound_takes_more_keyframes_and_holds(tmp_path: Path) -> None:
    scene = _turn(tmp_path, "rigid")
    counts = {}
    for bound in (1.0, 0.05):
        document = json.loads(tr.write(scene, tmp_path / f"t{bound}.json", max_error=bound).read_text())
        path = _items(_shape_layers(document)[0], "sh")[0]
        counts[bound] = len(path["ks"]["k"])
        worst = max(lottie_error(path["ks"], f, _pixels(tr.outlines(scene, f / 20)[0])) for f in range(41))
        assert worst <= bound + 0.002
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
    x = 0.3
    y = _timing(x, handles)
    closed_form = {"linear": x, "in-out": x * x * (3 - 2 * x), "in": x * x}[ease]
    assert y == pytest.approx(closed_form)
    svg = tr.write(scene, tmp_path / "lin.svg").read_text()
    d = re.search(r'<animate attributeName="d"[^>]*>', svg).group(0)
    assert len(re.search(r'values="([^"]*)"', d).group(1).split(";")) == 3  # the two keys, the last held to the end
    if ease != "linear":
        assert 'calcMode="spline"' in d
        splines = re.search(r'keySplines="([^"]*)"', d).group(1).split(";")
        assert [float(v) for v in splines[0].split()] == pytest.approx(handles, abs=1e-6)


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
        assert lottie_error(path["ks"], frame, exact) <= 0.252
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
        done = run_main("render", scene_path, "--format", fmt, "-o", by_cli, "-q", cwd=tmp_path)
        assert done.returncode == 0, done.stderr
        by_library = tr.write(tr.load_scene(scene_path), tmp_path / f"lib{suffix}")
        assert by_cli.read_text().replace("cli", "lib") == by_library.read_text()
    done = run_main("render", scene_path, "--format", "lottie", "-q", cwd=tmp_path)
    assert done.returncode == 0 and (tmp_path / "output" / "scene.json").is_file()
    done = run_main("render", scene_path, "--format", "svg", "-q", cwd=tmp_path)
    assert done.returncode == 0 and (tmp_path / "output" / "scene.svg").is_file()


@pytest.mark.parametrize("flag", [["--compare"], ["--paths"], ["--onion", "2"], ["--strip"], ["--workers", "2"],
                                  ["--cluster", "local:1"]])
@pytest.mark.parametrize("suffix", [".json", ".svg"])
def test_flags_a_vector_file_cannot_carry_are_usage_errors(tmp_path: Path, flag: list[str], suffix: str) -> None:
    scene_path = write_scene(tmp_path, TURN.format(method="rigid", ease="linear", rule="evenodd"))
    target = tmp_path / f"out{suffix}"
    done = run_main("render", scene_path, "-o", target, "-q", *flag, cwd=tmp_path)
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
        done = run_main("render", scene_path, "-o", tmp_path / "x.json", "--max-error", value, cwd=tmp_path)
        assert done.returncode == 2 and "--max-error" in done.stderr and len(done.stderr.strip().splitlines()) == 1
    done = run_main("render", scene_path, "-o", tmp_path / "x.mp4", "--max-error", "1", cwd=tmp_path)
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
    worst = max(lottie_error(path["ks"], f, _pixels(tr.outlines(scene, f / 20)[0])) for f in range(frames))
    assert worst <= 0.252


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
    assert np.array(outline["ks"]["k"][-1]["s"][0]["v"]) == pytest.approx(_pixels(key), abs=0.005 + 1e-9)
    for frame in range(40):
        exact = _pixels(tr.outlines(scene, frame / 20)[0])
        assert lottie_error(outline["ks"], frame, exact) <= 0.252


def _d_animation(svg: str) -> tuple[str, list[float], list[str], list[tuple[float, ...]]]:
    """The first ``d`` animation of ``svg``: its tag, keyTimes, values (one ``d`` each) and each span's
    keySplines (straight ones where calcMode is linear)."""
    animate = re.search(r'<animate attributeName="d"[^>]*>', svg).group(0)
    times = [float(t) for t in re.search(r'keyTimes="([^"]*)"', animate).group(1).split(";")]
    values = re.search(r'values="([^"]*)"', animate).group(1).split(";")
    splines = [(0.0, 0.0, 1.0, 1.0)] * (len(times) - 1)
    if 'calcMode="spline"' in animate:
        splines = [tuple(float(v) for v in s.split()) for s in
                   re.search(r'keySplines="([^"]*)"', animate).group(1).split(";")]
        assert len(splines) == len(times) - 1 and all(0 <= v <= 1 for s in splines for v in s)  # SMIL's range
    return animate, times, values, splines


_NUMBER = r"-?[\d.]+"


def _svg_error(times: list[float], values: list[str], splines: list[tuple[float, ...]], at: float,
               outlines: list[np.ndarray]) -> float:
    """How far the ``d`` animation played at key time ``at`` as SMIL does (every number of the path data
    straight between keyframes, through the span's keySplines; the commands those of every value) is from
    ``outlines`` (scene units), subpath by subpath."""
    numbers = np.array([[float(n) for n in re.findall(_NUMBER, d)] for d in values])  # (K, numbers)
    skeleton = r"[ ,]?" + _NUMBER  # a number with what parts it from the one before (a minus sign may)
    assert all(re.sub(skeleton, "#", d) == re.sub(skeleton, "#", values[0]) for d in values)  # one skeleton
    played = _played_between(times, numbers[:, :, None], splines, at)[:, 0]
    counter = iter(played.tolist())
    d = re.sub(skeleton, lambda _: " " + repr(next(counter)), values[0])
    subpaths = svg_path_points(d)
    assert len(subpaths) >= len(outlines)
    return max(distance(points, _pixels(c), True) for (points, _), c in zip(subpaths, outlines))


def test_svg_keytimes_played_by_hand_stay_within_the_bound(tmp_path: Path) -> None:
    """The ``d`` animation read as SMIL plays it: values at keyTimes, straight between through each span's
    keySplines; frame f is at keyTime f / F."""
    scene = _turn(tmp_path, "nonlinear")
    svg = tr.write(scene, tmp_path / "turn.svg").read_text()
    animate, times, values, splines = _d_animation(svg)
    assert times[0] == 0 and times[-1] == 1 and times == sorted(times)
    assert float(re.search(r'dur="([\d.]+)s"', animate).group(1)) == pytest.approx(41 / 20)
    worst = max(_svg_error(times, values, splines, frame / 41, tr.outlines(scene, frame / 20, method="nonlinear"))
                for frame in range(41))
    assert worst <= 0.252
    assert len(times) - 1 <= 41 // 2  # far fewer keyframes than frames


@pytest.mark.parametrize("suffix", [".json", ".svg"])
def test_a_reel_to_a_vector_file_is_a_usage_error(tmp_path: Path, suffix: str) -> None:
    scene_path = write_scene(tmp_path, TURN.format(method="rigid", ease="linear", rule="evenodd"))
    done = run_main("reel", scene_path, "-o", tmp_path / f"reel{suffix}", "-q", cwd=tmp_path)
    assert done.returncode == 2 and "reel" in done.stderr and len(done.stderr.strip().splitlines()) == 1
    assert not (tmp_path / f"reel{suffix}").exists()


def _two_squares(folder: Path, first: str, second: str, x: float, paints: tuple[str, str] = ('fill="#ff0000"',
                                                                                 'fill="#0000ff"')) -> Path:
    squares = {"a": f'<rect id="a" x="{x}" y="4" width="2" height="2" {paints[0]}/>',
               "b": f'<rect id="b" x="8.5" y="4" width="2" height="2" {paints[1]}/>'}
    path = folder / f"{first}{second}{x}.svg"
    path.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 20 10">{squares[first]}{squares[second]}'
                    "</svg>")
    return path


def test_layers_split_and_reorder_where_the_paint_order_switches(tmp_path: Path) -> None:
    """Square a passes over the still square b: under it in the first drawing, over it in the second; the
    order switches at t = 21/32 (tests/scenefile/test_key_frames.py). Each layer keeps one order: b's
    layer is above a's before the switch, below after it."""
    scene = tr.load_scene([_two_squares(tmp_path, "a", "b", 4), _two_squares(tmp_path, "b", "a", 14)])
    document = json.loads(tr.write(scene, tmp_path / "swap.json").read_text())
    fps, frames = document["fr"], document["op"]
    switch = math.ceil(21 / 32 * fps * 1.0 - 1e-9)  # the first frame at or after the switch (1 s segment)
    layers = _shape_layers(document)  # first on top

    def top_at(frame: int) -> str:
        shown = [layer["nm"] for layer in layers if layer["ip"] <= frame < layer["op"]]
        return shown[0]

    assert top_at(0) == "b" and top_at(switch - 1) == "b"
    assert top_at(switch) == "a" and top_at(frames - 1) == "a"
    svg = tr.write(scene, tmp_path / "swap.svg").read_text()
    ids = re.findall(r'<g id="([ab])-(\d+)"', svg)  # in paint order, first painted first
    assert [name for name, start in ids if int(start) < switch] == ["a", "b"]
    assert [name for name, start in ids if int(start) >= switch] == ["b", "a"]


def test_elements_of_one_opaque_colour_keep_one_layer_each_where_their_order_switches(tmp_path: Path) -> None:
    """The squares above, both black: either order draws the same picture, so each is one layer (one group of the
    SVG) over the whole clip, not split where the order switches."""
    black = ('fill="#000000"', 'fill="#000000"')
    scene = tr.load_scene([_two_squares(tmp_path, "a", "b", 4, black), _two_squares(tmp_path, "b", "a", 14, black)])
    document = json.loads(tr.write(scene, tmp_path / "swap.json").read_text())
    assert sorted((layer["nm"], layer["ip"], layer["op"]) for layer in _shape_layers(document)) == [
        ("a", 0, document["op"]), ("b", 0, document["op"])]
    svg = tr.write(scene, tmp_path / "swap.svg").read_text()
    assert sorted(re.findall(r'<g id="([ab])-(\d+)"', svg)) == [("a", "0"), ("b", "0")]


def test_a_fill_rule_that_switches_inside_a_run_keeps_one_layer_with_a_fill_of_each_rule(tmp_path: Path) -> None:
    """Two overlapping squares wound alike, filled nonzero at the first key and evenodd at the second: one
    layer of two fills of the same paths, the nonzero one shown until the frame where the raster takes the
    second key's rule, the evenodd one from there (the players draw it: tests/encode/test_vector_players.py);
    in the SVG, one path whose ``fill-rule`` switches at that frame."""
    scene = tr.load_scene(overlapping_squares(tmp_path))
    document = json.loads(tr.write(scene, tmp_path / "rule.json").read_text())
    (layer,) = _shape_layers(document)
    assert (layer["ip"], layer["op"]) == (0, document["op"])
    fills = _items(layer, "fl")
    assert [fill["r"] for fill in fills] == [1, 2]
    size = (document["w"], document["h"])
    scale = min(size[0] / 16, size[1] / 12)  # the 16 × 12 view box, centred
    overlap = (round((size[0] - 16 * scale) / 2 + 6.5 * scale), size[1] // 2)  # (6.5, 6): inside both squares
    filled = [bool(tr.frame(scene, f / document["fr"], size=size, background="#ffffff")[overlap[1], overlap[0], 0] < 128)
              for f in range(document["op"])]
    switch = filled.index(False)
    assert switch > 0 and not any(filled[switch:])  # the raster switches once

    def shown(fill: dict, frame: int) -> bool:
        keys = fill["o"]["k"]
        before = [k for k in keys if k["t"] <= frame]
        return (before[-1] if before else keys[0])["s"][0] > 0

    assert [shown(fills[0], f) for f in range(document["op"])] == filled
    assert [shown(fills[1], f) for f in range(document["op"])] == [not f for f in filled]
    svg = tr.write(scene, tmp_path / "rule.svg").read_text()
    assert svg.count("<path ") == 1 and f'values="nonzero;evenodd"' in svg


@pytest.mark.parametrize("paths, layers", [
    (("M2 2h4v4h-4z M10 2h4v4h-4z", "M2 3h4v4h-4z M10 3v4h4v-4z"), 1),  # apart: their windings change nothing
    (("M2 2h8v8h-8z M4 4h4v4h-4z", "M2 2h8v8h-8z M4 4v4h4v-4z"), 2)])  # nested: filled, then a hole
def test_windings_that_change_between_keys_start_a_layer_only_where_contours_meet(tmp_path: Path, paths, layers) -> None:  # type: ignore[no-untyped-def]
    """Two squares filled nonzero, the second drawing winding the second square the other way: apart, the picture
    is the same either way and the element stays one layer; one inside the other, the inner square turns from
    filled to a hole where the second key's windings take over, and the layer splits there."""
    drawings = [_drawing(tmp_path, f"{name}.svg", f'<path id="squares" d="{d}"/>') for name, d in zip("ab", paths)]
    document = json.loads(tr.write(tr.load_scene(drawings), tmp_path / "windings.json").read_text())
    assert len(_shape_layers(document)) == layers


def test_the_fill_rule_of_an_element_that_fills_nothing_starts_no_new_layer(tmp_path: Path) -> None:
    """The squares above stroked, not filled: their rule and windings change nothing drawn, so one layer (one SVG
    path) with no second fill and no switch."""
    drawings = overlapping_squares(tmp_path)
    for path in drawings:
        path.write_text(path.read_text().replace('<path ', '<path fill="none" stroke="#000" '))
    scene = tr.load_scene(drawings)
    document = json.loads(tr.write(scene, tmp_path / "rule.json").read_text())
    (layer,) = _shape_layers(document)
    assert (layer["ip"], layer["op"]) == (0, document["op"]) and not _items(layer, "fl")
    svg = tr.write(scene, tmp_path / "rule.svg").read_text()
    assert svg.count("<path ") == 1 and 'attributeName="fill-rule"' not in svg


def _drawing(folder: Path, name: str, body: str) -> Path:
    path = folder / name
    path.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 20 10">{body}</svg>')
    return path


def _box_drawings(folder: Path, defs: tuple[str, str], paint: str, group: str = "") -> tr.Scene:
    """Two drawings of one rectangle ``box`` painted ``paint``, with the ``defs`` of each (inside ``<g group>``)."""
    first = _drawing(folder, "a.svg", f'<defs>{defs[0]}</defs><g {group}><rect id="box" x="2" y="2" width="6" '
                                      f'height="6" {paint}/></g>')
    second = _drawing(folder, "b.svg", f'<defs>{defs[1]}</defs><g {group}><rect id="box" x="9" y="1" width="8" '
                                       f'height="4" {paint}/></g>')
    return tr.load_scene([first, second])


_TWO_STOPS = '<linearGradient id="g"><stop offset="0" stop-color="#ff0000"/><stop offset="1" stop-color="#0000ff"/>'
_THREE_STOPS = ('<linearGradient id="g" x2="0" y2="1"><stop offset="0" stop-color="#ff0000"/>'
                '<stop offset="0.5" stop-color="#00ff00"/><stop offset="1" stop-color="#0000ff"/>')
_CLIP = '<clipPath id="c"><rect x="0" y="0" width="{w}" height="10"/></clipPath>'


def _paths_in(items: list[dict]) -> list[dict]:
    """Every path item (``sh``) among ``items`` and in their groups."""
    return [item for item in items if item["ty"] == "sh"] + [
        found for item in items if item["ty"] == "gr" for found in _paths_in(item["it"])]


def test_an_elliptical_gradient_fills_a_still_rectangle_through_a_matte_of_the_paths(tmp_path: Path) -> None:
    """fluent-emoji's egg (an elliptical radial gradient, no stroke, no clip) becoming bootstrap's heart: the
    element's paths, keyed as in pixels (a few keyframes), are a matte layer (``td``) drawing them in white; the
    gradient fills one still rectangle below it (``tt`` 1), its group's transform placing the gradient's frame.
    Written in that frame instead, as before, the paths changed at every frame (the players draw it:
    tests/encode/test_vector_paint_players.py)."""
    icons = Path(__file__).resolve().parents[1] / "data" / "icons"
    scene = tr.load_scene([icons / "fluent-emoji" / "egg.svg", icons / "bootstrap" / "heart-fill.svg"])
    document = json.loads(tr.write(scene, tmp_path / "egg.json").read_text())
    layers = _shape_layers(document)
    mattes = [i for i, layer in enumerate(layers) if layer.get("td") == 1]
    assert mattes, "a matte layer"
    for i in mattes:
        matte, filled = layers[i], layers[i + 1]
        assert filled.get("tt") == 1 and (matte["ip"], matte["op"]) == (filled["ip"], filled["op"])
        (group,) = filled["shapes"]
        (cover,) = [item for item in group["it"] if item["ty"] == "sh"]
        assert cover["ks"]["a"] == 0 and len(cover["ks"]["k"]["v"]) == 4
        assert [item["ty"] for item in group["it"]] == ["sh", "gf", "tr"]
        paths = _paths_in(matte["shapes"])  # some may be still paths in a group that moves them
        assert paths and all(not p["ks"]["a"] or len(p["ks"]["k"]) < document["op"] // 2 for p in paths)


def test_gradients_and_clip_paths_are_written(tmp_path: Path) -> None:
    """A linear gradient of two stops becoming one of three, under a clip path: Lottie's gradient fill keeps
    one stop count (the three offsets) in every keyframe, its clip path is the layer's mask; the SVG has a
    gradient in pixels whose stops are animated, and a clip path whose outline moves."""
    defs = (_TWO_STOPS + "</linearGradient>" + _CLIP.format(w=6),
            _THREE_STOPS + "</linearGradient>" + _CLIP.format(w=13))
    scene = _box_drawings(tmp_path, defs, 'fill="url(#g)" clip-path="url(#c)"')
    layer = _shape_layers(json.loads(tr.write(scene, tmp_path / "x.json").read_text()))[0]
    fill = _items(layer, "gf")[0]
    assert fill["t"] == 1 and fill["g"]["p"] == 3 and not _items(layer, "fl")
    keys = fill["g"]["k"]["k"]
    assert len(keys) >= 2 and all(len(key["s"]) == 3 * 4 + 3 * 2 for key in keys)
    assert keys[0]["s"][:4] == [0, 1, 0, 0] and keys[-1]["s"][4:8] == [0.5, 0, 1, 0]
    assert [mask["mode"] for mask in layer["masksProperties"]] == ["a"]
    svg = tr.write(scene, tmp_path / "x.svg").read_text()
    assert '<linearGradient id="tr-run0-fill" gradientUnits="userSpaceOnUse" spreadMethod="pad"' in svg
    assert svg.count("<stop ") == 3 and '<animate attributeName="stop-color"' in svg
    assert 'fill="url(#tr-run0-fill)"' in svg and '<g clip-path="url(#tr-run0-clip-0)">' in svg
    assert re.search(r'<clipPath id="tr-run0-clip-0">\s*<path d="[^"]+" clip-rule="nonzero">\s*<animate attributeName="d"',
                     svg)


_SEVERAL = ('<clipPath id="c"><rect x="0" y="0" width="4" height="10"/><rect x="5" y="0" width="4" height="10"/>'
            '</clipPath><clipPath id="d"><rect x="0" y="0" width="20" height="3"/><rect x="0" y="4" width="20" '
            'height="6"/></clipPath>')


@pytest.mark.parametrize("defs, paint, group, what", [
    ((_TWO_STOPS.replace('id="g"', 'id="g" spreadMethod="repeat" x2="0.3"') + "</linearGradient>",) * 2,
     'fill="url(#g)"', "", "spreads by repeat"),
    ((_SEVERAL,) * 2, 'fill="#ff0000" clip-path="url(#c)"', 'clip-path="url(#d)"', "several clip paths")])
def test_what_lottie_cannot_carry_is_refused_naming_the_element(tmp_path: Path, defs: tuple[str, str], paint: str,
                                                                 group: str, what: str) -> None:
    """Lottie gradients pad, and a clip path of several contours is a matte, of which a layer has one: the
    library refuses naming the element, the command line too (exit 2, one line); the SVG carries both."""
    scene = _box_drawings(tmp_path, defs, paint, group)
    with pytest.raises(OptionError, match=f"'box'.*{what}"):
        tr.write(scene, tmp_path / "x.json")
    assert not (tmp_path / "x.json").exists()
    done = run_main("render", tmp_path / "a.svg", tmp_path / "b.svg", "-o", tmp_path / "x.json", "-q", cwd=tmp_path)
    lines = done.stderr.strip().splitlines()
    assert done.returncode == 2 and len(lines) == 1 and "'box'" in lines[0] and what in lines[0]
    assert not (tmp_path / "x.json").exists()
    svg = tr.write(scene, tmp_path / "x.svg").read_text()
    assert ('spreadMethod="repeat"' in svg) if "repeat" in what else svg.count("<clipPath ") == 2


@pytest.mark.parametrize("ease, handles", [("ease-in-out", (0.42, 0.0, 0.58, 1.0)),
                                           ("cubic-bezier(0.3, 0.1, 0.7, 0.9)", (0.3, 0.1, 0.7, 0.9))])
def test_css_easings_export_exactly_as_handles(tmp_path: Path, ease: str, handles: tuple) -> None:
    """CSS curves are the keyframe's handles; played by hand (x(u) = fraction by bisection, the position
    at y(u)) they give the exact outlines at every frame."""
    scene = _turn(tmp_path, "linear", ease)
    document = json.loads(tr.write(scene, tmp_path / "css.json").read_text())
    outline = _items(_shape_layers(document)[0], "sh")[0]["ks"]["k"]
    assert [k["t"] for k in outline] == [0, 40]
    got = (outline[0]["o"]["x"][0], outline[0]["o"]["y"][0], outline[0]["i"]["x"][0], outline[0]["i"]["y"][0])
    assert got == pytest.approx(handles)
    start, end = np.array(outline[0]["s"][0]["v"]), np.array(outline[1]["s"][0]["v"])
    for frame in range(41):
        played = start + _timing(frame / 40, handles) * (end - start)
        exact = _pixels(tr.outlines(scene, frame / 20)[0])
        assert np.linalg.norm(played - exact, axis=1).max() <= 0.01


def test_an_overshooting_curve_is_baked_within_the_bound(tmp_path: Path) -> None:
    """SMIL's keySplines take values in [0, 1] only: a curve that overshoots is baked, for both files."""
    scene = _turn(tmp_path, "linear", "cubic-bezier(0.3, -0.4, 0.7, 1.4)")
    document = json.loads(tr.write(scene, tmp_path / "over.json").read_text())
    path = _items(_shape_layers(document)[0], "sh")[0]["ks"]
    assert len(path["k"]) > 2
    worst = max(lottie_error(path, f, _pixels(tr.outlines(scene, f / 20)[0])) for f in range(41))
    assert worst <= 0.252
    svg = tr.write(scene, tmp_path / "over.svg").read_text()
    _, times, values, splines = _d_animation(svg)  # keySplines, if any, within [0, 1]
    assert len(times) > 3
    worst = max(_svg_error(times, values, splines, f / 41, tr.outlines(scene, f / 20)[:1]) for f in range(41))
    assert worst <= 0.252


def _ring(cx: float, cy: float, rx: float, ry: float, count: int = 96) -> str:
    """An ellipse as a closed polyline of ``count`` points, as TOML."""
    angles = np.linspace(0.0, 2 * np.pi, count, endpoint=False)
    return "[" + ", ".join(f"[{cx + rx * math.cos(a):.6f}, {cy + ry * math.sin(a):.6f}]" for a in angles) + "]"


ROUND = f"""size = [400, 300]
fps = 20
view = [0, 0, 40, 30]
background = "#ffffff"
method = "{{method}}"
[[shape]]
name = "blob"
fill = "#3366cc"
stroke = "#000000"
stroke_width = 0.2
[[shape.key]]
time = 0
contours = [{_ring(12, 15, 8, 8)}]
[[shape.key]]
time = 2
contours = [{_ring(27, 15, 11, 5)}]
"""


@pytest.mark.parametrize("method", ["linear", "nonlinear", "rigid"])
def test_round_keys_export_as_few_cubics_within_the_bound(tmp_path: Path, method: str) -> None:
    """Dense polylines of ellipses become a few cubic spans per contour (tangents written), and the curves as
    the files hold them, played and drawn from the cubic's closed form, stay within the bound at every frame."""
    scene = tr.load_scene(write_scene(tmp_path, ROUND.format(method=method)))
    document = json.loads(tr.write(scene, tmp_path / "round.json").read_text())
    (path,) = _items(_shape_layers(document)[0], "sh")
    keys = path["ks"]["k"]
    assert len({len(k["s"][0][name]) for k in keys for name in "vio"}) == 1  # one vertex count throughout
    assert len(keys[0]["s"][0]["v"]) <= 96 // 6  # far fewer vertices than the polyline's 96
    assert np.abs(np.array(keys[0]["s"][0]["o"])).max() > 1.0  # curved: tangents, not straight edges
    exact = [_pixels(tr.outlines(scene, f / 20, method=method)[0]) for f in range(41)]
    assert max(lottie_error(path["ks"], f, exact[f]) for f in range(41)) <= 0.252
    if method == "linear":
        assert [k["t"] for k in keys] == [0, 40]  # two keys, exact
    svg = tr.write(scene, tmp_path / "round.svg").read_text()
    _, times, values, splines = _d_animation(svg)
    assert "c" in values[0]  # cubic Béziers (relative to the pen)
    worst = max(_svg_error(times, values, splines, f / 41, tr.outlines(scene, f / 20, method=method))
                for f in range(41))
    assert worst <= 0.252


def test_a_tighter_bound_holds_on_curves(tmp_path: Path) -> None:
    scene = tr.load_scene(write_scene(tmp_path, ROUND.format(method="nonlinear")))
    vertices = {}
    for bound in (1.0, 0.05):
        document = json.loads(tr.write(scene, tmp_path / f"r{bound}.json", max_error=bound).read_text())
        path = _items(_shape_layers(document)[0], "sh")[0]["ks"]
        vertices[bound] = len(path["k"][0]["s"][0]["v"])
        worst = max(lottie_error(path, f, _pixels(tr.outlines(scene, f / 20, method="nonlinear")[0]))
                    for f in range(41))
        assert worst <= bound + 0.002
    assert vertices[0.05] > vertices[1.0]
