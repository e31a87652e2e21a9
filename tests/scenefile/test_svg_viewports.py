"""The root viewport: ``width`` × ``height`` is the picture, the ``viewBox`` placed in it by
``preserveAspectRatio`` (SVG 1.1 §7.8). Where the square lands is worked out by hand from the rule."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr


def _ink(tmp_path: Path, par: str) -> tuple[int, int, int, int]:
    """(left, top, right, bottom) pixel bounds of the green square in a 200 × 100 picture."""
    svg = tmp_path / "p.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="200" height="100" viewBox="0 0 100 100" '
                   f'preserveAspectRatio="{par}"><rect x="0" y="0" width="100" height="100" fill="#008000"/></svg>')
    picture = tr.frame(tr.load_scene(svg), 0.0, size=(200, 100), background="#ffffff")
    ys, xs = np.nonzero((picture[..., :3] != 255).any(axis=-1))
    return int(xs.min()), int(ys.min()), int(xs.max()) + 1, int(ys.max()) + 1


@pytest.mark.parametrize(("par", "bounds"), [
    ("xMidYMid meet", (50, 0, 150, 100)),
    ("xMinYMin meet", (0, 0, 100, 100)),
    ("xMaxYMax", (100, 0, 200, 100)),
    ("none", (0, 0, 200, 100)),
    ("xMidYMid slice", (0, 0, 200, 100)),
])
def test_the_view_box_is_placed_by_preserve_aspect_ratio(tmp_path: Path, par: str,
                                                         bounds: tuple[int, int, int, int]) -> None:
    assert _ink(tmp_path, par) == bounds
