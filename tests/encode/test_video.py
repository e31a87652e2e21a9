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
