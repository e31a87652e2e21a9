"""``tweenrender qcurves SCENE [--json] [-o PNG]``: Q-curves per vertex, motion class, auto's choice; a plot."""

from __future__ import annotations

import argparse

from .args import escaped, png_target, print_json, print_path


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("qcurves", help="Q-curves of every vertex, the motion they show and auto's choice")
    p.add_argument("scene", metavar="SCENE")
    p.add_argument("--json", action="store_true", help="print the report as JSON")
    p.add_argument("-o", "--output", metavar="PNG",
                   help="where to draw the plot (default output/<stem>-qcurves.png)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..reports.qcurve_report import qcurves_dict, qcurves_text, write_qcurve_plot
    from ..scenefile import load_scene

    target = png_target(args, "qcurves", "the plot")
    scene = load_scene(args.scene)
    report = qcurves_dict(scene)
    report["scene"] = args.scene
    if args.json:
        print_json(report)
        if args.output is not None:
            write_qcurve_plot(report, target)
        return 0
    print(qcurves_text(escaped(report)))
    print_path(write_qcurve_plot(report, target))
    return 0
