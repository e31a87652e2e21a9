"""Names: too long for the file system, no name at all, odd characters in a title or a file name.

Every case runs the real command line: one line on stderr, the right exit code, no traceback, and
nothing written beside the target.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from tests.helpers import SQUARE, run_main, write_scene

NAME_MAX = os.pathconf("/tmp", "PC_NAME_MAX")  # 255 on every Linux file system the tests run on


def _clean_refusal(done, *words: str) -> None:  # type: ignore[no-untyped-def]
    assert done.returncode == 2, (done.returncode, done.stderr)
    assert done.stderr.startswith("tweenrender: error: ") and done.stderr.count("\n") == 1, done.stderr
    assert "unexpected" not in done.stderr and "Traceback" not in done.stderr
    for word in words:
        assert word in done.stderr, done.stderr


COMMANDS = {
    "render mp4": ("render", "{scene}", "-o", "{name}.mp4", "--frames", "0:2", "-q"),
    "render gif": ("render", "{scene}", "-o", "{name}.gif", "--frames", "0:2", "-q"),
    "render png": ("render", "{scene}", "-o", "{name}", "--format", "png", "--frames", "0:2", "-q"),
    "sheet": ("sheet", "{scene}", "-o", "{name}.png"),
    "correspond": ("correspond", "{scene}", "-o", "{name}.png"),
    "qcurves": ("qcurves", "{scene}", "-o", "{name}.png"),
    "reel": ("reel", "{scene}", "-o", "{name}.mp4", "-q"),
    "report": ("report", "{scene}", "--compare", "linear", "-o", "{name}", "-q"),
}


@pytest.mark.parametrize("command", list(COMMANDS))
@pytest.mark.parametrize("length", [NAME_MAX + 20, NAME_MAX - 8], ids=["over", "no room for the temporary"])
def test_an_output_name_too_long_for_the_file_system_is_a_usage_error(tmp_path: Path, command: str,
                                                                     length: int) -> None:
    write_scene(tmp_path, SQUARE)
    name = "n" * length
    args = [a.format(scene="scene.toml", name=name) for a in COMMANDS[command]]
    done = run_main(*args, cwd=tmp_path)
    _clean_refusal(done, "too long")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]


@pytest.mark.parametrize("command", ["check", "render", "report", "sheet"])
def test_a_scene_name_too_long_is_one_line(tmp_path: Path, command: str) -> None:
    done = run_main(command, "s" * (NAME_MAX + 5) + ".toml", cwd=tmp_path)
    _clean_refusal(done, "too long")


@pytest.mark.parametrize("name", [".", "..", "", "/"])
def test_report_to_no_folder_of_its_own_is_a_usage_error(tmp_path: Path, name: str) -> None:
    write_scene(tmp_path, SQUARE)
    done = run_main("report", "scene.toml", "--compare", "linear", "-o", name, "-q", cwd=tmp_path)
    _clean_refusal(done, "report")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]


def test_a_surrogate_in_the_title_does_not_crash_the_report(tmp_path: Path) -> None:
    # JSON may spell a lone surrogate; Python reads it as one
    text = ('{"title": "caf\\udce9 \\u00e9t\\u00e9", "size": [64, 48], '
            '"shape": [{"name": "s\\ud800", "key": [{"time": 0, "points": [[0, 0], [4, 0], [4, 4]]}, '
            '{"time": 0.5, "points": [[1, 0], [5, 0], [5, 4]]}]}]}')
    write_scene(tmp_path, text, "odd.json")
    done = run_main("report", "odd.json", "--compare", "linear", "-o", "r", "-q", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    page = (tmp_path / "r" / "index.html").read_bytes().decode("utf-8")  # valid UTF-8 throughout
    assert "caf\ufffd été" in page and "s\ufffd" in page


@pytest.mark.parametrize("odd", ["new\nline", "esc\x1b[31mred", "bell\x07"])
def test_odd_characters_in_a_name_are_escaped_when_report_prints_it(tmp_path: Path, odd: str) -> None:
    write_scene(tmp_path, SQUARE, f"{odd}.toml")
    done = run_main("report", f"{odd}.toml", "--compare", "linear", "-q", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert done.stdout.count("\n") == 1 and "\x1b" not in done.stdout and "\x07" not in done.stdout
    assert repr(odd)[1:-1] in done.stdout
    assert (tmp_path / "output" / f"{odd}-report" / "index.html").is_file()


def test_odd_characters_in_a_shape_name_are_escaped_in_the_page(tmp_path: Path) -> None:
    write_scene(tmp_path, SQUARE.replace('name = "sq"', 'name = "<b>sq</b> & \\"x\\""'))
    done = run_main("report", "scene.toml", "--compare", "linear", "-o", "r", "-q", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    page = (tmp_path / "r" / "index.html").read_text()
    assert "<b>sq</b>" not in page and "&lt;b&gt;sq&lt;/b&gt; &amp; &quot;x&quot;" in page
