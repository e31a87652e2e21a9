"""What an output may replace: a name that is a file or folder of its own, and for PNG frames
only a folder that holds nothing but an earlier frame set.

A folder of frames is replaced whole, so a folder holding anything else (the user's
documents, ``output/`` with its videos) is refused before anything is drawn, and
again just before the new frames are moved into place.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

from ..errors import OptionError, printable

__all__ = ["FRAME_NAME", "check_output_name", "check_frames_folder"]

FRAME_NAME = re.compile(r"frame_\d{4,}\.png")
"""The files of a frame set (``frame_0000.png`` …): all a replaced PNG folder may hold."""

_NOT_A_NAME = "expected a file name (.mp4, .webm, .gif) or a folder's name for PNG frames"


def check_output_name(path: str | os.PathLike[str]) -> Path:
    """``path`` as a :class:`Path`, refused when it names no file or folder of its own:
    empty, the current folder, a parent folder (``..``), or the root."""
    text = os.fspath(path)
    target = Path(text)
    what = None
    if text == "":
        what = "empty"
    elif target.name == "..":
        what = "a parent folder"
    elif target.name == "" and target.anchor:
        what = "the root folder"
    elif target.name == "":
        what = "the current folder"
    if what is not None:
        raise OptionError(f"output {printable(repr(text))} is {what}; {_NOT_A_NAME}")
    return target


def check_frames_folder(target: Path) -> None:
    """Refuse ``target`` as a folder of PNG frames unless it is absent, empty, or holds only
    ``frame_NNNN.png`` files (an earlier frame set, which it then replaces)."""
    try:
        if not target.exists():
            return
        if not target.is_dir():
            raise OptionError(f"{printable(str(target))}: is a file; a PNG target is a folder of frames, "
                              "choose another name")
        others = sorted(entry.name for entry in target.iterdir()
                        if not (FRAME_NAME.fullmatch(entry.name) and entry.is_file() and not entry.is_symlink()))
    except OSError as error:
        raise OptionError(f"{printable(str(target))}: cannot look into the folder "
                          f"({error.strerror or error})") from None
    if others:
        shown = ", ".join(printable(name) for name in others[:3]) + (", …" if len(others) > 3 else "")
        raise OptionError(f"{printable(str(target))}: holds {len(others)} other "
                          f"{'entry' if len(others) == 1 else 'entries'} than frame_NNNN.png ({shown}); "
                          "a PNG target replaces only a folder of earlier frames: choose a new folder")
