"""The metric charts measure the shapes balanced as the scene says."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tests.helpers import write_scene
from tweenrender.core.measures import SWEEP, curves
from tweenrender.core.timing.timeline import build_track
from tweenrender.scenefile import load_scene

SCENE = """size = [160, 120]
balance = "{balance}"

[[shape]]
name = "square to heptagon"

[[shape.key]]
time = 0
points = [[0, 0], [4, 0], [4, 4], [0, 4]]

[[shape.key]]
time = 1
points = [[2, -1], [4.5, 0.5], [5, 3], [3.5, 5], [0.5, 5], [-1, 3], [-0.5, 0.5]]
"""


@pytest.mark.parametrize("balance", ["copies", "spread"])
def test_metric_panels_measure_the_scenes_balance(tmp_path: Path, balance: str) -> None:
    from tweenrender.reports.metric_report import metric_panels

    scene = load_scene(write_scene(tmp_path, SCENE.format(balance=balance)))
    (panel,) = metric_panels(scene, ["linear"])
    assert f"({balance})" in panel.subtitle
    # the same keys balanced by hand: a copy of a square's corner sits on that corner, a spread one
    # on one of its edges, so the two balance rules give different inbetweens (and measures)
    square = np.array([[0, 0], [4, 0], [4, 4], [0, 4]], float)
    expected = {}
    for rule in ("copies", "spread"):
        track = build_track(scene.shapes[0], scene.matching, unmatched=scene.unmatched, balance=rule)
        k0 = track.segments[0].k0
        on_corner = np.all([np.min(np.hypot(*(square - p).T)) < 1e-9 for p in k0])
        assert on_corner == (rule == "copies")
        expected[rule] = curves(track.segments[0].k0, track.segments[0].k1, "linear", SWEEP, ()).perimeter_ratio
    assert not np.allclose(expected["copies"], expected["spread"])
    assert np.allclose(panel.series["linear"]["perimeter_ratio"], expected[balance])
