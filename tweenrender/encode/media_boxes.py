"""Frame count and size of a video track read from an ISO base media file's boxes (MP4, QuickTime MOV).

A written MP4 or MOV is checked before it replaces its target (:mod:`.sinks`). Its sample tables
say how many frames its video track holds and its sample description their size, so reading a few
hundred bytes of boxes does what one more ffmpeg run copying the stream to nowhere did (about
45 ms a render: a process started and the whole file read; docs/performance.md).

The boxes read (ISO/IEC 14496-12): ``moov`` → ``trak`` → ``mdia`` → ``hdlr`` (handler ``vide``)
and ``minf`` → ``stbl`` → ``stsd`` (the first sample entry's width and height, 16 bits each)
and ``stsz`` (the sample count: one sample a frame).
"""

from __future__ import annotations

import struct
from pathlib import Path
from typing import BinaryIO, Iterator

__all__ = ["video_track"]

_HEADER = struct.Struct(">I4s")
_MOOV_LIMIT = 64 << 20  # a moov box this large is not one of a clip's few thousand frames: refused as corrupt


def video_track(path: Path) -> tuple[int, tuple[int, int]]:
    """Frame count and ``(width, height)`` of the first video track of the ISO base media file at
    ``path``; ValueError saying what is missing or malformed."""
    with open(path, "rb") as file:
        end = file.seek(0, 2)
        moov = _top_level_moov(file, end)
    for trak in _find(moov, b"trak"):
        mdia = _one(trak, b"mdia")
        handler = _one(mdia, b"hdlr")
        if handler[8:12] != b"vide":
            continue
        stbl = _one(_one(mdia, b"minf"), b"stbl")
        return _sample_count(_one(stbl, b"stsz")), _entry_size(_one(stbl, b"stsd"))
    raise ValueError("no video track")


def _top_level_moov(file: BinaryIO, end: int) -> bytes:
    """The payload of the file's ``moov`` box, the other top-level boxes (``mdat``: the frames) skipped."""
    at = 0
    while at < end:
        file.seek(at)
        size, kind, header = _box_header(file.read(16), 0, end - at)
        if kind == b"moov":
            if size > _MOOV_LIMIT:
                raise ValueError(f"a moov box of {size} bytes")
            file.seek(at + header)
            moov = file.read(size - header)
            if len(moov) < size - header:
                raise ValueError("the moov box cut short")
            return moov
        at += size
    raise ValueError("no moov box")


def _box_header(data: bytes, at: int, left: int) -> tuple[int, bytes, int]:
    """``(size, type, header bytes)`` of the box whose header starts ``data[at:]``, ``left`` bytes before the
    end of what holds it (a size of 0: the box runs to that end; 1: a 64-bit size follows the type)."""
    if len(data) - at < 8:
        raise ValueError("a box header cut short")
    size, kind = _HEADER.unpack_from(data, at)
    header = 8
    if size == 1:
        if len(data) - at < 16:
            raise ValueError("a box header cut short")
        size, header = struct.unpack_from(">Q", data, at + 8)[0], 16
    elif size == 0:
        size = left
    if size < header or size > left:
        raise ValueError(f"a {kind!r} box of {size} bytes where {left} remain")
    return size, kind, header


def _boxes(data: bytes) -> Iterator[tuple[bytes, bytes]]:
    """``(type, payload)`` of each box laid end to end in ``data``."""
    at = 0
    while at < len(data):
        size, kind, header = _box_header(data, at, len(data) - at)
        yield kind, data[at + header:at + size]
        at += size


def _find(data: bytes, kind: bytes) -> Iterator[bytes]:
    return (payload for found, payload in _boxes(data) if found == kind)


def _one(data: bytes, kind: bytes) -> bytes:
    found = next(_find(data, kind), None)
    if found is None:
        raise ValueError(f"no {kind.decode()} box")
    return found


def _sample_count(stsz: bytes) -> int:
    """The sample count of a ``stsz`` box (version and flags, a default size, the count)."""
    if len(stsz) < 12:
        raise ValueError("an stsz box cut short")
    return struct.unpack_from(">I", stsz, 8)[0]


def _entry_size(stsd: bytes) -> tuple[int, int]:
    """Width and height of the first visual sample entry of an ``stsd`` box: after the version and flags and
    the entry count, the entry's size and format, 6 reserved bytes, a data reference index, 16 bytes of
    fields and then width and height."""
    if len(stsd) < 8 + 36 or struct.unpack_from(">I", stsd, 4)[0] < 1:
        raise ValueError("an stsd box without a sample entry")
    width, height = struct.unpack_from(">HH", stsd, 8 + 32)
    return width, height
