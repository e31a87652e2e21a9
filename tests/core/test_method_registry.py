"""The method registry is the one list of methods: the docs' tables, the scene format, the command line
and ``stats`` follow it."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from tweenrender.core.methods.registry import METHODS, REGISTRY, interpolate, measured_methods
from tweenrender.errors import GeometryError

ROOT = Path(__file__).resolve().parents[2]


def _table_methods(text: str) -> list[str]:
    """The method names of the first markdown table whose header starts with ``| method |``."""
    rows = text.split("| method |", 1)[1].split("\n\n", 1)[0].splitlines()[2:]
    return [re.match(r"\| `([\w-]+)` \|", row).group(1) for row in rows if row.startswith("| `")]


def test_the_docs_method_table_lists_exactly_the_registry() -> None:
    assert _table_methods((ROOT / "docs" / "methods.md").read_text()) == list(METHODS)


def test_the_readme_names_every_method_and_no_other() -> None:
    table = (ROOT / "README.md").read_text().split("## Methods", 1)[1].split("\n## ", 1)[0]
    named = set(re.findall(r"`([a-z][\w-]*)`", table)) & (set(METHODS) | set(_table_methods(table)))
    assert set(_table_methods(table)) <= set(METHODS)
    assert named == set(METHODS)


def test_the_scene_format_and_the_command_line_take_exactly_the_registry(tmp_path: Path) -> None:
    from tweenrender.cli.main import build_parser
    from tweenrender.scenefile import parse_scene

    scene = 'size = [64, 48]\n[[shape]]\nname = "s"\nmethod = "{}"\njoints = [[0, 2]]\n' \
            '[[shape.key]]\ntime = 0\npoints = [[0, 0], [1, 0], [1, 1], [0, 1]]\n'
    for name in METHODS:
        assert parse_scene(scene.format(name), tmp_path / "s.toml").shapes[0].method == name
    helped = build_parser()._subparsers._group_actions[0].choices["render"].format_help()  # type: ignore[union-attr]
    assert all(name in helped for name in METHODS)


def test_measured_methods_leave_out_only_those_needing_joints() -> None:
    assert set(measured_methods(jointed=True)) == set(METHODS)
    assert set(METHODS) - set(measured_methods(jointed=False)) == {m for m in METHODS if REGISTRY[m].needs_joints}


def test_an_unknown_method_is_refused_with_a_suggestion() -> None:
    with pytest.raises(GeometryError, match=r"unknown method 'rigd' \(did you mean 'rigid'\?\)"):
        interpolate([[0, 0], [1, 0], [0, 1]], [[0, 0], [1, 0], [0, 1]], [0.5], "rigd")
