"""``tweenrender check SCENE... [--json]``: validate scenes, or print one as loaded."""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING

from ..errors import UsageError, printable
from .args import print_json

if TYPE_CHECKING:
    from ..model import Scene


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("check", help="validate scene files")
    p.add_argument("scene", nargs="+", metavar="SCENE")
    p.add_argument("--json", action="store_true", help="print the scene as loaded")
    p.set_defaults(run=run)


def _count(number: int, noun: str) -> str:
    return f"{number} {noun}{'' if number == 1 else 's'}"


def run(args: argparse.Namespace) -> int:
    """Check every scene; a bad one is reported on its own line and the others are still checked."""
    from ..errors import SceneError
    from ..scenefile import load_scene

    if args.json and len(args.scene) != 1:
        raise UsageError("check --json takes exactly one scene")
    if args.json:
        from ..pipeline.job import scene_view, tracks_of
        from ..reports.check_report import scene_dict

        scene = load_scene(args.scene[0])
        print_json(scene_dict(scene, scene_view(scene, tracks_of(scene), (None,))))
        return 0
    if len(args.scene) == 1:
        scene = load_scene(args.scene[0])  # a single bad scene is reported by the command line
        _report(args.scene[0], scene)
        return 0
    failed = 0
    for path in args.scene:
        try:
            _report(path, load_scene(path))
        except SceneError as error:
            print(f"tweenrender: error: {printable(str(error))}", file=sys.stderr)
            failed += 1
    return 2 if failed else 0


def _report(path: str, scene: "Scene") -> None:
    keys = sum(len(s.keys) for s in scene.shapes)
    print(f"{printable(path)}: ok ({_count(len(scene.shapes), 'shape')}, {_count(keys, 'key')}, "
          f"{scene.duration:g} s at {scene.fps:g} fps)")
