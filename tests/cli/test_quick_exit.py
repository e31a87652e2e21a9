"""The command's exit: with numba's compiler loaded it skips the interpreter's teardown (0.25–0.3 s) but
still runs the exit handlers, flushes what it printed and keeps its exit code; without numba, or with a
thread still to wait for, the exit is Python's own."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

_PROBE = """
import atexit, os, sys, threading
{load}
class Teardown:
    def __del__(self):
        os.write(2, b"teardown\\n")
kept = Teardown()  # let go only when the interpreter tears its modules down
atexit.register(lambda: os.write(2, b"atexit\\n"))
{thread}
sys.argv = ["tweenrender", *{argv!r}]
from tweenrender.cli.main import entry
entry()
"""


def _run(load: str, argv: list[str], thread: str = "") -> subprocess.CompletedProcess[str]:
    code = _PROBE.format(load=load, argv=argv, thread=thread)
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, timeout=300)


@pytest.mark.parametrize("scene", ["square.toml", "no-such-scene.toml"])
def test_with_numba_loaded_the_teardown_is_skipped_not_the_handlers_nor_the_output(scene: str) -> None:
    done = _run("import numba", ["check", "--json", str(ROOT / "scenes" / scene)])
    said = done.stderr.splitlines()
    assert "atexit" in said and "teardown" not in said
    if scene == "square.toml":
        assert done.returncode == 0 and json.loads(done.stdout)  # every byte printed is there
    else:
        assert done.returncode == 2 and any("no-such-scene.toml" in line for line in said)


def test_without_numba_or_with_a_thread_to_wait_for_python_exits_as_usual() -> None:
    plain = _run("", ["check", "--json", str(ROOT / "scenes" / "square.toml")])
    assert plain.returncode == 0 and json.loads(plain.stdout)
    assert {"atexit", "teardown"} <= set(plain.stderr.splitlines())
    waiting = _run("import numba", ["check", str(ROOT / "scenes" / "square.toml")],
                   # the thread must still run when the command is done: long enough for a machine under load
                   thread="threading.Thread(target=lambda: (__import__('time').sleep(8), "
                          "os.write(2, b'thread done\\n'))).start()")
    said = waiting.stderr.splitlines()
    assert waiting.returncode == 0 and {"thread done", "atexit", "teardown"} <= set(said)
