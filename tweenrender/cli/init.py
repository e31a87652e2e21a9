"""``tweenrender init A.svg B.svg.. [--step S] [--ease C] [--hold S] [--stagger S] [-o scene.toml]``: write the
scene those drawings make, to edit; never replacing a file."""

from __future__ import annotations

import argparse
from pathlib import Path

from ..errors import UsageError
from .args import print_path
from .inputs import add_scene_argument, is_morph, stem, timing


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("init", help="write the scene file SVG drawings make (as render takes them), to edit")
    add_scene_argument(p)
    p.add_argument("-o", "--output", metavar="SCENE.toml",
                   help="the scene file to write (default <a>-<b>.toml in the current folder); never replaced")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from ..api import init_scene

    if not is_morph(args.scene):
        raise UsageError("init takes SVG drawings (A.svg B.svg..), one key each")
    target = Path(args.output) if args.output is not None else Path(f"{stem(args.scene)}.toml")
    init_scene(args.scene, args.step, path=target, **timing(args))
    print_path(target)
    return 0
