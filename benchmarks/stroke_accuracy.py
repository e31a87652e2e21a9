"""How close round strokes come to the exact area: skia's stroker and the compiled kernel, against brute force.

    python benchmarks/stroke_accuracy.py

Each case is stroked white on black by skia and by ``tweenrender.raster.round_stroke``
on a 48 × 40 canvas; the error is each pixel's coverage minus the fraction of its
16 × 16 sample points within half the width of the outline (``tests/helpers.py``).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import skia

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from tests.helpers import stroke_cases, stroke_coverage  # noqa: E402
from tweenrender.raster.round_stroke import stroke_contours  # noqa: E402
from tweenrender.raster.surface import contours_path  # noqa: E402

SIZE = (48, 40)


def by_skia(contours: list[np.ndarray], closed: list[bool], width: float) -> np.ndarray:
    """Coverage ``(rows, cols)`` of skia's round-joined, round-capped stroke."""
    pixels = np.zeros((SIZE[1], SIZE[0], 4), np.uint8)
    pixels[..., 3] = 255
    surface = skia.Surface(pixels, colorType=skia.kBGRA_8888_ColorType)
    surface.getCanvas().drawPath(contours_path(contours, closed), skia.Paint(
        AntiAlias=True, Style=skia.Paint.kStroke_Style, StrokeWidth=width, Color=skia.ColorWHITE,
        StrokeJoin=skia.Paint.kRound_Join, StrokeCap=skia.Paint.kRound_Cap))
    return pixels[..., 0] / 255


def by_kernel(contours: list[np.ndarray], closed: list[bool], width: float) -> np.ndarray:
    """Coverage ``(rows, cols)`` of the compiled kernel's stroke."""
    pixels = np.zeros((SIZE[1], SIZE[0], 4), np.uint8)
    pixels[..., 3] = 255
    stroke_contours(pixels, contours, closed, width, np.array([255.0, 255.0, 255.0, 255.0]))
    return pixels[..., 0] / 255


def main() -> None:
    print("| outline | skia: mean, worst error | kernel: mean, worst error |")
    print("|---|---|---|")
    for label, contours, closed, width in stroke_cases():
        truth = stroke_coverage(contours, closed, width, SIZE)
        row = [np.abs(draw(contours, closed, width) - truth) for draw in (by_skia, by_kernel)]
        print(f"| {label} | " + " | ".join(f"{e.mean():.4f}, {e.max():.3f}" for e in row) + " |")


if __name__ == "__main__":
    main()
