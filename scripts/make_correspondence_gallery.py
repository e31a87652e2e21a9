"""Write the correspondence gallery: ``docs/correspondence/<stem>-<cost>-<align>.png``.

For each scene after the thesis's figs. 3.1–3.10, under three matchings
(distance as placed — the thesis's own —, distance after centring, S&G energy
after centring): the correspondence picture of ``tweenrender correspond``, and
beside it ``<stem>-<cost>-<align>-mid.png``, the mid-frame (t = 0.5) blend of
linear and nonlinear paths with that correspondence. Run from anywhere:

    python scripts/make_correspondence_gallery.py [SCENE_STEM ...]
"""

from __future__ import annotations

import sys
import tempfile
from dataclasses import replace
from pathlib import Path

import imageio.v3 as iio
import numpy as np

from tweenrender.reports.match_report import correspond_dict, matching_words
from tweenrender.plan.job import RenderJob
from tweenrender.pipeline.stream import render
from tweenrender.reports.match_report import report_picture
from tweenrender.raster.surface import Raster
from tweenrender.scenefile import load_scene

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "docs" / "correspondence"
STEMS = ("e-to-f", "twelve-to-six", "eight-to-three", "pentagon-to-triangle", "c-spike", "braces",
         "bird-feet", "bird-tail")
MATCHINGS = (("distance", "none"), ("distance", "centroid"), ("sg", "centroid"))
WIDTH = 640
MID_PANEL = (320, 200)  # each of the two method panels of the mid-frame picture
CAPTION = 24  # pixels of caption above the mid-frame


def _mid_frame(scene, folder: Path) -> np.ndarray:  # type: ignore[no-untyped-def]
    """The frame at t = 0.5 of the first shape's first segment, linear | nonlinear, RGBA."""
    segment_start, segment_end = scene.shapes[0].keys[0].time, scene.shapes[0].keys[1].time
    frame = round(0.5 * (segment_start + segment_end) * scene.fps)
    job = RenderJob(scene, ("linear", "nonlinear"), labels=True, size=MID_PANEL, fps=scene.fps,
                    frames=range(frame, frame + 1), paths=False, onion=0, strip=False)
    written = render(job, "png", folder / "mid")
    return iio.imread(sorted(Path(written).glob("frame_*.png"))[0])


def _captioned(picture: np.ndarray, words: str) -> np.ndarray:
    """``picture (H, W, 4)`` under a one-line caption."""
    height, width = picture.shape[:2]
    raster = Raster(width, CAPTION)
    raster.clear((255, 255, 255, 255))
    raster.text(words, 8, CAPTION - 8, 13, (30, 34, 45, 255))
    return np.concatenate([raster.rgba().copy(), picture[..., :4] if picture.shape[2] == 4 else
                           np.dstack([picture, np.full((height, width), 255, np.uint8)])])


def _write(path: Path, picture: np.ndarray) -> None:
    """``picture (H, W, 4)`` as a 128-colour palette PNG: a third of the size, no visible change."""
    from PIL import Image

    Image.fromarray(picture[..., :3]).quantize(colors=128, method=Image.Quantize.MEDIANCUT,
                                               dither=Image.Dither.NONE).save(path, optimize=True)


def main(stems: list[str]) -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    for stem in stems or STEMS:
        base = load_scene(ROOT / "scenes" / f"{stem}.toml")
        for cost, align in MATCHINGS:
            scene = replace(base, matching=replace(base.matching, cost=cost, align=align))
            report = correspond_dict(scene)
            name = f"{stem}-{cost}-{align}"
            _write(OUT / f"{name}.png", report_picture(scene, report, WIDTH))
            with tempfile.TemporaryDirectory() as folder:
                mid = _mid_frame(scene, Path(folder))
            words = f"{stem}, t = 0.5, pairs by {matching_words(cost, align)}"
            _write(OUT / f"{name}-mid.png", _captioned(mid, words))
            print(OUT / f"{name}.png", "  ".join(f"{e['name']}: work {e['work']:.4g} ({e['matched']})"
                                                 for e in report["shapes"]))


if __name__ == "__main__":
    main(sys.argv[1:])
