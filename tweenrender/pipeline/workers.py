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
from typing import Any, Callable, Iterator, Sequence

import numpy as np
from numpy.typing import NDArray

from ..errors import RenderError
from .job import Frames, RenderJob

__all__ = ["frame_stream", "draw_frame", "default_workers", "split_range"]

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


def default_workers(job: RenderJob, fmt: str, cpus: int | None = None) -> int:
    """How many processes to draw ``job``'s frames for ``fmt``: 1 unless it pays.

    Video encoders (x264, VP9, ffmpeg's GIF palette) already keep every core
    busy and drawing a frame costs a fraction of encoding it, so a video gets
    one drawing process whatever its size. PNG frames are compressed where they
    are drawn, which costs several times the drawing, so a PNG render of more
    than a second or so of 1080p gets one process per core (at most 8).
    """
    if cpus is None:
        cpus = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    width, height = job.frame_size
    pixels = width * height * len(job.frame_range)
    if fmt != "png" or cpus < 2 or pixels < _MIN_PARALLEL_PIXELS:
        return 1
    return min(cpus, 8)


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
    at most two batches per worker in flight, each frame passed through
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
    ahead = 2 * max(workers, getattr(executor, "_max_workers", 0) or 0, 1)
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


