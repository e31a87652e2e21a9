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
ICONS = ROOT / "tests" / "data" / "icons"
MORPHS = {  # name: drawings, one key a second (and a view, where the drawing's own is mostly empty)
    "apple-pear": ["twemoji/1f34e.svg", "twemoji/1f350.svg"],
    "grin-sunglasses": ["twemoji/1f600.svg", "twemoji/1f60e.svg"],
    "sun-moon": ["feather/sun.svg", "feather/moon.svg"],
    "letters-a-o-b": ["mdi/alpha-a.svg", "mdi/alpha-o.svg", "mdi/alpha-b.svg", (7.0, -19.0, 17.0, -5.0)],
    "heart-star": ["heroicons/heart.svg", "octicons/star-24.svg"],
    "potato-olive": ["fluent-emoji/potato.svg", "fluent-emoji/olive.svg"],
    "page-truck": ["twemoji/1f4c4.svg", "twemoji/1f69a.svg"],
    "smiley-letter-a": ["octicons/smiley-24.svg", "tabler/letter-a.svg"],
}
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
    icon_morphs()


def icon_morphs(names: list[str] | None = None) -> None:
    """Each morph as a GIF (by the command line) and a strip of six frames (by the library)."""
    import imageio.v3 as iio
    import numpy as np

    import tweenrender as tr

    from dataclasses import replace

    for name, files in MORPHS.items():
        if names is not None and name not in names:
            continue
        view = files[-1] if isinstance(files[-1], tuple) else None
        paths = [str(ICONS / f) for f in files if isinstance(f, str)]
        if view is None:
            tweenrender("render", *paths, "--size", "200x200", "--fps", "12", "-q",
                        "-o", str(GALLERY / f"{name}.gif"))
        scene = tr.load_scene(paths)
        if view is not None:
            scene = replace(scene, view=view)
            tr.write(scene, GALLERY / f"{name}.gif", size=(200, 280), fps=12)
        size = (160, 160) if view is None else (120, 168)
        times = np.linspace(0.0, scene.duration, 6 if len(paths) == 2 else 9)
        strip = np.concatenate([tr.frame(scene, t, size=size) for t in times], axis=1)
        iio.imwrite(GALLERY / f"{name}-strip.png", strip[..., :3])


if __name__ == "__main__":
    if sys.argv[1:]:  # only these morphs, e.g. ``python scripts/make_gallery.py potato-olive``
        sys.path.insert(0, str(ROOT))
        icon_morphs(sys.argv[1:])
    else:
        main()
