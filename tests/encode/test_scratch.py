"""Temporary folders: all under ``$TMPDIR/tweenrender-<uid>/``, removed by their run, and what a killed run
left removed by the next run of any command, never a folder whose owner still runs.

Owners are real processes read from ``/proc``: a finished child is dead, this test's process runs, and
this process's pid with another start time stands for a dead process whose pid was given again.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from tests.helpers import LONG_HD, SMALL, write_scene

pytestmark = pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="reads process start times in /proc")


def _start_of(pid: int) -> int:
    text = Path(f"/proc/{pid}/stat").read_text()
    return int(text[text.rindex(")") + 2:].split()[19])


def _root(tmp: Path) -> Path:
    return tmp / f"tweenrender-{os.getuid()}"


def _environment(tmp: Path) -> dict[str, str]:
    tmp.mkdir(exist_ok=True)
    return {**os.environ, "TMPDIR": str(tmp)}


def test_any_run_removes_the_folders_of_dead_owners_only(tmp_path: Path) -> None:
    root = _root(tmp_path / "tmp")
    root.mkdir(parents=True, mode=0o700)
    child = subprocess.Popen(["sleep", "0"])
    dead_start = _start_of(child.pid)
    child.wait()
    me, my_start = os.getpid(), _start_of(os.getpid())
    folders = {"dead": f"{child.pid}-{dead_start}-parts-0a1b2c3d", "running": f"{me}-{my_start}-parts-1b2c3d4e",
               "pid-reused": f"{me}-{my_start + 1}-dask-2c3d4e5f", "not-ours": "notes"}
    for name in folders.values():
        (root / name).mkdir()
        (root / name / "part.webm").write_bytes(b"left over")
    scene = write_scene(tmp_path, SMALL)
    done = subprocess.run([sys.executable, "-m", "tweenrender", "check", str(scene)], capture_output=True, text=True,
                          env=_environment(tmp_path / "tmp"), timeout=120)
    assert done.returncode == 0, done.stderr
    assert sorted(p.name for p in root.iterdir()) == sorted([folders["running"], folders["not-ours"]])


def test_a_root_that_is_not_this_users_folder_is_refused_in_one_line(tmp_path: Path) -> None:
    tmp = tmp_path / "tmp"
    tmp.mkdir()
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    _root(tmp).symlink_to(elsewhere)
    scene = write_scene(tmp_path, LONG_HD)
    done = subprocess.run([sys.executable, "-m", "tweenrender", "render", str(scene), "-o", str(tmp_path / "m.webm"),
                           "-q", "--workers", "2", "--frames", "0:4"], capture_output=True, text=True,
                          env=_environment(tmp), timeout=120)
    assert done.returncode == 1 and done.stderr.count("\n") == 1, done.stderr
    assert done.stderr.startswith(f"tweenrender: error: {_root(tmp)}: cannot keep temporary files there")
    assert list(elsewhere.iterdir()) == [] and not (tmp_path / "m.webm").exists()


def _wait_for_a_part(tmp: Path, process: subprocess.Popen[str]) -> None:
    """Return once a worker has begun a part (its temporary file exists, wherever it is in ``tmp``)."""
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        try:
            if any(f.is_file() and "part" in f.name for f in tmp.rglob("*")):
                time.sleep(0.5)
                return
        except FileNotFoundError:  # a folder gone between the listing and the look
            pass
        assert process.poll() is None, process.communicate()
        time.sleep(0.05)
    process.kill()
    pytest.fail("the render never started writing a part")


def test_ctrl_c_during_a_webm_render_with_workers_leaves_no_temporary(tmp_path: Path) -> None:
    scene = write_scene(tmp_path, LONG_HD)
    tmp = tmp_path / "tmp"
    process = subprocess.Popen([sys.executable, "-m", "tweenrender", "render", str(scene), "-o",
                                str(tmp_path / "movie.webm"), "-q", "--workers", "2"],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=_environment(tmp),
                               start_new_session=True, preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    _wait_for_a_part(tmp, process)
    os.killpg(process.pid, signal.SIGINT)  # Ctrl-C reaches the whole foreground group
    out, err = process.communicate(timeout=60)
    assert process.returncode == 130 and err == "tweenrender: interrupted; no output was changed\n", err
    assert [p for p in tmp.rglob("*") if p != _root(tmp)] == []  # the run's folders, and what is in them
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml", "tmp"]
