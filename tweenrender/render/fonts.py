"""The typeface shipped with the package (DejaVu Sans), so labels look the same everywhere."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import skia

__all__ = ["typeface", "font"]

_FOLDER = Path(__file__).with_name("fonts")


@lru_cache(maxsize=None)
def typeface(bold: bool = False) -> skia.Typeface:
    name = "DejaVuSans-Bold.ttf" if bold else "DejaVuSans.ttf"
    face = skia.Typeface.MakeFromFile(str(_FOLDER / name))
    return face if face is not None else skia.Typeface.MakeDefault()


def font(size: float, bold: bool = False) -> skia.Font:
    """An antialiased font of ``size`` pixels."""
    f = skia.Font(typeface(bold), size)
    f.setEdging(skia.Font.Edging.kAntiAlias)
    f.setSubpixel(True)
    return f
