"""``tweenrender check SCENE...|A.svg B.svg.. [--json]``: validate scenes, or print one as loaded."""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING

from ..errors import UsageError, printable
from .args import print_json
from .inputs import add_scene_argument, is_morph, timing

if TYPE_CHECKING:
    from ..api import Scene


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("check", help="validate scene files, or SVG drawings as one morph")
    add_scene_argument(p, several_scenes=True)
    p.add_argument("--json", action="store_true", help="print the scene as loaded")
    p.set_defaults(run=run)


def _count(number: int, noun: str) -> str:
    return f"{number} {noun}{'' if number == 1 else 's'}"


def run(args: argparse.Namespace) -> int:
    """Check every scene; a bad one is reported on its own line and the others are still checked."""
    from ..errors import SceneError
    from ..api import describe, load_scene

    morph = is_morph(args.scene)
    if args.json and len(args.scene) != 1 and not morph:
        raise UsageError("check --json takes exactly one scene (or SVG drawings, one morph)")
    if morph or len(args.scene) == 1:
        scene = load_scene(args.scene if morph else args.scene[0], args.step, **timing(args))  # the CLI's line
        if args.json:
            print_json(describe(scene))
        else:
            _report(", ".join(args.scene), scene)
        return 0
    failed = 0
    for path in args.scene:
        try:
            _report(path, load_scene(path, args.step, **timing(args)))
        except SceneError as error:
            print(f"tweenrender: error: {printable(str(error))}", file=sys.stderr)
            failed += 1
    return 2 if failed else 0


def _report(path: str, scene: "Scene") -> None:
    keys = sum(len(s.keys) for s in scene.shapes)
    print(f"{printable(path)}: ok ({_count(len(scene.shapes), 'shape')}, {_count(keys, 'key')}, "
          f"{scene.duration:g} s at {scene.fps:g} fps)")
