"""The cluster path fails cleanly: addresses checked before connecting, a port where nothing or something
else listens refused in one line, no dask log line on stderr when stopped, and a kill leaves temporaries
that the next run of the same output removes.

Child processes carry deadlines far above a correct run only so that a hang fails instead of blocking
the suite; nothing here asserts how long anything took.
"""

from __future__ import annotations

import http.server
import os
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from tests.cli.test_signals import descendants
from tests.helpers import LONG, SQUARE, write_scene

distributed = pytest.importorskip("distributed", reason="dask.distributed is not installed (the cluster extra)")

SMALL = SQUARE.replace("size = [320, 240]", "size = [160, 120]").replace("time = 2\n", "time = 1\n")


@pytest.mark.parametrize("address, words", [
    ("bogus", "tcp://HOST:PORT"),
    ("[::1", "tcp://HOST:PORT"),
    ("http://127.0.0.1:8786", "http"),
    ("https://scheduler:8786", "https"),
    ("inproc://x", "inproc"),
    ("ucx://scheduler:8786", "ucx"),
    ("tls://scheduler:8786", "tls"),
    ("ws://scheduler:8786", "ws"),
    ("tcp://scheduler:99999", "99999"),
    ("tcp://scheduler:0", "port"),
    ("tcp://scheduler:port", "port"),
    ("tcp://:8786", "host"),
    ("tcp://[::1:8786", "tcp://HOST:PORT"),
    ("tcp://a b:8786", "host"),
])
def test_a_bad_address_is_refused_before_connecting(cli, tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                    address: str, words: str) -> None:
    import tweenrender as tr
    from tweenrender.errors import OptionError

    def no_connection(*args: object, **kwargs: object) -> None:
        raise AssertionError("a connection was attempted")

    monkeypatch.setattr(distributed, "Client", no_connection)
    monkeypatch.setattr(distributed, "LocalCluster", no_connection)
    scene_path = write_scene(tmp_path, SMALL)
    with pytest.raises(OptionError) as caught:
        tr.write(tr.load_scene(scene_path), tmp_path / "x.mp4", cluster=address)
    assert words in str(caught.value) and "\n" not in str(caught.value)
    code, out, err = cli("render", scene_path, "-o", tmp_path / "x.mp4", "--cluster", address, "-q")
    assert code == 2 and err == f"tweenrender: error: {caught.value.for_flag()}\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]


@pytest.mark.parametrize("address, parsed", [
    ("tcp://127.0.0.1:8786", "tcp://127.0.0.1:8786"),
    (" 127.0.0.1:8786 ", "tcp://127.0.0.1:8786"),
    ("tcp://scheduler", "tcp://scheduler:8786"),
    ("tcp://[::1]:9000", "tcp://[::1]:9000"),
    ("[::1]:9000", "tcp://[::1]:9000"),
    ("scheduler.example.org:8786", "tcp://scheduler.example.org:8786"),
])
def test_good_addresses_are_read_as_tcp(address: str, parsed: str) -> None:
    from tweenrender.plan.cluster_address import parse_address

    assert parse_address(address) == (parsed, None)


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def _render(tmp_path: Path, *args: str) -> subprocess.CompletedProcess[str]:
    try:
        return subprocess.run([sys.executable, "-m", "tweenrender", "render", *args], capture_output=True,
                              text=True, cwd=tmp_path, timeout=150)
    except subprocess.TimeoutExpired:
        pytest.fail("the render did not return")


def test_a_port_where_nothing_listens_is_one_line(tmp_path: Path) -> None:
    write_scene(tmp_path, SMALL)
    done = _render(tmp_path, "scene.toml", "-o", "x.mp4", "-q", "--cluster", f"tcp://127.0.0.1:{_free_port()}")
    assert done.returncode == 1 and done.stderr.count("\n") == 1, done.stderr
    assert "nothing listens" in done.stderr and "unexpected" not in done.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args: object) -> None:
        pass


def test_an_http_server_is_not_taken_for_a_scheduler(tmp_path: Path) -> None:
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), _Quiet)
    thread = threading.Thread(target=server.serve_forever, kwargs={"poll_interval": 0.05}, daemon=True)
    thread.start()
    try:
        write_scene(tmp_path, SMALL)
        done = _render(tmp_path, "scene.toml", "-o", "x.mp4", "-q", "--cluster",
                       f"tcp://127.0.0.1:{server.server_address[1]}")
    finally:
        server.shutdown()
        server.server_close()
    assert done.returncode == 1 and done.stderr.count("\n") == 1, done.stderr
    assert "not a dask scheduler" in done.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]


def _environment(tmp: Path) -> dict[str, str]:
    tmp.mkdir(exist_ok=True)
    return {**os.environ, "TMPDIR": str(tmp)}


def _ours_in(tmp: Path) -> list[str]:
    """What the runs left in ``tmp``: the folders in the one place for temporaries (and any other
    ``tweenrender-`` entry)."""
    root = tmp / f"tweenrender-{os.getuid()}"
    others = [p.name for p in tmp.iterdir() if p.name.startswith("tweenrender-") and p != root]
    return sorted(others + ([p.name for p in root.iterdir()] if root.is_dir() else []))


def _start_cluster_render(tmp_path: Path, scene: Path, target: Path) -> subprocess.Popen[str]:
    """A long render on a local cluster of two, returned once a worker writes its part."""
    tmp = tmp_path / "tmp"
    process = subprocess.Popen([sys.executable, "-m", "tweenrender", "render", str(scene), "-o", str(target), "-q",
                                "--cluster", "local:2"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               env=_environment(tmp), start_new_session=True,
                               preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        # a worker's part folder (not dask's scratch) holding the part's temporary, being written
        try:
            parts = [p.stat().st_size for folder in tmp.glob(f"tweenrender-{os.getuid()}/*-part-*")
                     for p in folder.iterdir()]
        except FileNotFoundError:  # a folder or file gone between the listing and the look
            parts = []
        if any(parts):
            return process
        assert process.poll() is None, process.communicate()
        time.sleep(0.05)
    process.kill()
    pytest.fail("the cluster render never started writing a part")


def _kill_leftovers(process: subprocess.Popen[str], kids: set[int]) -> None:
    for pid in kids:
        try:
            os.kill(pid, signal.SIGKILL)
        except OSError:
            pass


@pytest.mark.parametrize("sig, code", [(signal.SIGTERM, 143), (signal.SIGINT, 130), (signal.SIGHUP, 129)],
                         ids=["SIGTERM", "SIGINT", "SIGHUP"])
def test_a_stopped_cluster_render_prints_no_dask_log(tmp_path: Path, sig: signal.Signals, code: int) -> None:
    scene = write_scene(tmp_path, LONG)
    target = tmp_path / "movie.mp4"
    process = _start_cluster_render(tmp_path, scene, target)
    kids = descendants(process.pid)
    try:
        if sig == signal.SIGINT:
            os.killpg(process.pid, sig)  # Ctrl-C: the whole group
        else:
            process.send_signal(sig)
        out, err = process.communicate(timeout=120)
    finally:
        _kill_leftovers(process, kids)
    assert process.returncode == code, err
    said = "tweenrender: interrupted; no output was changed\n" if sig == signal.SIGINT else ""
    assert out == "" and err == said
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml", "tmp"]
    assert _ours_in(tmp_path / "tmp") == []


def test_a_killed_cluster_render_leaves_what_the_next_run_removes(tmp_path: Path) -> None:
    scene = write_scene(tmp_path, LONG)
    target = tmp_path / "movie.mp4"
    process = _start_cluster_render(tmp_path, scene, target)
    kids = descendants(process.pid)
    process.send_signal(signal.SIGKILL)
    process.communicate(timeout=60)
    time.sleep(0.5)  # the workers see their parent gone
    _kill_leftovers(process, kids)
    left = _ours_in(tmp_path / "tmp")
    assert left, "a killed render cannot clean up (else this test shows nothing)"
    # every temporary folder is in the one place, named by the run (its pid) that owned it; none beside
    # the target
    assert all(name.startswith(f"{process.pid}-") for name in left), left
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml", "tmp"]
    # the next run of any command removes them
    short = write_scene(tmp_path, SMALL, "short.toml")
    done = subprocess.run([sys.executable, "-m", "tweenrender", "check", str(short)], capture_output=True, text=True,
                          env=_environment(tmp_path / "tmp"), timeout=150)
    assert done.returncode == 0 and done.stderr == "", done.stderr
    assert _ours_in(tmp_path / "tmp") == []
