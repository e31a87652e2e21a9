"""Rendering on a dask.distributed cluster: chunks drawn and encoded on its workers, joined here.

Needs the ``cluster`` extra (``pip install "tweenrender[cluster]"``); dask is
imported only inside these functions, so the rest of the package works without it.
The job (scene included) travels inside each task and only the encoded chunks
travel back: the workers need tweenrender installed, not the scene file nor a
shared file system. The output is written where this process runs.
"""

from __future__ import annotations

import contextlib
from concurrent.futures import Executor
from pathlib import Path
from typing import Any, Iterator

from ..errors import OptionError, RenderError
from .job import Progress, RenderJob

__all__ = ["parse_address", "connect", "cluster_chunks", "render_on_cluster"]

_LOCAL_LIMIT = 256
_CHUNKS_PER_WORKER = 4  # several chunks each: a slow chunk does not hold the others up, progress moves
_CONNECT_SECONDS = 20


def parse_address(address: str) -> tuple[str, int | None]:
    """``("local", N)`` for ``local:N`` (a LocalCluster of N processes), else ``(address, None)``."""
    text = str(address).strip()
    if not text:
        raise OptionError("cluster: expected a scheduler address (tcp://host:8786) or local:N")
    if text.lower().startswith("local:") or text.lower() == "local":
        _, _, count = text.partition(":")
        try:
            processes = int(count)
        except ValueError:
            raise OptionError(f"cluster {text!r}: expected local:N with N a whole number of processes") from None
        if not 1 <= processes <= _LOCAL_LIMIT:
            raise OptionError(f"cluster {text!r}: expected local:N with N from 1 to {_LOCAL_LIMIT}")
        return "local", processes
    return text, None


def _distributed() -> Any:
    try:
        import distributed
    except ImportError:
        raise OptionError('cluster: dask.distributed is not installed; install it with '
                          'pip install "tweenrender[cluster]"') from None
    return distributed


@contextlib.contextmanager
def connect(address: str) -> Iterator[tuple[Executor, int]]:
    """A ``concurrent.futures`` executor on the cluster at ``address`` and its capacity (worker threads).

    ``local:N`` starts a LocalCluster of N single-threaded worker processes for
    the occasion (and stops it after); any other address is a running
    scheduler's, e.g. ``tcp://scheduler:8786``.
    """
    distributed = _distributed()
    where, processes = parse_address(address)
    with contextlib.ExitStack() as stack:
        try:
            if processes is not None:
                cluster = stack.enter_context(distributed.LocalCluster(
                    n_workers=processes, threads_per_worker=1, processes=True, dashboard_address=":0"))
                client = stack.enter_context(distributed.Client(cluster))
            else:
                client = stack.enter_context(distributed.Client(where, timeout=f"{_CONNECT_SECONDS}s"))
            client.wait_for_workers(1, timeout=_CONNECT_SECONDS)
        except (OSError, TimeoutError) as error:
            raise RenderError(f"cluster {address}: cannot reach a scheduler with workers ({error})") from None
        capacity = sum(client.nthreads().values())
        yield client.get_executor(), max(capacity, 1)


def cluster_chunks(frames: int, capacity: int) -> int:
    """How many chunks to cut ``frames`` frames into for ``capacity`` workers: a few per worker,
    never fewer frames than a second or so (at 24 fps) in a chunk, never fewer chunks than workers."""
    return max(1, min(frames, max(capacity, min(_CHUNKS_PER_WORKER * capacity, frames // 24))))


def render_on_cluster(job: RenderJob, fmt: str, target: Path, address: str,
                      progress: Progress | None = None) -> Path:
    """Render ``job`` into ``target`` as ``fmt`` on the cluster at ``address`` (see :func:`connect`).

    Chunks are drawn and encoded on the cluster's workers and joined here
    (:func:`.chunks.render_chunks`); ``target`` changes only if every chunk and the join succeeded.
    """
    from .chunks import part_format, render_chunks

    part_format(fmt)  # an unknown format is refused before any cluster starts
    with connect(address) as (executor, capacity):
        chunks = cluster_chunks(len(job.frame_range), capacity)
        return render_chunks(job, fmt, Path(target), executor, chunks, progress)
