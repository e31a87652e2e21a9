"""``--frames`` counts from the end with negative numbers, as a Python slice does: ``-1`` is the last frame,
``-3:`` the last three, ``:-1`` all but the last; a selection of nothing is refused in one line."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tweenrender.errors import OptionError
from tweenrender.plan.job import pick_frames

from tests.helpers import SQUARE, read_png, run_main, write_scene


@pytest.mark.parametrize("text, expected", [
    ("-1", [48]), ("-49", [0]), ("-3:", [46, 47, 48]), (":-1", list(range(48))), ("-5:-3", [44, 45]),
    ("48", [48]), ("0", [0]), ("10:13", [10, 11, 12]),
])
def test_negative_frames_count_from_the_end(text: str, expected: list[int]) -> None:
    assert list(pick_frames(text, 49)) == expected  # a clip of 49 frames: 0 to 48


@pytest.mark.parametrize("text", ["-50", "49", "-1:-1", "5:2", "x", "1:2:3"])
def test_a_selection_of_nothing_is_refused(text: str) -> None:
    with pytest.raises(OptionError, match="frames"):
        pick_frames(text, 49)


def test_the_command_line_renders_the_last_frame(tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE)
    for name, frames in (("last", "-1"), ("by-index", "48")):
        done = run_main("render", scene, "-o", tmp_path / name, "--frames", frames, "-q")
        assert done.returncode == 0, done.stderr
    assert np.array_equal(read_png(tmp_path / "last" / "frame_0000.png"),
                          read_png(tmp_path / "by-index" / "frame_0000.png"))
