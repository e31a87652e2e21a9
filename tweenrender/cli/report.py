"""``tweenrender report SCENE [--compare M,M..] [-o DIR]``: one HTML page comparing methods."""

from __future__ import annotations

import argparse
from pathlib import Path

from .args import methods, print_path
from .matching_flags import add_balance_flag, add_matching_flags, with_matching


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("report", help="one HTML page comparing methods: animations in sync, sheet, "
                                      "correspondence, metric charts and a table")
    p.add_argument("scene", metavar="SCENE")
    p.add_argument("--compare", type=methods, metavar="M,M..",
                   help="the methods to compare (default: every method; jointed where a shape has joints)")
    p.add_argument("-o", "--output", metavar="DIR",
                   help="the report's folder (default output/<stem>-report); only an earlier report is replaced")
    add_matching_flags(p)
    add_balance_flag(p)
    p.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..reports.html_report import write_report
    from ..scenefile import load_scene
    from .progress import ProgressBar

    target = Path(args.output) if args.output is not None else Path("output") / f"{Path(args.scene).stem}-report"
    scene = with_matching(load_scene(args.scene), args)

    def bar(name: str) -> ProgressBar:
        return ProgressBar(name, enabled=False if args.quiet else None)

    print_path(write_report(scene, target, args.compare, bar))
    return 0
