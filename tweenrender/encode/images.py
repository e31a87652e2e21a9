"""Single pictures (sheets, plots) written as PNG, atomically."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from .atomic import replacing

__all__ = ["write_png", "png_bytes"]


def write_png(picture: NDArray[np.uint8], target: Path, what: str = "the picture") -> Path:
    """Write straight RGBA ``(H, W, 4)`` to ``target`` through a temporary sibling; returns ``target``.

    An opaque picture is stored as RGB, a quarter smaller. zlib's level 6: on a report's sheet (1700 × 1280)
    level 9 took six times as long (0.42 s against 0.07) for a file 5 % smaller.
    """
    import imageio.v3 as iio

    if picture.shape[-1] == 4 and np.all(picture[..., 3] == 255):
        picture = picture[..., :3]
    with replacing(target, ".png", what) as temporary:
        iio.imwrite(temporary, picture, extension=".png", compress_level=6)
    return target


def png_bytes(picture: NDArray[np.uint8], compress_level: int = 1) -> bytes:
    """Straight RGBA ``(H, W, 4)`` as PNG file bytes (RGB when opaque); level 1 compresses a flat
    picture nearly as well as 9 in a fraction of the time, which a frame served live needs."""
    import imageio.v3 as iio

    if picture.shape[-1] == 4 and np.all(picture[..., 3] == 255):
        picture = picture[..., :3]
    return bytes(iio.imwrite("<bytes>", picture, extension=".png", compress_level=compress_level))
