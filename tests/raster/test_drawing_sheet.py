"""The sheet of a drawing pair is a filmstrip of the frames as drawn, a row per method."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tests.helpers import DATA
from tweenrender.plan.job import scene_view, tracks_of
from tweenrender.reports.pictures import write_sheet


def test_a_drawing_sheet_shows_its_keys_filled_with_their_own_paint(tmp_path: Path) -> None:
    import imageio.v3 as iio

    icons = DATA / "icons" / "twemoji"
    scene = tr.load_scene([icons / "1f4c4.svg", icons / "1f69a.svg"])
    tracks = tracks_of(scene)
    view = scene_view(scene, tracks, ("linear", "auto"))
    picture = iio.imread(write_sheet(scene, tracks, ("linear", "auto"), view, tmp_path / "sheet.png", count=3))
    # five cells a row (two keys, three inbetweens): a row as tall as a cell, its caption and the label band
    assert picture.shape[1] == 1280 and picture.shape[0] < 64 + 2 * (1280 / 5 + 90)
    red = np.all(np.abs(picture[..., :3].astype(int) - (0xDD, 0x2E, 0x44)) <= 3, axis=-1)  # the truck's own red
    columns = np.flatnonzero(red.any(axis=0))
    assert red.sum() > 2000  # filled, at full strength, not a faint outline
    assert columns.min() > 1280 * 0.5  # only towards the end of the strip, where the truck is
    rows = np.flatnonzero(red.any(axis=1))
    assert rows.max() - rows.min() > picture.shape[0] / 3  # in both rows


@pytest.mark.parametrize(("value", "label"), [(1 / 12, "0.083"), (0.5, "0.5"), (1.0, "1"), (10.0, "10"),
                                              (-0.0004, "0"), (-0.5, "-0.5"), (1234.5678, "1234.568")])
def test_a_sheet_labels_times_to_the_millisecond(value: float, label: str) -> None:
    """Eleven in-betweens of a second fall every 1/12 s: labelled 0.083 s, not 0.0833333 s."""
    from tweenrender.raster.plots.storyboard import seconds

    assert seconds(value) == label
