"""``tweenrender correspond SCENE [--json] [-o PNG] [--cost C] [--align A]``: vertex pairs, work, a picture."""

from __future__ import annotations

import argparse

from .args import escaped, png_target, print_json, print_path
from .matching_flags import add_matching_flags, matching_of


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("correspond", help="the vertex correspondence of each segment: pairs, balanced "
                                          "count, work; a picture")
    p.add_argument("scene", metavar="SCENE")
    p.add_argument("--json", action="store_true", help="print the report as JSON (the picture only with -o)")
    p.add_argument("-o", "--output", metavar="PNG",
                   help="where to draw the picture (default output/<stem>-correspond.png)")
    add_matching_flags(p)
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..reports.match_report import correspond_dict, correspond_text, write_match_picture
    from ..scenefile import load_scene

    target = png_target(args, "correspond", "the picture")
    scene = load_scene(args.scene)
    report = correspond_dict(scene, matching_of(scene, args))
    report["scene"] = args.scene
    if args.json:
        print_json(report)
        if args.output is not None:
            write_match_picture(scene, report, target)
        return 0
    print(correspond_text(escaped(report)))
    print_path(write_match_picture(scene, report, target))
    return 0
