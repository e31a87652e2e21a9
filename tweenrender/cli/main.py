"""The ``tweenrender`` command: parses arguments, runs a command, maps errors to exit codes.

Exit codes: 0 done, 1 a failure while rendering or encoding, 2 bad input or usage.
Commands live beside this module, one module each (see :data:`COMMANDS`).
"""

from __future__ import annotations

import argparse
import contextlib
import logging
import os
import signal
import sys
from importlib import import_module
from typing import Iterator, NoReturn, Sequence

from ..api import __version__
from ..errors import OptionError, TweenrenderError, UsageError, printable

__all__ = ["COMMANDS", "main", "build_parser"]

COMMANDS = ("render", "init", "check", "stats", "correspond", "qcurves", "sheet", "reel", "report", "preview")
"""The commands, in the order ``--help`` lists them; each is the module of that name beside this one."""


class _Parser(argparse.ArgumentParser):
    """An argument parser whose refusals are one line, like every other: a :class:`UsageError`
    naming what is wrong and where to look, instead of a usage block and ``sys.exit(2)``."""

    def error(self, message: str) -> NoReturn:  # type: ignore[override]
        raise UsageError(f"{message} (see {self.prog} --help)")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="tweenrender",
        description="Inbetween 2-D keyframe polygons (linear, nonlinear Bézier, rigid, jointed paths) "
                    "and render them to PNG frames or video.")
    parser.add_argument("-v", "--verbose", action="store_true",
                        help="say what a drawing's reader skipped by SVG's error rules, and show tracebacks of failures")
    parser.add_argument("--version", action="version", version=f"tweenrender {__version__}")
    subparsers = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name in COMMANDS:
        import_module(f"{__package__}.{name}").register(subparsers)
    return parser


def entry() -> NoReturn:
    """The ``tweenrender`` command: :func:`main`, then an exit that skips the interpreter's teardown where
    numba's compiler was loaded.

    With LLVM linked into the process, tearing the interpreter down module by module took 0.25–0.3 s
    after the work was done (docs/performance.md, "What a render runs"): more than a short clip's
    frames. Python's exit handlers (``atexit``, which also runs the finalizers registered to run at
    exit) still run and both output streams are flushed; only the freeing of memory the system takes
    back anyway is skipped. Without numba loaded, or with a thread still to be waited for, the exit is
    Python's own.
    """
    code = main()
    import threading

    waits = any(not thread.daemon for thread in threading.enumerate() if thread is not threading.current_thread())
    if "llvmlite" not in sys.modules or waits:
        sys.exit(code)
    import atexit

    atexit._run_exitfuncs()
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(Exception):
            stream.flush()
    os._exit(code)


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit code (0 done, 1 failure, 2 bad input, 130 interrupted)."""
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except UsageError as error:  # raised by a type= converter
        print(f"tweenrender: error: {printable(str(error))}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return _interrupted()
    handler = _say_warnings() if args.verbose else None
    try:
        return _run(args)
    finally:
        if handler is not None:  # a library user's next call says nothing unless asked
            logging.getLogger("tweenrender").removeHandler(handler)


def _run(args: argparse.Namespace) -> int:
    """:func:`main` once the arguments are read: the command run, its failures said in one line."""
    try:
        with _terminate_cleanly():
            _sweep_temporaries()
            return args.run(args)
    except KeyboardInterrupt:
        return _interrupted()
    except BrokenPipeError:
        # the reader of stdout went away (``| head``): nothing left to say, and nowhere to say it
        _silence_stdout()
        return 1
    except (MemoryError, OSError, ImportError) as error:  # ImportError: a library that could not be mapped
        said = _exhausted(error)
        if said is None:
            return _unexpected(error, args.verbose)
        _explain(args.verbose)
        print(f"tweenrender: error: {said}", file=sys.stderr)
        return 1
    except TweenrenderError as error:
        _explain(args.verbose)
        # one line by design: a line break in it came from a name, and is shown escaped like one
        said = error.for_flag() if isinstance(error, OptionError) else str(error)
        print(f"tweenrender: error: {printable(said) or 'no message'}", file=sys.stderr)
        return error.exit_code
    except Exception as error:  # noqa: BLE001 - the last line of defence against tracebacks
        return _unexpected(error, args.verbose)


def _sweep_temporaries() -> None:
    """Every run removes what killed runs left among the temporaries (never a running one's)."""
    from ..api import sweep_temporaries

    with contextlib.suppress(OSError):
        sweep_temporaries()


def _unexpected(error: BaseException, verbose: bool) -> int:
    _explain(verbose)
    print(f"tweenrender: error: unexpected {type(error).__name__}: {printable(_one_line(str(error)))} "
          "(run with -v for details)", file=sys.stderr)
    return 1


def _exhausted(error: BaseException) -> str | None:
    """What to say when the process ran out of memory or file descriptors (None: it did not), naming the
    limit it met when one is set."""
    import errno
    import resource

    chain: list[BaseException] = []
    while error is not None and len(chain) < 10:  # a library that could not be mapped is wrapped in another
        chain.append(error)
        error = error.__cause__ or error.__context__  # type: ignore[assignment]
    if any(isinstance(e, MemoryError) or getattr(e, "errno", None) == errno.ENOMEM
           or "failed to map segment" in str(e) for e in chain):  # (dlopen's words for ENOMEM)
        limit = resource.getrlimit(resource.RLIMIT_AS)[0]
        room = f": the process may use at most {limit / (1 << 20):.0f} MiB (ulimit -v)" \
            if limit != resource.RLIM_INFINITY else ""
        return f"out of memory{room}"
    if any(getattr(e, "errno", None) in (errno.EMFILE, errno.ENFILE) for e in chain):
        limit = resource.getrlimit(resource.RLIMIT_NOFILE)[0]
        room = f": at most {limit} open files at once (ulimit -n)" if limit != resource.RLIM_INFINITY else ""
        return f"out of file descriptors{room}"
    return None


@contextlib.contextmanager
def _terminate_cleanly() -> Iterator[None]:
    """Turn SIGTERM (``kill``, ``timeout``, a container stopping) into ``SystemExit(143)`` and SIGHUP
    (the terminal closed) into ``SystemExit(129)``.

    Python's default for either ends the process on the spot; as an exception it
    unwinds through the sinks, which remove their temporaries.
    """
    me = os.getpid()

    def stop(signum: int, frame: object) -> None:
        if os.getpid() != me:  # a child forked to start a program (ffmpeg), caught before its exec
            os._exit(128 + signum)
        raise SystemExit(128 + signum)

    handled = [getattr(signal, name) for name in ("SIGTERM", "SIGHUP") if hasattr(signal, name)]
    try:
        previous = {signum: signal.signal(signum, stop) for signum in handled}
    except ValueError:  # not the main thread: leave signals alone
        yield
        return
    try:
        yield
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, handler)


def _interrupted() -> int:
    # outputs go through temporaries, and the sinks remove theirs on the way out
    print("tweenrender: interrupted; no output was changed", file=sys.stderr)
    return 130


def _say_warnings() -> logging.Handler:
    """With ``-v``, the library's warnings (what a drawing's reader skipped …) on stderr, a line each: the
    handler that says them."""
    handler = logging.StreamHandler(sys.stderr)
    handler.setFormatter(logging.Formatter("tweenrender: warning: %(message)s"))
    logger = logging.getLogger("tweenrender")
    logger.addHandler(handler)
    logger.setLevel(logging.WARNING)
    return handler


def _explain(verbose: bool) -> None:
    """With ``-v``, the traceback of the error being handled, before its one-line message."""
    if verbose:
        import traceback

        traceback.print_exc(file=sys.stderr)


def _one_line(text: str) -> str:
    return " | ".join(line.strip() for line in text.splitlines() if line.strip()) or "no message"


def _silence_stdout() -> None:
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):
        pass
