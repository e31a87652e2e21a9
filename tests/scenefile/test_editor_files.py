"""Drawings as Figma, Illustrator and Inkscape export them (``tests/data/editors``, with their sources and
licences) drawn at their key frame as librsvg draws them.

Each file is drawn about 600 pixels across: a copy whose root ``width`` and ``height`` are whole pixels
(its ``viewBox`` kept, or the one its size implies), so that both renderers place it on the same pixels.
"""

from __future__ import annotations

import math
import re
import subprocess
import warnings
from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tests.helpers import DATA
from tests.scenefile.test_icons import RSVG, needs_rsvg
from tests.scenefile.test_key_frames import measures

EDITORS = DATA / "editors"
FILES = sorted(p.name for p in EDITORS.glob("*.svg"))
_SIDE = 600
_UNITS = {"": 1.0, "px": 1.0, "pt": 96 / 72, "pc": 16.0, "mm": 96 / 25.4, "cm": 96 / 2.54, "in": 96.0}


def _whole_pixels(svg: Path, folder: Path) -> Path:
    """A copy of ``svg`` about :data:`_SIDE` pixels across, its root's ``width`` and ``height`` whole pixels."""
    text = svg.read_text(encoding="utf-8", errors="surrogateescape")
    root = re.search(r"<svg\b[^>]*>", text).group(0)  # type: ignore[union-attr]
    sizes = [re.search(rf'\s{name}="\s*([0-9.]+)\s*([a-z]*)\s*"', root) for name in ("width", "height")]
    assert all(sizes), f"{svg.name}: expected a width and a height on the root"
    width, height = (float(m.group(1)) * _UNITS[m.group(2)] for m in sizes)  # type: ignore[union-attr]
    scale = _SIDE / max(width, height)
    placed = root
    if "viewBox" not in root:
        placed = placed.replace("<svg", f'<svg viewBox="0 0 {width!r} {height!r}"', 1)
    placed = re.sub(r'(\s)width="[^"]*"', rf'\g<1>width="{math.ceil(width * scale)}"', placed, count=1)
    placed = re.sub(r'(\s)height="[^"]*"', rf'\g<1>height="{math.ceil(height * scale)}"', placed, count=1)
    copy = folder / svg.name
    copy.write_text(text.replace(root, placed, 1), encoding="utf-8", errors="surrogateescape")
    return copy


def test_the_files_are_kept_with_their_sources() -> None:
    listed = (EDITORS / "README.md").read_text()
    assert len(FILES) >= 6 and all(f"`{name}`" in listed for name in FILES)
    assert {name.split("-")[0] for name in FILES} >= {"figma", "illustrator", "inkscape"}


@needs_rsvg
@pytest.mark.parametrize("name", FILES)
def test_the_key_frame_is_drawn_as_librsvg_draws_it(name: str, tmp_path: Path) -> None:
    import imageio.v3 as iio

    svg = _whole_pixels(EDITORS / name, tmp_path)
    done = subprocess.run([RSVG, "-b", "white", str(svg)], capture_output=True, check=True)
    theirs = iio.imread(done.stdout, mode="RGB").astype(float)
    height, width = theirs.shape[:2]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ours = tr.frame(tr.load_scene(svg), 0.0, size=(width, height), background="#ffffff")[..., :3]
    iou, error = measures(ours.astype(float), theirs)
    assert iou >= 0.99 and error <= 0.02, (iou, error)
    assert np.abs(theirs - 255).max() > 32  # librsvg drew it: the comparison is not of two empty pictures
