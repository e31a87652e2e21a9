"""``tweenrender report SCENE|A.svg B.svg.. [--compare M,M..] [-o DIR]``: one HTML page comparing methods."""

from __future__ import annotations

import argparse
from pathlib import Path

from .args import methods, print_path
from .inputs import add_scene_argument, load_one, stem
from .matching_flags import add_balance_flag, add_matching_flags, matching_options


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("report", help="one HTML page comparing methods: animations in sync, sheet, "
                                      "correspondence, metric charts and a table")
    add_scene_argument(p)
    p.add_argument("--compare", type=methods, metavar="M,M..",
                   help="the methods to compare (default: every method; jointed where a shape has joints)")
    p.add_argument("-o", "--output", metavar="DIR",
                   help="the report's folder (default output/<stem>-report); only an earlier report is replaced")
    add_matching_flags(p)
    add_balance_flag(p)
    p.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..api import report
    from .progress import ProgressBar

    target = Path(args.output) if args.output is not None else Path("output") / f"{stem(args.scene)}-report"

    def bar(name: str) -> ProgressBar:
        return ProgressBar(name, enabled=False if args.quiet else None)

    print_path(report(load_one(args), target, compare=args.compare, progress=bar, **matching_options(args)))
    return 0
