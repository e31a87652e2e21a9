"""``tweenrender preview SCENE|A.svg B.svg..``: a page on 127.0.0.1 that plays the scene while it
renders and draws it again on every save; prints the page's address, then serves until Ctrl-C."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..errors import UsageError
from ..api import method_names
from .args import fps, method, seconds, size


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("preview", help="a local page that plays the animation as it renders and re-renders "
                                       "when the scene or its drawings change")
    p.add_argument("scene", nargs="+", metavar="SCENE|A.svg B.svg..",
                   help="a scene file (.toml, .json), or SVG drawings, one key each")
    p.add_argument("--step", type=seconds, metavar="S", default=1.0,
                   help="seconds between the keys of SVG drawings given on the command line (default 1)")
    p.add_argument("--method", type=method, metavar="M",
                   help=f"the method to start with (the page can change it): {', '.join(method_names())}")
    p.add_argument("--size", type=size, metavar="WxH", help="size of the picture (default the scene's)")
    p.add_argument("--fps", type=fps, metavar="N")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..preview import serve_preview

    if len(args.scene) > 1 and not all(Path(p).suffix.lower() == ".svg" for p in args.scene):
        raise UsageError("several inputs must all be SVG drawings (.svg); give one scene file at a time")
    for name in args.scene:
        if not Path(name).absolute().parent.is_dir():
            raise UsageError(f"{name}: its folder does not exist, so it cannot be watched")

    def announce(url: str) -> None:
        print(url, flush=True)
        print("tweenrender: previewing; Ctrl-C to stop", file=sys.stderr, flush=True)

    serve_preview(args.scene, method=args.method, size=args.size, fps=args.fps, step=args.step,
                  announce=announce)
    return 0
