"""``tweenrender sheet SCENE|A.svg B.svg.. [-o PNG] [--methods M,M..] [--count N] [--size WxH] [--paths]``:
a storyboard PNG."""

from __future__ import annotations

import argparse

from .args import methods, print_path, size
from .inputs import add_scene_argument, default_png, load_one
from .matching_flags import add_balance_flag, add_matching_flags, matching_options


def register(sub: argparse._SubParsersAction) -> None:
    from ..api import SHEET_COUNT

    p = sub.add_parser("sheet", help="a storyboard PNG: keys and inbetweens overlaid, one row per method")
    add_scene_argument(p)
    p.add_argument("-o", "--output", metavar="PNG", help="output file (default output/<stem>-sheet.png)")
    p.add_argument("--methods", type=methods, metavar="M,M..",
                   help="one row per method (default: the scene's compare list)")
    p.add_argument("--count", type=int, default=SHEET_COUNT, metavar="N",
                   help=f"inbetweens per row, evenly spaced in time over the clip (default {SHEET_COUNT})")
    p.add_argument("--size", type=size, metavar="WxH",
                   help="size of the whole sheet (default 1280 wide, rows as tall as the view asks; at most "
                        "4096x4096 pixels in area)")
    p.add_argument("--paths", action="store_true", help="draw every vertex's path behind the outlines")
    add_matching_flags(p)
    add_balance_flag(p)
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..api import sheet

    print_path(sheet(load_one(args), default_png(args, "sheet"), methods=args.methods, count=args.count,
                     size=args.size, paths=args.paths, **matching_options(args)))
    return 0
