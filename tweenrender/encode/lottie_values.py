"""Lottie property values: static and keyframed properties, transforms and paths (straight or cubic)."""

from __future__ import annotations

from typing import Any

import numpy as np

from .vector_data import HANDLE_DIGITS, PIXEL_DIGITS, SCALE_DIGITS, STRAIGHT, Array, ContourMove, Handles

__all__ = ["DIGITS", "compact", "static", "animated", "switched", "scalar", "percent", "transform", "contour",
           "path_item", "moved_group"]

DIGITS = PIXEL_DIGITS  # pixels are written to a hundredth


def static(value: Any) -> dict[str, Any]:
    """A property that never changes."""
    return {"a": 0, "k": value}


def animated(frames: tuple[int, ...], values: list[Any], eases: tuple[Handles, ...] = ()) -> dict[str, Any]:
    """A property keyed at ``frames``, each key eased to the next by its ``eases`` (CSS cubic-bezier, one a
    span; none: straight); static when every value is the first."""
    if len(frames) == 1 or all(v == values[0] for v in values[1:]):
        return static(values[0])
    keys: list[dict[str, Any]] = []
    for index, (frame, value) in enumerate(zip(frames, values)):
        key: dict[str, Any] = {"t": frame, "s": value}
        if index < len(frames) - 1:
            x1, y1, x2, y2 = (_short(h) for h in (eases[index] if eases else STRAIGHT))
            key["o"] = {"x": [x1], "y": [y1]}
            key["i"] = {"x": [x2], "y": [y2]}
        keys.append(key)
    return {"a": 1, "k": keys}


def switched(frames: tuple[int, ...], values: list[float], at: int, after: bool, early: float) -> dict[str, Any]:
    """A number keyed straight at ``frames`` (held before the first and after the last) until frame ``at``, 0 from
    it on; or (``after``) 0 until ``at`` and the number from it on. It switches ``early`` frames before ``at``,
    held from frame ``at - 1``: no player that draws a frame a hair early or late sees it."""
    def value(frame: float) -> float:
        return round(float(np.interp(frame, frames, values)), 3)

    edge = at - early
    if after:
        keys = [(at - 1, 0.0, True), (edge, value(edge), False), *((f, v, False) for f, v in zip(frames, values)
                                                                      if f > edge)]
    else:
        keys = [*((f, v, False) for f, v in zip(frames, values) if f < at - 1), (at - 1, value(at - 1), True),
                (edge, 0.0, False)]
    out: list[dict[str, Any]] = []
    for index, (frame, number, hold) in enumerate(keys):
        key: dict[str, Any] = {"t": frame, "s": [number]}
        if hold:
            key["h"] = 1
        elif index < len(keys) - 1:
            key["o"], key["i"] = {"x": [0], "y": [0]}, {"x": [1], "y": [1]}
        out.append(key)
    return {"a": 1, "k": out}


def _short(value: float) -> float | int:
    """A timing handle as written: to :data:`~.vector_data.HANDLE_DIGITS` decimals, a whole one as an integer
    (``0``, not ``0.0``)."""
    rounded = round(float(value), HANDLE_DIGITS) + 0.0
    return int(rounded) if rounded.is_integer() else rounded


def scalar(prop: dict[str, Any]) -> dict[str, Any]:
    """Lottie keeps one-dimensional static values as plain numbers."""
    if prop["a"] == 0 and isinstance(prop["k"], list):
        return static(prop["k"][0])
    return prop


def percent(values: Array) -> list[float]:
    """Fractions ``(P,)`` as percentages."""
    return [round(float(v) * 100.0, 3) for v in values]


def transform(opacity: dict[str, Any], position: dict[str, Any] | None = None, rotation: dict[str, Any] | None = None,
              scale: dict[str, Any] | None = None) -> dict[str, Any]:
    """A transform's properties: by default none moves, turns or scales."""
    return {"o": opacity, "r": rotation or static(0), "p": position or static([0, 0, 0]), "a": static([0, 0, 0]),
            "s": scale or static([100, 100, 100])}


def compact(values: Array) -> list[Any]:
    """``values`` (any shape) rounded to :data:`DIGITS` decimals as nested lists, whole numbers as ints
    (``330``, not ``330.0``; ``0``, not ``-0.0``): the same numbers in fewer characters."""
    rounded = np.round(np.asarray(values, dtype=np.float64), DIGITS) + 0.0  # + 0.0: -0.0 becomes 0.0
    whole = (rounded == np.rint(rounded)) & (np.abs(rounded) < 2.0 ** 53)  # exact as an int
    if not whole.any():
        return rounded.tolist()  # type: ignore[no-any-return]
    mixed = rounded.astype(object)
    mixed[whole] = rounded[whole].astype(np.int64)
    return mixed.tolist()  # type: ignore[no-any-return]


def _shape_value(points: Array, closed: bool) -> list[dict[str, Any]]:
    """One path value: straight edges ``(L, 2)``, or a cubic Bézier path ``(M, 3, 2)`` (in control point,
    vertex, out control point per vertex), its tangents written relative to their vertex."""
    if points.ndim == 2:
        vertices = compact(points)
        zero = [[0, 0]] * len(vertices)
        return [{"c": closed, "v": vertices, "i": zero, "o": zero}]
    vertex = np.round(points[:, 1], DIGITS)
    return [{"c": closed, "v": compact(vertex), "i": compact(points[:, 0] - vertex),
             "o": compact(points[:, 2] - vertex)}]


def contour(frames: tuple[int, ...], points: Array, closed: bool, eases: tuple[Handles, ...] = ()) -> dict[str, Any]:
    """A path ``points`` at ``frames``, each span timed by its ``eases`` (none: straight), as a shape
    property (``ks`` of a path, ``pt`` of a mask): straight edges ``(K, L, 2)`` or a cubic Bézier path
    ``(K, M, 3, 2)`` (:class:`~.vector_data.VectorRun`)."""
    values = [_shape_value(p, closed) for p in points]
    prop = animated(frames, values, eases)
    if prop["a"] == 0:
        prop = static(values[0][0])
    return prop


def path_item(name: str, index: int, frames: tuple[int, ...], points: Array, closed: bool,
              eases: tuple[Handles, ...] = ()) -> dict[str, Any]:
    """A path shape item (``sh``) named ``name``: :func:`contour` of ``points (K, L, 2)`` at ``frames``."""
    return {"ty": "sh", "nm": name, "ind": index, "ks": contour(frames, points, closed, eases)}


def moved_group(item: dict[str, Any], move: ContourMove) -> dict[str, Any]:
    """A group holding the path ``item`` (one still keyframe) placed by ``move``: its transform's anchor is the
    move's anchor, its position and scale keyed together (same frames, same timing), so every drawn point moves
    straight between keyframes as the move's do."""
    position = animated(move.frames, [compact(c) for c in move.centres], move.eases)
    scale = animated(move.frames, [[v, v, 100] for v in np.round(move.scales * 100.0, SCALE_DIGITS).tolist()],
                     move.eases)
    place = {"ty": "tr", "o": static(100), "r": static(0), "p": position, "a": static(compact(move.anchor)),
             "s": scale}
    return {"ty": "gr", "nm": item["nm"], "it": [item, place]}
