"""Regenerate the methods comparison of ``docs/gallery/``: every method on the articulated scenes.

Run from anywhere: ``python scripts/make_methods_gallery.py`` (needs ``tweenrender`` installed).
Each picture is a storyboard sheet made by the command line, exactly as a user would make it:
one row per method, the joints used only by ``jointed``.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
GALLERY = ROOT / "docs" / "gallery"
SCENES = ("walk", "hinge", "roofbox", "letter-svg", "foot-svg")
JOINTED = ("walk", "hinge", "roofbox")
METHODS = ("linear", "nonlinear", "rigid", "jointed", "arap", "intrinsic", "intrinsic-length")
WIDTH = 960
ROW = 210  # pixels per method row
TITLE = 48


def main() -> None:
    GALLERY.mkdir(parents=True, exist_ok=True)
    for name in SCENES:
        rows = [m for m in METHODS if m != "jointed" or name in JOINTED]
        subprocess.run([sys.executable, "-m", "tweenrender", "sheet", f"scenes/{name}.toml",
                        "--methods", ",".join(rows), "--count", "5",
                        "--size", f"{WIDTH}x{TITLE + len(rows) * ROW}",
                        "-o", str(GALLERY / f"{name}-methods.png")], check=True, cwd=ROOT)


if __name__ == "__main__":
    main()
