"""Every run's temporary folders in one place, each removed by its run or, if that run was killed, by the
next run of any command.

The place is ``<temporary folder>/tweenrender-<uid>/`` (``$TMPDIR``, else ``/tmp``; one per user, private
to them). A folder in it is named ``<pid>-<start>-<what>-<random>``: the process that owns it (the render,
or for a worker's part the render that started the worker) and that process's start time, so that a
later process given the same pid is not taken for the owner. A folder whose owner no longer runs is
left-over scratch: :func:`sweep_scratch` removes it. The hidden temporaries beside a target (the output
being written, ``encode.atomic``) stay beside it, where the final move is atomic.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import stat
import tempfile
import uuid
from pathlib import Path
from typing import Iterator

from ..errors import EncodeError

__all__ = ["scratch_root", "scratch_folder", "sweep_scratch", "start_time", "owner_runs"]


def scratch_root() -> Path:
    """``<temporary folder>/tweenrender-<uid>``: where every run's temporary folders go."""
    return Path(tempfile.gettempdir()) / f"tweenrender-{os.getuid() if hasattr(os, 'getuid') else 0}"


def start_time(pid: int) -> int | None:
    """When process ``pid`` started (clock ticks after boot, from ``/proc``): with the pid, names one process
    for good. None if it does not run; 0 where ``/proc`` is not there to ask."""
    try:
        text = Path(f"/proc/{pid}/stat").read_text()
    except FileNotFoundError:
        return None if Path("/proc/self/stat").exists() else _started_elsewhere(pid)
    except OSError:
        return None
    fields = text[text.rindex(")") + 2:].split()  # after the command name, which may hold spaces
    return None if fields[0] == "Z" else int(fields[19])  # field 22 of proc(5); a zombie has ended


def _started_elsewhere(pid: int) -> int | None:
    from .atomic import alive

    return 0 if alive(pid) else None


def owner_runs(pid: int, started: int) -> bool:
    """Whether the process ``pid`` that started at ``started`` still runs (0: any process of that pid)."""
    now = start_time(pid)
    return now is not None and (started == 0 or now == 0 or now == started)


def _private_root() -> Path:
    """The root, made if needed; refused when it is not a folder of this user's alone (someone else's, or a
    link to elsewhere)."""
    root = scratch_root()
    with contextlib.suppress(FileExistsError):
        root.mkdir(mode=0o700)
    found = os.lstat(root)
    if not stat.S_ISDIR(found.st_mode) or (hasattr(os, "getuid") and found.st_uid != os.getuid()):
        raise EncodeError(f"{root}: cannot keep temporary files there (not a folder of this user's own); "
                          "remove it, or set TMPDIR to another folder")
    return root


@contextlib.contextmanager
def scratch_folder(what: str, owner: int | None = None) -> Iterator[Path]:
    """A fresh folder for ``what`` under :func:`scratch_root`, removed afterwards; ``owner`` (default this
    process) is the process whose end makes it removable by any later run."""
    pid = os.getpid() if owner is None else owner
    started = start_time(pid)
    try:
        folder = _private_root() / f"{pid}-{started or 0}-{what}-{uuid.uuid4().hex[:8]}"
        folder.mkdir(mode=0o700)
    except OSError as error:
        raise EncodeError(f"{scratch_root()}: cannot create a temporary folder ({error.strerror or error})") from None
    try:
        yield folder
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def sweep_scratch(own: bool = False) -> list[Path]:
    """Remove the folders under :func:`scratch_root` whose owner no longer runs; with ``own``, this
    process's too (once every worker of this run has stopped). Returns what was removed."""
    removed: list[Path] = []
    root = scratch_root()
    try:
        found = os.lstat(root)
        if not stat.S_ISDIR(found.st_mode) or (hasattr(os, "getuid") and found.st_uid != os.getuid()):
            return removed  # not this user's own folder (a link, someone else's): nothing in it is ours
        entries = list(root.iterdir())
    except OSError:
        return removed
    for entry in entries:
        pid, _, rest = entry.name.partition("-")
        started = rest.partition("-")[0]
        if not (pid.isdigit() and started.isdigit()):
            continue  # not one of ours
        runs = owner_runs(int(pid), int(started))
        if not runs or (own and int(pid) == os.getpid()):
            shutil.rmtree(entry, ignore_errors=True)
            removed.append(entry)
    return removed
