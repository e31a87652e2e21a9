"""Write beside the target, move into place only when complete: a crash never leaves half a file.

A temporary is a hidden sibling of its target named ``.NAME.PID-RANDOM.part[.EXT]``:
in the same folder, so the final ``os.replace`` is atomic, and tagged with the
writing process, so a later run can remove the temporaries of a process that
was killed (:func:`sweep`) without touching those of one still running.
"""

from __future__ import annotations

import contextlib
import os
import re
import shutil
import uuid
from pathlib import Path
from typing import Iterator

from ..errors import EncodeError, OptionError

__all__ = ["create_new", "sibling", "prepare_folder", "commit_file", "commit_folder", "discard", "sweep", "replacing",
           "os_reason", "alive"]


def os_reason(error: OSError) -> str:
    """The system's words for ``error`` ("No space left on device"), without the path."""
    return error.strerror or str(error) or type(error).__name__


def sibling(target: Path, suffix: str = "") -> Path:
    """A fresh hidden path in ``target``'s folder (same file system, so the final move is atomic)."""
    return target.with_name(f".{target.name}.{os.getpid()}-{uuid.uuid4().hex[:8]}.part{suffix}")


def alive(pid: int) -> bool:
    """Whether process ``pid`` runs (one not ours to signal counts as running)."""
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OSError):
        return True  # someone else's process: leave its files alone
    return True


def sweep(target: Path) -> list[Path]:
    """Remove temporaries of ``target`` left by processes that no longer run; returns what was removed."""
    pattern = re.compile(rf"\.{re.escape(target.name)}\.(\d+)-[0-9a-f]{{8}}\.part(\.[A-Za-z0-9.]+)?")
    removed = []
    try:
        entries = list(target.parent.iterdir())
    except OSError:
        return removed
    for entry in entries:
        match = pattern.fullmatch(entry.name)
        if not match or alive(int(match.group(1))):
            continue
        if match.group(2) == ".old" and not target.exists():
            # killed between commit_folder's two renames: this is the earlier output, put it back
            try:
                os.replace(entry, target)
                continue
            except OSError:
                pass
        discard(entry)
        removed.append(entry)
    return removed


def prepare_folder(target: Path) -> None:
    """Create ``target``'s parent folder, reporting an unwritable place clearly; sweep stale temporaries.
    A name too long for the file system, its temporary's included, is refused first (an ``OptionError``)."""
    from .targets import check_name_fits

    check_name_fits(target)
    parent = target.parent
    try:
        parent.mkdir(parents=True, exist_ok=True)
    except FileExistsError:
        raise EncodeError(f"{parent}: cannot create the output folder (a file of that name is in the way)") from None
    except NotADirectoryError:
        raise EncodeError(f"{parent}: cannot create the output folder (part of the path is a file)") from None
    except OSError as error:
        raise EncodeError(f"{parent}: cannot create the output folder ({os_reason(error)})") from None
    if not os.access(parent, os.W_OK):
        raise EncodeError(f"{parent}: the output folder is not writable")
    if target.exists() and target.is_dir() != (target.suffix == ""):
        kind = "a folder" if target.is_dir() else "a file"
        raise EncodeError(f"{target}: is {kind}; refusing to replace it with another kind of output")
    sweep(target)


def _fsync(path: Path, directory: bool = False) -> None:
    """Flush ``path`` to disk so a power cut after the rename cannot leave an empty file."""
    try:
        descriptor = os.open(path, os.O_RDONLY | (getattr(os, "O_DIRECTORY", 0) if directory else 0))
    except OSError:
        return
    try:
        os.fsync(descriptor)
    except OSError:
        pass  # some file systems cannot fsync a folder; the rename is still atomic
    finally:
        os.close(descriptor)


def commit_file(temporary: Path, target: Path) -> None:
    """Atomically replace ``target`` with the finished ``temporary`` file."""
    try:
        _fsync(temporary)
        os.replace(temporary, target)
    except OSError as error:
        discard(temporary)
        raise EncodeError(f"{target}: cannot move the finished output into place ({os_reason(error)})") from None
    _fsync(target.parent, directory=True)


def commit_folder(temporary: Path, target: Path) -> None:
    """Replace folder ``target`` with the finished folder ``temporary``.

    Two renames: the old folder steps aside, the new one takes its name, and
    only then is the old one removed; if the second rename fails the old folder
    is put back.
    """
    old = sibling(target, ".old") if target.exists() else None
    try:
        if old is not None:
            os.replace(target, old)
        try:
            os.replace(temporary, target)
        except OSError:
            if old is not None:
                os.replace(old, target)
            raise
    except OSError as error:
        discard(temporary)
        raise EncodeError(f"{target}: cannot move the finished frames into place ({os_reason(error)})") from None
    _fsync(target.parent, directory=True)
    if old is not None:
        discard(old)  # a folder, or the link that was the target (what it points to is kept)


def discard(temporary: Path) -> None:
    """Remove a temporary file or folder, quietly."""
    try:
        if temporary.is_dir() and not temporary.is_symlink():
            shutil.rmtree(temporary, ignore_errors=True)
        else:
            temporary.unlink(missing_ok=True)
    except OSError:
        pass  # a temporary that cannot be removed is left for sweep(); never mask the real error


@contextlib.contextmanager
def replacing(target: Path, suffix: str = "", what: str = "the output") -> Iterator[Path]:
    """Yield a temporary path to write ``target``'s new content to; it replaces ``target`` on success.

    On any exception the temporary is removed and ``target`` is left as it was;
    an ``OSError`` while writing becomes an :class:`EncodeError` naming ``target``.
    """
    prepare_folder(target)
    temporary = sibling(target, suffix)
    try:
        yield temporary
    except OSError as error:
        discard(temporary)
        raise EncodeError(f"{target}: cannot write {what} ({os_reason(error)})") from None
    except BaseException:
        discard(temporary)
        raise
    commit_file(temporary, target)


def create_new(target: Path, text: str, what: str = "the file") -> None:
    """Write ``text`` to a new file ``target``, atomically; never replace one: an existing ``target`` (or one
    made meanwhile) is an :class:`OptionError` and stays as it was."""
    if target.exists() or target.is_symlink():
        raise OptionError(f"{target}: already exists; it is never replaced (give another name)")
    if not target.parent.is_dir():
        raise OptionError(f"{target}: cannot write {what} (no such folder {target.parent})")
    temporary = sibling(target)
    try:
        temporary.write_text(text, encoding="utf-8")
        _fsync(temporary)
        os.link(temporary, target)  # fails, rather than replaces, should the name be taken since the check
    except FileExistsError:
        raise OptionError(f"{target}: already exists; it is never replaced (give another name)") from None
    except OSError as error:
        raise OptionError(f"{target}: cannot write {what} ({os_reason(error)})") from None
    finally:
        discard(temporary)
    _fsync(target.parent, directory=True)
