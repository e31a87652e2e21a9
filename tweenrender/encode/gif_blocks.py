"""Frame count and size of a GIF read from its own blocks.

A written GIF is checked before it replaces its target (:mod:`.sinks`), as an MP4 is from its boxes
(:mod:`.media_boxes`): the logical screen descriptor gives the picture's size and each image descriptor
is one frame, so walking the blocks does what one more ffmpeg run copying the stream to nowhere did.

The blocks (GIF89a): a 6-byte signature, the logical screen descriptor (width and height, 16 bits
little-endian, then flags saying whether a global colour table of ``3·2^(k+1)`` bytes follows), then
extensions (``0x21``, a label, data sub-blocks), images (``0x2C``, a 9-byte descriptor, an optional local
colour table, the LZW code size, data sub-blocks) and the trailer (``0x3B``). Data sub-blocks are a
length byte and that many bytes, ended by a zero length.
"""

from __future__ import annotations

import mmap
import struct
from pathlib import Path

__all__ = ["video_track"]

_EXTENSION, _IMAGE, _TRAILER = 0x21, 0x2C, 0x3B


def video_track(path: Path) -> tuple[int, tuple[int, int]]:
    """Frame count and ``(width, height)`` of the GIF at ``path``; ValueError saying what is malformed."""
    with open(path, "rb") as file:
        if file.seek(0, 2) < 13:
            raise ValueError("too short for a GIF")
        with mmap.mmap(file.fileno(), 0, access=mmap.ACCESS_READ) as data:
            return _walk(data)


def _walk(data: mmap.mmap) -> tuple[int, tuple[int, int]]:
    if data[:6] not in (b"GIF87a", b"GIF89a"):
        raise ValueError("not a GIF (no GIF87a or GIF89a signature)")
    width, height, flags = struct.unpack_from("<HHB", data, 6)
    at = 13 + _colour_table(flags)
    frames = 0
    end = len(data)
    while True:
        if at >= end:
            raise ValueError("cut short: no trailer")
        kind = data[at]
        if kind == _TRAILER:
            return frames, (width, height)
        if kind == _EXTENSION:
            at = _after_sub_blocks(data, at + 2, end)
        elif kind == _IMAGE:
            if at + 11 > end:
                raise ValueError(f"an image descriptor cut short at byte {at}")
            at = _after_sub_blocks(data, at + 10 + _colour_table(data[at + 9]) + 1, end)  # after the LZW code size
            frames += 1
        else:
            raise ValueError(f"an unknown block 0x{kind:02X} at byte {at}")


def _colour_table(flags: int) -> int:
    """Bytes of the colour table that a descriptor's ``flags`` announce (0 without one)."""
    return 3 << ((flags & 7) + 1) if flags & 0x80 else 0


def _after_sub_blocks(data: mmap.mmap, at: int, end: int) -> int:
    """Where the data sub-blocks starting at ``at`` end (after their zero length)."""
    while True:
        if at >= end:
            raise ValueError("cut short inside a block's data")
        length = data[at]
        at += 1 + length
        if length == 0:
            return at
