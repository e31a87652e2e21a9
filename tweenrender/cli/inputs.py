"""The SCENE argument every command takes: a scene file, or SVG drawings morphing into each other."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING

from ..errors import UsageError
from .args import pause, seconds

if TYPE_CHECKING:
    from ..api import Scene

__all__ = ["add_scene_argument", "is_morph", "load_one", "load_each", "timing", "stem", "default_png"]


def add_scene_argument(p: argparse.ArgumentParser, several_scenes: bool = False) -> None:
    """``SCENE`` (or ``SCENE...`` where a command takes several scenes) or ``A.svg B.svg..``, and ``--step``,
    ``--ease``, ``--hold`` and ``--stagger``, which time drawings."""
    what = "scene files (.toml, .json)" if several_scenes else "a scene file (.toml, .json)"
    p.add_argument("scene", nargs="+", metavar="SCENE..." if several_scenes else "SCENE|A.svg B.svg..",
                   help=f"{what}, or SVG drawings, one key each")
    p.add_argument("--step", type=seconds, metavar="S", default=1.0,
                   help="seconds between the keys of SVG drawings given on the command line (default 1)")
    p.add_argument("--ease", metavar="CURVE",
                   help="timing of SVG drawings' moves: linear, in, out, in-out, ease, ease-in, ease-out, "
                        "ease-in-out, cubic-bezier(x1, y1, x2, y2), steps(n[, jump]) or hold (default linear)")
    p.add_argument("--hold", type=pause("--hold"), metavar="S",
                   help="seconds each SVG drawing stays before moving on for --step seconds (default 0)")
    p.add_argument("--stagger", type=pause("--stagger"), metavar="S",
                   help="seconds between the starts of a drawing's elements, in paint order; all arrive on time")


def is_morph(inputs: list[str]) -> bool:
    """Whether the inputs are SVG drawings (one morph); a mix of SVG and scene files is refused."""
    svg = [Path(p).suffix.lower() == ".svg" for p in inputs]
    if any(svg) and not all(svg):
        raise UsageError("SVG drawings and scene files do not mix: give SVG drawings (one morph) or scene files")
    return all(svg)


def load_one(args: argparse.Namespace) -> Scene:
    """The one scene of ``args.scene``: a scene file, or its SVG drawings as one morph."""
    from ..api import load_scene

    if not is_morph(args.scene):
        if len(args.scene) > 1:
            raise UsageError("this command takes one scene file (or SVG drawings, one morph)")
        return load_scene(args.scene[0], args.step, **timing(args))
    return load_scene(args.scene, args.step, **timing(args))


def load_each(args: argparse.Namespace) -> list[Scene]:
    """Every scene of ``args.scene``: one morph of SVG drawings, or each scene file."""
    from ..api import load_scene

    if is_morph(args.scene):
        return [load_scene(args.scene, args.step, **timing(args))]
    return [load_scene(path, args.step, **timing(args)) for path in args.scene]


def timing(args: argparse.Namespace) -> dict[str, object]:
    """The timing flags given (``ease``, ``hold``, ``stagger``), for ``load_scene``."""
    return {name: getattr(args, name) for name in ("ease", "hold", "stagger") if getattr(args, name, None) is not None}


def stem(inputs: list[str]) -> str:
    """The stem of default output names: the scene file's, or the drawings' joined by ``-`` (four at most)."""
    return "-".join(Path(p).stem for p in inputs[:4])


def default_png(args: argparse.Namespace, kind: str) -> str | Path:
    """``-o``, or ``output/<stem>-<kind>.png`` (the library checks that it names a PNG)."""
    return args.output if args.output is not None else Path("output") / f"{stem(args.scene)}-{kind}.png"
