"""Children die with their parent: ffmpeg by the kernel's death signal, drawing workers also by a watch."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from tests.cli.test_signals import _alive, _gone_within

pytestmark = pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="lists processes through /proc")


def _run_and_kill(code: str, count: int = 1) -> tuple[list[int], set[int]]:
    """Run ``code``, which prints ``count`` pids, one a line, and "ready"; SIGKILL it; the pids and
    those still alive 2 s later."""
    process = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
    assert process.stdout is not None
    pids, ready = [], False
    for line in process.stdout:  # the pids and "ready", in whichever order the processes print them
        if line.strip() == "ready":
            ready = True
        else:
            pids.append(int(line))
        if ready and len(pids) == count:
            break
    assert pids and all(_alive(pid) for pid in pids)
    process.kill()
    process.wait(timeout=10)
    left = _gone_within(set(pids), 2.0)
    return pids, left


def test_ffmpeg_ends_with_its_parent_even_while_its_input_is_held_open(tmp_path: Path) -> None:
    """A process forked after ffmpeg started holds ffmpeg's input open (as a drawing worker does), so
    ffmpeg never sees the end of its input: only the death signal can end it."""
    code = (
        "import os, time, numpy as np\n"
        "from pathlib import Path\n"
        "from tweenrender.encode.sinks import FFmpegVideo\n"
        f"sink = FFmpegVideo('mp4', Path({str(tmp_path / 'movie.mp4')!r}), 64, 48, 24.0, 1000)\n"
        "sink.write(np.zeros((48, 64, 4), np.uint8))\n"
        "holder = os.fork()\n"
        "if holder == 0:\n"
        "    os.setsid()\n"
        "    time.sleep(60)\n"
        "    os._exit(0)\n"
        "print(sink.process.pid, flush=True)\n"
        "print(holder, flush=True)\n"
        "print('ready', flush=True)\n"
        "time.sleep(600)\n")
    (ffmpeg, holder), left = _run_and_kill(code, 2)
    os.kill(holder, signal.SIGKILL)
    if ffmpeg in left:
        os.kill(ffmpeg, signal.SIGKILL)
    assert ffmpeg not in left, "ffmpeg outlived its parent by 2 s"


def test_the_watch_of_the_parent_ends_a_child_where_no_death_signal_is_set() -> None:
    """Without ``PR_SET_PDEATHSIG`` (not Linux), a child polls its parent and ends within 2 s of it."""
    code = (
        "import os, time\n"
        "from tweenrender.encode.lifeline import watch_parent\n"
        "parent = os.getpid()\n"
        "child = os.fork()\n"
        "if child == 0:\n"
        "    watch_parent(parent)\n"
        "    print('ready', flush=True)\n"
        "    time.sleep(600)\n"
        "    os._exit(0)\n"
        "print(child, flush=True)\n"
        "time.sleep(600)\n")
    (child,), left = _run_and_kill(code)
    if left:
        os.kill(child, signal.SIGKILL)
    assert not left, "the child outlived its parent by 2 s"


def test_a_worker_whose_parent_ended_before_it_was_set_up_ends_at_once() -> None:
    code = (
        "import os, time\n"
        "from tweenrender.encode.lifeline import die_with_parent\n"
        "parent = os.getpid()\n"
        "child = os.fork()\n"
        "if child == 0:\n"
        "    time.sleep(0.5)  # the parent is killed meanwhile\n"
        "    die_with_parent(parent)\n"
        "    time.sleep(600)\n"
        "    os._exit(0)\n"
        "print(child, flush=True)\n"
        "print('ready', flush=True)\n"
        "time.sleep(600)\n")
    (child,), left = _run_and_kill(code)
    if left:
        os.kill(child, signal.SIGKILL)
    assert not left


def test_a_stop_that_lands_in_a_finaliser_still_ends_the_part_quietly() -> None:
    """A chunk worker's SIGTERM raises ``Stopped`` wherever the worker is, and a finaliser (an object's
    ``__del__``, run when a frame's last reference goes) cannot pass an exception on: Python printed
    "Exception ignored in …" on the render's stderr and the worker drew on. Here the signal arrives inside
    one: the worker must still stop in its own code, at its next frame, clean up and say nothing."""
    code = (
        "import os, signal, sys\n"
        "from tweenrender.encode.lifeline import Stopped, part_worker_setup, stop_if_asked, stoppable\n"
        "part_worker_setup(os.getppid())\n"
        "class Frame:\n"
        "    def __del__(self):\n"
        "        os.kill(os.getpid(), signal.SIGTERM)\n"
        "        for _ in range(1000):  # the handler runs in here\n"
        "            pass\n"
        "try:\n"
        "    with stoppable():\n"
        "        Frame()\n"
        "        for _ in range(100000):\n"
        "            pass\n"
        "        stop_if_asked()  # the next frame\n"
        "    os._exit(3)  # drew on\n"
        "except Stopped as stop:\n"
        "    os._exit(stop.code)  # its part cleaned up\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert (done.stderr, done.returncode) == ("", 143)
