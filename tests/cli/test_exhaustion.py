"""Out of file descriptors or memory: one line saying so and naming the limit, exit code 1, nothing written.

Each command runs in a child whose limit is lowered before it starts (``RLIMIT_NOFILE``, ``RLIMIT_AS``),
as ``ulimit -n`` and ``ulimit -v`` do in a shell.
"""

from __future__ import annotations

import errno
import resource
import subprocess
import sys
from pathlib import Path

import pytest

from tests.helpers import SMALL, write_scene


def _limited(limit: int, value: int, *args: object) -> subprocess.CompletedProcess[str]:
    def lower() -> None:
        resource.setrlimit(limit, (value, value))

    return subprocess.run([sys.executable, "-m", "tweenrender", *map(str, args)], capture_output=True, text=True,
                          timeout=300, preexec_fn=lower)


def _one_line(done: subprocess.CompletedProcess[str], words: str) -> None:
    assert done.returncode == 1, done.stderr
    assert done.stderr.startswith(f"tweenrender: error: {words}") and done.stderr.count("\n") == 1, done.stderr
    assert "Traceback" not in done.stderr and "unexpected" not in done.stderr


@pytest.mark.parametrize("files", [8, 6])
def test_too_few_file_descriptors_is_said_in_one_line(tmp_path: Path, files: int) -> None:
    scene = write_scene(tmp_path, SMALL)
    target = tmp_path / "movie.mp4"
    done = _limited(resource.RLIMIT_NOFILE, files, "render", scene, "-o", target, "-q")
    _one_line(done, "out of file descriptors")
    assert f"at most {files} open files" in done.stderr and "ulimit -n" in done.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]


@pytest.mark.parametrize("mib", [200])
def test_too_little_memory_is_said_in_one_line(tmp_path: Path, mib: int) -> None:
    scene = write_scene(tmp_path, SMALL)
    target = tmp_path / "movie.mp4"
    done = _limited(resource.RLIMIT_AS, mib << 20, "render", scene, "-o", target, "-q")
    _one_line(done, "out of memory")
    assert f"at most {mib} MiB" in done.stderr and "ulimit -v" in done.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]


@pytest.mark.parametrize("code, kind", [(errno.EMFILE, OSError), (errno.ENOMEM, MemoryError)])
def test_an_ffmpeg_that_cannot_start_is_not_called_missing(monkeypatch, code: int, kind: type) -> None:
    # imageio-ffmpeg runs each candidate and calls any failure "No ffmpeg exe could be found"
    import imageio_ffmpeg

    from tweenrender.encode import sinks

    def nothing_found() -> str:
        raise RuntimeError("No ffmpeg exe could be found. Install ffmpeg on your system, or set the "
                           "IMAGEIO_FFMPEG_EXE environment variable.")

    def cannot_start(*args: object, **kwargs: object) -> None:
        raise OSError(code, "refused")

    monkeypatch.setattr(imageio_ffmpeg, "get_ffmpeg_exe", nothing_found)
    monkeypatch.setattr(sinks, "_FOUND", [])
    monkeypatch.setattr(subprocess, "Popen", cannot_start)
    with pytest.raises(kind) as caught:
        sinks.ffmpeg_exe()
    if kind is OSError:
        assert caught.value.errno == code


def test_a_library_that_could_not_be_mapped_is_out_of_memory(cli, tmp_path: Path, monkeypatch) -> None:
    # dlopen says "failed to map segment" when mmap fails for want of memory; a loader wraps it in its own
    import tweenrender.scenefile

    def unloadable(*args: object, **kwargs: object) -> None:
        try:
            raise OSError("libllvmlite.so: failed to map segment from shared object")
        except OSError:
            raise OSError("Could not find/load shared object file 'libllvmlite.so'")

    def unimportable(*args: object, **kwargs: object) -> None:
        raise ImportError("libfreetype-2f3b32b6.so.6.16.1: failed to map segment from shared object")

    for failing in (unloadable, unimportable):
        monkeypatch.setattr(tweenrender.scenefile, "load_scene", failing)
        code, out, err = cli("render", write_scene(tmp_path, SMALL), "-q")
        assert code == 1 and out == ""
        assert err.startswith("tweenrender: error: out of memory") and err.count("\n") == 1, err
