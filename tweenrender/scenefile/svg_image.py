"""Pictures and drawings in ``<image>``: where their bytes come from, and where they are drawn.

An ``<image>`` names a PNG, JPEG, GIF or WebP picture, or an SVG drawing (``.svg``, ``.svgz``), by a
``data:`` URL (base64 or percent-encoded) or by a file path (relative to the drawing's folder, or
absolute, as an editor's linked image is); a web address is not fetched, and a drawing given as data
reads no file. It is drawn in the viewport ``x``, ``y``, ``width``, ``height`` (a missing or ``auto`` size
is the picture's or drawing's own, or in its proportions where the other side is given; SVG 2), placed
there by the ``<image>``'s ``preserveAspectRatio`` (default ``xMidYMid meet``; a drawing's own is not
used), cut off at the viewport. A picture's ``image-rendering: pixelated`` (``optimizeSpeed``,
``crisp-edges``) samples the nearest pixel, anything else blends them; it is turned as its EXIF
orientation says (CSS ``image-orientation: from-image``); a GIF or WebP shows its first frame. A drawing's
shapes are read as the drawing's own (:mod:`.svg_document`), so they morph like any others. What cannot be
read (a missing file, a web address, data that is no picture or no well-formed drawing, a drawing that
shows itself) draws nothing,
as browsers draw a broken image in SVG, said with ``-v``; a picture of more than :data:`MAX_PIXELS` pixels
or a file over :data:`MAX_FILE_BYTES` is refused.
"""

from __future__ import annotations

import base64
import binascii
import hashlib
import io
import re
import urllib.parse
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from .svg_flatten import Refusal
from .svg_lengths import user_units
from .svg_notes import note
from .svg_viewport import aspect_matrix

__all__ = ["MAX_PIXELS", "PlacedImage", "image_data", "is_drawing", "place_picture", "placement"]

MAX_PIXELS = 40_000_000
"""The largest picture read, in pixels (160 MB of RGBA)."""
MAX_FILE_BYTES = 256 << 20
"""The largest file an ``<image>`` reads, in bytes."""

_NEAREST = ("pixelated", "optimizespeed", "crisp-edges", "-moz-crisp-edges")
_WEB = re.compile(r"^[a-z][a-z0-9+.-]*://", re.IGNORECASE)


class Node(Protocol):
    """An element of the drawing's tree (:class:`.svg_document.Node`)."""

    tag: str
    attrs: dict[str, str]
    line: int
    font: tuple[float, float]
    view: tuple[float, float]


@dataclass(frozen=True, slots=True, eq=False)
class PlacedImage:
    """A picture as an ``<image>`` draws it: ``pixels (H, W, 4)`` straight RGBA, ``matrix (3, 3)`` from its
    pixels (x right, y down, a pixel a unit) to the element's user units, ``rect`` ``(x, y, w, h)`` the part of
    the element's user space it covers (its viewport, cut to the placed picture), ``smooth`` whether pixels
    are blended (else the nearest is taken)."""

    pixels: NDArray[np.uint8]
    matrix: NDArray[np.float64]
    rect: tuple[float, float, float, float]
    smooth: bool

    def mean_colour(self) -> str:
        """The picture's mean colour (each pixel weighted by its alpha), as CSS ``#rrggbb``: the plain colour it
        stands on while it fades in or out, and stands for where one colour is drawn."""
        rgba = self.pixels.reshape(-1, 4).astype(np.float64)
        weight = rgba[:, 3].sum()
        mean = rgba[:, :3].T @ rgba[:, 3] / weight if weight > 0 else np.zeros(3)
        return "#" + "".join(f"{int(round(v)):02x}" for v in mean)


def image_data(node: Node, folder: Path | None) -> tuple[bytes, Path | None] | None:
    """The bytes ``node`` (an ``<image>``) names and the folder relative paths inside them are of (a file's;
    None for a ``data:`` URL, whose drawing reads no files); None where there are none (said with ``-v``).
    ``folder`` is the drawing's (None: no file is read)."""
    href = (node.attrs.get("href") or node.attrs.get("xlink:href") or "").strip()
    return _source(href, folder, node.line)


def is_drawing(data: bytes) -> bool:
    """Whether ``data`` is an SVG drawing (XML text, or gzip-compressed: ``.svgz``) rather than a picture."""
    start = data[:512].lstrip()
    return start.startswith(b"\x1f\x8b") or start[:1] == b"<"


def place_picture(node: Node, style: dict[str, str], data: bytes, viewport: tuple[float, float],
                  decoded: dict[bytes, NDArray[np.uint8] | None] | None = None) -> PlacedImage | None:
    """The picture in ``data`` as ``node`` (an ``<image>`` with the resolved ``style``) draws it, placed in its
    user space; None where it draws nothing. ``viewport`` is what its percentages are of; ``decoded`` keeps
    the pictures decoded so far by their data's digest (a picture used again is decoded once, its pixels
    shared)."""
    key = hashlib.sha256(data).digest()
    if decoded is None or key not in decoded:
        pixels = _decode(data, node.line)
        if decoded is not None:
            decoded[key] = pixels
    else:
        pixels = decoded[key]
    if pixels is None:
        return None
    height, width = pixels.shape[:2]
    placed = placement(node, viewport, (float(width), float(height)), (0.0, 0.0, float(width), float(height)))
    if placed is None:
        return None
    rendering = style.get("image-rendering", "auto").strip().lower()
    return PlacedImage(pixels, placed[0], placed[1], rendering not in _NEAREST)


def placement(node: Node, viewport: tuple[float, float], size: tuple[float, float],
              box: tuple[float, float, float, float]) -> tuple[NDArray[np.float64], tuple[float, float, float, float]] | None:
    """Where ``node`` (an ``<image>``) puts what it shows, of intrinsic ``size`` ``(w, h)`` and coordinates
    ``box`` ``(x, y, w, h)`` (a picture's pixels, a drawing's view box): the map ``(3, 3)`` from those
    coordinates to its user units, and the rectangle ``(x, y, w, h)`` it covers there (its viewport cut to
    what is placed in it); None where it covers nothing. ``viewport`` is what percentages are of."""
    found = _size(node, viewport, *size)
    if found is None:
        return None
    x = user_units(node.attrs.get("x", "0"), node.font, node.view, viewport[0], strict=True) or 0.0
    y = user_units(node.attrs.get("y", "0"), node.font, node.view, viewport[1], strict=True) or 0.0
    w, h = found
    fit = aspect_matrix(box, w, h, node.attrs.get("preserveAspectRatio", "xMidYMid meet").strip())
    matrix = np.array([[1.0, 0.0, x], [0.0, 1.0, y], [0.0, 0.0, 1.0]]) @ fit
    bx, by, bw, bh = box
    corners = matrix @ np.array([[bx, bx + bw], [by, by + bh], [1.0, 1.0]])
    left, right = max(x, float(corners[0].min())), min(x + w, float(corners[0].max()))
    top, bottom = max(y, float(corners[1].min())), min(y + h, float(corners[1].max()))
    if not (right > left and bottom > top and np.all(np.isfinite(matrix))):
        return None
    return matrix, (left, top, right - left, bottom - top)


def _size(node: Node, viewport: tuple[float, float], width: float, height: float) -> tuple[float, float] | None:
    """The viewport's width and height (user units): given, or the picture's own (in its proportions where
    one side is given); None where one is zero or less."""
    def side(name: str, relative: float) -> float | None:
        text = node.attrs.get(name, "auto").strip()
        if text in ("", "auto"):
            return None
        value = user_units(text, node.font, node.view, relative, strict=True)
        if value is None:
            note(f"{name}={text[:40]!r} on an <image>, which is not a length (line {node.line})")
        return value

    w, h = side("width", viewport[0]), side("height", viewport[1])
    if w is None and h is None:
        w, h = width, height
    elif w is None:
        w = h * width / height  # type: ignore[operator]
    elif h is None:
        h = w * height / width
    return (w, h) if w > 0 and h > 0 else None  # type: ignore[operator]


def _source(href: str, folder: Path | None, line: int) -> tuple[bytes, Path | None] | None:
    """The bytes ``href`` names, a ``data:`` URL's or a local file's, and the folder of that file (None for a
    ``data:`` URL); None (said with ``-v``) where there are none."""
    if not href:
        return None
    if href[:5].lower() == "data:":
        head, comma, body = href[5:].partition(",")
        if not comma:
            note(f"an <image> whose data: URL has no comma (line {line})")
            return None
        if head.lower().endswith(";base64"):
            try:
                return base64.b64decode(re.sub(r"\s+", "", body), validate=False), None
            except (binascii.Error, ValueError):
                note(f"an <image> whose base64 data cannot be read (line {line})")
                return None
        return urllib.parse.unquote_to_bytes(body), None
    if href.lower().startswith("file://"):
        href = urllib.parse.unquote(urllib.parse.urlparse(href).path)
    elif _WEB.match(href):
        note(f"an <image> of {href[:60]!r}, which is not fetched (line {line})")
        return None
    else:
        href = urllib.parse.unquote(href)
    if folder is None:  # inside a drawing given as data: it reads no file, as a browser's image does not
        note(f"an <image> of {href[:60]!r} in a drawing given as data, which reads no file (line {line})")
        return None
    path = folder / href  # an absolute path stays itself
    try:
        if not path.is_file():
            raise FileNotFoundError(path)
        with open(path, "rb") as handle:
            data = handle.read(MAX_FILE_BYTES + 1)
    except OSError:
        note(f"an <image> of {href[:60]!r}, a file that cannot be read (line {line})")
        return None
    if len(data) > MAX_FILE_BYTES:
        raise Refusal(f"expected an <image> file of at most {MAX_FILE_BYTES} bytes, found more (line {line})")
    return data, path.resolve().parent


def _decode(data: bytes, line: int) -> NDArray[np.uint8] | None:
    """The picture in ``data`` as straight RGBA ``(H, W, 4)``; None (said with ``-v``) where it is none."""
    from PIL import Image, ImageOps, UnidentifiedImageError

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", Image.DecompressionBombWarning)  # refused below, by its size
            with Image.open(io.BytesIO(data)) as picture:
                if picture.width * picture.height > MAX_PIXELS:
                    raise Refusal(f"expected a picture of at most {MAX_PIXELS} pixels in <image>, found "
                                  f"{picture.width} × {picture.height} (line {line})")
                picture.seek(0)
                upright = ImageOps.exif_transpose(picture)
                if upright.mode in ("I", "I;16", "I;16B", "I;16L"):  # 16-bit grey: to 8 bits
                    grey = np.asarray(upright, dtype=np.float64) / 65535.0
                    upright = Image.fromarray(np.clip(np.round(grey * 255.0), 0, 255).astype(np.uint8), "L")
                return np.ascontiguousarray(np.asarray(upright.convert("RGBA"), dtype=np.uint8))
    except (UnidentifiedImageError, OSError, ValueError, Image.DecompressionBombError):
        note(f"an <image> whose data is not a PNG, JPEG, GIF or WebP picture (line {line})")
        return None
