"""Title cards and the frame around a reel's comparison, drawn with the shipped font."""

from __future__ import annotations

from typing import Sequence

import numpy as np
from numpy.typing import NDArray

from ..model import Color
from .fonts import font
from .surface import Raster

__all__ = ["CARD_BACKGROUND", "draw_card", "draw_band"]

CARD_BACKGROUND: Color = (21, 24, 31, 255)
_TITLE: Color = (245, 246, 250, 255)
_ACCENT: Color = (126, 170, 255, 255)
_SOFT: Color = (245, 246, 250, 150)


def _centred(raster: Raster, words: str, y: float, size: float, color: Color, bold: bool = False) -> None:
    width = font(size, bold).measureText(words)
    if width > raster.width * 0.92:  # shrink a long line to fit rather than clip it
        size *= raster.width * 0.92 / width
        width = font(size, bold).measureText(words)
    raster.text(words, 0.5 * (raster.width - width), y, size, color, bold)


def draw_card(width: int, height: int, title: str, methods: Sequence[str], notes: Sequence[str] = (),
              corner: str = "") -> NDArray[np.uint8]:
    """A title card, straight RGBA ``(height, width, 4)`` (a new array).

    ``title`` big in the middle, the compared ``methods`` under it, then ``notes``
    in small type; ``corner`` (e.g. ``"2 / 5"``) in the bottom-right corner.
    """
    raster = Raster(width, height)
    raster.clear(CARD_BACKGROUND)
    unit = height / 18
    _centred(raster, title, height * 0.42, unit * 1.15, _TITLE, bold=True)
    _centred(raster, "   vs   ".join(methods), height * 0.42 + unit * 1.9, unit * 0.95, _ACCENT, bold=True)
    for row, note in enumerate(notes):
        _centred(raster, note, height * 0.42 + unit * (3.3 + 0.95 * row), unit * 0.55, _SOFT)
    if corner:
        size = unit * 0.5
        raster.text(corner, width - font(size).measureText(corner) - unit * 0.6, height - unit * 0.6, size, _SOFT)
    return raster.rgba().copy()


def draw_band(width: int, height: int, band: int, title: str, corner: str = "") -> NDArray[np.uint8]:
    """The reel's frame around a comparison: dark, ``title`` in a top band ``band`` pixels tall."""
    raster = Raster(width, height)
    raster.clear(CARD_BACKGROUND)
    size = band * 0.45
    pad = band * 0.4
    raster.text(title, pad, band * 0.66, size, _TITLE, bold=True)
    if corner:
        raster.text(corner, width - font(size * 0.8).measureText(corner) - pad, band * 0.66, size * 0.8, _SOFT)
    return raster.rgba().copy()
