"""A written WebM is read back from its own elements: the frame count and size they give are what a
decoder and ffmpeg's own reading see (live-style files of unknown sizes, laced blocks and block groups
included), and a file cut short, without a video track or not Matroska at all is refused (a sink
then keeps the earlier output: test_read_back.py)."""

from __future__ import annotations

import subprocess
from pathlib import Path

import imageio_ffmpeg
import pytest

from tweenrender.encode.sinks import probe_video
from tweenrender.encode.webm_elements import video_track

from tests.helpers import decode, write_clip


@pytest.mark.parametrize(("width", "height", "frames", "alpha", "held"), [
    (66, 40, 7, False, False),
    (2, 2, 1, False, False),
    (320, 180, 49, False, False),
    (33, 17, 5, True, False),  # alpha: blocks in block groups, with the alpha plane as an addition
    (64, 48, 9, False, True),  # every frame the same
])
def test_the_elements_give_what_ffmpeg_and_a_decoder_read(tmp_path: Path, width: int, height: int, frames: int,
                                                           alpha: bool, held: bool) -> None:
    target = write_clip(tmp_path / "clip.webm", "webm", width, height, frames, alpha, held)
    assert video_track(target) == probe_video(target) == (frames, (width, height))
    _, decoded = decode(target)
    assert len(decoded) == frames and decoded[0].shape[:2] == (height, width)


def test_a_webm_written_to_a_pipe_has_a_segment_of_unknown_size_and_reads_the_same(tmp_path: Path) -> None:
    target = tmp_path / "piped.webm"
    with open(target, "wb") as out:
        subprocess.run([imageio_ffmpeg.get_ffmpeg_exe(), "-v", "error", "-f", "lavfi", "-i",
                        "testsrc2=size=96x64:rate=24:duration=1.5", "-c:v", "libvpx-vp9", "-deadline", "realtime",
                        "-f", "webm", "pipe:1"], stdout=out, check=True)
    data = target.read_bytes()
    segment = data.index(bytes.fromhex("18538067"))
    assert data[segment + 4:segment + 12] == bytes.fromhex("01ffffffffffffff")  # the size ffmpeg could not fill in
    assert video_track(target) == probe_video(target) == (36, (96, 64))


def _number(value: int, length: int) -> bytes:
    """An EBML size of ``length`` bytes (the length marker set)."""
    return ((1 << (7 * length)) | value).to_bytes(length, "big")


def _element(kind: int, payload: bytes, unknown: bool = False) -> bytes:
    kind_bytes = kind.to_bytes((kind.bit_length() + 7) // 8, "big")
    size = b"\x01\xff\xff\xff\xff\xff\xff\xff" if unknown else _number(len(payload), 4)
    return kind_bytes + size + payload


def _uint(kind: int, value: int) -> bytes:
    return _element(kind, value.to_bytes(2, "big"))


def _block(track: int, laced_frames: int = 0) -> bytes:
    """A block's payload: its track number, a timestamp, flags (Xiph lacing when ``laced_frames``), then a
    lace count of ``laced_frames - 1`` and some frame data."""
    flags = 0x82 if laced_frames else 0x80
    lace = bytes([laced_frames - 1]) if laced_frames else b""
    return _number(track, 1) + b"\x00\x00" + bytes([flags]) + lace + bytes(7)


def _file(clusters: list[bytes], unknown: bool = False, video: bool = True) -> bytes:
    """A hand-made Matroska file: an EBML header, and a Segment holding an Info, a Tracks of a video track
    (number 1, 640x360) and a sound track (number 2), then ``clusters``."""
    entries = [_element(0xAE, _uint(0xD7, 2) + _uint(0x83, 2))]  # a sound track
    if video:
        entries.append(_element(0xAE, _uint(0xD7, 1) + _uint(0x83, 1)
                                + _element(0xE0, _uint(0xB0, 640) + _uint(0xBA, 360))))
    segment = _element(0x1549A966, bytes(10)) + _element(0x1654AE6B, b"".join(entries)) + b"".join(clusters)
    return _element(0x1A45DFA3, bytes(20)) + _element(0x18538067, segment, unknown)


def _cluster(*blocks: bytes, unknown: bool = False) -> bytes:
    return _element(0x1F43B675, _uint(0xE7, 0) + b"".join(blocks), unknown)


def test_hand_made_elements_are_counted_block_by_block(tmp_path: Path) -> None:
    path = tmp_path / "made.webm"
    simple = _element(0xA3, _block(1))
    sound = _element(0xA3, _block(2))
    group = _element(0xA0, _element(0xA1, _block(1)) + _uint(0x9B, 40))  # a Block and its duration
    laced = _element(0xA3, _block(1, laced_frames=3))
    path.write_bytes(_file([_cluster(simple, sound, simple), _cluster(group, laced, sound)]))
    assert video_track(path) == (6, (640, 360))  # 2 + 1 + 3; the sound track's blocks are not frames
    # a live stream's: the Segment and its Clusters of unknown size, each ending where the next begins
    path.write_bytes(_file([_cluster(simple, simple, unknown=True), _cluster(group, sound, unknown=True)],
                           unknown=True))
    assert video_track(path) == (3, (640, 360))
    path.write_bytes(_file([]))
    assert video_track(path) == (0, (640, 360))


@pytest.mark.parametrize("damage", ["cut in a block", "cut in a header", "no video track", "text", "empty",
                                    "an element larger than its parent", "a header of no length"])
def test_a_damaged_file_is_refused(tmp_path: Path, damage: str) -> None:
    simple = _element(0xA3, _block(1))
    data = _file([_cluster(simple, simple)])
    cluster = data.index(bytes.fromhex("1F43B675"))
    broken = {
        "cut in a block": data[:-3],
        "cut in a header": data[:cluster + 2],
        "no video track": _file([_cluster(simple)], video=False),
        "text": b"not a video at all, only words",
        "empty": b"",
        "an element larger than its parent": data[:cluster + 4] + _number(5000, 4) + data[cluster + 8:],
        "a header of no length": data[:cluster] + b"\x00" + data[cluster + 1:],
    }[damage]
    path = tmp_path / "broken.webm"
    path.write_bytes(broken)
    with pytest.raises(ValueError):
        video_track(path)

