"""The ``check --json`` report: the scene as loaded, in world units."""

from __future__ import annotations

from typing import Any, Sequence

from ..model import Color, Key, Paint, Scene, Shape

__all__ = ["scene_dict"]


def scene_dict(scene: Scene, view: Sequence[float]) -> dict[str, Any]:
    """The scene as loaded, for ``check --json``: points in world units.

    Every key has ``points`` (its first contour); a shape with several contours in a key,
    or with open ones, has ``contours`` (lists of points) and ``closed`` on each key as well.
    """
    return {
        "scene": str(scene.path) if scene.path else None,
        "title": scene.title,
        "size": list(scene.size),
        "fps": scene.fps,
        "background": _hex(scene.background),
        "view": list(view),
        "method": scene.method,
        "compare": list(scene.compare),
        "balance": scene.balance,
        "unmatched": scene.unmatched,
        "shapes": [_shape(scene, shape) for shape in scene.shapes],
    }


def _shape(scene: Scene, shape: Shape) -> dict[str, Any]:
    several = any(len(key.contours) > 1 or not all(c.closed for c in key.contours) for key in shape.keys)
    return {
        "name": shape.name,
        "method": scene.method_of(shape),
        "balance": scene.balance_of(shape),
        "joints": [list(j) for j in shape.joints],
        "fill_rule": shape.fill_rule,
        "cap": shape.cap,
        "join": shape.join,
        "stroke_units": "world" if shape.stroke_scales else "pixels",
        "keys": [_key(key, several) for key in shape.keys],
    }


def _key(key: Key, several: bool) -> dict[str, Any]:
    out: dict[str, Any] = {"time": key.time, "ease": key.ease, "points": key.points.tolist()}
    if several:
        out["contours"] = [c.points.tolist() for c in key.contours]
        out["closed"] = [c.closed for c in key.contours]
    ticks = getattr(key.easing, "ticks", None)
    if ticks is not None:
        out["spacing"] = list(ticks)
    if key.hints:
        out["hints"] = {h.letter: key.contours[h.contour].points[h.vertex].tolist() for h in key.hints}
    if key.delay:
        out["delay"] = key.delay
    if key.turn is not None:
        out["turn"] = key.turn
    if key.turns:
        out["turns"] = key.turns
    if key.arcs:
        out["arcs"] = {letter: list(point) for letter, point in key.arcs}
    if key.breakdown is not None:
        out["breakdown"] = key.breakdown
    out.update(_paint(key.paint))
    if key.hidden:
        out["hidden"] = True
    return out


def _paint(paint: Paint) -> dict[str, Any]:
    return {"fill": _hex(paint.fill), "stroke": _hex(paint.stroke), "stroke_width": paint.stroke_width,
            "opacity": paint.opacity}


def _hex(color: Color | None) -> str | None:
    if color is None:
        return None
    return "#" + "".join(f"{v:02x}" for v in color)
