"""The ``tweenrender`` command: parses arguments, calls the library, maps errors to exit codes.

Exit codes: 0 done, 1 a failure while rendering or encoding, 2 bad input or usage.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any, Sequence

from .errors import TweenrenderError, UsageError
from .model import METHODS

__all__ = ["main"]

DEFAULT_MAX_FRAMES = 100_000


def _methods(text: str) -> tuple[str, ...]:
    import difflib

    names = tuple(m.strip() for m in text.split(",") if m.strip())
    for name in names:
        if name not in METHODS:
            close = difflib.get_close_matches(name, METHODS, n=1)
            hint = f" (did you mean {close[0]!r}?)" if close else ""
            raise UsageError(f"unknown method {name!r}{hint}; expected one of {', '.join(METHODS)}")
    if not names:
        raise UsageError("expected at least one method name")
    return names


def _size(text: str) -> tuple[int, int]:
    from .scenefile import LIMITS

    width, x, height = text.lower().partition("x")
    try:
        size = (int(width), int(height))
    except ValueError:
        raise UsageError(f"--size: expected WIDTHxHEIGHT in pixels, e.g. 1920x1080, found {text!r}") from None
    if not x or not all(1 <= s <= LIMITS["canvas"] for s in size):
        raise UsageError(f"--size: expected WIDTHxHEIGHT from 1 to {LIMITS['canvas']} each, found {text!r}")
    return size


def _fps(text: str) -> float:
    from .scenefile import LIMITS

    low, high = LIMITS["fps"]
    try:
        fps = float(text)
    except ValueError:
        raise UsageError(f"--fps: expected a number of frames per second, found {text!r}") from None
    if not low <= fps <= high:
        raise UsageError(f"--fps: expected {low} to {high}, found {text}")
    return fps


def _times(text: str) -> list[float]:
    try:
        values = [float(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise UsageError(f"--t: expected comma-separated numbers in [0, 1], found {text!r}") from None
    if not values or not all(0.0 <= v <= 1.0 for v in values):
        raise UsageError(f"--t: expected comma-separated numbers in [0, 1], found {text!r}")
    return values


def _print_json(data: Any) -> None:
    json.dump(data, sys.stdout, indent=2)
    sys.stdout.write("\n")


# -- commands ------------------------------------------------------------------------------------

def cmd_check(args: argparse.Namespace) -> int:
    from .pipeline import scene_view, tracks_of
    from .reports import scene_dict
    from .scenefile import load_scene

    if args.json and len(args.scene) != 1:
        raise UsageError("check --json takes exactly one scene")
    for path in args.scene:
        scene = load_scene(path)
        if args.json:
            view = scene_view(scene, tracks_of(scene), (None,))
            _print_json(scene_dict(scene, view))
        else:
            keys = sum(len(s.keys) for s in scene.shapes)
            print(f"{path}: ok ({len(scene.shapes)} shapes, {keys} keys, {scene.duration:g} s "
                  f"at {scene.fps:g} fps)")
    return 0


def cmd_stats(args: argparse.Namespace) -> int:
    from .reports import stats_dict, stats_text
    from .scenefile import load_scene

    scene = load_scene(args.scene)
    stats = stats_dict(scene, args.t)
    stats["scene"] = args.scene
    if args.json:
        _print_json(stats)
    else:
        print(stats_text(stats))
    return 0


def _output_format(args: argparse.Namespace) -> tuple[str, Path]:
    from .encode import FORMATS

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
    if suffix in FORMATS and suffix != "png":
        return suffix, target
    if suffix == "":
        return "png", target
    raise UsageError(f"-o {target}: cannot tell the format from .{suffix}; "
                     f"use --format {'|'.join(FORMATS)} or a .mp4/.webm/.gif name")


def cmd_render(args: argparse.Namespace) -> int:
    from .pipeline import RenderJob, parse_frames, render, total_frames
    from .progress import ProgressBar
    from .scenefile import LIMITS, load_scene

    scene = load_scene(args.scene)
    fmt, target = _output_format(args)
    if args.compare is not None:
        methods: tuple[str | None, ...] = _methods(args.compare) if args.compare else scene.compare
        if args.method:
            raise UsageError("--method and --compare do not go together: list the methods in --compare")
    else:
        methods = (_methods(args.method)[0],) if args.method else (None,)
    fps = args.fps or scene.fps
    total = total_frames(scene, fps)
    frames = parse_frames(args.frames, total) if args.frames else range(total)
    if len(frames) > args.max_frames:
        raise UsageError(f"{args.scene}: {len(frames)} frames is more than --max-frames {args.max_frames}; "
                         "raise --max-frames to render it anyway")
    size = args.size or scene.size
    if size[0] * len(methods) > LIMITS["canvas"]:
        raise UsageError(f"{len(methods)} panels of {size[0]} px make a {size[0] * len(methods)} px wide "
                         f"frame, more than {LIMITS['canvas']}")
    job = RenderJob(scene, methods, labels=args.compare is not None, size=size, fps=fps, frames=frames)
    bar = ProgressBar(f"{target.name}", enabled=False if args.quiet else None)
    written = render(job, fmt, target, bar)
    print(written)
    return 0


# -- parser --------------------------------------------------------------------------------------

def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="tweenrender",
        description="Inbetween 2-D keyframe polygons (linear, nonlinear Bézier, rigid, jointed paths) "
                    "and render them to PNG frames or video.")
    parser.add_argument("-v", "--verbose", action="store_true", help="show tracebacks of failures")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    p = sub.add_parser("render", help="render a scene to video or PNG frames")
    p.add_argument("scene", metavar="SCENE")
    p.add_argument("-o", "--output", metavar="OUT",
                   help="output file or folder (default output/<stem>.mp4, output/<stem>/ for png)")
    p.add_argument("--method", metavar="M", help=f"one method for every shape: {', '.join(METHODS)}")
    p.add_argument("--compare", nargs="?", const="", metavar="M,M..",
                   help="one labelled panel per method, side by side (default: the scene's compare list)")
    p.add_argument("--format", choices=("mp4", "webm", "gif", "png"))
    p.add_argument("--size", type=_size, metavar="WxH", help="size of the picture (of each panel)")
    p.add_argument("--fps", type=_fps, metavar="N")
    p.add_argument("--frames", metavar="A:B", help="render frames A to B-1 only")
    p.add_argument("--max-frames", type=int, default=DEFAULT_MAX_FRAMES, metavar="N",
                   help=f"refuse to render more frames than this (default {DEFAULT_MAX_FRAMES})")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    p.set_defaults(run=cmd_render)

    p = sub.add_parser("check", help="validate scene files")
    p.add_argument("scene", nargs="+", metavar="SCENE")
    p.add_argument("--json", action="store_true", help="print the scene as loaded")
    p.set_defaults(run=cmd_check)

    p = sub.add_parser("stats", help="the thesis's perimeter report per shape, segment and method")
    p.add_argument("scene", metavar="SCENE")
    p.add_argument("--t", type=_times, default=[0.5], metavar="T,T..", help="where to measure (default 0.5)")
    p.add_argument("--json", action="store_true")
    p.set_defaults(run=cmd_stats)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except UsageError as error:  # raised by a type= converter
        print(f"tweenrender: error: {error}", file=sys.stderr)
        return 2
    try:
        return args.run(args)
    except TweenrenderError as error:
        if args.verbose:
            raise
        print(f"tweenrender: error: {error}", file=sys.stderr)
        return error.exit_code
    except KeyboardInterrupt:
        print("tweenrender: interrupted; no output was changed", file=sys.stderr)
        return 130
    except Exception as error:  # noqa: BLE001 - the last line of defence against tracebacks
        if args.verbose:
            raise
        print(f"tweenrender: error: unexpected {type(error).__name__}: {error} (run with -v for details)",
              file=sys.stderr)
        return 1
