"""``tweenrender render SCENE ...``: frames to video or PNG, one panel per method with ``--compare``.

Parses the flags and calls :func:`tweenrender.write`, which writes exactly what this command writes.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from ..errors import UsageError
from ..model import METHODS
from .args import (check_frame_count, count, curve, fps, max_frames_flag, method, methods, pause, print_path, seconds,
                   size)
from .matching_flags import add_balance_flag, add_matching_flags
from .overlay_flags import add_overlay_flags


def register(sub: argparse._SubParsersAction) -> None:
    from ..encode import FORMATS

    p = sub.add_parser("render", help="render a scene, or SVG drawings morphing into each other, to video or PNG")
    p.add_argument("scene", nargs="+", metavar="SCENE|A.svg B.svg..",
                   help="a scene file (.toml, .json), or SVG drawings, one key each")
    p.add_argument("--step", type=seconds, metavar="S", default=1.0,
                   help="seconds between the keys of SVG drawings given on the command line (default 1)")
    p.add_argument("--ease", type=curve, metavar="CURVE",
                   help="timing of SVG drawings' moves: linear, in, out, in-out, ease, ease-in, ease-out, "
                        "ease-in-out, cubic-bezier(x1, y1, x2, y2), steps(n[, jump]) or hold (default linear)")
    p.add_argument("--hold", type=pause("--hold"), metavar="S",
                   help="seconds each SVG drawing stays before moving on for --step seconds (default 0)")
    p.add_argument("--stagger", type=pause("--stagger"), metavar="S",
                   help="seconds between the starts of a drawing's elements, in paint order; all arrive on time")
    p.add_argument("-o", "--output", metavar="OUT",
                   help="output file or folder (default output/<stem>.mp4, output/<stem>/ for png)")
    p.add_argument("--method", type=method, metavar="M", help=f"one method for every shape: {', '.join(METHODS)}")
    p.add_argument("--compare", nargs="?", const="", metavar="M,M..",
                   help="one labelled panel per method, side by side (default: the scene's compare list)")
    p.add_argument("--format", choices=FORMATS)
    p.add_argument("--size", type=size, metavar="WxH", help="size of the picture (of each panel)")
    p.add_argument("--fps", type=fps, metavar="N")
    p.add_argument("--frames", metavar="A:B", help="render frames A to B-1 only")
    p.add_argument("--background", metavar="COLOR|none",
                   help="#rgb, #rgba, #rrggbb or #rrggbbaa, or none (transparent: webm, mov, gif and png keep it)")
    add_overlay_flags(p)
    add_matching_flags(p)
    add_balance_flag(p)
    max_frames_flag(p)
    p.add_argument("--workers", type=count(1, 256, "--workers"), metavar="N",
                   help="processes drawing frames (default: chosen from the measured cost of a frame against "
                        "the encoder's: 1 when the encoder is the limit)")
    p.add_argument("--cluster", metavar="ADDRESS",
                   help="render chunks on a dask.distributed cluster: a scheduler address (tcp://host:8786) "
                        "or local:N for N local processes; needs pip install \"tweenrender[cluster]\"")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    p.set_defaults(run=run)


def default_target(inputs: list[str], fmt: str | None, compare: bool) -> Path:
    """``output/<stem>.<fmt>`` (``<stem>-compare`` for comparisons; a folder ``output/<stem>`` for png);
    the stem of several drawings is theirs joined by ``-``."""
    stem = "-".join(Path(p).stem for p in inputs[:4]) + ("-compare" if compare else "")
    fmt = fmt or "mp4"
    return Path("output") / (stem if fmt == "png" else f"{stem}.{fmt}")


def run(args: argparse.Namespace) -> int:
    from ..encode.targets import check_output_name
    from ..pipeline.job import pick_frames, total_frames
    from ..pipeline.library import load_scene, output_format, write
    from .progress import ProgressBar

    if args.workers is not None and args.cluster is not None:
        raise UsageError("--workers and --cluster do not go together: the cluster's workers draw the frames")
    if args.method and args.compare is not None:
        raise UsageError("--method and --compare do not go together: list the methods in --compare")
    compare = None if args.compare is None else (methods(args.compare) if args.compare else True)
    if len(args.scene) > 1 and not all(Path(p).suffix.lower() == ".svg" for p in args.scene):
        raise UsageError("several inputs must all be SVG drawings (.svg); give one scene file at a time")
    target = check_output_name(args.output) if args.output is not None else \
        default_target(args.scene, args.format, compare is not None)
    output_format(target, args.format)  # a name the format cannot be told from is refused before loading
    timing = {k: v for k, v in (("ease", args.ease), ("hold", args.hold), ("stagger", args.stagger)) if v is not None}
    if timing and not all(Path(p).suffix.lower() == ".svg" for p in args.scene):
        raise UsageError(f"--{next(iter(timing))}: applies to SVG drawings given on the command line; "
                         "a scene file sets ease and stagger itself")
    scene = load_scene(args.scene if len(args.scene) > 1 else args.scene[0], args.step, **timing)
    frames = pick_frames(args.frames, total_frames(scene, args.fps))
    check_frame_count(len(frames), args.max_frames, args.scene[0])
    bar = ProgressBar(target.name, enabled=False if args.quiet else None)
    print_path(write(scene, target, method=args.method, compare=compare, format=args.format, size=args.size,
                     fps=args.fps, frames=frames, background=args.background, paths=args.paths, onion=args.onion,
                     strip=args.strip, cost=args.cost, align=args.align, equal_counts=args.equal_counts,
                     balance=args.balance, workers=args.workers, cluster=args.cluster, progress=bar))
    return 0
