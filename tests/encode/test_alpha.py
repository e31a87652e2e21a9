"""Transparent backgrounds, decoded: WebM (VP9 with alpha) and MOV (ProRes 4444) keep alpha, GIF has a
transparent index, PNG is straight RGBA; MP4 is refused before anything is written."""

from __future__ import annotations

import subprocess
from pathlib import Path

import numpy as np
import pytest

from tests.helpers import SQUARE, write_scene

# SQUARE in a 320 × 240 frame, view [-2, -2, 10, 7]: frame 0's square covers world (0..2, 0..2)
SCALE = min(320 / 12, 240 / 9)


def decode_rgba(path: Path, codec: list[str]) -> tuple[np.ndarray, str]:
    """Every frame as straight RGBA ``(F, 240, 320, 4)``, and ffmpeg's description of the stream."""
    import imageio_ffmpeg

    ffmpeg = imageio_ffmpeg.get_ffmpeg_exe()
    done = subprocess.run([ffmpeg, "-v", "error", *codec, "-i", str(path), "-f", "rawvideo", "-pix_fmt", "rgba", "-"],
                          capture_output=True, check=True)
    info = subprocess.run([ffmpeg, "-hide_banner", *codec, "-i", str(path)], capture_output=True, text=True).stderr
    return np.frombuffer(done.stdout, np.uint8).reshape(-1, 240, 320, 4), info


def inside_and_outside(frame: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The pixel at the middle of frame 0's square, and one far from every shape."""
    x, y = (1.0 + 2.0) * SCALE, 240 - (1.0 + 2.0) * SCALE - (240 - 9 * SCALE) / 2
    return frame[int(y), int(x)], frame[5, 315]


@pytest.mark.parametrize("fmt, codec, words", [
    ("webm", ["-c:v", "libvpx-vp9"], "vp9"),  # ffmpeg's own VP9 decoder drops the alpha plane
    ("mov", [], "prores"),
    ("gif", [], "gif"),
])
def test_transparent_video_keeps_alpha(cli, tmp_path: Path, fmt: str, codec: list[str], words: str) -> None:
    scene = write_scene(tmp_path, SQUARE)
    target = tmp_path / f"clip.{fmt}"
    code, _, err = cli("render", scene, "--background", "none", "-o", target, "-q")
    assert code == 0, err
    frames, info = decode_rgba(target, codec)
    assert len(frames) == 49 and words in info.lower()
    if fmt != "gif":  # GIF keeps delays in hundredths of a second
        assert "24 fps" in info
    ink, empty = inside_and_outside(frames[0])
    assert empty[3] == 0 and ink[3] == 255
    assert abs(int(ink[0]) - 0x3B) < 12 and abs(int(ink[2]) - 0xD8) < 12  # the square's blue, not black
    alpha = frames[:, :, :, 3].astype(float) / 255
    assert 0.0 < alpha.mean() < 0.2  # mostly transparent, the square opaque


def test_transparent_png_frames_are_straight_rgba(cli, tmp_path: Path) -> None:
    import imageio.v3 as iio

    scene = write_scene(tmp_path, SQUARE.replace('[[shape]]', 'background = "#ff000040"\n[[shape]]', 1))
    code, _, err = cli("render", scene, "--format", "png", "--frames", "0:1", "-o", tmp_path / "frames", "-q")
    assert code == 0, err
    frame = iio.imread(tmp_path / "frames" / "frame_0000.png")
    ink, empty = inside_and_outside(frame)
    assert tuple(empty) == (255, 0, 0, 0x40) and ink[3] == 255


def test_mp4_refuses_a_transparent_background_and_writes_nothing(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE)
    code, out, err = cli("render", scene, "--background", "none", "-o", tmp_path / "clip.mp4")
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and ".webm" in err and ".mov" in err and "Traceback" not in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]


def test_mov_is_prores_4444_even_when_opaque(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE)
    code, _, err = cli("render", scene, "-o", tmp_path / "clip.mov", "-q")
    assert code == 0, err
    frames, info = decode_rgba(tmp_path / "clip.mov", [])
    assert "prores" in info.lower() and "4444" in info and len(frames) == 49
    assert (frames[..., 3] == 255).all()


def test_the_docs_name_the_pixel_format_a_decoder_reports_for_a_transparent_mov(cli, tmp_path: Path) -> None:
    import re

    from tests.helpers import ROOT

    scene = write_scene(tmp_path, SQUARE)
    code, _, err = cli("render", scene, "--background", "none", "--frames", "0:2", "-o", tmp_path / "clip.mov", "-q")
    assert code == 0, err
    _, info = decode_rgba(tmp_path / "clip.mov", [])
    stream = next(line for line in info.splitlines() if "Video:" in line)
    reported = re.search(r"prores \([^)]*\)[^,]*, (\w+)", stream)
    assert reported is not None, stream
    documented = re.search(r"MOV is ProRes 4444[^`]*`(\w+)`", (ROOT / "docs" / "commands.md").read_text())
    assert documented is not None and documented.group(1) == reported.group(1), (documented, stream)
