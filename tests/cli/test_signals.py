"""Signals with real processes: no child outlives the command, and a hang-up cleans up like SIGTERM.

Each test starts ``python -m tweenrender render`` in its own session, lists its
process tree from ``/proc``, sends a real signal and polls for two seconds.
"""

from __future__ import annotations

import os
import select
import signal
import subprocess
import time
from pathlib import Path

import pytest

from tests.helpers import LONG, LONG_HD, MANIFEST, earlier_frames, start_render, write_scene

pytestmark = pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="lists processes through /proc")

# LONG_HD for a video, so ffmpeg has seconds of work queued when the parent dies


def _stat(pid: int) -> tuple[int, str] | None:
    """(parent pid, state letter) of ``pid``, or None once it is gone."""
    try:
        text = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return None
    fields = text[text.rindex(")") + 2:].split()
    return int(fields[1]), fields[0]


def descendants(root: int) -> set[int]:
    """Every living process below ``root``."""
    parents: dict[int, int] = {}
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            found = _stat(int(entry.name))
            if found is not None and found[1] != "Z":
                parents[int(entry.name)] = found[0]
    below, grew = set(), True
    while grew:
        grew = False
        for pid, parent in parents.items():
            if pid not in below and (parent == root or parent in below):
                below.add(pid)
                grew = True
    return below


def _alive(pid: int) -> bool:
    found = _stat(pid)
    return found is not None and found[1] != "Z"


_started: list[tuple[int, set[int]]] = []


@pytest.fixture(autouse=True)
def _leave_no_process():  # type: ignore[no-untyped-def]
    """Whatever a test found, no render it started (nor a child of one) outlives it."""
    yield
    while _started:
        pid, children = _started.pop()
        for leftover in [pid, *children, *descendants(pid)]:
            if _alive(leftover) and _ours(leftover):
                os.kill(leftover, signal.SIGKILL)


def _ours(pid: int) -> bool:
    """Whether ``pid`` still runs a render or its ffmpeg (not some process that took over the number)."""
    try:
        command = Path(f"/proc/{pid}/cmdline").read_bytes()
    except OSError:
        return False
    return b"tweenrender" in command or b"ffmpeg" in command


def _is_ffmpeg(pid: int) -> bool:
    try:
        return b"ffmpeg" in Path(f"/proc/{pid}/cmdline").read_bytes()
    except OSError:
        return False


def _start(folder: Path, scene: Path, target: Path, *flags: str, children: int) -> subprocess.Popen[bytes]:
    """Start a render into ``target``; return once it writes frames and has ``children`` processes."""
    before = set(folder.iterdir())
    process = start_render(scene, target, *flags, text=False)
    _started.append((process.pid, set()))
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        fresh = [p for p in set(folder.iterdir()) - before if p.name.startswith(f".{target.name}.")]
        started = fresh and (any(fresh[0].iterdir()) if fresh[0].is_dir() else fresh[0].stat().st_size > 0)
        kids = descendants(process.pid)
        # a video in chunks writes beside the target only once a chunk is done: its encoders show it started
        started = started or sum(_is_ffmpeg(pid) for pid in kids) >= 2
        if started and len(kids) >= children:
            _started[-1] = (process.pid, descendants(process.pid))
            return process
        assert process.poll() is None, process.communicate()
        time.sleep(0.02)
    process.kill()
    raise AssertionError("the render never started writing")


def _gone_within(pids: set[int], seconds: float) -> set[int]:
    """The pids still alive after polling for ``seconds``."""
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        left = {pid for pid in pids if _alive(pid)}
        if not left:
            return left
        time.sleep(0.02)
    return {pid for pid in pids if _alive(pid)}


def _eof_within(pipe, seconds: float) -> bool:  # type: ignore[no-untyped-def]
    """Whether every writer of ``pipe`` closed it within ``seconds`` (what ``| tail`` waits for)."""
    deadline = time.monotonic() + seconds
    while (left := deadline - time.monotonic()) > 0:
        ready, _, _ = select.select([pipe], [], [], left)
        if ready and not os.read(pipe.fileno(), 65536):
            return True
    return False


CASES = [("frames", ("--workers", "2"), 2), ("movie.mp4", (), 1), ("movie.mp4", ("--workers", "2"), 3)]


@pytest.mark.parametrize("output, flags, children", CASES, ids=["png-2-workers", "mp4", "mp4-2-workers"])
def test_sigkill_of_the_parent_ends_every_child_within_2_s(tmp_path: Path, output: str, flags: tuple[str, ...],
                                                          children: int) -> None:
    scene = write_scene(tmp_path, LONG_HD if output.endswith(".mp4") else LONG)
    process = _start(tmp_path, scene, tmp_path / output, *flags, children=children)
    kids = descendants(process.pid)
    assert len(kids) >= children - 1, kids  # a chunk's encoder may have finished meanwhile
    process.kill()
    process.wait(timeout=10)
    left = _gone_within(kids, 2.0)
    for pid in left:  # do not leave them running after the test, whatever it found
        os.kill(pid, signal.SIGKILL)
    assert not left, f"{len(left)} of {len(kids)} children outlived the parent by 2 s"
    assert _eof_within(process.stdout, 2.0), "a child still holds the parent's stdout"
    process.stdout.close()
    process.stderr.close()


@pytest.mark.parametrize("output, flags, children", CASES, ids=["png-2-workers", "mp4", "mp4-2-workers"])
@pytest.mark.parametrize("sig, code", [(signal.SIGHUP, 129), (signal.SIGTERM, 143), (signal.SIGINT, 130)],
                         ids=["SIGHUP", "SIGTERM", "SIGINT"])
def test_a_hang_up_terminate_or_interrupt_exits_cleanly(tmp_path: Path, output: str, flags: tuple[str, ...], children: int,
                                             sig: signal.Signals, code: int) -> None:
    scene = write_scene(tmp_path, LONG)
    target = tmp_path / output
    if output == "frames":
        earlier_frames(target, b"an earlier frame")
    else:
        target.write_bytes(b"an earlier movie")
    process = _start(tmp_path, scene, target, *flags, children=children)
    kids = descendants(process.pid)
    os.killpg(process.pid, sig)  # a terminal's hang-up reaches the whole foreground group
    out, err = process.communicate(timeout=60)
    assert process.returncode == code, err
    said = b"tweenrender: interrupted; no output was changed\n" if sig == signal.SIGINT else b""
    assert out == b"" and err == said
    assert not _gone_within(kids, 2.0)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(["scene.toml", output])  # no temporary left
    if output == "frames":
        assert sorted(p.name for p in target.iterdir()) == [MANIFEST, "frame_0000.png"]
    else:
        assert target.read_bytes() == b"an earlier movie"
