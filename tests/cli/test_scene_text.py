"""Text from a scene (names, titles, file names) never breaks a command or reaches the terminal raw.

Each run in a child process (forked from the test's, its streams writing to pipes as a terminal's
output redirected would: UTF-8, strict on stdout) and read back as strict UTF-8: a lone surrogate
cannot be encoded, and a newline, carriage return or escape sequence in a name must arrive escaped.
"""

from __future__ import annotations

import json
import unicodedata
from pathlib import Path

import pytest

from tests.helpers import SQUARE, run_forked, write_scene

NASTY = "a\ud800b\x1b[2J\rX\nY\x9b31m\u2028Z"
"""A lone surrogate, a clear-screen escape, a carriage return, a newline, a C1 CSI, a line separator."""
ESCAPED = "a\\ud800b\\x1b[2J\\rX\\nY\\x9b31m\\u2028Z"


def _scene(folder: Path, title: str = "T\ud800\x1b]0;owned\x07\nline two", name: str = NASTY) -> Path:
    keys = [{"time": 0, "points": [[0, 0], [2, 0], [2, 2], [0, 2]]},
            {"time": 1, "points": [[7, 1], [7, 3], [5, 3], [5, 1]]}]
    data = {"title": title, "size": [160, 120], "fps": 4, "view": [-2, -2, 10, 7],
            "shape": [{"name": name, "key": keys}]}
    path = folder / "scene.json"
    path.write_text(json.dumps(data))  # json escapes the surrogate as \ud800, which json.loads gives back
    return path


def _run(*args: object, cwd: Path) -> tuple[int, str, str]:
    # read back as strict UTF-8: a surrogate written with surrogateescape or the like would fail there
    done = run_forked(*map(str, args), cwd=cwd, deadline=300)
    return done.returncode, done.stdout, done.stderr


def _clean(text: str) -> bool:
    """No control character but the newlines between lines, no line or paragraph separator."""
    return all(c == "\n" or unicodedata.category(c) not in ("Cc", "Cs", "Zl", "Zp") for c in text)


COMMANDS = [
    ("check",), ("check", "--json"), ("stats",), ("stats", "--json"), ("qcurves", "-o", "q.png"),
    ("qcurves", "--json"), ("correspond", "-o", "c.png"), ("correspond", "--json"), ("sheet", "-o", "s.png"),
    ("reel", "-o", "reel", "--size", "320x180", "--fps", "4"), ("render", "-o", "frames", "--compare", "-q"),
]


@pytest.mark.parametrize("command", COMMANDS, ids=[" ".join(c) for c in COMMANDS])
def test_every_command_takes_a_scene_with_unprintable_names(tmp_path: Path, command: tuple[str, ...]) -> None:
    scene = _scene(tmp_path)
    code, out, err = _run(command[0], scene, *command[1:], cwd=tmp_path)
    assert code == 0, err
    assert err == "" or command[0] == "reel", err
    assert _clean(out) and _clean(err), (out, err)
    if "--json" in command:
        names = json.dumps(json.loads(out))
        assert "\\ud800" in names  # JSON keeps the name exactly, as JSON escapes
    elif command[0] in ("stats", "qcurves", "correspond"):
        assert ESCAPED in out, out


def test_the_text_reports_print_the_name_escaped_on_its_own_line(tmp_path: Path) -> None:
    scene = _scene(tmp_path)
    code, out, _ = _run("stats", scene, cwd=tmp_path)
    assert code == 0
    assert any(line.startswith(f"SHAPE {ESCAPED}, segment 0 (0 s to 1 s)") for line in out.splitlines()), out


def test_pictures_draw_an_unprintable_title_and_names(tmp_path: Path) -> None:
    import imageio.v3 as iio

    scene = _scene(tmp_path)
    for command in (("sheet", "-o", "s.png"), ("qcurves", "-o", "q.png"), ("correspond", "-o", "c.png")):
        code, _, err = _run(command[0], scene, *command[1:], cwd=tmp_path)
        assert code == 0, err
        picture = iio.imread(tmp_path / command[-1])
        assert picture.shape[0] > 0 and (picture[..., :3] < 128).any()  # something was drawn


def test_error_messages_escape_what_came_from_the_scene(tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE.replace('name = "sq"', 'name = "sq"\nmethod = "lin\\u001b[31mear\\r"'))
    code, out, err = _run("render", scene, "-q", "-o", "x.mp4", cwd=tmp_path)
    assert code == 2 and out == ""
    assert _clean(err) and err.count("\n") == 1, err
    assert "lin\\x1b[31mear\\r" in err


def test_a_file_name_with_a_newline_and_an_escape_is_shown_escaped(tmp_path: Path) -> None:
    name = "bad\n\x1b[31m.toml"
    write_scene(tmp_path, "size = [", name)
    code, out, err = _run("check", name, cwd=tmp_path)
    assert code == 2 and out == ""
    assert _clean(err) and err.count("\n") == 1, err
    assert err.startswith("tweenrender: error: bad\\n\\x1b[31m.toml: ")
    good = "good\r\x1b[2J.toml"
    write_scene(tmp_path, SQUARE, good)
    code, out, err = _run("check", good, name, cwd=tmp_path)
    assert code == 2 and _clean(out) and _clean(err), (out, err)
    assert out.startswith("good\\r\\x1b[2J.toml: ok")
