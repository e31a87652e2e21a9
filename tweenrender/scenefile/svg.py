"""SVG drawings as keys: one element's contours (``points = { svg, id }``), or a whole drawing.

For one element, world units are the drawing's *user units* (the coordinates
written in the file, inside the root's viewBox), with ``world y = -svg y``; the
root's viewBox→viewport scaling is not applied, so ``width="100mm" viewBox="0 0 100 100"``
gives 100 units, not 378 CSS pixels. A whole drawing with a viewBox and an absolute
width and height is its viewport, the viewBox placed in it by ``preserveAspectRatio``. Lengths written with units inside the
drawing (``r="2mm"``) convert at 96 per inch, as CSS does. Curves are flattened
within a tolerance in world units (:mod:`.svg_flatten`).

A whole drawing (:func:`read_drawing`) gives every visible shape element —
``path``, ``rect``, ``circle``, ``ellipse``, ``line``, ``polyline``,
``polygon``, inside groups, ``<use>`` copies and nested transforms — with its
paint as an SVG renderer resolves it (:mod:`.svg_document`). Invisible
elements (no fill and no stroke, ``display:none``, ``visibility:hidden``, zero
opacity) are left out. Linear and radial gradient fills and strokes are kept
(:mod:`.svg_gradients`, :mod:`.svg_gradient_paint`), and patterns (:mod:`.svg_patterns`), clip paths
as clip regions (``Element.clips``), masks (``Element.masks``, :mod:`.svg_mask`), and the groups with an
opacity each element is in (``Element.groups``, :mod:`.svg_groups`). SVG's
error rules apply (:mod:`.svg_pathdata`): bad data is drawn up to its first error, an
element of negative size or a ``<use>`` loop is left out. Dashes are read into the stroke's paint
(:mod:`.svg_dashes`); markers become elements of their own after their element (:mod:`.svg_markers`). Not
drawn: filters.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..errors import SceneError, did_you_mean
from ..model import Color, Contour, Dash, Mask, MaskShape, Paint, Pattern, frozen_points
from .svg_basic_shapes import PREFIX as BASIC_SHAPE
from .svg_document import SHAPES, Document, Drawn, Node, compose, length, matrix, parse, read, walk
from .svg_flatten import Budget, Refusal, distinct, flatten, subpaths, zero_length_segment
from .svg_color import parse_color
from .svg_dashes import read_dash
from .svg_marker_style import MARKER_PROPERTIES
from .svg_gradients import stop_color
from .svg_image import PlacedImage
from .svg_groups import fold_lone_groups
from .svg_gradient_paint import with_gradients
from .svg_paint_order import in_paint_order
from .svg_patterns import pattern_content
from .svg_stroke_space import clipped_miters, in_stroke_space
from .svg_notes import note, noting
from .svg_pathdata import path_prefix, points_prefix, smooth_controls
from .svg_lengths import user_units
from .svg_viewport import aspect_matrix, parse_view_box, renders

__all__ = ["DEFAULT_TOLERANCE", "MAX_VERTICES", "SUPPORTED", "SvgError", "Element", "Drawing", "load_svg_points",
           "load_svg_contours", "read_drawing", "view_box"]

DEFAULT_TOLERANCE: float = 0.01
"""World units, for one element's key. Drawings are made tens to hundreds of user units across
(Inkscape's mm or px), so 0.01 is about a ten-thousandth of a drawing: under a pixel when it fills
a 1280-pixel frame, while a circle of radius 50 still needs only ~160 vertices."""

MAX_VERTICES: int = 200_000
"""Vertices of one element's key, or of a whole drawing, once flattened."""

SUPPORTED: tuple[str, ...] = SHAPES
"""The SVG elements that give outlines."""

_DRAWING_TOLERANCE = 1 / 5000
"""A whole drawing's default tolerance, as a fraction of its view box's diagonal (0.2 px at 1080p)."""
_EXTENT_TOLERANCE = 1.0
"""User units a drawing without a view box or size is flattened within to find its extent (its box only)."""
_NUMBER = r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?"
_PATH_TOKEN = re.compile(r"[\s,]*(?:[MmZzLlHhVvCcSsQqTtAa]|" + _NUMBER + ")")
_POINTS_TOKEN = re.compile(r"[\s,]*(" + _NUMBER + ")")
_SEPARATORS = re.compile(r"[\s,]*")
_FLIP = np.diag([1.0, -1.0, 1.0])


class SvgError(SceneError, ValueError):
    """A drawing or one of its elements cannot be read.

    ``str()`` is one line: ``drawing.svg#id: what was expected, what was found``
    (or ``drawing.svg: ...`` for the whole file).
    """

    def __init__(self, svg_path: str | Path, element_id: str | None, message: str) -> None:
        self.element_id = element_id
        super().__init__(svg_path, f"#{element_id}" if element_id else None, message)

    def __str__(self) -> str:
        return f"{self.path}{self.where or ''}: {self.message}"

    def __reduce__(self) -> tuple[type[SvgError], tuple[str | None, str | None, str]]:  # type: ignore[override]
        return type(self), (self.path, self.element_id, self.message)


@dataclass(frozen=True, slots=True)
class Element:
    """One drawn element of a drawing: its contours in world units and how it is painted.

    ``paint.stroke_width`` is in world units. ``line`` is where it is written in the file.
    """

    id: str | None
    tag: str
    line: int
    contours: tuple[Contour, ...]
    paint: Paint
    fill_rule: str
    cap: str
    join: str
    miter_limit: float
    clips: tuple[tuple[Contour, ...], ...] = ()  # clip regions (world units, nonzero), all of them intersected
    masks: tuple[Mask, ...] = ()  # masks (world units), all of them multiplied (:mod:`.svg_mask`)
    groups: tuple[tuple[int, float], ...] = ()  # the groups with an opacity it is in (:mod:`.svg_groups`)


@dataclass(frozen=True, slots=True)
class Drawing:
    """A whole drawing: its view box in world units ``(xmin, ymin, xmax, ymax)``, y up, and its elements.

    ``to_world`` is the 3 × 3 map from the SVG's user units (y down) to world units (``None``: unknown).
    """

    path: Path
    box: tuple[float, float, float, float]
    elements: tuple[Element, ...]
    to_world: NDArray[np.float64] | None = None


# -- one element by id ------------------------------------------------------------------------------


def load_svg_contours(svg_path: Path, element_id: str, tolerance: float = DEFAULT_TOLERANCE
                      ) -> list[tuple[NDArray[np.float64], bool]]:
    """Every contour of element ``element_id`` of the drawing: ``(points (N, 2), closed)`` pairs.

    World units (user units, y up), in the drawing's order, without closing or
    consecutive duplicates; hidden layers (``display:none``) are read too, since
    animators hide the keys they are not working on.
    """
    try:
        tol = _check_tolerance(tolerance)
        if not isinstance(element_id, str) or not element_id:
            raise Refusal(f"expected a non-empty element id, found {element_id!r}")
        document = _document(Path(svg_path))
        node = _find(document, element_id)
        drawn = next((d for d in walk(document, keep_hidden=True) if d.node is node), None)
        if drawn is None:
            raise Refusal(f"expected an element that is drawn, found one inside <defs> or another "
                          f"unrendered container (line {node.line})")
        contours = _contours(drawn, _FLIP @ drawn.ctm, tol, Budget(MAX_VERTICES, tol), lenient=False)
        if not contours:
            raise Refusal(_why_not_drawn(node))
        return contours
    except Refusal as refusal:
        raise SvgError(svg_path, str(element_id), str(refusal)) from refusal.__cause__


def load_svg_points(svg_path: Path, element_id: str, tolerance: float = DEFAULT_TOLERANCE) -> NDArray[np.float64]:
    """The one closed outline of element ``element_id``: ``(N, 2)``, N ≥ 3 (see :func:`load_svg_contours`).

    Raises :class:`SvgError` when the element has several contours or an open one.
    """
    contours = load_svg_contours(svg_path, element_id, tolerance)
    if len(contours) > 1:
        raise SvgError(svg_path, element_id, f"expected a single closed outline, found {len(contours)} "
                                             "subpaths (holes or separate pieces)")
    points, closed = contours[0]
    if len(points) < 3:
        raise SvgError(svg_path, element_id,
                       f"expected a closed outline of at least 3 distinct vertices, found {len(points)}")
    return points


def _find(document: Document, element_id: str) -> Node:
    ids = document.ids
    if element_id not in ids:
        shapes = [i for i, nodes in ids.items() if nodes[0].tag in SHAPES and nodes[0].svg]
        hint = did_you_mean(element_id, ids)
        listed = ", ".join(f'"{i}"' for i in shapes[:8])
        listed += f" and {len(shapes) - 8} more" if len(shapes) > 8 else ""
        have = f"shapes with ids: {listed}" if shapes else "no shape in the file has an id"
        raise Refusal(f"expected an element with this id, found none{hint} ({have})")
    found = ids[element_id]
    if len(found) > 1:
        lines = ", ".join(str(f.line) for f in found)
        raise Refusal(f"expected a unique id, found {len(found)} elements with it (lines {lines})")
    node = found[0]
    if node.tag not in SHAPES or not node.svg:
        kinds = ", ".join(f"<{tag}>" for tag in SHAPES)
        kind = f"<{node.tag}>" if node.svg else f"<{{other namespace}}{node.tag}>"
        raise Refusal(f"expected one of {kinds}, found {kind} (line {node.line})")
    return node


def _check_tolerance(tolerance: object) -> float:
    try:
        if isinstance(tolerance, bool):
            raise TypeError
        tol = float(tolerance)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise Refusal(f"expected a tolerance that is a positive number, found {tolerance!r}") from None
    if not (math.isfinite(tol) and tol > 0):
        raise Refusal(f"expected a finite tolerance > 0 (world units), found {tol!r}")
    return tol


# -- whole drawings -----------------------------------------------------------------------------------


def view_box(document: Document) -> tuple[float, float, float, float] | None:
    """The root's viewBox ``(x, y, width, height)`` in user units, else ``(0, 0, width, height)``; None if neither.

    A viewBox in error (unreadable, not finite, a negative size) is ignored, as SVG 1.1 §7.7 says; one of zero
    size disables rendering (:func:`renders`), and the drawing's size still lays it out."""
    root = document.root
    box = parse_view_box(root.attrs.get("viewBox"))
    if box is not None:
        return box
    w, h = length(root, "width", 0.0), length(root, "height", 0.0)
    if w > 0 and h > 0 and "%" not in root.attrs.get("width", "") + root.attrs.get("height", ""):
        return (0.0, 0.0, w, h)
    return None


def _root_viewport(document: Document) -> tuple[tuple[float, float, float, float] | None, NDArray[np.float64]]:
    """The drawing's box in its viewport's units and the map of its user units into them: with a
    ``viewBox`` and an absolute ``width`` and ``height``, the viewport ``(0, 0, width, height)`` and the
    ``preserveAspectRatio`` map; else the view box and the identity."""
    box = view_box(document)
    root = document.root
    sizes = root.attrs.get("width", ""), root.attrs.get("height", "")
    given = parse_view_box(root.attrs.get("viewBox"))
    if box is None or given is None or not all(t.strip() for t in sizes) or "%" in "".join(sizes):
        return box, np.eye(3)
    width, height = length(root, "width", 0.0), length(root, "height", 0.0)
    if not (width > 0 and height > 0 and math.isfinite(width) and math.isfinite(height)):
        return box, np.eye(3)
    return (0.0, 0.0, width, height), aspect_matrix(box, width, height, root.attrs.get("preserveAspectRatio", ""))


def read_drawing(svg_path: Path, tolerance: float | None = None,
                 into: tuple[float, float, float, float] | None = None) -> Drawing:
    """Every visible shape element of the drawing, in paint order, in world units.

    ``into`` is a world box ``(xmin, ymin, xmax, ymax)`` the drawing's view box is fitted into,
    centred with its aspect kept (``xMidYMid meet``); without it, world units are user units
    with y flipped. ``tolerance`` is in world units (default 1/5000 of the view box's diagonal).
    """
    try:
        with noting(Path(svg_path)):
            return _read_drawing(Path(svg_path), tolerance, into)
    except Refusal as refusal:
        raise SvgError(svg_path, None, str(refusal)) from refusal.__cause__


def _document(svg_path: Path) -> Document:
    """The drawing at ``svg_path`` parsed, knowing its folder (what an ``<image>``'s relative path is of)."""
    document = parse(read(svg_path))
    document.folder = svg_path.resolve().parent
    return document


def _read_drawing(svg_path: Path, tolerance: float | None,
                  into: tuple[float, float, float, float] | None) -> Drawing:
    """:func:`read_drawing`'s work, refusals raised as :class:`Refusal`."""
    document = _document(svg_path)
    box, placed = _root_viewport(document)
    drawn = [d for d in walk(document, layered=True) if d.visible] if renders(document.root) else []
    if box is None:  # no viewBox and no size: the elements' own extent
        box = _extent(drawn)
    x, y, w, h = box
    world = (-y - h, x + w, -y)  # the box flipped: ymin, xmax, ymax
    with np.errstate(all="ignore"):  # a tiny viewBox in a large size overflows: refused below
        to_world = _FLIP @ placed
        if into is not None:
            to_world = _fit((x, world[0], world[1], world[2]), into) @ _FLIP @ placed
    if not np.isfinite(to_world).all():
        raise Refusal(f"expected a viewBox whose scale into the drawing's size is finite, found "
                      f"viewBox {document.root.attrs.get('viewBox', '')!r}")
    if into is not None:
        world_box = into
    else:
        world_box = (x, world[0], world[1], world[2])
    scale = math.sqrt(abs(_determinant(to_world)))
    if tolerance is None:
        tolerance = math.hypot(world_box[2] - world_box[0], world_box[3] - world_box[1]) * _DRAWING_TOLERANCE
    tol = _check_tolerance(tolerance)
    budget = Budget(MAX_VERTICES, tol)
    elements = []
    for d in drawn:
        element = _element(d, to_world, scale, tol, budget)
        if element is not None:
            elements += [part for ordered in in_paint_order(element, d.style.get("paint-order", ""))
                         for part in in_stroke_space(ordered, to_world @ d.ctm, clipped_miters(d.style))]
        if any(d.style.get(name, "none").strip() != "none" for name in MARKER_PROPERTIES):
            elements += _marker_elements(d, to_world, scale, tol, budget)
    return Drawing(Path(svg_path), world_box, fold_lone_groups(elements), to_world)


def _fit(box: tuple[float, float, float, float], into: tuple[float, float, float, float]) -> NDArray[np.float64]:
    """The 3x3 map of world box ``box`` into world box ``into``, centred, aspect kept."""
    x0, y0, x1, y1 = box
    u0, v0, u1, v1 = into
    s = min((u1 - u0) / (x1 - x0), (v1 - v0) / (y1 - y0))
    dx = 0.5 * (u0 + u1) - s * 0.5 * (x0 + x1)
    dy = 0.5 * (v0 + v1) - s * 0.5 * (y0 + y1)
    return np.array([[s, 0.0, dx], [0.0, s, dy], [0.0, 0.0, 1.0]])


def _extent(drawn: list[Drawn]) -> tuple[float, float, float, float]:
    """A view box around every element's geometry (user units), for drawings with no viewBox or size."""
    points = []
    for d in drawn:
        for contour, _ in _contours(d, d.ctm, _EXTENT_TOLERANCE, Budget(MAX_VERTICES, _EXTENT_TOLERANCE)):
            points.append(contour)
    if not points:
        return (0.0, 0.0, 1.0, 1.0)
    every = np.concatenate(points)
    (x0, y0), (x1, y1) = every.min(axis=0), every.max(axis=0)
    return (float(x0), float(y0), max(float(x1 - x0), 1e-9), max(float(y1 - y0), 1e-9))


def _element(d: Drawn, to_world: NDArray[np.float64], scale: float, tol: float, budget: Budget,
             chain: tuple[str, ...] = ()) -> Element | None:
    """``d`` in world units, or None when it draws nothing (``chain``: the masks being read around it)."""
    paint, fill_rule, cap, join, miter = _paint(d, scale)
    if not paint.visible:
        return None
    masks = _masks(d, to_world, scale, tol, budget, chain) if d.masks else ()
    if masks is None:
        return None
    unstroked = paint.stroke is None or paint.stroke[3] == 0 or paint.stroke_width <= 0
    contours = _contours(d, to_world @ d.ctm, tol, budget, unstroked, dots=not unstroked and cap != "butt",
                         open_ends=not unstroked and cap != "round")
    if not contours:
        return None
    box = view_box(d.document) or (0.0, 0.0, 100.0, 100.0)
    tile_tol = tol / max(math.sqrt(abs(_determinant(to_world @ d.ctm))), 1e-300)
    placed, extent = to_world @ d.ctm, contours
    if d.paint_space is not None:  # a paint server of the context element's: in its space and box
        space, owner = d.paint_space
        placed = to_world @ space
        x0, y0, w, h = _owner_box(owner, space, d, to_world, tol, budget)
        corners = np.array([[x0, y0, 1.0], [x0 + w, y0, 1.0], [x0 + w, y0 + h, 1.0], [x0, y0 + h, 1.0]])
        extent = [((placed @ corners.T)[:2].T, True)]
    paint = with_gradients(paint, d.style, d.document, placed, extent, (box[2], box[3]),
                           lambda node, ctm: pattern_content(node, ctm, d.document, budget, lambda inner: _element(
                               inner, np.eye(3), 1.0, tile_tol, budget)))
    if d.image is not None:
        paint = replace(paint, pattern=_picture(d.image, placed))
    clips = tuple(region for ref in d.clips for region in _clip_regions(ref[0], ref[1], d, to_world, tol, budget,
                                                                          owner=getattr(ref, "owner", None)))
    return Element(d.node.attrs.get("id"), d.node.tag, d.node.line,
                   tuple(Contour(frozen_points(p), closed) for p, closed in contours), paint, fill_rule, cap, join,
                   miter, tuple(c for c in clips if c is not None), masks, d.groups)


def _picture(image: PlacedImage, placed: NDArray[np.float64]) -> Pattern:
    """An ``<image>``'s picture as the pattern its rectangle is filled with, ``placed`` (3x3) its user space
    in the world."""
    full = placed @ image.matrix
    height, width = image.pixels.shape[:2]
    return Pattern((0.0, 0.0, float(width), float(height)), (float(full[0, 0]), float(full[1, 0]), float(full[0, 1]),
                                                           float(full[1, 1]), float(full[0, 2]), float(full[1, 2])),
                   (), image=image.pixels, smooth=image.smooth)


def _marker_elements(d: Drawn, to_world: NDArray[np.float64], scale: float, tol: float, budget: Budget,
                     chain: tuple[int, ...] = ()) -> list[Element]:
    """The shapes of ``d``'s markers as elements of their own, in paint order (:mod:`.svg_markers`); a marker
    met again inside its own content (``chain``: the markers being drawn) is left out."""
    from .svg_markers import marker_content, placements

    shape = _geometry(d.node, d.document, True, d.viewport)
    segments = list(shape.segments(transformed=False)) if shape is not None else []
    stroke_width = _stroke_width(d.style.get("stroke-width", "1"), d)
    base = d.node.attrs.get("id") or f"{d.node.tag}@{d.node.line}"
    out: list[Element] = []
    for placed in placements(d, segments, stroke_width, length):
        if id(placed.marker) in chain:
            continue
        for k, inner in enumerate(marker_content(d, placed, budget.memo)):
            if not inner.visible:
                continue
            element = _element(inner, to_world, scale, tol, budget)
            if element is not None:
                out.append(replace(element, id=f"{base}:marker-{placed.kind}{placed.index}.{k}", groups=d.groups))
            if any(inner.style.get(name, "none").strip() != "none" for name in MARKER_PROPERTIES):
                out += _marker_elements(inner, to_world, scale, tol, budget, chain + (id(placed.marker),))
    return out


def _masks(d: Drawn, to_world: NDArray[np.float64], scale: float, tol: float, budget: Budget,
           chain: tuple[str, ...]) -> tuple[Mask, ...] | None:
    """The masks on ``d`` in world units (:mod:`.svg_mask`); None when they let nothing of it through."""
    from .svg_mask import Reading, element_masks

    def shape(drawn: Drawn, inner: tuple[str, ...]) -> MaskShape | None:
        e = _element(drawn, to_world, scale, tol, budget, inner)
        return None if e is None else MaskShape(e.contours, e.paint, e.fill_rule, e.cap, e.join, e.miter_limit,
                                                e.clips, e.masks)

    def outline(drawn: Drawn, placed: NDArray[np.float64]) -> list[NDArray[np.float64]]:
        return [p for p, _ in _contours(drawn, placed, tol, Budget(MAX_VERTICES, tol), True)]

    box = view_box(d.document) or (0.0, 0.0, 100.0, 100.0)
    return element_masks(d, Reading(to_world, (box[2], box[3]), shape, outline), budget, chain)


def _clip_regions(ident: str, space: NDArray[np.float64], d: Drawn, to_world: NDArray[np.float64], tol: float,
                  budget: Budget, seen: tuple[str, ...] = (), owner: Node | None = None) -> list[tuple[Contour, ...]]:
    """The regions of ``<clipPath id=ident>`` in world units (each its shapes' closed contours, nonzero), to be
    intersected: its own, and those of the clip path on it (SVG 1.1 §14.3.5), applied in the user ``space``
    of the element that names it; none when ``ident`` is no clip path. A clip-path that leads back into
    the chain is ignored."""
    from .svg_document import own_style

    if ident.startswith(BASIC_SHAPE):
        return _basic_shape_region(ident.removeprefix(BASIC_SHAPE), space, d, to_world, tol, budget, owner)
    nodes = d.document.ids.get(ident)
    if not nodes or nodes[0].tag != "clipPath":
        return []
    if ident in seen:
        return []  # a clip path's clip-path in a loop is ignored
    regions = [_clip_region(nodes[0], ident, space, d, to_world, tol, budget, seen + (ident,), owner)]
    reference = own_style(nodes[0], d.document).get("clip-path", "none").strip()
    if reference.startswith("url("):
        target = reference[4:].partition(")")[0].strip().strip("'\"")
        regions += _clip_regions(target.removeprefix("#"), space, d, to_world, tol, budget, seen + (ident,), owner)
    return regions


def _basic_shape_region(value: str, space: NDArray[np.float64], d: Drawn, to_world: NDArray[np.float64],
                        tol: float, budget: Budget, owner: Node | None = None) -> list[tuple[Contour, ...]]:
    """The region of ``clip-path: circle(…)`` named by ``owner`` (``d`` or a group around it) in world units
    (:mod:`.svg_basic_shapes`); none when the value is not one that is read."""
    from .svg_basic_shapes import circle_outline
    from .svg_viewport import root_size

    x0, y0, w, h = _owner_box(owner, space, d, to_world, tol, budget)
    if d.viewport is not None:
        view = (0.0, 0.0, *d.viewport)
    else:
        view = view_box(d.document) or (0.0, 0.0, *root_size(d.document.root))
    stroked = d.style.get("stroke", "none").strip() not in ("none", "")
    scale = math.sqrt(abs(_determinant(to_world @ space))) or 1.0
    outline = circle_outline(value, (x0, y0, w, h), _stroke_width(d.style.get("stroke-width", "1"), d)
                             if stroked and owner in (None, d.node) else 0.0, view, tol / scale)
    if outline is None:
        return []
    placed = (to_world @ space @ np.column_stack([outline, np.ones(len(outline))]).T)[:2].T
    return [(Contour(frozen_points(placed), True),)] if len(placed) >= 3 else [()]


def _owner_box(owner: Node | None, space: NDArray[np.float64], d: Drawn, to_world: NDArray[np.float64], tol: float,
               budget: Budget) -> tuple[float, float, float, float]:
    """The bounding box ``(x, y, width, height)`` of what ``owner`` draws (``d`` itself when None) in its user
    ``space`` (strokes left out); ``(0, 0, 0, 0)`` when it draws nothing."""
    if owner is None or owner is d.node:
        every = np.concatenate([p for p, _ in _contours(d, np.eye(3), tol, budget, True)] or [np.zeros((1, 2))])
        (x0, y0), (x1, y1) = every.min(axis=0), every.max(axis=0)
        return (float(x0), float(y0), float(x1 - x0), float(y1 - y0))
    from .svg_mask import Reading, _box

    def outline(drawn: Drawn, placed: NDArray[np.float64]) -> list[NDArray[np.float64]]:
        return [p for p, _ in _contours(drawn, placed, tol, Budget(MAX_VERTICES, tol), True)]

    key = ("clip box", id(owner), space.tobytes())
    if key not in budget.memo:
        box = view_box(d.document) or (0.0, 0.0, 100.0, 100.0)
        budget.memo[key] = _box(owner, space, d.document, Reading(to_world, (box[2], box[3]), lambda *_: None,
                                                                   outline), budget)
    found = budget.memo[key]
    return found if found is not None else (0.0, 0.0, 0.0, 0.0)  # type: ignore[return-value]


def _clip_region(clip: Node, ident: str, space: NDArray[np.float64], d: Drawn, to_world: NDArray[np.float64],
                 tol: float, budget: Budget, seen: tuple[str, ...] = (), owner: Node | None = None
                 ) -> tuple[Contour, ...]:
    """The region of one ``<clipPath>`` in world units (its shapes' closed contours, nonzero), each child
    cut by its own clip path (``seen``: the clip paths being read around it, ignored when met again)."""
    from .svg_clip_children import intersection, valid_clip_child
    from .svg_clip_rule import inherited_clip_rule, union_by_rule
    from .svg_document import _Walk, own_style
    from .svg_transform_origin import about_origin, parse_origin
    from .svg_viewport import root_size

    units = clip.attrs.get("clipPathUnits", "userSpaceOnUse").strip()
    if units == "objectBoundingBox":
        x0, y0, w, h = _owner_box(owner, space, d, to_world, tol, budget)
        on_box = np.array([[w, 0.0, x0], [0.0, h, y0], [0.0, 0.0, 1.0]])
    if "transform" in clip.attrs:  # in the user space, around the bounding box's units (as browsers do)
        box = d.viewport or root_size(d.document.root)
        step = about_origin(matrix(clip.attrs["transform"], clip.line), parse_origin(
            clip.attrs.get("transform-origin", ""), box, clip.font, clip.view))
        space = compose(space, step, clip, f"transform {clip.attrs['transform'].strip()[:80]!r}")
    if units == "objectBoundingBox":
        space = space @ on_box
    walker = _Walk(d.document, False)

    def own_rule(node: Node) -> str | None:  # the cascade only where a clip-rule may be written
        if "clip-rule" in node.attrs or "clip-rule" in node.attrs.get("style", "") or \
                any("clip-rule" in layer for layer in d.document.sheet.get(id(node), ())):
            return own_style(node, d.document).get("clip-rule")
        return None

    rule = inherited_clip_rule(clip, d.document, own_rule)
    children = []
    for child in clip.children:
        if not valid_clip_child(child, d.document.ids):
            continue
        for shape in walker.visit(child, {"clip-rule": rule}, space, 1.0, True):
            if not shape.visible:
                continue
            shape_rule = shape.style.get("clip-rule", "nonzero").strip()
            contours = [p for p, _ in _contours(shape, to_world @ shape.ctm, tol, budget, True) if len(p) >= 3]
            if shape.clips:  # the child's own clip path
                own = [[c.points for c in r] for ref in shape.clips if ref[0] not in seen
                       for r in _clip_regions(ref[0], ref[1], shape, to_world, tol, budget, seen,
                                              getattr(ref, "owner", None))]
                contours, shape_rule = intersection(contours, shape_rule, own), "nonzero"
            children.append((shape_rule, contours))
    return tuple(Contour(frozen_points(p), True) for p in union_by_rule(children))


# -- paint ---------------------------------------------------------------------------------------------


def _determinant(matrix: np.ndarray) -> float:
    """The determinant of the linear part of an affine ``matrix (3, 3)``, in closed form on Python floats:
    numpy's LU route warns (divide by zero) on subnormal entries, and float overflow gives inf or nan
    quietly here."""
    (a, c), (b, d) = matrix[:2, :2].tolist()
    return a * d - b * c


def _paint(d: Drawn, scale: float) -> tuple[Paint, str, str, str, float]:
    """The element's paint (stroke width in world units), fill rule, cap, join and miter limit."""
    style = d.style
    fill = _color(style.get("fill", "black"), style, d.document, _number(style.get("fill-opacity"), 1.0))
    stroke = _color(style.get("stroke", "none"), style, d.document, _number(style.get("stroke-opacity"), 1.0))
    width_text = style.get("stroke-width", "1")
    width = _stroke_width(width_text, d) * math.sqrt(abs(_determinant(d.ctm))) * scale
    fill_rule = "evenodd" if style.get("fill-rule", "nonzero").strip() == "evenodd" else "nonzero"
    cap = style.get("stroke-linecap", "butt").strip()
    join = style.get("stroke-linejoin", "miter").strip()
    join = "miter" if join in ("miter-clip", "arcs") else join
    miter = _miter_limit(style.get("stroke-miterlimit"))
    dash = read_dash(style, d.node.font, _viewport_diagonal(d), math.sqrt(abs(_determinant(d.ctm))) * scale)
    if dash is not None and "pathLength" in d.node.attrs:
        dash = _along_path_length(dash, d)
    return (Paint(fill, stroke, width, d.opacity, dash=dash), fill_rule,
            cap if cap in ("butt", "round", "square") else "butt",
            join if join in ("miter", "round", "bevel") else "miter", miter)


def _number(text: str | None, default: float) -> float:
    if text is None:
        return default
    try:
        value = float(text.strip().rstrip("%")) / (100.0 if text.strip().endswith("%") else 1.0)
    except ValueError:
        return default
    return min(max(value, 0.0), 1.0) if math.isfinite(value) else default


def _miter_limit(text: str | None) -> float:
    """``stroke-miterlimit``: a number ≥ 1; any other value is in error and the initial 4 applies."""
    try:
        value = float((text or "4").strip())
    except ValueError:
        return 4.0
    return value if math.isfinite(value) and value >= 1.0 else 4.0


def _stroke_width(text: str, d: Drawn) -> float:
    """``stroke-width`` in user units (percentages of the viewport's normalised diagonal); 1 where in error."""
    value = user_units(text, d.node.font, d.node.view, _diagonal(d.document))
    return value if value is not None and value >= 0 else 1.0


def _along_path_length(dash: Dash, d: Drawn) -> Dash:
    """``dash`` in the units of the element's ``pathLength`` (:func:`.svg_dashes.along_path_length`)."""
    from .svg_dashes import along_path_length

    shape = _geometry(d.node, d.document, True, d.viewport)
    try:
        length = float(shape.length()) if shape is not None else 0.0
    except Exception:  # a third-party measure on arbitrary input: no length, no scaling
        length = 0.0
    return along_path_length(dash, d.node.attrs.get("pathLength"), length)


def _viewport_diagonal(d: Drawn) -> float:
    """The normalised diagonal of the viewport ``d`` is in: what its percentages of lengths are of."""
    if d.viewport is not None:
        return math.hypot(*d.viewport) / math.sqrt(2)
    return _diagonal(d.document)


def _diagonal(document: Document) -> float:
    box = view_box(document) or (0.0, 0.0, 100.0, 100.0)
    return math.hypot(box[2], box[3]) / math.sqrt(2)


def _color(text: str, style: dict[str, str], document: Document, opacity: float) -> Color | None:
    """A paint value as straight RGBA: ``none`` → None; ``currentColor`` → the ``color`` property
    (black by default); ``url(#gradient)`` → the average of its stops; else a CSS colour."""
    value = text.strip()
    if value in ("none", "transparent") or not value:
        return None
    if value.startswith("url("):
        ref, _, fallback = value[4:].partition(")")
        found = _gradient_color(ref.strip().strip("'\"").lstrip("#"), document)
        if found is None:
            return _color(fallback.strip() or "black", style, document, opacity) if fallback.strip() else None
        r, g, b, a = found
        return (r, g, b, int(round(a * opacity)))
    if value.lower() == "currentcolor":
        value = style.get("color", "black").strip() or "black"
        if value.lower() == "currentcolor":
            value = "black"
    c = parse_color(value)
    if c is None:
        return (0, 0, 0, int(round(255 * opacity)))  # an unreadable colour: black, as browsers fall back
    return (c[0], c[1], c[2], int(round(c[3] * opacity)))


def _gradient_color(ident: str, document: Document, depth: int = 0) -> Color | None:
    nodes = document.ids.get(ident)
    if not nodes or depth > 8:
        return None
    node = nodes[0]
    if node.tag == "pattern":
        return (128, 128, 128, 255)  # its tile's mean colour once read (.svg_gradient_paint)
    if node.tag not in ("linearGradient", "radialGradient"):
        return None  # stops are taken from gradients only
    stops = [c for c in node.children if c.tag == "stop"]
    if not stops:
        href = node.attrs.get("href", node.attrs.get("xlink:href", ""))
        return _gradient_color(href.lstrip("#"), document, depth + 1) if href.startswith("#") else None
    colours = []
    for stop in stops:
        colours.append(stop_color(stop, node, document))
    if not colours:
        return None
    mean = np.mean(np.array(colours, dtype=float), axis=0)
    return (int(round(mean[0])), int(round(mean[1])), int(round(mean[2])), int(round(mean[3])))


# -- geometry ------------------------------------------------------------------------------------------


def _contours(d: Drawn, to_world: NDArray[np.float64], tol: float, budget: Budget, unstroked: bool = False,
              lenient: bool = True, dots: bool = False, open_ends: bool = False
              ) -> list[tuple[NDArray[np.float64], bool]]:
    """The element's subpaths flattened into world contours, without degenerate ones.

    ``lenient``: SVG's error rules (bad data drawn up to its first error, a negative size not drawn);
    else such an element is refused (one element asked for by id).

    A subpath is closed when it ends in Z, or ends where it starts (unless ``open_ends``: a stroke whose
    butt or square caps show there, as SVG strokes such a subpath open); with ``unstroked`` (an
    element drawn without a stroke, whose fill closes every subpath anyway) every subpath of
    three vertices or more is. With ``dots`` (a stroke with round or square caps), a subpath of zero length
    is kept as a segment ``tol`` long along the user x axis, which its caps draw as a dot (SVG 1.1 §11.4).
    """
    if not np.all(np.isfinite(to_world)) or abs(_determinant(to_world)) == 0:
        return []  # a transform that collapses the element: nothing is drawn (as in SVG)
    shape = _geometry(d.node, d.document, lenient, d.viewport)
    if shape is None:
        return []
    try:
        segments_all = list(shape.segments(transformed=False))
    except Exception as error:  # a third-party parser on arbitrary input: report, do not crash
        raise Refusal(_why_not_drawn(d.node)) from error
    out = []
    for segments, closed in subpaths(segments_all, dots):
        points = distinct(flatten(segments, to_world, tol, budget), False)
        if len(points) == 1:
            if dots:
                out.append((zero_length_segment(points[0], to_world, tol), False))
            continue
        returns = len(points) > 2 and bool(np.allclose(points[0], points[-1], rtol=0.0,
                                                       atol=1e-9 * float(np.ptp(points, axis=0).max())))
        closed = closed or (returns and not open_ends) or unstroked
        points = distinct(points, closed)
        if len(points) >= 2:
            out.append((points, closed and len(points) >= 3))
    return out


def _geometry(node: Node, document: Document, lenient: bool = True,  # type: ignore[no-untyped-def]
              viewport: tuple[float, float] | None = None):
    """The element as an svgelements shape in its own coordinates, or None when SVG draws nothing
    (``lenient``: by SVG's error rules; else a bad element is refused). Percentages are of ``viewport``
    ``(width, height)``, by default the root's view box."""
    from svgelements import Circle, Ellipse, Path, Polygon, Polyline, Rect, SimpleLine

    w, h = viewport or (view_box(document) or (0.0, 0.0, 100.0, 100.0))[2:]
    diag = math.hypot(w, h) / math.sqrt(2)
    tag = node.tag
    if lenient:
        if tag in ("path", "polygon", "polyline"):
            _within_limit(node.attrs.get("d" if tag == "path" else "points", ""), node)
        negative = [name for name in ("width", "height", "r") if node.attrs.get(name, "").strip().startswith("-")]
        if negative:  # SVG: a negative size is an error, and the element is not rendered
            note(f"<{tag}> of negative {negative[0]} (line {node.line})")
            return None
    else:
        _check_syntax(node)
    if tag == "path":
        d = _prefix(path_prefix, node, "d") if lenient else node.attrs.get("d", "")
        if not d:
            return None
        try:
            return smooth_controls(Path(d))
        except Exception as error:  # svgelements refuses data with too few numbers for a command
            raise Refusal(_why_not_drawn(node)) from error
    if tag in ("polygon", "polyline"):
        cls = Polygon if tag == "polygon" else Polyline
        points = node.attrs.get("points", "")
        return cls({"points": _prefix(points_prefix, node, "points") if lenient else points})
    if tag == "line":
        return SimpleLine({k: str(length(node, k, 0.0, w if k[0] == "x" else h)) for k in ("x1", "y1", "x2", "y2")})
    if tag == "rect":
        width, height = length(node, "width", 0.0, w), length(node, "height", 0.0, h)
        if width <= 0 or height <= 0:
            return None
        values = {"x": length(node, "x", 0.0, w), "y": length(node, "y", 0.0, h), "width": width, "height": height}
        for k, rel in (("rx", w), ("ry", h)):
            if k in node.attrs and not node.attrs[k].strip().startswith("-"):  # a negative radius is auto
                values[k] = length(node, k, 0.0, rel)
        return Rect({k: str(v) for k, v in values.items()})
    if tag == "circle":
        r = length(node, "r", 0.0, diag)
        if r <= 0:
            return None
        return Circle({"cx": str(length(node, "cx", 0.0, w)), "cy": str(length(node, "cy", 0.0, h)), "r": str(r)})
    if tag == "ellipse":
        radii = [node.attrs.get(k, "auto").strip() for k in ("rx", "ry")]
        if lenient and any(r == "auto" or r.startswith("-") for r in radii):  # SVG 2: auto is the other radius
            valid = [(k, rel) for k, r, rel in (("rx", radii[0], w), ("ry", radii[1], h))
                     if r != "auto" and not r.startswith("-")]
            if not valid:
                return None
            rx = ry = length(node, valid[0][0], 0.0, valid[0][1])
        else:
            rx, ry = length(node, "rx", 0.0, w), length(node, "ry", 0.0, h)
        if rx <= 0 or ry <= 0:
            return None
        return Ellipse({"cx": str(length(node, "cx", 0.0, w)), "cy": str(length(node, "cy", 0.0, h)),
                        "rx": str(rx), "ry": str(ry)})
    return None


def _prefix(prefix: Callable[[str], tuple[str, bool]], node: Node, name: str) -> str:
    """What SVG draws of the ``d`` or ``points`` attribute ``name``: all of it, or what comes before its first
    error (noted as skipped)."""
    text = node.attrs.get(name, "")
    drawn, whole = prefix(text)
    if not whole:
        note(f"the {name} of <{node.tag}> from its first error on (line {node.line})")
    return drawn


def _check_syntax(node: Node) -> None:
    """Refuse what svgelements would silently truncate (stray characters, odd coordinates) and path
    data too large to be within the vertex limit, before it is parsed."""
    if node.tag == "path":
        d = node.attrs.get("d", "")
        if not d.strip():
            raise Refusal(f"expected path data, found an empty or missing d (line {node.line})")
        _within_limit(d, node)
        position = _scan_tokens(_PATH_TOKEN, d)
        if position is not None:
            raise Refusal(f"expected path data of commands and numbers, found {_excerpt(d, position)!r} "
                          f"at character {position + 1} (line {node.line})")
        if d.strip()[0] not in "Mm":
            raise Refusal(f"expected path data that starts with M or m, found {_excerpt(d, 0)!r} (line {node.line})")
    elif node.tag in ("polygon", "polyline"):
        points = node.attrs.get("points", "")
        _within_limit(points, node)
        position = _scan_tokens(_POINTS_TOKEN, points)
        if position is not None:
            raise Refusal(f"expected points as numbers, found {_excerpt(points, position)!r} "
                          f"at character {position + 1} (line {node.line})")
        count = len(_POINTS_TOKEN.findall(points))
        if count % 2:
            raise Refusal(f"expected points as x,y pairs, found an odd count of numbers ({count}) (line {node.line})")
    for name in ("width", "height", "r", "rx", "ry"):  # SVG: a negative size is an error
        if node.attrs.get(name, "").strip().startswith("-"):
            raise Refusal(f"expected {name} ≥ 0, found {name}={node.attrs[name]!r} (line {node.line})")


def _within_limit(text: str, node: Node) -> None:
    """Refuse data whose numbers alone prove more than :data:`MAX_VERTICES` vertices, in one pass.

    Every number lies within one run of number characters (digits, ``.``, ``e``, signs), so the
    runs bound the numbers from below; a vertex takes at most 7 numbers (an arc), 6 without arcs
    (a cubic), 2 with lines only.
    """
    per_vertex = 7 if ("A" in text or "a" in text) else 6 if any(c in text for c in "CcSsQqTt") else 2
    if len(text) < 2 * per_vertex * MAX_VERTICES:
        return  # too short to hold that many numbers
    chars = np.frombuffer(text.encode("ascii", "replace"), dtype=np.uint8)
    number = np.isin(chars, np.frombuffer(b"0123456789.eE+-", dtype=np.uint8))
    runs = int(np.count_nonzero(number[1:] & ~number[:-1])) + int(number[0])
    if runs // per_vertex > MAX_VERTICES:
        raise Refusal(f"expected at most {MAX_VERTICES} vertices, found data for more "
                      f"({len(text)} characters, line {node.line})")


def _scan_tokens(token: re.Pattern[str], text: str) -> int | None:
    """The index of the first character ``token`` cannot read, or None when all is read."""
    position = 0
    while (match := token.match(text, position)) is not None and match.end() > position:
        position = match.end()
    position = _SEPARATORS.match(text, position).end()  # type: ignore[union-attr]
    return None if position == len(text) else position


def _excerpt(text: str, position: int) -> str:
    rest = text[position:]
    return rest if len(rest) <= 24 else rest[:24] + "…"


def _why_not_drawn(node: Node) -> str:
    """Why an element gives no outline (svgelements skips bad or empty geometry)."""
    if node.tag == "path":
        d = node.attrs.get("d", "")
        return (f"expected path data with the right count of numbers per command that draws distinct vertices, "
                f"found {_excerpt(d, 0)!r} (line {node.line})")
    if node.tag in ("polygon", "polyline"):
        points = node.attrs.get("points", "")
        least = 3 if node.tag == "polygon" else 2
        return f"expected at least {least} distinct vertices, found points={_excerpt(points, 0)!r} (line {node.line})"
    geometry = " ".join(f'{k}="{v}"' for k, v in node.attrs.items()
                        if k in ("x", "y", "width", "height", "rx", "ry", "cx", "cy", "r", "x1", "y1", "x2", "y2"))
    return (f"expected a <{node.tag}> of positive size, found one that draws nothing "
            f"({geometry or 'no geometry'}, line {node.line})")
