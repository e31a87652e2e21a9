"""A written MP4 or MOV is read back from its own boxes: the frame count and size they give are what a
decoder and ffmpeg's own reading see, and a file cut short, without its index or not a video at all
is refused (a sink then keeps the earlier output: test_read_back.py)."""

from __future__ import annotations

import struct
from pathlib import Path

import pytest

from tweenrender.encode.media_boxes import video_track
from tweenrender.encode.sinks import probe_video

from tests.helpers import decode, write_clip


@pytest.mark.parametrize(("fmt", "width", "height", "frames", "alpha"), [
    ("mp4", 66, 40, 7, False),
    ("mp4", 2, 2, 1, False),
    ("mp4", 320, 180, 49, False),
    ("mov", 33, 17, 5, True),
    ("mov", 64, 48, 3, False),
])
def test_the_boxes_give_what_ffmpeg_and_a_decoder_read(tmp_path: Path, fmt: str, width: int, height: int,
                                                        frames: int, alpha: bool) -> None:
    target = write_clip(tmp_path / f"clip.{fmt}", fmt, width, height, frames, alpha)
    assert video_track(target) == probe_video(target) == (frames, (width, height))
    _, decoded = decode(target)
    assert len(decoded) == frames and decoded[0].shape[:2] == (height, width)


def _box(kind: bytes, payload: bytes, large: bool = False) -> bytes:
    if large:
        return struct.pack(">I4sQ", 1, kind, 16 + len(payload)) + payload
    return struct.pack(">I4s", 8 + len(payload), kind) + payload


def _movie(count: int, width: int, height: int, handler: bytes = b"vide", large: bool = False) -> bytes:
    """A hand-made file of the boxes read: an ``ftyp``, a ``moov`` with one track, an ``mdat``."""
    entry = _box(b"avc1", bytes(6) + struct.pack(">H", 1) + bytes(16) + struct.pack(">HH", width, height) + bytes(50))
    stbl = _box(b"stbl", _box(b"stsd", bytes(4) + struct.pack(">I", 1) + entry)
                + _box(b"stsz", bytes(4) + struct.pack(">II", 0, count) + bytes(4 * count)))
    mdia = _box(b"mdia", _box(b"mdhd", bytes(24)) + _box(b"hdlr", bytes(8) + handler + bytes(13))
                + _box(b"minf", _box(b"vmhd", bytes(12)) + stbl))
    moov = _box(b"moov", _box(b"mvhd", bytes(100)) + _box(b"trak", _box(b"tkhd", bytes(84)) + mdia), large)
    return _box(b"ftyp", b"isom" + bytes(4)) + _box(b"mdat", bytes(40), large) + moov


def test_hand_made_boxes_are_read_field_by_field(tmp_path: Path) -> None:
    path = tmp_path / "made.mp4"
    path.write_bytes(_movie(12, 1920, 1080))
    assert video_track(path) == (12, (1920, 1080))
    path.write_bytes(_movie(300, 640, 360, large=True))  # 64-bit sizes
    assert video_track(path) == (300, (640, 360))
    data = _movie(5, 64, 48)
    at = data.index(b"moov") - 4
    path.write_bytes(data[:at] + struct.pack(">I", 0) + data[at + 4:])  # a last box running to the end
    assert video_track(path) == (5, (64, 48))


@pytest.mark.parametrize("damage", ["cut in the index", "cut in a header", "no index", "sound only",
                                    "a box larger than its parent", "a box smaller than its header",
                                    "a 64-bit size of 0", "text"])
def test_a_damaged_file_is_refused(tmp_path: Path, damage: str) -> None:
    data = _movie(12, 64, 48)
    moov = data.index(b"moov") - 4
    broken = {
        "cut in the index": data[:-20],
        "cut in a header": data[:moov + 5],
        "no index": data[:moov],
        "sound only": _movie(12, 64, 48, handler=b"soun"),
        "a box larger than its parent": data.replace(_box(b"mvhd", bytes(100))[:4], struct.pack(">I", 5000), 1),
        "a box smaller than its header": data.replace(_box(b"mvhd", bytes(100))[:4], struct.pack(">I", 3), 1),
        "a 64-bit size of 0": data.replace(_box(b"mvhd", bytes(100))[:8], struct.pack(">I4s", 1, b"mvhd"), 1),
        "text": b"not a video at all, only words",
    }[damage]
    path = tmp_path / "broken.mp4"
    path.write_bytes(broken)
    with pytest.raises(ValueError):
        video_track(path)

