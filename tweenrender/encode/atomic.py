"""Write beside the target, move into place only when complete: a crash never leaves half a file."""

from __future__ import annotations

import os
import shutil
import uuid
from pathlib import Path

from ..errors import EncodeError

__all__ = ["sibling", "prepare_folder", "commit_file", "commit_folder", "discard"]


def sibling(target: Path, suffix: str = "") -> Path:
    """A fresh hidden path in ``target``'s folder (same file system, so the final move is atomic)."""
    return target.with_name(f".{target.name}.{uuid.uuid4().hex[:8]}.part{suffix}")


def prepare_folder(target: Path) -> None:
    """Create ``target``'s parent folder, reporting an unwritable place clearly."""
    parent = target.parent
    try:
        parent.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise EncodeError(f"{parent}: cannot create the output folder ({error.strerror or error})") from None
    if not os.access(parent, os.W_OK):
        raise EncodeError(f"{parent}: the output folder is not writable")
    if target.exists() and target.is_dir() != (target.suffix == ""):
        kind = "a folder" if target.is_dir() else "a file"
        raise EncodeError(f"{target}: is {kind}; refusing to replace it with another kind of output")


def commit_file(temporary: Path, target: Path) -> None:
    """Atomically replace ``target`` with the finished ``temporary`` file."""
    os.replace(temporary, target)


def commit_folder(temporary: Path, target: Path) -> None:
    """Replace folder ``target`` with the finished folder ``temporary``.

    Two renames: the old folder steps aside, the new one takes its name, and
    only then is the old one removed; if the second rename fails the old folder
    is put back.
    """
    old = sibling(target, ".old") if target.exists() else None
    if old is not None:
        os.replace(target, old)
    try:
        os.replace(temporary, target)
    except OSError:
        if old is not None:
            os.replace(old, target)
        raise
    if old is not None:
        shutil.rmtree(old, ignore_errors=True)


def discard(temporary: Path) -> None:
    """Remove a temporary file or folder, quietly."""
    if temporary.is_dir():
        shutil.rmtree(temporary, ignore_errors=True)
    else:
        temporary.unlink(missing_ok=True)
