"""Q-curve plots like the thesis's figs. 4.4–4.8: one panel per shape and segment.

Each vertex's Q-curve is drawn in the ``(F·B, F×B)`` plane with its control
polygon ``Q0–Q1–Q2``; the origin is marked with axes and the positive x-axis is
emphasised, since a curve crossing it means the vertex angle passes through zero.
When the curves are small beside the axis range (a translation collapses each
curve to a point; a shape far from any fold sits far from the origin) a zoomed
inset shows them.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

import numpy as np
import skia
from numpy.typing import NDArray

from ...model import Color
from ..fonts import font
from ..painter import SOFT as _SOFT
from ..painter import Painter
from ..surface import Raster, paint_color

__all__ = ["QPanel", "PALETTE", "NOTHING_MOVES", "axis_range", "qcurves_picture"]

NOTHING_MOVES = "no shape has two keys: nothing moves"
"""What a picture without panels says unless told why it has none."""

PALETTE: tuple[Color, ...] = (
    (31, 119, 180, 255), (214, 39, 40, 255), (44, 160, 44, 255), (255, 127, 14, 255),
    (148, 103, 189, 255), (23, 190, 207, 255), (140, 86, 75, 255), (227, 119, 194, 255),
    (188, 189, 34, 255), (127, 127, 127, 255),
)
"""Curve colours, one per vertex in turn (the tab10 colours)."""

_INK: Color = (30, 34, 45, 255)
_AXIS: Color = (30, 34, 45, 90)
_ZERO: Color = (200, 30, 30, 255)
_FRAME: Color = (30, 34, 45, 60)
_BACK: Color = (255, 255, 255, 255)
_MARGIN = 0.12  # of the axis range, around the farthest control point
_ZOOM_BELOW = 0.2  # inset when the curves span less than this share of the axes' width
_FAR_PIXELS = 1e9  # pixel coordinates are kept within this, far off any picture


@dataclass(frozen=True, slots=True)
class QPanel:
    """One shape segment's Q-curves: ``q (N, 3, 2)`` control points, ``through_zero (N,)``.

    ``subtitle`` is wrapped to the panel's width; a newline starts a new line.
    """

    title: str
    subtitle: str
    q: NDArray[np.float64]
    through_zero: NDArray[np.bool_]


def axis_range(q: NDArray[np.float64], margin: float = _MARGIN) -> float:
    """Half-width ``R`` of the symmetric square ``[-R, R]²`` holding every control point ``(N, 3, 2)``."""
    finite = q[np.isfinite(q)]
    reach = float(np.abs(finite).max()) if finite.size else 0.0
    return reach * (1.0 + margin) if reach > 0 else 1.0


class _Map:
    """World box ``[cx ± r] × [cy ± r]`` onto a pixel square at ``(x, y)`` of side ``side``, y up."""

    def __init__(self, cx: float, cy: float, r: float, x: float, y: float, side: float) -> None:
        # a half-side of at least the least float: the curves of a shape of 1e-160 and less are subnormal
        self.cx, self.cy, self.r, self.x, self.y, self.side = cx, cy, max(r, 5e-324), x, y, side

    def __call__(self, p: NDArray[np.float64]) -> NDArray[np.float64]:
        # shares of the box first, then pixels: side / 2r overflows for a subnormal box; points far
        # outside a tiny box are kept a billion pixels off the picture
        with np.errstate(over="ignore"):
            u = (p[..., 0] - self.cx + self.r) / (2 * self.r)
            v = (self.cy + self.r - p[..., 1]) / (2 * self.r)
            pixels = np.stack([self.x + u * self.side, self.y + v * self.side], axis=-1)
        return np.clip(pixels, -_FAR_PIXELS, _FAR_PIXELS)


def _groups(pix: NDArray[np.float64], tol: float) -> list[list[int]]:
    """Vertices whose three control points ``(N, 3, 2)`` pixels lie within ``tol`` pixels of each
    other's: drawn on top of each other, so one label names them all."""
    groups: list[list[int]] = []
    for i in range(len(pix)):
        for g in groups:
            if np.abs(pix[g[0]] - pix[i]).max() <= tol:
                g.append(i)
                break
        else:
            groups.append([i])
    return groups


class _Painter(Painter):
    def square(self, p: NDArray[np.float64], half: float, color: Color) -> None:
        h = half * self.scale
        self.fill.setColor(paint_color(color))
        self.canvas.drawRect(skia.Rect.MakeLTRB(p[0] - h, p[1] - h, p[0] + h, p[1] + h), self.fill)

    def curve(self, points: NDArray[np.float64], color: Color, width: float) -> None:
        """The quadratic Bézier through pixel control points ``(3, 2)`` (an affine image of the curve)."""
        path = skia.Path()
        path.moveTo(*points[0].tolist())
        path.quadTo(*points[1].tolist(), *points[2].tolist())
        self.stroke.setColor(paint_color(color))
        self.stroke.setStrokeWidth(width * self.scale)
        self.canvas.drawPath(path, self.stroke)



def _plot_area(p: _Painter, m: _Map, panel: QPanel, labels: bool, size: float) -> None:
    """Axes, the emphasised positive x-axis, then every curve with its control polygon."""
    c = p.canvas
    c.save()
    c.clipRect(skia.Rect.MakeXYWH(m.x, m.y, m.side, m.side))
    lo, hi = m(np.array([m.cx - m.r, m.cy - m.r])), m(np.array([m.cx + m.r, m.cy + m.r]))
    origin = m(np.zeros(2))
    p.line(np.array([lo[0], origin[1]]), np.array([hi[0], origin[1]]), _AXIS, 1.0)
    p.line(np.array([origin[0], lo[1]]), np.array([origin[0], hi[1]]), _AXIS, 1.0)
    if hi[0] > origin[0]:  # where the angle is zero: a curve crossing it folds the two edges together
        p.line(np.array([max(origin[0], lo[0]), origin[1]]), np.array([hi[0], origin[1]]), _ZERO, 2.5, 0.55)
    p.dot(origin, 3.0, _INK)

    q = panel.q
    pix = m(q)
    for i in reversed(range(len(q))):
        color = PALETTE[i % len(PALETTE)]
        p.line(pix[i, 0], pix[i, 1], color, 1.0, 0.6)
        p.line(pix[i, 1], pix[i, 2], color, 1.0, 0.6)
    # Lowest index on top: coincident curves then show the colour of their label.
    for i in reversed(range(len(q))):
        p.curve(pix[i], PALETTE[i % len(PALETTE)], 3.0 if panel.through_zero[i] else 2.0)
    for i in reversed(range(len(q))):
        color = PALETTE[i % len(PALETTE)]
        p.dot(pix[i, 1], 3.5, color, hollow=True)
        p.square(pix[i, 2], 3.2, color)
        p.dot(pix[i, 0], 4.0, color)
    if labels:
        placed: list[tuple[float, float, float]] = []  # (x, baseline, width) of labels drawn
        line = (size + 2) * p.scale
        for group in _groups(pix, 3.0 * p.scale):
            first = group[0]
            words = ",".join(map(str, group[:5])) + (f"… (+{len(group) - 5})" if len(group) > 5 else "")
            x, y = pix[first, 0, 0] + 7 * p.scale, pix[first, 0, 1] - 6 * p.scale
            width = font(size * p.scale, True).measureText(words)
            # Labels of curves that start close together stack downwards instead of overprinting.
            while any(abs(y - b) < line and x < bx + bw and bx < x + width for bx, b, bw in placed):
                y += line
            placed.append((x, y, width))
            p.text(words, x, y, size, PALETTE[first % len(PALETTE)], bold=True)
    c.restore()
    p.stroke.setColor(paint_color(_FRAME))
    p.stroke.setStrokeWidth(1.0)
    c.drawRect(skia.Rect.MakeXYWH(m.x, m.y, m.side, m.side), p.stroke)


def _zoom_box(q: NDArray[np.float64], r: float) -> tuple[float, float, float] | None:
    """``(cx, cy, half-side)`` of a zoom on the curves, or None when they already fill the axes."""
    pts = q.reshape(-1, 2)
    pts = pts[np.all(np.isfinite(pts), axis=1)]
    if len(pts) == 0:
        return None
    low, high = pts.min(axis=0), pts.max(axis=0)
    span = float((high - low).max())
    if span >= _ZOOM_BELOW * 2 * r:
        return None
    # Curves that are single points (a translation) still get a box to sit in.
    half = max(0.5 * span * (1 + 2 * _MARGIN), 0.02 * r)
    centre = 0.5 * (low + high)
    return float(centre[0]), float(centre[1]), half


def _panel(p: _Painter, panel: QPanel, x: float, y: float, width: float, height: float) -> None:
    s = p.scale
    lines = p.heading(panel.title, panel.subtitle, x, y, width)
    top, bottom = y + (56 + 17 * (lines - 1)) * s, y + height - 30 * s
    side = min(width - 28 * s, bottom - top)
    left = x + (width - side) / 2
    r = axis_range(panel.q)
    main = _Map(0.0, 0.0, r, left, top, side)
    _plot_area(p, main, panel, labels=True, size=12)
    p.text("F·B", left + side - 4 * s, main(np.zeros(2))[1] + 15 * s, 11, _SOFT, anchor="right")
    p.text("F×B", main(np.zeros(2))[0] + 5 * s, top + 13 * s, 11, _SOFT)

    zoom = _zoom_box(panel.q, r)
    if zoom is not None:
        cx, cy, half = zoom
        inset = 0.42 * side
        # The corner farthest from the curves, so the inset hides nothing.
        right = cx < 0
        below = cy > 0
        ix = left + side - inset - 8 * s if right else left + 8 * s
        iy = top + side - inset - 8 * s if below else top + 8 * s
        marked = main(np.array([[cx - half, cy - half], [cx + half, cy + half]]))
        p.stroke.setColor(paint_color(_SOFT))
        p.stroke.setStrokeWidth(1.0 * s)
        (ax, ay), (bx, by) = marked
        p.canvas.drawRect(skia.Rect.MakeLTRB(min(ax, bx) - 2, min(ay, by) - 2, max(ax, bx) + 2, max(ay, by) + 2),
                          p.stroke)
        p.fill.setColor(paint_color(_BACK))
        p.canvas.drawRect(skia.Rect.MakeXYWH(ix, iy, inset, inset), p.fill)
        _plot_area(p, _Map(cx, cy, half, ix, iy, inset), panel, labels=True, size=11)
        p.text(f"zoom ×{r / half:.3g}", ix + 5 * s, iy + inset - 6 * s, 10, _SOFT)

    p.text("● Q0   ○ Q1   ■ Q2   red: positive x-axis (angle 0)", x + 14 * s, y + height - 10 * s, 11, _SOFT)


def qcurves_picture(panels: Sequence[QPanel], panel_size: tuple[int, int] = (620, 680),
                    columns: int | None = None, scale: float = 1.0, note: str = NOTHING_MOVES) -> NDArray[np.uint8]:
    """Every panel in a grid (``columns`` default: up to 3), straight RGBA ``(H, W, 4)``; without panels,
    ``note`` says why."""
    count = max(len(panels), 1)
    columns = columns or min(count, 3)
    rows = -(-count // columns)
    w, h = int(panel_size[0] * scale), int(panel_size[1] * scale)
    raster = Raster(w * columns, h * rows)
    raster.clear(_BACK)
    painter = _Painter(raster, scale)
    if not panels:
        painter.note(note, 20 * scale, h / 2, w * columns - 40 * scale)
    for k, panel in enumerate(panels):
        _panel(painter, panel, (k % columns) * w, (k // columns) * h, w, h)
    return raster.rgba().copy()
