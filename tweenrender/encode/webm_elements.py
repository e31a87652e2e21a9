"""Frame count and size of a WebM's video track read from its own elements (Matroska, EBML).

A written WebM is checked before it replaces its target (:mod:`.sinks`), as an MP4 is from its boxes
(:mod:`.media_boxes`): the track entry gives the picture's size, and each block of the video track holds
one frame (or, laced, the count its lacing byte gives), so reading the elements' headers does what one
more ffmpeg run copying the stream to nowhere did. The file is mapped, not read: only the pages of the
headers are touched.

The elements read (RFC 9559): the EBML header, then the ``Segment``'s ``Tracks`` → ``TrackEntry``
(``TrackNumber``, ``TrackType`` 1 for video, ``Video`` → ``PixelWidth``, ``PixelHeight``) and each
``Cluster``'s ``SimpleBlock``\\ s and ``BlockGroup`` → ``Block``\\ s (track number, timestamp, flags,
then the lace count where the flags say the block is laced). A ``Segment`` or ``Cluster`` of unknown
size (a live stream's) runs to the end of the file, or to the next element of the ``Segment``'s level.
"""

from __future__ import annotations

import mmap
from pathlib import Path

__all__ = ["video_track"]

_EBML, _SEGMENT, _TRACKS, _CLUSTER = 0x1A45DFA3, 0x18538067, 0x1654AE6B, 0x1F43B675
_TRACK_ENTRY, _TRACK_NUMBER, _TRACK_TYPE, _VIDEO = 0xAE, 0xD7, 0x83, 0xE0
_PIXEL_WIDTH, _PIXEL_HEIGHT = 0xB0, 0xBA
_SIMPLE_BLOCK, _BLOCK_GROUP, _BLOCK = 0xA3, 0xA0, 0xA1
_TOP_LEVEL = frozenset((0x114D9B74, 0x1549A966, _TRACKS, _CLUSTER, 0x1C53BB6B, 0x1043A770, 0x1941A469, 0x1254C367))
"""The ``Segment``'s children (SeekHead, Info, Tracks, Cluster, Cues, Chapters, Attachments, Tags): one of
them ends a ``Cluster`` of unknown size."""
_VIDEO_TYPE = 1
_UNKNOWN = -1


def video_track(path: Path) -> tuple[int, tuple[int, int]]:
    """Frame count and ``(width, height)`` of the first video track of the WebM (Matroska) file at ``path``;
    ValueError saying what is missing or malformed."""
    with open(path, "rb") as file:
        if file.seek(0, 2) == 0:
            raise ValueError("an empty file")
        with mmap.mmap(file.fileno(), 0, access=mmap.ACCESS_READ) as data:
            return _Elements(data).video_track()


class _Elements:
    """Walks one mapped file's elements."""

    def __init__(self, data: mmap.mmap) -> None:
        self.data, self.end = data, len(data)

    def video_track(self) -> tuple[int, tuple[int, int]]:
        kind, size, at = self._header(0, self.end)
        if kind != _EBML:
            raise ValueError("not an EBML file (no EBML header)")
        at = self._after(at, size, self.end)
        while at < self.end:
            kind, size, start = self._header(at, self.end)
            if kind == _SEGMENT:
                return self._segment(start, self.end if size == _UNKNOWN else self._after(start, size, self.end))
            at = self._after(start, size, self.end)
        raise ValueError("no Segment element")

    def _segment(self, at: int, stop: int) -> tuple[int, tuple[int, int]]:
        video: tuple[int, tuple[int, int]] | None = None  # (track number, size) of the first video track
        frames: dict[int, int] = {}
        while at < stop:
            kind, size, start = self._header(at, stop)
            if kind == _CLUSTER:
                at = self._cluster(start, stop if size == _UNKNOWN else self._after(start, size, stop), frames)
                continue
            at = self._after(start, size, stop)
            if kind == _TRACKS and video is None:
                video = self._video_entry(start, at)
        if video is None:
            raise ValueError("no video track")
        number, picture = video
        return frames.get(number, 0), picture

    def _video_entry(self, at: int, stop: int) -> tuple[int, tuple[int, int]] | None:
        """(track number, (width, height)) of the first video ``TrackEntry`` in ``Tracks``, if any."""
        for kind, start, end in self._children(at, stop):
            if kind != _TRACK_ENTRY:
                continue
            fields = {k: (s, e) for k, s, e in self._children(start, end)}
            if _TRACK_TYPE not in fields or self._uint(*fields[_TRACK_TYPE]) != _VIDEO_TYPE:
                continue
            if _TRACK_NUMBER not in fields or _VIDEO not in fields:
                raise ValueError("a video track without its number or picture")
            picture = {k: (s, e) for k, s, e in self._children(*fields[_VIDEO])}
            if _PIXEL_WIDTH not in picture or _PIXEL_HEIGHT not in picture:
                raise ValueError("a video track without its width and height")
            return (self._uint(*fields[_TRACK_NUMBER]),
                    (self._uint(*picture[_PIXEL_WIDTH]), self._uint(*picture[_PIXEL_HEIGHT])))
        return None

    def _cluster(self, at: int, stop: int, frames: dict[int, int]) -> int:
        """Add the frames of a ``Cluster``'s blocks to ``frames`` (by track number); returns where it ends."""
        while at < stop:
            kind, size, start = self._header(at, stop)
            if kind in _TOP_LEVEL:
                return at  # a Cluster of unknown size ends where the Segment's next child begins
            if size == _UNKNOWN:
                raise ValueError("a block of unknown size")
            end = self._after(start, size, stop)
            if kind == _SIMPLE_BLOCK:
                self._block(start, end, frames)
            elif kind == _BLOCK_GROUP:
                for child, begin, finish in self._children(start, end):
                    if child == _BLOCK:
                        self._block(begin, finish, frames)
            at = end
        return at

    def _block(self, at: int, stop: int, frames: dict[int, int]) -> None:
        """Count a block's frames: its track number, a 16-bit timestamp, its flags (lacing in bits 1-2), then
        for a laced block the number of frames less one."""
        number, at = self._number(at, stop, strip=True)
        if at + 3 > stop:
            raise ValueError("a block cut short")
        laced = (self.data[at + 2] >> 1) & 3
        if laced and at + 4 > stop:
            raise ValueError("a laced block cut short")
        frames[number] = frames.get(number, 0) + (self.data[at + 3] + 1 if laced else 1)

    def _children(self, at: int, stop: int) -> list[tuple[int, int, int]]:
        """``(ID, payload start, payload end)`` of each element laid end to end in ``[at, stop)``."""
        found = []
        while at < stop:
            kind, size, start = self._header(at, stop)
            if size == _UNKNOWN:
                raise ValueError(f"an element 0x{kind:X} of unknown size")
            at = self._after(start, size, stop)
            found.append((kind, start, at))
        return found

    def _header(self, at: int, stop: int) -> tuple[int, int, int]:
        """``(ID, payload size or _UNKNOWN, payload start)`` of the element at ``at``."""
        kind, at = self._number(at, stop, strip=False, longest=4)
        size, at = self._number(at, stop, strip=True)
        return kind, size, at

    def _number(self, at: int, stop: int, strip: bool, longest: int = 8) -> tuple[int, int]:
        """An EBML variable-length integer at ``at`` (its first byte's leading zeros give its length): with
        the length marker stripped (a size; all ones: ``_UNKNOWN``) or kept (an ID); and where it ends."""
        if at >= stop:
            raise ValueError(f"an element cut short at byte {at}")
        first = self.data[at]
        length = 9 - first.bit_length()
        if first == 0 or length > longest or at + length > stop:
            raise ValueError(f"a malformed element header at byte {at}")
        value = int.from_bytes(self.data[at:at + length], "big")
        if strip:
            value &= (1 << (7 * length)) - 1
            if value == (1 << (7 * length)) - 1:
                value = _UNKNOWN
        return value, at + length

    def _uint(self, at: int, stop: int) -> int:
        if not 0 < stop - at <= 8:
            raise ValueError(f"an unsigned integer of {stop - at} bytes at byte {at}")
        return int.from_bytes(self.data[at:stop], "big")

    @staticmethod
    def _after(start: int, size: int, stop: int) -> int:
        """The end of a payload of ``size`` bytes from ``start``, which must lie within ``stop``."""
        if size == _UNKNOWN or start + size > stop:
            raise ValueError(f"an element of {'unknown size' if size == _UNKNOWN else f'{size} bytes'} "
                             f"where {stop - start} remain")
        return start + size
