"""Keyframe polygons from SVG drawings: one element, its curves flattened, in world units.

A scene key may take its points from a drawing: ``points = { svg = "bird0.svg",
id = "body" }``. :func:`load_svg_points` finds the element with that id, applies
every transform above it (groups and its own), flips y, and flattens its curves
into a polygon within a tolerance given in world units.

World units are the drawing's *user units* (the coordinates written in the
file), with ``world y = -svg y``. The root ``<svg>``'s viewBox→viewport mapping
(and a ``transform`` on the root, which lies outside the user space) is undone:
svgelements applies it to every element, so ``width="100mm" viewBox="0 0 100 100"``
would otherwise give CSS pixels (x 3.7795). Lengths written with units inside
the drawing (``r="2mm"``) convert at 96 per inch, as CSS does, into user units.

Elements read: ``path``, ``polygon``, ``polyline``, ``rect``, ``circle`` and
``ellipse``, under any groups, hidden ones (``display:none``) included since
animators hide the layers of the other keys. Parsing is svgelements'; this
module adds a strict XML pre-pass (ids, line numbers, refusing DTD internal
subsets and entity declarations) and checks of what svgelements would silently
skip or truncate (stray characters in ``d``, odd ``points``, negative sizes).
"""

from __future__ import annotations

import difflib
import io
import math
import re
from dataclasses import dataclass
from pathlib import Path
from xml.parsers import expat

import numpy as np
from numpy.typing import NDArray
from svgelements import SVG, Arc, Close, CubicBezier, Line, Matrix, Move, QuadraticBezier, Shape

from tweenrender.errors import SceneError

__all__ = ["DEFAULT_TOLERANCE", "MAX_FILE_BYTES", "MAX_VERTICES", "SUPPORTED", "SvgError", "load_svg_points"]

DEFAULT_TOLERANCE: float = 0.01
"""World units. Drawings are made tens to hundreds of user units across (Inkscape's
mm or px), so 0.01 is about a ten-thousandth of a drawing: under a pixel when it
fills a 1280-pixel frame, while a circle of radius 50 still needs only ~160 vertices
(the correspondence cost grows with the product of two keys' vertex counts)."""

MAX_FILE_BYTES: int = 20 * 1024 * 1024
"""Larger files are refused before parsing: a keyframe drawing is a few kilobytes."""

MAX_VERTICES: int = 100_000
"""A flattened element with more vertices than this is refused (tolerance far too small)."""

SUPPORTED: tuple[str, ...] = ("path", "polygon", "polyline", "rect", "circle", "ellipse")
"""The SVG elements that can give a keyframe outline."""

_SVG_NS = "http://www.w3.org/2000/svg"
_MAX_DEPTH = 48  # Bézier halvings; the flatness bound shrinks 4x per halving
_NUMBER = r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?"
_PATH_TOKEN = re.compile(r"[\s,]*(?:[MmZzLlHhVvCcSsQqTtAa]|" + _NUMBER + ")")
_POINTS_TOKEN = re.compile(r"[\s,]*(" + _NUMBER + ")")
_SEPARATORS = re.compile(r"[\s,]*")
_ENTITY = re.compile(rb"<!ENTITY", re.IGNORECASE)
_UNSAFE = (
    "expected plain SVG, found a DOCTYPE with entity declarations (refused: entities can "
    "expand without bound or read other files); save the drawing as plain SVG"
)


class SvgError(SceneError, ValueError):
    """A drawing or one of its elements cannot give a keyframe polygon.

    ``str()`` is one line: ``drawing.svg#id: what was expected, what was found``.
    """

    def __init__(self, svg_path: str | Path, element_id: str, message: str) -> None:
        self.element_id = element_id
        super().__init__(svg_path, f"#{element_id}", message)

    def __str__(self) -> str:
        return f"{self.path}{self.where}: {self.message}"

    def __reduce__(self) -> tuple[type[SvgError], tuple[str | None, str, str]]:
        return type(self), (self.path, self.element_id, self.message)


class _Refusal(Exception):
    """Raised inside this module; :func:`load_svg_points` names the file and id."""


@dataclass(frozen=True, slots=True)
class _Found:
    """An element as the XML scan saw it: its tag (local name), namespace, line, attributes."""

    tag: str
    namespace: str
    line: int
    attributes: dict[str, str]

    @property
    def drawable(self) -> bool:
        return self.namespace in ("", _SVG_NS) and self.tag in SUPPORTED

    @property
    def kind(self) -> str:
        return f"<{self.tag}>" if self.namespace in ("", _SVG_NS) else f"<{{{self.namespace}}}{self.tag}>"


def load_svg_points(
    svg_path: Path, element_id: str, tolerance: float = DEFAULT_TOLERANCE
) -> NDArray[np.float64]:
    """The polygon of element ``element_id`` of the drawing ``svg_path``: ``(N, 2)`` float64.

    World units (user units, y up, see the module docstring), N ≥ 3, in the
    drawing's order, without the closing duplicate or consecutive duplicates.
    Curves (Béziers, arcs, circles, ellipses, rounded corners) are flattened so
    that no point of the curve lies farther than ``tolerance`` (world units,
    > 0) from the polygon; straight segments stay single edges.

    Raises :class:`SvgError` for an unreadable, oversized or unsafe file, an
    unknown id, an unsupported or malformed element, or one with several subpaths.
    """
    try:
        tol = _check_tolerance(tolerance)
        if not isinstance(element_id, str) or not element_id:
            raise _Refusal(f"expected a non-empty element id, found {element_id!r}")
        data = _read(Path(svg_path))
        found = _find(_scan(data), element_id)
        _check_syntax(found)
        return _polygon(data, element_id, found, tol)
    except _Refusal as refusal:
        raise SvgError(svg_path, str(element_id), str(refusal)) from refusal.__cause__


def _check_tolerance(tolerance: object) -> float:
    try:
        if isinstance(tolerance, bool):
            raise TypeError
        tol = float(tolerance)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise _Refusal(f"expected a tolerance that is a positive number, found {tolerance!r}") from None
    if not (math.isfinite(tol) and tol > 0):
        raise _Refusal(f"expected a finite tolerance > 0 (world units), found {tol!r}")
    return tol


def _read(svg_path: Path) -> bytes:
    try:
        size = svg_path.stat().st_size
        if size > MAX_FILE_BYTES:
            raise _Refusal(f"expected a drawing of at most {MAX_FILE_BYTES} bytes, found {size} bytes")
        with svg_path.open("rb") as handle:
            data = handle.read(MAX_FILE_BYTES + 1)
    except FileNotFoundError:
        raise _Refusal("expected an SVG file, found no file at this path") from None
    except OSError as error:
        raise _Refusal(f"expected a readable SVG file, found: {error.strerror or error}") from error
    if len(data) > MAX_FILE_BYTES:
        raise _Refusal(f"expected a drawing of at most {MAX_FILE_BYTES} bytes, found more")
    # NULs are dropped so that UTF-16/32 text is caught too; the XML scan below
    # refuses the same declarations in any encoding expat reads.
    if _ENTITY.search(data.replace(b"\x00", b"")):
        raise _Refusal(_UNSAFE)
    return data


def _scan(data: bytes) -> dict[str, list[_Found]]:
    """Every element that has an id, by id, from a strict XML pass that refuses DTD subsets."""
    parser = expat.ParserCreate(namespace_separator=" ")
    found: dict[str, list[_Found]] = {}
    root: list[str] = []

    def doctype(name: str, system_id: str | None, public_id: str | None, internal: int) -> None:
        if internal:
            raise _Refusal(_UNSAFE)

    def entity(*_: object) -> None:
        raise _Refusal(_UNSAFE)

    def start(name: str, attributes: dict[str, str]) -> None:
        namespace, _, tag = name.rpartition(" ")
        if not root:
            root.append(tag if namespace in ("", _SVG_NS) else name)
        if "id" in attributes:
            element = _Found(tag, namespace, parser.CurrentLineNumber, attributes)
            found.setdefault(attributes["id"], []).append(element)

    parser.StartDoctypeDeclHandler = doctype
    parser.EntityDeclHandler = entity
    parser.StartElementHandler = start
    try:
        parser.Parse(data, True)
    except expat.ExpatError as error:
        raise _Refusal(
            f"expected well-formed XML, found {expat.ErrorString(error.code)} "
            f"at line {error.lineno}, column {error.offset + 1}"
        ) from error
    if root != ["svg"]:
        raise _Refusal(f"expected an <svg> root element, found <{root[0] if root else ''}>")
    return found


def _find(elements: dict[str, list[_Found]], element_id: str) -> _Found:
    if element_id not in elements:
        shapes = [i for i, found in elements.items() if found[0].drawable]
        close = difflib.get_close_matches(element_id, list(elements), n=1, cutoff=0.6)
        hint = f'; did you mean "{close[0]}"?' if close else ""
        listed = ", ".join(f'"{i}"' for i in shapes[:8])
        listed += f" and {len(shapes) - 8} more" if len(shapes) > 8 else ""
        have = f"shapes with ids: {listed}" if shapes else "no shape in the file has an id"
        raise _Refusal(f"expected an element with this id, found none{hint} ({have})")
    found = elements[element_id]
    if len(found) > 1:
        lines = ", ".join(str(f.line) for f in found)
        raise _Refusal(f"expected a unique id, found {len(found)} elements with it (lines {lines})")
    element = found[0]
    if not element.drawable:
        kinds = ", ".join(f"<{tag}>" for tag in SUPPORTED)
        raise _Refusal(f"expected one of {kinds}, found {element.kind} (line {element.line})")
    return element


def _check_syntax(found: _Found) -> None:
    """Refuse what svgelements would silently truncate: stray characters, odd coordinates."""
    if found.tag == "path":
        d = found.attributes.get("d", "")
        if not d.strip():
            raise _Refusal(f"expected path data, found an empty or missing d (line {found.line})")
        position = _scan_tokens(_PATH_TOKEN, d)
        if position is not None:
            raise _Refusal(
                f"expected path data of commands and numbers, found {_excerpt(d, position)!r} "
                f"at character {position + 1} (line {found.line})"
            )
        if d.strip()[0] not in "Mm":
            raise _Refusal(f"expected path data that starts with M or m, found {_excerpt(d, 0)!r}")
    elif found.tag in ("polygon", "polyline"):
        points = found.attributes.get("points", "")
        position = _scan_tokens(_POINTS_TOKEN, points)
        if position is not None:
            raise _Refusal(
                f"expected points as numbers, found {_excerpt(points, position)!r} "
                f"at character {position + 1} (line {found.line})"
            )
        count = len(_POINTS_TOKEN.findall(points))
        if count % 2:
            raise _Refusal(f"expected points as x,y pairs, found an odd count of numbers ({count})")
    for name in ("width", "height", "r", "rx", "ry"):  # SVG: a negative size is an error
        if found.attributes.get(name, "").strip().startswith("-"):
            raise _Refusal(f"expected {name} ≥ 0, found {name}={found.attributes[name]!r} (line {found.line})")


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


def _polygon(data: bytes, element_id: str, found: _Found, tol: float) -> NDArray[np.float64]:
    try:
        # display="none" elements are parsed too: animators hide the layers of other keys.
        document = SVG.parse(io.BytesIO(data), reify=False, parse_display_none=True)
    except Exception as error:  # a third-party parser on arbitrary input: report, do not crash
        raise _Refusal(f"expected a drawing svgelements can read, found: {error}") from error
    if not (document.width and document.height):  # svgelements stops at a zero-sized root
        raise _Refusal("expected a root <svg> of positive size, found a zero width or height")
    element = document.get_element_by_id(element_id)
    if not isinstance(element, Shape):
        raise _Refusal(_why_not_drawn(found))
    segments = _single_subpath(list(element.segments(transformed=False)), found)
    points = _distinct(_flatten(segments, _to_world(document, element), tol))
    if len(points) < 3:
        raise _Refusal(f"expected a closed outline of at least 3 distinct vertices, found {len(points)}")
    return points


def _why_not_drawn(found: _Found) -> str:
    """Why svgelements left out an element the XML scan found (it skips bad or empty ones)."""
    if found.tag == "path":
        d = found.attributes.get("d", "")
        return f"expected path data with the right count of numbers per command, found {_excerpt(d, 0)!r}"
    if found.tag in ("polygon", "polyline"):
        points = found.attributes.get("points", "")
        return f"expected at least 3 distinct vertices, found points={_excerpt(points, 0)!r}"
    geometry = " ".join(
        f'{k}="{v}"' for k, v in found.attributes.items()
        if k in ("x", "y", "width", "height", "rx", "ry", "cx", "cy", "r")
    )
    return (
        f"expected a <{found.tag}> of positive size, found one svgelements cannot draw "
        f"({geometry or 'no geometry'}, line {found.line})"
    )


def _matrix(matrix: Matrix) -> NDArray[np.float64]:
    """svgelements' ``(a, b, c, d, e, f)`` as a 3x3 acting on column vectors ``(x, y, 1)``."""
    return np.array([[matrix.a, matrix.c, matrix.e], [matrix.b, matrix.d, matrix.f], [0.0, 0.0, 1.0]])


def _to_world(document: SVG, element: Shape) -> NDArray[np.float64]:
    """Element coordinates → world: every transform inside the root, then y flipped."""
    # svgelements' element.transform = root transform ∘ viewBox mapping ∘ groups ∘ own;
    # the first two are undone to stay in user units.
    outside = _matrix(Matrix(f"{document.values.get('transform', '')} {document.viewbox_transform}"))
    if np.linalg.det(outside[:2, :2]) == 0:
        raise _Refusal("expected a root <svg> of positive size, found one that collapses the drawing")
    user = np.linalg.solve(outside, _matrix(element.transform))
    return np.diag([1.0, -1.0, 1.0]) @ user


def _single_subpath(segments: list[object], found: _Found) -> list[object]:
    """The drawing segments of the only subpath that draws; refuse several."""
    subpaths: list[list[object]] = []
    current: list[object] | None = None
    for segment in segments:
        if isinstance(segment, Move):
            current = None
            continue
        if current is None:
            current = []
            subpaths.append(current)
        current.append(segment)
        if isinstance(segment, Close):
            current = None  # a command after Z starts a new subpath at the same point
    drawing = [s for s in subpaths if any(_draws(segment) for segment in s)]
    if len(drawing) > 1:
        raise _Refusal(
            f"expected a single closed outline, found {len(drawing)} subpaths in this <{found.tag}> "
            f"(holes or separate pieces; line {found.line}); split or combine them in the editor"
        )
    return drawing[0] if drawing else []


def _draws(segment: object) -> bool:
    points = [segment.start, segment.end]  # type: ignore[attr-defined]
    if isinstance(segment, QuadraticBezier):
        points.append(segment.control)
    elif isinstance(segment, CubicBezier):
        points += [segment.control1, segment.control2]
    return any(p != points[0] for p in points[1:])


def _flatten(segments: list[object], to_world: NDArray[np.float64], tol: float) -> NDArray[np.float64]:
    """World vertices of a subpath, its start first; curves within ``tol`` of their chords."""
    if not segments:
        return np.empty((0, 2))
    linear, offset = to_world[:2, :2], to_world[:2, 2]

    def world(*points: object) -> NDArray[np.float64]:
        local = np.array([(p.x, p.y) for p in points], dtype=np.float64)  # type: ignore[attr-defined]
        with np.errstate(invalid="ignore", over="ignore"):  # refused just below
            placed = local @ linear.T + offset
        if not np.all(np.isfinite(placed)):
            raise _Refusal("expected finite coordinates, found infinite or NaN ones after transforms")
        return placed

    out: list[NDArray[np.float64]] = [world(segments[0].start)]  # type: ignore[attr-defined]
    count = 1
    for segment in segments:
        if isinstance(segment, CubicBezier):
            piece = _flatten_bezier(world(segment.start, segment.control1, segment.control2, segment.end), tol)
        elif isinstance(segment, QuadraticBezier):
            piece = _flatten_bezier(world(segment.start, segment.control, segment.end), tol)
        elif isinstance(segment, Arc):
            piece = _flatten_arc(segment, linear, offset, tol, world(segment.end))
        elif isinstance(segment, (Line, Close)):
            piece = world(segment.end)
        else:
            raise _Refusal(f"expected lines, Béziers and arcs, found a {type(segment).__name__} segment")
        count += len(piece)
        if count > MAX_VERTICES:
            raise _Refusal(f"expected at most {MAX_VERTICES} vertices, found more at tolerance {tol:g}")
        out.append(piece)
    return np.concatenate(out)


def _flatten_bezier(nodes: NDArray[np.float64], tol: float) -> NDArray[np.float64]:
    """Vertices after the first of a Bézier ``(degree + 1, 2)``, by halving until flat.

    Each emitted chord's piece is within ``tol`` of it (see :func:`_flatness`),
    so the whole curve is within ``tol`` of the polygon.
    """
    out: list[NDArray[np.float64]] = []
    stack = [(nodes, 0)]
    while stack:
        piece, depth = stack.pop()
        if _flatness(piece) <= tol:
            out.append(piece[-1])
            if len(out) > MAX_VERTICES:
                raise _Refusal(f"expected at most {MAX_VERTICES} vertices, found more at tolerance {tol:g}")
            continue
        if depth >= _MAX_DEPTH:
            raise _Refusal(f"expected a tolerance the coordinates can resolve, found {tol:g}")
        left, right = _halve(piece)
        stack += [(right, depth + 1), (left, depth + 1)]
    return np.array(out)


def _flatness(nodes: NDArray[np.float64]) -> float:
    """An upper bound of the distance from a Bézier to its chord (segment first–last node).

    The smaller of two sound bounds: the curve lies in its control points' convex
    hull and distance to a segment is convex, so the farthest control point
    bounds it (zero for any straight curve); and, writing B(t) - L(t) as
    Σ b_i(t) (P_i - L(i/n)) with L the chord at uniform speed, that is at most
    (1 - 2^(1-n)) max |P_i - L(i/n)| (3/4 for cubics, 1/2 for quadratics).
    """
    first, last = nodes[0], nodes[-1]
    inner = nodes[1:-1]
    chord = last - first
    # control points near the float limit overflow to inf or NaN here, deliberately: such a
    # curve never flattens, and _flatten_bezier refuses it
    with np.errstate(over="ignore", invalid="ignore"):
        length2 = float(chord @ chord)
        s = np.clip((inner - first) @ chord / length2, 0.0, 1.0) if length2 > 0 else np.zeros(len(inner))
        hull = np.max(np.hypot(*(inner - first - s[:, None] * chord).T))
        n = len(nodes) - 1
        u = np.arange(1, n)[:, None] / n
        uniform = (1.0 - 2.0 ** (1 - n)) * np.max(np.hypot(*(inner - first - u * chord).T))
    return float(min(hull, uniform))


def _halve(nodes: NDArray[np.float64]) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """de Casteljau at t = 1/2: the control points of both halves."""
    left, right, level = [nodes[0]], [nodes[-1]], nodes
    while len(level) > 1:
        level = 0.5 * (level[:-1] + level[1:])
        left.append(level[0])
        right.append(level[-1])
    return np.array(left), np.array(right[::-1])


def _flatten_arc(
    arc: Arc, linear: NDArray[np.float64], offset: NDArray[np.float64], tol: float, end: NDArray[np.float64]
) -> NDArray[np.float64]:
    """Vertices after the first of an elliptical arc, at equal steps of its parameter; ``end`` ``(1, 2)``.

    Locally the arc is c + a cos θ + b sin θ (a, b its semi-axes); in the world
    it is c' + W (cos θ, sin θ) with W = linear @ [a b], the affine image of a
    unit circle. A chord spanning Δ of the unit circle stays within the sagitta
    1 - cos(Δ/2) of it, and W stretches no distance by more than its largest
    singular value σ, so steps Δ ≤ 2 arccos(1 - tol/σ) keep the curve within tol.
    For a circle of radius r this is the exact sagitta rule (σ = r).
    """
    rx, ry = float(arc.rx), float(arc.ry)
    if arc.sweep == 0 or rx == 0 or ry == 0:
        return end  # a zero-radius arc is a straight line (SVG's rule)
    center = np.array([arc.center.x, arc.center.y])
    a = np.array([arc.prx.x, arc.prx.y]) - center
    b = (ry / rx) * np.array([-a[1], a[0]])  # svgelements' frame: t = π/2 lies 90° on from prx
    axes = np.column_stack([a, b])
    theta0, theta1 = (
        math.atan2(*np.linalg.solve(axes, np.array([p.x, p.y]) - center)[::-1]) for p in (arc.start, arc.end)
    )
    # The sweep from the exact end points, in the direction and turn count of svgelements' sweep.
    sweep = theta1 - theta0 + 2 * math.pi * round((arc.sweep - (theta1 - theta0)) / (2 * math.pi))
    world_axes = linear @ axes
    sigma = float(np.linalg.norm(world_axes, 2))
    if sigma <= tol:
        step = math.pi / 2
    else:
        step = min(math.pi / 2, 2.0 * math.acos(1.0 - tol / sigma))
    n = max(1, math.ceil(abs(sweep) / step - 1e-12))
    if n > MAX_VERTICES:
        raise _Refusal(f"expected at most {MAX_VERTICES} vertices, found more at tolerance {tol:g}")
    theta = theta0 + sweep * np.arange(1, n) / n
    inner = (linear @ center + offset) + np.column_stack([np.cos(theta), np.sin(theta)]) @ world_axes.T
    return np.vstack([inner, end])


def _distinct(points: NDArray[np.float64]) -> NDArray[np.float64]:
    """Without consecutive duplicates or closing duplicates (within 1e-9 of the extent)."""
    if len(points) == 0:
        return points
    extent = float(np.max(np.ptp(points, axis=0)))
    eps = 1e-9 * extent
    kept = [points[0]]
    for point in points[1:]:
        if np.max(np.abs(point - kept[-1])) > eps:
            kept.append(point)
    while len(kept) > 1 and np.max(np.abs(kept[-1] - kept[0])) <= eps:
        kept.pop()
    return np.array(kept, dtype=np.float64)
