"""Shared helpers: run the command line in-process, decode videos, update goldens."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]
SCENES = ROOT / "scenes"
GOLDEN = Path(__file__).resolve().parent / "golden"


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption("--update-golden", action="store_true", help="rewrite the golden images in tests/golden")


@pytest.fixture
def update_golden(request: pytest.FixtureRequest) -> bool:
    return bool(request.config.getoption("--update-golden"))


@pytest.fixture
def cli(capsys: pytest.CaptureFixture[str]):
    """Run ``tweenrender ARGS`` in-process; returns (exit code, stdout, stderr)."""
    from tweenrender.cli import main

    def run(*args: str) -> tuple[int, str, str]:
        code = main([str(a) for a in args])
        out, err = capsys.readouterr()
        return code, out, err

    return run


def run_module(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    """Run ``python -m tweenrender ARGS`` as a separate process."""
    return subprocess.run([sys.executable, "-m", "tweenrender", *map(str, args)], capture_output=True,
                          text=True, cwd=cwd, timeout=600)


def decode(path: Path) -> tuple[dict, list[np.ndarray]]:
    """A video's metadata and every frame as RGB ``(H, W, 3)`` uint8, decoded by ffmpeg."""
    import imageio_ffmpeg

    reader = imageio_ffmpeg.read_frames(str(path))
    meta = next(reader)
    width, height = meta["size"]
    frames = [np.frombuffer(raw, np.uint8).reshape(height, width, 3) for raw in reader]
    return meta, frames


def write_scene(folder: Path, text: str, name: str = "scene.toml") -> Path:
    path = folder / name
    path.write_text(text)
    return path


SQUARE = """size = [320, 240]
view = [-2, -2, 10, 7]
[[shape]]
name = "sq"
[[shape.key]]
time = 0
points = [[0, 0], [2, 0], [2, 2], [0, 2]]
[[shape.key]]
time = 2
points = [[7, 1], [7, 3], [5, 3], [5, 1]]
"""
