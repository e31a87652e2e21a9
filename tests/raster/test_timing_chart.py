"""The animator's marks: a timing chart's ticks are the eased fractions at the frame times, and a sheet
or correspondence picture of a hinted scene shows lettered dots where the hints are."""

from __future__ import annotations

import numpy as np
import pytest

import tweenrender as tr
from tweenrender.core.timing.timeline import build_track
from tweenrender.raster.plots.timing_chart import chart_ticks

SQ = [[0, 0], [2, 0], [2, 2], [0, 2]]
_HINT = np.array([120, 40, 170])


def _scene(tmp_path, timing: str, hints: bool = False, fps: int = 4):
    h0 = "\nhints = { a = [2, 0] }" if hints else ""
    h1 = "\nhints = { a = [12, 2] }" if hints else ""
    text = (f'fps = {fps}\nsize = [320, 200]\n[[shape]]\nname = "s"\nmethod = "linear"\n'
            f'[[shape.key]]\ntime = 1\npoints = {SQ}\n{timing}{h0}\n'
            f'[[shape.key]]\ntime = 3\npoints = {[[x + 10, y] for x, y in SQ]}{h1}\n')
    path = tmp_path / "s.toml"
    path.write_text(text)
    return tr.load_scene(path)


@pytest.mark.parametrize("timing, expected", [
    ('ease = "linear"', np.arange(9) / 8),
    ('ease = "in"', (np.arange(9) / 8) ** 2),
    ('ease = "hold"', np.r_[np.zeros(8), 1.0]),
    ("spacing = [0, 0.1, 0.5, 0.9, 1]", np.array([0, 0.1, 0.5, 0.9, 1])),  # at 2 fps each frame is a tick
])
def test_ticks_are_the_eased_fractions_at_frame_times(tmp_path, timing: str, expected: np.ndarray) -> None:
    fps = 2 if "spacing" in timing else 4
    scene = _scene(tmp_path, timing, fps=fps)
    segment = build_track(scene.shapes[0], scene.matching).segments[0]
    assert chart_ticks(segment, scene.fps) == pytest.approx(expected, abs=1e-15)


def _hint_pixels(picture: np.ndarray) -> int:
    return int((np.abs(picture[..., :3].astype(int) - _HINT).max(axis=-1) < 12).sum())


@pytest.mark.parametrize("command", ["sheet", "correspond"])
def test_hints_are_drawn_as_dots(cli, tmp_path, command: str) -> None:
    import imageio.v3 as iio

    counts = []
    for hinted in (False, True):
        scene = _scene(tmp_path, "", hints=hinted)
        target = tmp_path / f"{command}-{hinted}.png"
        code, _, err = cli(command, scene.path, "-o", target)
        assert code == 0, err
        counts.append(_hint_pixels(iio.imread(target)))
    assert counts[0] == 0 and counts[1] > 100


def test_a_hint_path_runs_from_its_point_to_its_partner(tmp_path) -> None:
    from tweenrender.raster.plots.timing_chart import hint_paths

    scene = _scene(tmp_path, "", hints=True)
    segment = build_track(scene.shapes[0], scene.matching).segments[0]
    (path,) = hint_paths(segment, "linear", samples=5)
    # linear paths: a straight line from (2, 0) on the first key to (12, 2) on the second, evenly
    assert path == pytest.approx(np.column_stack([np.linspace(2, 12, 5), np.linspace(0, 2, 5)]), abs=1e-12)
