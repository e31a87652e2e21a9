"""Fonts for ``<text>``: a CSS font (families, weight, width, slant) matched to a font file, text shaped
and each glyph's outline read by HarfBuzz (uharfbuzz: kerning, ligatures, the scripts' own rules).

Font files are looked for, in this order, in the folders of the environment variable ``TWEENRENDER_FONT_PATH``
(separated like ``PATH``), in the system's font folders, and last in the DejaVu Sans shipped with the
package, so text always draws. Family names match without regard to case (a file is known by its
typographic family name, its legacy one, its full name and its PostScript name, as Illustrator writes
``font-family="'MyriadPro-Regular'"``); among a family's faces the nearest in width, then slant,
then weight is taken, as CSS Fonts 4 §5.2 orders them. A generic family (``serif``, ``sans-serif``,
``monospace``, ``cursive``, ``fantasy``, ``system-ui``) is the first of a few common families that is
installed. A character the chosen face has no glyph for is drawn in the first face found that has one.
"""

from __future__ import annotations

import os
import struct
import sys
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

__all__ = ["FONT_PATH", "FontRequest", "Face", "Glyph", "face_for", "fallback_for", "shape", "outline"]

FONT_PATH = "TWEENRENDER_FONT_PATH"
"""The environment variable naming folders of fonts searched before the system's."""

MAX_FONT_FILES = 20_000
"""Font files read in one folder tree (a folder of more is read that far)."""

_GENERIC = {
    "serif": ("Noto Serif", "DejaVu Serif", "Times New Roman", "Liberation Serif", "Times"),
    "sans-serif": ("Noto Sans", "DejaVu Sans", "Arial", "Helvetica", "Liberation Sans"),
    "monospace": ("Noto Sans Mono", "Noto Mono", "DejaVu Sans Mono", "Courier New", "Liberation Mono", "Courier"),
    "cursive": ("Comic Sans MS", "Noto Sans", "DejaVu Sans"),
    "fantasy": ("Impact", "Noto Sans", "DejaVu Sans"),
    "system-ui": ("Noto Sans", "DejaVu Sans", "Arial", "Helvetica"),
}
_SHIPPED = Path(__file__).resolve().parents[1] / "raster" / "fonts"
_EXTENSIONS = (".ttf", ".otf", ".ttc", ".otc")


@dataclass(frozen=True, slots=True)
class FontRequest:
    """A font as CSS asks for it: families in order of preference, weight (1–1000), width (1–9), slant
    (0 upright, 1 italic, 2 oblique)."""

    families: tuple[str, ...]
    weight: int = 400
    width: int = 5
    slant: int = 0


@dataclass(frozen=True, slots=True)
class _Entry:
    """One face of a font file: where it is and what it is."""

    path: str
    index: int
    weight: int
    width: int
    slant: int


@dataclass(eq=False)
class Face:
    """A face opened for shaping and drawing: its HarfBuzz font (scaled in font units) and units per em."""

    entry: _Entry
    font: object = field(repr=False)
    upem: int = 1000
    _cmap: set[int] | None = field(default=None, repr=False)
    _outlines: dict[int, tuple[tuple[str, NDArray[np.float64]], ...]] = field(default_factory=dict, repr=False)

    def has(self, codepoint: int) -> bool:
        """Whether the face has a glyph for ``codepoint``."""
        if self._cmap is None:
            self._cmap = set(self.font.face.unicodes)  # type: ignore[attr-defined]
        return codepoint in self._cmap


@dataclass(frozen=True, slots=True)
class Glyph:
    """One shaped glyph: its id, the character index (of the shaped string) it starts at, its advance and
    offset in font units (x right, y up, as HarfBuzz gives them)."""

    gid: int
    cluster: int
    advance: tuple[int, int]
    offset: tuple[int, int]


def _system_folders() -> list[str]:
    """The system's font folders on this platform."""
    home = Path.home()
    if sys.platform == "darwin":
        folders = ["/System/Library/Fonts", "/Library/Fonts", str(home / "Library" / "Fonts")]
    elif sys.platform == "win32":
        windows = os.environ.get("WINDIR", r"C:\Windows")
        local = os.environ.get("LOCALAPPDATA", str(home / "AppData" / "Local"))
        folders = [os.path.join(windows, "Fonts"), os.path.join(local, "Microsoft", "Windows", "Fonts")]
    else:
        data = os.environ.get("XDG_DATA_HOME", str(home / ".local" / "share"))
        folders = ["/usr/share/fonts", "/usr/local/share/fonts", os.path.join(data, "fonts"), str(home / ".fonts")]
    return folders


def _faces_in(path: str) -> list[tuple[list[str], _Entry]]:
    """Each face of the font file ``path``: the names it is known by and what it is ([] when it cannot be read)."""
    import uharfbuzz as hb

    try:
        blob = hb.Blob.from_file_path(path)
        with open(path, "rb") as handle:
            head = handle.read(12)
    except (OSError, ValueError):
        return []
    count = struct.unpack(">I", head[8:12])[0] if head[:4] == b"ttcf" and len(head) == 12 else 1
    found = []
    for index in range(min(count, 64)):
        face = hb.Face(blob, index)
        if face.glyph_count == 0:
            continue
        names = [face.get_name(hb.OTNameIdPredefined.TYPOGRAPHIC_FAMILY),
                 face.get_name(hb.OTNameIdPredefined.FONT_FAMILY), face.get_name(hb.OTNameIdPredefined.FULL_NAME),
                 face.get_name(hb.OTNameIdPredefined.POSTSCRIPT_NAME)]
        names = [n for n in dict.fromkeys(names) if n]
        if names:
            found.append((names, _describe(face, path, index)))
    return found


def _describe(face, path: str, index: int) -> _Entry:  # type: ignore[no-untyped-def]
    """The weight, width and slant of a face, from its OS/2 table (else its style name)."""
    table = face.reference_table("OS/2").data
    if len(table) >= 64:
        weight, width = struct.unpack(">HH", table[4:8])
        selection = struct.unpack(">H", table[62:64])[0]
        slant = 2 if selection & 0x200 else 1 if selection & 0x1 else 0
        return _Entry(path, index, min(max(weight, 1), 1000), min(max(width, 1), 9), slant)
    import uharfbuzz as hb

    style = (face.get_name(hb.OTNameIdPredefined.FONT_SUBFAMILY) or "").lower()
    return _Entry(path, index, 700 if "bold" in style else 400, 5,
                  1 if "italic" in style else 2 if "oblique" in style else 0)


@lru_cache(maxsize=16)
def _index(folder: str) -> dict[str, list[_Entry]]:
    """Every face in the font files under ``folder``, by lower-case family name."""
    faces: dict[str, list[_Entry]] = {}
    seen = 0
    for root, _, files in sorted(os.walk(folder)):
        for name in sorted(files):
            if not name.lower().endswith(_EXTENSIONS):
                continue
            seen += 1
            if seen > MAX_FONT_FILES:
                return faces
            for names, entry in _faces_in(os.path.join(root, name)):
                for family in names:
                    faces.setdefault(family.lower(), []).append(entry)
    return faces


def _folders() -> list[str]:
    """The font folders searched, in order: :data:`FONT_PATH`'s, the system's, the shipped one."""
    given = [f for f in os.environ.get(FONT_PATH, "").split(os.pathsep) if f]
    return [f for f in given + _system_folders() + [str(_SHIPPED)] if os.path.isdir(f)]


def _weight_order(wanted: int, weight: int) -> tuple[int, int]:
    """How far ``weight`` is from ``wanted`` in CSS's order of preference (smaller first)."""
    if 400 <= wanted <= 500:
        if wanted <= weight <= 500:
            return (0, weight - wanted)
        return (1, wanted - weight) if weight < wanted else (2, weight - wanted)
    if wanted < 400:
        return (0, wanted - weight) if weight <= wanted else (1, weight - wanted)
    return (0, weight - wanted) if weight >= wanted else (1, wanted - weight)


_SLANT_ORDER = {0: (0, 2, 1), 1: (1, 2, 0), 2: (2, 1, 0)}


def _best(entries: list[_Entry], request: FontRequest) -> _Entry:
    """The face of a family nearest ``request``: width, then slant, then weight (CSS Fonts 4 §5.2)."""
    def order(entry: _Entry) -> tuple[object, ...]:
        narrower_first = request.width <= 5
        width = (0, 0) if entry.width == request.width else \
            ((0 if (entry.width < request.width) == narrower_first else 1), abs(entry.width - request.width))
        return (width, _SLANT_ORDER[request.slant].index(entry.slant), _weight_order(request.weight, entry.weight))

    return min(entries, key=order)


@lru_cache(maxsize=64)
def _open(entry: _Entry) -> Face:
    import uharfbuzz as hb

    face = hb.Face(hb.Blob.from_file_path(entry.path), entry.index)
    return Face(entry, hb.Font(face), face.upem)


def _find(family: str, request: FontRequest, folders: tuple[str, ...]) -> Face | None:
    """The face of one family name in the first folder that has it, or None."""
    for folder in folders:
        entries = _index(folder).get(family.lower())
        if entries:
            return _open(_best(entries, request))
    return None


def face_for(request: FontRequest) -> Face:
    """The face that draws ``request``: of its first family that is installed, else the shipped one."""
    return _face_for(request, tuple(_folders()))


@lru_cache(maxsize=256)
def _face_for(request: FontRequest, folders: tuple[str, ...]) -> Face:
    for family in request.families + ("sans-serif",):
        for name in (family,) + _GENERIC.get(family.lower(), ()):
            found = _find(name, request, folders)
            if found is not None:
                return found
    return _open(_best(_index(str(_SHIPPED))["dejavu sans"], request))


def fallback_for(request: FontRequest, codepoint: int) -> Face | None:
    """The first face found (generic families first, then every folder) that has ``codepoint``, or None."""
    return _fallback_for(request, codepoint, tuple(_folders()))


@lru_cache(maxsize=256)
def _fallback_for(request: FontRequest, codepoint: int, folders: tuple[str, ...]) -> Face | None:
    for family in _GENERIC["sans-serif"] + _GENERIC["serif"]:
        found = _find(family, request, folders)
        if found is not None and found.has(codepoint):
            return found
    for folder in folders:
        for entries in _index(folder).values():
            face = _open(_best(entries, request))
            if face.has(codepoint):
                return face
    return None


def shape(face: Face, text: str) -> list[Glyph]:
    """``text`` shaped in ``face`` (HarfBuzz, its default features: kerning and ligatures), in visual order."""
    import uharfbuzz as hb

    buffer = hb.Buffer()
    buffer.add_str(text)
    buffer.guess_segment_properties()
    hb.shape(face.font, buffer, {})
    return [Glyph(info.codepoint, info.cluster, (pos.x_advance, pos.y_advance), (pos.x_offset, pos.y_offset))
            for info, pos in zip(buffer.glyph_infos, buffer.glyph_positions)]


class _Pen:
    """Collects a glyph's outline as ``(verb, points (K, 2))`` steps, y flipped down."""

    def __init__(self) -> None:
        self.steps: list[tuple[str, NDArray[np.float64]]] = []

    def _add(self, verb: str, *points: tuple[float, float]) -> None:
        self.steps.append((verb, np.array([(x, -y) for x, y in points], dtype=float).reshape(-1, 2)))

    def moveTo(self, p: tuple[float, float]) -> None:  # noqa: N802 - the pen protocol's names
        self._add("M", p)

    def lineTo(self, p: tuple[float, float]) -> None:  # noqa: N802
        self._add("L", p)

    def qCurveTo(self, *points: tuple[float, float]) -> None:  # noqa: N802
        *controls, end = points
        for a, b in zip(controls, controls[1:]):  # implied on-curve points between controls
            self._add("Q", a, ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2))
        self._add("Q", controls[-1], end) if controls else self._add("L", end)

    def curveTo(self, *points: tuple[float, float]) -> None:  # noqa: N802
        self._add("C", *points[-3:])

    def closePath(self) -> None:  # noqa: N802
        self.steps.append(("Z", np.empty((0, 2))))

    endPath = closePath  # noqa: N815


def outline(face: Face, gid: int) -> tuple[tuple[str, NDArray[np.float64]], ...]:
    """Glyph ``gid``'s outline in font units, y down (SVG's way), baseline at 0: ``(verb, points (K, 2))``
    steps, verbs ``M``, ``L``, ``Q``, ``C``, ``Z``; read once a glyph."""
    if gid not in face._outlines:
        pen = _Pen()
        face.font.draw_glyph_with_pen(gid, pen)  # type: ignore[attr-defined]
        face._outlines[gid] = tuple(pen.steps)
    return face._outlines[gid]
