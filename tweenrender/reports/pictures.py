"""Storyboard sheets, drawn and written as PNG atomically."""

from __future__ import annotations

from pathlib import Path
from typing import Sequence

from ..core.timing.timeline import Track
from ..model import Scene
from ..core.view import Box

__all__ = ["write_sheet"]


def write_sheet(scene: Scene, tracks: Sequence[Track], methods: Sequence[str], view: Box, target: Path,
                count: int = 7, size: tuple[int, int] | None = None, paths: bool = False) -> Path:
    """Draw the sheet and write it to ``target`` (a temporary sibling, then ``os.replace``)."""
    from ..encode.images import write_png
    from ..raster.plots.storyboard import draw_sheet, is_drawing, sheet_layout

    cells = count + 2 if is_drawing(scene) else 1  # a drawing's sheet is a filmstrip: keys and inbetweens
    picture = draw_sheet(scene, tracks, methods, view, sheet_layout(view, len(methods), size, cells), count, paths)
    return write_png(picture, target, "the sheet")

