"""Chunks rendered apart and joined give the single render's output, for every format; the number of
drawing processes follows the measured cost of a frame."""

from __future__ import annotations

from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np
import pytest

from tests.helpers import LONG_HD, SQUARE, decode, read_png, small_job, start_render, video_stream_line, write_scene


_job = small_job


def test_png_chunks_are_the_single_renders_frames(tmp_path: Path, pool: ProcessPoolExecutor) -> None:
    from tweenrender.pipeline.chunks import render_chunks
    from tweenrender.pipeline.stream import render

    job = _job(tmp_path)
    whole = render(job, "png", tmp_path / "whole")
    seen: list[tuple[int, int]] = []
    joined = render_chunks(job, "png", tmp_path / "joined", pool, chunks=3, progress=lambda d, t: seen.append((d, t)))
    names = sorted(p.name for p in whole.glob("*.png"))
    assert names == [f"frame_{i:04d}.png" for i in range(25)] == sorted(p.name for p in joined.glob("*.png"))
    assert all(np.array_equal(read_png(whole / n), read_png(joined / n)) for n in names)
    assert seen == [(i, 25) for i in range(1, 26)]


def test_gif_chunks_join_into_the_single_renders_file(tmp_path: Path, pool: ProcessPoolExecutor) -> None:
    from tweenrender.pipeline.chunks import render_chunks
    from tweenrender.pipeline.stream import render

    job = _job(tmp_path)
    whole = render(job, "gif", tmp_path / "whole.gif")
    joined = render_chunks(job, "gif", tmp_path / "joined.gif", pool, chunks=3)
    # one palette for the whole clip, made from the same frames: the same file, byte for byte
    assert whole.read_bytes() == joined.read_bytes()
    _, frames = decode(joined)
    assert len(frames) == 25
    assert sorted(p.name for p in tmp_path.iterdir()) == ["joined.gif", "scene.toml", "whole.gif"]


@pytest.mark.parametrize("fmt", ["mp4", "webm"])
def test_video_chunks_decode_to_the_single_renders_frames(tmp_path: Path, pool: ProcessPoolExecutor,
                                                          fmt: str) -> None:
    from tweenrender.pipeline.chunks import render_chunks
    from tweenrender.pipeline.stream import render

    job = _job(tmp_path)
    _, single = decode(render(job, fmt, tmp_path / f"whole.{fmt}"))
    target = render_chunks(job, fmt, tmp_path / f"joined.{fmt}", pool, chunks=3)
    _, joined = decode(target)
    assert len(joined) == len(single) == 25
    assert "yuv420p(tv, smpte170m" in video_stream_line(target)  # the parts' colour tags, copied
    # lossy codecs: each part is encoded on its own, so the same pictures within codec noise, and
    # each frame is nearer its own counterpart than any neighbour (nothing lost, doubled or swapped)
    for index, frame in enumerate(joined):
        errors = [np.abs(frame.astype(int) - other.astype(int)).mean() for other in single]
        assert errors[index] < 1.5 and int(np.argmin(errors)) == index


def test_render_in_processes_chunks_a_video_and_streams_frames_otherwise(tmp_path: Path) -> None:
    from tweenrender.pipeline.chunks import render_in_processes
    from tweenrender.pipeline.stream import render

    job = _job(tmp_path)
    _, video = decode(render_in_processes(job, "mp4", tmp_path / "two.mp4", 2))
    assert len(video) == 25
    one = render(job, "png", tmp_path / "one")
    two = render_in_processes(job, "png", tmp_path / "two", 2)
    assert all(np.array_equal(read_png(one / p.name), read_png(two / p.name)) for p in one.glob("*.png"))


def test_predicted_seconds_follow_the_model() -> None:
    from tweenrender.pipeline.workers import Cost, predicted_seconds

    cost = Cost(draw=0.1, encode=0.1)
    # one process: the longer of drawing (slowed by sharing the cores) and the cores' share of all the work
    assert predicted_seconds(cost, "mp4", 100, 8 << 20, 1, 2) == pytest.approx(100 * max(0.125, 0.1))
    # two chunks halve the drawing; the cores' share stays; starting a process costs half a second
    assert predicted_seconds(cost, "mp4", 100, 8 << 20, 2, 2) == pytest.approx(100 * 0.1 + 1.0)
    # a GIF's frames travel back to its one encoder: a copy each
    assert predicted_seconds(cost, "gif", 100, 10**7, 2, 2) == pytest.approx(100 * (0.2 + 0.04) / 2 + 1.0)
    # PNG frames are compressed where they are drawn: the work divides among the processes, up to the cores
    assert predicted_seconds(cost, "png", 100, 0, 4, 2) == pytest.approx(100 * 0.2 / 2 + 2.0)


def test_workers_come_from_the_cost() -> None:
    from tweenrender.pipeline.workers import Cost, choose_workers

    frame = 1920 * 1080 * 4
    encoder_bound = Cost(draw=0.005, encode=0.108)  # 1080p busy scene: drawing is a twentieth of encoding
    draw_bound = Cost(draw=0.100, encode=0.108)  # 100 stroked shapes of 500 vertices
    for cpus in (2, 4, 8):
        assert choose_workers(encoder_bound, "mp4", 121, frame, cpus) == 1
    small = 640 * 360 * 4
    assert choose_workers(draw_bound, "mp4", 121, small, 2) == 2
    assert choose_workers(draw_bound, "mp4", 121, small, 1) == 1
    # at 1080p two chunks, each with its encoder, would hold more than the 400 MiB allowed
    assert choose_workers(draw_bound, "mp4", 121, frame, 2) == 1
    assert choose_workers(Cost(0.005, 0.12), "png", 121, frame, 2) == 2
    # four drawing processes would hold more than the 400 MiB allowed at 1080p
    assert choose_workers(Cost(0.005, 0.12), "png", 121, frame, 4) == 2
    assert choose_workers(Cost(0.005, 0.12), "png", 3, frame, 4) == 1  # too short to repay the start
    assert choose_workers(Cost(0.02, 0.1), "gif", 121, frame, 2) == 1


def test_default_workers_measures_only_what_can_pay(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from tweenrender.pipeline import workers
    from tweenrender.plan.job import RenderJob
    from tweenrender.scenefile import parse_scene

    measured: list[str] = []
    monkeypatch.setattr(workers, "measure_cost", lambda job, fmt: measured.append(fmt) or workers.Cost(0.1, 0.108))
    job = RenderJob(parse_scene(SQUARE.replace("time = 2\n", "time = 20\n"), "long.toml"), size=(640, 360))
    assert workers.default_workers(job, "mp4", cpus=2) == 2 and measured == ["mp4"]
    assert workers.default_workers(RenderJob(job.scene, size=(160, 120)), "mp4", cpus=2) == 1
    assert workers.default_workers(job, "mp4", cpus=1) == 1 and measured == ["mp4"]
    # at 1080p no second process with its encoder fits 400 MiB: one, and nothing measured
    assert workers.default_workers(RenderJob(job.scene, size=(1920, 1080)), "mp4", cpus=8) == 1
    assert measured == ["mp4"]


def test_ctrl_c_stops_chunk_workers_at_once_and_leaves_nothing(tmp_path: Path) -> None:
    import os
    import signal
    import subprocess
    import time

    # 14401 frames of 1080p in two chunks: each would run for many minutes if it were waited for
    scene = write_scene(tmp_path, LONG_HD)
    target = tmp_path / "out" / "clip.mp4"
    render = start_render(scene, target, "--workers", "2", stdout=None)
    try:
        time.sleep(4.0)  # the workers have started and are rendering their chunks
        assert render.poll() is None
        os.killpg(render.pid, signal.SIGINT)  # what a terminal's Ctrl-C does
        # the chunks in progress are stopped, not waited for (finishing them would take many minutes)
        _, err = render.communicate(timeout=120)
    finally:
        if render.poll() is None:
            os.killpg(render.pid, signal.SIGKILL)
    assert render.returncode == 130 and "interrupted" in err and "Traceback" not in err
    assert not target.exists() and list(target.parent.iterdir()) == []
    leftover = subprocess.run(["pgrep", "-f", str(tmp_path)], capture_output=True, text=True).stdout.split()
    assert leftover == []  # no ffmpeg nor worker still running on this render's files


@pytest.mark.parametrize("size", [(1920, 1080), (3840, 2160), (1280, 720), (640, 360)])
@pytest.mark.parametrize("fmt", ["mp4", "webm", "gif", "png"])
def test_whatever_auto_chooses_stays_within_the_memory_budget(size: tuple[int, int], fmt: str) -> None:
    from tweenrender.pipeline.workers import Cost, choose_workers, memory_budget_mib, tree_mib

    pixels = size[0] * size[1]
    for draw in (0.001, 0.02, 0.1, 1.0):
        for encode in (0.0, 0.01, 0.1):
            for cpus in (2, 4, 8, 16):
                chosen = choose_workers(Cost(draw, encode), fmt, 1000, pixels * 4, cpus)
                assert chosen == 1 or tree_mib(fmt, pixels, chosen) <= memory_budget_mib(pixels)
    assert memory_budget_mib(1920 * 1080) == 400.0
    assert 1000 <= memory_budget_mib(3840 * 2160) <= 1024


def test_the_encoder_cost_is_measured_on_the_jobs_own_frames(monkeypatch: pytest.MonkeyPatch) -> None:
    import numpy as np

    from tweenrender.encode import encoder_cost
    from tweenrender.pipeline import workers
    from tweenrender.pipeline.frames import Frames
    from tweenrender.plan.job import RenderJob
    from tweenrender.scenefile import parse_scene

    seen: list[list[np.ndarray]] = []
    monkeypatch.setattr(encoder_cost, "encoder_seconds",
                        lambda fmt, pictures, fps, alpha=False, draft=False: seen.append(list(pictures)) or 0.0125)
    job = RenderJob(parse_scene(SQUARE, "square.toml"), size=(64, 48))
    cost = workers.measure_cost(job, "mp4")
    assert cost.encode == 0.0125 and len(seen) == 1 and len(seen[0]) == 3
    middle = len(job.frame_range) // 2
    drawn = Frames(job)
    for offset, picture in enumerate(seen[0]):
        assert np.array_equal(picture, drawn(middle + offset))


def test_the_encoder_probe_counts_ffmpegs_cpu_time() -> None:
    import math

    import numpy as np

    from tweenrender.encode.encoder_cost import encoder_seconds

    rng = np.random.default_rng(0)
    pictures = [rng.integers(0, 256, (240, 320, 4), dtype=np.uint8) for _ in range(3)]
    for picture in pictures:
        picture[..., 3] = 255
    seconds = encoder_seconds("mp4", pictures, 24.0)
    assert math.isfinite(seconds) and seconds > 0.0
