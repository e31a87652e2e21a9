"""``tweenrender render SCENE|A.svg B.svg.. ...``: frames to video or PNG, one panel per method with ``--compare``.

Parses the flags and calls :func:`tweenrender.write`, which checks them and writes the output.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from .args import fps, max_frames_flag, method, methods, print_path, size
from .inputs import add_scene_argument, load_one, stem
from .matching_flags import add_balance_flag, add_matching_flags
from .overlay_flags import add_overlay_flags


def register(sub: argparse._SubParsersAction) -> None:
    from ..api import default_suffix, format_loop, format_names, listing, method_names

    vector = format_names(vector=True)

    p = sub.add_parser("render", help="render a scene, or SVG drawings morphing into each other, to video, PNG, "
                                       "Lottie or animated SVG")
    add_scene_argument(p)
    p.add_argument("-o", "--output", metavar="OUT",
                   help="output file or folder (default " + ", ".join(
                       f"output/<stem>{default_suffix(n) or '/'}" + (f" for {n}" if i else "")
                       for i, n in enumerate(format_names())) + ")")
    p.add_argument("--method", type=method, metavar="M", help=f"one method for every shape: {', '.join(method_names())}")
    p.add_argument("--compare", nargs="?", const="", metavar="M,M..",
                   help="one labelled panel per method, side by side (default: the scene's compare list)")
    p.add_argument("--format", choices=format_names(),
                   help="the output format (default: from -o's extension); "
                        f"{listing([f'{n} ({default_suffix(n)})' for n in vector])} hold the paths, keyframed")
    p.add_argument("--max-error", type=float, metavar="PX",
                   help=f"{listing(vector)}: how far (output pixels) the keyframed paths may stray from the exact "
                        "inbetween at a frame (default 0.25)")
    looping = format_names(loop=True)
    p.add_argument("--loop", action="store_true",
                   help=f"{listing(looping)} only: the file plays over and over ("
                        + "; ".join(f"{n}: {format_loop(n)}" for n in looping) + ")")
    p.add_argument("--draft", action="store_true",
                   help=f"{listing(format_names(draft=True))} only: encode at the encoder's quickest settings, "
                        "for a quick look (the same quality asked for, a larger file)")
    p.add_argument("--size", type=size, metavar="WxH", help="size of the picture (of each panel)")
    p.add_argument("--fps", type=fps, metavar="N")
    p.add_argument("--frames", metavar="A:B", help="render frames A to B-1 only")
    p.add_argument("--background", metavar="COLOR|none",
                   help="#rgb, #rgba, #rrggbb or #rrggbbaa, or none (transparent: "
                        f"{listing(format_names(vector=False, alpha=True))} keep it)")
    add_overlay_flags(p)
    add_matching_flags(p)
    add_balance_flag(p)
    max_frames_flag(p)
    p.add_argument("--workers", type=int, metavar="N",
                   help="processes drawing frames (default: chosen from the measured cost of a frame against "
                        "the encoder's: 1 when the encoder is the limit)")
    p.add_argument("--cluster", metavar="ADDRESS",
                   help="render chunks on a dask.distributed cluster: a scheduler address (tcp://host:8786) "
                        "or local:N for N local processes; needs pip install \"tweenrender[cluster]\"")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    p.set_defaults(run=run)


def default_target(inputs: list[str], fmt: str | None, compare: bool) -> Path:
    """``output/<stem><suffix>`` (``<stem>-compare`` for comparisons; a folder ``output/<stem>`` for PNG
    frames); the stem of several drawings is theirs joined by ``-``."""
    from ..api import default_suffix

    return Path("output") / (stem(inputs) + ("-compare" if compare else "") + default_suffix(fmt))


def run(args: argparse.Namespace) -> int:
    from ..api import RenderOptions, encoder_search_done, start_encoder_search, write
    from .progress import ProgressBar

    compare = None if args.compare is None else (methods(args.compare) if args.compare else True)
    target = args.output if args.output is not None else default_target(args.scene, args.format, compare is not None)
    start_encoder_search(target, args.format)
    try:
        given = {name: getattr(args, name) for name in RenderOptions.names() if hasattr(args, name)}
        options = RenderOptions.create(**{**given, "compare": compare, "progress": ProgressBar(
            Path(target).name, enabled=False if args.quiet else None)})
        print_path(write(load_one(args), target, options=options))
    finally:
        encoder_search_done()
    return 0
