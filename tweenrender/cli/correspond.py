"""``tweenrender correspond SCENE|A.svg B.svg.. [--json] [-o PNG] [--cost C] [--align A]``: vertex pairs,
work, a picture."""

from __future__ import annotations

import argparse

from .args import escaped, print_json, print_path
from .inputs import add_scene_argument, default_png, load_one
from .matching_flags import add_matching_flags, matching_options


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("correspond", help="the vertex correspondence of each segment: pairs, balanced "
                                          "count, work; a picture")
    add_scene_argument(p)
    p.add_argument("--json", action="store_true", help="print the report as JSON (the picture only with -o)")
    p.add_argument("-o", "--output", metavar="PNG",
                   help="where to draw the picture (default output/<stem>-correspond.png)")
    add_matching_flags(p)
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..api import correspondence, correspondence_text

    picture = None if args.json and args.output is None else default_png(args, "correspond")
    report = correspondence(load_one(args), picture, **matching_options(args))
    if args.json:
        print_json(report)
        return 0
    print(correspondence_text(escaped(report)))
    print_path(picture)
    return 0
