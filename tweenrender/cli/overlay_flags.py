"""The overlay flags shared by ``render`` and ``reel``: ``--paths``, ``--onion N``, ``--strip``."""

from __future__ import annotations

import argparse

__all__ = ["add_overlay_flags"]


def add_overlay_flags(p: argparse.ArgumentParser) -> None:
    p.add_argument("--paths", action="store_true",
                   help="draw every vertex's path (as its method moves it) and the keys, behind the shapes")
    p.add_argument("--onion", type=int, default=0, metavar="N",
                   help="N ghosted inbetweens before and after each frame, one every fps/6 frames")
    p.add_argument("--strip", action="store_true",
                   help="plot the perimeter ratio over the clip along each panel's bottom")
