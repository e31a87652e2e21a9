"""A written GIF is read back from its own blocks: the frame count and size they give are what Pillow's
decoder and ffmpeg's own reading see (transparency, held frames, colour tables and extensions included),
and a file cut short or not a GIF is refused (a sink then keeps the earlier output: test_read_back.py)."""

from __future__ import annotations

import struct
from pathlib import Path

import pytest
from PIL import Image

from tweenrender.encode.gif_blocks import video_track
from tweenrender.encode.sinks import probe_video

from tests.helpers import write_clip


@pytest.mark.parametrize(("width", "height", "frames", "alpha", "held"), [
    (66, 40, 7, False, False),
    (2, 2, 1, False, False),
    (320, 180, 49, False, False),
    (33, 17, 6, True, False),
    (64, 48, 9, False, True),  # every frame the same
])
def test_the_blocks_give_what_ffmpeg_and_a_decoder_read(tmp_path: Path, width: int, height: int, frames: int,
                                                        alpha: bool, held: bool) -> None:
    target = write_clip(tmp_path / "clip.gif", "gif", width, height, frames, alpha, held)
    assert video_track(target) == probe_video(target) == (frames, (width, height))
    with Image.open(target) as picture:  # a decoder of its own (ffmpeg's repeats frames to a constant rate)
        assert (picture.n_frames, picture.size) == (frames, (width, height))


def _sub_blocks(data: bytes) -> bytes:
    return b"".join(bytes([len(data[i:i + 255])]) + data[i:i + 255] for i in range(0, len(data), 255)) + b"\x00"


def _image(local_table: bool = False, data: bytes = bytes(300)) -> bytes:
    flags = 0x81 if local_table else 0  # a local colour table of 3·2² bytes
    return (b"\x2c" + struct.pack("<HHHHB", 0, 0, 4, 4, flags) + (bytes(12) if local_table else b"")
            + b"\x02" + _sub_blocks(data))


def _gif(*blocks: bytes, width: int = 300, height: int = 200, global_table: bool = True) -> bytes:
    flags = 0xF7 if global_table else 0x70  # a global colour table of 3·2⁸ bytes
    return (b"GIF89a" + struct.pack("<HHBBB", width, height, flags, 0, 0) + (bytes(768) if global_table else b"")
            + b"".join(blocks) + b"\x3b")


def test_hand_made_blocks_are_counted_image_by_image(tmp_path: Path) -> None:
    path = tmp_path / "made.gif"
    control = b"\x21\xf9" + _sub_blocks(bytes(4))  # a graphic control extension
    comment = b"\x21\xfe" + _sub_blocks(b"\x2c" * 600)  # a comment full of image separators
    path.write_bytes(_gif(control, _image(), comment, control, _image(local_table=True), _image(data=bytes(255))))
    assert video_track(path) == (3, (300, 200))
    path.write_bytes(_gif(_image(), width=1, height=65535, global_table=False) + b"trailing bytes")
    assert video_track(path) == (1, (1, 65535))
    path.write_bytes(_gif())
    assert video_track(path) == (0, (300, 200))


@pytest.mark.parametrize("damage", ["no trailer", "cut in an image", "cut in the descriptor", "an unknown block",
                                    "text", "GIF88a"])
def test_a_damaged_file_is_refused(tmp_path: Path, damage: str) -> None:
    data = _gif(_image(), _image())
    broken = {
        "no trailer": data[:-1],
        "cut in an image": data[:-100],
        "cut in the descriptor": _gif()[:-1] + b"\x2c\x00\x00",
        "an unknown block": _gif()[:-1] + b"\x99" + _image() + b"\x3b",
        "text": b"not a picture at all, only words",
        "GIF88a": b"GIF88a" + data[6:],
    }[damage]
    path = tmp_path / "broken.gif"
    path.write_bytes(broken)
    with pytest.raises(ValueError):
        video_track(path)

