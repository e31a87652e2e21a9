"""Reliability: bad input refused clearly, outputs never lost, degenerate input rendered.

Through the real command line: exit codes (0 done, 1 render/encode failure, 2 bad
input, 130 interrupted), one-line messages without tracebacks (unless ``-v``),
earlier outputs byte-identical after any failure, a kill or Ctrl-C, a full disk.
"""

from __future__ import annotations

import json
import math
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tweenrender.core.methods.registry import interpolate

from tests.helpers import (LONG, MANIFEST, SQUARE, earlier_frames, run_module, start_render, unprivileged,
                           write_scene)
from tests.scenefile.test_load_more import MORE_BAD

METHODS = ("linear", "nonlinear", "rigid", "auto", "jointed")


def _listing(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir())


# -- bad scenes through the command line ----------------------------------------------------------

@pytest.mark.parametrize("name, text, where, words", MORE_BAD, ids=[b[0] for b in MORE_BAD])
def test_bad_scene_exits_2_and_keeps_the_output(cli, tmp_path: Path, name: str, text: str, where: str,
                                                words: str) -> None:
    scene = write_scene(tmp_path, text, name)
    target = tmp_path / "movie.mp4"
    target.write_bytes(b"an earlier render")
    code, out, err = cli("render", scene, "-o", target, "-q")
    assert code == 2 and out == ""
    assert err.startswith(f"tweenrender: error: {scene}: ") and err.count("\n") == 1, err
    assert where in err and words in err and "Traceback" not in err
    assert target.read_bytes() == b"an earlier render"
    assert _listing(tmp_path) == sorted([name, "movie.mp4"])


def test_a_fifo_scene_does_not_hang_the_command(tmp_path: Path) -> None:
    fifo = tmp_path / "pipe.toml"
    os.mkfifo(fifo)
    result = subprocess.run([sys.executable, "-m", "tweenrender", "check", str(fifo)], capture_output=True,
                            text=True, timeout=60)
    assert result.returncode == 2
    assert result.stderr == f"tweenrender: error: {fifo}: is a pipe (FIFO), expected a scene file (.toml or .json)\n"


def test_verbose_shows_the_traceback_and_keeps_the_exit_code(tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE.replace("time = 2", "time = -2"))
    quiet = run_module("check", scene)
    loud = run_module("-v", "check", scene)
    assert quiet.returncode == loud.returncode == 2
    assert "Traceback" not in quiet.stderr and quiet.stderr.count("\n") == 1
    assert loud.stderr.startswith("Traceback (most recent call last):") and "SceneError" in loud.stderr
    assert loud.stderr.endswith(quiet.stderr)


def test_an_unexpected_failure_is_one_line_and_exit_1(cli, tmp_path: Path, monkeypatch) -> None:
    import tweenrender.scenefile

    def broken(path: object, step: float = 1.0, *timing: object) -> None:
        raise ZeroDivisionError("a bug\nover two lines")

    monkeypatch.setattr(tweenrender.scenefile, "load_scene", broken)
    scene = write_scene(tmp_path, SQUARE)
    code, _, err = cli("render", scene, "-q")
    assert code == 1
    assert err == ("tweenrender: error: unexpected ZeroDivisionError: a bug | over two lines "
                   "(run with -v for details)\n")
    code, _, err = cli("-v", "render", scene, "-q")
    assert code == 1 and "Traceback" in err and 'raise ZeroDivisionError("a bug' in err


def test_too_many_frames_names_the_flag(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE.replace("time = 2", "time = 1e7"))
    code, _, err = cli("render", scene, "--fps", "240", "-q", "-o", tmp_path / "x.mp4")
    # 10 million seconds at 240 frames per second, both ends included
    assert code == 2 and f"--max-frames: {240 * 10**7 + 1} frames is more than 100000" in err
    assert _listing(tmp_path) == ["scene.toml"]


# -- outputs are never lost -------------------------------------------------------------------------

def test_an_output_under_a_file_is_reported(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE)
    code, _, err = cli("render", scene, "-o", tmp_path / "scene.toml" / "movie.mp4", "-q")
    assert code == 1
    assert err == f"tweenrender: error: {scene}: cannot create the output folder (a file of that name is in the way)\n"
    assert scene.read_text() == SQUARE


def test_a_read_only_folder_is_reported(open_tmp_path: Path) -> None:
    """As an unprivileged user (root writes anywhere, so a root run drops to ``nobody`` first)."""
    import contextlib
    import io

    from tweenrender.cli.main import main

    scene = write_scene(open_tmp_path, SQUARE)
    locked = open_tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o555)

    def render() -> tuple[int, str]:
        said = io.StringIO()
        with contextlib.redirect_stderr(said):
            code = main(["render", str(scene), "-o", str(locked / "movie.mp4"), "-q"])
        return code, said.getvalue()

    code, err = unprivileged(render)
    assert code == 1 and err == f"tweenrender: error: {locked}: the output folder is not writable\n"
    assert _listing(locked) == []


@pytest.mark.parametrize("output, seconds, limit", [("movie.mp4", 20, 32), ("movie.gif", 5, 32), ("frames", 2, 2)])
def test_a_file_size_limit_is_reported_and_the_old_output_kept(tmp_path: Path, output: str, seconds: int,
                                                               limit: int) -> None:
    """A write refused half-way (here by ``ulimit -f``, in KiB, which needs no privilege; a full disk
    fails the same way) is one line, exit 1, and leaves the earlier output and no temporary."""
    import resource

    # at 640x480: 20 s is about 100 KB of H.264, 5 s 170 KB of GIF; a PNG frame is 3 to 4 KB
    scene = write_scene(tmp_path, SQUARE.replace("size = [320, 240]", "size = [640, 480]")
                        .replace("time = 2", f"time = {seconds}"))
    disk = tmp_path / "disk"
    disk.mkdir()
    target = disk / output
    if output == "frames":
        earlier_frames(target)
    else:
        target.write_bytes(b"old movie")

    def limited() -> None:
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit << 10, limit << 10))

    done = subprocess.run([sys.executable, "-m", "tweenrender", "render", str(scene), "-o", str(target), "-q"],
                          capture_output=True, text=True, preexec_fn=limited, timeout=300)
    err = done.stderr
    assert done.returncode == 1 and err.count("\n") == 1, err
    # Python's own writes get EFBIG; ffmpeg, which keeps the default action, is stopped by SIGXFSZ
    words = "File too large" if output == "frames" else "stopped by SIGXFSZ (File size limit exceeded)"
    assert err.startswith(f"tweenrender: error: {target}: ") and words in err and "Traceback" not in err
    if output == "frames":
        assert _listing(target) == [MANIFEST, "frame_0000.png"] and (target / "frame_0000.png").read_bytes() == b"old frame"
    else:
        assert target.read_bytes() == b"old movie"
    assert _listing(disk) == [output]  # the temporary is gone




def _start_and_wait_for_temporary(folder: Path, scene: Path, target: Path) -> subprocess.Popen[str]:
    """Start a long render into ``target`` in its own session; return once its temporary exists."""
    before = set(folder.iterdir())
    process = start_render(scene, target)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        fresh = [p for p in set(folder.iterdir()) - before if p.name.startswith(f".{target.name}.")]
        started = fresh and (any(fresh[0].iterdir()) if fresh[0].is_dir() else fresh[0].stat().st_size > 0)
        if started:
            return process
        assert process.poll() is None, process.communicate()
        time.sleep(0.01)
    process.kill()
    raise AssertionError("the render never started writing")


def test_sigkill_midway_leaves_the_old_output_and_the_next_run_sweeps(tmp_path: Path) -> None:
    scene = write_scene(tmp_path, LONG)
    target = tmp_path / "movie.mp4"
    target.write_bytes(b"old movie")
    process = _start_and_wait_for_temporary(tmp_path, scene, target)
    process.send_signal(signal.SIGKILL)
    process.communicate(timeout=60)
    assert process.returncode == -signal.SIGKILL
    assert target.read_bytes() == b"old movie"
    stale = [p for p in tmp_path.iterdir() if p.name.startswith(".movie.mp4.")]
    assert len(stale) == 1  # a killed process cannot clean up...
    short = write_scene(tmp_path, SQUARE, "short.toml")
    result = run_module("render", short, "-o", target, "--frames", "0:2", "-q")
    assert result.returncode == 0, result.stderr
    assert _listing(tmp_path) == ["movie.mp4", "scene.toml", "short.toml"]  # ...the next run does


def test_sigterm_midway_removes_the_temporary(tmp_path: Path) -> None:
    scene = write_scene(tmp_path, LONG)
    target = tmp_path / "movie.mp4"
    target.write_bytes(b"old movie")
    process = _start_and_wait_for_temporary(tmp_path, scene, target)
    process.terminate()
    process.communicate(timeout=60)
    assert process.returncode == 128 + signal.SIGTERM
    assert target.read_bytes() == b"old movie"
    assert _listing(tmp_path) == ["movie.mp4", "scene.toml"]


@pytest.mark.parametrize("output", ["movie.mp4", "frames"])
def test_ctrl_c_midway_exits_130_and_keeps_the_old_output(tmp_path: Path, output: str) -> None:
    scene = write_scene(tmp_path, LONG)
    target = tmp_path / output
    if output == "frames":
        earlier_frames(target)
    else:
        target.write_bytes(b"old movie")
    process = _start_and_wait_for_temporary(tmp_path, scene, target)
    os.killpg(process.pid, signal.SIGINT)  # what a terminal's Ctrl-C does: the whole group, ffmpeg too
    out, err = process.communicate(timeout=60)
    assert process.returncode == 130
    assert out == "" and err == "tweenrender: interrupted; no output was changed\n"
    if output == "frames":
        assert _listing(target) == [MANIFEST, "frame_0000.png"] and (target / "frame_0000.png").read_bytes() == b"old frame"
    else:
        assert target.read_bytes() == b"old movie"
    assert _listing(tmp_path) == sorted(["scene.toml", output])


# -- degenerate but legal input renders -----------------------------------------------------------

SQ = [(0, 0), (2, 0), (2, 2), (0, 2)]
RING = [(3 + 2 * math.cos(a), 1 + 2 * math.sin(a)) for a in np.linspace(0, 2 * math.pi, 400, endpoint=False)]
DEGENERATE = {
    "collinear": [[(0, 0), (1, 0), (2, 0)], [(0, 0), (0, 1), (0, 2)]],
    "repeated": [[(0, 0), (0, 0), (2, 0), (2, 2), (2, 2)], [(5, 5), (5, 5), (7, 5), (7, 7), (7, 7)]],
    "bow-tie": [[(0, 0), (2, 2), (2, 0), (0, 2)], [(4, 0), (6, 2), (6, 0), (4, 2)]],
    "half-turn": [SQ, [(2, 2), (0, 2), (0, 0), (2, 0)]],
    # (1, 1) is the vertex mean of the first key, (5, 1) of the second
    "vertex-at-center": [[(0, 0), (3, 0), (1, 1), (0, 3)], [(6, 0), (6, 3), (5, 1), (3, 0)]],
    "one-point": [[(1, 1)] * 4, [(2, 2)] * 4],
    "tiny": [[(0, 0), (1e-9, 0), (1e-9, 1e-9), (0, 1e-9)], [(1e-9, 1e-9), (2e-9, 1e-9), (2e-9, 2e-9), (1e-9, 2e-9)]],
    "one-key": [SQ],
    "3-to-400": [[(0, 0), (1, 0), (0, 1)], RING],
    "400-to-3": [RING, [(0, 0), (1, 0), (0, 1)]],
    "huge": [[(-1e9, -1e9), (1e9, -1e9), (0, 1e9)], [(1e9, 1e9), (-1e9, 1e9), (0, -1e9)]],
}


def _scene_text(keys: list[list[tuple[float, float]]], method: str, view: str = "") -> str:
    joints = "joints = [[0, 2]]\n" if method == "jointed" and len(keys[0]) >= 4 else ""
    text = f'size = [160, 120]\nfps = 4\n{view}[[shape]]\nname = "s"\nstroke = "#000000"\nmethod = "{method}"\n{joints}'
    for k, points in enumerate(keys):
        text += f"[[shape.key]]\ntime = {k}\npoints = {json.dumps([[float(x), float(y)] for x, y in points])}\n"
    return text


def _frames(folder: Path) -> list[np.ndarray]:
    import imageio.v3 as iio

    return [iio.imread(path) for path in sorted(folder.glob("frame_*.png"))]


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("case", sorted(DEGENERATE))
def test_degenerate_shapes_render(cli, tmp_path: Path, case: str, method: str) -> None:
    keys = DEGENERATE[case]
    if method == "jointed" and len(keys[0]) < 4:
        method = "nonlinear"  # joints need four vertices; the case is still drawn
    scene = write_scene(tmp_path, _scene_text(keys, method))
    code, _, err = cli("render", scene, "-o", tmp_path / "frames", "-q")
    assert code == 0, err
    frames = _frames(tmp_path / "frames")
    assert len(frames) == (5 if len(keys) == 2 else 1)  # 1 s at 4 fps, both ends
    for index, rgba in enumerate(frames):
        assert rgba.shape == (120, 160, 4) and (rgba[..., 3] == 255).all()
        inked = (rgba[..., :3] < 200).any(axis=-1).sum()
        assert inked >= 1, f"frame {index} is blank"

    from tweenrender.pipeline.frames import Frames
    from tweenrender.plan.job import RenderJob
    from tweenrender.scenefile import load_scene

    frames_of = Frames(RenderJob(load_scene(scene)))
    for time_ in np.linspace(0.0, 1.0, 21):
        assert all(np.isfinite(c).all() for at in frames_of.shapes_at(method, float(time_)) for c in at.contours)


def test_shapes_off_the_view_render_blank(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, _scene_text(DEGENERATE["half-turn"], "nonlinear", "view = [100, 100, 110, 105]\n"))
    code, _, err = cli("render", scene, "-o", tmp_path / "frames", "-q")
    assert code == 0, err
    assert all((rgba == 255).all() for rgba in _frames(tmp_path / "frames"))


# -- properties of the interpolation --------------------------------------------------------------

_PROPERTY = settings(max_examples=200, deadline=None)
_COORD = st.floats(-1e6, 1e6, allow_nan=False, allow_infinity=False)


@st.composite
def _key_pairs(draw: st.DrawFn) -> tuple[np.ndarray, np.ndarray]:
    count = draw(st.integers(3, 12))
    points = st.lists(st.tuples(_COORD, _COORD), min_size=count, max_size=count)
    return np.array(draw(points), dtype=np.float64), np.array(draw(points), dtype=np.float64)


def _turn(points: np.ndarray, angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return points @ np.array([[c, s], [-s, c]])


@_PROPERTY
@given(keys=_key_pairs(), method=st.sampled_from(METHODS), t=st.lists(st.floats(0, 1), max_size=6))
def test_keys_are_hit_exactly_and_inbetweens_are_finite(keys: tuple[np.ndarray, np.ndarray], method: str,
                                                       t: list[float]) -> None:
    k0, k1 = keys
    joints = [(0, 2)] if method == "jointed" and len(k0) >= 4 else []
    frames = interpolate(k0, k1, np.array([0.0, 1.0, *t]), method, joints)
    assert frames.shape == (2 + len(t), len(k0), 2)
    assert np.array_equal(frames[0], k0) and np.array_equal(frames[1], k1)
    assert np.isfinite(frames).all()


@st.composite
def _rigid_motions(draw: st.DrawFn) -> tuple[np.ndarray, float, np.ndarray]:
    count = draw(st.integers(3, 10))
    small = st.floats(-100, 100, allow_nan=False)
    shape = np.array(draw(st.lists(st.tuples(small, small), min_size=count, max_size=count)), dtype=np.float64)
    spread = np.linalg.norm(shape - shape.mean(axis=0), axis=1).max()
    from hypothesis import assume

    assume(spread > 1e-2)  # a shape that is a single point has no rotation to keep
    angle = draw(st.floats(-0.95 * math.pi, 0.95 * math.pi))
    shift = np.array(draw(st.tuples(small, small)), dtype=np.float64)
    return shape, angle, shift


@_PROPERTY
@given(motion=_rigid_motions(), t=st.floats(0, 1))
def test_rigid_keeps_a_rigid_motion_at_every_t(motion: tuple[np.ndarray, float, np.ndarray], t: float) -> None:
    k0, angle, shift = motion
    c0 = k0.mean(axis=0)
    k1 = _turn(k0 - c0, angle) + c0 + shift
    expected = _turn(k0 - c0, t * angle) + c0 + t * shift
    got = interpolate(k0, k1, [t], "rigid")[0]
    assert np.allclose(got, expected, rtol=0, atol=1e-7 * (1 + np.abs(k0).max() + np.abs(shift).max()))


@_PROPERTY
@given(motion=_rigid_motions())
def test_nonlinear_keeps_a_rigid_motion_at_mid_turn(motion: tuple[np.ndarray, float, np.ndarray]) -> None:
    k0, angle, shift = motion
    c0 = k0.mean(axis=0)
    k1 = _turn(k0 - c0, angle) + c0 + shift
    # the thesis's mid frame: the shape turned by half the angle about the midpoint of the centers
    expected = _turn(k0 - c0, angle / 2) + c0 + shift / 2
    got = interpolate(k0, k1, [0.5], "nonlinear")[0]
    assert np.allclose(got, expected, rtol=0, atol=1e-7 * (1 + np.abs(k0).max() + np.abs(shift).max()))


def test_the_scene_is_never_its_own_output(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE)
    code, _, err = cli("render", scene, "--format", "mp4", "-o", scene, "-q")
    assert code == 2 and err == f"tweenrender: error: {scene}: is the scene file itself; choose another output\n"
    assert scene.read_text() == SQUARE and _listing(tmp_path) == ["scene.toml"]


@pytest.mark.parametrize("flags, words", [
    (("--method", "nonlinaer"), "unknown method 'nonlinaer' (did you mean 'nonlinear'?)"),
    (("--method", "linear,rigid"), "--method: expected one method, found 2 (linear,rigid); use --compare"),
    (("--compare", "linear,rgid"), "unknown method 'rgid' (did you mean 'rigid'?)"),
])
def test_method_flags_suggest(cli, tmp_path: Path, flags: tuple[str, ...], words: str) -> None:
    scene = write_scene(tmp_path, SQUARE)
    code, _, err = cli("render", scene, *flags, "-q", "-o", tmp_path / "x.mp4")
    assert code == 2 and words in err and err.count("\n") == 1
    assert _listing(tmp_path) == ["scene.toml"]


def test_sweep_restores_a_folder_caught_between_two_renames(tmp_path: Path) -> None:
    from tweenrender.encode.atomic import sweep

    target = tmp_path / "frames"
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True,
                          text=True).stdout.strip()  # a process id that has finished
    aside = tmp_path / f".frames.{dead}-0123abcd.part.old"  # the earlier output, stepped aside
    aside.mkdir()
    (aside / "frame_0000.png").write_bytes(b"old frame")
    half = tmp_path / f".frames.{dead}-89abcdef.part"  # the new output, unfinished
    half.mkdir()
    mine = tmp_path / f".frames.{os.getpid()}-00000000.part"  # a live process's: left alone
    mine.mkdir()
    sweep(target)
    assert (target / "frame_0000.png").read_bytes() == b"old frame"
    assert _listing(tmp_path) == [mine.name, "frames"]
