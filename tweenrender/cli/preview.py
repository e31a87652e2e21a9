"""``tweenrender preview SCENE|A.svg B.svg..``: a page on 127.0.0.1 that plays the scene while it
renders, draws it again on every save and edits the scene by pointing; prints the page's address
(and the path of a scene file its first edit of drawings writes), then serves until Ctrl-C."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..errors import UsageError
from ..api import method_names
from .args import fps, method, size
from .inputs import add_scene_argument, is_morph, timing


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("preview", help="a local page that plays the animation as it renders, re-renders when "
                                       "the scene or its drawings change, and edits hints, arcs, turns, "
                                       "breakdowns and timing by pointing")
    add_scene_argument(p)
    p.add_argument("--method", type=method, metavar="M",
                   help=f"the method to start with (the page can change it): {', '.join(method_names())}")
    p.add_argument("--size", type=size, metavar="WxH", help="size of the picture (default the scene's)")
    p.add_argument("--fps", type=fps, metavar="N")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..preview import serve_preview

    morph = is_morph(args.scene)
    if not morph and len(args.scene) > 1:
        raise UsageError("several inputs must all be SVG drawings (.svg); give one scene file at a time")
    given = timing(args)
    if given and not morph:
        name = next(iter(given))
        raise UsageError(f"--{name}: applies to SVG drawings morphing into each other; a scene file sets ease "
                         "and stagger itself")
    for name in args.scene:
        if not Path(name).absolute().parent.is_dir():
            raise UsageError(f"{name}: its folder does not exist, so it cannot be watched")

    def announce(line: str) -> None:
        print(line, flush=True)
        if line.startswith("http://"):
            print("tweenrender: previewing; Ctrl-C to stop", file=sys.stderr, flush=True)

    serve_preview(args.scene, method=args.method, size=args.size, fps=args.fps, step=args.step,
                  announce=announce, **given)  # type: ignore[arg-type]
    return 0
