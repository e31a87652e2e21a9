"""An SVG file read safely into a tree, and walked into the elements it draws.

The XML is read with expat (bounded size, element count and depth; a DTD subset may
declare only plain internal entities, :mod:`.svg_entities`). Walking the tree resolves
what an SVG renderer would: CSS (presentation attributes, ``<style>`` sheets matched by
:mod:`.svg_css`, inline ``style``, ``!important``), inheritance, ``currentColor``,
transforms (about their ``transform-origin``, :mod:`.svg_transform_origin`), ``display``,
``visibility`` and group ``opacity``, nested viewports (:mod:`.svg_viewport`), lengths
relative to the font and the viewport (:mod:`.svg_lengths`), ``<switch>`` and conditional
attributes (:mod:`.svg_conditions`), ``<text>`` (its glyphs' outlines, :mod:`.svg_text`), and
``<use>`` — whose expansion is counted as it goes, so a file of nested ``<use>`` s cannot grow without bound.
"""

from __future__ import annotations

import gzip
import hashlib
import io
import math
import os
import re
import stat
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterator
from xml.parsers import expat

import numpy as np
from numpy.typing import NDArray
from svgelements import Matrix

from .svg_basic_shapes import PREFIX as BASIC_SHAPE, is_basic_shape
from .svg_conditions import conditions_hold, switch_choice
from .svg_context_paint import NO_CONTEXT, context_of, in_context, source_of
from .svg_css import MAX_STYLE_WORK, Declarations, cascade, sheet_declarations, style_attribute
from .svg_entities import UNSAFE, check_entities, safe_declaration
from .svg_flatten import Refusal
from .svg_image import PlacedImage, image_data, is_drawing, place_picture, placement
from .svg_lengths import DEFAULT_FONT_SIZE, DEFAULT_VIEW, font_size, user_units
from .svg_marker_style import marker_longhands
from .svg_notes import note
from .svg_text import font_longhands, lay_out
from .svg_transform_origin import about_origin, parse_origin
from .svg_viewport import nested_viewport, outermost_size, parse_view_box, renders, root_size

__all__ = ["MAX_FILE_BYTES", "MAX_ELEMENTS", "MAX_DEPTH", "MAX_EXPANDED", "MAX_RULE_MATCHES", "SHAPES", "Node", "Document",
           "Drawn", "Masking", "read", "parse"]

MAX_FILE_BYTES = 20 * 1024 * 1024
"""Larger files are refused before parsing: a keyframe drawing is a few kilobytes."""
MAX_ELEMENTS = 200_000
"""Elements in one file."""
MAX_DEPTH = 200
"""Nesting of elements."""
MAX_EXPANDED = 50_000
"""Elements visited while drawing, ``<use>`` copies included."""
MAX_RULE_MATCHES = MAX_STYLE_WORK
"""Style rules tried and elements their selectors walk over, summed over the elements: a sheet of
thousands of rules for one tag over thousands of elements is refused rather than matched for minutes."""

SHAPES = ("path", "polygon", "polyline", "rect", "circle", "ellipse", "line")
"""The elements that draw a shape."""

SVG_NS = "http://www.w3.org/2000/svg"
XLINK = "http://www.w3.org/1999/xlink"
_CONTAINERS = ("svg", "g", "a", "switch")
_NOT_DRAWN = ("defs", "symbol", "clipPath", "mask", "marker", "pattern", "linearGradient", "radialGradient",
              "filter", "title", "desc", "metadata", "style", "script")
_UNSUPPORTED = ("foreignObject",)
_INHERITED = ("fill", "fill-opacity", "fill-rule", "stroke", "stroke-opacity", "stroke-width", "stroke-linecap",
              "stroke-linejoin", "stroke-miterlimit", "visibility", "color", "stroke-dasharray", "stroke-dashoffset",
              "marker-start", "marker-mid", "marker-end", "clip-rule", "paint-order", "font-family", "font-weight",
              "font-style", "font-stretch", "text-anchor", "letter-spacing", "word-spacing", "font-size",
              "image-rendering")
_PROPERTIES = _INHERITED + ("opacity", "display", "stop-color", "stop-opacity", "clip-path", "mask", "mask-type",
                             "color-interpolation")
# the properties an element's own style is read for: those above, and what a sheet may set that no child inherits
_OWN = frozenset(_PROPERTIES + ("transform", "overflow", "font-size", "marker", "transform-origin", "font"))
_UNSAFE = UNSAFE.format(what="a DOCTYPE declaring elements, attributes or notations")


@dataclass(slots=True)
class Node:
    """One XML element: its local name, attributes (namespace-free names), line, children, text."""

    tag: str
    attrs: dict[str, str]
    line: int
    children: list[Node] = field(default_factory=list)
    text: str = ""  # its character data (a <style>), or what comes before its first child (text content)
    tail: str = ""  # inside text content: the character data after it, up to its next sibling
    svg: bool = True  # in the SVG namespace (or none)
    font: tuple[float, float] = (DEFAULT_FONT_SIZE, DEFAULT_FONT_SIZE)  # its font-size and the root's (user units)
    view: tuple[float, float] = DEFAULT_VIEW  # the outermost viewport's size, what vw and vh are of (CSS px)


@dataclass(slots=True)
class Document:
    """A parsed drawing: its root, every element with an id, and what its style sheets declare for the
    elements they match (``id(node)`` → declarations, weakest first; :mod:`.svg_css`)."""

    root: Node
    ids: dict[str, list[Node]]
    sheet: dict[int, tuple[Declarations, ...]] = field(default_factory=dict)
    folder: Path | None = None  # the drawing's folder, what an <image>'s relative path is of (None: not read)
    pictures: dict[bytes, NDArray[np.uint8] | None] = field(default_factory=dict)  # decoded, by data digest


class ClipRef(tuple):  # type: ignore[type-arg]
    """A clip path on an element, ``(id of the <clipPath>, the user space it is in, 3x3)``, that knows
    ``owner``: the element that names it (whose bounding box ``objectBoundingBox`` units are of)."""

    owner: Node | None = None

    @classmethod
    def of(cls, ident: str, space: NDArray[np.float64], owner: Node) -> ClipRef:
        ref = cls((ident, space))
        ref.owner = owner
        return ref


Masking = tuple[str, NDArray[np.float64], "Node"]
"""A mask on an element: the ``<mask>``'s id, the element's user space (3x3), the element (whose box it may use)."""


@dataclass(frozen=True, slots=True)
class Drawn:
    """A shape element as drawn: its node, its resolved style, and its transform to the root's user units."""

    node: Node
    style: dict[str, str]
    ctm: NDArray[np.float64]  # 3x3, acting on column vectors (x, y, 1)
    opacity: float  # the product of its own and every ancestor's opacity
    visible: bool  # display and visibility allow it to be seen
    document: Document
    # the clip paths on it and its ancestors: (id of the <clipPath>, the user space it is in, 3x3)
    clips: tuple[tuple[str, NDArray[np.float64]], ...] = ()
    # what percentages are of in the nested viewport it is in (user units); None: the root's
    viewport: tuple[float, float] | None = None
    # the masks on it and its ancestors: (id of the <mask>, the user space it is in, the element that names it)
    masks: tuple[Masking, ...] = ()
    # with a layered walk: the groups with an opacity it is in, outermost first, (number, opacity), whose
    # opacity is then left out of ``opacity`` (:mod:`.svg_groups`)
    groups: tuple[tuple[int, float], ...] = ()
    # where its fill or stroke is a paint server taken from its context element (context-fill, …): that
    # element's user space (3x3) and node, whose box and space the paint server is drawn in; None: its own
    paint_space: tuple[NDArray[np.float64], Node] | None = None
    # an <image>'s picture, placed in its user space (its node then a rectangle path over the part it covers)
    image: PlacedImage | None = None


def _gunzip(data: bytes) -> bytes:
    """A gzip-compressed drawing (``.svgz``) unpacked; refused past :data:`MAX_FILE_BYTES` or where it cannot be."""
    try:
        with gzip.GzipFile(fileobj=io.BytesIO(data)) as unpacked:
            out = unpacked.read(MAX_FILE_BYTES + 1)
    except (OSError, EOFError):
        raise Refusal("expected gzip-compressed data, found data that cannot be unpacked") from None
    if len(out) > MAX_FILE_BYTES:
        raise Refusal(f"expected a drawing of at most {MAX_FILE_BYTES} bytes, found more")
    return out


def read(path: Path) -> bytes:
    """The file's bytes, refused when not a regular file or too large.

    A pipe would block ``open`` until a writer comes and a device may never end: the kind is checked
    before opening, and again on the open descriptor (opened without blocking) in case the name was
    swapped in between."""
    try:
        kind = _not_a_file(os.stat(path).st_mode)
        if kind:
            raise Refusal(f"expected an SVG file, found {kind}")
        descriptor = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
        with os.fdopen(descriptor, "rb") as handle:
            info = os.fstat(handle.fileno())
            kind = _not_a_file(info.st_mode)
            if kind:
                raise Refusal(f"expected an SVG file, found {kind}")
            if info.st_size > MAX_FILE_BYTES:
                raise Refusal(f"expected a drawing of at most {MAX_FILE_BYTES} bytes, found {info.st_size} bytes")
            data = handle.read(MAX_FILE_BYTES + 1)
    except FileNotFoundError:
        raise Refusal("expected an SVG file, found no file at this path") from None
    except IsADirectoryError:
        raise Refusal("expected an SVG file, found a folder") from None
    except OSError as error:
        raise Refusal(f"expected a readable SVG file, found: {error.strerror or error}") from None
    if len(data) > MAX_FILE_BYTES:
        raise Refusal(f"expected a drawing of at most {MAX_FILE_BYTES} bytes, found more")
    return data


def _not_a_file(mode: int) -> str | None:
    """What a file of ``mode`` is when it is not a regular file (``"a folder"``, ``"a pipe (FIFO)"`` …)."""
    for test, kind in ((stat.S_ISDIR, "a folder"), (stat.S_ISFIFO, "a pipe (FIFO)"),
                       (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
                       (stat.S_ISSOCK, "a socket")):
        if test(mode):
            return kind
    return None if stat.S_ISREG(mode) else "not a regular file"


def parse(data: bytes) -> Document:
    """The XML tree of ``data``, with its ids and style rules."""
    check_entities(data)  # only safe entities are declared; the XML pass refuses any other declaration
    parser = expat.ParserCreate(namespace_separator=" ")
    stack: list[Node] = []
    roots: list[Node] = []
    ids: dict[str, list[Node]] = {}
    count = [0]
    texts: dict[int, tuple[Node, list[str]]] = {}
    content: dict[tuple[int, str], tuple[Node, list[str]]] = {}  # inside <text>: (node, "text" or "tail")
    in_text = [0]  # <text> elements open

    def declaration(*_: object) -> None:  # an internal DTD subset holds entity declarations only
        raise Refusal(_UNSAFE)

    def entity(name: str, is_parameter: int, value: str | None, base: str | None, system_id: str | None,
               public_id: str | None, notation: str | None) -> None:
        if not safe_declaration(bool(is_parameter), value, system_id, public_id, notation):
            raise Refusal(UNSAFE.format(what=f"entity {name} that is not internal text"))

    def start(name: str, attributes: dict[str, str]) -> None:
        namespace, _, tag = name.rpartition(" ")
        count[0] += 1
        if count[0] > MAX_ELEMENTS:
            raise Refusal(f"expected at most {MAX_ELEMENTS} elements, found more")
        if len(stack) >= MAX_DEPTH:
            raise Refusal(f"expected elements nested at most {MAX_DEPTH} deep, found deeper "
                          f"(line {parser.CurrentLineNumber})")
        attrs = {}
        for key, value in attributes.items():
            space, _, local = key.rpartition(" ")
            attrs["xlink:href" if (space == XLINK and local == "href") else local] = value
        node = Node(tag, attrs, parser.CurrentLineNumber, svg=namespace in ("", SVG_NS))
        (stack[-1].children if stack else roots).append(node)
        stack.append(node)
        in_text[0] += tag == "text" and node.svg
        if "id" in attrs:
            ids.setdefault(attrs["id"], []).append(node)

    def end(name: str) -> None:
        node = stack.pop()
        in_text[0] -= node.tag == "text" and node.svg

    def text(data: str) -> None:
        if stack and stack[-1].tag == "style":  # pieces joined once at the end: no quadratic copying
            texts.setdefault(id(stack[-1]), (stack[-1], []))[1].append(data)
        elif in_text[0]:  # text content: before the first child, or after the last child so far
            node = stack[-1].children[-1] if stack[-1].children else stack[-1]
            kind = "tail" if stack[-1].children else "text"
            content.setdefault((id(node), kind), (node, []))[1].append(data)

    parser.ElementDeclHandler = parser.AttlistDeclHandler = parser.NotationDeclHandler = declaration
    parser.UnparsedEntityDeclHandler = declaration
    parser.EntityDeclHandler = entity
    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.CharacterDataHandler = text
    try:
        parser.Parse(data, True)
    except expat.ExpatError as error:
        raise Refusal(f"expected well-formed XML, found {expat.ErrorString(error.code)} "
                      f"at line {error.lineno}, column {error.offset + 1}") from error
    if not roots or roots[0].tag != "svg" or not roots[0].svg:
        raise Refusal(f"expected an <svg> root element, found <{roots[0].tag if roots else ''}>")
    for node, pieces in texts.values():
        node.text = "".join(pieces)
    for (_, kind), (node, pieces) in content.items():
        setattr(node, kind, "".join(pieces))
    document = Document(roots[0], ids, sheet_declarations(roots[0]) if texts else {})
    _resolve_fonts(document)
    return document


def _resolve_fonts(document: Document) -> None:
    """Every element's ``font`` (its ``font-size`` and the root's), inherited down the tree, and ``view`` (the
    outermost viewport's size); the cascade is looked at only where a ``font-size`` may be set (an attribute,
    a ``style``, a matching rule)."""
    root = document.root
    stack = [(root, DEFAULT_FONT_SIZE)]
    root_size = DEFAULT_FONT_SIZE
    view = outermost_size(root)
    while stack:
        node, parent = stack.pop()
        size = parent
        if "font-size" in node.attrs or "font-size" in node.attrs.get("style", "") or \
                any("font-size" in layer for layer in document.sheet.get(id(node), ())):
            size = font_size(own_style(node, document).get("font-size"), parent, root_size, view)
        if node is root:
            root_size = size
        if size != DEFAULT_FONT_SIZE or root_size != DEFAULT_FONT_SIZE:
            node.font = (size, root_size)
        node.view = view
        stack.extend((child, size) for child in node.children)


# -- CSS ------------------------------------------------------------------------------------------


def own_style(node: Node, document: Document) -> dict[str, str]:
    """The node's own properties (``transform`` among them): presentation attributes, then the style
    sheets' rules that match it, then ``style``, then the ``!important`` ones (:func:`.svg_css.cascade`)."""
    inline = style_attribute(node.attrs["style"]) if "style" in node.attrs else {}
    return cascade(node.attrs, document.sheet.get(id(node), ()), inline, _OWN)


# -- walking --------------------------------------------------------------------------------------


def undisplayed(own: dict[str, str]) -> bool:
    """Whether an element of ``own`` style has ``display: none``."""
    return own.get("display", "").strip() == "none"


def inherited_style(parent: dict[str, str], own: dict[str, str], node: Node) -> dict[str, str]:
    """An element's style: the inherited properties of its parent's, then its ``own`` (``inherit`` left to
    the parent's). ``font-size`` is kept computed (user units), so text instanced by a ``<use>`` takes
    the size of where it is drawn."""
    style = {k: parent[k] for k in _INHERITED if k in parent}
    if "font" in own:  # the shorthand, under the longhands the element gives too
        own = {**font_longhands(own["font"]), **{k: v for k, v in own.items() if k != "font"}}
    style.update((k, v) for k, v in own.items() if v != "inherit")
    if "font-size" in own:
        above = float(parent.get("font-size", DEFAULT_FONT_SIZE))
        style["font-size"] = repr(font_size(own["font-size"], above, node.font[1], node.view)
                                  if own["font-size"] != "inherit" else above)
    return style


_TRANSFORM_NUMBER = re.compile(r"[-+]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d+)?|nan|inf(?:inity)?", re.IGNORECASE)


def matrix(text: str, line: int = 0) -> NDArray[np.float64]:
    """A ``transform`` attribute as a 3x3 matrix (an invalid one reads as identity, as browsers do);
    a number that is not finite (``NaN``, ``1e400``) is refused, naming the attribute and its ``line``."""
    for number in _TRANSFORM_NUMBER.findall(text):
        if not math.isfinite(float(number)):
            raise Refusal(f"expected finite numbers in transform {text.strip()[:80]!r}, found {number} (line {line})")
    try:
        m = Matrix(text)
    except Exception:  # a third-party parser on arbitrary input: what it cannot read is no transform
        note(f"the transform {text.strip()[:40]!r}, which is not one (line {line})")
        return np.eye(3)
    return np.array([[m.a, m.c, m.e], [m.b, m.d, m.f], [0.0, 0.0, 1.0]])


def compose(ctm: NDArray[np.float64], step: NDArray[np.float64], node: Node, what: str) -> NDArray[np.float64]:
    """``ctm @ step``, refused when the product overflows (``scale(1e200) scale(1e200)``): ``what`` names
    the attribute that took it there."""
    with np.errstate(all="ignore"):
        product = ctm @ step
    if not (np.isfinite(step).all() and np.isfinite(product).all()):
        raise Refusal(f"expected a transform that stays finite, found {what} overflowing it (line {node.line})")
    return product


def length(node: Node, name: str, default: float = 0.0, relative: float = 1.0) -> float:
    """A length attribute in user units (units at 96 per inch, percentages of ``relative``, ``em``, ``rem``,
    ``ex`` of the element's font: :mod:`.svg_lengths`); ``default`` when it is not a length."""
    text = node.attrs.get(name)
    if text is None or not text.strip():
        return default
    value = user_units(text, node.font, node.view, relative, strict=True)
    if value is None:
        note(f"{name}={text.strip()[:40]!r}, which is not a length (line {node.line})")
        return default  # a length in error: the attribute's initial value, as renderers take it
    return value


class _Walk:
    """One walk of the tree: counts every element visited (``<use>`` copies included)."""

    def __init__(self, document: Document, keep_hidden: bool, layered: bool = False) -> None:
        self.document = document
        self.keep_hidden = keep_hidden
        self.layered = layered  # a container's opacity makes a group (``Drawn.groups``), not a factor
        self.groups: tuple[tuple[int, float], ...] = ()
        self.group_count = 0
        self.visited = 0
        self.using: list[str] = []
        self.looping: dict[str, bool] = {}  # id → whether a <use> of it leads back to itself
        self.viewport: tuple[float, float] | None = None  # the nested viewport's size; None: the root's
        self.context = NO_CONTEXT  # the fill and stroke of the <use> around (context-fill, context-stroke)
        self.shown_drawings: frozenset[bytes] = frozenset()  # digests of the drawings the walk is inside

    def visit(self, node: Node, parent: dict[str, str], ctm: NDArray[np.float64], opacity: float,
              shown: bool, clips: tuple[tuple[str, NDArray[np.float64]], ...] = (),
              masks: tuple[Masking, ...] = (), instance: Node | None = None) -> Iterator[Drawn]:
        """The shapes drawn by ``node`` and its children; ``instance`` is the ``<use>`` that instances it."""
        self.visited += 1
        if self.visited > MAX_EXPANDED:
            raise Refusal(f"expected at most {MAX_EXPANDED} elements once <use> copies are counted, found more")
        if not node.svg or (node.tag in _NOT_DRAWN and not (node.tag == "symbol" and instance is not None)) \
                or not conditions_hold(node):
            return
        own = own_style(node, self.document)
        if "marker" in own:  # the shorthand: of style sheets only
            own = marker_longhands(own, node, self.document.sheet.get(id(node), ()))
        if undisplayed(own):
            if not self.keep_hidden:
                return
            shown = False
        alpha = opacity_value(own.get("opacity", "1"))
        if self.layered and 0.0 < alpha < 1.0 and node.tag not in SHAPES:
            self.group_count += 1
            saved_groups, self.groups = self.groups, self.groups + ((self.group_count, alpha),)
            try:
                yield from self.visit_inside(node, own, parent, ctm, opacity, shown, clips, masks, instance)
            finally:
                self.groups = saved_groups
            return
        opacity *= alpha
        yield from self.visit_inside(node, own, parent, ctm, opacity, shown, clips, masks, instance)

    def visit_inside(self, node: Node, own: dict[str, str], parent: dict[str, str], ctm: NDArray[np.float64],
                     opacity: float, shown: bool, clips: tuple[tuple[str, NDArray[np.float64]], ...],
                     masks: tuple[Masking, ...], instance: Node | None) -> Iterator[Drawn]:
        """:meth:`visit` once the node's own style and opacity are read."""
        style = inherited_style(parent, own, node)
        if node is not self.document.root and "transform" in own and node.tag != "symbol":  # SVG 1.1: none on symbols
            step = matrix(own["transform"], node.line)
            if "transform-origin" in own:
                step = about_origin(step, parse_origin(own["transform-origin"], self.viewport or root_size(
                    self.document.root), node.font, node.view))
            ctm = compose(ctm, step, node, f"transform {own['transform'][:80]!r}")
        masked = own.get("mask", "none").strip()
        if masked.startswith("url(") and shown:
            target = masked[4:].partition(")")[0].strip().strip("'\"")
            masks = masks + ((target.removeprefix("#"), ctm, node),)
        reference = own.get("clip-path", "none").strip()
        if reference.startswith("url(") and shown:
            target = reference[4:].partition(")")[0].strip().strip("'\"")
            clips = clips + (ClipRef.of(target[1:] if target.startswith("#") else target, ctm, node),)
        elif is_basic_shape(reference) and shown:  # clip-path: circle(…) (:mod:`.svg_basic_shapes`)
            clips = clips + (ClipRef.of(BASIC_SHAPE + reference, ctm, node),)
        if node.tag in SHAPES:
            paint_space = self.in_context(style)
            visible = shown and style.get("visibility", "visible") not in ("hidden", "collapse")
            yield Drawn(node, style, ctm, opacity, visible, self.document, clips, viewport=self.viewport, masks=masks,
                        groups=self.groups, paint_space=paint_space)
        elif node.tag == "use":
            yield from self.use(node, style, ctm, opacity, shown, clips, masks)
        elif node.tag == "text":
            yield from self.text(node, style, ctm, opacity, shown, clips, masks)
        elif node.tag == "image":
            yield from self.image(node, style, ctm, opacity, shown, clips, masks)
        elif node.tag in ("svg", "symbol") and node is not self.document.root:
            yield from self.viewport_children(node, own, style, ctm, opacity, shown, clips, instance, masks)
        elif node.tag in _CONTAINERS:
            children = node.children
            if node.tag == "switch":  # its first child whose conditions hold (SVG 1.1 §5.8.2)
                chosen = switch_choice(node, SHAPES + _CONTAINERS + ("use", "text", "image") + _UNSUPPORTED)
                children = [chosen] if chosen is not None else []
            for child in children:
                yield from self.visit(child, style, ctm, opacity, shown, clips, masks)
        elif node.tag in _UNSUPPORTED and shown:
            raise Refusal(f"expected shapes, found <{node.tag}> (line {node.line}); "
                          "convert it to paths in the editor (Inkscape: Path > Object to Path)")

    def text(self, node: Node, style: dict[str, str], ctm: NDArray[np.float64], opacity: float, shown: bool,
             clips: tuple[tuple[str, NDArray[np.float64]], ...], masks: tuple[Masking, ...]) -> Iterator[Drawn]:
        """The glyphs of a ``<text>``, a path for each element in it with characters (:mod:`.svg_text`)."""
        viewport = self.viewport or root_size(self.document.root)
        for laid in lay_out(node, style, self.content_style, viewport, self.document.ids):  # type: ignore[arg-type]
            span = laid.node
            attrs = {"d": laid.d, **({"id": span.attrs["id"]} if "id" in span.attrs else {})}
            path = Node("path", attrs, span.line, font=span.font, view=span.view)  # type: ignore[arg-type]
            own = {k: v for k, v in laid.style.items() if not k.startswith("marker")}  # text has none
            paint_space = self.in_context(own)
            yield Drawn(path, own, ctm, opacity, shown and laid.visible, self.document, clips,
                        viewport=self.viewport, masks=masks, groups=self.groups, paint_space=paint_space)

    def image(self, node: Node, style: dict[str, str], ctm: NDArray[np.float64], opacity: float, shown: bool,
              clips: tuple[tuple[str, NDArray[np.float64]], ...], masks: tuple[Masking, ...]) -> Iterator[Drawn]:
        """An ``<image>`` (:mod:`.svg_image`): a picture is a rectangle over the part of its user space it
        covers, filled with it; a drawing's shapes are drawn there; nothing where it draws nothing."""
        found = image_data(node, self.document.folder)
        if found is None:
            return
        data, folder = found
        viewport = self.viewport or root_size(self.document.root)
        if is_drawing(data):
            yield from self.drawing(node, data, folder, viewport, ctm, opacity, shown, clips, masks)
            return
        placed = place_picture(node, style, data, viewport, self.document.pictures)
        if placed is None:
            return
        x, y, w, h = placed.rect
        attrs = {"d": f"M {x!r} {y!r} H {x + w!r} V {y + h!r} H {x!r} Z",
                 **({"id": node.attrs["id"]} if "id" in node.attrs else {})}
        path = Node("path", attrs, node.line, font=node.font, view=node.view)
        own = {k: v for k, v in style.items() if not k.startswith("marker") and not k.startswith("stroke")}
        own.update({"fill": placed.mean_colour(), "fill-opacity": "1", "fill-rule": "nonzero", "stroke": "none"})
        visible = shown and style.get("visibility", "visible") not in ("hidden", "collapse")
        yield Drawn(path, own, ctm, opacity, visible, self.document, clips, viewport=self.viewport, masks=masks,
                    groups=self.groups, image=placed)

    def drawing(self, node: Node, data: bytes, folder: Path | None, viewport: tuple[float, float],
                ctm: NDArray[np.float64], opacity: float, shown: bool,
                clips: tuple[tuple[str, NDArray[np.float64]], ...], masks: tuple[Masking, ...]) -> Iterator[Drawn]:
        """The shapes of an SVG drawing shown by the ``<image>`` ``node``, placed in its viewport and cut off
        there, with the clips and masks on the ``<image>``; nothing where an ``<image>`` of that drawing is
        already being drawn (a drawing showing itself is drawn once inside itself, as browsers do)."""
        key = hashlib.sha256(data).digest()
        if key in self.shown_drawings:
            note(f"an <image> that shows a drawing it is in (line {node.line})")
            return
        try:
            inner = parse(_gunzip(data) if data[:2] == b"\x1f\x8b" else data)
        except Refusal as refusal:  # as a browser shows a broken image: nothing, and the rest of the drawing
            note(f"an <image> of a drawing that cannot be read (line {node.line}): {str(refusal)[:80]}")
            return
        inner.folder = folder
        if not renders(inner.root):
            return
        size = outermost_size(inner.root)
        box = parse_view_box(inner.root.attrs.get("viewBox")) or (0.0, 0.0, *size)
        placed = placement(node, viewport, size, box)
        if placed is None:
            return
        matrix, rect = placed
        walk = _Walk(inner, self.keep_hidden, self.layered)
        walk.shown_drawings = self.shown_drawings | {key}
        walk.groups, walk.group_count, walk.visited = self.groups, self.group_count, self.visited
        # the <image>'s own clips and masks name elements of this drawing: lent to the other under names no
        # file can write
        lent_clips: list[tuple[str, NDArray[np.float64]]] = []
        for ref in clips:
            lent = walk.lend(self.document, ref[0])
            lent_clips.append(ClipRef.of(lent, ref[1], getattr(ref, "owner", None)) if lent != ref[0] else ref)
        lent_masks = tuple((walk.lend(self.document, ident), space, owner) for ident, space, owner in masks)
        cut = ClipRef.of(walk.viewport_clip(rect), ctm, node)
        try:
            yield from walk.visit(inner.root, {}, compose(ctm, matrix, node, "the <image>'s placement"), opacity,
                                  shown, (*lent_clips, cut), lent_masks)
        finally:
            self.visited, self.group_count = walk.visited, walk.group_count

    def lend(self, other: Document, ident: str) -> str:
        """The id under which the element ``ident`` of ``other`` (a clip path, a mask) is known in this walk's
        drawing, put there under a name no file can write; ``ident`` itself where ``other`` has no such id."""
        nodes = other.ids.get(ident)
        if not nodes or ident.startswith(BASIC_SHAPE):
            return ident
        lent = f"\0lent {id(other)} {ident}"
        self.document.ids.setdefault(lent, nodes)
        return lent

    def in_context(self, style: dict[str, str]) -> tuple[NDArray[np.float64], Node] | None:
        """Replaces ``context-fill`` and ``context-stroke`` in ``style`` by the context's paint; the context
        element's user space and node where a paint server comes from it (None: none does)."""
        found = None
        for name in ("fill", "stroke"):
            if name in style:
                found = found or source_of(style[name], self.context)
                style[name] = in_context(style[name], self.context)
        return found

    def content_style(self, node: Node, parent: dict[str, str]) -> dict[str, str] | None:
        """The style of a ``<tspan>``, ``<a>`` or ``<tref>`` in text; None when it is not displayed (or its
        conditional attributes do not hold)."""
        self.visited += 1
        if not conditions_hold(node):
            return None
        own = own_style(node, self.document)
        return None if undisplayed(own) else inherited_style(parent, own, node)

    def viewport_children(self, node: Node, own: dict[str, str], style: dict[str, str], ctm: NDArray[np.float64],
                          opacity: float, shown: bool, clips: tuple[tuple[str, NDArray[np.float64]], ...],
                          instance: Node | None, masks: tuple[Masking, ...] = ()) -> Iterator[Drawn]:
        """The children of a nested ``<svg>`` or an instanced ``<symbol>``, in the viewport it opens
        (:mod:`.svg_viewport`), clipped to it unless its ``overflow`` is visible."""
        outer = self.viewport or root_size(self.document.root)
        viewport = nested_viewport(node, outer, own.get("overflow", "hidden"), instance)
        if viewport is None:
            return  # a viewport of zero size draws nothing
        if viewport.rect is not None:
            clips = clips + ((self.viewport_clip(viewport.rect), ctm),)
        ctm = compose(ctm, viewport.to_parent, node, f"the <{node.tag}>'s viewport transform")
        saved, self.viewport = self.viewport, viewport.size
        try:
            for child in node.children:
                yield from self.visit(child, style, ctm, opacity, shown, clips, masks)
        finally:
            self.viewport = saved

    def viewport_clip(self, rect: tuple[float, float, float, float]) -> str:
        """The id of a ``<clipPath>`` of the rectangle ``rect`` ``(x, y, width, height)``, made for the
        drawing under a name no file can write (XML has no NUL)."""
        ident = "\0viewport " + " ".join(repr(v) for v in rect)
        if ident not in self.document.ids:
            x, y, w, h = (repr(v) for v in rect)
            shape = Node("rect", {"x": x, "y": y, "width": w, "height": h}, 0)
            self.document.ids[ident] = [Node("clipPath", {"id": ident}, 0, [shape])]
        return ident

    def loops(self, ident: str, open_ids: set[str]) -> bool:
        """Whether the element ``ident`` (through the ``<use>`` elements in it) leads back to an id in
        ``open_ids`` or to itself; each id is searched once."""
        if ident in open_ids:
            return True
        if ident in self.looping:
            return self.looping[ident]
        target = self.document.ids.get(ident)
        found = False
        if target:
            open_ids.add(ident)
            stack = [target[0]]
            while stack and not found:
                current = stack.pop()
                stack.extend(current.children)
                if current.tag == "use":
                    ref = current.attrs.get("href", current.attrs.get("xlink:href", "")).strip()
                    found = ref.startswith("#") and self.loops(ref[1:], open_ids)
            open_ids.discard(ident)
        self.looping[ident] = found
        return found

    def use(self, node: Node, style: dict[str, str], ctm: NDArray[np.float64], opacity: float,
            shown: bool, clips: tuple[tuple[str, NDArray[np.float64]], ...] = (),
            masks: tuple[Masking, ...] = ()) -> Iterator[Drawn]:
        href = node.attrs.get("href", node.attrs.get("xlink:href", "")).strip()
        if not href.startswith("#"):
            return  # external references are not followed
        target = self.document.ids.get(href[1:])
        if not target or href in self.using or self.loops(href[1:], set()):
            what = "a loop of references" if target else "nothing"
            note(f"a <use> of {href[:40]!r}, {what} (line {node.line})")
            return  # SVG: a <use> of nothing, or in a loop of references, is in error and not rendered
        width, height = self.viewport or root_size(self.document.root)
        shift = np.array([[1.0, 0.0, length(node, "x", 0.0, width)], [0.0, 1.0, length(node, "y", 0.0, height)],
                          [0.0, 0.0, 1.0]])
        placed = compose(ctm, shift, node, "the <use> element's x, y transform")
        self.using.append(href)
        saved, self.context = self.context, context_of(style, self.context, ctm, node)
        try:
            yield from self.visit(target[0], style, placed, opacity, shown, clips, masks, instance=node)
        finally:
            self.using.pop()
            self.context = saved


HREF_DEPTH = 8
"""``href`` links followed at most from a paint server to the ones it inherits from."""


def href_chain(ident: str, document: Document, tags: tuple[str, ...]) -> list[Node]:
    """The node of ``ident`` and the nodes its ``href`` (or ``xlink:href``) leads to, nearest first, while each
    is one of ``tags`` and none repeats (at most :data:`HREF_DEPTH` links followed)."""
    chain: list[Node] = []
    while ident and len(chain) <= HREF_DEPTH:
        nodes = document.ids.get(ident)
        if not nodes or nodes[0].tag not in tags or nodes[0] in chain:
            break
        chain.append(nodes[0])
        href = nodes[0].attrs.get("href", nodes[0].attrs.get("xlink:href", "")).strip()
        ident = href[1:] if href.startswith("#") else ""
    return chain


def opacity_value(text: str) -> float:
    """An ``opacity``: a number or a percentage (CSS Color 4), clamped to [0, 1]; 1 when unreadable."""
    text = text.strip()
    try:
        value = float(text[:-1]) / 100.0 if text.endswith("%") else float(text)
    except ValueError:
        return 1.0
    return min(max(value, 0.0), 1.0) if math.isfinite(value) else 1.0


def walk(document: Document, keep_hidden: bool = False, layered: bool = False) -> Iterator[Drawn]:
    """Every shape element of the drawing in paint order, with its style and transform.

    ``keep_hidden`` walks into ``display:none`` too (the elements come with ``visible`` False).
    """
    return _Walk(document, keep_hidden, layered).visit(document.root, {}, np.eye(3), 1.0, True)
