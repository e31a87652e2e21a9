"""Correspondence pictures like the thesis's figs. 3.1–3.10: one panel per shape segment, stacked.

Both keys are drawn as outlines side by side, thin lines join corresponding
vertices, and a vertex the path duplicates ("inserted") wears a red ring with
its number of copies. Shape hints are lettered dots on both keys, joined by the path they
force. Keys whose boxes overlap are pulled apart for the picture
only (the second moves right of the first), and the panel says so, since the
lines would otherwise cross each other illegibly.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

import numpy as np
from numpy.typing import NDArray

from ...model import Color
from ..fonts import font, wrap
from ..painter import Painter
from ..surface import Raster
from ...core.view import Viewport

__all__ = ["CPanel", "placed_apart", "correspond_picture"]

_INK: Color = (30, 34, 45, 255)
_SOFT: Color = (30, 34, 45, 160)
_BACK: Color = (255, 255, 255, 255)
_RULE: Color = (30, 34, 45, 50)
_KEY_A: Color = (31, 119, 180, 255)
_KEY_B: Color = (230, 110, 20, 255)
_PAIR: Color = (70, 74, 85, 255)
_INSERTED: Color = (205, 30, 40, 255)
_HINT: Color = (120, 40, 170, 255)
_GAP = 0.25  # space between keys pulled apart, as a share of the wider key


@dataclass(frozen=True, slots=True)
class CPanel:
    """One segment: keys ``a (m, 2)`` and ``b (n, 2)`` (world units, y up), ``pairs (L, 2)`` into them.

    ``subtitle`` is wrapped to the panel's width; a newline starts a new line. ``hints`` are shape
    hints as ``(letter, vertex of a, vertex of b)``.
    """

    title: str
    subtitle: str
    a: NDArray[np.float64]
    b: NDArray[np.float64]
    pairs: NDArray[np.intp]
    hints: tuple[tuple[str, int, int], ...] = ()


def placed_apart(a: NDArray[np.float64], b: NDArray[np.float64]) -> tuple[NDArray[np.float64], float]:
    """``b (n, 2)`` moved right of ``a (m, 2)`` when their bounding boxes overlap; and the shift (0 if none)."""
    (ax0, ay0), (ax1, ay1) = a.min(axis=0), a.max(axis=0)
    (bx0, by0), (bx1, by1) = b.min(axis=0), b.max(axis=0)
    if bx0 > ax1 or ax0 > bx1 or by0 > ay1 or ay0 > by1:
        return b, 0.0
    shift = float(ax1 - bx0 + _GAP * max(ax1 - ax0, bx1 - bx0, ay1 - ay0, by1 - by0))
    return b + np.array([shift, 0.0]), shift


@dataclass(frozen=True, slots=True)
class _Layout:
    """A panel's header lines and the pixel size of its drawing area."""

    lines: list[str]
    note: str
    b: NDArray[np.float64]  # the second key as drawn (maybe shifted)
    area: tuple[float, float, float, float]  # x, y offset within the panel, width, height
    height: float


def _layout(panel: CPanel, width: float, s: float) -> _Layout:
    b, shift = placed_apart(panel.a, panel.b)
    note = f"keys overlap: the second is drawn {shift:.3g} units to the right" if shift else ""
    lines = wrap(panel.subtitle, 12 * s, width - 28 * s)
    top = (50 + 16 * (len(lines) - 1)) * s
    both = np.concatenate([panel.a, b])
    span = np.maximum(both.max(axis=0) - both.min(axis=0), 1e-9)
    pad = 26 * s  # room for index labels and rings around the outlines
    area_w = width - 2 * pad
    # As tall as the keys' aspect asks, within reason: very flat or very tall keys still read.
    area_h = float(np.clip(area_w * span[1] / span[0], 0.22 * width, 0.5 * width))
    footer = (34 if note else 20) * s
    return _Layout(lines, note, b, (pad, top + pad, area_w, area_h), top + area_h + 2 * pad + footer)


def _copies(indices: NDArray[np.intp], count: int) -> NDArray[np.intp]:
    return np.bincount(indices, minlength=count)


class _Painter(Painter):
    def text(self, words: str, x: float, y: float, size: float, color: Color = _INK,
             bold: bool = False, centred: bool = False) -> None:
        size *= self.scale
        if centred:
            wide = font(size, bold).measureText(words)
            # Kept inside the picture: labels of vertices at the edge would be cut off.
            x = min(max(x - wide / 2, 2.0), self.raster.width - wide - 2.0)
            y += 0.35 * size
        self.raster.text(words, x, y, size, color, bold)


def _outward(pix: NDArray[np.float64]) -> NDArray[np.float64]:
    """Unit vectors ``(N, 2)`` pointing out of the polygon ``pix (N, 2)`` at each vertex.

    The normal of the vertex's tangent (the sum of its two edge directions), on
    the right of travel for a positive shoelace area, on the left otherwise.
    """
    def unit(v: NDArray[np.float64]) -> NDArray[np.float64]:
        return v / np.maximum(np.linalg.norm(v, axis=1, keepdims=True), 1e-9)

    tangent = unit(unit(np.roll(pix, -1, axis=0) - pix) + unit(pix - np.roll(pix, 1, axis=0)))
    x, y = pix[:, 0], pix[:, 1]
    area = 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))
    return np.stack([tangent[:, 1], -tangent[:, 0]], axis=1) * (1.0 if area >= 0 else -1.0)


def _roomy(pix: NDArray[np.float64], s: float) -> NDArray[np.bool_]:
    """Vertices ``(N,)`` with room for an index label: no other vertex within a label's size."""
    gaps = np.linalg.norm(pix[:, None] - pix[None], axis=2)
    np.fill_diagonal(gaps, np.inf)
    return gaps.min(axis=1) >= 10 * s


def _key(p: _Painter, pix: NDArray[np.float64], color: Color, copies: NDArray[np.intp]) -> None:
    p.raster.polygon(pix, color, None, alpha=0.10)
    p.raster.polygon(pix, None, color, 2.0 * p.scale)
    out = _outward(pix)
    labels = _roomy(pix, p.scale)
    for i, point in enumerate(pix):
        p.dot(point, 2.8, color)
        if copies[i] > 1:
            p.ring(point, 6.5, _INSERTED)
            tag = point + out[i] * 15 * p.scale
            p.text(f"{i} (×{copies[i]})", float(tag[0]), float(tag[1]), 10, _INSERTED, bold=True, centred=True)
        elif labels[i]:
            tag = point + out[i] * 12 * p.scale
            p.text(str(i), float(tag[0]), float(tag[1]), 9, _SOFT, centred=True)


def _hints(p: _Painter, hints: Sequence[tuple[str, int, int]], pa: NDArray[np.float64],
           pb: NDArray[np.float64]) -> None:
    """Each hint: its path between the keys, and a lettered dot on each key."""
    for letter, i, j in hints:
        p.line(pa[i], pb[j], _HINT, 2.0, 0.9)
    for pix, side in ((pa, [h[1] for h in hints]), (pb, [h[2] for h in hints])):
        out = _outward(pix)
        for (letter, _, _), v in zip(hints, side):
            p.dot(pix[v], 7.5, _HINT)
            p.text(letter, float(pix[v][0]), float(pix[v][1]) + 3.5 * p.scale, 10, _BACK, bold=True, centred=True)
            tag = pix[v] + out[v] * 22 * p.scale
            p.text(letter, float(tag[0]), float(tag[1]), 12, _HINT, bold=True, centred=True)


def _panel(p: _Painter, panel: CPanel, lay: _Layout, y: float, width: float) -> None:
    s = p.scale
    p.text(panel.title, 14 * s, y + 22 * s, 15, bold=True)
    for k, line in enumerate(lay.lines):
        p.text(line, 14 * s, y + (40 + 16 * k) * s, 12, _SOFT)
    ax, ay, aw, ah = lay.area
    both = np.concatenate([panel.a, lay.b])
    low, high = both.min(axis=0), both.max(axis=0)
    # A key flat along one axis would make the view's scale infinite: give the box some depth.
    depth = max(float((high - low).max()), 1e-9) * 0.05
    low, high = np.minimum(low, (low + high) / 2 - depth), np.maximum(high, (low + high) / 2 + depth)
    view = Viewport((float(low[0]), float(low[1]), float(high[0]), float(high[1])),
                    max(int(aw), 1), max(int(ah), 1))
    offset = np.array([ax, y + ay])
    pa = view.to_pixels(panel.a) + offset
    pb = view.to_pixels(lay.b) + offset
    i, j = panel.pairs[:, 0], panel.pairs[:, 1]
    ca, cb = _copies(i, len(pa)), _copies(j, len(pb))
    # Pairs first, under the outlines; a pair that uses a duplicated vertex is drawn in red.
    for k in range(len(panel.pairs)):
        extra = ca[i[k]] > 1 or cb[j[k]] > 1
        p.line(pa[i[k]], pb[j[k]], _INSERTED if extra else _PAIR, 1.0, 0.75 if extra else 0.45)
    _key(p, pa, _KEY_A, ca)
    _key(p, pb, _KEY_B, cb)
    _hints(p, panel.hints, pa, pb)
    bottom = y + lay.height
    if lay.note:
        p.text(lay.note, 14 * s, bottom - 24 * s, 10.5, _SOFT)
    x = 14 * s
    for words, color in (("key a", _KEY_A), ("  → key b", _KEY_B),
                         ("   lines join corresponding vertices; ringed i (×k): vertex i used k times",
                          _SOFT)):
        p.text(words, x, bottom - 9 * s, 10.5, color, bold=color != _SOFT)
        x += font(10.5 * s, color != _SOFT).measureText(words)
    p.line(np.array([0.0, bottom - 0.5]), np.array([width, bottom - 0.5]), _RULE, 1.0 / s)


def correspond_picture(panels: Sequence[CPanel], width: int = 960) -> NDArray[np.uint8]:
    """Every panel stacked, ``width`` pixels wide: straight RGBA ``(H, W, 4)``.

    Sizes of text and marks scale with ``width`` (960 px is scale 1).
    """
    s = float(np.clip(width / 960, 0.9, 2.0))  # text stays legible in small pictures
    layouts = [_layout(panel, width, s) for panel in panels]
    height = int(np.ceil(sum(lay.height for lay in layouts))) if layouts else int(80 * s)
    raster = Raster(width, max(height, 1))
    raster.clear(_BACK)
    painter = _Painter(raster, s)
    if not panels:
        painter.text("no shape has two keys: nothing to put in correspondence", 14 * s, 44 * s, 14)
    y = 0.0
    for panel, lay in zip(panels, layouts):
        _panel(painter, panel, lay, y, width)
        y += lay.height
    return raster.rgba().copy()
