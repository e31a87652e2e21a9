"""Every output format, in one table: what a format is called, what its files are named, how ffmpeg
encodes it, whether it keeps transparency, the largest frames its encoder takes, how a clip rendered
in chunks is joined.

Adding a format is one :class:`Format` entry in :data:`TABLE` (and, for a new kind of file, one sink
in :mod:`.sinks`). The sizes were measured with the bundled ffmpeg (``scripts/probe_encoder_limits.py``
repeats it): x264 takes at most 16384 pixels a side (16386x2 fails) and needs even sides in yuv420p;
VP9 takes 65536x2 and odd sizes; GIF stores a side in 16 bits; ProRes 4444 takes odd sizes and
30000x16; every video format also goes through ffmpeg's picture check (:data:`PICTURE_LIMIT`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from ..errors import OptionError, did_you_mean

__all__ = ["Format", "TABLE", "FORMATS", "DEFAULT", "LOSSLESS", "PICTURE_LIMIT", "lookup", "by_suffix",
           "formats_for", "check_frame_size", "check_alpha"]

PICTURE_LIMIT = 2**31 - 1
"""ffmpeg's av_image_check_size: a frame passes while 8·(width + 128)·(height + 128) is below this."""

Join = Literal["copy", "lossless", "frames"]
"""How chunks of a clip become one output: video parts joined by stream copy (each starts on a key
frame), lossless parts encoded once at the join (a GIF's palette must see every frame), or the
frames' PNG files written in order."""
Readback = Literal["boxes", "ebml", "gif", "ffmpeg"]
"""Where a written file's frame count and size are read back from (see :class:`Format`)."""


@dataclass(frozen=True, slots=True)
class Format:
    """One output format.

    ``suffix`` is the file name's extension (``""``: a folder of frames); ``ffmpeg`` the encoder's output
    options; ``alpha`` the replacements in them that keep a transparent background (``None``: it cannot
    keep one); ``max_side`` the encoder's largest width or height in pixels (``None``: any the canvas
    takes); ``even`` whether both sides must be even; ``join`` how chunks are joined; ``chunked`` whether
    several processes render it as chunks, each with an encoder of its own; ``container`` the
    container's options that a join by stream copy repeats; ``yuv420`` whether opaque frames go to
    ffmpeg as yuv420p planes made here; ``readback`` where a written file's frame count and size are
    read back from to check it: its own ISO base media boxes (``"boxes"``, MP4 and QuickTime:
    :mod:`.media_boxes`), Matroska elements (``"ebml"``, WebM: :mod:`.webm_elements`) or GIF blocks
    (``"gif"``: :mod:`.gif_blocks`), or one more ffmpeg run (``"ffmpeg"``); ``vector`` whether the
    file holds the animated paths rather than pictures (written by :mod:`.lottie` or
    :mod:`.animated_svg`, a player draws them: any size, any background). What encoding a frame costs
    is measured in the run (:mod:`.encoder_cost`; PNG frames, compressed where they are drawn, by
    timing that).
    """

    name: str
    codec: str
    suffix: str
    ffmpeg: tuple[str, ...] = ()
    alpha: tuple[tuple[str, str], ...] | None = None
    max_side: int | None = None
    even: bool = False
    join: Join | None = None
    chunked: bool = False
    container: tuple[str, ...] = ()
    yuv420: bool = False
    readback: Readback = "ffmpeg"
    listed: bool = True  # False: an internal format (a GIF's lossless parts), never asked for by name
    vector: bool = False  # the paths themselves, keyframed (Lottie, animated SVG): no frames are drawn

    @property
    def keeps_alpha(self) -> bool:
        return self.alpha is not None

    @property
    def folder(self) -> bool:
        """Whether the output is a folder of frames rather than one file."""
        return self.suffix == ""

    def options(self, alpha: bool = False) -> list[str]:
        """ffmpeg's output options; with ``alpha``, those that keep transparency."""
        options = list(self.ffmpeg)
        for old, new in (self.alpha or ()) if alpha else ():
            options = [option.replace(old, new) for option in options]
        return options

    def size_problem(self, width: int, height: int) -> str | None:
        """Why this format cannot take ``width × height`` frames, or None if it can."""
        if self.even and (width % 2 or height % 2):
            return f"{self.codec} in yuv420p needs an even width and height"
        if self.max_side is not None and max(width, height) > self.max_side:
            return f"{self.codec} takes at most {self.max_side} pixels a side"
        if self.ffmpeg and 8 * (width + 128) * (height + 128) >= PICTURE_LIMIT:
            return ("ffmpeg takes frames only while (width + 128)·(height + 128) < 268435456, "
                    "e.g. 16384x16128 or 16254x16254")
        return None


TABLE: dict[str, Format] = {f.name: f for f in (
    Format("mp4", "H.264", ".mp4",
           ("-c:v", "libx264", "-preset", "medium", "-crf", "18", "-pix_fmt", "yuv420p",
            "-movflags", "+faststart", "-f", "mp4"),
           max_side=16384, even=True, join="copy", chunked=True, container=("-movflags", "+faststart"),
           yuv420=True, readback="boxes"),
    Format("webm", "VP9", ".webm",
           ("-c:v", "libvpx-vp9", "-b:v", "0", "-crf", "32", "-pix_fmt", "yuv420p",
            "-deadline", "good", "-cpu-used", "4", "-row-mt", "1", "-f", "webm"),
           alpha=(("yuv420p", "yuva420p"),), max_side=65536, join="copy", chunked=True, yuv420=True,
           readback="ebml"),
    Format("mov", "ProRes 4444", ".mov",
           ("-c:v", "prores_ks", "-profile:v", "4444", "-vendor", "apl0", "-pix_fmt", "yuv444p10le", "-f", "mov"),
           alpha=(("yuv444p10le", "yuva444p10le"),), max_side=65536, readback="boxes"),
    Format("gif", "GIF", ".gif",
           ("-filter_complex", "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=sierra2_4a",
            "-loop", "0", "-f", "gif"),
           alpha=(("palettegen=stats_mode=diff", "palettegen=stats_mode=diff:reserve_transparent=1"),
                  ("paletteuse=dither=sierra2_4a", "paletteuse=dither=sierra2_4a:alpha_threshold=128")),
           max_side=65535, join="lossless", readback="gif"),
    Format("png", "PNG", "", alpha=(), join="frames"),  # any size the canvas takes
    Format("lottie", "Lottie", ".json", alpha=(), vector=True),
    Format("svg", "animated SVG", ".svg", alpha=(), vector=True),
    # a GIF's chunk: FFV1 in NUT, BGRA, exact frame times; encoded into the GIF when the parts are joined
    Format("nut", "FFV1", ".nut", ("-c:v", "ffv1", "-pix_fmt", "bgra", "-f", "nut"), alpha=(), max_side=65536,
           listed=False),
)}

FORMATS: tuple[str, ...] = tuple(name for name, f in TABLE.items() if f.listed)
"""The formats a user may ask for, in the order help texts list them."""

DEFAULT = "mp4"
"""The format of an output named by default."""

LOSSLESS = TABLE["nut"]
"""The format a chunk of a ``join = "lossless"`` output is rendered in."""


def lookup(name: str) -> Format:
    """The format called ``name`` (one of :data:`FORMATS`), or an :class:`OptionError` saying which exist."""
    found = TABLE.get(name) if isinstance(name, str) else None
    if found is None or not found.listed:
        raise OptionError(f"unknown format {name!r}{did_you_mean(str(name), FORMATS)}; "
                          f"expected one of {', '.join(FORMATS)}", "format")
    return found


def by_suffix(suffix: str) -> Format | None:
    """The listed format whose files end in ``suffix`` (``".mp4"``, any case; ``""``: PNG frames), if any."""
    suffix = suffix.lower()
    return next((f for f in TABLE.values() if f.listed and f.suffix == suffix), None)


def formats_for(width: int, height: int) -> list[str]:
    """The formats of pictures whose encoders take ``width × height`` frames (the vector formats, which
    take any size, are not among them)."""
    return [name for name in FORMATS if not TABLE[name].vector and TABLE[name].size_problem(width, height) is None]


def check_frame_size(fmt: str, width: int, height: int) -> None:
    """Refuse ``width × height`` frames for ``fmt`` unless its encoder takes them, saying which formats do."""
    reason = TABLE[fmt].size_problem(width, height)
    if reason is None:
        return
    others = [f for f in formats_for(width, height) if f != fmt]
    can = " and ".join([", ".join(others[:-1]), others[-1]] if len(others) > 2 else others)
    raise OptionError(f"{fmt} cannot take {width}x{height} frames: {reason}; {can} can")


def check_alpha(fmt: str, alpha: bool) -> None:
    """Refuse a transparent background in a format that cannot keep it."""
    if alpha and not TABLE[fmt].keeps_alpha:
        keep = ", ".join(f"{TABLE[f].suffix} ({TABLE[f].codec})" if TABLE[f].suffix else "PNG frames"
                         for f in FORMATS if TABLE[f].keeps_alpha)
        raise OptionError(f"{fmt} ({TABLE[fmt].codec}) cannot keep a transparent background; use {keep}, "
                          "or an opaque background")
