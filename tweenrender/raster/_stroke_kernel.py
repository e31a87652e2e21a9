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
(the pixel inside both edges, in closed form: ``_both``).

The work goes row by row, so that a row's scratch stays in the cache: each
segment whose capsule (the points within ``r + √½``, beyond which a pixel is not
covered at all) reaches the row visits the row's pixels inside the capsule's
box and the slab along it, and keeps in each the two nearest segments' gains and
the offsets from their nearest points; then the row's touched pixels are blended
once, source-over.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..core.jit import cached_jit as _jit

__all__ = ["coverage", "polyline_segments", "stroke_polylines", "stroke_segments"]

_HALF_DIAGONAL = 0.7072
"""A pixel whose centre lies farther than ``r + √½`` from every segment is not covered at all."""

_inline = njit(inline="always", error_model="numpy")

_GAIN, _INTERIOR, _X, _Y, _GAIN_2, _X_2, _Y_2 = range(7)
"""A row's scratch per pixel: the nearest segment's gain, whether its nearest point lies inside it (1.0)
and the offset from that point to the centre; the nearest interior one's gain and offset."""
_FIELDS = 8
"""Seven fields used; eight make a pixel's scratch one 64-byte cache line."""


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
def _edge(px: float, py: float, radius: float) -> tuple[float, float, float]:
    """``(u, nx, ny)``: how far a centre lying ``(px, py)`` from a segment's nearest point is inside its
    capsule of half-width ``radius``, and the unit normal of the capsule's edge nearest to it (out)."""
    d2 = px * px + py * py
    if d2 == 0.0:
        return radius, 1.0, 0.0
    d = math.sqrt(d2)
    inv = 1.0 / d
    return radius - d, px * inv, py * inv


@_inline
def _span(low: float, high: float, slope: float, limit: float, strict: bool) -> tuple[float, float]:
    """``[low, high]`` cut to the ``t`` with ``slope · t ≤ limit`` (empty: ``high < low``); where the slope
    is 0 the whole span stays or goes, ``strict`` dropping it when ``limit`` is exactly 0 too."""
    bound = limit / slope
    high = min(high, bound) if slope > 0.0 else high
    low = max(low, bound) if slope < 0.0 else low
    return low, (-np.inf if (slope == 0.0 and (limit < 0.0 or (strict and limit == 0.0))) else high)


@_inline
def _side_inside(s1: float, l1: float, s2: float, l2: float, out1: bool, out2: bool) -> float:
    """Length of a side of the unit pixel, ``t`` in ``[-½, ½]``, where ``s1 · t ≤ l1`` and ``s2 · t ≤ l2``; a side
    lying on edge line k is left to that line where both face the same way (``out_k``: its ``u > 0``)."""
    low, high = _span(-0.5, 0.5, s1, l1, out1)
    low, high = _span(low, high, s2, l2, out2)
    return max(0.0, high - low)


@_inline
def _line_inside(u: float, nx: float, ny: float, slope: float, limit: float, strict: bool) -> float:
    """Length of the line ``n · w = u`` inside the unit pixel (centred at 0) and ``slope · λ ≤ limit``,
    ``λ`` running along ``(-ny, nx)`` from ``u n``."""
    low, high = _span(-2.0, 2.0, -ny, 0.5 - u * nx, False)
    low, high = _span(low, high, ny, 0.5 + u * nx, False)
    low, high = _span(low, high, nx, 0.5 - u * ny, False)
    low, high = _span(low, high, -nx, 0.5 + u * ny, False)
    low, high = _span(low, high, slope, limit, strict)
    return max(0.0, high - low)


@_inline
def _both(u1: float, n1x: float, n1y: float, u2: float, n2x: float, n2y: float) -> float:
    """Area of the unit pixel (centred at 0) inside both ``n1 · w ≤ u1`` and ``n2 · w ≤ u2``.

    A convex region's area is half the sum over its edges of each edge's length times its line's
    distance from the origin: ¼ for the pixel's own sides, ``u`` for each edge line's part (Green's
    theorem). Where two parts of the boundary lie on one line, facing the same way, one of them counts
    (facing opposite ways, they cancel): a side on an edge line is that line's, and one line the first's."""
    out1, out2 = u1 > 0.0, u2 > 0.0
    sides = (_side_inside(n1x, u1 + 0.5 * n1y, n2x, u2 + 0.5 * n2y, out1, out2)
             + _side_inside(n1x, u1 - 0.5 * n1y, n2x, u2 - 0.5 * n2y, out1, out2)
             + _side_inside(n1y, u1 + 0.5 * n1x, n2y, u2 + 0.5 * n2x, out1, out2)
             + _side_inside(n1y, u1 - 0.5 * n1x, n2y, u2 - 0.5 * n2x, out1, out2))
    cross = n1x * n2y - n1y * n2x
    cosine = n1x * n2x + n1y * n2y
    first = _line_inside(u1, n1x, n1y, cross, u2 - u1 * cosine, False)
    second = _line_inside(u2, n2x, n2y, -cross, u1 - u2 * cosine, cosine > 0.0)
    return 0.25 * sides + 0.5 * (u1 * first + u2 * second)


@_jit
def polyline_segments(points: np.ndarray, counts: np.ndarray, closed: np.ndarray, scale: float, dx: float,
                      dy: float) -> np.ndarray:
    """The segments ``(M, 4)`` (``ax, ay, bx, by``) of contours laid end to end in ``points (N, 2)``,
    ``counts[k]`` vertices each (contours of fewer than 2 are skipped), closed or open, each vertex taken to
    ``scale · p + (dx, dy)``; a segment that this takes past float range is left out (it is off any canvas)."""
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
                if (math.isfinite(segments[row, 0]) and math.isfinite(segments[row, 1])
                        and math.isfinite(segments[row, 2]) and math.isfinite(segments[row, 3])):
                    row += 1
        start += n
    return segments[:row]


@_jit
def stroke_polylines(pixels: np.ndarray, points: np.ndarray, counts: np.ndarray, closed: np.ndarray, scale: float,
                     dx: float, dy: float, radius: float, color: np.ndarray, left: int, top: int, right: int,
                     bottom: int) -> int:
    """``stroke_segments`` of ``polyline_segments(points, counts, closed, scale, dx, dy)``, in one call (a
    detailed scene strokes each of its shapes apart, and each call from Python costs some microseconds)."""
    segments = polyline_segments(points, counts, closed, scale, dx, dy)
    return stroke_segments(pixels, segments, radius, color, left, top, right, bottom)


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
    # each pixel's nearest segment so far (gain, whether its nearest point lies inside it, the offset
    # from that point to the centre) and the nearest one whose nearest point lies inside it (gain, offset)
    state = np.zeros((width, _FIELDS))
    touched = np.empty(width, np.int64)
    active = np.empty(m, np.int64)
    n_active = 0
    upcoming = 0
    while upcoming < m and firsts[order[upcoming]] > lasts[order[upcoming]]:
        upcoming += 1  # reaches no row of the box (sorted first: their first row is the box's top)
    alpha = color[3] / 255.0
    solid = color[3] >= 255.0
    # a centre within r - √½ of a segment: the pixel lies wholly inside its capsule
    inside = far - (radius - _HALF_DIAGONAL) ** 2 if radius > _HALF_DIAGONAL else np.inf
    total = 0
    warm = 0
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
                interior = 0.0 < along < 1.0
                nearest = state[x, _GAIN]
                if g > nearest:
                    if nearest == 0.0:
                        touched[count] = x
                        count += 1
                    elif state[x, _INTERIOR] != 0.0 and nearest > state[x, _GAIN_2]:
                        state[x, _GAIN_2] = nearest
                        state[x, _X_2], state[x, _Y_2] = state[x, _X], state[x, _Y]
                    state[x, _GAIN], state[x, _INTERIOR] = g, 1.0 if interior else 0.0
                    state[x, _X], state[x, _Y] = px, py
                elif interior and g > state[x, _GAIN_2]:
                    state[x, _GAIN_2], state[x, _X_2], state[x, _Y_2] = g, px, py
        total += count
        for i in range(count):  # the row's pixels read at once, their cache misses overlapping
            warm += pixels[y, touched[i], 3]
        for i in range(count):
            x = touched[i]
            nearest, second = state[x, _GAIN], state[x, _GAIN_2]
            state[x, _GAIN] = state[x, _GAIN_2] = 0.0
            if nearest >= inside:
                c = 1.0
            else:
                u, nx, ny = _edge(state[x, _X], state[x, _Y], radius)
                c = coverage(u, nx, ny)
            if c < 1.0 and second > 0.0:  # a second edge within r + √½ of the centre
                u2, mx, my = _edge(state[x, _X_2], state[x, _Y_2], radius)
                c2 = coverage(u2, mx, my)
                if c2 >= 1.0 or c == 0.0:
                    c = max(c, c2)
                elif c2 > 0.0:
                    c = min(1.0, c + c2 - _both(u, nx, ny, u2, mx, my))
            if c >= 1.0 and solid:
                for ch in range(4):
                    pixels[y, x, ch] = np.uint8(color[ch])
            elif c > 0.0:
                keep = 1.0 - alpha * c
                for ch in range(4):
                    pixels[y, x, ch] = min(255, int(color[ch] * c + pixels[y, x, ch] * keep + 0.5))
        y += 1
    return total + (warm < 0)  # warm is never negative: its loop is kept, not folded away
