"""The ``tweenrender`` command: parses arguments, runs a command, maps errors to exit codes.

Exit codes: 0 done, 1 a failure while rendering or encoding, 2 bad input or usage.
Commands live in :mod:`tweenrender.commands`, one module each.
"""

from __future__ import annotations

import argparse
import sys
from typing import Sequence

from .commands import register_all
from .errors import TweenrenderError, UsageError

__all__ = ["main", "build_parser"]


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="tweenrender",
        description="Inbetween 2-D keyframe polygons (linear, nonlinear Bézier, rigid, jointed paths) "
                    "and render them to PNG frames or video.")
    parser.add_argument("-v", "--verbose", action="store_true", help="show tracebacks of failures")
    register_all(parser.add_subparsers(dest="command", required=True, metavar="COMMAND"))
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except UsageError as error:  # raised by a type= converter
        print(f"tweenrender: error: {error}", file=sys.stderr)
        return 2
    try:
        return args.run(args)
    except TweenrenderError as error:
        if args.verbose:
            raise
        print(f"tweenrender: error: {error}", file=sys.stderr)
        return error.exit_code
    except KeyboardInterrupt:
        print("tweenrender: interrupted; no output was changed", file=sys.stderr)
        return 130
    except Exception as error:  # noqa: BLE001 - the last line of defence against tracebacks
        if args.verbose:
            raise
        print(f"tweenrender: error: unexpected {type(error).__name__}: {error} (run with -v for details)",
              file=sys.stderr)
        return 1
