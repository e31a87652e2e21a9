"""The typeface shipped with the package (DejaVu Sans), so labels look the same everywhere."""

from __future__ import annotations

import os
import re
from contextlib import contextmanager
from functools import lru_cache
from pathlib import Path
from typing import Iterator

import skia

__all__ = ["typeface", "font", "wrap", "drawable"]

_FOLDER = Path(__file__).with_name("fonts")
_SURROGATE = re.compile("[\ud800-\udfff]")


@contextmanager
def _quiet_stderr() -> Iterator[None]:
    """Silence file descriptor 2 for a moment.

    skia's bundled fontconfig warns about newer system configuration files it
    cannot parse when its font manager starts; the shipped fonts need none of it.
    """
    try:
        saved = os.dup(2)
    except OSError:
        yield
        return
    try:
        with open(os.devnull, "wb") as null:
            os.dup2(null.fileno(), 2)
            yield
    finally:
        os.dup2(saved, 2)
        os.close(saved)


@lru_cache(maxsize=None)
def typeface(bold: bool = False) -> skia.Typeface:
    name = "DejaVuSans-Bold.ttf" if bold else "DejaVuSans.ttf"
    with _quiet_stderr():
        face = skia.Typeface.MakeFromFile(str(_FOLDER / name))
    return face if face is not None else skia.Typeface.MakeDefault()


def drawable(words: str) -> str:
    """``words`` as skia takes them: UTF-8 cannot carry a lone surrogate, so each becomes U+FFFD."""
    return words if words.isascii() else _SURROGATE.sub("\ufffd", words)


class _Font(skia.Font):
    """A font that measures any ``str``, lone surrogates included (see :func:`drawable`)."""

    def measureText(self, text: str, *args: object, **kwargs: object) -> float:  # noqa: N802 - skia's name
        return super().measureText(drawable(text), *args, **kwargs)  # type: ignore[no-any-return]


def font(size: float, bold: bool = False) -> skia.Font:
    """An antialiased font of ``size`` pixels; it measures any text, lone surrogates included."""
    f = _Font(typeface(bold), size)
    f.setEdging(skia.Font.Edging.kAntiAlias)
    f.setSubpixel(True)
    return f


def wrap(words: str, size: float, width: float) -> list[str]:
    """``words`` broken at spaces into lines no wider than ``width`` pixels at ``size``."""
    face = font(size)
    lines: list[str] = []
    for paragraph in words.split("\n"):
        line = ""
        for word in paragraph.split(" "):
            trial = f"{line} {word}" if line else word
            if line and face.measureText(trial) > width:
                lines.append(line)
                line = word
            else:
                line = trial
        lines.append(line)
    return lines
