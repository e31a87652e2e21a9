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
from typing import Callable, Iterable

from ..errors import OptionError, printable
from .formats import frame_folders, listing, suffixes
from .manifest import foreign_entry, frame_names

__all__ = ["FRAME_NAME", "check_output_name", "check_name_fits", "check_frames_folder", "check_own_folder",
           "check_not_an_input"]

FRAME_NAME = re.compile(r"frame_\d{4,}\.png")
"""The files of a frame set (``frame_0000.png`` …): the only names a frames manifest may list."""

_NOT_A_NAME = f"expected a file name ({', '.join(suffixes())}) or a folder's name for {listing(frame_folders(), 'or')}"


_TEMPORARY_EXTRA = 32
"""Bytes a temporary's name adds to its target's (``.NAME.PID-XXXXXXXX.part.webm``, see ``atomic.sibling``)."""


def _shown(name: str) -> str:
    return printable(name if len(name) <= 40 else name[:20] + "…" + name[-12:])


def check_name_fits(target: Path) -> None:
    """Refuse ``target`` when its name, or the temporary written beside it, is longer than the file
    system takes (255 bytes a name, 4096 a path, on Linux): before any work, not after it."""
    name = os.fsencode(target.name)
    probe = target.parent
    while not probe.exists() and probe != probe.parent:
        probe = probe.parent
    try:
        most, longest_path = os.pathconf(probe, "PC_NAME_MAX"), os.pathconf(probe, "PC_PATH_MAX")
    except (OSError, ValueError):
        most, longest_path = 255, 4096
    allowed = most - _TEMPORARY_EXTRA
    if len(name) > allowed:
        raise OptionError(f"output {_shown(target.name)}: name too long ({len(name)} bytes; this file system takes "
                          f"{most}, and {allowed} leave room for the temporary written beside it)")
    whole = len(os.fsencode(os.path.abspath(target))) + _TEMPORARY_EXTRA
    if whole > longest_path:
        raise OptionError(f"output {_shown(target.name)}: path too long ({whole} bytes with its temporary; "
                          f"this file system takes {longest_path})")


def check_output_name(path: str | os.PathLike[str], expected: str = _NOT_A_NAME) -> Path:
    """``path`` as a :class:`Path`, refused when it names no file or folder of its own (empty, the current
    folder, a parent folder ``..``, or the root) or one too long for the file system; ``expected`` says
    what was expected instead."""
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
        raise OptionError(f"output {printable(repr(text))} is {what}; {expected}")
    check_name_fits(target)
    return target


def check_frames_folder(target: Path) -> None:
    """Refuse ``target`` as a folder of PNG frames unless it is absent, empty, or an earlier frame set
    this tool wrote there (every entry listed in its manifest, unchanged), which it then replaces."""
    check_own_folder(target, frame_names(FRAME_NAME), "a PNG target")


def check_own_folder(target: Path, ours: Callable[[str], bool], what: str) -> None:
    """Refuse ``target`` as a folder to replace unless :func:`~.manifest.foreign_entry` finds it ours;
    the one line names its first foreign or changed entry."""
    check_name_fits(target)
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


def _same_file(a: str | Path, b: str | Path) -> bool:
    try:
        return os.path.samefile(a, b)
    except (OSError, ValueError):  # either is missing (or unnamable): not one file
        return False


def check_not_an_input(target: Path, sources: Iterable[str | os.PathLike[str]], folder: bool = False,
                       files: Iterable[str] = (), scene_files: Iterable[str | os.PathLike[str]] = ()) -> None:
    """Refuse to write ``target`` over a file the command reads (``sources``: the scene, its SVG keys and
    drawings), compared through symbolic and hard links. A ``folder`` target is replaced whole, so a source
    inside it clashes too, as does a source that any of ``files`` (the names put in it) already is.
    The one line names both (once when they are one name; ``scene_files`` are called the scene file)."""
    real_target = os.path.realpath(target)
    inside = real_target.rstrip(os.sep) + os.sep
    scenes = {str(p) for p in scene_files}
    for source in sources:
        real = os.path.realpath(source)
        shown = f"{printable(str(target))}: is {printable(str(source))}"
        if real == real_target or _same_file(target, source):
            if str(source) in scenes:
                itself = "" if str(source) == str(target) else f" ({printable(str(source))})"
                raise OptionError(f"{printable(str(target))}: is the scene file itself{itself}; choose another output")
            raise OptionError(f"{shown}, which this command reads; choose another output")
        if not folder:
            continue
        if real.startswith(inside):
            raise OptionError(f"{printable(str(target))}: holds {printable(str(source))}, which this command reads, "
                              "and would be replaced whole; choose another output")
        for name in files:
            if _same_file(target / name, source):
                raise OptionError(f"{printable(str(target / name))}: is {printable(str(source))}, which this "
                                  "command reads; choose another output")
