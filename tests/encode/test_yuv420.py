"""Opaque MP4 and WebM frames go to ffmpeg as yuv420p planes made here: the planes hold BT.601 limited-range
levels (the textbook values of the primaries), chroma is each 2 × 2 block's mean, and what players decode
is the colour drawn, in place, and what the RGB path gave, labelled as BT.601 "tv"."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tweenrender.encode import open_sink
from tweenrender.encode.yuv420 import Yuv420

from tests.helpers import SQUARE, decode, video_stream_line, write_scene

# BT.601 with 8-bit limited range, as tabulated (e.g. ITU-R BT.601 colour bars; Jack, "Video Demystified",
# table "75% / 100% colour bars", 100% column): (R, G, B) -> (Y, Cb, Cr)
PRIMARIES = {
    "black": ((0, 0, 0), (16, 128, 128)),
    "white": ((255, 255, 255), (235, 128, 128)),
    "red": ((255, 0, 0), (81, 90, 240)),
    "green": ((0, 255, 0), (145, 54, 34)),
    "blue": ((0, 0, 255), (41, 240, 110)),
    "yellow": ((255, 255, 0), (210, 16, 146)),
    "cyan": ((0, 255, 255), (170, 166, 16)),
    "magenta": ((255, 0, 255), (106, 202, 222)),
}


def _flat(rgb: tuple[int, int, int], height: int = 4, width: int = 6, order: str = "bgra") -> np.ndarray:
    frame = np.full((height, width, 4), 255, np.uint8)
    frame[..., :3] = rgb[::-1] if order == "bgra" else rgb
    return frame


@pytest.mark.parametrize("name", sorted(PRIMARIES))
@pytest.mark.parametrize("order", ["bgra", "rgba"])
def test_primaries_take_their_bt601_levels(name: str, order: str) -> None:
    rgb, (y, u, v) = PRIMARIES[name]
    convert = Yuv420(6, 4, order)
    planes = convert(_flat(rgb, order=order))
    assert planes.shape == (6 * 4 * 3 // 2,)
    assert set(planes[:24]) == {y} and set(planes[24:30]) == {u} and set(planes[30:]) == {v}


def test_chroma_is_each_blocks_mean_and_an_edge_stays_put() -> None:
    # columns 0-3 red, 4-7 blue; the lower half's block at columns 2-3 mixes red and blue pixels
    frame = np.zeros((4, 8, 4), np.uint8)
    frame[..., 3] = 255
    frame[:, :4, 2] = 255  # red (BGRA order)
    frame[:, 4:, 0] = 255  # blue
    frame[2, 3] = (255, 0, 0, 255)  # one blue pixel in the block of rows 2-3, columns 2-3
    frame[3, 3] = (255, 0, 0, 255)  # and a second: that block is half red, half blue
    convert = Yuv420(8, 4)
    convert(frame)
    assert convert.y[0].tolist() == [81] * 4 + [41] * 4  # each pixel its own Y: the edge where it was drawn
    assert convert.u.tolist() == [[90, 90, 240, 240], [90, 165, 240, 240]]
    assert convert.v.tolist() == [[240, 240, 110, 110], [240, 175, 110, 110]]
    # (127.5, 0, 127.5): U = 128 + (112 - 37.797) / 2 = 165.1, V = 128 + (112 - 18.214) / 2 = 174.9


def test_any_picture_within_half_a_level_of_the_formulas() -> None:
    rng = np.random.default_rng(3)
    height, width = 150, 98  # bands of 72 rows: two whole, one short
    frame = rng.integers(0, 256, (height, width, 4), dtype=np.uint8)
    frame[..., 3] = 255
    planes = Yuv420(width, height)(frame)
    b, g, r = (frame[..., i].astype(float) for i in range(3))
    y = 16 + (65.481 * r + 128.553 * g + 24.966 * b) / 255
    mean = [c.reshape(height // 2, 2, width // 2, 2).mean(axis=(1, 3)) for c in (r, g, b)]
    u = 128 + (-37.797 * mean[0] - 74.203 * mean[1] + 112 * mean[2]) / 255
    v = 128 + (112 * mean[0] - 93.786 * mean[1] - 18.214 * mean[2]) / 255
    area = width * height
    for got, want in ((planes[:area], y), (planes[area:area * 5 // 4], u), (planes[area * 5 // 4:], v)):
        assert np.abs(got - want.ravel()).max() <= 0.502


def test_odd_sizes_and_wrong_frames_are_refused() -> None:
    with pytest.raises(ValueError, match="even"):
        Yuv420(5, 4)
    with pytest.raises(ValueError, match=r"expected uint8 \(4, 6, 4\)"):
        Yuv420(6, 4)(np.zeros((4, 6, 3), np.uint8))


@pytest.mark.parametrize("fmt", ["mp4", "webm"])
def test_flat_colours_decode_back_to_themselves(tmp_path: Path, fmt: str) -> None:
    colours = [rgb for rgb, _ in PRIMARIES.values()] + [(59, 111, 216), (253, 253, 248), (128, 128, 128)]
    target = tmp_path / f"flat.{fmt}"
    sink = open_sink(fmt, target, 64, 48, 24, len(colours), pixel_format="bgra")
    for rgb in colours:
        sink.write(_flat(rgb, 48, 64))
    sink.close()
    meta, frames = decode(target)
    assert meta["size"] == (64, 48) and len(frames) == len(colours)
    for rgb, frame in zip(colours, frames):
        assert np.abs(frame.astype(int) - rgb).max() <= 2, (rgb, frame[24, 32])
    assert "yuv420p(tv, smpte170m" in video_stream_line(target)  # BT.601, limited range, as converted


def test_a_sharp_edge_decodes_in_place(tmp_path: Path) -> None:
    frame = _flat((216, 75, 59), 48, 64)  # #d84b3b on the left ...
    frame[:, 32:, :3] = (216, 111, 59)  # ... #3b6fd8 (BGRA order) on the right
    frame[24:, :, :3] = 250  # and a pale lower half: a horizontal edge too
    target = tmp_path / "edge.mp4"
    sink = open_sink("mp4", target, 64, 48, 24, 1, pixel_format="bgra")
    sink.write(frame)
    sink.close()
    _, (picture,) = decode(target)
    red = picture[8, :, 0].astype(int)  # along a row of the upper half: 216 red, then 59
    crossing = int(np.argmax(red < (216 + 59) / 2))
    assert crossing == 32 and abs(red[29] - 216) <= 4 and abs(red[35] - 59) <= 4
    column = picture[:, 8].astype(int).mean(axis=1)
    assert int(np.argmax(column > 200)) == 24  # the horizontal edge: rows 0-23 dark, 24-47 pale


def test_the_rgb_path_and_the_yuv_path_decode_alike(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from tweenrender.encode import sinks
    from tweenrender.pipeline.job import RenderJob
    from tweenrender.pipeline.stream import render
    from tweenrender.scenefile import load_scene

    job = RenderJob(load_scene(write_scene(tmp_path, SQUARE)), frames=range(0, 48, 6))
    _, planar = decode(render(job, "mp4", tmp_path / "yuv.mp4"))
    monkeypatch.setattr(sinks, "sends_yuv420", lambda *args, **kwargs: False)
    rgb = render(job, "mp4", tmp_path / "rgb.mp4")
    _, packed = decode(rgb)
    assert "yuv420p(progressive)" in video_stream_line(rgb)  # ffmpeg's own conversion: no colour tags
    assert len(planar) == len(packed) == 8
    for ours, ffmpegs in zip(planar, packed):
        difference = np.abs(ours.astype(int) - ffmpegs.astype(int))
        assert difference.mean() < 0.5 and np.percentile(difference, 99) <= 8


@pytest.mark.parametrize("size", [(64, 48), (65, 47)])
def test_odd_sized_and_transparent_webm_still_go_as_rgb(tmp_path: Path, size: tuple[int, int]) -> None:
    width, height = size
    opaque, clear = tmp_path / "opaque.webm", tmp_path / "clear.webm"
    for target, alpha in ((opaque, False), (clear, True)):
        sink = open_sink("webm", target, width, height, 24, 2, pixel_format="rgba", alpha=alpha)
        for _ in range(2):
            frame = np.zeros((height, width, 4), np.uint8)
            frame[..., :3] = (59, 111, 216)
            frame[..., 3] = 128 if alpha else 255
            sink.write(frame)
        sink.close()
    # planes made here only for even sizes; at odd ones ffmpeg converts, as it always did
    assert ("yuv420p(tv, smpte170m" in video_stream_line(opaque)) == (width % 2 == 0)
    assert "yuva420p(" in video_stream_line(clear, "-c:v", "libvpx-vp9")  # alpha kept
    meta, frames = decode(opaque)
    assert meta["size"] == size and len(frames) == 2
    assert np.abs(frames[0].astype(int) - (59, 111, 216)).max() <= 3
