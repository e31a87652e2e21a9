"""check_not_an_input: an output that is, or (a folder) holds, a file the command reads is refused,
through symbolic and hard links; a neighbour is not."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from tweenrender.encode.targets import check_not_an_input
from tweenrender.errors import OptionError


def test_the_same_file_by_any_name_clashes(tmp_path: Path) -> None:
    source = tmp_path / "b.svg"
    source.write_text("<svg/>")
    (tmp_path / "soft.gif").symlink_to(source)
    os.link(source, tmp_path / "hard.gif")
    (tmp_path / "sub").mkdir()
    for name in ("b.svg", "soft.gif", "hard.gif", "sub/../b.svg"):
        with pytest.raises(OptionError, match=r"b\.svg, which this command reads"):
            check_not_an_input(tmp_path / name, [source])
    check_not_an_input(tmp_path / "b.gif", [source])  # a neighbour is fine
    check_not_an_input(tmp_path / "new" / "b.svg", [source])  # so is a file of that name elsewhere


def test_a_folder_output_clashes_with_what_it_holds(tmp_path: Path) -> None:
    (tmp_path / "out" / "deep").mkdir(parents=True)
    source = tmp_path / "out" / "deep" / "scene.toml"
    source.write_text("")
    with pytest.raises(OptionError, match="holds .*scene.toml"):
        check_not_an_input(tmp_path / "out", [source], folder=True)
    check_not_an_input(tmp_path / "out", [source])  # as a file target, a folder is not its content
    check_not_an_input(tmp_path / "ou", [source], folder=True)  # a prefix of the name is not the folder
    elsewhere = tmp_path / "scene.toml"
    elsewhere.write_text("")
    (tmp_path / "report").mkdir()
    (tmp_path / "report" / "index.html").symlink_to(elsewhere)
    with pytest.raises(OptionError, match="index.html: is"):
        check_not_an_input(tmp_path / "report", [elsewhere], folder=True, files=["index.html"])
