"""``tweenrender reel SCENE... -o OUT``: a demo reel, a title card and a comparison per scene."""

from __future__ import annotations

import argparse
from pathlib import Path

from ..errors import UsageError
from .args import check_frame_count, count, fps, max_frames_flag, methods, print_path, size
from .matching_flags import add_balance_flag, add_matching_flags, with_matching
from .overlay_flags import MAX_ONION

DEFAULT_SIZE = (1280, 720)
DEFAULT_FPS = 24.0


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("reel", help="a demo reel: a title card and a comparison for each scene, one video")
    p.add_argument("scene", nargs="+", metavar="SCENE")
    p.add_argument("-o", "--output", metavar="OUT", default="output/reel.mp4",
                   help="a .mp4, .webm or .gif file, or a folder of PNG frames (default output/reel.mp4)")
    p.add_argument("--size", type=size, default=DEFAULT_SIZE, metavar="WxH",
                   help="size of the whole reel (default 1280x720); comparisons are fitted inside")
    p.add_argument("--fps", type=fps, default=DEFAULT_FPS, metavar="N", help="frame rate of the whole reel (default 24)")
    p.add_argument("--methods", type=methods, metavar="M,M..",
                   help="the panels of every comparison (default: each scene's compare list)")
    p.add_argument("--onion", type=count(0, MAX_ONION, "--onion"), default=0, metavar="N",
                   help="N ghosted inbetweens before and after each frame")
    add_matching_flags(p)
    add_balance_flag(p)
    p.add_argument("--plain", action="store_true", help="no vertex paths and no perimeter strip")
    max_frames_flag(p)
    p.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..encode.targets import check_output_name
    from .progress import ProgressBar
    from ..pipeline.demo_reel import plan_reel, write_reel
    from ..pipeline.library import output_format
    from ..scenefile import load_scene

    target = check_output_name(args.output)
    fmt = output_format(target)
    if fmt in ("lottie", "svg"):
        raise UsageError(f"-o {target}: a reel is a video of title cards and labelled comparisons, which a {fmt} "
                         "file cannot hold; write .mp4, .webm, .mov, .gif or a folder of PNG frames")
    scenes = [with_matching(load_scene(path), args) for path in args.scene]
    names = [Path(path).stem for path in args.scene]
    parts = plan_reel(scenes, names, args.size, args.fps, args.methods, paths=not args.plain,
                      onion=args.onion, strip=not args.plain)
    frames = sum(part.frames for part in parts)
    check_frame_count(frames, args.max_frames, "the reel")
    bar = ProgressBar(target.name, enabled=False if args.quiet else None)
    print_path(write_reel(parts, fmt, target, args.size, args.fps, bar))
    return 0
