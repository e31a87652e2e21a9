"""Paint between keys (maths §5.8): colours in OKLab with alpha premultiplied (a gradient's stops each on
its own, straight), widths and opacity linearly.

OKLab is Björn Ottosson's perceptual colour space (2020): straight lines in it
look like even blends, so red → blue passes through purple, not a dark muddy
violet as sRGB does. A missing colour (``None``: no fill, no stroke) blends as
the other key's colour at alpha 0, so a fill fades in or out in its own hue.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..model import Color, Paint
from .dashes import blend_dashes

__all__ = ["srgb_to_oklab", "oklab_to_srgb", "blend_colors", "blend_stop_colours", "blend_paints"]

Array = NDArray[np.float64]

# Ottosson's matrices: linear sRGB → LMS, then cube-rooted LMS → Lab, and their inverses.
_M1 = np.array([[0.4122214708, 0.5363325363, 0.0514459929],
                [0.2119034982, 0.6806995451, 0.1073969566],
                [0.0883024619, 0.2817188376, 0.6299787005]])
_M2 = np.array([[0.2104542553, 0.7936177850, -0.0040720468],
                [1.9779984951, -2.4285922050, 0.4505937099],
                [0.0259040371, 0.7827717662, -0.8086757660]])
_M1_INV = np.linalg.inv(_M1)
_M2_INV = np.linalg.inv(_M2)


def _to_linear(c: Array) -> Array:
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def _to_gamma(c: Array) -> Array:
    c = np.clip(c, 0.0, 1.0)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1 / 2.4) - 0.055)


def srgb_to_oklab(rgb: ArrayLike) -> Array:
    """sRGB in [0, 1], ``(..., 3)`` → OKLab ``(..., 3)`` (L in [0, 1])."""
    lms = _to_linear(np.asarray(rgb, dtype=np.float64)) @ _M1.T
    return np.cbrt(lms) @ _M2.T


def oklab_to_srgb(lab: ArrayLike) -> Array:
    """OKLab ``(..., 3)`` → sRGB in [0, 1] ``(..., 3)``, clipped to the gamut."""
    lms = (np.asarray(lab, dtype=np.float64) @ _M2_INV.T) ** 3
    return _to_gamma(lms @ _M1_INV.T)


def blend_colors(c0: Color | None, c1: Color | None, t: ArrayLike) -> list[Color | None]:
    """``c0 → c1`` at each of ``t (T,)``: OKLab premultiplied by alpha; ``None`` is ``c1``/``c0`` at alpha 0."""
    t = np.atleast_1d(np.asarray(t, dtype=np.float64))
    if c0 is None and c1 is None:
        return [None] * len(t)
    if c0 == c1:
        return [c0] * len(t)
    a = c1 if c0 is None else c0
    b = c0 if c1 is None else c1
    rgba0 = np.array(a, dtype=np.float64) / 255.0
    rgba1 = np.array(b, dtype=np.float64) / 255.0
    if c0 is None:
        rgba0[3] = 0.0
    if c1 is None:
        rgba1[3] = 0.0
    lab = srgb_to_oklab(np.stack([rgba0[:3], rgba1[:3]]))
    alpha = (1.0 - t) * rgba0[3] + t * rgba1[3]  # (T,)
    premultiplied = (1.0 - t)[:, None] * lab[0] * rgba0[3] + t[:, None] * lab[1] * rgba1[3]  # (T, 3)
    # where alpha is 0 nothing shows: take the plain blend there rather than divide by 0
    plain = (1.0 - t)[:, None] * lab[0] + t[:, None] * lab[1]
    with np.errstate(divide="ignore", invalid="ignore"):
        straight = np.where(alpha[:, None] > 0, premultiplied / alpha[:, None], plain)
    rgb = np.rint(oklab_to_srgb(straight) * 255.0).astype(int)
    alphas = np.rint(alpha * 255.0).astype(int)
    out: list[Color | None] = [(int(r), int(g), int(b_), int(al)) for (r, g, b_), al in zip(rgb, alphas)]
    return [c0 if x == 0.0 else c1 if x == 1.0 else o for x, o in zip(t.tolist(), out)]  # the keys, exactly


def blend_stop_colours(c0: NDArray[np.int64], c1: NDArray[np.int64], t: float) -> list[Color]:
    """Each pair of a gradient's straight RGBA stops ``c0[i] → c1[i]`` (``(S, 4)``, 0 to 255) at one ``t``:
    ``(S,)`` colours, the colour in OKLab and alpha linearly, each blended on its own (not premultiplied).
    A gradient draws the ramp between two stops from their straight colours, so a transparent stop's colour
    shows in its neighbour's ramp: blended premultiplied, a stop turning transparent kept its first colour
    until the key and jumped there in the last frame."""
    c0, c1 = np.asarray(c0, dtype=np.int64), np.asarray(c1, dtype=np.int64)
    if t == 0.0 or t == 1.0:
        return [tuple(int(v) for v in row) for row in (c0 if t == 0.0 else c1)]  # type: ignore[misc]
    rgba0, rgba1 = c0 / 255.0, c1 / 255.0
    lab = (1.0 - t) * srgb_to_oklab(rgba0[:, :3]) + t * srgb_to_oklab(rgba1[:, :3])
    alpha = (1.0 - t) * rgba0[:, 3] + t * rgba1[:, 3]  # (S,)
    rows = np.column_stack([np.rint(oklab_to_srgb(lab) * 255.0), np.rint(alpha * 255.0)]).astype(np.int64)
    rows = np.where(np.all(c0 == c1, axis=1)[:, None], c0, rows)  # equal colours stay exactly
    return [tuple(int(v) for v in row) for row in rows]  # type: ignore[misc]


def blend_paints(p0: Paint, p1: Paint, t: ArrayLike) -> list[Paint]:
    """The paint at each of ``t (T,)`` (already eased) between keys painted ``p0`` and ``p1``.

    A stroke that only one key has keeps that key's width while it fades; dash patterns blend as
    :func:`.dashes.blend_dashes` says.
    """
    t = np.atleast_1d(np.asarray(t, dtype=np.float64))
    if p0 == p1:
        return [p0] * len(t)
    fills = blend_colors(p0.fill, p1.fill, t)
    strokes = blend_colors(p0.stroke, p1.stroke, t)
    w0 = p0.stroke_width if p0.stroke is not None else p1.stroke_width
    w1 = p1.stroke_width if p1.stroke is not None else p0.stroke_width
    widths = (1.0 - t) * w0 + t * w1
    opacity = (1.0 - t) * p0.opacity + t * p1.opacity
    dashes = blend_dashes(p0.dash, p1.dash, t)
    blended = [Paint(f, s, float(w), float(o), dash=d)
               for f, s, w, o, d in zip(fills, strokes, widths, opacity, dashes)]
    return [p0 if x == 0.0 else p1 if x == 1.0 else b for x, b in zip(t.tolist(), blended)]
