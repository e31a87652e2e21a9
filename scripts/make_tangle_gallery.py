"""Regenerate ``docs/gallery/tangles-*.png``: one unrelated pair of real icons under every method, crossings marked.

Run from anywhere: ``python scripts/make_tangle_gallery.py`` (needs ``tweenrender`` installed).
One row per method, five in-betweens (t = .2 … .8) of the element that moves, filled even-odd;
a red ring marks every point where a contour crosses itself or a hole crosses its outline
(the test of ``stats``' ``crossings``), a red frame every in-between that tangles.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import tweenrender as tr  # noqa: E402
from tweenrender.core.tangles import parents, proper_crossings, tangles  # noqa: E402
from tweenrender.core.timing.timeline import build_track, pair_paths  # noqa: E402

GALLERY = ROOT / "docs" / "gallery"
ICONS = ROOT / "tests" / "data" / "icons"
PAIRS = (("octicons/moon-24", "mdi/alpha-b"), ("simple-icons/python", "mdi/alpha-o"))
METHODS = ("linear", "nonlinear", "rigid", "arap", "intrinsic", "injective", "auto")
T = (0.2, 0.35, 0.5, 0.65, 0.8)
CELL, LABEL = 150, 110


def crossing_points(contours: list[np.ndarray], closed: list[bool], parent: list[int | None]) -> list[np.ndarray]:
    """Where the pairs of contours that count cross properly (float, for drawing only)."""
    points = []
    for c, d in proper_crossings(contours, closed):
        if not (c == d or parent[c] == d or parent[d] == c):
            continue
        a, b = contours[c], contours[d]
        ea = np.stack([a, np.roll(a, -1, axis=0)], axis=1)
        eb = np.stack([b, np.roll(b, -1, axis=0)], axis=1)
        for i, (p, q) in enumerate(ea):
            r, s = eb[:, 0], eb[:, 1]
            e, f = q - p, s - r
            den = e[0] * f[:, 1] - e[1] * f[:, 0]
            with np.errstate(divide="ignore", invalid="ignore"):
                u = ((r[:, 0] - p[0]) * f[:, 1] - (r[:, 1] - p[1]) * f[:, 0]) / den
                v = ((r[:, 0] - p[0]) * e[1] - (r[:, 1] - p[1]) * e[0]) / den
            near = (u > 0) & (u < 1) & (v > 0) & (v < 1)
            if c == d:
                j = np.arange(len(eb))
                near &= (np.abs(j - i) > 1) & ~(((i == 0) & (j == len(eb) - 1)) | ((j == 0) & (i == len(eb) - 1)))
            points += [p + w * e for w in u[near]]
    return points


def element(a: str, b: str):
    scene = tr.load_scene([ICONS / f"{a}.svg", ICONS / f"{b}.svg"])
    best = None
    for shape in scene.shapes:
        track = build_track(shape, scene.matching, unmatched=scene.unmatched, balance=scene.balance_of(shape))
        for segment in track.segments:
            moving = [k for k, p in enumerate(segment.pairs) if p.moving]
            if moving and (best is None or len(moving) > len(best[1])):
                best = (segment, moving)
    return best


def draw(a: str, b: str) -> Path:
    import skia

    segment, moving = element(a, b)
    closed = [segment.pairs[k].closed for k in moving]
    rows = {m: [pair_paths(segment, np.array(T), m)[k] for k in moving] for m in METHODS}
    everything = np.concatenate([f.reshape(-1, 2) for frames in rows.values() for f in frames])
    low, high = everything.min(axis=0), everything.max(axis=0)
    scale = 0.86 * CELL / float((high - low).max())
    parent = parents([segment.pairs[k].k0 for k in moving], closed)
    width, height = LABEL + CELL * len(T), 28 + CELL * len(METHODS)
    surface = skia.Surface(width, height)
    canvas = surface.getCanvas()
    canvas.clear(skia.ColorWHITE)
    from tweenrender.raster.fonts import typeface

    font = skia.Font(typeface(), 15)
    ink = skia.Paint(Color=skia.ColorBLACK, AntiAlias=True)
    fill = skia.Paint(Color=skia.Color(70, 110, 200), AntiAlias=True)
    line = skia.Paint(Color=skia.Color(20, 30, 60), AntiAlias=True, Style=skia.Paint.kStroke_Style, StrokeWidth=1)
    red = skia.Paint(Color=skia.Color(220, 20, 20), AntiAlias=True, Style=skia.Paint.kStroke_Style, StrokeWidth=2)
    for col, t in enumerate(T):
        canvas.drawString(f"t = {t:g}", LABEL + col * CELL + CELL / 2 - 22, 20, font, ink)
    for row, method in enumerate(METHODS):
        top = 28 + row * CELL
        canvas.drawString(method, 8, top + CELL / 2, font, ink)
        for col in range(len(T)):
            left = LABEL + col * CELL
            contours = [frames[col] for frames in rows[method]]

            def place(p: np.ndarray) -> tuple[float, float]:
                x = left + 0.07 * CELL + (p[0] - low[0]) * scale
                y = top + 0.93 * CELL - (p[1] - low[1]) * scale
                return float(x), float(y)

            path = skia.Path()
            path.setFillType(skia.PathFillType.kEvenOdd)
            for points, shut in zip(contours, closed):
                xy = [place(p) for p in points]
                path.moveTo(*xy[0])
                for p in xy[1:]:
                    path.lineTo(*p)
                if shut:
                    path.close()
            canvas.drawPath(path, fill)
            canvas.drawPath(path, line)
            if tangles(contours, closed, parent):
                canvas.drawRect(skia.Rect(left + 2, top + 2, left + CELL - 2, top + CELL - 2), red)
                for p in crossing_points(contours, closed, parent):
                    canvas.drawCircle(*place(p), 5, red)
    target = GALLERY / f"tangles-{a.split('/')[-1]}-{b.split('/')[-1]}.png"
    surface.makeImageSnapshot().save(str(target), skia.kPNG)
    return target


def main() -> None:
    GALLERY.mkdir(parents=True, exist_ok=True)
    for a, b in PAIRS:
        print(draw(a, b))


if __name__ == "__main__":
    main()
