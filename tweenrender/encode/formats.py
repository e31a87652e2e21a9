"""Every output format, in one table: what a format is called, what its files are named, how ffmpeg
encodes it, whether it keeps transparency, the largest frames its encoder takes, how a clip rendered
in chunks is joined, what writes it and what reads a written file back.

Adding a format is one :class:`Format` entry in :data:`TABLE` (and, for a new kind of file, the module
that writes or reads it, which the entry names). Every format list of the help texts and messages is
made from the table (:func:`names`, :func:`suffixes`, :func:`outputs_text`).

The sizes were measured with the bundled ffmpeg (``scripts/probe_encoder_limits.py`` repeats it):
x264 takes at most 16384 pixels a side (16386x2 fails) and needs even sides in yuv420p; VP9 takes
65536x2 and odd sizes; GIF stores a side in 16 bits; ProRes 4444 takes odd sizes and 30000x16; every
video format also goes through ffmpeg's picture check (:data:`PICTURE_LIMIT`).
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Literal, Sequence

from ..errors import OptionError, did_you_mean

__all__ = ["Format", "TABLE", "FORMATS", "DEFAULT", "LOSSLESS", "PICTURE_LIMIT", "lookup", "by_suffix",
           "formats_for", "check_frame_size", "check_alpha", "check_loop", "writer", "reader", "tuning", "is_vector",
           "names", "suffixes", "frame_folders", "listing", "outputs_text"]

PICTURE_LIMIT = 2**31 - 1
"""ffmpeg's av_image_check_size: a frame passes while 8·(width + 128)·(height + 128) is below this."""

Join = Literal["copy", "lossless", "frames"]
"""How chunks of a clip become one output: video parts joined by stream copy (each starts on a key
frame), lossless parts encoded once at the join (a GIF's palette must see every frame), or the
frames' PNG files written in order."""


@dataclass(frozen=True, slots=True)
class Format:
    """One output format.

    ``suffix`` is the file name's extension (``""``: a folder of frames); ``ffmpeg`` the encoder's output
    options; ``alpha`` the replacements in them that keep a transparent background (``None``: it cannot
    keep one); ``max_side`` the encoder's largest width or height in pixels (``None``: any the canvas
    takes); ``even`` whether both sides must be even; ``join`` how chunks are joined; ``chunked`` whether
    several processes render it as chunks, each with an encoder of its own; ``container`` the
    container's options that a join by stream copy repeats; ``yuv420`` whether opaque frames go to
    ffmpeg as yuv420p planes made here; ``vector`` whether the file holds the animated paths rather than
    pictures (a player draws them: any size, any background); ``loop`` what ``--loop`` makes of the file
    (``None``: it cannot say whether it loops; its player decides); ``draft`` the encoder's quickest
    settings, each an option and the value it takes in ``ffmpeg`` for ``--draft`` (the same quality asked
    for, a larger file; empty: the format encodes as usual).

    ``writer``, ``reader`` and ``tuning`` name a function of this package's modules as
    ``"module.name"``, imported where it is used (:func:`writer`, :func:`reader`, :func:`tuning`):
    ``writer`` makes the output, for pictures a sink taking ``(fmt, target, width, height, fps, frames,
    pixel_format, alpha, draft)`` (:func:`.sinks.open_sink`), for a vector format a function writing
    a :class:`~.vector_data.VectorClip` to a target; ``reader`` gives a written file's frame count and
    size, to check it, from its own ISO base media boxes (MP4, QuickTime: :mod:`.media_boxes`),
    Matroska elements (WebM: :mod:`.webm_elements`), GIF blocks (:mod:`.gif_blocks`) or one more
    ffmpeg run (``None``: nothing is read back); ``tuning`` gives the encoder's options for a frame
    size, put right after the ``-c:v`` choice in ``ffmpeg``. What encoding a frame costs is measured in
    the run (:mod:`.encoder_cost`; PNG frames, compressed where they are drawn, by timing that).
    """

    name: str
    codec: str
    suffix: str
    writer: str
    ffmpeg: tuple[str, ...] = ()
    alpha: tuple[tuple[str, str], ...] | None = None
    max_side: int | None = None
    even: bool = False
    join: Join | None = None
    chunked: bool = False
    container: tuple[str, ...] = ()
    yuv420: bool = False
    reader: str | None = None
    tuning: str | None = None
    listed: bool = True  # False: an internal format (a GIF's lossless parts), never asked for by name
    vector: bool = False  # the paths themselves, keyframed (Lottie, animated SVG): no frames are drawn
    loop: str | None = None  # what --loop does to the file; None: the file cannot say
    draft: tuple[tuple[str, str], ...] = ()  # (option, value) for a quicker encode: --draft

    @property
    def keeps_alpha(self) -> bool:
        return self.alpha is not None

    @property
    def folder(self) -> bool:
        """Whether the output is a folder of frames rather than one file."""
        return self.suffix == ""

    @property
    def muxer(self) -> str | None:
        """The name of the ffmpeg muxer ``ffmpeg`` writes with (its ``-f``), if any."""
        return self.ffmpeg[self.ffmpeg.index("-f") + 1] if "-f" in self.ffmpeg else None

    def options(self, alpha: bool = False, draft: bool = False) -> list[str]:
        """ffmpeg's output options; with ``alpha``, those that keep transparency; with ``draft``, the
        encoder's quickest (:attr:`draft`)."""
        options = list(self.ffmpeg)
        for old, new in (self.alpha or ()) if alpha else ():
            options = [option.replace(old, new) for option in options]
        for option, value in self.draft if draft else ():
            options[options.index(option) + 1] = value
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


_VIDEO = "sinks.FFmpegVideo"  # the writer of every format ffmpeg encodes

TABLE: dict[str, Format] = {f.name: f for f in (
    Format("mp4", "H.264", ".mp4", _VIDEO,
           ("-c:v", "libx264", "-preset", "medium", "-crf", "18", "-pix_fmt", "yuv420p",
            "-movflags", "+faststart", "-f", "mp4"),
           max_side=16384, even=True, join="copy", chunked=True, container=("-movflags", "+faststart"),
           yuv420=True, reader="media_boxes.video_track", tuning="sinks.x264_tuning",
           draft=(("-preset", "veryfast"),)),
    Format("webm", "VP9", ".webm", _VIDEO,
           ("-c:v", "libvpx-vp9", "-b:v", "0", "-crf", "32", "-pix_fmt", "yuv420p",
            "-deadline", "good", "-cpu-used", "4", "-row-mt", "1", "-f", "webm"),
           alpha=(("yuv420p", "yuva420p"),), max_side=65536, join="copy", chunked=True, yuv420=True,
           reader="webm_elements.video_track", draft=(("-deadline", "realtime"), ("-cpu-used", "8"))),
    Format("mov", "ProRes 4444", ".mov", _VIDEO,
           ("-c:v", "prores_ks", "-profile:v", "4444", "-vendor", "apl0", "-pix_fmt", "yuv444p10le", "-f", "mov"),
           alpha=(("yuv444p10le", "yuva444p10le"),), max_side=65536, reader="media_boxes.video_track"),
    Format("gif", "GIF", ".gif", _VIDEO,
           ("-filter_complex", "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=sierra2_4a",
            "-loop", "0", "-f", "gif"),
           alpha=(("palettegen=stats_mode=diff", "palettegen=stats_mode=diff:reserve_transparent=1"),
                  ("paletteuse=dither=sierra2_4a", "paletteuse=dither=sierra2_4a:alpha_threshold=128")),
           max_side=65535, join="lossless", reader="gif_blocks.video_track",
           loop="it loops in any case, its loop count 0"),
    # any size the canvas takes; each frame's file is counted as it is written
    Format("png", "PNG", "", "sinks.frames_folder", alpha=(), join="frames"),
    Format("lottie", "Lottie", ".json", "lottie.write_lottie", alpha=(), vector=True),
    Format("dotlottie", "dotLottie", ".lottie", "dotlottie.write_dotlottie", alpha=(), vector=True,
           loop="its manifest's loop is true"),
    Format("svg", "animated SVG", ".svg", "animated_svg.write_animated_svg", alpha=(), vector=True,
           loop="every animation repeats indefinitely"),
    # a GIF's chunk: FFV1 in NUT, BGRA, exact frame times; encoded into the GIF when the parts are joined
    Format("nut", "FFV1", ".nut", _VIDEO, ("-c:v", "ffv1", "-pix_fmt", "bgra", "-f", "nut"), alpha=(),
           max_side=65536, reader="sinks.probe_video", listed=False),
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
    raise OptionError(f"{fmt} cannot take {width}x{height} frames: {reason}; {listing(others)} can")


def check_alpha(fmt: str, alpha: bool) -> None:
    """Refuse a transparent background in a format that cannot keep it."""
    if alpha and not TABLE[fmt].keeps_alpha:
        keep = ", ".join(f"{TABLE[f].codec} frames" if TABLE[f].folder else f"{TABLE[f].suffix} ({TABLE[f].codec})"
                         for f in names(alpha=True))
        raise OptionError(f"{fmt} ({TABLE[fmt].codec}) cannot keep a transparent background; use {keep}, "
                          "or an opaque background")


def _resolve(spec: str) -> Callable[..., Any]:
    """The function ``spec`` (``"module.name"``, a module of this package) names, looked up now (so a
    replaced one is the one found)."""
    module, _, name = spec.partition(".")
    return getattr(importlib.import_module(f"{__package__}.{module}"), name)


def writer(fmt: str) -> Callable[..., Any]:
    """What makes ``fmt`` output (:attr:`Format.writer`)."""
    return _resolve(TABLE[fmt].writer)


def reader(fmt: str) -> Callable[[Path], tuple[int, tuple[int, int]]] | None:
    """What reads a written ``fmt`` file's frame count and ``(width, height)`` back, if anything does
    (:attr:`Format.reader`)."""
    spec = TABLE[fmt].reader
    return None if spec is None else _resolve(spec)


def tuning(fmt: str) -> Callable[[int, int], list[str]] | None:
    """What gives ``fmt``'s encoder options for a frame size, if anything does (:attr:`Format.tuning`)."""
    spec = TABLE[fmt].tuning
    return None if spec is None else _resolve(spec)


def is_vector(fmt: str) -> bool:
    """Whether ``fmt`` is a format of the paths themselves, keyframed, rather than of pictures."""
    found = TABLE.get(fmt)
    return found is not None and found.vector


def names(*, vector: bool | None = None, alpha: bool | None = None, loop: bool | None = None,
          draft: bool | None = None) -> tuple[str, ...]:
    """The formats a user may ask for, in the order help texts list them; ``vector`` keeps only the formats
    of paths (True) or of pictures (False), ``alpha`` only those that keep a transparent background (True)
    or cannot (False), ``loop`` only those whose file can say it loops (True) or cannot (False), ``draft``
    only those with quicker encoder settings (True) or without (False)."""
    return tuple(name for name in FORMATS
                 if (vector is None or TABLE[name].vector == vector)
                 and (alpha is None or TABLE[name].keeps_alpha == alpha)
                 and (loop is None or (TABLE[name].loop is not None) == loop)
                 and (draft is None or bool(TABLE[name].draft) == draft))


def check_loop(fmt: str, loop: bool) -> None:
    """Refuse ``loop`` for a format whose file cannot say it loops, saying which can."""
    if loop and TABLE[fmt].loop is None:
        can = listing([f"{n} ({TABLE[n].suffix})" for n in names(loop=True)], "or")
        raise OptionError(f"{fmt} ({TABLE[fmt].codec}) cannot say whether it loops (its player decides); "
                          f"write {can}", "loop")


def check_draft(fmt: str, draft: bool) -> None:
    """Refuse ``draft`` for a format without quicker encoder settings, saying which have them."""
    if draft and not TABLE[fmt].draft:
        can = listing([f"{n} ({TABLE[n].suffix})" for n in names(draft=True)], "or")
        raise OptionError(f"{fmt} ({TABLE[fmt].codec}) has no quicker encoder settings; write {can}", "draft")


def suffixes(*, vector: bool | None = None) -> tuple[str, ...]:
    """The file name endings of the formats :func:`names` gives (``.mp4`` …), folders of frames left out."""
    return tuple(TABLE[name].suffix for name in names(vector=vector) if not TABLE[name].folder)


def frame_folders(*, vector: bool | None = None) -> tuple[str, ...]:
    """What the folders of frames among :func:`names` hold: ``("PNG frames",)``."""
    return tuple(f"{TABLE[name].codec} frames" for name in names(vector=vector) if TABLE[name].folder)


def listing(items: Sequence[str], last: str = "and") -> str:
    """``items`` as a sentence lists them: ``a``, ``a and b``, ``a, b and c`` (``last`` joins the last two)."""
    return f"{', '.join(items[:-1])} {last} {items[-1]}" if len(items) > 1 else "".join(items)


def outputs_text(*, vector: bool | None = None, last: str = "or") -> str:
    """What an output of the formats :func:`names` gives may be, for help texts and messages:
    ``.mp4, .webm, .mov, .gif or a folder of PNG frames`` (``vector=False``)."""
    folders = [f"a folder of {held}" for held in frame_folders(vector=vector)]
    return listing([*suffixes(vector=vector), *folders], last)
