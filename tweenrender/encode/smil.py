"""SMIL pieces of an animated SVG: numbers, colours and ``<animate>`` elements at clip frames."""

from __future__ import annotations

from xml.sax.saxutils import quoteattr

from .vector_data import STRAIGHT, Array, Handles

__all__ = ["number", "hex_colour", "path_data", "animate"]


def number(value: float, digits: int = 3) -> str:
    """``value`` with at most ``digits`` decimals, no trailing zeros."""
    text = f"{value:.{digits}f}".rstrip("0").rstrip(".")
    return "0" if text in ("", "-0") else text


def hex_colour(rgb: Array | tuple[float, float, float]) -> str:
    """``#rrggbb`` of an RGB in [0, 1]."""
    return "#" + "".join(f"{int(round(float(v) * 255)):02x}" for v in rgb)


def animate(name: str, frames: tuple[int, ...], values: list[str], total: int, duration: str,
            eases: tuple[Handles, ...] = (), transform: str | None = None, additive: bool = False) -> str:
    """An ``<animate>`` of ``name`` through ``values`` at clip ``frames``, each span timed by its ``eases``
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
    return (f'<{tag} attributeName="{name}" dur="{duration}" fill="freeze" '
            + ('additive="sum" ' if additive else "")
            + f'keyTimes="{";".join(number(t, 9) for t in times)}" values={quoteattr(";".join(values))}{spline}/>')


def path_data(paths: list[Array], closed: tuple[bool, ...]) -> str:
    """One path's ``d``: ``M x,y L x,y … Z`` per contour (``(L, 2)`` pixels each)."""
    parts = []
    for points, shut in zip(paths, closed):
        coords = [f"{number(x)},{number(y)}" for x, y in points.tolist()]
        parts.append("M" + coords[0] + " L" + " ".join(coords[1:]) + (" Z" if shut else ""))
    return " ".join(parts)
