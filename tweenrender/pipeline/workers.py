"""Frames drawn in worker processes and handed back in order.

A frame is a pure function of (scene, methods, index), so any process can draw
any frame. :func:`frame_stream` has batches of frames drawn by a
``concurrent.futures.Executor`` (a ``ProcessPoolExecutor``, or a cluster's,
e.g. ``dask.distributed.Client.get_executor()``) and yields them in order to
one sink in this process, with a bounded number in flight so memory does not
grow with the clip. :mod:`.chunks` spreads whole parts of a clip instead.

skia holds the GIL while it draws, so threads do not help: use processes.
"""

from __future__ import annotations

import os
import uuid
from collections import deque
from concurrent.futures import Executor, Future
from dataclasses import dataclass
from typing import Any, Callable, Iterator, Sequence

import numpy as np
from numpy.typing import NDArray

from ..encode.formats import TABLE
from ..errors import RenderError
from .job import Frames, RenderJob

__all__ = ["frame_stream", "draw_frame", "default_workers", "split_range", "Cost", "measure_cost",
           "predicted_seconds", "choose_workers"]

# Below about this many pixels per clip, starting worker processes (≈0.3 s
# each, importing skia) costs more than the work they would share.
_MIN_PARALLEL_PIXELS = 24 * 1920 * 1080

Encode = Callable[[NDArray[np.uint8]], Any]
"""Applied to each frame where it was drawn (e.g. ``png_bytes``): what travels back is its result."""


def draw_frame(frames: Frames, index: int) -> NDArray[np.uint8]:
    """Frame ``index`` of ``frames``, with drawing failures reported as :class:`RenderError`."""
    try:
        return frames(index)
    except (ValueError, FloatingPointError, RuntimeError, ZeroDivisionError) as error:
        raise RenderError(f"frame {index}: {error}") from error


_CONTENTION = 1.25  # a lone drawing process, sharing the cores with the encoder's threads, draws this much slower
_START_SECONDS = 0.5  # one more worker process: starting Python, importing skia, building the job's frames
_TRANSFER_SECONDS_PER_BYTE = 4e-9  # a raw frame pickled back from a worker process
_GAIN = 0.9  # more processes only when they are predicted to take at most this share of one's time


@dataclass(frozen=True)
class Cost:
    """What one frame of a job costs: ``draw`` seconds to draw it in one process, ``encode`` CPU
    seconds to encode it (the video encoder's estimate, or PNG compression timed)."""

    draw: float
    encode: float


def measure_cost(job: RenderJob, fmt: str) -> Cost:
    """Time drawing one frame of ``job`` (its middle one, drawn twice, the second timed: the first
    builds the job's tracks and surface) and estimate the encoder's share for ``fmt``."""
    import time

    from ..encode.sinks import png_bytes

    frames = Frames(job)
    middle = job.frame_range[len(job.frame_range) // 2]
    draw_frame(frames, middle)
    start = time.perf_counter()
    picture = draw_frame(frames, middle)
    draw = time.perf_counter() - start
    per_megapixel = TABLE[fmt].encode_cost
    if per_megapixel is None:  # compressed where it is drawn: timed
        start = time.perf_counter()
        png_bytes(picture)
        return Cost(draw, time.perf_counter() - start)
    width, height = job.frame_size
    return Cost(draw, per_megapixel * width * height / 1e6)


def predicted_seconds(cost: Cost, fmt: str, frames: int, frame_bytes: int, processes: int, cpus: int) -> float:
    """Predicted wall time of rendering ``frames`` frames with ``processes`` drawing processes on ``cpus`` cores.

    PNG frames: each process draws and compresses, so the work divides among
    the processes (up to the cores). Video: one process draws while the encoder
    runs, so a frame takes the longer of drawing it (slowed by sharing the
    cores) and the cores' time for all the work; more processes divide the
    drawing (a chunked format as chunks with encoders of their own, any other
    as frames sent back to its one encoder, which costs a copy each).
    """
    start = _START_SECONDS * processes if processes > 1 else 0.0
    if TABLE[fmt].folder:
        return frames * (cost.draw + cost.encode) / min(processes, cpus) + start
    shared = cost.draw + cost.encode
    if processes > 1 and not TABLE[fmt].chunked:
        shared += _TRANSFER_SECONDS_PER_BYTE * frame_bytes
    per_frame = max(cost.draw * _CONTENTION / processes, shared / cpus)
    return frames * per_frame + start


def choose_workers(cost: Cost, fmt: str, frames: int, frame_bytes: int, cpus: int) -> int:
    """The number of drawing processes predicted fastest (at most ``cpus`` and 8), or 1 unless more
    save at least a tenth of the time."""
    alone = predicted_seconds(cost, fmt, frames, frame_bytes, 1, cpus)
    best, best_seconds = 1, alone
    for processes in range(2, min(cpus, 8) + 1):
        seconds = predicted_seconds(cost, fmt, frames, frame_bytes, processes, cpus)
        if seconds < best_seconds:
            best, best_seconds = processes, seconds
    return best if best_seconds <= _GAIN * alone else 1


def default_workers(job: RenderJob, fmt: str, cpus: int | None = None, cost: Cost | None = None) -> int:
    """How many processes to draw ``job``'s frames for ``fmt``: 1 unless the measured cost says more pay.

    The cost of a frame is measured once (:func:`measure_cost`) and weighed by
    :func:`choose_workers`: an encoder-bound video keeps one process (more
    would only compete with the encoder for the cores), a detailed, stroked
    scene whose drawing is the limit gets more, and PNG frames, compressed
    where they are drawn, one per core. Clips too short to repay starting
    processes are not measured.
    """
    if cpus is None:
        cpus = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    width, height = job.frame_size
    frames = len(job.frame_range)
    if cpus < 2 or width * height * frames < _MIN_PARALLEL_PIXELS:
        return 1
    cost = cost or measure_cost(job, fmt)
    return choose_workers(cost, fmt, frames, width * height * 4, cpus)


def split_range(frames: range, parts: int) -> list[range]:
    """``frames`` cut into ``parts`` consecutive, nearly equal, non-empty ranges (fewer if it is short)."""
    parts = max(1, min(parts, len(frames)))
    edges = np.linspace(0, len(frames), parts + 1).round().astype(int)
    return [frames[a:b] for a, b in zip(edges[:-1], edges[1:]) if b > a]


# One Frames per worker process, kept between batches of the same job: building
# it (correspondence, view, surfaces) is paid once per process, not per batch.
_cached: tuple[str, Frames] | None = None


def _draw_batch(token: str, job: RenderJob, indices: range, encode: Encode | None = None) -> Sequence[Any]:
    """Frames ``indices`` of ``job``: stacked ``(len(indices), height, width, 4)`` straight RGBA,
    or a list of ``encode(frame)``."""
    global _cached
    if _cached is None or _cached[0] != token:
        _cached = (token, Frames(job))
    frames = _cached[1]
    if encode is not None:
        return [encode(draw_frame(frames, index)) for index in indices]
    out = np.empty((len(indices), *job.frame_size[::-1], 4), dtype=np.uint8)
    for slot, index in enumerate(indices):
        out[slot] = draw_frame(frames, index)
    return out


def frame_stream(job: RenderJob, executor: Executor | None = None, workers: int = 1,
                 batch: int | None = None, encode: Encode | None = None, layout: str = "rgba") -> Iterator[Any]:
    """``job``'s frames in order as straight RGBA ``(height, width, 4)`` (or ``encode(frame)`` of each).

    Drawn here when ``executor`` is None and ``workers`` ≤ 1 (each array then
    reused by the next frame); otherwise in batches of ``batch`` frames on
    ``executor`` (or on a pool of ``workers`` processes made for the occasion),
    at most two batches per worker in flight (``workers`` is the executor's
    capacity: its processes, or a cluster's worker threads), each frame passed through
    ``encode`` (a picklable function) where it was drawn. ``layout="bgra"``
    hands over the surface's own pixels when drawing here (see ``Frames``).
    """
    indices = job.frame_range
    if executor is None and workers <= 1:
        frames = Frames(job, layout)
        for index in indices:
            frame = draw_frame(frames, index)
            yield frame if encode is None else encode(frame)
        return
    own = executor is None
    if executor is None:
        from concurrent.futures import ProcessPoolExecutor

        from ..encode.lifeline import worker_setup

        # workers die with this process, leave Ctrl-C, SIGHUP and SIGTERM to it (it stops them), and let go of
        # its stdout
        executor = ProcessPoolExecutor(max_workers=workers, initializer=worker_setup, initargs=(os.getpid(),))
    width, height = job.frame_size
    # a batch of about 32 MB amortises a round trip without holding much memory
    batch = batch or max(1, min(8, (32 << 20) // (width * height * 4)))
    # two batches per worker keep every worker busy while the sink takes the oldest
    ahead = 2 * max(workers, 1)
    token = uuid.uuid4().hex
    pending: deque[Future[Sequence[Any]]] = deque()
    batches = iter(split_range(indices, -(-len(indices) // batch)))
    try:
        for chunk in batches:
            pending.append(executor.submit(_draw_batch, token, job, chunk, encode))
            if len(pending) >= ahead:
                break
        while pending:
            done = pending.popleft().result()
            chunk = next(batches, None)
            if chunk is not None:
                pending.append(executor.submit(_draw_batch, token, job, chunk, encode))
            yield from done
    finally:
        for future in pending:
            future.cancel()
        if own:
            executor.shutdown(wait=True, cancel_futures=True)


