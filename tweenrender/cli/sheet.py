"""``tweenrender sheet SCENE [-o PNG] [--methods M,M..] [--count N] [--size WxH] [--paths]``: a storyboard PNG."""

from __future__ import annotations

import argparse

from .args import count, methods, png_target, print_path, size
from .matching_flags import add_balance_flag, add_matching_flags, with_matching

DEFAULT_COUNT = 7


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("sheet", help="a storyboard PNG: keys and inbetweens overlaid, one row per method")
    p.add_argument("scene", metavar="SCENE")
    p.add_argument("-o", "--output", metavar="PNG", help="output file (default output/<stem>-sheet.png)")
    p.add_argument("--methods", type=methods, metavar="M,M..",
                   help="one row per method (default: the scene's compare list)")
    p.add_argument("--count", type=count(0, 200, "--count"), default=DEFAULT_COUNT, metavar="N",
                   help=f"inbetweens per row, evenly spaced in time over the clip (default {DEFAULT_COUNT})")
    p.add_argument("--size", type=size, metavar="WxH",
                   help="size of the whole sheet (default 1280 wide, rows as tall as the view asks)")
    p.add_argument("--paths", action="store_true", help="draw every vertex's path behind the outlines")
    add_matching_flags(p)
    add_balance_flag(p)
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..pipeline.job import scene_view, tracks_of
    from ..scenefile import load_scene
    from ..pipeline.pictures import write_sheet

    scene = with_matching(load_scene(args.scene), args)
    rows = args.methods or scene.compare
    target = png_target(args, "sheet", "a sheet")
    tracks = tracks_of(scene)
    view = scene_view(scene, tracks, rows)
    print_path(write_sheet(scene, tracks, rows, view, target, args.count, args.size, args.paths))
    return 0
