"""``tweenrender reel SCENE... -o OUT``: a demo reel, a title card and a comparison per scene."""

from __future__ import annotations

import argparse
from pathlib import Path

from .args import fps, max_frames_flag, methods, print_path, size
from .inputs import add_scene_argument, is_morph, load_each, stem
from .matching_flags import add_balance_flag, add_matching_flags, matching_options


def register(sub: argparse._SubParsersAction) -> None:
    from ..api import REEL_FPS, REEL_SIZE, default_suffix, output_kinds

    p = sub.add_parser("reel", help="a demo reel: a title card and a comparison for each scene, one video")
    add_scene_argument(p, several_scenes=True)
    p.add_argument("-o", "--output", metavar="OUT", default="output/reel.mp4",
                   help=f"{output_kinds(vector=False)} (default output/reel{default_suffix()})")
    p.add_argument("--size", type=size, default=REEL_SIZE, metavar="WxH",
                   help="size of the whole reel (default 1280x720); comparisons are fitted inside")
    p.add_argument("--fps", type=fps, default=REEL_FPS, metavar="N", help="frame rate of the whole reel (default 24)")
    p.add_argument("--methods", type=methods, metavar="M,M..",
                   help="the panels of every comparison (default: each scene's compare list)")
    p.add_argument("--onion", type=int, default=0, metavar="N",
                   help="N ghosted inbetweens before and after each frame")
    add_matching_flags(p)
    add_balance_flag(p)
    p.add_argument("--plain", action="store_true", help="no vertex paths and no perimeter strip")
    max_frames_flag(p)
    p.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..api import reel
    from .progress import ProgressBar

    names = [stem(args.scene)] if is_morph(args.scene) else [Path(path).stem for path in args.scene]
    bar = ProgressBar(Path(args.output).name, enabled=False if args.quiet else None)
    print_path(reel(load_each(args), args.output, names=names, size=args.size, fps=args.fps, methods=args.methods,
                    onion=args.onion, plain=args.plain, max_frames=args.max_frames, progress=bar,
                    **matching_options(args)))
    return 0
