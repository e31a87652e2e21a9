"""Frame sizes each encoder takes, refused before anything is drawn or ffmpeg is started.

The limits were measured with the bundled ffmpeg (``scripts/probe_encoder_limits.py``
reruns the measurement): x264 takes sides up to 16384 (16386 fails), ffmpeg's
picture check takes 8·(w+128)·(h+128) < 2³¹ − 1 for every encoder (16384x16128
passes, 16384x16130 and 16256x16256 fail), and x264 in yuv420p needs even sides (VP9 does
not). VP9 took 16254x16254 as input but needed over 24 GB to encode it: memory, not a limit
of the format.
"""

from __future__ import annotations

from pathlib import Path

import pytest

import tweenrender as tr
from tweenrender.encode.formats import check_frame_size, formats_for
from tweenrender.errors import OptionError

from tests.helpers import SQUARE, write_scene

MEASURED = [  # (format, width, height, taken by the bundled ffmpeg and its encoder)
    ("mp4", 16384, 16128, True), ("mp4", 16384, 16130, False), ("mp4", 16254, 16254, True),
    ("mp4", 16256, 16256, False), ("mp4", 16384, 16384, False), ("mp4", 16384, 2, True), ("mp4", 2, 16384, True),
    ("mp4", 321, 240, False), ("mp4", 320, 241, False),
    ("webm", 8192, 8192, True), ("webm", 16384, 16384, False), ("webm", 16384, 16130, False),
    ("webm", 321, 241, True),
    ("gif", 16254, 16254, True), ("gif", 16256, 16256, False), ("gif", 321, 241, True),
    ("png", 16384, 16384, True), ("png", 321, 241, True),
]


@pytest.mark.parametrize("fmt, width, height, fits", MEASURED)
def test_the_measured_limits(fmt: str, width: int, height: int, fits: bool) -> None:
    if fits:
        check_frame_size(fmt, width, height)
        assert fmt in formats_for(width, height)
    else:
        with pytest.raises(OptionError, match=f"{fmt} cannot take {width}x{height} frames"):
            check_frame_size(fmt, width, height)
        assert fmt not in formats_for(width, height)


def test_the_message_says_which_formats_can() -> None:
    with pytest.raises(OptionError) as caught:
        check_frame_size("mp4", 16384, 16384)
    assert str(caught.value).endswith("; png can")
    with pytest.raises(OptionError) as caught:
        check_frame_size("mp4", 321, 240)
    assert "even width and height" in str(caught.value) and str(caught.value).endswith("; webm, mov, gif and png can")


def _no_drawing_and_no_ffmpeg(monkeypatch) -> None:  # type: ignore[no-untyped-def]
    import subprocess

    from tweenrender.pipeline import frames

    def refuse(*args: object, **kwargs: object) -> None:
        raise AssertionError("drew a frame or started ffmpeg before refusing the size")

    monkeypatch.setattr(frames.Frames, "_draw", refuse)
    monkeypatch.setattr(subprocess, "Popen", refuse)


def test_a_scene_too_large_for_mp4_is_refused_at_once(cli, tmp_path: Path, monkeypatch) -> None:
    scene = write_scene(tmp_path, SQUARE.replace("size = [320, 240]", "size = [16384, 16384]"))
    target = tmp_path / "movie.mp4"
    target.write_bytes(b"an earlier movie")
    _no_drawing_and_no_ffmpeg(monkeypatch)
    code, out, err = cli("render", scene, "-o", target, "-q")
    assert code == 2 and out == ""
    assert err.startswith("tweenrender: error: mp4 cannot take 16384x16384 frames") and err.endswith("; png can\n")
    assert err.count("\n") == 1
    assert target.read_bytes() == b"an earlier movie"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["movie.mp4", "scene.toml"]


@pytest.mark.parametrize("flags, words", [
    (("--size", "8192x16200", "--compare", "linear,nonlinear", "-o", "{tmp}/c.webm"), "webm cannot take 16384x16200"),
    (("--size", "16384x16384", "-o", "{tmp}/g.gif"), "gif cannot take 16384x16384"),
    (("--size", "321x240", "-o", "{tmp}/odd.mp4"), "mp4 cannot take 321x240"),
])
def test_sizes_from_flags_are_refused_before_drawing(cli, tmp_path: Path, monkeypatch, flags: tuple[str, ...],
                                                     words: str) -> None:
    scene = write_scene(tmp_path, SQUARE)
    _no_drawing_and_no_ffmpeg(monkeypatch)
    code, _, err = cli("render", scene, "-q", *[f.format(tmp=tmp_path) for f in flags])
    assert code == 2 and words in err and err.count("\n") == 1, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]


def test_a_reel_too_large_is_refused_before_drawing(cli, tmp_path: Path, monkeypatch) -> None:
    scene = write_scene(tmp_path, SQUARE)
    _no_drawing_and_no_ffmpeg(monkeypatch)
    from tweenrender.raster import title_cards

    monkeypatch.setattr(title_cards, "draw_card", lambda *a, **k: (_ for _ in ()).throw(AssertionError("drew")))
    code, _, err = cli("reel", scene, "--size", "16384x16384", "-o", tmp_path / "reel.mp4", "-q")
    assert code == 2 and "mp4 cannot take 16384x16384" in err and err.count("\n") == 1, err


def test_the_library_refuses_the_same(tmp_path: Path, monkeypatch) -> None:
    scene = tr.load_scene(write_scene(tmp_path, SQUARE))
    _no_drawing_and_no_ffmpeg(monkeypatch)
    with pytest.raises(OptionError, match="mp4 cannot take 16384x16384 frames"):
        tr.write(scene, tmp_path / "big.mp4", size=(16384, 16384))
