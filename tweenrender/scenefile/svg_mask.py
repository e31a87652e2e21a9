"""SVG masks read into world units: each ``<mask>`` an element names, as a :class:`~tweenrender.model.Mask`.

As SVG 1.1 §14.4 and CSS Masking define them: the mask's region is its ``x``, ``y``, ``width``,
``height`` (default -10%, -10%, 120%, 120%) in ``maskUnits`` (default ``objectBoundingBox``: fractions of
the masked element's bounding box in its user space; ``userSpaceOnUse``: that user space, percentages of
the viewport); its content is drawn in the element's user space, or in its bounding box with
``maskContentUnits="objectBoundingBox"``. ``mask-type="alpha"`` (attribute or style) takes the content's
alpha; otherwise its luminance times alpha (of its colours in linear RGB with
``color-interpolation="linearRGB"``). A ``mask`` on the ``<mask>`` masks its content.

As browsers do: a reference to no ``<mask>`` draws the element unmasked; a reference that leads back into
the masks being read (a mask on itself, two masks on each other) is ignored; an element whose mask needs
its bounding box while it has none (a horizontal line) is not drawn, nor one whose mask's region is empty.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..model import Contour, Mask, MaskShape, frozen_points
from .svg_document import (
    MAX_EXPANDED,
    Document,
    Drawn,
    Masking,
    Node,
    _Walk,
    length,
    matrix,
    own_style,
)
from .svg_flatten import Budget, Refusal

__all__ = ["Reading", "element_masks"]

_HIDDEN = "hidden"
"""A mask that lets nothing of its element through."""
_DEFAULT_REGION = {"x": -0.1, "y": -0.1, "width": 1.2, "height": 1.2}
_Box = tuple[float, float, float, float]
_LENGTH = re.compile(r"\s*[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?(?:px|pt|pc|mm|cm|in|%)?\s*$")


@dataclass(frozen=True)
class Reading:
    """What reading masks takes from the reading of the drawing: ``to_world`` (3x3) maps user units to world
    units; ``view`` is the viewport's width and height in user units (what percentages are of); ``shape``
    reads a drawn element of a mask's content (inside the masks named) into world units, None when it draws
    nothing; ``outline`` gives a drawn element's contours ``(N_i, 2)`` placed by a 3x3 map."""

    to_world: NDArray[np.float64]
    view: tuple[float, float]
    shape: Callable[[Drawn, tuple[str, ...]], MaskShape | None]
    outline: Callable[[Drawn, NDArray[np.float64]], list[NDArray[np.float64]]]


def element_masks(d: Drawn, reading: Reading, budget: Budget, chain: tuple[str, ...] = ()
                  ) -> tuple[Mask, ...] | None:
    """The masks on ``d`` and its ancestors in world units; None when one of them lets nothing of it through.
    ``chain``: the masks being read around this one; ``budget`` keeps what is worked out once."""
    out = []
    for masking in d.masks:
        mask = _cached_mask(masking, d.document, reading, budget, chain)
        if mask == _HIDDEN:
            return None
        if mask is not None:
            out.append(mask)
    return tuple(out)  # type: ignore[arg-type]


def _reference(style: dict[str, str]) -> str | None:
    value = style.get("mask", "none").strip()
    if not value.startswith("url("):
        return None
    target = value[4:].partition(")")[0].strip().strip("'\"")
    return target.removeprefix("#")


def _cached_mask(masking: Masking, document: Document, reading: Reading, budget: Budget,
                 chain: tuple[str, ...]) -> Mask | str | None:
    """:func:`_mask`, worked out once per masked element (the children of a masked group share it)."""
    ident, space, node = masking
    key = ("mask", ident, id(node), space.tobytes(), chain)
    if key not in budget.memo:
        budget.memo[key] = _mask(ident, space, node, document, reading, budget, chain)
    return budget.memo[key]  # type: ignore[return-value]


def _mask(ident: str, space: NDArray[np.float64], node: Node, document: Document, reading: Reading,
          budget: Budget, chain: tuple[str, ...]) -> Mask | str | None:
    """``<mask id=ident>`` on ``node`` (whose user space is ``space``): a Mask, :data:`_HIDDEN`, or None (no
    mask: the reference is ignored)."""
    found = document.ids.get(ident)
    if not found or found[0].tag != "mask" or not found[0].svg:
        return None
    if ident in chain or _leads_into(ident, chain, document, set()):
        return None
    mask_node = found[0]
    style = own_style(mask_node, document)
    on_user_space = mask_node.attrs.get("maskUnits", "").strip() == "userSpaceOnUse"
    content_on_box = mask_node.attrs.get("maskContentUnits", "").strip() == "objectBoundingBox"
    box = _box(node, space, document, reading, budget)
    if (not on_user_space or content_on_box) and (box is None or box[2] <= 0 or box[3] <= 0):
        return _HIDDEN
    region = _region(mask_node, on_user_space, box, reading.view)
    if region is None:
        return _HIDDEN
    x, y, w, h = region
    corners = np.array([[x, y, 1.0], [x + w, y, 1.0], [x + w, y + h, 1.0], [x, y + h, 1.0]]).T
    outline = ((reading.to_world @ space @ corners)[:2].T).copy()
    content_space = space
    if content_on_box:
        bx, by, bw, bh = box  # type: ignore[misc]
        content_space = space @ np.array([[bw, 0.0, bx], [0.0, bh, by], [0.0, 0.0, 1.0]])
    inner = chain + (ident,)
    key = ("content", ident, content_space.tobytes(), inner)  # shared by the elements masked in one space
    if key not in budget.memo:
        budget.memo[key] = _content(mask_node, style, content_space, document, reading, budget, inner)
    shapes: tuple[MaskShape, ...] = budget.memo[key]  # type: ignore[assignment]
    masks: tuple[Mask, ...] = ()
    own = _reference(style)
    if own is not None and own not in inner and not _leads_into(own, inner, document, set()):
        on_mask = _cached_mask((own, space, node), document, reading, budget, inner)
        if on_mask == _HIDDEN:
            return _HIDDEN
        masks = (on_mask,) if isinstance(on_mask, Mask) else ()
    alpha = style.get("mask-type", "luminance").strip() == "alpha"
    linear = style.get("color-interpolation", "sRGB").strip() == "linearRGB"
    return Mask((Contour(frozen_points(outline), True),), shapes, alpha, masks, linear)


def _region(mask_node: Node, on_user_space: bool, box: _Box | None, view: tuple[float, float]) -> _Box | None:
    """The mask's region ``(x, y, width, height)`` in the masked element's user space; None when empty."""
    if on_user_space:
        sizes = {"x": view[0], "y": view[1], "width": view[0], "height": view[1]}
        values = {k: _length(mask_node, k, v * sizes[k], sizes[k]) for k, v in _DEFAULT_REGION.items()}
        x, y, w, h = values["x"], values["y"], values["width"], values["height"]
    else:
        bx, by, bw, bh = box  # type: ignore[misc]
        values = {k: _length(mask_node, k, v, 1.0) for k, v in _DEFAULT_REGION.items()}
        x, y = bx + values["x"] * bw, by + values["y"] * bh
        w, h = values["width"] * bw, values["height"] * bh
    if not (w > 0 and h > 0 and all(np.isfinite((x, y, w, h)))):
        return None
    return (x, y, w, h)


def _length(node: Node, name: str, default: float, relative: float) -> float:
    """A length of the region, its default where it is not a length (as browsers do with an invalid value)."""
    if not _LENGTH.match(node.attrs.get(name, "0")):
        return default
    try:
        return length(node, name, default, relative)
    except Refusal:
        return default


def _box(node: Node, space: NDArray[np.float64], document: Document, reading: Reading, budget: Budget
         ) -> _Box | None:
    """The bounding box ``(x, y, width, height)`` of what ``node`` draws (its geometry, strokes left out), in
    its user space ``space``; None when it draws nothing. Elements hidden by ``visibility`` are in it, as
    browsers take them."""
    to_world = reading.to_world
    own = np.eye(3)
    if node is not document.root and "transform" in node.attrs:
        own = matrix(node.attrs["transform"], node.line)
    try:
        local = np.linalg.inv(own)
        back = np.linalg.inv(to_world @ space)
    except np.linalg.LinAlgError:
        return None
    points = []
    walker = _Walk(document, False)
    for drawn in walker.visit(node, {}, local, 1.0, True):  # hidden ones count too, undisplayed ones not (SVG 2)
        placed = to_world @ space @ drawn.ctm
        points += reading.outline(drawn, placed)
    _count(walker, budget)
    if not points:
        return None
    every = np.concatenate(points)
    user = (back @ np.column_stack([every, np.ones(len(every))]).T)[:2].T
    (x0, y0), (x1, y1) = user.min(axis=0), user.max(axis=0)
    return (float(x0), float(y0), float(x1 - x0), float(y1 - y0))


def _content(mask_node: Node, style: dict[str, str], space: NDArray[np.float64], document: Document,
             reading: Reading, budget: Budget, chain: tuple[str, ...]) -> tuple[MaskShape, ...]:
    """The shapes the mask's children draw, in world units, in paint order."""
    walker = _Walk(document, False)
    shapes = []
    for child in mask_node.children:
        for drawn in walker.visit(child, style, space, 1.0, True):
            shape = reading.shape(drawn, chain) if drawn.visible else None
            if shape is not None:
                shapes.append(shape)
    _count(walker, budget)
    return tuple(shapes)


def _count(walker: _Walk, budget: Budget) -> None:
    """Add the elements ``walker`` visited to those of every mask of the drawing, refused past
    :data:`MAX_EXPANDED` (many elements masked by large masks would otherwise cost their product)."""
    visited = int(budget.memo.get("mask elements", 0)) + walker.visited  # type: ignore[call-overload]
    budget.memo["mask elements"] = visited
    if visited > MAX_EXPANDED:
        raise Refusal(f"expected at most {MAX_EXPANDED} elements visited to read the drawing's masks, found more")


def _leads_into(ident: str, chain: tuple[str, ...], document: Document, seen: set[str]) -> bool:
    """Whether the ``<mask id=ident>`` (through the masks on it and on its content) names a mask of ``chain``."""
    if ident in seen:
        return False
    seen.add(ident)
    found = document.ids.get(ident)
    if not found or found[0].tag != "mask":
        return False
    stack = [found[0]]
    while stack:
        current = stack.pop()
        stack.extend(current.children)
        target = _reference(own_style(current, document))
        if target is not None and (target in chain or _leads_into(target, chain, document, seen)):
            return True
    return False
