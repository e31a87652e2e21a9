"""Lottie JSON (bodymovin 5.x, as lottie-web, rlottie, ThorVG and Skottie play it) from a :class:`VectorClip`.

One shape layer per run (an element over the frames of one segment and one paint order, from
``ip`` to ``op``, about half a frame before the run's first frame and after its last), first in
the list on top; in it one group: a ``sh`` path per contour (straight edges: in and out tangents
zero; holes are sibling paths), the stroke (``st``) above the fill (``fl``, ``r`` 1 nonzero,
2 even-odd), and the group's transform (contours growing from a point: a group per stroke width
above one of the fill). The layer's opacity is the paint's, so fill and stroke fade together as
one picture. A full-size rectangle layer at the bottom is the background.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np

from .atomic import replacing
from .vector_data import STRAIGHT, Array, Handles, VectorClip, VectorRun

__all__ = ["lottie_document", "write_lottie"]

_DIGITS = 3  # pixels are written to a thousandth
_CAPS = {"butt": 1, "round": 2, "square": 3}
_JOINS = {"miter": 1, "round": 2, "bevel": 3}
_FILL_RULES = {"nonzero": 1, "evenodd": 2}
_EARLY_IN, _EARLY_OUT = 0.499, 0.501
"""How much earlier than its first frame a run's layer starts (``ip``) and than the frame after its last it
ends (``op``). Players disagree at the edges: rlottie rounds ``ip`` and ``op`` to whole frames and draws
frame ``op``; lottie-web and ThorVG draw from ``ip`` up to, not including, ``op``. Just under half a frame
early suits all three, and leaves a thousandth of a frame between consecutive layers of an element."""


def write_lottie(clip: VectorClip, target: Path) -> Path:
    """Write ``clip`` to ``target`` as Lottie JSON, atomically; returns ``target``."""
    text = json.dumps(lottie_document(clip, target.stem), separators=(",", ":"), allow_nan=False)
    with replacing(target, ".json", "the Lottie file") as temporary:
        temporary.write_text(text, encoding="utf-8")
    return target


def lottie_document(clip: VectorClip, name: str = "tweenrender") -> dict[str, Any]:
    """The Lottie animation of ``clip`` as a JSON-ready dict: ``w``, ``h``, ``fr``, ``ip = 0``, ``op = F``."""
    width, height = clip.size
    layers = [_layer(run, index + 1, clip.frames) for index, run in enumerate(reversed(clip.runs))]
    if clip.background[3] > 0:
        layers.append(_background(clip, len(layers) + 1))
    return {"v": "5.7.0", "nm": name, "fr": clip.fps, "ip": 0, "op": clip.frames, "w": width, "h": height,
            "ddd": 0, "assets": [], "layers": layers}


def _static(value: Any) -> dict[str, Any]:
    return {"a": 0, "k": value}


def _transform(opacity: dict[str, Any]) -> dict[str, Any]:
    return {"o": opacity, "r": _static(0), "p": _static([0, 0, 0]), "a": _static([0, 0, 0]),
            "s": _static([100, 100, 100])}


def _animated(frames: tuple[int, ...], values: list[Any], eases: tuple[Handles, ...] = ()) -> dict[str, Any]:
    """A property keyed at ``frames``, each key eased to the next by its ``eases`` (CSS cubic-bezier;
    none: straight)."""
    if len(frames) == 1 or all(v == values[0] for v in values[1:]):
        return _static(values[0])
    keys: list[dict[str, Any]] = []
    for index, (frame, value) in enumerate(zip(frames, values)):
        key: dict[str, Any] = {"t": frame, "s": value}
        if index < len(frames) - 1:
            x1, y1, x2, y2 = eases[index] if eases else STRAIGHT
            key["o"] = {"x": [x1], "y": [y1]}
            key["i"] = {"x": [x2], "y": [y2]}
        keys.append(key)
    return {"a": 1, "k": keys}


def _shape_value(points: Array, closed: bool) -> list[dict[str, Any]]:
    vertices = np.round(points, _DIGITS).tolist()
    zero = [[0, 0]] * len(vertices)
    return [{"c": closed, "v": vertices, "i": zero, "o": zero}]


def _path(frames: tuple[int, ...], points: Array, closed: bool, eases: tuple[Handles, ...],
          index: int) -> dict[str, Any]:
    """One contour: ``points (K, L, 2)`` at ``frames``, each span timed by its ``eases``."""
    values = [_shape_value(p, closed) for p in points]
    prop = _animated(frames, values, eases)
    if prop["a"] == 0:
        prop = _static(values[0][0])
    return {"ty": "sh", "nm": f"contour {index}", "ind": index, "ks": prop}


def _percent(values: Array) -> list[float]:
    return [round(float(v) * 100.0, 3) for v in values]


def _colour_prop(frames: tuple[int, ...], colours: Array) -> tuple[dict[str, Any], dict[str, Any]]:
    """A colour ``(P, 4)`` as Lottie's ``c`` (RGB in [0, 1]) and ``o`` (alpha in percent)."""
    rgb = [[round(float(v), 5) for v in c[:3]] + [1] for c in colours]
    alpha = [[a] for a in _percent(colours[:, 3])]
    return _animated(frames, rgb), _scalar(_animated(frames, alpha))


def _scalar(prop: dict[str, Any]) -> dict[str, Any]:
    """Lottie keeps one-dimensional static values as plain numbers."""
    if prop["a"] == 0 and isinstance(prop["k"], list):
        return _static(prop["k"][0])
    return prop


def _layer(run: VectorRun, index: int, frames: int) -> dict[str, Any]:
    paths = [_path(run.path_frames, p, shut, run.eases, i) for i, (p, shut) in enumerate(zip(run.paths, run.closed))]
    groups = run.stroke_groups() if run.stroke is not None else []
    shapes: list[dict[str, Any]] = []
    if len(groups) == 1:  # one group: the paths, the stroke above the fill
        items = [*paths, _stroke(run, groups[0][1]), *_fill(run), {"ty": "tr", **_transform(_static(100))}]
        shapes.append({"ty": "gr", "nm": run.element, "it": items})
    else:  # contours growing from a point stroke with their share of the width: strokes apart, above the fill
        for members, widths in groups:
            items = [*(paths[i] for i in members), _stroke(run, widths), {"ty": "tr", **_transform(_static(100))}]
            shapes.append({"ty": "gr", "nm": f"{run.element} stroke", "it": items})
        shapes.append({"ty": "gr", "nm": run.element,
                       "it": [*paths, *_fill(run), {"ty": "tr", **_transform(_static(100))}]})
    opacity = _scalar(_animated(run.paint_frames, [[v] for v in _percent(run.opacity)]))
    return {"ddd": 0, "ind": index, "ty": 4, "nm": run.element, "sr": 1, "ks": _transform(opacity), "ao": 0,
            "ip": run.first - _EARLY_IN if run.first > 0 else 0,
            "op": run.stop - _EARLY_OUT if run.stop < frames else frames,
            "st": 0, "bm": 0, "shapes": shapes}


def _stroke(run: VectorRun, widths: Array) -> dict[str, Any]:
    colour, alpha = _colour_prop(run.paint_frames, run.stroke)  # type: ignore[arg-type]
    width = _scalar(_animated(run.paint_frames, [[round(float(w), 4)] for w in widths]))
    return {"ty": "st", "nm": "stroke", "c": colour, "o": alpha, "w": width, "lc": _CAPS[run.cap],
            "lj": _JOINS[run.join], "ml": run.miter_limit}


def _fill(run: VectorRun) -> list[dict[str, Any]]:
    if run.fill is None:
        return []
    colour, alpha = _colour_prop(run.paint_frames, run.fill)
    return [{"ty": "fl", "nm": "fill", "c": colour, "o": alpha, "r": _FILL_RULES[run.fill_rule]}]


def _background(clip: VectorClip, index: int) -> dict[str, Any]:
    width, height = clip.size
    r, g, b, a = clip.background
    rect = {"ty": "rc", "nm": "background", "d": 1, "s": _static([width, height]),
            "p": _static([width / 2, height / 2]), "r": _static(0)}
    fill = {"ty": "fl", "c": _static([r / 255, g / 255, b / 255, 1]), "o": _static(round(a / 2.55, 3)), "r": 1}
    return {"ddd": 0, "ind": index, "ty": 4, "nm": "background", "sr": 1, "ks": _transform(_static(100)), "ao": 0,
            "ip": 0, "op": clip.frames, "st": 0, "bm": 0,
            "shapes": [{"ty": "gr", "nm": "background", "it": [rect, fill, {"ty": "tr", **_transform(_static(100))}]}]}
