"""Markers (``marker-start``, ``marker-mid``, ``marker-end``) expanded into the shapes they draw.

At each vertex of a shape element (SVG 2: every one; each subpath's start and every segment's end, a
``Z``'s being its subpath's start, which gets no middle marker) a marker's content is placed as SVG says:
its ``(refX, refY)`` on the vertex, turned by ``orient`` (an angle, or ``auto``: the direction of the
path there, the bisector of the directions in and out at a vertex between two segments;
``auto-start-reverse`` turns the start marker round), scaled by the element's ``stroke-width`` (unless
``markerUnits="userSpaceOnUse"``) and by its ``viewBox`` into ``markerWidth`` × ``markerHeight``, and
clipped to that viewport unless its ``overflow`` is visible. The content inherits from the marker's
ancestors, not from the element; it is drawn with the element's opacity and clip paths, after it, in the
order start, middle, end (which markers an element names: :mod:`.svg_marker_style`).
A marker inside its own content is not drawn again.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Callable, Iterator

import numpy as np
from numpy.typing import NDArray

from .svg_document import MAX_EXPANDED, SHAPES, Document, Drawn, Node, compose, own_style
from .svg_flatten import Refusal
from .svg_viewport import aspect_matrix, parse_view_box, root_size

__all__ = ["Placed", "placements", "marker_content"]

_ANGLE = re.compile(r"^\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*(deg|grad|rad|turn)?\s*$", re.IGNORECASE)
_PER_UNIT = {"deg": 1.0, "grad": 0.9, "rad": 180.0 / math.pi, "turn": 360.0}

Matrix = NDArray[np.float64]  # 3x3, acting on column vectors (x, y, 1)
Length = Callable[[Node, str, float, float], float]  # a length attribute in user units: (node, name, default, of)
Direction = NDArray[np.float64]  # (2,)


@dataclass(frozen=True, slots=True)
class Placed:
    """One marker to draw: the ``<marker>`` node, the kind (``start``, ``mid``, ``end``), the vertex's index,
    the 3x3 maps of its content's user space (``content``) and of its viewport (``viewport``) into the
    root's user units, and the rectangle ``(x, y, w, h)`` of its viewport that clips it (None: not clipped)."""

    marker: Node
    kind: str
    index: int
    content: Matrix
    viewport: Matrix
    rect: tuple[float, float, float, float] | None


def _target(value: str, document: Document) -> Node | None:
    text = value.strip()
    if not text.startswith("url("):
        return None
    ident = text[4:].partition(")")[0].strip().strip("'\"").removeprefix("#")
    nodes = document.ids.get(ident)
    return nodes[0] if nodes and nodes[0].tag == "marker" and nodes[0].svg else None


def _orient(text: str | None) -> str | float:
    """``auto``, ``auto-start-reverse`` or an angle in degrees (what cannot be read is 0)."""
    value = (text or "0").strip()
    if value in ("auto", "auto-start-reverse"):
        return value
    match = _ANGLE.match(value)
    if match is None:
        return 0.0
    angle = float(match.group(1)) * _PER_UNIT[(match.group(2) or "deg").lower()]
    return angle if math.isfinite(angle) else 0.0


def _angle(direction: Direction) -> float:
    return math.degrees(math.atan2(direction[1], direction[0])) if np.any(direction) else 0.0


def _bisector(incoming: Direction, outgoing: Direction) -> float:
    """The angle (degrees) halfway between the directions in and out, on the side of the smaller turn (of a
    path turning right round, the one a quarter turn on from the larger of the two angles in [0, 360))."""
    a, b = _angle(incoming) % 360.0, _angle(outgoing) % 360.0
    half = (b - a) / 2.0
    return a + half - (180.0 if abs(half) > 90.0 else 0.0)


def _point(p: object) -> NDArray[np.float64]:
    return np.array([p.x, p.y], dtype=np.float64)  # type: ignore[attr-defined]


def _ends(segment: object, start: NDArray[np.float64], end: NDArray[np.float64]) -> tuple[Direction, Direction]:
    """A segment's directions at its start and at its end (zero vectors where it has none)."""
    from svgelements import Arc, CubicBezier, QuadraticBezier

    if isinstance(segment, CubicBezier):
        nodes = [start, _point(segment.control1), _point(segment.control2), end]
    elif isinstance(segment, QuadraticBezier):
        nodes = [start, _point(segment.control), end]
    elif isinstance(segment, Arc) and segment.sweep and segment.rx and segment.ry:
        step = 1e-6
        return (_point(segment.point(step)) - start) / step, (end - _point(segment.point(1.0 - step))) / step
    else:
        nodes = [start, end]
    out = next((n - start for n in nodes[1:] if np.any(n != start)), np.zeros(2))
    into = next((end - n for n in nodes[-2::-1] if np.any(n != end)), np.zeros(2))
    return out, into


def _vertices(segments: list[object]) -> list[tuple[NDArray[np.float64], float, bool]]:
    """Each vertex of a path, its ``auto`` angle (degrees), and whether a ``Z`` ends there, in order. At a
    ``Z`` the angle is the closing line's: the vertex is its subpath's start, which has its own."""
    from svgelements import Close, Move

    points: list[NDArray[np.float64]] = []
    closes: list[bool] = []
    into: list[Direction | None] = []
    out: list[Direction | None] = []
    start = current = None
    first: Direction | None = None
    for segment in segments:
        if isinstance(segment, Move):
            current = start = _point(segment.end)
            points.append(current)
            closes.append(False)
            into.append(None)
            out.append(None)
            first = None
            continue
        if current is None:
            current = start = _point(segment.start)  # type: ignore[attr-defined]
            points.append(current)
            closes.append(False)
            into.append(None)
            out.append(None)
        end = start if isinstance(segment, Close) else _point(segment.end)  # type: ignore[attr-defined]
        leaving, arriving = _ends(segment, current, end)  # type: ignore[arg-type]
        if out[-1] is None:
            out[-1] = leaving
        if first is None:
            first = leaving
        points.append(end)  # type: ignore[arg-type]
        closes.append(isinstance(segment, Close))
        into.append(arriving)
        out.append(None)
        current = end
    angles = []
    for incoming, outgoing in zip(into, out):
        if incoming is None:
            angles.append(_angle(outgoing) if outgoing is not None else 0.0)
        elif outgoing is None:
            angles.append(_angle(incoming))
        else:
            angles.append(_bisector(incoming, outgoing))
    return list(zip(points, angles, closes))


def placements(d: Drawn, segments: list[object], stroke_width: float, length: Length) -> list[Placed]:
    """Every marker ``d`` draws, in paint order. ``segments`` are its geometry's svgelements segments
    (user units), ``stroke_width`` its stroke width in user units, ``length(node, name, default, relative)``
    a length attribute in user units."""
    if d.node.tag not in SHAPES:
        return []
    found = {kind: _target(d.style.get(f"marker-{kind}", "none"), d.document) for kind in ("start", "mid", "end")}
    if not any(found.values()):
        return []
    vertices = _vertices(segments)
    if not vertices:
        return []
    out: list[Placed] = []
    last = len(vertices) - 1
    middle = [i for i in range(1, last) if not vertices[i][2]]  # a Z's vertex is its subpath's start: not again
    for kind, indices in (("start", [0]), ("mid", middle), ("end", [last])):
        marker = found[kind]
        if marker is None:
            continue
        for i in indices:
            placed = _place(marker, kind, i, vertices[i], d, stroke_width, length)
            if placed is not None:
                out.append(placed)
    return out


def _place(marker: Node, kind: str, index: int, vertex: tuple[NDArray[np.float64], float, bool], d: Drawn,
           stroke_width: float, length: Length) -> Placed | None:
    width, height = d.viewport or root_size(d.document.root)
    marker_width = length(marker, "markerWidth", 3.0, width)
    marker_height = length(marker, "markerHeight", 3.0, height)
    if not (marker_width > 0 and marker_height > 0):
        return None  # SVG: a marker of zero (or negative) size is not drawn
    units = marker.attrs.get("markerUnits", "strokeWidth").strip()
    scale = 1.0 if units == "userSpaceOnUse" else stroke_width
    if not scale > 0:
        return None
    orient = _orient(marker.attrs.get("orient"))
    point, auto, _ = vertex
    if orient == "auto":
        angle = auto
    elif orient == "auto-start-reverse":
        angle = auto + (180.0 if kind == "start" else 0.0)
    else:
        angle = float(orient)  # type: ignore[arg-type]
    box = parse_view_box(marker.attrs.get("viewBox"))
    fit = np.eye(3) if box is None else aspect_matrix(box, marker_width, marker_height,
                                                      marker.attrs.get("preserveAspectRatio", ""))
    ref = fit @ np.array([length(marker, "refX", 0.0, width), length(marker, "refY", 0.0, height), 1.0])
    c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    placing = (np.array([[1.0, 0.0, point[0]], [0.0, 1.0, point[1]], [0.0, 0.0, 1.0]])
               @ np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
               @ np.diag([scale, scale, 1.0])
               @ np.array([[1.0, 0.0, -ref[0]], [0.0, 1.0, -ref[1]], [0.0, 0.0, 1.0]]))
    viewport = compose(d.ctm, placing, marker, "the marker's placement")
    content = compose(viewport, fit, marker, "the marker's viewBox")
    overflow = _overflow(marker, d.document)
    rect = None if overflow in ("visible", "auto") else (0.0, 0.0, marker_width, marker_height)
    return Placed(marker, kind, index, content, viewport, rect)


def _overflow(marker: Node, document: Document) -> str:
    """The marker's computed ``overflow`` (``hidden`` by SVG's user-agent sheet); ``inherit`` takes its parent's,
    which is ``hidden`` for a nested ``<svg>``, a ``<symbol>``, ``<marker>`` or ``<pattern>`` that sets none and
    ``visible`` (the initial value) for any other element, or with no parent."""
    value = own_style(marker, document).get("overflow", "hidden").strip().lower()
    parents: dict[int, Node] | None = None
    node = marker
    while value == "inherit":
        parents = parents if parents is not None else _parents(document, {})
        parent = parents.get(id(node))
        if parent is None:
            return "visible"
        clipping = parent.tag in ("symbol", "marker", "pattern") or (parent.tag == "svg" and parent is not document.root)
        value = own_style(parent, document).get("overflow", "hidden" if clipping else "visible").strip().lower()
        node = parent
    return value


def _parents(document: Document, memo: dict[object, object]) -> dict[int, Node]:
    """Each node's parent (by ``id``), worked out once per reading."""
    key = ("marker parents", id(document))
    if key not in memo:
        parents: dict[int, Node] = {}
        stack = [document.root]
        while stack:
            node = stack.pop()
            for child in node.children:
                parents[id(child)] = node
                stack.append(child)
        memo[key] = parents
    return memo[key]  # type: ignore[return-value]


def _inherited(marker: Node, document: Document, memo: dict[object, object]) -> dict[str, str]:
    """The marker's own style, inherited from its ancestors (what its content inherits)."""
    from .svg_document import _INHERITED

    parents = _parents(document, memo)
    chain = [marker]
    while id(chain[-1]) in parents:
        chain.append(parents[id(chain[-1])])
    style: dict[str, str] = {}
    for node in reversed(chain):
        own = own_style(node, document)
        inherited = {k: style[k] for k in _INHERITED if k in style}
        inherited.update((k, v) for k, v in own.items() if v != "inherit")
        style = inherited
    return style


def marker_content(d: Drawn, placed: Placed, memo: dict[object, object]) -> Iterator[Drawn]:
    """The shapes of one placed marker, as drawn (with ``d``'s opacity and clip paths, and the marker's
    viewport clip)."""
    from .svg_document import _Walk
    from .svg_context_paint import NO_CONTEXT, context_of

    walker = _Walk(d.document, False)
    walker.context = context_of(d.style, NO_CONTEXT, d.ctm, d.node)  # context-fill, -stroke: the marked element's
    clips = d.clips
    if placed.rect is not None:
        clips = clips + ((walker.viewport_clip(placed.rect), placed.viewport),)
    style = _inherited(placed.marker, d.document, memo)
    for child in placed.marker.children:
        if child.tag in SHAPES + ("g", "use", "svg", "switch", "a", "image", "text"):
            yield from walker.visit(child, style, placed.content, d.opacity, True, clips, d.masks)
    visited = int(memo.get("marker visits", 0)) + walker.visited  # type: ignore[call-overload]
    memo["marker visits"] = visited
    if visited > MAX_EXPANDED:
        raise Refusal(f"expected at most {MAX_EXPANDED} elements once markers' copies are counted, found more")
