"""Helpers shared by the tests: paths, a scene to start from, running the CLI, decoding videos."""

from __future__ import annotations

import os
import pickle
import signal
import subprocess
import sys
from pathlib import Path
from typing import Any, Callable

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
SCENES = ROOT / "scenes"
GOLDEN = Path(__file__).resolve().parent / "golden"
DATA = Path(__file__).resolve().parent / "data"


def start_render(scene: Path, target: Path, *flags: str, text: bool = True,
                 stdout: int | None = subprocess.PIPE) -> subprocess.Popen[Any]:
    """``tweenrender render scene -o target -q *flags`` started in a session of its own, with Ctrl-C's default
    action as from a terminal: a shell starts a background job (a test run with ``&``) with SIGINT ignored,
    and a Python started so keeps ignoring it, which is right for it and wrong for a test of Ctrl-C."""
    return subprocess.Popen([sys.executable, "-m", "tweenrender", "render", str(scene), "-o", str(target), "-q", *flags],
                            stdout=stdout, stderr=subprocess.PIPE, text=text, start_new_session=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))


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


def video_stream_line(path: Path, *decoder: str) -> str:
    """ffmpeg's line about the video stream of ``path`` (codec, pixel format, colour tags, size), read with
    ``decoder`` options if any (e.g. ``-c:v libvpx-vp9``, which sees VP9's alpha)."""
    import imageio_ffmpeg

    said = subprocess.run([imageio_ffmpeg.get_ffmpeg_exe(), "-hide_banner", *decoder, "-i", str(path)],
                          capture_output=True, text=True).stderr
    return next(line for line in said.splitlines() if "Video:" in line)


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
"""The thesis's square (ch. 6): 2 × 2, translated and turned 90° in 2 s, in a 320 × 240 frame."""


def read_png(path: Path) -> np.ndarray:
    import imageio.v3 as iio

    return np.asarray(iio.imread(path))


def assert_close_to_golden(picture: np.ndarray, name: str, update: bool) -> None:
    """Compare ``picture`` with ``tests/golden/NAME`` within antialiasing noise.

    With ``--update-golden`` the golden image is rewritten and the test *skips*: a test
    that writes its own expectation proves nothing in that run.
    """
    import imageio.v3 as iio
    import pytest

    golden = GOLDEN / name
    if update:
        iio.imwrite(golden, picture)
        pytest.skip(f"rewrote {golden.name}; run again without --update-golden to compare")
    expected = read_png(golden)
    assert picture.shape == expected.shape, f"{name}: {picture.shape} against {expected.shape}"
    difference = np.abs(picture.astype(int) - expected.astype(int))
    assert difference.mean() < 0.5 and np.percentile(difference, 99.9) < 64, \
        f"{name}: mean difference {difference.mean():.3f}, 99.9th percentile {np.percentile(difference, 99.9)}"


def unprivileged(function: Callable[..., Any], *args: Any) -> Any:
    """``function(*args)`` run in a forked child as an unprivileged user; its (picklable) result.

    Root reads and writes whatever the permissions say, so a test of a permission
    refusal drops to ``nobody`` first; anyone else runs it as they are. Every module of
    the package is imported before dropping, since the interpreter's own files may not
    be readable by ``nobody``. The folders involved must be reachable by that user
    (see the ``open_tmp_path`` fixture).
    """
    import importlib
    import pkgutil

    import tweenrender

    read, write = os.pipe()
    child = os.fork()
    if child == 0:  # pragma: no cover - runs in the child
        os.close(read)
        try:
            for module in pkgutil.walk_packages(tweenrender.__path__, "tweenrender."):
                if not module.name.endswith("__main__"):
                    importlib.import_module(module.name)
            if os.geteuid() == 0:
                import pwd

                try:
                    user = pwd.getpwnam("nobody")
                    uid, gid = user.pw_uid, user.pw_gid
                except KeyError:
                    uid = gid = 65534
                os.setgroups([])
                os.setgid(gid)
                os.setuid(uid)
            outcome: tuple[bool, Any] = (True, function(*args))
        except BaseException as error:  # noqa: BLE001 - reported to the parent
            outcome = (False, f"{type(error).__name__}: {error}")
        with os.fdopen(write, "wb") as pipe:
            pickle.dump(outcome, pipe)
        os._exit(0)
    os.close(write)
    with os.fdopen(read, "rb") as pipe:
        data = pipe.read()
    os.waitpid(child, 0)
    done, value = pickle.loads(data)
    assert done, f"the unprivileged child failed: {value}"
    return value


SMALL = SQUARE.replace("size = [320, 240]", "size = [160, 120]").replace("time = 2\n", "time = 1\n")
LONG = SQUARE.replace("time = 2", "time = 600").replace("size = [320, 240]", "size = [640, 480]")
"""A render long enough to be stopped midway however slow the machine is at that moment (about half a
minute uninterrupted): for tests that interrupt, terminate or kill one."""
LONG_HD = LONG.replace("size = [640, 480]", "size = [1920, 1080]")
"""25 frames of a 160 × 120 square that slides right and turns a quarter."""


def small_job(folder: Path, **changes):  # type: ignore[no-untyped-def]
    """A :class:`RenderJob` of :data:`SMALL`, with ``changes`` to its fields."""
    from tweenrender.pipeline.job import RenderJob
    from tweenrender.scenefile import load_scene

    return RenderJob(load_scene(write_scene(folder, SMALL)), **changes)
