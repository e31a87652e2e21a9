"""Rendering on a dask.distributed cluster: chunks drawn and encoded on its workers, joined here.

Needs the ``cluster`` extra (``pip install "tweenrender[cluster]"``); dask is
imported only inside these functions, so the rest of the package works without it.
The job (scene included) travels inside each task and only the encoded chunks
travel back: the workers need tweenrender installed, not the scene file nor a
shared file system. The output is written where this process runs.
"""

from __future__ import annotations

import contextlib
import ipaddress
import os
import re
from concurrent.futures import Executor
from pathlib import Path
from typing import Any, Iterator

from ..errors import OptionError, RenderError, printable
from .job import Progress, RenderJob

__all__ = ["parse_address", "probe", "connect", "cluster_chunks", "render_on_cluster"]

_LOCAL_LIMIT = 256
_CHUNKS_PER_WORKER = 4  # several chunks each: a slow chunk does not hold the others up, progress moves
_CONNECT_SECONDS = 10


_EXPECTED = "expected tcp://HOST:PORT (a dask scheduler's address) or local:N"
_DEFAULT_PORT = 8786
_HOST = re.compile(r"[A-Za-z0-9](?:[A-Za-z0-9._-]*[A-Za-z0-9])?")
_OTHER_SCHEMES = {
    "tls": "tls:// needs certificates, which tweenrender does not take: reach the scheduler over tcp:// "
           "in a private network or through an SSH tunnel",
    "inproc": "inproc:// reaches only a scheduler inside this very process",
    "ucx": "ucx:// needs the UCX libraries and their dask extra, which tweenrender does not support",
}


def _refuse(text: str, problem: str) -> OptionError:
    return OptionError(f"{_EXPECTED}, found {printable(repr(text))}: {problem}", "cluster")


def parse_address(address: str) -> tuple[str, int | None]:
    """``("local", N)`` for ``local:N`` (a LocalCluster of N processes), else ``("tcp://HOST:PORT", None)``.

    Only what can work is taken: ``tcp://`` (or no scheme, with a port), a host name or an IP
    address (IPv6 in brackets), a port from 1 to 65535 (8786, dask's, when a ``tcp://`` address
    has none). Anything else is an :class:`OptionError` before any connection is tried.
    """
    text = str(address).strip()
    if not text:
        raise OptionError(f"{_EXPECTED}, found an empty address", "cluster")
    if text.lower().startswith("local:") or text.lower() == "local":
        _, _, count = text.partition(":")
        try:
            processes = int(count)
        except ValueError:
            raise OptionError(f"expected local:N with N a whole number of processes, found {printable(repr(text))}",
                              "cluster") from None
        if not 1 <= processes <= _LOCAL_LIMIT:
            raise OptionError(f"expected local:N with N from 1 to {_LOCAL_LIMIT}, found {printable(repr(text))}",
                              "cluster")
        return "local", processes
    scheme, separator, rest = text.partition("://")
    if not separator:
        scheme, rest = "tcp", text
    scheme = scheme.lower()
    if scheme != "tcp":
        reason = _OTHER_SCHEMES.get(scheme, "a scheme dask's schedulers do not speak")
        raise _refuse(text, f"the {scheme}:// scheme ({reason})")
    if rest.startswith("["):
        close = rest.find("]")
        if close < 0:
            raise _refuse(text, "an IPv6 address without its closing ]")
        host, after = rest[1:close], rest[close + 1:]
        try:
            ipaddress.IPv6Address(host)
        except ValueError:
            raise _refuse(text, f"{printable(repr(host))}, not an IPv6 address") from None
        shown = f"[{host}]"
        if after and not after.startswith(":"):
            raise _refuse(text, f"{printable(repr(after))} after the address")
        port_text = after[1:] if after else None
    else:
        if rest.count(":") > 1:
            raise _refuse(text, "an IPv6 address without brackets (write tcp://[ADDRESS]:PORT)")
        host, colon, port_text_found = rest.partition(":")
        port_text = port_text_found if colon else None
        if not host:
            raise _refuse(text, "no host")
        if not _HOST.fullmatch(host):
            raise _refuse(text, f"the host {printable(repr(host))} (letters, digits, dots and hyphens only)")
        shown = host
    if port_text is None:
        if not separator:
            raise _refuse(text, "no scheme and no port")
        port = _DEFAULT_PORT
    else:
        if not port_text.isascii() or not port_text.isdigit():
            raise _refuse(text, f"the port {printable(repr(port_text))}, not a number")
        port = int(port_text)
        if not 1 <= port <= 65535:
            raise _refuse(text, f"port {port} (ports run from 1 to 65535)")
    return f"tcp://{shown}:{port}", None


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
