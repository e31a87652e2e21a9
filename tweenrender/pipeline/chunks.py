"""Chunks of a clip rendered apart (on any ``concurrent.futures.Executor``) and joined into one output.

Each chunk is a ``frames`` range of the job, rendered where the executor runs
it; only its encoded result travels back:

- a video part joined by stream copy (MP4, WebM: each part starts on a key frame);
- a lossless part (FFV1), the whole output encoded once at the join (a GIF, so its
  palette sees every frame and the file is the single render's, byte for byte);
- the frames' PNG bytes, written in order into the target folder (PNG frames).

Which one is each format's :attr:`~tweenrender.encode.formats.Format.join`.
"""

from __future__ import annotations

import contextlib
import os
from concurrent.futures import Executor, Future
from dataclasses import replace
from pathlib import Path
from typing import Any, Iterator

from ..encode.formats import TABLE
from ..errors import EncodeError
from ..plan.job import Progress, RenderJob
from .workers import draw_frame, split_range

__all__ = ["render_part", "render_chunks", "part_format", "render_in_processes"]


def part_format(fmt: str) -> str:
    """The format a chunk of a ``fmt`` output is rendered in (its own, or the lossless one its join encodes)."""
    from ..encode.formats import LOSSLESS, lookup

    return LOSSLESS.name if lookup(fmt).join == "lossless" else fmt


def sweep_parts(own: bool = False) -> None:
    """Remove the temporary folders of runs that no longer run (killed with their workers before these
    could clean up); with ``own``, this process's too (once its workers are stopped)."""
    from ..encode.scratch import sweep_scratch

    sweep_scratch(own)


@contextlib.contextmanager
def run_folder(what: str) -> Iterator[Path]:
    """A temporary folder for this run's ``what`` (see :mod:`..encode.scratch`), removed afterwards; a run
    killed before that leaves it to the next run's sweep."""
    from ..encode.scratch import scratch_folder

    with scratch_folder(what) as folder:
        yield folder


def render_part(job: RenderJob, fmt: str) -> Any:
    """Render ``job`` (typically a ``frames`` chunk) for a ``fmt`` output where this runs.

    Returns a video part's bytes, or for a folder of frames the list of each frame's PNG bytes. Meant
    to run on an executor's worker, whose files it does not keep.
    """
    from ..encode.lifeline import Stopped, stoppable
    from ..encode.sinks import png_bytes
    from .frames import Frames
    from .stream import render

    try:
        with stoppable():
            if TABLE[fmt].folder:
                frames = Frames(job)
                return [png_bytes(draw_frame(frames, index)) for index in job.frame_range]
            from ..encode.scratch import scratch_folder

            sweep_parts()  # on a worker machine, those of renders killed there before
            # owned by the process that started this worker: when it ends, the folder is anyone's to remove
            with scratch_folder("part", owner=os.getppid()) as folder:
                path = folder / f"part.{fmt}"
                render(job, fmt, path)
                return path.read_bytes()
    except Stopped as stop:  # the part, its folder and its encoder are gone by now: end the worker
        os._exit(stop.code if isinstance(stop.code, int) else 1)


def render_chunks(job: RenderJob, fmt: str, target: Path, executor: Executor, chunks: int,
                  progress: Progress | None = None) -> Path:
    """Render ``job`` as ``chunks`` parts on ``executor`` and join them into ``target`` as ``fmt``.

    Parts are submitted at once and joined in order; ``progress`` hears of
    each part's frames as it arrives. Video parts are written to a folder among
    the run's temporaries (:mod:`..encode.scratch`) and removed after the join;
    ``target`` changes only if every part and the join succeeded.
    """
    target = Path(target)
    kind = part_format(fmt)
    ranges = split_range(job.frame_range, chunks)
    futures = [executor.submit(render_part, replace(job, frames=r), kind) for r in ranges]
    try:
        if TABLE[fmt].folder:
            return _join_frames(job, fmt, target, futures, progress)
        return _join_videos(job, fmt, kind, target, futures, [len(r) for r in ranges], progress)
    finally:
        for future in futures:
            future.cancel()


def render_in_processes(job: RenderJob, fmt: str, target: Path, workers: int,
                        progress: Progress | None = None) -> Path:
    """Render ``job`` with ``workers`` processes: a format rendered in chunks (:attr:`.formats.Format.chunked`,
    MP4 and WebM) as that many chunks, each drawn and encoded by a process of its own and joined by
    stream copy (no frame travels between processes); others (PNG frames, GIF) as frames drawn in the
    processes and written here in order."""
    from .stream import render

    if workers <= 1 or not TABLE[fmt].chunked:
        return render(job, fmt, target, progress, workers=workers)
    from concurrent.futures import ProcessPoolExecutor

    from ..encode.lifeline import part_worker_setup

    sweep_parts()
    # found (and checked by running it) once here, not by each worker: a worker should not fork
    # but to start the encoder (see encode.lifeline.start_program)
    from ..encode.sinks import ffmpeg_exe

    ffmpeg_exe()
    with ProcessPoolExecutor(max_workers=workers, initializer=part_worker_setup, initargs=(os.getpid(),)) as pool:
        try:
            return render_chunks(job, fmt, target, pool, chunks=workers, progress=progress)
        except BaseException:
            # a chunk runs for long: stop the workers now (each aborts its part, ffmpeg included)
            # rather than wait for their chunks to finish
            _stop_workers(pool)
            pool.shutdown(wait=True, cancel_futures=True)
            sweep_parts(own=True)  # the workers are stopped: what a stopped one left is removable
            raise


def _stop_workers(pool: Any) -> None:
    """SIGTERM to every worker process of a ``ProcessPoolExecutor``."""
    terminate = getattr(pool, "terminate_workers", None)  # Python 3.14
    if terminate is not None:
        terminate()
        return
    for process in list((getattr(pool, "_processes", None) or {}).values()):  # earlier Pythons: no public way
        if process.is_alive():
            process.terminate()


def _join_frames(job: RenderJob, fmt: str, target: Path, futures: list[Future[Any]], progress: Progress | None) -> Path:
    from ..encode import open_sink

    from .stream import stream_into

    width, height = job.frame_size
    total = len(job.frame_range)
    sink = open_sink(fmt, target, width, height, job.rate, total)
    pictures = (data for future in futures for data in future.result())  # each part's PNG bytes, in order
    return stream_into(sink, pictures, total, progress, sink.write_encoded)  # type: ignore[attr-defined]


def _join_videos(job: RenderJob, fmt: str, kind: str, target: Path, futures: list[Future[Any]],
                 sizes: list[int], progress: Progress | None) -> Path:
    from ..encode.atomic import os_reason, prepare_folder
    from ..encode.concat import concat

    prepare_folder(target)
    total = len(job.frame_range)
    parts: list[Path] = []
    with run_folder("parts") as folder:  # with every temporary folder: a killed run's is swept by the next
        done = 0
        for future, size in zip(futures, sizes):
            part = folder / f"{len(parts):04d}.{kind}"
            parts.append(part)
            data = future.result()
            try:
                part.write_bytes(data)
            except OSError as error:
                raise EncodeError(f"{target}: cannot write part {len(parts)} in {folder.parent} "
                                  f"({os_reason(error)})") from None
            done += size
            if progress is not None:
                progress(done, total)
        return concat(parts, target, expected=total, fmt=fmt, rate=job.rate,
                      alpha=job.scene.background[3] < 255)
