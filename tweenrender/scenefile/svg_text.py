"""``<text>`` laid out as SVG 1.1 §10 and browsers lay it out, into the outlines of its glyphs.

The characters of a ``<text>`` and of the ``<tspan>``, ``<a>`` and ``<tref>`` in it are gathered in
document order, each with the style of the element it is in (``display: none`` leaves an element's
characters out; ``visibility: hidden`` keeps their room). White space is what browsers make of it:
with ``xml:space="default"`` line breaks and tabs are spaces, runs of spaces one space, and the text's
leading and trailing spaces go; ``xml:space="preserve"`` keeps every space. The ``x``, ``y``, ``dx``
and ``dy`` lists give characters their positions, an inner element's over an outer one's; a character
with an ``x`` or ``y`` starts a text chunk, placed by its ``text-anchor``. Runs of one style are
shaped (:mod:`.svg_fonts`) and moved by ``letter-spacing`` and ``word-spacing``.

Each element's glyphs become one path (``d``, in the text's user space), drawn with its style.
``<textPath>``, vertical writing and the baseline properties are not read: a ``<textPath>`` is refused.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

from .svg_flatten import Refusal
from .svg_fonts import Face, FontRequest, face_for, fallback_for, outline, shape
from .svg_lengths import DEFAULT_FONT_SIZE, user_units

__all__ = ["MAX_CHARACTERS", "TextNode", "Laid", "font_longhands", "lay_out"]

MAX_CHARACTERS = 100_000
"""Characters in one ``<text>``: a keyframe drawing's labels are a few words."""

_CONTENT = ("tspan", "a", "tref")
_WEIGHTS = {"normal": 400, "bold": 700}
_WIDTHS = {"ultra-condensed": 1, "extra-condensed": 2, "condensed": 3, "semi-condensed": 4, "normal": 5,
           "semi-expanded": 6, "expanded": 7, "extra-expanded": 8, "ultra-expanded": 9}
_SEPARATOR = re.compile(r"[\s,]+")
_FONT_TOKEN = re.compile(r"""'[^']*'|"[^"]*"|[^\s'"]+""")
_STYLES = ("italic", "oblique")
_WEIGHT_WORDS = ("bold", "bolder", "lighter")


class TextNode(Protocol):
    tag: str
    attrs: dict[str, str]
    line: int
    children: list[TextNode]  # type: ignore[misc]
    text: str
    tail: str
    svg: bool
    font: tuple[float, float]
    view: tuple[float, float]


StyleOf = Callable[[TextNode, dict[str, str]], "dict[str, str] | None"]
"""An element's style given its parent's; None when it is not displayed."""


@dataclass(frozen=True, slots=True)
class Laid:
    """One element's glyphs: the element, its style, whether it is visible, and its glyphs as path data."""

    node: TextNode
    style: dict[str, str]
    visible: bool
    d: str


@dataclass(slots=True)
class _Span:
    node: TextNode
    style: dict[str, str]
    request: FontRequest
    size: float


@dataclass(slots=True)
class _Char:
    char: str
    span: int
    chain: tuple[int, ...]  # the positioning elements it is in, outermost first
    preserve: bool


def font_longhands(value: str) -> dict[str, str]:
    """The CSS ``font`` shorthand (``italic bold 12px/1.2 "Noto Sans", sans-serif``) as its longhands; {} when
    it names no size (a system font keyword, or not a font)."""
    tokens = _FONT_TOKEN.findall(value.strip())
    found: dict[str, str] = {}
    for index, token in enumerate(tokens):
        word = token.lower()
        size = word.split("/")[0]
        if size in _SIZE_WORDS or (size[:1].isdigit() or size[:1] == ".") and not word.isdigit():
            family = " ".join(tokens[index + 1:]).strip()
            if not family:
                return {}
            return {**found, "font-size": token.split("/")[0], "font-family": family}
        if word in _STYLES:
            found["font-style"] = word
        elif word in _WEIGHT_WORDS or word.isdigit():
            found["font-weight"] = word
        elif word in _WIDTHS and word != "normal":
            found["font-stretch"] = word
    return {}


_SIZE_WORDS = ("xx-small", "x-small", "small", "medium", "large", "x-large", "xx-large", "xxx-large", "smaller",
               "larger")


def lay_out(node: TextNode, style: dict[str, str], style_of: StyleOf, viewport: tuple[float, float],
            ids: dict[str, list[TextNode]]) -> list[Laid]:
    """The glyphs of the ``<text>`` ``node`` (style ``style``), an entry for each element with characters;
    ``viewport`` ``(width, height)`` is what percentages are of, ``ids`` what ``<tref>`` names."""
    spans: list[_Span] = []
    chars: list[_Char] = []
    elements: list[TextNode] = []
    _gather(node, style, None, (), False, style_of, ids, spans, chars, elements)
    chars = _collapse(chars)
    if len(chars) > MAX_CHARACTERS:
        raise Refusal(f"expected at most {MAX_CHARACTERS} characters in a <text>, found {len(chars)} "
                      f"(line {node.line})")
    if not chars:
        return []
    x, y, dx, dy = _positions(chars, elements, viewport)
    glyphs = _place(chars, spans, x, y, dx, dy)
    laid = []
    for index, span in enumerate(spans):
        d = " ".join(_path(placed) for placed in glyphs if placed[0] == index)
        if d:
            visible = span.style.get("visibility", "visible").strip() not in ("hidden", "collapse")
            laid.append(Laid(span.node, span.style, visible, d))
    return laid


def _gather(node: TextNode, style: dict[str, str], parent: FontRequest | None, chain: tuple[int, ...],
            preserve: bool, style_of: StyleOf, ids: dict[str, list[TextNode]], spans: list[_Span],
            chars: list[_Char], elements: list[TextNode], parent_style: dict[str, str] | None = None) -> None:
    """Appends the characters of ``node`` and of the text content elements in it."""
    space = node.attrs.get("space")
    preserve = space.strip() == "preserve" if space is not None else preserve
    request = _request(style, parent, parent_style)
    span = len(spans)
    spans.append(_Span(node, style, request, float(style.get("font-size", DEFAULT_FONT_SIZE))))
    chain = chain + (len(elements),)
    elements.append(node)

    def add(text: str) -> None:
        chars.extend(_Char(c, span, chain, preserve) for c in text)

    if node.tag == "tref":
        href = node.attrs.get("href", node.attrs.get("xlink:href", "")).strip()
        target = ids.get(href[1:]) if href.startswith("#") else None
        add(_all_text(target[0]) if target else "")
        return
    add(node.text)
    for child in node.children:
        if child.svg and child.tag == "textPath":
            raise Refusal(f"expected text without <textPath>, found one (line {child.line}); "
                          "convert it to paths in the editor (Inkscape: Path > Object to Path)")
        if child.svg and child.tag in _CONTENT:
            child_style = style_of(child, style)
            if child_style is not None:
                _gather(child, child_style, request, chain, preserve, style_of, ids, spans, chars, elements, style)
        add(child.tail)


def _all_text(node: TextNode) -> str:
    """Every character of ``node``'s content, its descendants' included."""
    return node.text + "".join(_all_text(child) + child.tail for child in node.children)


def _request(style: dict[str, str], parent: FontRequest | None, parent_style: dict[str, str] | None) -> FontRequest:
    """The font ``style`` asks for; ``bolder`` and ``lighter`` are of the parent's weight."""
    families = tuple(f.strip().strip("'\"").strip() for f in style.get("font-family", "serif").split(","))
    weight_text = style.get("font-weight", "normal").strip().lower()
    inherited = parent is not None and parent_style is not None and \
        parent_style.get("font-weight") == style.get("font-weight")
    base = parent.weight if parent is not None else 400
    if inherited:
        weight = base
    elif weight_text == "bolder":
        weight = 400 if base < 350 else 700 if base < 550 else 900
    elif weight_text == "lighter":
        weight = 100 if base < 550 else 400 if base < 750 else 700
    else:
        weight = _WEIGHTS.get(weight_text) or (int(weight_text) if weight_text.isdigit() else base)
    slant_text = style.get("font-style", "normal").strip().lower()
    slant = 1 if slant_text == "italic" else 2 if slant_text.startswith("oblique") else 0
    width = _WIDTHS.get(style.get("font-stretch", "normal").strip().lower(), 5)
    return FontRequest(tuple(f for f in families if f) or ("serif",), min(max(weight, 1), 1000), width, slant)


def _collapse(chars: list[_Char]) -> list[_Char]:
    """White space as browsers make it: line breaks and tabs are spaces; outside ``preserve``, runs of spaces
    are one and the text's leading and trailing spaces go."""
    kept: list[_Char] = []
    for c in chars:
        char = " " if c.char in "\n\r\t" else c.char
        if char == " " and not c.preserve and (not kept or kept[-1].char == " "):
            continue
        kept.append(_Char(char, c.span, c.chain, c.preserve))
    while kept and kept[-1].char == " " and not kept[-1].preserve:
        kept.pop()
    return kept


def _positions(chars: list[_Char], elements: list[TextNode], viewport: tuple[float, float]
               ) -> tuple[list[float | None], list[float | None], list[float], list[float]]:
    """Each character's absolute ``x`` and ``y`` (None: where the text before leaves it) and ``dx``, ``dy``."""
    x: list[float | None] = [None] * len(chars)
    y: list[float | None] = [None] * len(chars)
    dx = [0.0] * len(chars)
    dy = [0.0] * len(chars)
    owned: list[list[int]] = [[] for _ in elements]
    for index, c in enumerate(chars):
        for element in c.chain:
            owned[element].append(index)
    width, height = viewport
    for element, node in enumerate(elements):  # outermost first: an inner element's values win
        for name, values, relative in (("x", x, width), ("y", y, height), ("dx", dx, width), ("dy", dy, height)):
            for index, value in zip(owned[element], _length_list(node, name, relative)):
                values[index] = value  # type: ignore[call-overload]
    return x, y, dx, dy


def _length_list(node: TextNode, name: str, relative: float) -> list[float]:
    """A list of lengths (``x="10 20 30"``) in user units; reading stops at the first that is not a length."""
    values = []
    for text in _SEPARATOR.split(node.attrs.get(name, "").strip()):
        value = user_units(text, node.font, node.view, relative, strict=True) if text else None
        if value is None:
            break
        values.append(value)
    return values


_Placed = tuple[int, Face, int, float, float, float]
"""A glyph placed: (span, face, glyph id, x, y of its origin, user units per font unit)."""


def _place(chars: list[_Char], spans: list[_Span], x: list[float | None], y: list[float | None],
           dx: list[float], dy: list[float]) -> list[_Placed]:
    """Every glyph placed: chunks started by an absolute position, shaped run by run, moved by their anchor."""
    placed: list[_Placed] = []
    pen_x = pen_y = 0.0
    start = 0
    while start < len(chars):
        end = start + 1
        while end < len(chars) and x[end] is None and y[end] is None:
            end += 1
        pen_x = x[start] if x[start] is not None else pen_x  # type: ignore[assignment]
        pen_y = y[start] if y[start] is not None else pen_y  # type: ignore[assignment]
        left, first = pen_x, len(placed)
        run = start
        while run < end:
            stop = run + 1
            while stop < end and chars[stop].span == chars[run].span:
                stop += 1
            pen_x, pen_y = _shape_run(chars, run, stop, spans[chars[run].span], dx, dy, pen_x, pen_y, placed)
            run = stop
        anchor = spans[chars[start].span].style.get("text-anchor", "start").strip()
        shift = {"middle": -(pen_x - left) / 2.0, "end": -(pen_x - left)}.get(anchor, 0.0)
        placed[first:] = [(s, tf, g, px + shift, py, k) for s, tf, g, px, py, k in placed[first:]]
        start = end
    return placed


def _shape_run(chars: list[_Char], start: int, stop: int, span: _Span, dx: list[float], dy: list[float],
               pen_x: float, pen_y: float, placed: list[_Placed]) -> tuple[float, float]:
    """Shapes ``chars[start:stop]`` (one style) from the pen, in pieces of one face; the pen after it."""
    primary = face_for(span.request)
    letter = _spacing(span, "letter-spacing")
    word = _spacing(span, "word-spacing")
    index = start
    while index < stop:
        face = _face_of(primary, span.request, chars[index].char)
        end = index + 1
        while end < stop and _face_of(primary, span.request, chars[end].char) is face:
            end += 1
        text = "".join(c.char for c in chars[index:end])
        scale = span.size / face.upem
        seen: set[int] = set()
        for glyph in shape(face, text):
            at = index + glyph.cluster
            if at not in seen:
                seen.add(at)
                pen_x, pen_y = pen_x + dx[at], pen_y + dy[at]
            placed.append((chars[at].span, face, glyph.gid, pen_x + glyph.offset[0] * scale,
                           pen_y - glyph.offset[1] * scale, scale))
            pen_x += glyph.advance[0] * scale + letter + (word if chars[at].char == " " else 0.0)
            pen_y -= glyph.advance[1] * scale
        index = end
    return pen_x, pen_y


def _face_of(primary: Face, request: FontRequest, char: str) -> Face:
    """``primary`` when it has a glyph for ``char`` (or it is a space or a control), else a fallback that has."""
    code = ord(char)
    if char.isspace() or code < 32 or primary.has(code):
        return primary
    return fallback_for(request, code) or primary


def _spacing(span: _Span, name: str) -> float:
    """``letter-spacing`` or ``word-spacing`` in user units (``normal``, a percentage, what is not a length: 0)."""
    text = span.style.get(name, "normal").strip()
    if text == "normal" or not text or text.endswith("%"):
        return 0.0
    return user_units(text, span.node.font, span.node.view, strict=True) or 0.0


def _path(placed: _Placed) -> str:
    """One placed glyph's outline as path data in user units."""
    _, face, gid, px, py, scale = placed
    parts = []
    for verb, points in outline(face, gid):
        parts.append(verb)
        if len(points):
            xy = points * scale + (px, py)
            parts.append(" ".join(f"{v:.7g}" for v in xy.ravel()))
    return " ".join(parts)
