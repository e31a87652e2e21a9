"""Written videos, decoded: size, fps, frame count, and what the frames show."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tests.helpers import SCENES, SQUARE, decode, write_scene


def test_1080p_stays_1080p_with_every_frame(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE.replace("size = [320, 240]", "size = [1920, 1080]"))
    target = tmp_path / "hd.mp4"
    code, _, err = cli("render", scene, "-o", target, "-q", "--fps", "12")
    assert code == 0, err
    meta, frames = decode(target)
    assert meta["size"] == (1920, 1080)  # never the silent 1080 → 1088 of macro blocks
    assert meta["fps"] == pytest.approx(12.0)
    assert len(frames) == 2 * 12 + 1  # duration × fps + 1
    assert meta["codec"] == "h264"


def test_default_fps_is_24(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE)
    target = tmp_path / "sd.mp4"
    assert cli("render", scene, "-o", target, "-q")[0] == 0
    meta, frames = decode(target)
    assert meta["fps"] == pytest.approx(24.0) and len(frames) == 49 and meta["size"] == (320, 240)


@pytest.mark.parametrize("fmt, codec", [("webm", "vp9"), ("gif", "gif")])
def test_other_formats(cli, tmp_path: Path, fmt: str, codec: str) -> None:
    scene = write_scene(tmp_path, SQUARE)
    target = tmp_path / f"clip.{fmt}"
    code, _, err = cli("render", scene, "-o", target, "-q", "--frames", "0:10")
    assert code == 0, err
    meta, frames = decode(target)
    assert meta["codec"].startswith(codec) and meta["size"] == (320, 240) and len(frames) == 10


def _blue_area(frame: np.ndarray) -> int:
    """Pixels clearly of the square's fill (#3b6fd8), however the codec rounds."""
    r, g, b = (frame[..., i].astype(int) for i in range(3))
    return int(np.sum((b > 150) & (r < 120) & (b - r > 80)))


def test_comparison_linear_shrinks_nonlinear_keeps(cli, tmp_path: Path) -> None:
    target = tmp_path / "square-compare.mp4"
    code, _, err = cli("render", SCENES / "square.toml", "--compare", "-o", target, "-q", "--size", "640x360")
    assert code == 0, err
    meta, frames = decode(target)
    assert meta["size"] == (1280, 360) and len(frames) == 49
    first, middle = frames[0], frames[24]
    left = [_blue_area(f[:, :640]) for f in (first, middle)]
    right = [_blue_area(f[:, 640:]) for f in (first, middle)]
    # same start in both panels; at t = 0.5 linear has cos²(45°) = 1/2 of the area, nonlinear all of it
    assert left[0] == pytest.approx(right[0], rel=0.02)
    assert left[1] / left[0] == pytest.approx(0.5, abs=0.04)
    assert right[1] / right[0] == pytest.approx(1.0, abs=0.04)


@pytest.mark.parametrize("fmt, background", [("mp4", None), ("webm", None), ("webm", "none")])
def test_a_draft_decodes_to_the_frames_drawn_as_the_full_encode_does(cli, tmp_path: Path, fmt: str,
                                                                     background: str | None) -> None:
    """``--draft`` trades the file's size for the encoder's time, not what the frames show: decoded by ffmpeg,
    every frame is as near the picture drawn as the usual encode's is (transparency kept)."""
    import tweenrender as tr

    scene_file = write_scene(tmp_path, SQUARE)
    extra = ["--background", background] if background else []
    errors = {}
    for draft in (False, True):
        target = tmp_path / f"{'draft' if draft else 'full'}.{fmt}"
        code, _, err = cli("render", scene_file, "-o", target, "-q", *extra, *(["--draft"] if draft else []))
        assert code == 0, err
        meta, frames = decode(target)
        assert meta["size"] == (320, 240) and len(frames) == 49 and meta["fps"] == pytest.approx(24.0)
        scene = tr.load_scene(scene_file)
        drawn = [tr.frame(scene, i / 24) for i in (0, 12, 24, 36, 48)]
        errors[draft] = max(float(np.abs(frames[i * 12].astype(int) - d[..., :3].astype(int)).mean())
                            for i, d in enumerate(drawn)) if background is None else 0.0
    assert errors[True] <= max(1.5 * errors[False], 1.0), errors
    if background == "none":
        from tests.encode.test_alpha import decode_rgba

        rgba, _ = decode_rgba(tmp_path / "draft.webm", ["-c:v", "libvpx-vp9"])
        assert rgba[..., 3].min() == 0 and rgba[..., 3].max() == 255  # transparent around the opaque square


@pytest.mark.parametrize("fmt", ["gif", "png", "mov", "json"])
def test_draft_for_a_format_without_quicker_settings_is_a_usage_error(cli, tmp_path: Path, fmt: str) -> None:
    scene_file = write_scene(tmp_path, SQUARE)
    kept = tmp_path / (f"out.{fmt}" if fmt != "png" else "frames")
    if fmt != "png":
        kept.write_text("mine")
    code, out, err = cli("render", scene_file, "--draft", "-o", kept, "--format", "lottie" if fmt == "json" else fmt,
                         "-q")
    assert code == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "--draft" in lines[0], err
    if fmt != "json":
        assert "mp4 (.mp4) or webm (.webm)" in lines[0]  # what has them, from the format table
    assert not kept.exists() if fmt == "png" else kept.read_text() == "mine"
