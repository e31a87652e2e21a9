"""Gradient fills and clip paths in Lottie.

A linear gradient, and a radial one that stays a circle, is a gradient fill (``gf``, type 1 or 2) beside
the paths: start ``s`` and end ``e`` in pixels, a radial one's focal point as its highlight (``h``, percent
of the radius, at angle ``a`` from ``s → e``), the stops as ``g`` (``p`` colour stops ``offset, r, g, b``
then as many opacity stops ``offset, alpha``), all keyed at the paint keyframes. Lottie's gradients are
circles: an elliptical one is drawn in its own group whose transform (position, rotation, scale) turns
the circle into the ellipse. It fills a rectangle that covers the picture at every frame, drawn through a
matte of the run's own paths (a layer above it drawing them in white); where the run is stroked or clipped
(its layer's one matte taken, or the stroke to be drawn with the fill) the paths are written in that
group's frame instead, from the exact paths at every frame through the transform the player computes
there, keyframed within the tolerance. Lottie gradients
pad: a gradient that repeats or reflects is refused.

Clip paths of one contour are the layer's masks (in pixels; a layer is not transformed), intersected
(``a``, then ``i``): masks are combined one after the other by rlottie but each with all that follow it
by ThorVG, which agree for intersections only, and rlottie loses spans when it adds, subtracts or
excludes masks. A clip path of several contours (its nonzero fill, holes and all) is a matte: a layer
just above the run's, drawing it in white, which the run's layer shows through (alpha matte). A second
clip path of several contours is refused.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import OptionError
from .lottie_values import animated, contour, path_item, percent, scalar, static, transform
from .vector_data import Array, ClipPathKeys, GradientKeys, VectorRun, into_gradient_frame

__all__ = ["gradient_fill", "stretched_fill", "stretched_cover", "masks", "matte", "refuse_unsupported"]

_DECIMALS = 5


def refuse_unsupported(run: VectorRun) -> None:
    """Refuse, naming the element, what Lottie cannot carry: a gradient that does not pad, a clip of
    regions masks cannot combine."""
    gradient = run.gradient
    if gradient is not None and gradient.spread != "pad":
        raise OptionError(f"element {run.element!r}: its gradient spreads by {gradient.spread}, which Lottie "
                          "cannot carry (its gradients pad); write an animated SVG, or pad the gradient", "format")
    if run.clip_paths is not None and sum(len(region) > 1 for region in run.clip_paths.regions) > 1:
        raise OptionError(f"element {run.element!r}: it is clipped by several clip paths of several contours each, "
                          "which Lottie cannot carry (one is a matte, the others masks of one contour); write an "
                          "animated SVG", "format")


def gradient_fill(frames: tuple[int, ...], gradient: GradientKeys, rule: int, stretched: bool = False
                  ) -> dict[str, Any]:
    """A gradient fill (``gf``) keyed at ``frames`` with fill rule ``rule``; ``stretched``: in the frame of
    :func:`stretched_fill`'s group, where it is a circle about the origin."""
    radius = np.linalg.norm(gradient.end - gradient.start, axis=1)  # (P,)
    if stretched:
        start = np.zeros_like(gradient.start)
        end = np.stack([radius, np.zeros_like(radius)], axis=1)
    else:
        start, end = gradient.start, gradient.end
    item: dict[str, Any] = {"ty": "gf", "nm": "fill", "o": static(100), "r": rule,
                            "t": 1 if gradient.kind == "linear" else 2,
                            "s": animated(frames, _points(start)), "e": animated(frames, _points(end)),
                            "g": {"p": len(gradient.offsets), "k": animated(frames, _stops(gradient))}}
    if gradient.kind == "radial":
        length = np.linalg.norm(gradient.focal, axis=1) / np.maximum(radius, 1e-12)
        turn = np.degrees(np.unwrap(np.arctan2(gradient.focal[:, 1], gradient.focal[:, 0])))
        item["h"] = scalar(animated(frames, [[v] for v in percent(length)]))
        item["a"] = scalar(animated(frames, [[round(float(v), 3)] for v in turn]))
    return item


def _points(points: Array) -> list[list[float]]:
    return np.round(points, 3).tolist()


def _stops(gradient: GradientKeys) -> list[list[float]]:
    """Per keyframe, Lottie's flat stop list: ``offset, r, g, b`` per stop, then ``offset, alpha`` per stop."""
    out = []
    for colours in gradient.colours:  # (S, 4)
        values: list[float] = []
        for offset, colour in zip(gradient.offsets, colours):
            values += [float(offset), *(float(v) for v in colour[:3])]
        for offset, colour in zip(gradient.offsets, colours):
            values += [float(offset), float(colour[3])]
        out.append([round(v, _DECIMALS) for v in values])
    return out


def stretched_fill(run: VectorRun, gradient: GradientKeys, rule: int) -> dict[str, Any]:
    """A group filling the run's contours with its elliptical ``gradient``: its transform places the
    gradient's own frame (``pixel = start + R(angle) · diag(1, ratio) · u``), the paths are written in it."""
    frames = run.paint_frames
    assert run.gradient_paths is not None, "an elliptical gradient's run carries its paths in the gradient's frame"
    path_frames, local, eases = run.gradient_paths
    paths = [path_item(f"contour {i}", i, path_frames, points, shut, eases)
             for i, (points, shut) in enumerate(zip(local, run.closed))]
    items = [*paths, gradient_fill(frames, gradient, rule, stretched=True), _gradient_frame(frames, gradient)]
    return {"ty": "gr", "nm": run.element, "it": items}


def _gradient_frame(frames: tuple[int, ...], gradient: GradientKeys) -> dict[str, Any]:
    """A group's transform (``tr``) placing the elliptical ``gradient``'s own frame, keyed at ``frames``."""
    position = animated(frames, _points(gradient.start))
    rotation = scalar(animated(frames, [[round(float(a), 4)] for a in gradient.angle]))
    scale = animated(frames, [[100.0, round(float(100.0 * r), 4)] for r in gradient.ratio])
    return {"ty": "tr", **transform(static(100), position, rotation, scale)}


def stretched_cover(run: VectorRun, gradient: GradientKeys, size: tuple[int, int]) -> dict[str, Any]:
    """A group filling, with the run's elliptical ``gradient``, a rectangle in the gradient's own frame that covers
    the picture (``size`` pixels) at every frame of the run, as the player places that frame: drawn through a
    matte of the run's paths (:func:`matte_of`)."""
    width, height = size
    corners = np.array([[0.0, 0.0], [width, 0.0], [width, height], [0.0, height]])
    centre, angle, ratio = run.gradient_placed(np.arange(run.first, run.stop, dtype=np.float64))
    local = np.concatenate([into_gradient_frame(corners, c, a, r) for c, a, r in zip(centre, angle, ratio)])
    low, high = np.floor(local.min(axis=0)) - 1, np.ceil(local.max(axis=0)) + 1  # a pixel's margin and more
    box = np.array([[low[0], low[1]], [high[0], low[1]], [high[0], high[1]], [low[0], high[1]]])
    items = [path_item("cover", 0, (run.first,), box[None], True),
             gradient_fill(run.paint_frames, gradient, 1, stretched=True), _gradient_frame(run.paint_frames, gradient)]
    return {"ty": "gr", "nm": run.element, "it": items}


def matte_of(name: str, paths: list[dict[str, Any]], rule: int) -> dict[str, Any]:
    """The shapes of a matte layer (``td``) drawing ``paths`` (path items) in white, filled by ``rule``."""
    return {"ty": "gr", "nm": name, "it": [*paths, {"ty": "fl", "nm": "matte", "c": static([1, 1, 1, 1]),
                                                    "o": static(100), "r": rule},
                                           {"ty": "tr", **transform(static(100))}]}


def masks(clip_paths: ClipPathKeys) -> list[dict[str, Any]]:
    """A layer's masks: the clip paths of one contour each, intersected (none when there are none)."""
    singles = [region[0] for region in clip_paths.regions if len(region) == 1]
    return [{"nm": f"clip {index}", "mode": "i" if index else "a", "inv": False, "o": static(100), "x": static(0),
             "pt": contour(clip_paths.frames, points, True)} for index, points in enumerate(singles)]


def matte(clip_paths: ClipPathKeys) -> dict[str, Any] | None:
    """The shapes of a matte layer (``td``) drawing the clip path of several contours (nonzero), for a
    layer to show through (``tt`` 1, alpha); ``None`` when there is none."""
    several = [region for region in clip_paths.regions if len(region) > 1]
    if not several:
        return None
    paths = [path_item(f"clip {i}", i, clip_paths.frames, points, True) for i, points in enumerate(several[0])]
    return matte_of("clip", paths, 1)
