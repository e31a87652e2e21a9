"""``--max-memory``: an ``sg`` search past the limit is refused in one line (exit 2, nothing written);
under it the command runs as without the flag."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.helpers import SCENES

FEET = SCENES / "bird-feet.toml"  # keys of 22 and 20 vertices: about 53 KiB of sg tables


@pytest.mark.parametrize("command, target", [("correspond", "picture.png"), ("render", "clip.mp4"),
                                             ("sheet", "sheet.png"), ("report", "report.html")])
def test_a_search_past_the_limit_is_refused_in_one_line(cli, tmp_path: Path, command: str, target: str) -> None:
    output = tmp_path / target
    code, out, err = cli(command, FEET, "--cost", "sg", "--max-memory", "8K", "-o", output)
    assert code == 2 and out.strip() in ("", str(FEET))
    assert err.count("\n") == 1 and "Traceback" not in err and err.startswith("tweenrender: error: ")
    assert "22 × 20 vertices" in err and "--cost distance" in err and "8 KiB" in err
    assert not output.exists()


def test_under_the_limit_the_search_runs(cli) -> None:
    code, out, err = cli("correspond", FEET, "--cost", "sg", "--max-memory", "1M", "--json")
    assert code == 0, err
    default = cli("correspond", FEET, "--cost", "sg", "--json")
    assert json.loads(out) == json.loads(default[1])


def test_the_distance_cost_ignores_the_limit(cli) -> None:
    code, out, err = cli("correspond", FEET, "--cost", "distance", "--max-memory", "1K", "--json")
    assert code == 0, err


@pytest.mark.parametrize("size", ["2X", "0", "lots"])
def test_a_size_that_is_no_size_names_the_flag(cli, size: str) -> None:
    code, _, err = cli("correspond", FEET, "--cost", "sg", "--max-memory", size)
    assert code == 2 and err.startswith("tweenrender: error: --max-memory: expected a size") and err.count("\n") == 1
