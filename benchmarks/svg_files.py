"""Whole drawings from editors beside rsvg-convert and Chromium: frame 0 of each, by the key-frame measure.

    python benchmarks/svg_files.py FOLDER [--sample 40] [--seed 1] [--with TEXT] [--size 600] [-v]

Draws a seeded sample of the ``.svg`` files under ``FOLDER`` (those containing ``--with``, e.g. ``<text``,
when given) at ``--size`` pixels across (aspect kept) over white, with tweenrender (``load_scene(X.svg)`` at
time 0), rsvg-convert and headless Chromium, and compares each pair by the key-frame measure of
``tests/scenefile/test_key_frames.py`` (coverage IoU ≥ 0.99, colour error ≤ 0.02). Each file is counted as
drawn like librsvg, like Chromium only, where librsvg and Chromium differ as much from each other, as
differing, or as refused (a :class:`~tweenrender.errors.TweenrenderError`). Text is drawn by all three in the
system's fonts (tweenrender: ``TWEENRENDER_FONT_PATH`` unset), so they draw it in the same faces.

The Open Clip Art Library (Debian ``openclipart-svg``, public domain) is such a folder:
``/usr/share/openclipart/svg``.
"""

from __future__ import annotations

import argparse
import os
import random
import sys
from collections import Counter
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from svg_conformance import chromium_batch, draw_rsvg, draw_tweenrender, measures, over_white  # noqa: E402

PASS_IOU, PASS_ERROR = 0.99, 0.02


def _alike(a: np.ndarray, b: np.ndarray) -> bool:
    iou, error = measures(over_white(a), over_white(b))
    return iou >= PASS_IOU and error <= PASS_ERROR


def _size(svg: Path, across: int) -> tuple[int, int]:
    """The drawing's pixel size at ``across`` pixels on the longer side of its view box."""
    from tweenrender.scenefile.svg import read_drawing

    x0, y0, x1, y1 = read_drawing(svg).box
    w, h = max(x1 - x0, 1e-9), max(y1 - y0, 1e-9)
    scale = across / max(w, h)
    return max(1, round(w * scale)), max(1, round(h * scale))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", type=Path)
    parser.add_argument("--sample", type=int, default=40)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--with", dest="containing", default=None)
    parser.add_argument("--size", type=int, default=600)
    parser.add_argument("-v", "--verbose", action="store_true")
    args = parser.parse_args()
    os.environ.pop("TWEENRENDER_FONT_PATH", None)
    files = sorted(args.folder.rglob("*.svg"))
    if args.containing:
        files = [f for f in files if args.containing in f.read_text(errors="replace")]
    chosen = sorted(random.Random(args.seed).sample(files, min(args.sample, len(files))))
    print(f"{len(chosen)} of {len(files)} files under {args.folder}" +
          (f" containing {args.containing!r}" if args.containing else "") + f", seed {args.seed}")
    from tweenrender.errors import TweenrenderError

    sized, ours, refused = {}, {}, {}
    for svg in chosen:
        try:
            sized[svg] = _size(svg, args.size)
            ours[svg] = draw_tweenrender(svg, *sized[svg])
        except TweenrenderError as error:
            refused[svg] = str(error).splitlines()[0]
        except Exception as error:  # noqa: BLE001 - a file librsvg cannot draw either is left out
            refused[svg] = f"not measured: {type(error).__name__}: {error}"[:200]
    measured = [svg for svg in chosen if svg in ours]
    theirs = chromium_batch(measured, [sized[s] for s in measured])
    counts: Counter[str] = Counter()
    for svg in chosen:
        if svg in refused:
            counts["refused"] += 1
            if args.verbose:
                print(f"  refused: {svg.relative_to(args.folder)}: {refused[svg]}")
            continue
        librsvg = draw_rsvg(svg, *sized[svg])
        like_rsvg, like_chromium = _alike(ours[svg], librsvg), _alike(ours[svg], theirs[svg])
        kind = ("drawn like librsvg" if like_rsvg else "like Chromium only" if like_chromium
                else "librsvg and Chromium differ as much" if not _alike(librsvg, theirs[svg]) else "differ")
        counts[kind] += 1
        if args.verbose and kind != "drawn like librsvg":
            iou, error = measures(over_white(ours[svg]), over_white(librsvg))
            print(f"  {kind}: {svg.relative_to(args.folder)} (against librsvg IoU {iou:.3f}, error {error:.3f})")
    for kind in ("drawn like librsvg", "like Chromium only", "librsvg and Chromium differ as much", "differ",
                 "refused"):
        print(f"{kind:40s} {counts[kind]}")


if __name__ == "__main__":
    main()
