"""Watches the files a scene was read from and calls back when one of them changes on disk.

``watchfiles`` (inotify on Linux) watches the folders that hold the files, not the files
themselves: an editor that saves by writing a new file and renaming it over the old one
replaces the file's inode, which a watch on the file would lose. A folder removed and made again
(a branch checkout) is a new inode that the old watch does not see: every answer of the watch checks
that each folder is still the one watched, and watches afresh when one is not.
"""

from __future__ import annotations

import os
import threading
from pathlib import Path
from typing import Callable, Iterable

__all__ = ["FileWatcher"]

_QUIET_MS = 20  # a burst of events (truncate, write, rename) ends after this much quiet
_RETRY_SECONDS = 0.5  # a folder that cannot be watched (removed, renamed) is tried again after this
_ARMED_CHECK_MS = 200  # an armed watch answers (with nothing) after this much quiet


class FileWatcher:
    """Calls ``on_change`` (from its own thread) when any file given to :meth:`watch` changes."""

    def __init__(self, on_change: Callable[[], None]) -> None:
        self._on_change = on_change
        self._files: frozenset[str] = frozenset()
        self._baseline: dict[str, tuple[int, int, int] | None] = {}
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._restart = threading.Event()  # set to end the current watch: new files, or stopping
        self._thread = threading.Thread(target=self._run, name="tweenrender-watch", daemon=True)

    def start(self) -> None:
        self._thread.start()

    def watch(self, files: Iterable[Path]) -> None:
        """Watch ``files`` (they need not exist yet, but their folders should)."""
        names = set()
        for file in files:
            names.add(os.path.abspath(file))
            names.add(os.path.realpath(file))  # a symbolic link's target changes too
        with self._lock:
            if frozenset(names) == self._files:
                return
            self._files = frozenset(names)
            self._baseline = _signatures(self._files)  # a save from now on is seen, even before the watch is armed
        self._restart.set()

    def stop(self, timeout: float = 2.0) -> None:
        self._stop.set()
        self._restart.set()
        if self._thread.is_alive():
            self._thread.join(timeout)

    def _run(self) -> None:
        import watchfiles

        while not self._stop.is_set():
            with self._lock:
                files, baseline = self._files, self._baseline
            self._restart.clear()
            every_folder = sorted({os.path.dirname(f) for f in files})
            folders = [folder for folder in every_folder if os.path.isdir(folder)]
            if not folders:
                self._restart.wait(_RETRY_SECONDS)
                continue
            # a save made before the watch is armed has no event: once armed (its first answer, an event
            # or a timeout), the files are compared with what they were when they were given to watch
            seen: dict[str, tuple[int, int, int] | None] | None = baseline
            identities = _identities(every_folder)
            try:
                for changes in watchfiles.watch(*folders, watch_filter=lambda _change, path: path in files,
                                                recursive=False, step=_QUIET_MS, debounce=400,
                                                rust_timeout=_ARMED_CHECK_MS, yield_on_timeout=True,
                                                stop_event=self._restart, raise_interrupt=False):
                    if _identities(every_folder) != identities:  # a folder went or came back: watch afresh
                        break
                    missed = seen is not None and _signatures(files) != seen
                    seen = None
                    if (changes or missed) and not self._stop.is_set():
                        with self._lock:
                            if files == self._files:
                                self._baseline = _signatures(files)
                        self._on_change()
            except (OSError, RuntimeError):  # a folder went away while watched: try again shortly
                self._restart.wait(_RETRY_SECONDS)


def _identities(folders: Iterable[str]) -> list[tuple[int, int] | None]:
    """Each folder's (device, inode), or None where it is missing."""
    out: list[tuple[int, int] | None] = []
    for folder in folders:
        try:
            found = os.stat(folder)
            out.append((found.st_dev, found.st_ino))
        except OSError:
            out.append(None)
    return out


def _signatures(files: Iterable[str]) -> dict[str, tuple[int, int, int] | None]:
    """Each file's (inode, size, modification time in ns), or None where it is missing."""
    out: dict[str, tuple[int, int, int] | None] = {}
    for name in files:
        try:
            found = os.stat(name)
            out[name] = (found.st_ino, found.st_size, found.st_mtime_ns)
        except OSError:
            out[name] = None
    return out
