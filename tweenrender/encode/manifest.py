"""The list of files tweenrender wrote into an output folder, and what it allows that folder to be replaced.

Every folder the tool writes (PNG frames, a report) carries :data:`MANIFEST`: each file's
name, size and modification time. A folder is the tool's to replace only when each of its
entries is listed there and unchanged; a note the user saved inside, a frame edited
since, a subfolder or a link makes it the user's folder.
"""

from __future__ import annotations

import json
import os
import re
import stat
from pathlib import Path
from typing import Callable

from ..errors import EncodeError

__all__ = ["MANIFEST", "write_manifest", "foreign_entry"]

MANIFEST = ".tweenrender-manifest.json"
"""The manifest's name inside the folder it describes."""

_MAX_BYTES = 64 << 20  # a manifest of a million frames is about 60 MiB; anything larger is not ours
_STAMP = "tweenrender"


def write_manifest(folder: Path) -> None:
    """List every file of ``folder`` (sizes, modification times) in its manifest; the folder holds
    only regular files the caller has just written."""
    files: dict[str, dict[str, int]] = {}
    try:
        with os.scandir(folder) as entries:
            for entry in entries:
                if entry.name == MANIFEST:
                    continue
                info = entry.stat(follow_symlinks=False)
                files[entry.name] = {"bytes": info.st_size, "mtime_ns": info.st_mtime_ns}
        text = json.dumps({"written_by": _STAMP, "files": dict(sorted(files.items()))}, indent=0)
        (folder / MANIFEST).write_text(text, encoding="utf-8")
    except OSError as error:
        raise EncodeError(f"{folder}: cannot write the list of its files ({error.strerror or error})") from None


def _listing(folder: Path) -> dict[str, dict[str, int]] | str:
    """The manifest's entries, or why there is no manifest to trust."""
    path = folder / MANIFEST
    try:
        info = path.lstat()
    except FileNotFoundError:
        return f"has no {MANIFEST}"
    if not stat.S_ISREG(info.st_mode):
        return f"its {MANIFEST} is not a file"
    if info.st_size > _MAX_BYTES:
        return f"its {MANIFEST} is larger than tweenrender writes"
    descriptor = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOFOLLOW", 0))
    with os.fdopen(descriptor, "rb") as handle:
        raw = handle.read(_MAX_BYTES + 1)
    try:
        data = json.loads(raw.decode("utf-8"))
        files = data["files"]
        if data.get("written_by") != _STAMP or not isinstance(files, dict):
            raise ValueError
        for entry in files.values():
            if not (isinstance(entry, dict) and isinstance(entry.get("bytes"), int)
                    and isinstance(entry.get("mtime_ns"), int)):
                raise ValueError
    except (ValueError, KeyError, TypeError, AttributeError, RecursionError):
        return f"its {MANIFEST} is not one tweenrender wrote"
    return files


def foreign_entry(folder: Path, ours: Callable[[str], bool]) -> str | None:
    """Why ``folder`` is not the tool's to replace, naming its first foreign or changed entry; ``None``
    when it is: absent, empty, or holding only files its manifest lists, unchanged. ``ours(name)``
    says whether the tool writes a file of that name into such a folder."""
    try:
        names = sorted(os.listdir(folder))
    except FileNotFoundError:
        return None
    except OSError as error:
        return f"cannot be looked into ({error.strerror or error})"
    names = [name for name in names if name != MANIFEST]
    if not names and not os.path.lexists(folder / MANIFEST):
        return None
    try:
        listing = _listing(folder)
    except OSError as error:
        return f"its {MANIFEST} cannot be read ({error.strerror or error})"
    if isinstance(listing, str):
        if names:
            return f"holds {names[0]!r} but {listing.removeprefix('has ')} (not written by tweenrender, or by an older version)"
        return listing
    for name in names:
        entry = listing.get(name)
        if entry is None or not ours(name):
            return f"holds {name!r}, which tweenrender did not write"
        try:
            info = os.lstat(folder / name)
        except OSError:
            continue  # removed meanwhile: nothing of the user's is lost
        if not stat.S_ISREG(info.st_mode):
            return f"holds {name!r}, which tweenrender did not write (not a plain file)"
        if (info.st_size, info.st_mtime_ns) != (entry["bytes"], entry["mtime_ns"]):
            return f"holds {name!r}, changed since tweenrender wrote it"
    return None


def frame_names(pattern: re.Pattern[str]) -> Callable[[str], bool]:
    """``ours`` for :func:`foreign_entry`: names ``pattern`` matches whole."""
    return lambda name: pattern.fullmatch(name) is not None
