"""An animated SVG (SMIL) from a :class:`VectorClip`: browsers play it as it is.

A full-size rectangle is the background; each run (an element over the frames of one segment) is
a group, shown only over its frames (``visibility``, discrete) and faded by the paint's
``opacity``, holding one ``<path>``: all its contours as subpaths, so holes follow the fill rule.
``<animate>`` moves ``d`` through the path keyframes (``calcMode="spline"`` with the easing's
``keySplines`` for an exact segment) and ``fill``, ``fill-opacity``, ``stroke``,
``stroke-opacity``, ``stroke-width`` through the paint keyframes, and ``fill-rule`` (discrete) where it
switches inside a run; gradient fills and clip paths as
:mod:`.svg_paint` writes them, with ids of the file's own (``tr-run0-fill``, ``tr-run0-clip-0``, …, under
a prefix no group id begins with: :func:`own_prefix`); each group's id is its element's name and first
frame. Frame ``f`` is at ``keyTime f / F`` of ``dur = F / fps`` seconds; every animation freezes at its end.
"""

from __future__ import annotations

from pathlib import Path
from xml.sax.saxutils import escape, quoteattr

import numpy as np

from .atomic import replacing
from .smil import animate, clip_timing, hex_colour, number, path_data, straight_spans
from .svg_paint import clip_path_elements, gradient_element
from .vector_data import PIXEL_DIGITS, SCALE_DIGITS, Array, ContourMove, VectorClip, VectorRun

__all__ = ["svg_document", "write_animated_svg"]

_EARLY = 1e-3  # frames: how much earlier than its first frame a run is shown (and hidden after its last)


def write_animated_svg(clip: VectorClip, target: Path) -> Path:
    """Write ``clip`` to ``target`` as an animated SVG, atomically; returns ``target``."""
    text = svg_document(clip, target.stem)
    with replacing(target, ".svg", "the SVG file") as temporary:
        temporary.write_text(text, encoding="utf-8")
    return target


def svg_document(clip: VectorClip, title: str = "tweenrender") -> str:
    """The SVG text of ``clip``."""
    width, height = clip.size
    timing = clip_timing(clip.frames / clip.fps, clip.loop)
    lines = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
             f'viewBox="0 0 {width} {height}">', f"<title>{escape(title)}</title>"]
    r, g, b, a = clip.background
    if a > 0:
        lines.append(f'<rect width="{width}" height="{height}" fill="{hex_colour((r / 255, g / 255, b / 255))}"'
                     + (f' fill-opacity="{number(a / 255, 4)}"' if a < 255 else "") + "/>")
    prefix = own_prefix([_group_id(run) for run in clip.runs])
    for index, run in enumerate(clip.runs):
        lines.extend(_run(run, f"{prefix}run{index}", clip.frames, timing, clip.size))
    lines.append("</svg>")
    return "\n".join(lines) + "\n"


def own_prefix(taken: list[str]) -> str:
    """The prefix of the file's own ids (its gradients' and clip paths'): ``tr-``, else ``tr1-``, ``tr2-``, …,
    the first that begins none of the ids ``taken`` (the groups', named after the drawing's elements), so no
    id of the file is used twice and a reference finds the element it means."""
    prefix, count = "tr-", 0
    while any(ident.startswith(prefix) for ident in taken):
        count += 1
        prefix = f"tr{count}-"
    return prefix


def _group_id(run: VectorRun) -> str:
    """The id of a run's group: its element's name and first frame."""
    return f"{run.element}-{run.first}"


def _run(run: VectorRun, ident: str, total: int, timing: str, size: tuple[int, int]) -> list[str]:
    """The run as a group in a view of ``size``; ``ident`` names its gradient (``ident-fill``), clip paths
    (``ident-clip-0``, …) and masks (``ident-cut-0``, …).
    Its contours are one path, or one path per piece (:func:`_pieces`) where that is shorter."""
    lines = [f"<g id={quoteattr(_group_id(run))}"
             + (' visibility="hidden"' if run.first > 0 else "") + _static_opacity(run) + ">"]
    if run.first > 0 or run.stop < total:
        # switched a thousandth of a frame early, so a frame's own time is never on the edge
        values, times = (["hidden", "visible"], [0.0, (run.first - _EARLY) / total]) if run.first > 0 \
            else (["visible"], [0.0])
        if run.stop < total:
            values, times = [*values, "hidden"], [*times, (run.stop - _EARLY) / total]
        lines.append(f'<animate attributeName="visibility" {timing} calcMode="discrete" '
                     f'keyTimes="{";".join(number(t, 9) for t in times)}" values="{";".join(values)}"/>')
    lines.append(animate("opacity", run.paint_frames, [number(o, 4) for o in run.opacity], total, timing))
    gradient = gradient_element(run, f"{ident}-fill", total, timing)
    clip_paths, opening, closing = clip_path_elements(run, f"{ident}-clip", total, timing)
    if gradient or clip_paths:
        lines += ["<defs>", *gradient, *clip_paths, "</defs>"]
    lines += opening
    fill = f"url(#{ident}-fill)" if gradient else None
    groups = run.stroke_groups() if run.stroke is not None else []
    if len(groups) <= 1:
        widths = groups[0][1] if groups else None
        whole = _path(run, list(range(len(run.paths))), True, widths, total, timing, fill)
        apart = _pieces(run, ident, size, widths, total, timing, fill)
        lines += whole if apart is None or _length(apart) >= _length(whole) else apart
    else:  # contours growing from a point stroke with their share of the width: the fill, then each stroke
        lines += _path(run, list(range(len(run.paths))), True, None, total, timing, fill)
        for members, widths in groups:
            lines += _path(run, members, False, widths, total, timing)
    lines += [*closing, "</g>"]
    return [line for line in lines if line]


def _path(run: VectorRun, members: list[int], filled: bool, widths: Array | None, total: int,
          timing: str, gradient: str | None = None) -> list[str]:
    """One ``<path>`` of the contours ``members``: filled (or not; by the paint server ``gradient`` if given),
    stroked ``widths (P,)`` wide (``None``: not)."""
    shape, moves = _geometry(run.path_frames, [run.paths[i] for i in members], tuple(run.closed[i] for i in members),
                             run.eases, total, timing)
    paint, changes = _paint(run, members, filled, widths, total, timing, gradient)
    return _element("path", shape + paint, moves + changes)


def _pieces(run: VectorRun, ident: str, size: tuple[int, int], widths: Array | None, total: int, timing: str,
            gradient: str | None) -> list[str] | None:
    """The run's contours as one ``<path>`` per piece (:attr:`VectorRun.pieces`) in a group that holds the paint:
    a contour alone in its piece moves by its own keyframes (:meth:`VectorRun.keys_of`), or as a still path under
    a keyed translation and scale where it only grows, shrinks and moves (:meth:`VectorRun.move_of`), several by
    their piece's own (:attr:`VectorRun.piece_keys`). A piece's holes cut out (:attr:`VectorRun.piece_cuts`) are
    black in a mask of its own (``ident-cut-K``, white over the ``size`` of the view), each by its own keys.
    None where the run has neither two pieces nor a hole to cut."""
    pieces = run.pieces
    if pieces is None or (len(pieces) < 2 and run.piece_cuts is None):
        return None
    paint, changes = _paint(run, list(range(len(run.paths))), True, widths, total, timing, gradient)
    lines = ["<g " + " ".join(paint) + ">", *(line for line in changes if line)]  # the paths inherit the paint
    width, height = size
    for index, members in enumerate(pieces):
        cut = run.cut_of(index)
        drawn = [i for i in members if i not in cut]
        own = run.piece_keys[index] if run.piece_keys is not None else None
        if own is not None:
            frames, paths, eases = own
            shape, moves = _geometry(frames, list(paths), tuple(run.closed[i] for i in drawn), eases, total, timing)
        else:  # one contour left in the piece
            shape, moves = _own_geometry(run, drawn[0], total, timing)
        if cut:
            mask = f"{ident}-cut-{index}"
            lines += [f'<mask id="{mask}" maskUnits="userSpaceOnUse" x="0" y="0" width="{width}" height="{height}" '
                      'style="mask-type:luminance" color-interpolation="sRGB">',
                      f'<rect width="{width}" height="{height}" fill="#ffffff"/>']
            for i in cut:
                hole, hole_moves = _own_geometry(run, i, total, timing)
                lines += _element("path", [*hole, 'fill="#000000"'], hole_moves)
            lines.append("</mask>")
            shape = [*shape, f'mask="url(#{mask})"']
        lines += _element("path", shape, moves)
    return [*lines, "</g>"]


def _own_geometry(run: VectorRun, index: int, total: int, timing: str) -> tuple[list[str], list[str]]:
    """Contour ``index`` alone by its own keyframes and move (:func:`_geometry`)."""
    frames, path, eases = run.keys_of(index)
    return _geometry(frames, [path], (run.closed[index],), eases, total, timing, run.move_of(index))


def _geometry(frames: tuple[int, ...], paths: list[Array], closed: tuple[bool, ...], eases: tuple,
              total: int, timing: str, move: ContourMove | None = None) -> tuple[list[str], list[str]]:
    """The ``d`` of the contours ``paths`` (keyed at clip ``frames`` through ``eases``, as :attr:`VectorRun.paths`)
    and its animation; with a ``move``, the one still keyframe about the move's anchor and the ``transform`` that
    places it (a translation to the centre, then the scale, keyed together)."""
    if move is not None:
        paths = [p - move.anchor for p in paths]
    shapes = [[p[k] for p in paths] for k in range(len(frames))]
    lines = [straight_spans(p) if p.ndim == 4 else np.zeros(0, dtype=bool) for p in paths]
    d_values = [path_data(s, closed, lines) for s in shapes]
    attributes, inner = [f'd="{d_values[0]}"'], [animate("d", frames, d_values, total, timing, eases)]
    if move is not None:
        centres = [f"{number(x, PIXEL_DIGITS)} {number(y, PIXEL_DIGITS)}" for x, y in move.centres.tolist()]
        scales = [number(v, SCALE_DIGITS + 2) for v in move.scales.tolist()]
        attributes.append(f'transform="translate({centres[0]}) scale({scales[0]})"')
        inner += [animate("transform", move.frames, centres, total, timing, move.eases, transform="translate"),
                  animate("transform", move.frames, scales, total, timing, move.eases, transform="scale",
                          additive=True)]
    return attributes, inner


def _paint(run: VectorRun, members: list[int], filled: bool, widths: Array | None, total: int, timing: str,
           gradient: str | None = None) -> tuple[list[str], list[str]]:
    """The paint attributes of the contours ``members`` (as :func:`_path` draws them) and their animations."""
    attributes, inner = [f'fill-rule="{run.fill_rule}"'], []
    if filled and run.rule_switch is not None:  # switched as the run's visibility is, a thousandth of a frame early
        at, rule = run.rule_switch
        inner.append(f'<animate attributeName="fill-rule" {timing} calcMode="discrete" '
                     f'keyTimes="0;{number((at - _EARLY) / total, 9)}" values="{run.fill_rule};{rule}"/>')
    for name, colours in (("fill", run.fill if filled else None), ("stroke", run.stroke if widths is not None
                                                                          else None)):
        if name == "fill" and filled and gradient is not None:
            attributes.append(f'fill="{gradient}"')
            continue
        if colours is None:
            attributes.append(f'{name}="none"')
            continue
        hexes = [hex_colour(c[:3]) for c in colours]
        alphas = [number(c[3], 4) for c in colours]
        attributes += [f'{name}="{hexes[0]}"', f'{name}-opacity="{alphas[0]}"']
        inner += [animate(name, run.paint_frames, hexes, total, timing),
                  animate(f"{name}-opacity", run.paint_frames, alphas, total, timing)]
    if widths is not None and run.stroke is not None:
        numbers = [number(w, 4) for w in widths]
        attributes += [f'stroke-width="{numbers[0]}"', f'stroke-linecap="{run.cap}"',
                       f'stroke-linejoin="{run.join}"', f'stroke-miterlimit="{number(run.miter_limit, 4)}"']
        inner.append(animate("stroke-width", run.paint_frames, numbers, total, timing))
        if run.dash is not None:
            rows = run.dash[members[0]]
            patterns = [" ".join(number(float(v), 4) for v in row[:-1]) for row in rows]
            offsets = [number(float(row[-1]), 4) for row in rows]
            attributes += [f'stroke-dasharray="{patterns[0]}"', f'stroke-dashoffset="{offsets[0]}"']
            inner += [animate("stroke-dasharray", run.paint_frames, patterns, total, timing),
                      animate("stroke-dashoffset", run.paint_frames, offsets, total, timing)]
    return attributes, inner


def _element(tag: str, attributes: list[str], inner: list[str]) -> list[str]:
    """``<tag attributes…>`` holding the animations ``inner`` (those that are ``""`` left out), or empty."""
    inner = [line for line in inner if line]
    if not inner:
        return [f"<{tag} " + " ".join(attributes) + "/>"]
    return [f"<{tag} " + " ".join(attributes) + ">", *inner, f"</{tag}>"]


def _length(lines: list[str]) -> int:
    return sum(len(line) + 1 for line in lines)


def _static_opacity(run: VectorRun) -> str:
    opacity = float(run.opacity[0])
    return "" if opacity == 1.0 else f' opacity="{number(opacity, 4)}"'

