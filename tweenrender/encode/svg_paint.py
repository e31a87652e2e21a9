"""Gradient fills and clip paths in an animated SVG.

A gradient is a ``<linearGradient>`` (``x1 y1 x2 y2``: its points at offsets 0 and 1) or a
``<radialGradient>`` (a circle about the origin of radius ``r`` with its focal point ``fx fy``, placed
by ``gradientTransform = translate rotate scale``), in ``userSpaceOnUse`` pixels, with its spread
method; ``<animate>`` moves the geometry and each stop's ``stop-color`` and ``stop-opacity`` (and
``offset``) through the paint keyframes, ``<animateTransform>`` the placement. Clip paths are
``<clipPath>``s of one path each (a region's contours, nonzero), ``d`` moved through the clip
keyframes, applied by nested groups so that the regions intersect.
"""

from __future__ import annotations

import numpy as np

from .smil import animate, hex_colour, number, path_data
from .vector_data import Array, GradientKeys, VectorRun

__all__ = ["gradient_element", "clip_path_elements"]


def gradient_element(run: VectorRun, ident: str, total: int, timing: str) -> list[str]:
    """The run's gradient as an element of id ``ident`` (none when it fills plainly)."""
    gradient: GradientKeys | None = run.gradient
    if gradient is None:
        return []
    frames = run.paint_frames

    def moving(name: str, values: Array, digits: int = 3) -> tuple[str, str]:
        texts = [number(float(v), digits) for v in values]
        return f'{name}="{texts[0]}"', animate(name, frames, texts, total, timing)

    if gradient.kind == "linear":
        tag = "linearGradient"
        pairs = [moving(name, values) for name, values in (("x1", gradient.start[:, 0]), ("y1", gradient.start[:, 1]),
                                                             ("x2", gradient.end[:, 0]), ("y2", gradient.end[:, 1]))]
    else:
        tag = "radialGradient"
        radius = np.linalg.norm(gradient.end - gradient.start, axis=1)
        pairs = [('cx="0" cy="0"', ""), moving("r", radius), moving("fx", gradient.focal[:, 0]),
                 moving("fy", gradient.focal[:, 1])]
        pairs.append(_placement(run, gradient, total, timing))
    attributes = " ".join(a for a, _ in pairs)
    lines = [f'<{tag} id="{ident}" gradientUnits="userSpaceOnUse" spreadMethod="{gradient.spread}" {attributes}>',
             *(line for _, line in pairs if line)]
    for index, offset in enumerate(gradient.offsets):
        colours = gradient.colours[:, index]  # (P, 4)
        hexes = [hex_colour(c[:3]) for c in colours]
        alphas = [number(float(c[3]), 4) for c in colours]
        inner = [animate("stop-color", frames, hexes, total, timing),
                 animate("stop-opacity", frames, alphas, total, timing)]
        inner = [line for line in inner if line]
        stop = f'<stop offset="{number(float(offset), 6)}" stop-color="{hexes[0]}" stop-opacity="{alphas[0]}"'
        lines += [stop + ">", *inner, "</stop>"] if inner else [stop + "/>"]
    lines.append(f"</{tag}>")
    return lines


def _placement(run: VectorRun, gradient: GradientKeys, total: int, timing: str) -> tuple[str, str]:
    """A radial gradient's ``gradientTransform`` (its centre, the turn of its first axis, the second axis's
    stretch) and, where it moves, the ``<animateTransform>``s that move it, added in that order."""
    parts = [("translate", [f"{number(x)} {number(y)}" for x, y in gradient.start.tolist()]),
             ("rotate", [number(float(a), 4) for a in gradient.angle]),
             ("scale", [f"1 {number(float(r), 6)}" for r in gradient.ratio])]
    attribute = 'gradientTransform="' + " ".join(f"{kind}({values[0]})" for kind, values in parts) + '"'
    if all(all(v == values[0] for v in values) for _, values in parts):
        return attribute, ""
    lines = [animate("gradientTransform", run.paint_frames, values, total, timing, transform=kind,
                     additive=index > 0) for index, (kind, values) in enumerate(parts)]
    return attribute, "\n".join(lines)


def clip_path_elements(run: VectorRun, ident: str, total: int, timing: str
                       ) -> tuple[list[str], list[str], list[str]]:
    """The run's clip paths: their ``<clipPath>`` elements (ids ``ident-0``, ``ident-1``, …), and the group
    tags that open and close around what they clip (nothing when unclipped)."""
    clip_paths = run.clip_paths
    if clip_paths is None:
        return [], [], []
    elements, opening = [], []
    for index, region in enumerate(clip_paths.regions):
        d_values = [path_data([c[k] for c in region], (True,) * len(region)) for k in range(len(clip_paths.frames))]
        moves = animate("d", clip_paths.frames, d_values, total, timing)
        path = f'<path d="{d_values[0]}" clip-rule="nonzero"'
        elements += [f'<clipPath id="{ident}-{index}">', *([path + ">", moves, "</path>"] if moves else [path + "/>"]),
                     "</clipPath>"]
        opening.append(f'<g clip-path="url(#{ident}-{index})">')
    return elements, opening, ["</g>"] * len(opening)
