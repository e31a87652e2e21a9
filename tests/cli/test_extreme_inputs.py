"""Inputs at the edges of what numbers hold: refused in one line (exit 2), or drawn without a warning.

Each in a child process (forked from the test's, stdout and stderr read from its file descriptors, Python's
warnings shown as a fresh interpreter shows them), so that stderr is what a user sees: a refusal is one line
naming the file and the place, a legal input renders with nothing on stderr (no Python warning, no traceback).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from tests.helpers import run_forked, write_scene

TRIANGLE = [[0, 0], [1, 0], [0, 1]]


def _two_keys(k0: list, k1: list, key_line: str = "", top: str = "") -> str:
    return (f'size = [160, 120]\nfps = 4\n{top}[[shape]]\nname = "s"\nfill = "#000000"\n'
            f"[[shape.key]]\ntime = 0\npoints = {json.dumps(k0)}\n{key_line}\n"
            f"[[shape.key]]\ntime = 1\npoints = {json.dumps(k1)}\n")


def _refused(tmp_path: Path, scene: Path, *words: str) -> str:
    """Run ``check`` and ``render`` on ``scene``: both exit 2 with one line naming it, and write nothing."""
    before = sorted(p.name for p in tmp_path.iterdir())
    for command in (("check", scene), ("render", scene, "-o", tmp_path / "out.mp4", "-q")):
        result = run_forked(*command)
        err = result.stderr
        assert result.returncode == 2, err
        assert err.startswith(f"tweenrender: error: {scene}: ") and err.count("\n") == 1, err
        assert "Traceback" not in err and "Warning" not in err
        assert all(word in err for word in words), err
    assert sorted(p.name for p in tmp_path.iterdir()) == before
    return err


def _renders_quietly(tmp_path: Path, *inputs: Path, method: str | None = None) -> None:
    flags = ("--method", method) if method else ()
    result = run_forked("render", *inputs, *flags, "-o", tmp_path / "frames", "-q")
    assert result.returncode == 0 and result.stderr == "", result.stderr
    assert sorted((tmp_path / "frames").glob("frame_*.png"))


# -- numbers too long for Python's int() -----------------------------------------------------------

def test_steps_of_five_thousand_digits_is_refused_in_the_scenes_words(tmp_path: Path) -> None:
    scene = write_scene(tmp_path, _two_keys(TRIANGLE, TRIANGLE, f'ease = "steps({"9" * 5000})"'))
    err = _refused(tmp_path, scene, "shape[0].key[0].ease", "expected n from 1 to 10000", "5000 digits")
    assert "set_int_max_str_digits" not in err


@pytest.mark.parametrize("fmt", ["toml", "json"])
def test_an_integer_of_five_thousand_digits_is_refused_in_the_scenes_words(tmp_path: Path, fmt: str) -> None:
    huge = "9" * 5000
    text = (f"size = [160, 120]\nfps = {huge}\n" if fmt == "toml"
            else f'{{"size": [160, 120], "fps": {huge}, "shapes": []}}')
    scene = write_scene(tmp_path, text, f"scene.{fmt}")
    err = _refused(tmp_path, scene, "5000 digits")
    assert "set_int_max_str_digits" not in err


# -- subnormal and tiny values ---------------------------------------------------------------------

def test_a_spacing_chart_with_a_subnormal_tick_renders_quietly(tmp_path: Path) -> None:
    scene = write_scene(tmp_path, _two_keys(TRIANGLE, [[0, 0], [2, 0], [0, 1]], "spacing = [0, 1e-320, 1]"))
    _renders_quietly(tmp_path, scene)


@pytest.mark.parametrize("size", [1e-100, 1e-160, 1e-300])
@pytest.mark.parametrize("method", ["arap", "auto", "injective"])
def test_a_tiny_triangle_shrinking_to_a_point_renders_quietly(tmp_path: Path, size: float, method: str) -> None:
    point = [size / 3, size / 3]
    scene = write_scene(tmp_path, _two_keys([[0, 0], [size, 0], [0, size]], [point] * 3))
    _renders_quietly(tmp_path, scene, method=method)
    stats = run_forked("stats", scene, "--json")
    assert stats.returncode == 0 and stats.stderr == "", stats.stderr


def _svg(view_box: str, size: str, width: str) -> str:
    return (f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{view_box}" {size}>'
            f'<rect x="0" y="0" width="{width}" height="{width}"/></svg>')


def test_a_subnormal_viewbox_scaled_to_a_size_is_refused(tmp_path: Path) -> None:
    a = write_scene(tmp_path, _svg("0 0 1e-320 1e-320", 'width="100" height="100"', "1e-320"), "a.svg")
    b = write_scene(tmp_path, _svg("0 0 1e-320 1e-320", 'width="100" height="100"', "5e-321"), "b.svg")
    for command in (("check", a, b), ("render", a, b, "-o", tmp_path / "out.mp4", "-q")):
        result = run_forked(*command)
        assert result.returncode == 2, result.stderr
        assert result.stderr.startswith(f"tweenrender: error: {a}: ") and result.stderr.count("\n") == 1
        assert "viewBox" in result.stderr and "Warning" not in result.stderr
    assert not (tmp_path / "out.mp4").exists()


def test_a_subnormal_viewbox_without_a_size_is_drawn(tmp_path: Path) -> None:
    a = write_scene(tmp_path, _svg("0 0 1e-320 1e-320", "", "10"), "a.svg")
    b = write_scene(tmp_path, _svg("0 0 1e-320 1e-320", "", "20"), "b.svg")
    _renders_quietly(tmp_path, a, b)
    import imageio.v3 as iio

    for path in sorted((tmp_path / "frames").glob("frame_*.png")):
        # the rects cover the view box and all to its lower right (views this small are drawn at the
        # largest magnification, 1e307, about their centre: the lower right quarter at least)
        assert np.all(iio.imread(path)[360:, 360:, :3] < 128)


# -- limits enforced before the work -----------------------------------------------------------------

def _gradient_svg(stops: int, width: int) -> str:
    rows = "".join(f'<stop offset="{i / stops:.6f}" stop-color="#{(i * 37) % 256:02x}{(i * 11) % 256:02x}40"/>'
                   for i in range(stops))
    return (f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100"><defs><linearGradient id="many">'
            f'{rows}</linearGradient></defs><rect id="box" x="10" y="10" width="{width}" height="50" '
            f'fill="url(#many)"/></svg>')


def test_a_gradient_of_100000_stops_is_refused_naming_the_limit(tmp_path: Path) -> None:
    a = write_scene(tmp_path, _gradient_svg(100_000, 50), "a.svg")
    b = write_scene(tmp_path, _gradient_svg(3, 80), "b.svg")
    for command in (("check", a, b), ("render", a, b, "-o", tmp_path / "out.mp4", "-q")):
        result = run_forked(*command)
        assert result.returncode == 2, result.stderr
        assert result.stderr.startswith(f"tweenrender: error: {a}: ") and result.stderr.count("\n") == 1
        assert "'many'" in result.stderr and "at most 1000 stops" in result.stderr and "100000" in result.stderr
    assert not (tmp_path / "out.mp4").exists()


@pytest.mark.lottie_input
def test_a_lottie_gradient_of_100000_stops_is_refused_naming_the_limit(tmp_path: Path) -> None:
    import tweenrender as tr
    from tweenrender.errors import SceneError

    document = json.loads((Path(__file__).resolve().parent.parent / "data" / "lottie" / "morph.json").read_text())
    items = document["layers"][0]["shapes"][0]["it"]
    stops = 100_000
    flat = [v for i in range(stops) for v in (i / stops, 0.5, 0.2, 0.1)]
    items[1] = {"ty": "gf", "nm": "paint", "o": {"a": 0, "k": 100}, "r": 1, "t": 1,
                "s": {"a": 0, "k": [0, 0]}, "e": {"a": 0, "k": [100, 0]}, "g": {"p": stops, "k": {"a": 0, "k": flat}}}
    path = tmp_path / "anim.json"
    path.write_text(json.dumps(document))
    with pytest.raises(SceneError) as caught:
        tr.load_scene(path)
    message = str(caught.value)
    assert message.startswith(f"{path}: layer 1 ") and "at most 1000" in message and "100000" in message
    assert "\n" not in message


def test_a_sheet_larger_than_its_area_limit_is_refused_before_drawing(tmp_path: Path) -> None:
    scene = write_scene(tmp_path, _two_keys(TRIANGLE, [[0, 0], [2, 0], [0, 1]]))
    target = tmp_path / "sheet.png"
    result = run_forked("sheet", scene, "--size", "16384x16384", "--count", "200", "-o", target)
    assert result.returncode == 2 and result.stderr.count("\n") == 1, result.stderr
    assert result.stderr.startswith("tweenrender: error: --size: ") and "16777216 pixels" in result.stderr
    assert "268435456" in result.stderr and not target.exists()
    # the limit is an area: a long thin sheet within it is drawn
    result = run_forked("sheet", scene, "--size", "16384x600", "--count", "3", "-o", target)
    assert result.returncode == 0, result.stderr
    import imageio.v3 as iio

    assert iio.imread(target).shape[:2] == (600, 16384)


def test_the_librarys_sheet_refuses_the_same_area(tmp_path: Path) -> None:
    import tweenrender as tr
    from tweenrender.errors import OptionError

    scene = tr.parse_scene(_two_keys(TRIANGLE, [[0, 0], [2, 0], [0, 1]]), tmp_path / "scene.toml")
    with pytest.raises(OptionError, match="size=: expected a sheet of at most 16777216 pixels"):
        tr.sheet(scene, tmp_path / "sheet.png", size=(8192, 4097))
    assert not (tmp_path / "sheet.png").exists()


@pytest.mark.parametrize("size", [1e-160, 1e-300])
def test_the_q_curves_of_a_tiny_triangle_shrinking_to_a_point_draw_quietly(tmp_path: Path, size: float) -> None:
    point = [size / 3, size / 3]
    scene = write_scene(tmp_path, _two_keys([[0, 0], [size, 0], [0, size]], [point] * 3))
    for command in (("qcurves", "-o", tmp_path / "q.png"), ("correspond", "-o", tmp_path / "c.png"),
                    ("sheet", "-o", tmp_path / "s.png")):
        done = run_forked(command[0], scene, *command[1:])
        assert done.returncode == 0 and done.stderr == "", (command[0], done.stderr)


def _squares_svg(count: int) -> str:
    squares = " ".join(f"M{(i % 80) * 4} {(i // 80) * 4}h2v2h-2z" for i in range(count))
    return f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 320 320"><path d="{squares}"/></svg>'


def test_a_key_of_more_contours_than_the_limit_is_refused_naming_it(tmp_path: Path) -> None:
    """One path of 5 001 small squares (a key of 5 000 renders in 30 s to 3 minutes here): refused before any
    contour is paired, in one line naming the limit; a scene file's key too."""
    a = write_scene(tmp_path, _squares_svg(5_001), "a.svg")
    b = write_scene(tmp_path, _squares_svg(3), "b.svg")
    for command in (("check", a, b), ("render", a, b, "-o", tmp_path / "out.mp4", "-q")):
        result = run_forked(*command)
        assert result.returncode == 2, result.stderr
        assert result.stderr.startswith(f"tweenrender: error: {a}: ") and result.stderr.count("\n") == 1, result.stderr
        assert "at most 5000 contours" in result.stderr and "5001" in result.stderr, result.stderr
    assert not (tmp_path / "out.mp4").exists()
    square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    contours = json.dumps([[[x + 2 * i, y] for x, y in square] for i in range(5_001)])
    scene = write_scene(tmp_path, f'size = [160, 120]\n[[shape]]\nname = "s"\n[[shape.key]]\ntime = 0\n'
                                  f'contours = {contours}\n[[shape.key]]\ntime = 1\npoints = {json.dumps(square)}\n',
                        "many.toml")
    _refused(tmp_path, scene, "shape[0].key[0].contours", "at most 5000 contours", "5001")
