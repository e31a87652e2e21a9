"""``tweenrender qcurves SCENE|A.svg B.svg.. [--json] [-o PNG]``: Q-curves per vertex, motion class, auto's
choice; a plot."""

from __future__ import annotations

import argparse

from .args import escaped, print_json, print_path
from .inputs import add_scene_argument, default_png, load_one


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("qcurves", help="Q-curves of every vertex, the motion they show and auto's choice")
    add_scene_argument(p)
    p.add_argument("--json", action="store_true", help="print the report as JSON")
    p.add_argument("-o", "--output", metavar="PNG",
                   help="where to draw the plot (default output/<stem>-qcurves.png)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..api import qcurves, qcurves_text

    picture = None if args.json and args.output is None else default_png(args, "qcurves")
    report = qcurves(load_one(args), picture)
    if args.json:
        print_json(report)
        return 0
    print(qcurves_text(escaped(report)))
    print_path(picture)
    return 0
