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


def run_main(*args: str, cwd: Path | None = None, warnings_as_errors: bool = False) -> subprocess.CompletedProcess[str]:
    """``tweenrender ARGS`` run in this process, seen as :func:`run_module` sees a process: the exit code, and
    stdout and stderr read as text from file descriptors 1 and 2 (so what a library or a child writes there is
    seen too), Python's streams encoding as a pipe's (UTF-8, strict on stdout), the warnings a fresh
    interpreter would show written to stderr (``warnings_as_errors``: raised instead, as ``python -W error``
    does). For tests of what a command does and says; signals, exits, start-up and the interpreter's own
    warnings are tested on real processes (:func:`run_module`)."""
    import io
    import tempfile
    import warnings

    from tweenrender.cli.main import main

    for stream in (sys.stdout, sys.stderr):
        stream.flush()
    here, streams, kept = os.getcwd(), (sys.stdout, sys.stderr), (os.dup(1), os.dup(2))
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err, \
            warnings.catch_warnings(record=True) as caught:
        warnings.resetwarnings()  # a fresh interpreter's filters
        for quiet in (DeprecationWarning, PendingDeprecationWarning, ImportWarning, ResourceWarning):
            warnings.simplefilter("ignore", quiet)
        warnings.filterwarnings("default", category=DeprecationWarning, module="__main__")
        if warnings_as_errors:
            warnings.simplefilter("error")
        os.dup2(out.fileno(), 1)
        os.dup2(err.fileno(), 2)
        sys.stdout = io.TextIOWrapper(open(os.dup(1), "wb"), encoding="utf-8", errors="strict", line_buffering=False)
        sys.stderr = io.TextIOWrapper(open(os.dup(2), "wb"), encoding="utf-8", errors="backslashreplace",
                                      line_buffering=True)
        try:
            if cwd is not None:
                os.chdir(cwd)
            try:
                code = main([str(a) for a in args])
            except SystemExit as done:  # --help, --version
                code = done.code if isinstance(done.code, int) else (0 if done.code is None else 1)
            for shown in caught:
                sys.stderr.write(warnings.formatwarning(shown.message, shown.category, shown.filename, shown.lineno,
                                                        shown.line))
        finally:
            for stream in (sys.stdout, sys.stderr):
                stream.close()
            sys.stdout, sys.stderr = streams
            os.dup2(kept[0], 1)
            os.dup2(kept[1], 2)
            for fd in kept:
                os.close(fd)
            os.chdir(here)
        out.seek(0)
        err.seek(0)
        return subprocess.CompletedProcess(["tweenrender", *map(str, args)], code, out.read().decode(),
                                           err.read().decode())


def run_forked(*args: str, cwd: Path | None = None, deadline: float = 120.0,
               warnings_as_errors: bool = False) -> subprocess.CompletedProcess[str]:
    """:func:`run_main` in a forked child that is killed at ``deadline`` seconds (raising
    ``subprocess.TimeoutExpired``): for inputs that must not hang the command, each a process of its own but
    without the start of a fresh interpreter (Python, numpy and skia are already loaded here). A child that
    dies of an exception reports it as exit code 1 with its traceback on stderr; one killed by a signal, as
    the signal's negative number."""
    command = ["tweenrender", *map(str, args)]
    kind, value = in_child(lambda: run_main(*args, cwd=cwd, warnings_as_errors=warnings_as_errors), command, deadline)
    if kind == "done":
        return value
    if kind == "raised":
        return subprocess.CompletedProcess(command, 1, "", value[1])
    return subprocess.CompletedProcess(command, value, "", f"the forked child ended without a report (status {value})")


def in_child(work: Callable[[], Any], command: list[str], deadline: float | None = None) -> tuple[str, Any]:
    """``work()`` run in a child forked from this process, its picklable outcome sent back through a pipe:
    ``("done", result)``, ``("raised", (one line, traceback))``, or ``("died", status)`` where the child ended
    before it reported (a signal as its negative number). Past ``deadline`` seconds the child is killed and
    ``subprocess.TimeoutExpired`` (naming ``command``) raised."""
    import selectors
    import time
    import traceback

    read, write = os.pipe()
    child = os.fork()
    if child == 0:  # pragma: no cover - runs in the child
        os.close(read)
        try:
            outcome: tuple[str, Any] = ("done", work())
        except BaseException as error:  # noqa: BLE001 - reported to the parent as a crash would be
            outcome = ("raised", (f"{type(error).__name__}: {error}", traceback.format_exc()))
        with os.fdopen(write, "wb") as pipe:
            pickle.dump(outcome, pipe)
        os._exit(0)
    os.close(write)
    data = bytearray()
    end = None if deadline is None else time.monotonic() + deadline
    with os.fdopen(read, "rb", buffering=0) as pipe, selectors.DefaultSelector() as waiting:
        waiting.register(pipe, selectors.EVENT_READ)
        while True:
            left = None if end is None else end - time.monotonic()
            if left is not None and (left <= 0 or not waiting.select(left)):
                os.kill(child, signal.SIGKILL)
                os.waitpid(child, 0)
                raise subprocess.TimeoutExpired(command, deadline)
            chunk = pipe.read(1 << 16)
            if not chunk:
                break
            data += chunk
    _, status = os.waitpid(child, 0)
    if not data:
        return "died", -os.WTERMSIG(status) if os.WIFSIGNALED(status) else os.WEXITSTATUS(status)
    return pickle.loads(bytes(data))


def decode(path: Path) -> tuple[dict, list[np.ndarray]]:
    """A video's metadata and every frame as RGB ``(H, W, 3)`` uint8, decoded by ffmpeg."""
    import imageio_ffmpeg

    reader = imageio_ffmpeg.read_frames(str(path))
    meta = next(reader)
    width, height = meta["size"]
    frames = [np.frombuffer(raw, np.uint8).reshape(height, width, 3) for raw in reader]
    return meta, frames


def write_clip(target: Path, fmt: str, width: int, height: int, frames: int, alpha: bool = False,
               held: bool = False) -> Path:
    """A short clip of flat frames written by the package's own sink: each a shade of its own (or all the
    same when ``held``), translucent when ``alpha``."""
    from tweenrender.encode import open_sink

    sink = open_sink(fmt, target, width, height, 24.0, frames, alpha=alpha)
    for shade in range(frames):
        value = 0 if held else 11 * shade % 256
        sink.write(np.full((height, width, 4), (value, 90, 200, 120 if alpha else 255), dtype=np.uint8))
    sink.close()
    return target


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


def overlapping_squares(folder: Path) -> list[Path]:
    """Two drawings of one path of two overlapping squares wound alike (the overlap winds twice), filled
    ``nonzero`` in the first (the overlap filled) and ``evenodd`` in the second (the overlap a hole), the
    squares drawn apart a little more: the picture shows which rule is in force. Each square begins on an edge
    outside the other, so both are outlines (not holes) in both drawings and pair with themselves."""
    drawings = []
    for name, rule, gap in (("nonzero.svg", "nonzero", 3), ("evenodd.svg", "evenodd", 4)):
        path = folder / name
        path.write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 16 12">'
                        f'<path id="squares" fill-rule="{rule}" d="M2 2h7v7h-7z M{9 + gap} 3v7h-7v-7z"/></svg>')
        drawings.append(path)
    return drawings


def same_wound_rings(folder: Path) -> list[Path]:
    """Two drawings of a square ring filled ``evenodd``, its outline and its hole wound the same way (as editors
    often write a compound path): only the even-odd rule leaves the hole empty."""
    drawings = []
    for name, x in (("ring-a.svg", 2), ("ring-b.svg", 4)):
        path = folder / name
        path.write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 16 12">'
                        f'<path id="ring" fill-rule="evenodd" d="M{x} 2h8v8h-8z M{x + 2} 4h4v4h-4z"/></svg>')
        drawings.append(path)
    return drawings


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

    def work() -> Any:
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
        return function(*args)

    kind, value = in_child(work, [getattr(function, "__name__", "function")])
    assert kind == "done", f"the unprivileged child failed: {value[0] if kind == 'raised' else value}"
    return value


SMALL = SQUARE.replace("size = [320, 240]", "size = [160, 120]").replace("time = 2\n", "time = 1\n")
LONG = SQUARE.replace("time = 2", "time = 600").replace("size = [320, 240]", "size = [640, 480]")
"""A render long enough to be stopped midway however slow the machine is at that moment (about half a
minute uninterrupted): for tests that interrupt, terminate or kill one."""
LONG_HD = LONG.replace("size = [640, 480]", "size = [1920, 1080]")
"""25 frames of a 160 × 120 square that slides right and turns a quarter."""


def small_job(folder: Path, **changes):  # type: ignore[no-untyped-def]
    """A :class:`RenderJob` of :data:`SMALL`, with ``changes`` to its fields."""
    from tweenrender.plan.job import RenderJob
    from tweenrender.scenefile import load_scene

    return RenderJob(load_scene(write_scene(folder, SMALL)), **changes)


def stroke_coverage(contours: list[np.ndarray], closed: list[bool], width: float, size: tuple[int, int],
                    samples: int = 16) -> np.ndarray:
    """Brute force: the fraction of each pixel's ``samples²`` points within ``width / 2`` of the polylines
    (a round-joined, round-capped stroke), ``(rows, cols)`` for ``size = (cols, rows)``."""
    cols, rows = size
    axis_x, axis_y = (np.arange(cols * samples) + 0.5) / samples, (np.arange(rows * samples) + 0.5) / samples
    inside = np.zeros((rows * samples, cols * samples), dtype=bool)
    r = width / 2
    for vertices, shut in zip(contours, closed):
        ends = np.roll(vertices, -1, axis=0) if shut else vertices[1:]
        for p, q in zip(vertices if shut else vertices[:-1], ends):
            xs = np.flatnonzero((axis_x >= min(p[0], q[0]) - r) & (axis_x <= max(p[0], q[0]) + r))
            ys = np.flatnonzero((axis_y >= min(p[1], q[1]) - r) & (axis_y <= max(p[1], q[1]) + r))
            if not len(xs) or not len(ys):
                continue
            px, py = np.meshgrid(axis_x[xs], axis_y[ys])
            edge = q - p
            length2 = edge @ edge
            t = np.clip(((px - p[0]) * edge[0] + (py - p[1]) * edge[1]) / length2, 0, 1) if length2 else 0.0
            inside[ys[0]:ys[-1] + 1, xs[0]:xs[-1] + 1] |= np.hypot(px - p[0] - t * edge[0],
                                                                   py - p[1] - t * edge[1]) <= r
    return inside.reshape(rows, samples, cols, samples).mean(axis=(1, 3))


def stroke_cases() -> list[tuple[str, list[np.ndarray], list[bool], float]]:
    """Outlines to stroke on a 48 × 40 canvas: smooth at four widths, a 30° and a 90° V (open), random
    spikes, an open wiggle, a lone point."""
    rng = np.random.default_rng(3)
    cases = []
    for width in (1.0, 2.0, 3.5, 8.0):
        turn = np.linspace(0, 2 * np.pi, 120, endpoint=False)
        radius = rng.uniform(8, 15)
        outline = np.stack([24.3 + 1.2 * radius * np.cos(turn),
                            20.1 + radius * np.sin(turn) * (0.8 + 0.2 * np.cos(3 * turn))], 1)
        cases.append((f"smooth, {width:g} px", [outline], [True], width))
    for angle in (30, 90):
        half = np.radians(angle) / 2
        tip = np.array([24.3, 12.2])
        one = tip + np.outer(np.linspace(18, 0, 40, endpoint=False), [np.sin(half), np.cos(half)])
        two = tip + np.outer(np.linspace(0, 18, 41), [-np.sin(half), np.cos(half)])
        cases.append((f"a {angle}° V of straight arms, 2 px", [np.concatenate([one, two])], [False], 2.0))
    for seed in range(2):
        spikes = np.random.default_rng(seed)
        turn = np.sort(spikes.uniform(0, 2 * np.pi, 100))
        radius = spikes.uniform(6, 17, 100)
        cases.append((f"random spikes, 2 px ({seed})", [np.stack([24 + radius * np.cos(turn),
                                                                   20 + radius * np.sin(turn)], 1)], [True], 2.0))
    x = np.linspace(4, 44, 60)
    cases.append(("an open wiggle, 3 px", [np.stack([x, 20 + 9 * np.sin(x / 4)], 1)], [False], 3.0))
    cases.append(("a lone point, closed, 5 px", [np.array([[20.3, 17.8], [20.3, 17.8]])], [True], 5.0))
    return cases


def ring_scene(shapes: int, vertices: int, size: tuple[int, int] = (480, 270), stroke: str = "#1d2b50",
               join: str = "round") -> str:
    """A scene's TOML text: ``shapes`` jagged rings of ``vertices`` vertices on a grid, each with a 2 px
    ``stroke`` and ``join``, turning a quarter between keys at 0 and 1 s."""
    rng = np.random.default_rng(5)
    lines = [f"size = [{size[0]}, {size[1]}]", "fps = 24", 'background = "#fdfdf8"', "view = [0, 0, 16, 9]", ""]
    columns = max(1, int(np.ceil(np.sqrt(shapes * 16 / 9))))
    for s in range(shapes):
        cx, cy = 1 + (s % columns) * 14 / columns, 1 + (s // columns) * 7 / max(1, shapes // columns)
        radius = 0.6 * (1 + 0.1 * rng.uniform(-1, 1, vertices))
        lines += ["[[shape]]", f'name = "r{s}"', 'fill = "#3b6fd8"', f'stroke = "{stroke}"', "stroke_width = 2.0",
                  f'join = "{join}"', ""]
        for time, turn in ((0, 0.0), (1, np.pi / 2)):
            angle = np.linspace(0, 2 * np.pi, vertices, endpoint=False) + turn
            points = np.stack([cx + radius * np.cos(angle), cy + radius * np.sin(angle)], 1).round(4)
            lines += ["[[shape.key]]", f"time = {time}", f"points = {points.tolist()}", ""]
    return "\n".join(lines)


MANIFEST = ".tweenrender-manifest.json"


def earlier_frames(folder: Path, data: bytes = b"old frame") -> None:
    """A frame set as tweenrender leaves one: ``frame_0000.png`` holding ``data`` and the manifest listing it
    (written here by hand, as the documented format says)."""
    import json

    folder.mkdir()
    frame = folder / "frame_0000.png"
    frame.write_bytes(data)
    info = frame.stat()
    listing = {"frame_0000.png": {"bytes": info.st_size, "mtime_ns": info.st_mtime_ns}}
    (folder / MANIFEST).write_text(json.dumps({"written_by": "tweenrender", "files": listing}))


def count_calls(monkeypatch: Any, owner: Any, name: str) -> list[int]:
    """Replace ``owner.name`` (a module's function) for the test with a wrapper that calls it and appends 1 to
    the list returned, so a test asserts counted work."""
    calls: list[int] = []
    real = getattr(owner, name)

    def counted(*args: Any, **kwargs: Any) -> Any:
        calls.append(1)
        return real(*args, **kwargs)

    monkeypatch.setattr(owner, name, counted)
    return calls
