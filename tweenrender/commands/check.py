"""``tweenrender check SCENE... [--json]``: validate scenes, or print one as loaded."""

from __future__ import annotations

import argparse

from ..errors import UsageError
from ._args import print_json


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("check", help="validate scene files")
    p.add_argument("scene", nargs="+", metavar="SCENE")
    p.add_argument("--json", action="store_true", help="print the scene as loaded")
    p.set_defaults(run=run)


def _count(number: int, noun: str) -> str:
    return f"{number} {noun}{'' if number == 1 else 's'}"


def run(args: argparse.Namespace) -> int:
    from ..scenefile import load_scene

    if args.json and len(args.scene) != 1:
        raise UsageError("check --json takes exactly one scene")
    for path in args.scene:
        scene = load_scene(path)
        if args.json:
            from ..pipeline import scene_view, tracks_of
            from ..reports import scene_dict

            print_json(scene_dict(scene, scene_view(scene, tracks_of(scene), (None,))))
        else:
            keys = sum(len(s.keys) for s in scene.shapes)
            print(f"{path}: ok ({_count(len(scene.shapes), 'shape')}, {_count(keys, 'key')}, "
                  f"{scene.duration:g} s at {scene.fps:g} fps)")
    return 0
