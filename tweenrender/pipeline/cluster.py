"""Rendering on a dask.distributed cluster: chunks drawn and encoded on its workers, joined here.

Needs the ``cluster`` extra (``pip install "tweenrender[cluster]"``); dask is
imported only inside these functions, so the rest of the package works without it.
The job (scene included) travels inside each task and only the encoded chunks
travel back: the workers need tweenrender installed, not the scene file nor a
shared file system. The output is written where this process runs.
"""

from __future__ import annotations

import contextlib
import os
from concurrent.futures import Executor
from pathlib import Path
from typing import Any, Iterator

from ..errors import OptionError, RenderError, printable
from ..plan.cluster_address import parse_address
from ..plan.job import Progress, RenderJob

__all__ = ["parse_address", "probe", "connect", "cluster_chunks", "render_on_cluster"]

_CHUNKS_PER_WORKER = 4  # several chunks each: a slow chunk does not hold the others up, progress moves
_CONNECT_SECONDS = 10


def _distributed() -> Any:
    try:
        import distributed
    except ImportError:
        raise OptionError('cluster: dask.distributed is not installed; install it with '
                          'pip install "tweenrender[cluster]"') from None
    return distributed


def probe(address: str, seconds: float = _CONNECT_SECONDS) -> None:
    """Refuse ``tcp://HOST:PORT`` unless a dask scheduler answers there: one that listens speaks first
    (its handshake, a message length in 8 bytes); an HTTP server or anything else that waits for a
    request says nothing, and is refused after ``seconds`` rather than waited on for ever."""
    import socket

    rest = address.removeprefix("tcp://")
    host, _, port = rest.rpartition(":")
    host = host.strip("[]")
    connected = False
    try:
        with socket.create_connection((host, int(port)), timeout=seconds) as connection:
            connected = True
            connection.settimeout(seconds)
            first = b""
            while len(first) < 8:
                piece = connection.recv(8 - len(first))
                if not piece:
                    break
                first += piece
    except ConnectionRefusedError:
        raise RenderError(f"cluster {address}: nothing listens there (connection refused)") from None
    except socket.gaierror as error:
        raise RenderError(f"cluster {address}: no such host ({error.strerror or error})") from None
    except TimeoutError:
        if connected:
            raise RenderError(f"cluster {address}: something listens there but says nothing within {seconds:g} s: "
                              "not a dask scheduler (an HTTP server?)") from None
        raise RenderError(f"cluster {address}: no answer within {seconds:g} s (no such machine, or a firewall)") \
            from None
    except OSError as error:
        raise RenderError(f"cluster {address}: cannot connect ({error.strerror or error})") from None
    length = int.from_bytes(first.ljust(8, b"\0"), "little")
    if len(first) < 8 or not 0 < length < 1 << 20:
        raise RenderError(f"cluster {address}: what listens there is not a dask scheduler (it answered "
                          f"{printable(repr(first[:8]))})")


@contextlib.contextmanager
def _quiet_dask() -> Iterator[None]:
    """dask's own log lines (worker restarts, lost connections when the render is stopped) kept off
    stderr, in this process and in the worker processes it starts; a failure is still one line of ours."""
    import logging

    names = ("distributed", "tornado")
    levels = {name: logging.getLogger(name).level for name in names}
    variable = "DASK_LOGGING__DISTRIBUTED"
    before = os.environ.get(variable)
    os.environ[variable] = "critical"
    for name in names:
        logging.getLogger(name).setLevel(logging.CRITICAL + 1)
    try:
        yield
    finally:
        for name, level in levels.items():
            logging.getLogger(name).setLevel(level)
        if before is None:
            os.environ.pop(variable, None)
        else:
            os.environ[variable] = before


@contextlib.contextmanager
def connect(address: str) -> Iterator[tuple[Executor, int]]:
    """A ``concurrent.futures`` executor on the cluster at ``address`` and its capacity (worker threads).

    ``local:N`` starts a LocalCluster of N single-threaded worker processes for
    the occasion (and stops it after), its scratch space in a folder of this run
    (:func:`.chunks.run_folder`); any other address is a running scheduler's, e.g.
    ``tcp://scheduler:8786``, checked by :func:`probe` before dask connects.
    """
    from .chunks import run_folder, sweep_parts

    where, processes = parse_address(address)
    distributed = _distributed()
    sweep_parts()
    try:
        with contextlib.ExitStack() as stack:
            stack.enter_context(_quiet_dask())
            try:
                if processes is not None:
                    scratch = stack.enter_context(run_folder("dask"))
                    with _workers_leave_ctrl_c_to_us():
                        cluster = stack.enter_context(distributed.LocalCluster(
                            n_workers=processes, threads_per_worker=1, processes=True, dashboard_address=":0",
                            local_directory=str(scratch)))
                    client = stack.enter_context(distributed.Client(cluster))
                else:
                    probe(where)
                    client = stack.enter_context(distributed.Client(where, timeout=f"{_CONNECT_SECONDS}s"))
                client.wait_for_workers(1, timeout=_CONNECT_SECONDS)
            except (OSError, TimeoutError) as error:
                raise RenderError(f"cluster {address}: cannot reach a scheduler with workers ({error})") from None
            capacity = sum(client.nthreads().values())
            yield client.get_executor(), max(capacity, 1)
    finally:
        if processes is not None:
            sweep_parts(own=True)  # the local workers are stopped: what a stopped one left is removable


@contextlib.contextmanager
def _workers_leave_ctrl_c_to_us() -> Iterator[None]:
    """Start local workers with SIGINT ignored (a started Python keeps it so), as the drawing processes
    of ``--workers`` are: Ctrl-C reaches the whole process group, and only this process answers it."""
    import signal

    try:
        previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    except ValueError:  # not the main thread: signals are not ours to change
        yield
        return
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)


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
