"""Sinks check what they were given: a frame count other than the one announced is refused, and the
earlier output stays; what a video sink wrote is decoded back frame for frame."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tweenrender.encode import open_sink
from tweenrender.errors import EncodeError

from tests.helpers import decode

WIDTH, HEIGHT = 64, 48


def _frame(value: int) -> np.ndarray:
    frame = np.full((HEIGHT, WIDTH, 4), 255, dtype=np.uint8)
    frame[..., :3] = value
    return frame


def _listing(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir())


@pytest.mark.parametrize("fmt", ["png", "mp4", "webm", "gif"])
@pytest.mark.parametrize("written", [4, 6])
def test_a_sink_given_the_wrong_number_of_frames_refuses(tmp_path: Path, fmt: str, written: int) -> None:
    target = tmp_path / ("frames" if fmt == "png" else f"movie.{fmt}")
    if fmt == "png":
        earlier = open_sink(fmt, target, WIDTH, HEIGHT, 24.0, 1)
        earlier.write(_frame(0))
        earlier.close()
        old_frame = (target / "frame_0000.png").read_bytes()
    else:
        target.write_bytes(b"old movie")
    sink = open_sink(fmt, target, WIDTH, HEIGHT, 24.0, 5)
    for index in range(written):
        sink.write(_frame(40 * index))
    with pytest.raises(EncodeError, match=f"{written} frames"):
        sink.close()
    if fmt == "png":
        assert _listing(target) == [".tweenrender-manifest.json", "frame_0000.png"]
        assert (target / "frame_0000.png").read_bytes() == old_frame
    else:
        assert target.read_bytes() == b"old movie"
    assert _listing(tmp_path) == [target.name]  # no temporary left


@pytest.mark.parametrize("fmt", ["mp4", "webm"])
def test_a_video_sink_writes_every_frame_it_was_given(tmp_path: Path, fmt: str) -> None:
    target = tmp_path / f"movie.{fmt}"
    sink = open_sink(fmt, target, WIDTH, HEIGHT, 12.0, 5)
    for index in range(5):
        sink.write(_frame(50 * index))
    assert sink.close() == target
    meta, frames = decode(target)
    assert len(frames) == 5 and meta["fps"] == pytest.approx(12.0)
    levels = [float(f.mean()) for f in frames]
    assert levels == pytest.approx([50.0 * i for i in range(5)], abs=3)  # each grey, in order


def test_a_fractional_frame_rate_is_kept(tmp_path: Path) -> None:
    target = tmp_path / "movie.mp4"
    sink = open_sink("mp4", target, WIDTH, HEIGHT, 12.5, 5)
    for index in range(5):
        sink.write(_frame(50 * index))
    sink.close()
    meta, frames = decode(target)
    assert meta["fps"] == pytest.approx(12.5) and len(frames) == 5


# What the bundled ffmpeg printed for the probe's command (plus -stats_period 0.0005, which makes it
# print progress often) on a 3000-frame 64x48 video: progress lines as it goes, the total at the end.
PROBE_OUTPUT = """\
Input #0, mov,mp4,m4a,3gp,3g2,mj2, from 'probe.mp4':
  Duration: 00:02:05.00, start: 0.000000, bitrate: 393 kb/s
  Stream #0:0[0x1](und): Video: h264 (High) (avc1 / 0x31637661), yuv420p(progressive), 64x48, 392 kb/s, 24 fps, \
24 tbr, 12288 tbn (default)
Stream mapping:
  Stream #0:0 -> #0:0 (copy)
Output #0, null, to 'pipe:':
  Stream #0:0(und): Video: h264 (High) (avc1 / 0x31637661), yuv420p(progressive), 64x48, q=2-31, 392 kb/s, 24 fps, \
24 tbr, 12288 tbn (default)
frame=   28 fps=0.0 q=-1.0 size=N/A time=00:00:01.04 bitrate=N/A speed=1.79e+03x elapsed=0:00:00.00    \r\
frame=   87 fps=0.0 q=-1.0 size=N/A time=00:00:03.50 bitrate=N/A speed=2.94e+03x elapsed=0:00:00.00    \r\
frame= 2938 fps=0.0 q=-1.0 size=N/A time=00:02:02.33 bitrate=N/A speed=4.54e+03x elapsed=0:00:00.02    \r\
frame= 3000 fps=0.0 q=-1.0 size=N/A time=N/A bitrate=N/A speed=N/A elapsed=0:00:00.02    \r\
[out#0/null @ 0x55d0dac08d40] video:5985KiB audio:0KiB subtitle:0KiB other streams:0KiB global headers:0KiB \
muxing overhead: unknown
frame= 3000 fps=0.0 q=-1.0 Lsize=N/A time=00:02:04.91 bitrate=N/A speed=4.52e+03x elapsed=0:00:00.02    
"""


def test_the_probe_reads_the_final_frame_count(monkeypatch) -> None:
    import subprocess

    from tweenrender.encode import sinks

    def ran(command: list[str], **options: object) -> subprocess.CompletedProcess[str]:
        return subprocess.CompletedProcess(command, 0, "", PROBE_OUTPUT)

    monkeypatch.setattr(sinks, "run_program", ran)
    assert sinks.probe_video(Path("probe.mp4")) == (3000, (64, 48))


def test_ffmpeg_searched_early_is_searched_once_and_a_failure_is_reported_where_needed(monkeypatch) -> None:
    import threading

    import imageio_ffmpeg

    from tweenrender.encode import sinks

    calls: list[str] = []
    release = threading.Event()

    def found() -> str:
        calls.append(threading.current_thread().name)
        release.wait(5)
        return "/opt/ffmpeg"

    monkeypatch.setattr(sinks, "_FOUND", [])
    monkeypatch.setattr(sinks, "_EARLY", [])
    monkeypatch.setattr(imageio_ffmpeg, "get_ffmpeg_exe", found)
    sinks.find_ffmpeg_early()
    sinks.find_ffmpeg_early()  # a second call starts no second search
    release.set()
    assert sinks.ffmpeg_exe() == "/opt/ffmpeg" and sinks.ffmpeg_exe() == "/opt/ffmpeg"
    assert calls == ["find-ffmpeg"] and not sinks._EARLY[0].is_alive()

    def missing() -> str:
        calls.append(threading.current_thread().name)
        raise RuntimeError("No ffmpeg exe could be found.")

    monkeypatch.setattr(sinks, "_FOUND", [])
    monkeypatch.setattr(sinks, "_EARLY", [])
    monkeypatch.setattr(imageio_ffmpeg, "get_ffmpeg_exe", missing)
    sinks.find_ffmpeg_early()
    with pytest.raises(RuntimeError, match="No ffmpeg"):
        sinks.ffmpeg_exe()
    # each search is tried twice (a failure for want of file descriptors another thread held for a moment
    # passes), the early one's failure left for where ffmpeg is needed, which reports its own
    assert calls[1:] == ["find-ffmpeg", "find-ffmpeg", "MainThread", "MainThread"]


def test_a_render_refused_early_waits_for_the_ffmpeg_search_it_began(tmp_path: Path, monkeypatch) -> None:
    import threading
    import time

    import imageio_ffmpeg

    from tweenrender.cli.main import main
    from tweenrender.encode import sinks

    def slow() -> str:
        time.sleep(0.3)  # imageio-ffmpeg running ffmpeg -version to check it
        return "/opt/ffmpeg"

    monkeypatch.setattr(sinks, "_FOUND", [])
    monkeypatch.setattr(sinks, "_EARLY", [])
    monkeypatch.setattr(imageio_ffmpeg, "get_ffmpeg_exe", slow)
    bad = tmp_path / "bad.toml"
    bad.write_text("size = [10, 10\n")
    assert main(["render", str(bad), "-o", str(tmp_path / "out.mp4"), "-q"]) == 2
    assert len(sinks._EARLY) == 1 and not sinks._EARLY[0].is_alive()
    assert not any(t.name == "find-ffmpeg" for t in threading.enumerate())
