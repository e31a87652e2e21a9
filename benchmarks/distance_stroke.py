"""A round-joined stroke drawn from distances, not by skia's stroker: a measured idea, not adopted.

    python benchmarks/distance_stroke.py        # accuracy against brute force, beside skia's

``benchmarks/bench_render.py --only drawing`` times it on the stroked scene.

A round join with round caps is every point within half the width of the
polyline, so a pixel's coverage can follow from its centre's distance ``d`` to
the nearest segment: the area of the unit pixel inside the straight edge at
``u = r - d`` with that segment's normal ``n``, in closed form::

    a = max(|nx|, |ny|), b = min(|nx|, |ny|), w = (a + b) / 2
    |u| ≤ (a - b) / 2            0.5 + u / a
    (a - b) / 2 < |u| < w        1 - (w - u)² / 2ab  (u > 0),   (w + u)² / 2ab  (u < 0)
    |u| ≥ w                      1 (u > 0), 0 (u < 0)

Where two edges cross one pixel (the inner corner of a bend, a gap between
spikes) the nearest edge alone misses part of the pixel; with ``corners`` the
second-nearest segment whose nearest point lies inside it adds its part, less
the part both cover (the square clipped by both edges).

Each segment visits the pixels its capsule can reach (its bounding box, or on
long slanted segments the band along it, row by row) and leaves in canvas-sized
scratch planes the two nearest; then every pixel touched is blended once.
"""

from __future__ import annotations

import math
from typing import Sequence

import numpy as np
from numba import njit
from numpy.typing import NDArray

_jit = njit(cache=True, nogil=True, error_model="numpy")
_inline = njit(inline="always", error_model="numpy")


@_inline
def coverage(u: float, nx: float, ny: float) -> float:
    """Area of the unit pixel inside a straight edge with unit normal ``(nx, ny)`` whose centre lies ``u``
    inside it."""
    a, b = abs(nx), abs(ny)
    if b > a:
        a, b = b, a
    outer = 0.5 * (a + b)
    if u >= outer:
        return 1.0
    if u <= -outer:
        return 0.0
    if b < 1e-9 or abs(u) <= 0.5 * (a - b):
        return min(1.0, max(0.0, 0.5 + u / a))
    if u > 0.0:
        return 1.0 - (outer - u) ** 2 / (2.0 * a * b)
    return (outer + u) ** 2 / (2.0 * a * b)


@_inline
def _pixel_range(low: float, high: float, first: int, last: int) -> tuple[int, int]:
    """Pixels ``[start, stop)`` of ``[first, last)`` whose centres (index + 0.5) may lie in ``[low, high]``."""
    return max(first, int(math.floor(max(low, first - 1.0) + 0.5))), min(last, int(math.ceil(min(high, last + 1.0) - 0.5)))


@_inline
def _edge(segments: np.ndarray, inverse: np.ndarray, s: int, cx: float, cy: float, radius: float,
          shared: int = -1) -> tuple[float, float, float]:
    """``(u, nx, ny)``: how far the point ``(cx, cy)`` lies inside segment ``s``'s capsule and the unit
    normal of the capsule's edge nearest to it (pointing out). ``u = -inf`` when that nearest point is the
    segment's end ``shared`` (0 start, 1 end): a vertex whose disc the neighbour's capsule holds already."""
    ax, ay = segments[s, 0], segments[s, 1]
    ex, ey = segments[s, 2] - ax, segments[s, 3] - ay
    dx, dy = cx - ax, cy - ay
    t = min(1.0, max(0.0, (dx * ex + dy * ey) * inverse[s]))
    if (shared == 0 and t == 0.0) or (shared == 1 and t == 1.0):
        return -np.inf, 1.0, 0.0
    px, py = dx - t * ex, dy - t * ey
    d = math.sqrt(px * px + py * py)
    if d == 0.0:
        return radius, 1.0, 0.0
    return radius - d, px / d, py / d


@_inline
def _shared_end(segments: np.ndarray, s: int, other: int) -> int:
    """Which end of segment ``other`` is a vertex of segment ``s`` (0 its start, 1 its end, -1 neither)."""
    if segments[other, 0] == segments[s, 2] and segments[other, 1] == segments[s, 3]:
        return 0
    if segments[other, 2] == segments[s, 0] and segments[other, 3] == segments[s, 1]:
        return 1
    return -1


@_inline
def _clip(source: np.ndarray, count: int, target: np.ndarray, u: float, nx: float, ny: float) -> int:
    """Polygon ``source[:count]`` cut to the half-plane ``n · w ≤ u`` into ``target``; returns its length."""
    kept = 0
    for i in range(count):
        j = i + 1 if i + 1 < count else 0
        ax, ay, bx, by = source[i, 0], source[i, 1], source[j, 0], source[j, 1]
        da, db = nx * ax + ny * ay - u, nx * bx + ny * by - u
        if da <= 0.0:
            target[kept, 0], target[kept, 1] = ax, ay
            kept += 1
        if (da < 0.0 < db) or (db < 0.0 < da):
            f = da / (da - db)
            target[kept, 0], target[kept, 1] = ax + f * (bx - ax), ay + f * (by - ay)
            kept += 1
    return kept


@_inline
def _both(u1: float, n1x: float, n1y: float, u2: float, n2x: float, n2y: float, buffers: np.ndarray) -> float:
    """Area of the unit pixel (centred at 0) inside both ``n1 · w ≤ u1`` and ``n2 · w ≤ u2``."""
    square = buffers[0]
    square[0, 0], square[0, 1], square[1, 0], square[1, 1] = -0.5, -0.5, 0.5, -0.5
    square[2, 0], square[2, 1], square[3, 0], square[3, 1] = 0.5, 0.5, -0.5, 0.5
    count = _clip(square, 4, buffers[1], u1, n1x, n1y)
    count = _clip(buffers[1], count, buffers[0], u2, n2x, n2y)
    area = 0.0
    for i in range(count):
        j = i + 1 if i + 1 < count else 0
        area += buffers[0, i, 0] * buffers[0, j, 1] - buffers[0, j, 0] * buffers[0, i, 1]
    return 0.5 * abs(area)


@_jit
def stroke_segments(pixels: np.ndarray, segments: np.ndarray, radius: float, color: np.ndarray,
                    left: int, top: int, right: int, bottom: int, q: np.ndarray, owner: np.ndarray,
                    touched: np.ndarray, corners: bool = True) -> None:
    """Blend the round-joined stroke of ``segments (M, 4)`` (``ax, ay, bx, by`` in device pixels) with
    half-width ``radius`` (≥ 0.5) in premultiplied ``color (4,)`` (0..255, the pixels' channel order,
    alpha last) over ``pixels (H, W, 4)`` uint8 premultiplied, source-over, inside the box
    ``[left, right) × [top, bottom)`` (within the pixels; W ≤ 65536).

    Scratch: ``q (H, W, 2)`` float32 all zero (and left so), ``owner (H, W, 2)`` int32, ``touched (H·W,)``
    int32. ``q`` holds ``reach² - d²`` (0: none within reach) of the nearest segment so far and of the
    nearest one whose nearest point lies inside it, not at an end (a vertex's disc lies in both its
    segments' capsules, so only such a segment can add an edge of its own); ``owner`` holds those
    segments (the first as ``2 s + 1`` when its nearest point is inside it, ``2 s`` when at an end).
    """
    m = segments.shape[0]
    if m == 0 or right <= left or bottom <= top:
        return
    reach = radius + 0.75  # a pixel whose centre lies farther than radius + √½ from the line is not covered
    far = reach * reach
    inverse = np.empty(m)
    count = 0
    for s in range(m):
        ax, ay, bx, by = segments[s, 0], segments[s, 1], segments[s, 2], segments[s, 3]
        ex, ey = bx - ax, by - ay
        length2 = ex * ex + ey * ey
        inv = 1.0 / length2 if length2 > 0.0 else 0.0
        inverse[s] = inv
        first, last = _pixel_range(min(ay, by) - reach, max(ay, by) + reach, top, bottom)
        x_lo, x_hi = _pixel_range(min(ax, bx) - reach, max(ax, bx) + reach, left, right)
        slanted = x_hi - x_lo > 12 and last - first > 12 and abs(ey) > 1e-9
        half = reach * math.sqrt(length2) / abs(ey) if slanted else 0.0
        for y in range(first, last):
            dy = y + 0.5 - ay
            start, stop = x_lo, x_hi
            if slanted:  # only the row's stretch of the band |n · (p - a)| ≤ reach around the line
                centre = ax + dy * ex / ey
                start, stop = _pixel_range(centre - half, centre + half, x_lo, x_hi)
            along_y = dy * ey
            for x in range(start, stop):
                dx = x + 0.5 - ax
                along = (dx * ex + along_y) * inv
                t = min(1.0, max(0.0, along))
                px, py = dx - t * ex, dy - t * ey
                gain = far - (px * px + py * py)
                nearest = q[y, x, 0]
                if gain > nearest:
                    if nearest == 0.0:
                        touched[count] = (y << 16) | x
                        count += 1
                    elif owner[y, x, 0] & 1 and nearest > q[y, x, 1]:
                        q[y, x, 1], owner[y, x, 1] = nearest, owner[y, x, 0] >> 1
                    q[y, x, 0], owner[y, x, 0] = gain, 2 * s + (t == along)
                elif gain > q[y, x, 1] and t == along:
                    q[y, x, 1], owner[y, x, 1] = gain, s
    alpha = color[3] / 255.0
    corner = np.empty((2, 8, 2))  # the clipping's two polygon buffers
    # a second edge can cover part of a pixel only if its centre lies within radius + √½ of it
    reaches = far - (radius + 0.7072) ** 2
    for i in range(count):
        y, x = touched[i] >> 16, touched[i] & 0xFFFF
        second = q[y, x, 1]
        q[y, x, 0] = q[y, x, 1] = 0.0
        s = owner[y, x, 0] >> 1
        cx, cy = x + 0.5, y + 0.5
        u, nx, ny = _edge(segments, inverse, s, cx, cy, radius)
        c = coverage(u, nx, ny)
        if corners and c < 1.0 and second > reaches:
            # where two edges cross the pixel (the inner corner of a bend, a gap between two parts)
            # the second covers more of it: add its part, less the part both cover
            other = owner[y, x, 1]
            u2, mx, my = _edge(segments, inverse, other, cx, cy, radius, _shared_end(segments, s, other))
            c2 = coverage(u2, mx, my)
            if c2 >= 1.0 or c == 0.0:
                c = max(c, c2)
            elif c2 > 0.0:
                c = min(1.0, c + c2 - _both(u, nx, ny, u2, mx, my, corner))
        if c > 0.0:
            keep = 1.0 - alpha * c
            for ch in range(4):
                pixels[y, x, ch] = min(255, int(color[ch] * c + pixels[y, x, ch] * keep + 0.5))


class Scratch:
    """The kernel's scratch planes for a ``height × width`` canvas (20 bytes a pixel)."""

    def __init__(self, height: int, width: int) -> None:
        self.gain = np.zeros((height, width, 2), np.float32)
        self.owner = np.zeros((height, width, 2), np.int32)
        self.touched = np.zeros(height * width, np.int32)


def stroke(pixels: NDArray[np.uint8], contours: Sequence[NDArray[np.float64]], closed: Sequence[bool],
           width: float, color: tuple[int, int, int, int], scratch: Scratch, corners: bool = True) -> None:
    """Blend the round-joined stroke of ``contours`` (each ``(N, 2)`` pixels) of ``width`` in straight RGBA
    ``color`` over premultiplied BGRA ``pixels (H, W, 4)``."""
    runs = []
    for points, shut in zip(contours, closed):
        ends = np.roll(points, -1, axis=0) if shut else points[1:]
        runs.append(np.concatenate([points if shut else points[:-1], ends], axis=1))
    r, g, b, a = color
    premultiplied = np.array([b, g, r, 255.0]) * (a / 255.0)
    height, wide = pixels.shape[:2]
    stroke_segments(pixels, np.concatenate(runs), width / 2, premultiplied, 0, 0, wide, height,
                    scratch.gain, scratch.owner, scratch.touched, corners)


def _covered(contours: Sequence[NDArray[np.float64]], closed: Sequence[bool], width: float, size: tuple[int, int],
             samples: int = 16) -> NDArray[np.float64]:
    """Brute force: the fraction of each pixel's ``samples²`` points within ``width / 2`` of the polyline."""
    cols, rows = size
    axis_x, axis_y = (np.arange(cols * samples) + 0.5) / samples, (np.arange(rows * samples) + 0.5) / samples
    inside = np.zeros((rows * samples, cols * samples), dtype=bool)
    r = width / 2
    for vertices, shut in zip(contours, closed):
        ends = np.roll(vertices, -1, axis=0) if shut else vertices[1:]
        for p, q in zip(vertices if shut else vertices[:-1], ends):
            xs = np.flatnonzero((axis_x >= min(p[0], q[0]) - r) & (axis_x <= max(p[0], q[0]) + r))
            ys = np.flatnonzero((axis_y >= min(p[1], q[1]) - r) & (axis_y <= max(p[1], q[1]) + r))
            if not len(xs) or not len(ys):
                continue
            px, py = np.meshgrid(axis_x[xs], axis_y[ys])
            edge = q - p
            length2 = edge @ edge
            t = np.clip(((px - p[0]) * edge[0] + (py - p[1]) * edge[1]) / length2, 0, 1) if length2 else 0.0
            inside[ys[0]:ys[-1] + 1, xs[0]:xs[-1] + 1] |= np.hypot(px - p[0] - t * edge[0],
                                                                   py - p[1] - t * edge[1]) <= r
    return inside.reshape(rows, samples, cols, samples).mean(axis=(1, 3))


def _cases() -> list[tuple[str, NDArray[np.float64], bool, float]]:
    rng = np.random.default_rng(3)
    cases = []
    for width in (1.0, 2.0, 3.5, 8.0):
        turn = np.linspace(0, 2 * np.pi, 120, endpoint=False)
        radius = rng.uniform(8, 15)
        outline = np.stack([24.3 + 1.2 * radius * np.cos(turn),
                            20.1 + radius * np.sin(turn) * (0.8 + 0.2 * np.cos(3 * turn))], 1)
        cases.append((f"smooth, {width:g} px", outline, True, width))
    for angle in (30, 90):
        half = np.radians(angle) / 2
        tip = np.array([24.3, 12.2])
        one = tip + np.outer(np.linspace(18, 0, 40, endpoint=False), [np.sin(half), np.cos(half)])
        two = tip + np.outer(np.linspace(0, 18, 41), [-np.sin(half), np.cos(half)])
        cases.append((f"a {angle}° V of straight arms, 2 px", np.concatenate([one, two]), False, 2.0))
    for seed in range(2):
        spikes = np.random.default_rng(seed)
        turn = np.sort(spikes.uniform(0, 2 * np.pi, 100))
        radius = spikes.uniform(6, 17, 100)
        cases.append((f"random spikes, 2 px ({seed})", np.stack([24 + radius * np.cos(turn),
                                                                  20 + radius * np.sin(turn)], 1), True, 2.0))
    return cases


def main() -> None:
    import skia

    size = (48, 40)
    print("| outline | skia: mean, max error | distance, nearest edge | distance, two edges |")
    print("|---|---|---|---|")
    for label, outline, shut, width in _cases():
        truth = _covered([outline], [shut], width, size)
        row = []
        for how in ("skia", False, True):
            pixels = np.zeros((size[1], size[0], 4), np.uint8)
            pixels[..., 3] = 255
            if how == "skia":
                surface = skia.Surface(pixels, colorType=skia.kBGRA_8888_ColorType)
                path = skia.Path()
                path.addPoly([skia.Point(*p) for p in outline.tolist()], shut)
                surface.getCanvas().drawPath(path, skia.Paint(AntiAlias=True, Style=skia.Paint.kStroke_Style,
                                                              StrokeWidth=width, Color=skia.ColorWHITE,
                                                              StrokeJoin=skia.Paint.kRound_Join,
                                                              StrokeCap=skia.Paint.kRound_Cap))
            else:
                stroke(pixels, [outline], [shut], width, (255, 255, 255, 255), Scratch(size[1], size[0]), how)
            error = np.abs(pixels[..., 0] / 255 - truth)
            row.append(f"{error.mean():.4f}, {error.max():.3f}")
        print(f"| {label} | {' | '.join(row)} |")


if __name__ == "__main__":
    main()
