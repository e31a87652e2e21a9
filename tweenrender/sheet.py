"""Storyboard sheets: draw with :mod:`tweenrender.render.sheet`, write the PNG atomically."""

from __future__ import annotations

from pathlib import Path
from typing import Sequence

import numpy as np

from .core.timeline import Track
from .errors import EncodeError
from .model import Scene
from .render.view import Box

__all__ = ["write_sheet"]


def write_sheet(scene: Scene, tracks: Sequence[Track], methods: Sequence[str], view: Box, target: Path,
                count: int = 7, size: tuple[int, int] | None = None, paths: bool = False) -> Path:
    """Draw the sheet and write it to ``target`` (a temporary sibling, then ``os.replace``)."""
    import imageio.v3 as iio

    from .encode.atomic import commit_file, discard, prepare_folder, sibling
    from .render.sheet import draw_sheet, sheet_layout

    picture = draw_sheet(scene, tracks, methods, view, sheet_layout(view, len(methods), size), count, paths)
    prepare_folder(target)
    temporary = sibling(target, ".png")
    try:
        if np.all(picture[..., 3] == 255):  # opaque: RGB is a quarter smaller
            picture = picture[..., :3]
        iio.imwrite(temporary, picture, extension=".png", compress_level=9)
        commit_file(temporary, target)
    except OSError as error:
        discard(temporary)
        raise EncodeError(f"{target}: cannot write the sheet ({error.strerror or error})") from None
    except BaseException:
        discard(temporary)
        raise
    return target
