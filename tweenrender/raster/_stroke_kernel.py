"""Compiled kernel of the round stroke (numba); the API is in ``round_stroke.py``.

A stroke with round joins and round caps covers exactly the points within half
its width ``r`` of the polyline: the union of one capsule per segment. A
pixel's coverage follows from its centre's distance ``d`` to the nearest
segment: the area of the unit pixel inside the straight edge at ``u = r - d``
whose normal ``n`` points from that segment's nearest point to the centre, in
closed form (``coverage``). Where two parts of the outline cross one pixel (the
inner corner of a bend, the gap between two spikes) the nearest edge alone
misses some of it, so the nearest segment whose nearest point lies inside it
(not at an end) is kept too, and its part is added less the part both cover
(the pixel clipped by both edges, ``_both``).

The work goes row by row, so that a row's scratch stays in the cache: each
segment whose capsule (the points within ``r + √½``, beyond which a pixel is not
covered at all) reaches the row visits the row's pixels inside the capsule's
box and the slab along it, and keeps in each the two nearest segments and the
offset from the nearest one's nearest point; then the row's touched pixels are
blended once, source-over.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..core.jit import cached_jit as _jit

__all__ = ["coverage", "polyline_segments", "stroke_segments"]

_HALF_DIAGONAL = 0.7072
"""A pixel whose centre lies farther than ``r + √½`` from every segment is not covered at all."""

_inline = njit(inline="always", error_model="numpy")


@_jit
def coverage(u: float, nx: float, ny: float) -> float:
    """Area of the unit pixel inside a straight edge with unit normal ``(nx, ny)`` (pointing out) whose
    centre lies ``u`` inside it (negative: outside)."""
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
def _within(value: float, low: int, high: int) -> float:
    """``value`` held to ``[low - 1, high + 1]`` before it becomes an integer: a far or infinite bound then
    converts exactly (an out-of-range float has no integer)."""
    return min(max(value, low - 1.0), high + 1.0)


@_inline
def _edge(segments: np.ndarray, inverse: np.ndarray, s: int, cx: float, cy: float, radius: float,
          shared: int) -> tuple[float, float, float]:
    """``(u, nx, ny)``: how far ``(cx, cy)`` lies inside segment ``s``'s capsule and the unit normal of the
    capsule's edge nearest to it (pointing out). ``u = -inf`` when that nearest point is the end ``shared``
    (0 start, 1 end) of ``s``: a vertex whose disc another segment's capsule holds already."""
    ax, ay = segments[s, 0], segments[s, 1]
    ex, ey = segments[s, 2] - ax, segments[s, 3] - ay
    dx, dy = cx - ax, cy - ay
    t = min(1.0, max(0.0, (dx * ex + dy * ey) * inverse[s]))
    if (shared == 0 and t == 0.0) or (shared == 1 and t == 1.0):
        return -np.inf, 1.0, 0.0
    px, py = dx - t * ex, dy - t * ey
    d2 = px * px + py * py
    if d2 == 0.0:
        return radius, 1.0, 0.0
    d = math.sqrt(d2)
    inv = 1.0 / d
    return radius - d, px * inv, py * inv


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
def polyline_segments(points: np.ndarray, counts: np.ndarray, closed: np.ndarray, scale: float, dx: float,
                      dy: float) -> np.ndarray:
    """The segments ``(M, 4)`` (``ax, ay, bx, by``) of contours laid end to end in ``points (N, 2)``,
    ``counts[k]`` vertices each (contours of fewer than 2 are skipped), closed or open, each vertex taken to
    ``scale · p + (dx, dy)``."""
    total = 0
    for k in range(counts.shape[0]):
        if counts[k] >= 2:
            total += counts[k] if closed[k] else counts[k] - 1
    segments = np.empty((total, 4))
    start = 0
    row = 0
    for k in range(counts.shape[0]):
        n = counts[k]
        if n >= 2:
            for i in range(n if closed[k] else n - 1):
                j = start + (i + 1) % n
                segments[row, 0] = scale * points[start + i, 0] + dx
                segments[row, 1] = scale * points[start + i, 1] + dy
                segments[row, 2] = scale * points[j, 0] + dx
                segments[row, 3] = scale * points[j, 1] + dy
                row += 1
        start += n
    return segments


@_jit
def stroke_segments(pixels: np.ndarray, segments: np.ndarray, radius: float, color: np.ndarray,
                    left: int, top: int, right: int, bottom: int) -> int:
    """Blend the round-joined, round-capped stroke of ``segments (M, 4)`` (``ax, ay, bx, by`` in device
    pixels, finite; bounds far off the box are held to it) with half-width ``radius`` (> 0) in premultiplied ``color (4,)`` (0..255,
    the pixels' channel order, alpha last) over ``pixels (H, W, 4)`` uint8 premultiplied, source-over,
    inside the box ``[left, right) × [top, bottom)`` (within the pixels). Returns the number of pixels
    touched.

    Row by row (each row's work stays in cache): the segments whose capsules reach the row are kept
    active; each visits the row's pixels inside its box and the slab along it and, in those within
    ``reach = r + √½`` of it, leaves ``gain = reach² - d²`` of the nearest segment so far and of the
    nearest one whose nearest point lies inside it, not at an end (a vertex's disc lies in both its
    segments' capsules, so only such a segment can add an edge of its own); then the row's touched
    pixels are blended.
    """
    m = segments.shape[0]
    if m == 0 or right <= left or bottom <= top:
        return 0
    reach = radius + _HALF_DIAGONAL
    far = reach * reach
    inverse = np.empty(m)
    constants = np.empty((m, 4))  # x0, x1 of the box; ex / ey and reach · |e| / |ey| of the slab (-1: none)
    firsts = np.empty(m, np.int64)
    lasts = np.empty(m, np.int64)
    for s in range(m):
        ax, ay, bx, by = segments[s, 0], segments[s, 1], segments[s, 2], segments[s, 3]
        ex, ey = bx - ax, by - ay
        length2 = ex * ex + ey * ey
        constants[s, 0] = min(ax, bx) - reach
        constants[s, 1] = max(ax, bx) + reach
        if abs(ey) >= 1e-6:  # below that the box is a few rows high anyway, and ex / ey may overflow
            constants[s, 2] = ex / ey
            constants[s, 3] = reach * math.sqrt(length2) / abs(ey)
        else:
            constants[s, 2] = 0.0
            constants[s, 3] = -1.0
        inverse[s] = 1.0 / length2 if length2 > 0.0 else 0.0
        firsts[s] = max(top, int(math.ceil(_within(min(ay, by) - reach - 0.5, top, bottom))))
        lasts[s] = min(bottom - 1, int(math.floor(_within(max(ay, by) + reach - 0.5, top, bottom))))
    order = np.argsort(firsts, kind="mergesort")
    width = pixels.shape[1]
    gain = np.zeros((width, 2))
    vector = np.empty((width, 2))  # from the nearest segment's nearest point to the pixel's centre
    owner = np.zeros((width, 2), np.int64)
    touched = np.empty(width, np.int64)
    active = np.empty(m, np.int64)
    n_active = 0
    upcoming = 0
    while upcoming < m and firsts[order[upcoming]] > lasts[order[upcoming]]:
        upcoming += 1  # reaches no row of the box (sorted first: their first row is the box's top)
    alpha = color[3] / 255.0
    solid = color[3] >= 255.0
    corner = np.empty((2, 8, 2))  # the clipping's two polygon buffers
    # a centre within r - √½ of a segment: the pixel lies wholly inside its capsule
    inside = far - (radius - _HALF_DIAGONAL) ** 2 if radius > _HALF_DIAGONAL else np.inf
    total = 0
    y = firsts[order[upcoming]] if upcoming < m else bottom
    while y < bottom and (n_active > 0 or upcoming < m):
        while upcoming < m and firsts[order[upcoming]] <= y:
            s = order[upcoming]
            upcoming += 1
            if lasts[s] >= firsts[s]:
                active[n_active] = s
                n_active += 1
        kept = 0
        for i in range(n_active):
            if lasts[active[i]] >= y:
                active[kept] = active[i]
                kept += 1
        n_active = kept
        if n_active == 0:
            if upcoming < m:
                y = firsts[order[upcoming]]
                continue
            break
        yc = y + 0.5
        count = 0
        for i in range(n_active):
            s = active[i]
            ax, ay = segments[s, 0], segments[s, 1]
            ex, ey = segments[s, 2] - ax, segments[s, 3] - ay
            inv = inverse[s]
            low, high = constants[s, 0], constants[s, 1]
            if constants[s, 3] >= 0.0:  # the slab |(p - a) × e| <= reach |e| crosses the row here
                centre = ax + (yc - ay) * constants[s, 2]
                low, high = max(low, centre - constants[s, 3]), min(high, centre + constants[s, 3])
                if low > high:
                    continue
            start = max(left, int(math.ceil(_within(low - 0.5, left, right))))
            stop = min(right - 1, int(math.floor(_within(high - 0.5, left, right))))
            dy = yc - ay
            along_y = dy * ey
            for x in range(start, stop + 1):
                dx = x + 0.5 - ax
                along = (dx * ex + along_y) * inv
                t = min(1.0, max(0.0, along))
                px, py = dx - t * ex, dy - t * ey
                g = far - (px * px + py * py)
                if g <= 0.0:
                    continue
                nearest = gain[x, 0]
                if g > nearest:
                    if nearest == 0.0:
                        touched[count] = x
                        count += 1
                    elif owner[x, 0] & 1 and nearest > gain[x, 1]:
                        gain[x, 1], owner[x, 1] = nearest, owner[x, 0] >> 1
                    gain[x, 0], owner[x, 0] = g, 2 * s + (t == along)
                    vector[x, 0], vector[x, 1] = px, py
                elif g > gain[x, 1] and t == along:
                    gain[x, 1], owner[x, 1] = g, s
        total += count
        for i in range(count):
            x = touched[i]
            nearest, second = gain[x, 0], gain[x, 1]
            gain[x, 0] = gain[x, 1] = 0.0
            s = owner[x, 0] >> 1
            cx = x + 0.5
            if nearest >= inside:
                c = 1.0
            else:
                px, py = vector[x, 0], vector[x, 1]
                d2 = px * px + py * py
                if d2 == 0.0:
                    u, nx, ny = radius, 1.0, 0.0
                else:
                    d = math.sqrt(d2)
                    inv = 1.0 / d
                    u, nx, ny = radius - d, px * inv, py * inv
                c = coverage(u, nx, ny)
            if c < 1.0 and second > 0.0:  # a second edge within r + √½ of the centre
                other = owner[x, 1]
                u2, mx, my = _edge(segments, inverse, other, cx, yc, radius, _shared_end(segments, s, other))
                c2 = coverage(u2, mx, my)
                if c2 >= 1.0 or c == 0.0:
                    c = max(c, c2)
                elif c2 > 0.0:
                    c = min(1.0, c + c2 - _both(u, nx, ny, u2, mx, my, corner))
            if c >= 1.0 and solid:
                for ch in range(4):
                    pixels[y, x, ch] = np.uint8(color[ch])
            elif c > 0.0:
                keep = 1.0 - alpha * c
                for ch in range(4):
                    pixels[y, x, ch] = min(255, int(color[ch] * c + pixels[y, x, ch] * keep + 0.5))
        y += 1
    return total
