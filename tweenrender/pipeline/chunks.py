"""Chunks of a clip rendered apart (on any ``concurrent.futures.Executor``) and joined without re-encoding."""

from __future__ import annotations

import tempfile
from concurrent.futures import Executor
from dataclasses import replace
from pathlib import Path

from ..errors import EncodeError, OptionError
from .job import RenderJob
from .workers import split_range

__all__ = ["render_part", "render_chunks"]


def render_part(job: RenderJob, fmt: str) -> bytes:
    """Render ``job`` (typically a ``frames`` chunk) to a ``fmt`` file where this runs; its bytes.

    Meant to run on an executor's worker: only the encoded part travels back.
    """
    from .stream import render

    with tempfile.TemporaryDirectory(prefix="tweenrender-part-") as folder:
        path = Path(folder) / f"part.{fmt}"
        render(job, fmt, path)
        return path.read_bytes()


def render_chunks(job: RenderJob, fmt: str, target: Path, executor: Executor, chunks: int) -> Path:
    """Render ``job`` as ``chunks`` parts on ``executor`` and join them into ``target`` without re-encoding.

    Parts are written beside ``target`` as hidden temporaries and removed after
    the join; ``target`` changes only if every part and the join succeeded.
    """
    from ..encode.atomic import discard, prepare_folder, sibling
    from ..encode.concat import CONCAT_FORMATS, concat

    if fmt not in CONCAT_FORMATS:
        raise OptionError(f"chunks can be joined for {' or '.join(CONCAT_FORMATS)} only, not {fmt}")
    target = Path(target)
    prepare_folder(target)
    ranges = split_range(job.frame_range, chunks)
    futures = [executor.submit(render_part, replace(job, frames=r), fmt) for r in ranges]
    parts: list[Path] = []
    try:
        for future in futures:
            part = sibling(target, f".{len(parts):04d}.{fmt}")
            parts.append(part)
            try:
                part.write_bytes(future.result())
            except OSError as error:
                raise EncodeError(f"{target}: cannot write part {len(parts)} beside it ({error.strerror or error})") \
                    from None
        return concat(parts, target, expected=len(job.frame_range))
    finally:
        for future in futures:
            future.cancel()
        for part in parts:
            discard(part)
