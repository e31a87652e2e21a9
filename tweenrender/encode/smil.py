"""SMIL pieces of an animated SVG: numbers, colours and ``<animate>`` elements at clip frames."""

from __future__ import annotations

from xml.sax.saxutils import quoteattr

import numpy as np

from .vector_data import HANDLE_DIGITS, PIXEL_DIGITS, STRAIGHT, Array, Handles

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
        " ".join(number(v, HANDLE_DIGITS) for v in s) for s in splines) + '"'
    tag = "animate" if transform is None else f'animateTransform type="{transform}"'
    return (f'<{tag} attributeName="{name}" {timing} '
            + ('additive="sum" ' if additive else "")
            + f'keyTimes="{";".join(number(t, 9) for t in times)}" values={quoteattr(";".join(values))}{spline}/>')


def path_data(paths: list[Array], closed: tuple[bool, ...], lines: list[Array] | None = None) -> str:
    """One path's ``d``, short: per contour an absolute ``M`` then ``l`` per straight edge (``(L, 2)`` pixels),
    or ``c`` per span of a cubic Bézier contour (``(M, 3, 2)``: in control point, vertex, out control point;
    ``l`` for each span ``lines``, one ``(M,)`` bool per contour by the vertex it leaves, marks straight),
    ``z`` where closed. Points are rounded to :data:`PIXEL_DIGITS` decimals first and each relative step is
    the difference of rounded points, so the path is the rounded absolute one, with no error summed along
    it; a command is not repeated, numbers drop their leading zero and a minus sign parts them."""
    parts = []
    for index, (points, shut) in enumerate(zip(paths, closed)):
        if points.ndim == 3:
            parts.append(_curve_data(points, shut, None if lines is None else lines[index]))
            continue
        rounded = _rounded(points)
        steps = np.diff(rounded, axis=0)
        parts.append("M" + _numbers(rounded[0]) + ("l" + _numbers(steps.ravel()) if len(steps) else "")
                     + ("z" if shut else ""))
    return "".join(parts)


def _rounded(points: Array) -> Array:
    """``points`` rounded as they are written (:data:`PIXEL_DIGITS` decimals)."""
    return np.round(np.asarray(points, dtype=np.float64), PIXEL_DIGITS)


def _numbers(values: Array) -> str:
    """Numbers of path data, as short as SVG's grammar reads them: no leading zero, a space between two
    but where a minus sign parts them."""
    out = []
    for value in np.asarray(values, dtype=np.float64).ravel().tolist():
        text = number(value, PIXEL_DIGITS)
        if text.startswith("0."):
            text = text[1:]
        elif text.startswith("-0."):
            text = "-" + text[2:]
        if out and not text.startswith("-"):
            out.append(" ")
        out.append(text)
    return "".join(out)


def straight_spans(curves: Array) -> Array:
    """Which spans of cubic Bézier contours ``(K, M, 3, 2)`` are straight at every keyframe (both control
    points on their ends), by the vertex each leaves: ``(M,)``."""
    leaving = np.all(curves[:, :, 2] == curves[:, :, 1], axis=(0, 2))
    arriving = np.all(curves[:, :, 0] == curves[:, :, 1], axis=(0, 2))
    return leaving & np.roll(arriving, -1)


def _curve_data(points: Array, closed: bool, lines: Array | None) -> str:
    """``M``, then ``c`` (``l`` where ``lines (M,)`` says so) per span of a cubic Bézier contour ``(M, 3, 2)``
    (closed: back to its first vertex), relative to the rounded pen (:func:`path_data`)."""
    rounded = _rounded(points)
    count = len(points)
    spans = [(k, k + 1) for k in range(count - 1)] + ([(count - 1, 0)] if closed and count > 1 else [])
    text, command = "M" + _numbers(rounded[0, 1]), ""
    for a, b in spans:
        pen = rounded[a, 1]
        straight = lines is not None and bool(lines[a])
        letter = "l" if straight else "c"
        values = rounded[b, 1] - pen if straight else np.concatenate(
            [rounded[a, 2] - pen, rounded[b, 0] - pen, rounded[b, 1] - pen])
        text += (letter if letter != command else " ") + _numbers(values)
        command = letter
    return text + ("z" if closed else "")
