"""A shape layer's items as lottie-web draws them: every paint item (fill ``fl``, stroke ``st``, gradient
fill ``gf``) draws the paths listed before it in its group and in the groups listed before it there,
each through its groups' transforms; an item listed later is drawn below. A stroke listed right above
a fill of the same paths is drawn with it, as one element.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..model import Color, Gradient
from .lottie_geometry import PathItem, Transform
from .lottie_props import Array, Malformed, Prop, Unreadable
from .scene_limits import LIMITS

__all__ = ["PaintItem", "Element", "layer_elements", "gradient_at"]

_REFUSED = {"gs": "a gradient stroke", "tm": "trim paths", "rp": "a repeater", "rd": "rounded corners",
            "mm": "merged paths", "op": "offset paths", "pb": "pucker and bloat", "tw": "a twist",
            "zz": "zig-zag", "sr": "a star or polygon"}
CAPS = {1: "butt", 2: "round", 3: "square"}
JOINS = {1: "miter", 2: "round", 3: "bevel"}


class PaintItem:
    """A fill, stroke or gradient fill: its props and :meth:`paint` parts at a frame."""

    def __init__(self, raw: dict[str, Any]) -> None:
        self.kind = raw["ty"]
        self.name = str(raw.get("nm", self.kind))
        self.opacity = Prop(raw.get("o"), "a paint's opacity", [100])
        self.fill_rule = "evenodd" if raw.get("r") == 2 else "nonzero"
        props = [self.opacity]
        if self.kind in ("fl", "st"):
            self.colour = Prop(raw.get("c"), "a colour", [0, 0, 0, 1])
            props.append(self.colour)
        if self.kind == "st":
            if raw.get("d"):
                raise Unreadable("a dashed stroke")
            self.width = Prop(raw.get("w"), "a stroke width", [1])
            props.append(self.width)
            self.cap = CAPS.get(raw.get("lc", 2), "round")
            self.join = JOINS.get(raw.get("lj", 2), "round")
            self.miter = float(raw.get("ml", 4) or 4)
        if self.kind == "gf":
            self.linear = raw.get("t", 1) == 1
            self.start = Prop(raw.get("s"), "a gradient's start", [0, 0])
            self.end = Prop(raw.get("e"), "a gradient's end", [0, 0])
            self.highlight = Prop(raw.get("h"), "a gradient's highlight", [0])
            self.angle = Prop(raw.get("a"), "a gradient's angle", [0])
            stops = raw.get("g")
            if not isinstance(stops, dict) or "k" not in stops:
                raise Malformed("expected gradient stops g = {p, k}")
            self.count = int(stops.get("p", 0))
            if self.count < 1:
                raise Malformed(f"expected at least one gradient stop, found p = {stops.get('p')!r}")
            if self.count > LIMITS["gradient_stops"]:
                raise Malformed(f"expected at most {LIMITS['gradient_stops']} gradient stops, found p = {self.count}")
            self.stops = Prop(stops["k"], "gradient stops")
            props += [self.start, self.end, self.highlight, self.angle, self.stops]
        self.animated = any(p.animated for p in props)

    def colour_at(self, frame: float) -> Color:
        """The straight RGBA colour at ``frame`` (alpha from the item's opacity)."""
        rgb = np.clip(np.resize(self.colour.at(frame), 3), 0.0, 1.0)
        alpha = np.clip(float(self.opacity.at(frame)[0]) / 100.0, 0.0, 1.0)
        return tuple(int(round(float(v) * 255)) for v in (*rgb, alpha))  # type: ignore[return-value]


def gradient_at(item: PaintItem, frame: float, matrix: Array) -> tuple[Gradient, Color]:
    """The gradient fill at ``frame`` in world units (``matrix (3, 3)`` maps its group's frame into the world)
    and its stops' mean colour."""
    flat = item.stops.at(frame)
    count = item.count
    if len(flat) < 4 * count:
        raise Malformed(f"expected {4 * count} numbers of {count} colour stops, found {len(flat)}")
    colours = flat[: 4 * count].reshape(count, 4)
    rest = flat[4 * count:]
    offsets = np.clip(colours[:, 0], 0.0, 1.0)
    if len(rest) >= 2:
        alphas = rest[: len(rest) // 2 * 2].reshape(-1, 2)
        alpha = np.interp(offsets, alphas[:, 0], alphas[:, 1])
    else:
        alpha = np.ones(count)
    opacity = np.clip(float(item.opacity.at(frame)[0]) / 100.0, 0.0, 1.0)
    stops = tuple((float(o), tuple(int(round(float(np.clip(v, 0, 1)) * 255)) for v in (*c[1:], a * opacity)))
                  for o, c, a in zip(offsets, colours, alpha))
    start, end = np.resize(item.start.at(frame), 2), np.resize(item.end.at(frame), 2)
    if item.linear:
        geometry: tuple[float, ...] = (*start, *end)
        kind = "linear"
    else:
        radius = float(np.hypot(*(end - start)))
        share = min(max(float(item.highlight.at(frame)[0]) / 100.0, -0.99), 0.99)
        turn = np.arctan2(end[1] - start[1], end[0] - start[0]) + np.radians(float(item.angle.at(frame)[0]))
        focal = start + share * radius * np.array([np.cos(turn), np.sin(turn)])
        geometry = (*start, radius, *focal)
        kind = "radial"
    a, c, e = matrix[0]
    b, d, f = matrix[1]
    mean = tuple(int(round(float(np.mean([s[1][q] for s in stops])))) for q in range(4))
    return Gradient(kind, tuple(float(v) for v in geometry), (a, b, c, d, e, f), stops), mean  # type: ignore[arg-type]


@dataclass
class Element:
    """What one paint item (and a stroke drawn with it) draws: its paths, each with the transforms of its
    groups (innermost first), and the transforms of the paint's own groups."""

    fill: PaintItem | None
    stroke: PaintItem | None
    transforms: list[Transform]
    name: str
    paths: list[tuple[PathItem, list[Transform]]] = field(default_factory=list)


def layer_elements(items: Any, layer_name: str) -> list[Element]:
    """The elements a shape layer's ``shapes`` draw, from the bottom up."""
    out: list[Element] = []
    _walk(items, [], [], out, layer_name)
    merged: list[Element] = []
    for element in out:
        last = merged[-1] if merged else None
        if (last is not None and element.stroke is not None and element.fill is None and last.stroke is None
                and last.fill is not None and last.transforms is element.transforms
                and [id(p) for p, _ in last.paths] == [id(p) for p, _ in element.paths]):
            last.stroke = element.stroke
            continue
        merged.append(element)
    for element in merged:
        element.paths.reverse()  # in the order the file lists them
    return [e for e in merged if e.paths]


def _walk(items: Any, outer: list[Transform], active: list[Element], out: list[Element], name: str) -> None:
    """Items of one group (``outer``: the transforms of the groups around it, innermost first)."""
    if not isinstance(items, list):
        raise Malformed("expected a list of shape items")
    shown = [item for item in items if isinstance(item, dict) and not item.get("hd")]
    own = next((item for item in shown if item.get("ty") == "tr"), None)
    chain = [Transform(own), *outer]
    here = list(active)
    for item in reversed(shown):
        kind = item.get("ty")
        label = str(item.get("nm", kind))
        if kind == "tr":
            continue
        if kind in _REFUSED:
            raise Unreadable(f"{_REFUSED[kind]} ({label!r})")
        if kind in ("fl", "gf"):
            element = Element(PaintItem(item), None, chain, f"{name} {label}")
        elif kind == "st":
            element = Element(None, PaintItem(item), chain, f"{name} {label}")
        elif kind in ("sh", "rc", "el"):
            path = PathItem(item)
            for element in here:
                element.paths.append((path, chain))
            continue
        elif kind == "gr":
            _walk(item.get("it", []), chain, here, out, name)
            continue
        else:
            raise Unreadable(f"a shape item of type {kind!r} ({label!r})")
        here.append(element)
        out.append(element)
