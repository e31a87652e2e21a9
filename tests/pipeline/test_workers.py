"""Frames drawn in worker processes and chunks rendered apart give the single render's video."""

from __future__ import annotations

from concurrent.futures import Executor, Future, ProcessPoolExecutor
from pathlib import Path

import numpy as np
import pytest

from tests.helpers import SMALL, SQUARE, decode, small_job, write_scene


_job = small_job


def _blue(frame: np.ndarray) -> np.ndarray:
    r, g, b = (frame[..., i].astype(int) for i in range(3))
    return (b > 150) & (r < 120) & (b - r > 80)


def test_split_range_covers_every_frame_once_in_order() -> None:
    from tweenrender.pipeline.workers import split_range

    for frames in (range(0, 10), range(7, 50), range(3, 4)):
        for parts in (1, 2, 3, 7, 100):
            pieces = split_range(frames, parts)
            assert [i for piece in pieces for i in piece] == list(frames)
            assert all(len(piece) > 0 for piece in pieces) and len(pieces) == min(parts, len(frames))
            assert max(map(len, pieces)) - min(map(len, pieces)) <= 1


def test_worker_frames_come_back_in_order_and_equal(tmp_path: Path, pool: ProcessPoolExecutor) -> None:
    from tweenrender.pipeline.workers import frame_stream

    job = _job(tmp_path)
    alone = [frame.copy() for frame in frame_stream(job)]
    spread = list(frame_stream(job, pool, workers=2, batch=3))
    assert len(alone) == len(spread) == 25  # 1 s at 24 fps, both ends
    assert all(np.array_equal(a, b) for a, b in zip(alone, spread))
    # the square moves right: its blue mass's mean column increases frame after frame
    columns = [np.nonzero(_blue(frame))[1].mean() for frame in spread]
    assert all(later > earlier for earlier, later in zip(columns, columns[1:]))


class _Recording(Executor):
    """Runs tasks at once in this process and counts them, to see how far ahead work is asked for."""

    def __init__(self) -> None:
        self.submitted = 0

    def submit(self, fn, /, *args, **kwargs):  # type: ignore[no-untyped-def, override]
        self.submitted += 1
        future: Future = Future()
        future.set_result(fn(*args, **kwargs))
        return future


def test_work_in_flight_is_bounded(tmp_path: Path) -> None:
    from tweenrender.pipeline.workers import frame_stream

    executor = _Recording()
    stream = frame_stream(_job(tmp_path), executor, workers=2, batch=2)
    next(stream)
    assert executor.submitted == 2 * 2 + 1  # two batches per worker ahead, plus the refill
    assert sum(1 for _ in stream) == 24 and executor.submitted == 13  # ceil(25 / 2) batches in all


def test_render_through_a_process_pool_writes_every_frame(tmp_path: Path, pool: ProcessPoolExecutor) -> None:
    from tweenrender.pipeline.stream import render

    target = render(_job(tmp_path), "mp4", tmp_path / "pooled.mp4", executor=pool)
    meta, frames = decode(target)
    assert meta["size"] == (160, 120) and len(frames) == 25


def test_chunks_rendered_apart_and_joined_match_one_render(tmp_path: Path, pool: ProcessPoolExecutor) -> None:
    from tweenrender.pipeline.chunks import render_chunks
    from tweenrender.pipeline.stream import render

    job = _job(tmp_path)
    whole = render(job, "mp4", tmp_path / "whole.mp4")
    joined = render_chunks(job, "mp4", tmp_path / "joined.mp4", pool, chunks=3)
    meta_w, frames_w = decode(whole)
    meta_j, frames_j = decode(joined)
    assert meta_j["size"] == meta_w["size"] == (160, 120)
    assert meta_j["fps"] == pytest.approx(24.0)
    assert len(frames_j) == len(frames_w) == 25
    for a, b in zip(frames_w, frames_j):
        assert np.abs(a.astype(int) - b.astype(int)).mean() < 2.0  # codec tolerance: same pictures
        assert abs(int(_blue(a).sum()) - int(_blue(b).sum())) <= 0.03 * _blue(a).sum()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["joined.mp4", "scene.toml", "whole.mp4"]


def test_concat_refuses_what_it_cannot_join(tmp_path: Path) -> None:
    from tweenrender.encode import concat
    from tweenrender.errors import OptionError

    with pytest.raises(OptionError, match="mp4, webm, gif only"):
        concat([tmp_path / "a.png"], tmp_path / "out.png")
    (tmp_path / "a.mp4").write_bytes(b"")
    with pytest.raises(OptionError, match="lossless .nut parts"):
        concat([tmp_path / "a.mp4"], tmp_path / "out.gif")
    with pytest.raises(OptionError, match="does not exist"):
        concat([tmp_path / "missing.mp4"], tmp_path / "out.mp4")


def test_default_workers() -> None:
    from tweenrender.plan.job import RenderJob
    from tweenrender.pipeline.workers import Cost, default_workers
    from tweenrender.scenefile import parse_scene

    scene_text = SQUARE.replace("time = 2\n", "time = 20\n")
    job = RenderJob(parse_scene(scene_text, "long.toml"), size=(1920, 1080))  # 481 frames of 1080p
    # costs given, not timed: the choice must not depend on how busy the machine is
    assert default_workers(job, "mp4", cpus=8, cost=Cost(draw=0.01, encode=0.1)) == 1  # the encoder is the limit
    # each process compresses its own frames, but four would hold more than 400 MiB at 1080p
    assert default_workers(job, "png", cpus=4, cost=Cost(draw=0.05, encode=0.1)) == 2
    assert default_workers(job, "png", cpus=1) == 1
    short = RenderJob(job.scene, size=(320, 240))
    assert default_workers(short, "png", cpus=4) == 1


def test_cli_workers(cli, tmp_path: Path) -> None:
    import imageio.v3 as iio

    scene = write_scene(tmp_path, SMALL)
    for workers in ("1", "2"):
        code, out, err = cli("render", scene, "-o", tmp_path / f"frames{workers}", "-q", "--workers", workers)
        assert code == 0, err
    names = [f"frame_{i:04d}.png" for i in range(25)]
    assert sorted(p.name for p in (tmp_path / "frames2").glob("*.png")) == names
    for name in names:  # compressed in the workers, the same pictures
        assert np.array_equal(iio.imread(tmp_path / "frames1" / name), iio.imread(tmp_path / "frames2" / name))
    first = iio.imread(tmp_path / "frames2" / names[0])
    # the 2×2 square at 160/12 = 13.33 px per unit (view 12 × 9 units in 160×120): 711 px, between
    # the pixels it fully covers and those it touches at all (one ring of antialiased edge)
    side = 2 * 160 / 12
    full, touched = _blue(first).sum(), (first[..., :3] != 255).any(axis=-1).sum()
    assert full <= side**2 <= touched and touched - full <= 4 * (side + 2)
    code, _, err = cli("render", scene, "-o", tmp_path / "x.mp4", "--workers", "0")
    assert code == 2 and "--workers" in err


def test_a_frame_failing_in_a_worker_stops_the_render_cleanly(tmp_path: Path,
                                                               monkeypatch: pytest.MonkeyPatch) -> None:
    import multiprocessing

    from tweenrender.errors import RenderError
    from tweenrender.pipeline.frames import Frames
    from tweenrender.pipeline.stream import render

    original = Frames.__call__

    def failing(self, index):  # type: ignore[no-untyped-def]
        if index == 7:
            raise ValueError("no polygon")
        return original(self, index)

    monkeypatch.setattr(Frames, "__call__", failing)
    job = _job(tmp_path)
    # forked workers inherit the patched class
    with ProcessPoolExecutor(max_workers=2, mp_context=multiprocessing.get_context("fork")) as pool:
        with pytest.raises(RenderError, match="frame 7: no polygon"):
            render(job, "mp4", tmp_path / "broken.mp4", executor=pool)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]  # no output, no temporaries
