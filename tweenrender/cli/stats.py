"""``tweenrender stats SCENE|A.svg B.svg.. [--t T,T..] [--json]``: the thesis's ch. 6 perimeter report."""

from __future__ import annotations

import argparse

from .args import escaped, print_json, times
from .inputs import add_scene_argument, load_one


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("stats", help="the thesis's perimeter report per shape, segment and method")
    add_scene_argument(p)
    p.add_argument("--t", type=times, default=[0.5], metavar="T,T..", help="where to measure (default 0.5)")
    p.add_argument("--json", action="store_true")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..api import stats, stats_text

    report = stats(load_one(args), args.t)
    print_json(report) if args.json else print(stats_text(escaped(report)))
    return 0
