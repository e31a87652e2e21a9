"""Opaque MP4 and WebM frames go to ffmpeg as yuv420p planes made here: the planes hold BT.601 limited-range
levels (the textbook values of the primaries), chroma pairs pixels across and halves the rows with swscale's
bicubic filter (within a level of ffmpeg's own conversion), and what players decode is the colour drawn, in
place, and what the RGB path gave, labelled as BT.601 "tv"."""

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


def test_chroma_pairs_pixels_across_and_an_edge_stays_put() -> None:
    # columns 0-3 red, 4-7 blue, the same down every column (so the filter down the rows changes nothing);
    # column 3 blue too in the lower half: the block of columns 2-3 there is half red, half blue
    frame = np.zeros((8, 8, 4), np.uint8)
    frame[..., 3] = 255
    frame[:, :4, 2] = 255  # red (BGRA order)
    frame[:, 4:, 0] = 255  # blue
    convert = Yuv420(8, 8)
    convert(frame)
    assert convert.y[0].tolist() == [81] * 4 + [41] * 4  # each pixel its own Y: the edge where it was drawn
    assert convert.u.tolist() == [[90, 90, 240, 240]] * 4
    assert convert.v.tolist() == [[240, 240, 110, 110]] * 4
    frame[:, 3] = (255, 0, 0, 255)
    convert(frame)
    # (127.5, 0, 127.5): U = 128 + (112 - 37.797) / 2 = 165.1, V = 128 + (112 - 18.214) / 2 = 174.9
    assert convert.u[:, 1].tolist() == [165] * 4 and convert.v[:, 1].tolist() == [175] * 4


def _keys(x: float, a: float = -0.6) -> float:
    """Keys' cubic convolution kernel (swscale's default "bicubic": B = 0, C = 0.6)."""
    x = abs(x)
    if x < 1:
        return (a + 2) * x ** 3 - (a + 3) * x ** 2 + 1
    return a * x ** 3 - 5 * a * x ** 2 + 8 * a * x - 4 * a if x < 2 else 0.0


def test_the_filter_down_the_rows_is_bicubic_halving() -> None:
    from tweenrender.encode.yuv420 import CHROMA_TAPS

    # halving: a chroma row sits between its two pixel rows, so rows lie 0.5, 1.5, 2.5, 3.5 rows away, or
    # 0.25 … 1.75 of the kernel's (doubled) reach
    weights = np.array([_keys(d / 2) for d in (3.5, 2.5, 1.5, 0.5, 0.5, 1.5, 2.5, 3.5)])
    assert sum(CHROMA_TAPS) == 64
    assert np.abs(np.array(CHROMA_TAPS) / 64 - weights / weights.sum()).max() < 0.5 / 64
    # a horizontal edge: rows 0-7 red (U 90.203, V 240), 8-15 blue (U 240, V 109.786). Chroma row i reads
    # rows 2i - 3 … 2i + 4; row 2 has one blue row (weight -1), row 3 three (8 - 3 - 1 = 4), row 4 five (60),
    # row 5 seven (65): U = (65 · 90.203 - 240) / 64 = 87.9, (60 · 90.203 + 4 · 240) / 64 = 99.6,
    # (4 · 90.203 + 60 · 240) / 64 = 230.6, (-90.203 + 65 · 240) / 64 = 242.3; V likewise
    frame = np.zeros((16, 4, 4), np.uint8)
    frame[..., 3] = 255
    frame[:8, :, 2] = 255
    frame[8:, :, 0] = 255
    convert = Yuv420(4, 16)
    convert(frame)
    assert convert.u[:, 0].tolist() == [90, 90, 88, 100, 231, 242, 240, 240]
    assert convert.v[:, 0].tolist() == [240, 240, 242, 232, 118, 108, 110, 110]
    assert (convert.u == convert.u[:, :1]).all()  # the same across


def test_planes_are_ffmpegs_own_conversion_within_a_level() -> None:
    import subprocess

    import imageio_ffmpeg

    rng = np.random.default_rng(4)
    height, width = 240, 320  # blocks of 8 × 8 random colours: edges everywhere, across and down
    frame = np.repeat(np.repeat(rng.integers(0, 256, (height // 8, width // 8, 4), dtype=np.uint8), 8, 0), 8, 1)
    frame[..., 3] = 255
    theirs = subprocess.run([imageio_ffmpeg.get_ffmpeg_exe(), "-v", "error", "-f", "rawvideo", "-pix_fmt", "bgra",
                             "-s", f"{width}x{height}", "-i", "-", "-f", "rawvideo", "-pix_fmt", "yuv420p", "-"],
                            input=frame.tobytes(), capture_output=True, check=True).stdout
    ours = Yuv420(width, height)(frame)
    difference = np.abs(ours.astype(int) - np.frombuffer(theirs, np.uint8))
    area = width * height
    assert difference.max() <= 1
    assert difference[:area].mean() < 0.02 and difference[area:].mean() < 0.3  # Y all but equal


def test_any_picture_within_half_a_level_of_the_formulas() -> None:
    rng = np.random.default_rng(3)
    height, width = 150, 98  # bands of 72 rows: two whole, one short
    frame = rng.integers(0, 256, (height, width, 4), dtype=np.uint8)
    frame[..., 3] = 255
    planes = Yuv420(width, height)(frame)
    b, g, r = (frame[..., i].astype(float) for i in range(3))
    y = 16 + (65.481 * r + 128.553 * g + 24.966 * b) / 255
    area = width * height
    assert np.abs(planes[:area] - y.ravel()).max() <= 0.502
    taps = np.array([-1, -3, 8, 28, 28, 8, -3, -1]) / 64
    chroma = {(-37.797, -74.203, 112.0): planes[area:area * 5 // 4], (112.0, -93.786, -18.214): planes[area * 5 // 4:]}
    for (red, green, blue), plane in chroma.items():
        level = 128 + (red * r + green * g + blue * b) / 255
        across = (level[:, 0::2] + level[:, 1::2]) / 2
        padded = np.concatenate([across[:1]] * 3 + [across] + [across[-1:]] * 4)  # edge rows repeated
        down = sum(t * padded[j:j + height:2] for j, t in enumerate(taps))
        assert np.abs(plane - np.clip(down, 0, 255).ravel()).max() <= 0.502


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
    from tweenrender.plan.job import RenderJob
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
