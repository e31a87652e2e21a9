"""SMIL pieces of an animated SVG: numbers, colours and ``<animate>`` elements at clip frames."""

from __future__ import annotations

from xml.sax.saxutils import quoteattr

import numpy as np

from .vector_data import PIXEL_DIGITS, STRAIGHT, Array, Handles

__all__ = ["number", "hex_colour", "path_data", "straight_spans", "clip_timing", "animate"]


def number(value: float, digits: int = 3) -> str:
    """``value`` with at most ``digits`` decimals, no trailing zeros."""
    text = f"{value:.{digits}f}".rstrip("0").rstrip(".")
    return "0" if text in ("", "-0") else text


def hex_colour(rgb: Array | tuple[float, float, float]) -> str:
    """``#rrggbb`` of an RGB in [0, 1]."""
    return "#" + "".join(f"{int(round(float(v) * 255)):02x}" for v in rgb)


def clip_timing(seconds: float, loop: bool) -> str:
    """The timing attributes of every animation of a clip ``seconds`` long: played once and held at its end,
    or (``loop``) repeated for ever."""
    return f'dur="{number(seconds, 6)}s" ' + ('repeatCount="indefinite"' if loop else 'fill="freeze"')


def animate(name: str, frames: tuple[int, ...], values: list[str], total: int, timing: str,
            eases: tuple[Handles, ...] = (), transform: str | None = None, additive: bool = False) -> str:
    """An ``<animate>`` of ``name`` through ``values`` at clip ``frames`` of ``total``, over the clip's
    ``timing`` attributes (:func:`clip_timing`), each span timed by its ``eases``
    (none: straight), held before the first and after the last (keyTimes run from 0 to 1); ``""`` when the
    value never changes. ``transform``: an
    ``<animateTransform>`` of that type instead (always written), ``additive``: added to the transforms
    before it."""
    if transform is None and all(v == values[0] for v in values[1:]):
        return ""
    times = [f / total for f in frames]
    splines = list(eases) or [STRAIGHT] * (len(frames) - 1)
    held = STRAIGHT
    if frames[0] > 0:
        times, values, splines = [0.0, *times], [values[0], *values], [held, *splines]
    times, values, splines = [*times, 1.0], [*values, values[-1]], [*splines, held]
    spline = "" if all(s == STRAIGHT for s in splines) else ' calcMode="spline" keySplines="' + ";".join(
        " ".join(number(v, 6) for v in s) for s in splines) + '"'
    tag = "animate" if transform is None else f'animateTransform type="{transform}"'
    return (f'<{tag} attributeName="{name}" {timing} '
            + ('additive="sum" ' if additive else "")
            + f'keyTimes="{";".join(number(t, 9) for t in times)}" values={quoteattr(";".join(values))}{spline}/>')


def path_data(paths: list[Array], closed: tuple[bool, ...], lines: list[Array] | None = None) -> str:
    """One path's ``d``: ``M x,y L x,y … Z`` per contour of straight edges (``(L, 2)`` pixels), ``M x,y C
    x,y x,y x,y … Z`` per cubic Bézier contour (``(M, 3, 2)``: in control point, vertex, out control point),
    an ``L`` for each span ``lines`` (one ``(M,)`` bool per contour, by the vertex it leaves) marks straight."""
    parts = []
    for index, (points, shut) in enumerate(zip(paths, closed)):
        if points.ndim == 3:
            parts.append(_curve_data(points, shut, None if lines is None else lines[index]))
            continue
        coords = [f"{number(x, PIXEL_DIGITS)},{number(y, PIXEL_DIGITS)}" for x, y in points.tolist()]
        parts.append("M" + coords[0] + " L" + " ".join(coords[1:]) + (" Z" if shut else ""))
    return " ".join(parts)


def straight_spans(curves: Array) -> Array:
    """Which spans of cubic Bézier contours ``(K, M, 3, 2)`` are straight at every keyframe (both control
    points on their ends), by the vertex each leaves: ``(M,)``."""
    leaving = np.all(curves[:, :, 2] == curves[:, :, 1], axis=(0, 2))
    arriving = np.all(curves[:, :, 0] == curves[:, :, 1], axis=(0, 2))
    return leaving & np.roll(arriving, -1)


def _curve_data(points: Array, closed: bool, lines: Array | None) -> str:
    """``M`` and one ``C`` (``L`` where ``lines (M,)`` says so) per span of a cubic Bézier contour ``(M, 3, 2)``
    (closed: back to its first vertex), the points written to :data:`PIXEL_DIGITS` decimals."""
    def pair(xy: Array) -> str:
        return f"{number(float(xy[0]), PIXEL_DIGITS)},{number(float(xy[1]), PIXEL_DIGITS)}"

    count = len(points)
    spans = [(k, k + 1) for k in range(count - 1)] + ([(count - 1, 0)] if closed and count > 1 else [])
    text = "M" + pair(points[0, 1])
    for a, b in spans:
        if lines is not None and lines[a]:
            text += " L" + pair(points[b, 1])
        else:
            text += " C" + pair(points[a, 2]) + " " + pair(points[b, 0]) + " " + pair(points[b, 1])
    return text + (" Z" if closed else "")
