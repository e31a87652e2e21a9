"""Child processes that end with the process that started them, however it ends (SIGKILL included).

On Linux the child asks the kernel for SIGKILL when its parent dies
(``prctl(PR_SET_PDEATHSIG)``); elsewhere, or if that is refused, a drawing
worker watches its parent's pid from a thread. ffmpeg gets the death signal
(no thread can run in it); where there is none it still ends at the end of
its input, which closes when the parent dies.
"""

from __future__ import annotations

import ctypes
import contextlib
import os
import signal
import subprocess
import sys
import threading
from typing import Any, Callable, Iterator

__all__ = ["die_with_parent", "death_signal_setup", "watch_parent", "worker_setup", "part_worker_setup", "Stopped", "stoppable",
           "stop_if_asked", "start_program", "run_program"]

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


def watch_parent(parent: int, grace: float = 0.0) -> threading.Thread:
    """Start a daemon thread that ends this process once ``parent`` no longer runs (polled 4 times a
    second), ``grace`` seconds after it notices (time for a death signal's own clean-up to finish)."""
    own_parent = os.getppid()

    def gone() -> bool:
        if os.getppid() != own_parent:  # re-parented: whoever started this process is gone
            return True
        try:
            os.kill(parent, 0)
        except ProcessLookupError:
            return True
        except OSError:
            pass  # running, but not ours to signal
        return False

    def watch() -> None:
        while not gone():
            threading.Event().wait(_POLL_SECONDS)
        threading.Event().wait(grace)
        _end_now()

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
        signal.pthread_sigmask(signal.SIG_UNBLOCK, _HELD)  # held by start_program while forking

    return setup


_HELD = {getattr(signal, name) for name in ("SIGINT", "SIGTERM", "SIGHUP") if hasattr(signal, name)}


def start_program(command: list[str], **options: Any) -> subprocess.Popen[Any]:
    """``subprocess.Popen(command, **options)`` for a program that dies with this process.

    The signals that stop a render are held while it forks: Python runs its fork hooks then, and a
    handler that raises there can only be reported, not obeyed. They arrive once the program has
    started (and the program itself starts with them unblocked).
    """
    held = signal.pthread_sigmask(signal.SIG_BLOCK, _HELD)
    try:
        return subprocess.Popen(command, preexec_fn=death_signal_setup(), **options)
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, held)


def run_program(command: list[str], **options: Any) -> subprocess.CompletedProcess[Any]:
    """Like ``subprocess.run(command, capture_output=True, **options)``, started by :func:`start_program`."""
    process = start_program(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, **options)
    try:
        out, err = process.communicate()
    except BaseException:
        process.kill()
        process.wait()
        raise
    return subprocess.CompletedProcess(command, process.returncode, out, err)


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
    """Raised in a chunk worker by SIGTERM inside :func:`stoppable`; whoever catches it after cleaning
    up must end the process (``os._exit``): a process pool's worker would otherwise take it as a
    task's failure and wait on."""


_stoppable = False
_pending: int | None = None  # the exit code of a stop raised where it could not pass on (in a finaliser)


@contextlib.contextmanager
def stoppable() -> Iterator[None]:
    """Where SIGTERM raises :class:`Stopped` in a chunk worker (rendering a part, whose files and encoder
    are then cleaned up); anywhere else the worker ends at once — it may be blocked sending a result
    to a parent that is gone, where an exception would only be sent on after it and block again. A stop
    that fell in a finaliser is raised at the next frame (:func:`stop_if_asked`), or here at the end."""
    global _stoppable
    _stoppable = True
    try:
        yield
        stop_if_asked()
    finally:
        _stoppable = False


def stop_if_asked() -> None:
    """Raise the :class:`Stopped` that a SIGTERM asked for where it could not be raised (in an object's
    finaliser, which cannot pass an exception on): a chunk worker calls this between frames."""
    if _pending is not None and _stoppable:
        raise Stopped(_pending)


def part_worker_setup(parent: int) -> None:
    """Initializer of a process rendering whole chunks: as :func:`worker_setup`, except that SIGTERM —
    from the parent stopping it, or from the kernel when the parent dies — raises :class:`Stopped`,
    so the part it was writing and its encoder are cleaned up on the way out."""
    die_with_parent(parent, int(signal.SIGTERM))
    # and, whatever the signal found it doing (sending a result to no one blocks for good), a watch
    # that ends it a second after the parent is gone
    watch_parent(parent, grace=1.0)
    for name in ("SIGINT", "SIGHUP"):
        if hasattr(signal, name):
            signal.signal(getattr(signal, name), signal.SIG_IGN)

    me = os.getpid()

    def stop(number: int, frame: object) -> None:
        # idle, or a child forked to start ffmpeg and caught before its exec: end at once, quietly
        if not _stoppable or os.getpid() != me:
            os._exit(128 + number)
        raise Stopped(128 + number)

    signal.signal(signal.SIGTERM, stop)
    sys.unraisablehook = _kept_stops(sys.unraisablehook)
    _let_go_of_stdout()


def _kept_stops(hook: Callable[[Any], object]) -> Callable[[Any], None]:
    """``sys.unraisablehook`` of a chunk worker: a :class:`Stopped` raised where it cannot pass on (in an
    object's finaliser, which Python would report on stderr and carry on from) is kept, quietly, to be raised
    in the worker's own code (:func:`stop_if_asked`); every other unraisable exception goes to ``hook``."""

    def handle(unraisable: Any) -> None:
        global _pending
        if isinstance(unraisable.exc_value, Stopped):
            code = unraisable.exc_value.code
            _pending = code if isinstance(code, int) else 1
            return
        hook(unraisable)

    return handle


def _let_go_of_stdout() -> None:
    try:
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, 1)
        os.close(null)
    except OSError:
        pass
