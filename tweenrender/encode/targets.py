"""What an output may replace: a name that is a file or folder of its own, and for a folder
(PNG frames, a report) only one this tool wrote, as its manifest (:mod:`.manifest`) shows.

A folder is replaced whole, so a folder holding anything else (the user's own
``frame_0001.png``, documents, ``output/`` with its videos) is refused before anything is
drawn, and again just before the new folder is moved into place.
"""

from __future__ import annotations

import os
import re
from pathlib import Path
from typing import Callable

from ..errors import OptionError, printable
from .manifest import foreign_entry, frame_names

__all__ = ["FRAME_NAME", "check_output_name", "check_frames_folder", "check_own_folder"]

FRAME_NAME = re.compile(r"frame_\d{4,}\.png")
"""The files of a frame set (``frame_0000.png`` …): the only names a frames manifest may list."""

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
    """Refuse ``target`` as a folder of PNG frames unless it is absent, empty, or an earlier frame set
    this tool wrote there (every entry listed in its manifest, unchanged), which it then replaces."""
    check_own_folder(target, frame_names(FRAME_NAME), "a PNG target")


def check_own_folder(target: Path, ours: Callable[[str], bool], what: str) -> None:
    """Refuse ``target`` as a folder to replace unless :func:`~.manifest.foreign_entry` finds it ours;
    the one line names its first foreign or changed entry."""
    try:
        if target.is_symlink() and not target.is_dir():
            raise OptionError(f"{printable(str(target))}: is a link to no folder; {what} is a folder, "
                              "choose another name")
        if target.exists() and not target.is_dir():
            raise OptionError(f"{printable(str(target))}: is a file; {what} is a folder, choose another name")
    except OSError as error:
        raise OptionError(f"{printable(str(target))}: cannot look into the folder "
                          f"({error.strerror or error})") from None
    reason = foreign_entry(target, ours)
    if reason is not None:
        raise OptionError(f"{printable(str(target))}: {printable(reason)}; {what} replaces only a folder "
                          "tweenrender wrote: choose another folder, or remove this one yourself")
