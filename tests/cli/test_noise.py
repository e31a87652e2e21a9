"""Nothing but the answer on stderr: no numpy warning, no usage block, a BOM taken in stride.

Each case runs as a real process with Python's default warning filters, as a user's would.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from tests.helpers import SQUARE, read_png, write_scene

BLUE = (0x3B, 0x6F, 0xD8)  # the default fill


def _run(*args: object, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "tweenrender", *map(str, args)], capture_output=True, text=True,
                          cwd=cwd, timeout=300)


def _view(view: str) -> str:
    return SQUARE.replace("view = [-2, -2, 10, 7]", f"view = {view}").replace("size = [320, 240]", "size = [64, 48]")


COMMANDS = [("render", "-o", "frames", "-q", "--frames", "0:3"),
            ("render", "-o", "frames", "-q", "--frames", "0:3", "--compare", "--paths", "--onion", "2", "--strip"),
            ("sheet", "-o", "sheet.png"), ("qcurves", "-o", "q.png"), ("correspond", "-o", "c.png"), ("stats",),
            ("check", "--json")]


VIEWS = ["[0, 0, 1e-300, 1e-300]", "[0, 0, 5e-324, 5e-324]", "[-1e9, 0, 1e9, 1e-300]",
         "[1, 1, 1.0000000000000002, 1.0000000000000002]"]


@pytest.mark.parametrize("command", COMMANDS, ids=[" ".join(c[:1] + c[3:]) for c in COMMANDS])
@pytest.mark.parametrize("view", VIEWS)
def test_extreme_views_make_no_warning(cli, tmp_path: Path, monkeypatch, command: tuple[str, ...],
                                       view: str) -> None:
    """In this process, with every warning recorded (pytest would otherwise keep them from stderr)."""
    import warnings

    scene = write_scene(tmp_path, _view(view))
    monkeypatch.chdir(tmp_path)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        code, _, err = cli(command[0], scene, *command[1:])
    assert code == 0 and err == "", err
    assert [str(w.message) for w in caught] == []


def test_an_extreme_view_prints_nothing_on_stderr(tmp_path: Path) -> None:
    """The same through a real process and Python's default warning filters, as a user runs it."""
    scene = write_scene(tmp_path, _view(VIEWS[0]))
    done = _run(*COMMANDS[1][:1], scene, *COMMANDS[1][1:], cwd=tmp_path)
    assert done.returncode == 0 and done.stderr == "", done.stderr


def test_a_view_inside_the_square_is_all_square(tmp_path: Path) -> None:
    """At t = 0 the square covers [0, 2]²: a view [0.5, 0.5, 0.5 + 1e-300, ...] lies inside it, so the
    picture is the fill colour everywhere (pixel coordinates 1e300 and more, far beyond float32)."""
    scene = write_scene(tmp_path, _view("[0.5, 0.5, 0.5000000000000001, 0.5000000000000001]"))
    done = _run("render", scene, "-o", "frames", "-q", "--frames", "0:1", cwd=tmp_path)
    assert done.returncode == 0 and done.stderr == "", done.stderr
    picture = read_png(tmp_path / "frames" / "frame_0000.png")
    assert (picture[..., :3] == BLUE).all()
    scene = write_scene(tmp_path, _view("[0, 0, 1e-300, 1e-300]"))
    done = _run("render", scene, "-o", "tiny", "-q", "--frames", "0:1", cwd=tmp_path)
    assert done.returncode == 0 and done.stderr == "", done.stderr
    picture = read_png(tmp_path / "tiny" / "frame_0000.png")[..., :3]
    # the square view fills the 48 px height, centred: columns 8..55 show x from 0 to 1e-300, all in the
    # square; the 8 columns each side show x < 0 (white) and x > 1e-300 (still the square)
    blue = np.all(picture == BLUE, axis=-1)
    assert blue[:, 9:].all() and (picture[:, :7] == 255).all()


def test_bezier_control_points_at_1e308_make_no_warning(tmp_path: Path) -> None:
    (tmp_path / "c.svg").write_text(
        '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">'
        '<path id="p" d="M 0 0 C 1e308 1e308 -1e308 -1e308 10 10 L 0 10 Z"/></svg>')
    scene = write_scene(tmp_path, SQUARE.replace("points = [[0, 0], [2, 0], [2, 2], [0, 2]]",
                                                 'points = { svg = "c.svg", id = "p" }'))
    done = _run("check", scene, cwd=tmp_path)
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert "Warning" not in done.stderr and done.stderr.startswith(f"tweenrender: error: {scene}: ")


@pytest.mark.parametrize("suffix", [".toml", ".json"])
def test_a_byte_order_mark_is_taken(tmp_path: Path, suffix: str) -> None:
    import json
    import tomllib

    text = SQUARE if suffix == ".toml" else json.dumps(tomllib.loads(SQUARE))
    scene = tmp_path / f"scene{suffix}"
    scene.write_bytes(b"\xef\xbb\xbf" + text.encode())
    done = _run("check", scene, cwd=tmp_path)
    assert done.returncode == 0 and done.stderr == "", done.stderr
    assert done.stdout == f"{scene}: ok (1 shape, 2 keys, 2 s at 24 fps)\n"
    # and the lines of later errors are still counted from the first line
    scene.write_bytes(b"\xef\xbb\xbf" + text.replace("time = 2", "time = -2").encode() if suffix == ".toml"
                      else b"\xef\xbb\xbf" + text.replace('"time": 2', '"time": -2').encode())
    done = _run("check", scene, cwd=tmp_path)
    assert done.returncode == 2 and done.stderr.count("\n") == 1
    if suffix == ".toml":
        assert "(line 9)" in done.stderr, done.stderr  # "time = 2" is the 9th line of SQUARE


BAD_FLAGS = [
    (("render", "{scene}", "--format", "avi"), "argument --format: invalid choice: 'avi'"),
    (("render", "{scene}", "--bogus"), "unrecognized arguments: --bogus"),
    (("render", "{scene}", "--workers"), "argument --workers: expected one argument"),
    (("render",), "the following arguments are required: SCENE"),
    (("frobnicate",), "argument COMMAND: invalid choice: 'frobnicate'"),
    ((), "the following arguments are required: COMMAND"),
    (("stats", "{scene}", "--json", "--t"), "argument --t: expected one argument"),
    (("correspond", "{scene}", "--cost", "cheap"), "--cost: expected one of distance, sg, found 'cheap'"),
]


@pytest.mark.parametrize("args, words", BAD_FLAGS, ids=[" ".join(a) or "nothing" for a, _ in BAD_FLAGS])
def test_a_bad_flag_is_one_line(tmp_path: Path, args: tuple[str, ...], words: str) -> None:
    scene = write_scene(tmp_path, SQUARE)
    done = _run(*[a.format(scene=scene) for a in args], cwd=tmp_path)
    assert done.returncode == 2 and done.stdout == ""
    assert done.stderr.startswith(f"tweenrender: error: {words}") and done.stderr.count("\n") == 1, done.stderr
    # argparse's own refusals point to --help; a value the library refuses names the flag instead
    assert "usage:" not in done.stderr and ("(see tweenrender" in done.stderr or words.startswith("--"))


def test_help_and_version_still_print_and_exit_0(tmp_path: Path) -> None:
    done = _run("render", "--help", cwd=tmp_path)
    assert done.returncode == 0 and done.stdout.startswith("usage: tweenrender render") and done.stderr == ""
    done = _run("--version", cwd=tmp_path)
    assert done.returncode == 0 and done.stdout.startswith("tweenrender ")


@pytest.mark.parametrize("transform", ["matrix(0 5e-324 0 1 0 0)", "matrix(0 5e-324 0 1 0 0) scale(3)",
                                       "matrix(1 2 2 4 0 0)"])
def test_a_collapsing_svg_transform_prints_nothing_on_stderr(tmp_path: Path, transform: str) -> None:
    """A transform with a subnormal entry made numpy's LU determinant divide by zero (a warning on
    stderr); whatever the matrix, the element is drawn or dropped quietly."""
    drawing = tmp_path / "odd.svg"
    drawing.write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 24 24">'
                       f'<path transform="{transform}" stroke="red" d="M2 2 L10 2 L10 10 Z"/>'
                       '<rect x="3" y="3" width="10" height="8"/></svg>')
    done = _run("render", drawing, drawing, "-o", "frames", "-q", "--frames", "0:2", cwd=tmp_path)
    assert done.returncode == 0 and done.stderr == "", done.stderr
