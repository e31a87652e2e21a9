"""Inputs that cannot hang or explode: only regular files are read, hostile style sheets are read
or refused in one line and selector matching is counted, counts of keys and shapes are refused before
work starts, every number of a transform is checked.

Each case runs the command line in a child process (forked from the test's, Python's warnings raised as
errors) with a deadline far above what a correct run needs; the assertions are on what it printed, never on
how long it took.
"""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

from tests.helpers import SQUARE, run_forked, write_scene

SVG = ('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">'
       '<path id="a" d="M1 1 L9 1 L9 9 Z"{extra}/></svg>')


def _run(*args: object, cwd: Path) -> subprocess.CompletedProcess[str]:
    """The command in a forked child; a hang fails the test (the deadline is minutes above a correct run)."""
    try:
        return run_forked(*map(str, args), cwd=cwd, deadline=120, warnings_as_errors=True)
    except subprocess.TimeoutExpired:
        pytest.fail("the command did not return: it hung on its input")


def _one_line(done: subprocess.CompletedProcess[str], *words: str) -> None:
    assert done.returncode == 2, done.stderr
    assert done.stderr.startswith("tweenrender: error: ") and done.stderr.count("\n") == 1, done.stderr
    assert "Traceback" not in done.stderr and "unexpected" not in done.stderr and "Warning" not in done.stderr
    for word in words:
        assert word in done.stderr, done.stderr


# -- only regular files -----------------------------------------------------------------------------

def _drawing_scene(folder: Path, svg: str) -> Path:
    return write_scene(folder, f'[[drawing]]\ntime = 0\nsvg = "{svg}"\n[[drawing]]\ntime = 1\nsvg = "b.svg"\n',
                       "drawings.toml")


@pytest.mark.parametrize("kind", ["fifo", "device", "folder"])
@pytest.mark.parametrize("how", ["command line", "scene's drawing", "scene's key"])
def test_a_non_regular_svg_is_refused_at_once(tmp_path: Path, kind: str, how: str) -> None:
    (tmp_path / "b.svg").write_text(SVG.format(extra=""))
    if kind == "fifo":
        os.mkfifo(tmp_path / "a.svg")  # no writer ever comes: open() without O_NONBLOCK waits for ever
        name = "a.svg"
    elif kind == "device":
        (tmp_path / "a.svg").symlink_to("/dev/zero")  # endless bytes
        name = "a.svg"
    else:
        (tmp_path / "a.svg").mkdir()
        name = "a.svg"
    if how == "command line":
        done = _run("check", name, "b.svg", cwd=tmp_path)
    elif how == "scene's drawing":
        _drawing_scene(tmp_path, name)
        done = _run("check", "drawings.toml", cwd=tmp_path)
    else:
        write_scene(tmp_path, f'[[shape]]\nname = "s"\n[[shape.key]]\ntime = 0\n'
                              f'points = {{ svg = "{name}", id = "a" }}\n', "keyed.toml")
        done = _run("check", "keyed.toml", cwd=tmp_path)
    _one_line(done, "a.svg", {"fifo": "pipe", "device": "device", "folder": "folder"}[kind])


# -- style sheets ------------------------------------------------------------------------------------

HOSTILE = {
    "one 120 kB selector": "a" * 120_000,
    "one 120 kB rule": "path" + ".x" * 60_000 + " { fill: red }",
    "many rules": "path.c { fill: red }\n" * 12_000,
    "unclosed comments": "/*" * 60_000,
    "unclosed blocks": "a {" * 40_000,
    "stray closings": "} a" * 40_000,
    "nested negations": ":not(" * 20_000 + "a" + ")" * 20_000 + " { fill: red }",
    "nested brackets": "[" * 60_000,
    "a value nested deep": "path { fill: " + "(" * 50_000 + " }",
    "a value of nested functions": "path { fill: " + "f(" * 50_000 + " }",
}


@pytest.mark.parametrize("name", list(HOSTILE))
def test_a_hostile_style_sheet_is_read_or_refused_in_one_line(tmp_path: Path, name: str) -> None:
    sheet = HOSTILE[name]
    (tmp_path / "a.svg").write_text(SVG.format(extra=' class="c"').replace("<path", f"<style>{sheet}</style><path"))
    (tmp_path / "b.svg").write_text(SVG.format(extra=""))
    done = _run("check", "a.svg", "b.svg", cwd=tmp_path)
    if done.returncode != 0:
        _one_line(done, "a.svg", "style")


def test_a_style_attribute_nested_deep_is_read(tmp_path: Path) -> None:
    (tmp_path / "a.svg").write_text(SVG.format(extra=' style="fill: ' + "(" * 50_000 + '"'))
    (tmp_path / "b.svg").write_text(SVG.format(extra=""))
    done = _run("check", "a.svg", "b.svg", cwd=tmp_path)
    assert done.returncode == 0 and not done.stderr, done.stderr


def test_selectors_walking_a_deep_tree_combinatorially_are_refused(tmp_path: Path) -> None:
    """``circle g g g g g g g g path`` over 150 nested groups tries every choice of 8 of the ancestors
    (10^13) before it fails: the matcher's count of elements walked refuses it instead of running for hours."""
    depth = 150
    body = "<g>" * depth + '<path id="a" d="M1 1 L9 1 L9 9 Z"/>' + "</g>" * depth
    (tmp_path / "a.svg").write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">'
                                    f"<style>circle {'g ' * 8}path {{ fill: red }}</style>{body}</svg>")
    (tmp_path / "b.svg").write_text(SVG.format(extra=""))
    _one_line(_run("check", "a.svg", "b.svg", cwd=tmp_path), "a.svg", "style rules")


def test_a_drawing_with_a_huge_style_sheet_loads(tmp_path: Path) -> None:
    sheet = "path.c { fill: red }\n" * 12_000 + "path" + ".x" * 60_000 + " { fill: red }"
    (tmp_path / "a.svg").write_text(SVG.format(extra=' class="c"').replace("<path", f"<style>{sheet}</style><path"))
    (tmp_path / "b.svg").write_text(SVG.format(extra=""))
    done = _run("check", "a.svg", "b.svg", cwd=tmp_path)
    assert done.returncode == 0, done.stderr


# -- counts refused before work -----------------------------------------------------------------------

def test_too_many_keys_are_refused_before_work(tmp_path: Path) -> None:
    keys = "".join(f"[[shape.key]]\ntime = {i}\npoints = [[0, 0], [1, 0], [1, 1]]\n" for i in range(10_001))
    write_scene(tmp_path, '[[shape]]\nname = "s"\n' + keys, "keys.toml")
    _one_line(_run("check", "keys.toml", cwd=tmp_path), "10000 keys", "10001")


def test_too_many_shapes_are_refused_before_work(tmp_path: Path) -> None:
    shapes = "".join(f'[[shape]]\nname = "s{i}"\n[[shape.key]]\ntime = 0\npoints = [[0, 0], [1, 0], [1, 1]]\n'
                     for i in range(10_001))
    write_scene(tmp_path, shapes, "shapes.toml")
    _one_line(_run("check", "shapes.toml", cwd=tmp_path), "10000 shapes", "10001")


def test_as_many_keys_as_allowed_still_load(tmp_path: Path) -> None:
    from tweenrender.scenefile import LIMITS

    assert LIMITS["keys"] == 10_000 and LIMITS["shapes"] == 10_000
    keys = "".join(f"[[shape.key]]\ntime = {i}\npoints = [[0, 0], [1, 0], [1, 1]]\n" for i in range(10_000))
    write_scene(tmp_path, '[[shape]]\nname = "s"\n' + keys, "keys.toml")
    done = _run("check", "keys.toml", cwd=tmp_path)
    assert done.returncode == 0, done.stderr


# -- transforms ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("transform", ["scale(NaN)", "scale(nan)", "translate(1e308) scale(1e308)", "scale(1e308)",
                                       "scale(1e400)", "matrix(1 0 0 1 1e400 0)", "rotate(1e400)",
                                       "scale(1e200) scale(1e200)", "skewX(inf)"])
def test_every_number_of_a_transform_is_checked(tmp_path: Path, transform: str) -> None:
    (tmp_path / "a.svg").write_text(SVG.format(extra=f' transform="{transform}"'))
    (tmp_path / "b.svg").write_text(SVG.format(extra=""))
    for args in (("check", "a.svg", "b.svg"), ("render", "a.svg", "b.svg", "-o", "x.gif", "--frames", "0:2")):
        done = _run(*args, cwd=tmp_path)
        _one_line(done, "a.svg", "transform")
    assert not (tmp_path / "x.gif").exists()


def test_a_large_but_finite_transform_still_draws(tmp_path: Path) -> None:
    (tmp_path / "a.svg").write_text(SVG.format(extra=' transform="scale(1e-3) scale(1e3)"'))
    (tmp_path / "b.svg").write_text(SVG.format(extra=""))
    assert _run("check", "a.svg", "b.svg", cwd=tmp_path).returncode == 0


def test_a_regular_scene_still_loads(tmp_path: Path) -> None:
    write_scene(tmp_path, SQUARE)
    assert _run("check", "scene.toml", cwd=tmp_path).returncode == 0
