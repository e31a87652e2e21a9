"""``tweenrender qcurves SCENE [--json] [-o PNG]``: Q-curves per vertex, motion class, auto's choice; a plot."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from ._args import png_target, print_json


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("qcurves", help="Q-curves of every vertex, the motion they show and auto's choice")
    p.add_argument("scene", metavar="SCENE")
    p.add_argument("--json", action="store_true", help="print the report as JSON")
    p.add_argument("-o", "--output", metavar="PNG",
                   help="where to draw the plot (default output/<stem>-qcurves.png)")
    p.set_defaults(run=run)


def _plot(report: dict[str, Any], target: Path) -> Path:
    """Draw the report's Q-curves and write them to ``target`` atomically."""
    from ..encode.images import write_png
    from ..render.qplot import report_picture

    picture = report_picture(report)
    return write_png(picture, target, "the plot")


def run(args: argparse.Namespace) -> int:
    from ..qreport import qcurves_dict, qcurves_text
    from ..scenefile import load_scene

    target = png_target(args, "qcurves", "the plot")
    scene = load_scene(args.scene)
    report = qcurves_dict(scene)
    report["scene"] = args.scene
    if args.json:
        print_json(report)
        if args.output is not None:
            _plot(report, target)
        return 0
    print(qcurves_text(report))
    print(_plot(report, target))
    return 0
