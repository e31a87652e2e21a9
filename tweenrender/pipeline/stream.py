"""One output file from a job: frames drawn (here or on workers) and streamed into a sink."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable, Iterable

from ..plan.job import Progress, RenderJob
from .workers import frame_stream

if TYPE_CHECKING:
    from concurrent.futures import Executor

    from ..encode.sinks import Sink

__all__ = ["render", "stream_into"]


def render(job: RenderJob, fmt: str, target: Path, progress: Progress | None = None,
           executor: Executor | None = None, workers: int = 1) -> Path:
    """Render ``job`` into ``target`` as ``fmt``; the target changes only if everything succeeded.

    Frames stream one at a time into the sink, so memory does not grow with the
    clip. They are drawn here, on ``executor`` (any
    ``concurrent.futures.Executor``, whose capacity ``workers`` gives), or on
    ``workers`` processes started for the occasion, and written in order; PNG
    frames drawn elsewhere are compressed there too.
    (:func:`.chunks.render_in_processes` renders a video in chunks instead.)
    """
    from ..encode import open_sink
    from ..encode.formats import TABLE
    from ..encode.sinks import png_bytes

    indices = job.frame_range
    width, height = job.frame_size
    here = executor is None and workers <= 1
    # Over an opaque background premultiplied pixels are straight ones: a video
    # sink can take skia's own BGRA surface without a copy (MP4 and WebM turn it
    # into yuv420p planes, encode.yuv420; the other formats send it as it is).
    folder = TABLE[fmt].folder
    layout = "bgra" if here and not folder and job.scene.background[3] == 255 else "rgba"
    sink = open_sink(fmt, target, width, height, job.rate, len(indices), pixel_format=layout,
                     alpha=job.scene.background[3] < 255, draft=job.draft)
    elsewhere = folder and not here
    stream = frame_stream(job, executor, workers, encode=png_bytes if elsewhere else None, layout=layout)
    write = sink.write_encoded if elsewhere else sink.write  # type: ignore[attr-defined]
    try:
        return stream_into(sink, stream, len(indices), progress, write)
    finally:
        stream.close()  # now, not when the traceback lets go: stops a pool of workers at once


def stream_into(sink: Sink, pictures: Iterable[Any], total: int, progress: Progress | None = None,
                write: Callable[[Any], None] | None = None) -> Path:
    """Hand every picture to ``sink`` (through ``write``, default ``sink.write``), report progress,
    and close it; on any failure the sink is aborted, so its target stays as it was."""
    write = write or sink.write
    try:
        for done, picture in enumerate(pictures, start=1):
            write(picture)
            if progress is not None:
                progress(done, total)
        return sink.close()
    except BaseException:
        sink.abort()
        raise
