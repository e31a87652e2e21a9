"""``tweenrender render SCENE ...``: frames to video or PNG, one panel per method with ``--compare``."""

from __future__ import annotations

import argparse
from pathlib import Path

from ..errors import UsageError
from ..model import METHODS
from ._args import (check_frame_count, count, format_of, fps, max_frames_flag, method, methods, not_an_input,
                    size)
from ._matching import add_matching_flags, with_matching
from ._overlays import add_overlay_flags


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("render", help="render a scene to video or PNG frames")
    p.add_argument("scene", metavar="SCENE")
    p.add_argument("-o", "--output", metavar="OUT",
                   help="output file or folder (default output/<stem>.mp4, output/<stem>/ for png)")
    p.add_argument("--method", metavar="M", help=f"one method for every shape: {', '.join(METHODS)}")
    p.add_argument("--compare", nargs="?", const="", metavar="M,M..",
                   help="one labelled panel per method, side by side (default: the scene's compare list)")
    p.add_argument("--format", choices=("mp4", "webm", "gif", "png"))
    p.add_argument("--size", type=size, metavar="WxH", help="size of the picture (of each panel)")
    p.add_argument("--fps", type=fps, metavar="N")
    p.add_argument("--frames", metavar="A:B", help="render frames A to B-1 only")
    add_overlay_flags(p)
    add_matching_flags(p)
    max_frames_flag(p)
    p.add_argument("--workers", type=count(1, 256, "--workers"), metavar="N",
                   help="processes drawing frames (default: 1 for video, whose encoder is the limit; "
                        "one per core for PNG frames of more than a second or so of 1080p)")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    p.set_defaults(run=run)


def _output_format(args: argparse.Namespace) -> tuple[str, Path]:
    from ..encode import FORMATS

    stem = Path(args.scene).stem + ("-compare" if args.compare is not None else "")
    if args.output is None:
        fmt = args.format or "mp4"
        return fmt, Path("output") / (stem if fmt == "png" else f"{stem}.{fmt}")
    target = Path(args.output)
    suffix = target.suffix.lower().lstrip(".")
    if args.format:
        if suffix in FORMATS and suffix != args.format and args.format != "png":
            raise UsageError(f"-o {target} ends in .{suffix} but --format is {args.format}")
        return args.format, target
    fmt = format_of(target)
    if fmt is not None:
        return fmt, target
    raise UsageError(f"-o {target}: cannot tell the format from .{suffix}; "
                     f"use --format {'|'.join(FORMATS)} or a .mp4/.webm/.gif name")


def run(args: argparse.Namespace) -> int:
    from ..pipeline import RenderJob, parse_frames, render, total_frames
    from ..progress import ProgressBar
    from ..scenefile import LIMITS, load_scene

    scene = with_matching(load_scene(args.scene), args)
    fmt, target = _output_format(args)
    not_an_input(target, args.scene)
    if args.compare is not None:
        panels: tuple[str | None, ...] = methods(args.compare) if args.compare else scene.compare
        if args.method:
            raise UsageError("--method and --compare do not go together: list the methods in --compare")
    else:
        panels = (method(args.method),) if args.method else (None,)
    rate = args.fps or scene.fps
    total = total_frames(scene, rate)
    frames = parse_frames(args.frames, total) if args.frames else range(total)
    check_frame_count(len(frames), args.max_frames, args.scene)
    width, height = args.size or scene.size
    if width * len(panels) > LIMITS["canvas"]:
        raise UsageError(f"{len(panels)} panels of {width} px make a {width * len(panels)} px wide "
                         f"frame, more than {LIMITS['canvas']}")
    job = RenderJob(scene, panels, labels=args.compare is not None, size=(width, height), fps=rate,
                    frames=frames, paths=args.paths, onion=args.onion, strip=args.strip)
    bar = ProgressBar(f"{target.name}", enabled=False if args.quiet else None)
    if args.workers is None:
        from ..parallel import default_workers

        args.workers = default_workers(job, fmt)
    written = render(job, fmt, target, bar, workers=args.workers)
    print(written)
    return 0
