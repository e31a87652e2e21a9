"""Child processes that end with the process that started them, however it ends (SIGKILL included).

On Linux the child asks the kernel for SIGKILL when its parent dies
(``prctl(PR_SET_PDEATHSIG)``); elsewhere, or if that is refused, a drawing
worker watches its parent's pid from a thread. ffmpeg gets the death signal
(no thread can run in it); where there is none it still ends at the end of
its input, which closes when the parent dies.
"""

from __future__ import annotations

import ctypes
import os
import signal
import sys
import threading
from typing import Callable

__all__ = ["die_with_parent", "death_signal_setup", "watch_parent", "worker_setup", "part_worker_setup", "Stopped"]

_PR_SET_PDEATHSIG = 1
_POLL_SECONDS = 0.25


def _load_prctl() -> Callable[..., int] | None:
    if not sys.platform.startswith("linux"):
        return None
    try:
        return ctypes.CDLL(None, use_errno=True).prctl  # type: ignore[no-any-return]
    except (OSError, AttributeError):
        return None


# looked up once, in the parent: a child between fork and exec should only call it
_prctl = _load_prctl()


def _set_death_signal(number: int = int(signal.SIGKILL)) -> bool:
    """Ask for signal ``number`` (SIGKILL by default) when this process's parent ends; whether the
    system agreed."""
    if _prctl is None:
        return False
    return _prctl(_PR_SET_PDEATHSIG, int(number), 0, 0, 0) == 0


def _end_now() -> None:
    kill = getattr(signal, "SIGKILL", None)
    if kill is not None:
        os.kill(os.getpid(), kill)
    os._exit(1)


def watch_parent(parent: int) -> threading.Thread:
    """Start a daemon thread that ends this process once ``parent`` no longer runs (polled 4 times a second)."""
    own_parent = os.getppid()

    def watch() -> None:
        while True:
            if os.getppid() != own_parent:  # re-parented: whoever started this process is gone
                _end_now()
            try:
                os.kill(parent, 0)
            except ProcessLookupError:
                _end_now()
            except OSError:
                pass  # running, but not ours to signal
            threading.Event().wait(_POLL_SECONDS)

    thread = threading.Thread(target=watch, name="tweenrender-parent-watch", daemon=True)
    thread.start()
    return thread


def die_with_parent(parent: int, number: int = int(signal.SIGKILL)) -> None:
    """In a child process: end it when ``parent`` ends, by the kernel's death signal ``number`` or a
    watching thread."""
    if _set_death_signal(number) and os.getppid() == parent:
        return
    if os.getppid() != parent and not _running(parent):  # it ended before the signal was set
        _end_now()
    watch_parent(parent)


def _running(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:
        return True
    return True


def death_signal_setup() -> Callable[[], None]:
    """A ``preexec_fn`` for ``subprocess.Popen``: the program it starts gets SIGKILL when this process ends.

    Runs between fork and exec, so it only calls ``prctl`` (looked up beforehand)
    and, should this process already be gone, exits.
    """
    parent = os.getpid()

    def setup() -> None:
        _set_death_signal()
        if os.getppid() != parent:
            os._exit(1)

    return setup


def worker_setup(parent: int) -> None:
    """Initializer of a drawing process: dies with ``parent``, leaves the signals that stop a render to it,
    and lets go of its stdout (so a reader such as ``| tail`` sees the end when the parent ends).

    Ctrl-C, a hang-up or ``kill`` of the process group reach every worker; the parent handles them and
    stops its workers. (A worker forked from the command line would otherwise inherit its handlers,
    which raise ``SystemExit`` in the middle of the pool's own code.)
    """
    die_with_parent(parent)
    for name in ("SIGINT", "SIGHUP", "SIGTERM"):
        if hasattr(signal, name):
            signal.signal(getattr(signal, name), signal.SIG_IGN)
    _let_go_of_stdout()


class Stopped(SystemExit):
    """Raised in a chunk worker by SIGTERM; whoever catches it after cleaning up must end the process
    (``os._exit``): a process pool's worker would otherwise take it as a task's failure and wait on."""


def part_worker_setup(parent: int) -> None:
    """Initializer of a process rendering whole chunks: as :func:`worker_setup`, except that SIGTERM —
    from the parent stopping it, or from the kernel when the parent dies — raises :class:`Stopped`,
    so the part it was writing and its encoder are cleaned up on the way out."""
    die_with_parent(parent, int(signal.SIGTERM))
    for name in ("SIGINT", "SIGHUP"):
        if hasattr(signal, name):
            signal.signal(getattr(signal, name), signal.SIG_IGN)

    def stop(number: int, frame: object) -> None:
        raise Stopped(128 + number)

    signal.signal(signal.SIGTERM, stop)
    _let_go_of_stdout()


def _let_go_of_stdout() -> None:
    try:
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, 1)
        os.close(null)
    except OSError:
        pass
