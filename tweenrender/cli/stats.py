"""``tweenrender stats SCENE [--t T,T..] [--json]``: the thesis's ch. 6 perimeter report."""

from __future__ import annotations

import argparse

from .args import escaped, print_json, times


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("stats", help="the thesis's perimeter report per shape, segment and method")
    p.add_argument("scene", metavar="SCENE")
    p.add_argument("--t", type=times, default=[0.5], metavar="T,T..", help="where to measure (default 0.5)")
    p.add_argument("--json", action="store_true")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..reports.stats import stats_dict, stats_text
    from ..scenefile import load_scene

    scene = load_scene(args.scene)
    stats = stats_dict(scene, args.t)
    stats["scene"] = args.scene
    print_json(stats) if args.json else print(stats_text(escaped(stats)))
    return 0
