"""Regenerate ``docs/gallery/``: a storyboard sheet of every shipped scene and one short GIF.

Run from anywhere: ``python scripts/make_gallery.py`` (needs ``tweenrender`` installed).
Every picture is made by the command line, exactly as a user would make it.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
GALLERY = ROOT / "docs" / "gallery"
WIDTH = 960
ROW = 250  # pixels per method row of a sheet
TITLE = 48


def tweenrender(*args: str) -> None:
    subprocess.run([sys.executable, "-m", "tweenrender", *args], check=True, cwd=ROOT)


def main() -> None:
    sys.path.insert(0, str(ROOT))
    from tweenrender.scenefile import load_scene

    GALLERY.mkdir(parents=True, exist_ok=True)
    for path in sorted((ROOT / "scenes").glob("*.toml")):
        rows = len(load_scene(path).compare)
        tweenrender("sheet", str(path.relative_to(ROOT)), "-o", str(GALLERY / f"{path.stem}-sheet.png"),
                    "--size", f"{WIDTH}x{TITLE + rows * ROW}")
    tweenrender("render", "scenes/square.toml", "--compare", "--paths", "--strip", "--onion", "2",
                "--size", "400x270", "--fps", "12", "-q", "-o", str(GALLERY / "square-compare.gif"))


if __name__ == "__main__":
    main()
