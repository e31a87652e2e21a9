"""The frame sizes each output format takes, so a size no encoder can take is refused before drawing.

Measured with the bundled ffmpeg (``scripts/probe_encoder_limits.py`` repeats it):

- every video format goes through ffmpeg's picture check, which takes a frame only while
  8·(width + 128)·(height + 128) < 2³¹ − 1: 16384x16128 and 16254x16254 pass, 16384x16130
  and 16256x16256 fail ("Picture size ... is invalid");
- x264 (mp4) takes at most 16384 pixels a side (16386x2 fails); VP9 (webm) 65536x2 passes;
  GIF stores a side in 16 bits (65535); ProRes 4444 (mov) takes odd sizes and 30000x16;
- x264 in yuv420p needs an even width and height; VP9 takes odd ones (321x241 is written and
  read back as 321x241).

PNG frames take any size up to the canvas limit.
"""

from __future__ import annotations

from ..errors import OptionError

__all__ = ["MAX_SIDE", "check_frame_size", "formats_for"]

MAX_SIDE = {"mp4": 16384, "webm": 65536, "mov": 65536, "gif": 65535}
"""The largest width or height of each video format's encoder, in pixels."""

_EVEN = ("mp4",)
_CODEC = {"mp4": "H.264", "webm": "VP9", "mov": "ProRes", "gif": "GIF"}
_PICTURE_LIMIT = 2**31 - 1  # ffmpeg's av_image_check_size: 8 bytes a pixel, 128 pixels of padding a side


def _reason(fmt: str, width: int, height: int) -> str | None:
    """Why ``fmt`` cannot take ``width × height`` frames, or None if it can."""
    if fmt not in MAX_SIDE:
        return None
    if fmt in _EVEN and (width % 2 or height % 2):
        return f"{_CODEC[fmt]} in yuv420p needs an even width and height"
    if max(width, height) > MAX_SIDE[fmt]:
        return f"{_CODEC[fmt]} takes at most {MAX_SIDE[fmt]} pixels a side"
    if 8 * (width + 128) * (height + 128) >= _PICTURE_LIMIT:
        return ("ffmpeg takes frames only while (width + 128)·(height + 128) < 268435456, "
                "e.g. 16384x16128 or 16254x16254")
    return None


def formats_for(width: int, height: int) -> list[str]:
    """The output formats that take ``width × height`` frames (PNG always does)."""
    return [fmt for fmt in (*MAX_SIDE, "png") if _reason(fmt, width, height) is None]


def check_frame_size(fmt: str, width: int, height: int) -> None:
    """Refuse ``width × height`` frames for ``fmt`` unless its encoder takes them, saying which formats do."""
    reason = _reason(fmt, width, height)
    if reason is None:
        return
    others = [f for f in formats_for(width, height) if f != fmt]
    can = " and ".join([", ".join(others[:-1]), others[-1]] if len(others) > 2 else others)
    raise OptionError(f"{fmt} cannot take {width}x{height} frames: {reason}; {can} can")
