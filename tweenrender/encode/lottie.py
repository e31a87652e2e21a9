"""Lottie JSON (bodymovin 5.x, as lottie-web, rlottie, ThorVG and Skottie play it) from a :class:`VectorClip`.

One shape layer per run (an element over the frames of one segment and one paint order, from
``ip`` to ``op``, about half a frame before the run's first frame and after its last), first in
the list on top; in it one group: a ``sh`` path per contour (straight edges: in and out tangents
zero; holes are sibling paths), the stroke (``st``) above the fill (``fl``, ``r`` 1 nonzero,
2 even-odd; where the rule switches inside the run, a fill of each rule, its opacity held at 0 while the other's is
in force), and the group's transform (contours growing from a point: a group per stroke width
above one of the fill). A contour that only grows, shrinks and moves is a still path in a group of its own,
whose transform's position and scale are keyed: the fill and stroke of the group above draw it with the
others, holes and all. The layer's opacity is the paint's, so fill and stroke fade together as
one picture; gradient fills and clip paths (the layer's masks, or a matte layer just above it) as
:mod:`.lottie_paint` writes them. A full-size rectangle layer at the bottom is the background.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from .atomic import replacing
from .lottie_paint import gradient_fill, masks, matte, matte_of, refuse_unsupported, stretched_cover, stretched_fill
from .lottie_values import animated, moved_group, path_item, percent, scalar, static, switched, transform
from .vector_data import Array, VectorClip, VectorRun

__all__ = ["lottie_document", "lottie_text", "write_lottie"]

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
    text = lottie_text(clip, target.stem)
    with replacing(target, ".json", "the Lottie file") as temporary:
        temporary.write_text(text, encoding="utf-8")
    return target


def lottie_text(clip: VectorClip, name: str = "tweenrender") -> str:
    """The Lottie JSON text of ``clip``, compact."""
    return json.dumps(lottie_document(clip, name), separators=(",", ":"), allow_nan=False)


def lottie_document(clip: VectorClip, name: str = "tweenrender") -> dict[str, Any]:
    """The Lottie animation of ``clip`` as a JSON-ready dict: ``w``, ``h``, ``fr``, ``ip = 0``, ``op = F``."""
    width, height = clip.size
    for run in clip.runs:
        refuse_unsupported(run)
    layers = [layer for run in reversed(clip.runs) for layer in _layers(run, clip)]
    if clip.background[3] > 0:
        layers.append(_background(clip))
    for index, layer in enumerate(layers):
        layer["ind"] = index + 1
    return {"v": "5.7.0", "nm": name, "fr": clip.fps, "ip": 0, "op": clip.frames, "w": width, "h": height,
            "ddd": 0, "assets": [], "layers": layers}


def _colour_prop(frames: tuple[int, ...], colours: Array) -> tuple[dict[str, Any], dict[str, Any]]:
    """A colour ``(P, 4)`` as Lottie's ``c`` (RGB in [0, 1]) and ``o`` (alpha in percent)."""
    rgb = [[round(float(v), 5) for v in c[:3]] + [1] for c in colours]
    alpha = [[a] for a in percent(colours[:, 3])]
    return animated(frames, rgb), scalar(animated(frames, alpha))


def _layers(run: VectorRun, clip: VectorClip) -> list[dict[str, Any]]:
    """The run's layer, below the matte of its clip path of several contours if it has one; or, for a fill of an
    elliptical gradient neither stroked nor clipped, a layer of the gradient below a matte of the run's paths."""
    frames = clip.frames
    paths = []
    for i, shut in enumerate(run.closed):
        keyframes, points, eases = run.keys_of(i)  # each contour keyed on its own
        item = path_item(f"contour {i}", i, keyframes, points, shut, eases)
        move = run.move_of(i)
        paths.append(item if move is None else moved_group(item, move))
    groups = run.stroke_groups() if run.stroke is not None else []
    gradient = run.gradient
    stretched = gradient is not None and gradient.kind == "radial" and not gradient.circular
    opacity = scalar(animated(run.paint_frames, [[v] for v in percent(run.opacity)]))
    start = run.first - _EARLY_IN if run.first > 0 else 0
    stop = run.stop - _EARLY_OUT if run.stop < frames else frames
    if stretched and run.gradient_matted():  # the gradient's frame fills the picture, seen through the paths
        assert gradient is not None
        outline = matte_of(run.element, paths, _FILL_RULES[run.fill_rule])
        shape = _shape_layer(f"{run.element} shape", static(100), [outline], start, stop)
        cover = _shape_layer(run.element, opacity, [stretched_cover(run, gradient, clip.size)], start, stop)
        return [dict(shape, td=1), dict(cover, tt=1)]
    shapes: list[dict[str, Any]] = []
    if len(groups) == 1 and not stretched:  # one group: the paths, the stroke above the fill
        items = [*paths, _stroke(run, groups[0][1], groups[0][0]), *_fill(run),
                 {"ty": "tr", **transform(static(100))}]
        shapes.append({"ty": "gr", "nm": run.element, "it": items})
    else:  # strokes apart, above the fill: contours growing from a point with their share of the width, or
        # a fill in the frame of its elliptical gradient
        for members, widths in groups:
            items = [*(paths[i] for i in members), _stroke(run, widths, members),
                     {"ty": "tr", **transform(static(100))}]
            shapes.append({"ty": "gr", "nm": f"{run.element} stroke", "it": items})
        if gradient is not None and stretched:
            shapes.append(stretched_fill(run, gradient, _FILL_RULES[run.fill_rule]))
        else:
            shapes.append({"ty": "gr", "nm": run.element,
                           "it": [*paths, *_fill(run), {"ty": "tr", **transform(static(100))}]})
    layer = _shape_layer(run.element, opacity, shapes, start, stop)
    if run.clip_paths is None:
        return [layer]
    clipping = masks(run.clip_paths)
    if clipping:
        layer.update(hasMask=True, masksProperties=clipping)
    region = matte(run.clip_paths)
    if region is None:
        return [layer]
    layer["tt"] = 1
    return [dict(_shape_layer(f"{run.element} clip", static(100), [region], layer["ip"], layer["op"]), td=1), layer]


def _shape_layer(name: str, opacity: dict[str, Any], shapes: list[dict[str, Any]], start: float,
                 stop: float) -> dict[str, Any]:
    """A shape layer (its ``ind`` is set when the layers are listed)."""
    return {"ddd": 0, "ind": 0, "ty": 4, "nm": name, "sr": 1, "ks": transform(opacity), "ao": 0, "ip": start,
            "op": stop, "st": 0, "bm": 0, "shapes": shapes}


def _stroke(run: VectorRun, widths: Array, members: list[int]) -> dict[str, Any]:
    colour, alpha = _colour_prop(run.paint_frames, run.stroke)  # type: ignore[arg-type]
    width = scalar(animated(run.paint_frames, [[round(float(w), 4)] for w in widths]))
    item = {"ty": "st", "nm": "stroke", "c": colour, "o": alpha, "w": width, "lc": _CAPS[run.cap],
            "lj": _JOINS[run.join], "ml": run.miter_limit}
    if run.dash is not None:
        item["d"] = _dashes(run.paint_frames, run.dash[members[0]])
    return item


def _dashes(frames: tuple[int, ...], dash: Array) -> list[dict[str, Any]]:
    """A stroke's ``d``: dash and gap lengths ``dash[:, :-1]`` then the offset ``dash[:, -1]`` (``(P, C + 1)``)."""
    out = []
    for j in range(dash.shape[1]):
        kind, name = ("o", "offset") if j == dash.shape[1] - 1 else ("d", f"dash {j // 2}") if j % 2 == 0 \
            else ("g", f"gap {j // 2}")
        out.append({"n": kind, "nm": name, "v": scalar(animated(frames, [[round(float(v), 4)] for v in dash[:, j]]))})
    return out


def _fill(run: VectorRun) -> list[dict[str, Any]]:
    if run.gradient is not None:
        return [gradient_fill(run.paint_frames, run.gradient, _FILL_RULES[run.fill_rule])]
    if run.fill is None:
        return []
    colour, alpha = _colour_prop(run.paint_frames, run.fill)
    if run.rule_switch is None:
        return [{"ty": "fl", "nm": "fill", "c": colour, "o": alpha, "r": _FILL_RULES[run.fill_rule]}]
    # the fill rule switches: two fills of the same paths, each shown while its rule is in force
    at, rule = run.rule_switch
    alphas = percent(run.fill[:, 3])
    return [{"ty": "fl", "nm": name, "c": colour, "o": switched(run.paint_frames, alphas, at, after, _EARLY_IN),
             "r": _FILL_RULES[chosen]}
            for name, chosen, after in (("fill", run.fill_rule, False), (f"fill from frame {at}", rule, True))]


def _background(clip: VectorClip) -> dict[str, Any]:
    width, height = clip.size
    r, g, b, a = clip.background
    rect = {"ty": "rc", "nm": "background", "d": 1, "s": static([width, height]),
            "p": static([width / 2, height / 2]), "r": static(0)}
    fill = {"ty": "fl", "c": static([r / 255, g / 255, b / 255, 1]), "o": static(round(a / 2.55, 3)), "r": 1}
    return _shape_layer("background", static(100), [{"ty": "gr", "nm": "background", "it": [
        rect, fill, {"ty": "tr", **transform(static(100))}]}], 0, clip.frames)
