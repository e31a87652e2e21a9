"""Comparison panels: each method's caption sits above the art, never over it."""

from __future__ import annotations

from pathlib import Path

import numpy as np

import tweenrender as tr
from tweenrender.pipeline.frames import Frames
from tweenrender.plan.job import RenderJob


def test_captions_sit_outside_the_art(tmp_path: Path) -> None:
    # a drawing whose red square fills its whole view box: any caption drawn over the art lands on red
    svg = tmp_path / "full.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">'
                   '<rect width="10" height="10" fill="#ff0000"/></svg>')
    scene = tr.load_scene([svg, svg])
    picture = Frames(RenderJob(scene, ("linear", "auto"), labels=True, size=(240, 240)))(0).copy()
    red = (picture[..., 0] > 200) & (picture[..., 1] < 60) & (picture[..., 2] < 60)
    dark = picture[..., :3].max(axis=-1) < 120
    rows = np.flatnonzero(red.any(axis=1))
    assert dark[: rows[0]].sum() > 50  # the captions are drawn, above the art
    assert not dark[rows[0]: rows[-1] + 1, :].any()  # and nothing dark within the art's rows
    assert rows[-1] - rows[0] + 1 >= 180  # the art keeps most of the panel
