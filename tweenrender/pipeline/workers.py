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
from dataclasses import dataclass, replace
from typing import Any, Callable, Iterator, Sequence

import numpy as np
from numpy.typing import NDArray

from ..core.correspondence.correspond import SearchTooLarge
from ..core.timing.timeline import tracks_of
from ..encode.formats import TABLE
from ..encode.lifeline import stop_if_asked
from ..errors import RenderError
from ..plan.job import RenderJob
from .frames import Frames

__all__ = ["frame_stream", "draw_frame", "default_workers", "split_range", "Cost", "measure_cost",
           "predicted_seconds", "choose_workers", "tree_mib", "memory_budget_mib"]

# Below about this many pixels per clip, starting worker processes (≈0.3 s
# each, importing skia) costs more than the work they would share.
_MIN_PARALLEL_PIXELS = 24 * 1920 * 1080

Encode = Callable[[NDArray[np.uint8]], Any]
"""Applied to each frame where it was drawn (e.g. ``png_bytes``): what travels back is its result."""


def draw_frame(frames: Frames, index: int) -> NDArray[np.uint8]:
    """Frame ``index`` of ``frames``, with drawing failures reported as :class:`RenderError` (a search refused
    for its memory is the input's fault and stays as it is); in a chunk worker asked to stop where it could
    not be (:func:`~..encode.lifeline.stop_if_asked`), the stop."""
    stop_if_asked()
    try:
        return frames(index)
    except SearchTooLarge:
        raise
    except (ValueError, FloatingPointError, RuntimeError, ZeroDivisionError) as error:
        raise RenderError(f"frame {index}: {error}") from error


_CONTENTION = 1.25  # a lone drawing process, sharing the cores with the encoder's threads, draws this much slower
_START_SECONDS = 0.5  # one more worker process: starting Python, importing skia, building the job's frames
_TRANSFER_SECONDS_PER_BYTE = 4e-9  # a raw frame pickled back from a worker process
_GAIN = 0.9  # more processes only when they are predicted to take at most this share of one's time

# Peak memory of the process tree (resident, every process), measured with benchmarks/bench_render.py
# on the busy scene: one process and its encoder 335 MiB at 1080p, 892 MiB at 4K; two chunks 625 and
# 1594 MiB. Each chunk (a drawing process with an encoder of its own) thus holds about 132 MiB plus
# 78 MiB a megapixel of frame; the command's own process, idle meanwhile, about 40 MiB.
_PROCESS_MIB = 132.0
_ENCODER_MIB_PER_MEGAPIXEL = 78.0
_IDLE_PARENT_MIB = 40.0
_BUDGET_MIB = 400.0  # the most the whole tree may hold at 1080p ...
_BUDGET_MIB_PER_MEGAPIXEL = 100.0  # ... and this much more a megapixel above it (about 1 GiB at 4K)
_BUDGET_BASE_PIXELS = 1920 * 1080


@dataclass(frozen=True)
class Cost:
    """What one frame of a job costs: ``draw`` seconds to draw it in one process, ``encode`` CPU
    seconds to encode it (the video encoder's estimate, or PNG compression timed)."""

    draw: float
    encode: float


def measure_cost(job: RenderJob, fmt: str) -> Cost:
    """Time drawing frames of ``job`` in CPU seconds (three from its middle: the first builds the job's
    tracks and surface, the other two are timed) and the encoder on those three frames (its CPU time, start
    included, see :mod:`..encode.encoder_cost`; PNG compression timed for PNG frames)."""
    import time

    from ..encode.sinks import png_bytes

    frames = Frames(job)
    indices = job.frame_range
    middle = len(indices) // 2
    picked = [indices[min(middle + k, len(indices) - 1)] for k in range(3)]
    pictures = [draw_frame(frames, picked[0]).copy()]
    start = time.process_time()  # CPU seconds, as the encoder's are: other load on the machine stretches neither
    for index in picked[1:]:
        pictures.append(draw_frame(frames, index).copy())
    draw = (time.process_time() - start) / (len(picked) - 1)
    if TABLE[fmt].folder:  # compressed where it is drawn: timed here
        start = time.process_time()
        png_bytes(pictures[-1])
        return Cost(draw, time.process_time() - start)
    from ..encode.encoder_cost import encoder_seconds

    return Cost(draw, encoder_seconds(fmt, pictures, job.rate, alpha=job.scene.background[3] < 255, draft=job.draft))


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


def tree_mib(fmt: str, pixels: int, processes: int) -> float:
    """Predicted peak memory (MiB) of the whole process tree drawing ``pixels``-pixel frames for ``fmt``
    with ``processes`` > 1 drawing processes: MP4 and WebM as chunks, each process with an encoder of
    its own; PNG and GIF as frames drawn there and written (or encoded) by the command's process."""
    megapixels = pixels / 1e6
    encoder = _ENCODER_MIB_PER_MEGAPIXEL * megapixels
    if TABLE[fmt].chunked:
        return _IDLE_PARENT_MIB + processes * (_PROCESS_MIB + encoder)
    if TABLE[fmt].folder:  # compressed where drawn, written by the command's process
        return _IDLE_PARENT_MIB + processes * _PROCESS_MIB
    return _PROCESS_MIB + encoder + processes * _PROCESS_MIB  # one encoder, fed by the command's process


def memory_budget_mib(pixels: int) -> float:
    """The most the process tree may hold for frames of ``pixels`` when more processes are chosen:
    400 MiB up to 1080p, about 1 GiB at 4K."""
    return _BUDGET_MIB + _BUDGET_MIB_PER_MEGAPIXEL * max(0.0, pixels - _BUDGET_BASE_PIXELS) / 1e6


def choose_workers(cost: Cost, fmt: str, frames: int, frame_bytes: int, cpus: int) -> int:
    """The number of drawing processes predicted fastest (at most ``cpus`` and 8, and within the
    memory budget: :func:`tree_mib` ≤ :func:`memory_budget_mib`), or 1 unless more save at least a
    tenth of the time."""
    pixels = frame_bytes // 4
    alone = predicted_seconds(cost, fmt, frames, frame_bytes, 1, cpus)
    best, best_seconds = 1, alone
    for processes in range(2, min(cpus, 8) + 1):
        if tree_mib(fmt, pixels, processes) > memory_budget_mib(pixels):
            break
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
    where they are drawn, one per core, as far as the memory budget allows.
    Clips too short to repay starting processes, and frames too large for a
    second process to fit the budget, are not measured.
    """
    if cpus is None:
        cpus = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    width, height = job.frame_size
    frames = len(job.frame_range)
    if cpus < 2 or width * height * frames < _MIN_PARALLEL_PIXELS:
        return 1
    if tree_mib(fmt, width * height, 2) > memory_budget_mib(width * height):
        return 1  # no second process fits the memory budget: nothing to measure
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
    if job.tracks is None:  # built once here, not again in every worker
        job = replace(job, tracks=tracks_of(job.scene))
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


