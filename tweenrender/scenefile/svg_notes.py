"""What the SVG reader skipped by SVG's error rules (path data after its first error, a shape of negative
size, a ``<use>`` of nothing …), said once a drawing: a warning of the ``tweenrender`` logger, which the
command line shows with ``-v`` only (the package's own handler says nothing)."""

from __future__ import annotations

import logging
from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from pathlib import Path

__all__ = ["MAX_NOTES", "note", "noting"]

MAX_NOTES = 8
"""Notes said of one drawing; more are counted."""

_NOTES: ContextVar[list[str] | None] = ContextVar("svg_notes", default=None)
_LOG = logging.getLogger("tweenrender")
_LOG.addHandler(logging.NullHandler())


def note(text: str) -> None:
    """Notes ``text`` for the drawing being read (once; nothing when no drawing is being read)."""
    notes = _NOTES.get()
    if notes is not None and text not in notes:
        notes.append(text)


@contextmanager
def noting(path: Path) -> Iterator[None]:
    """Reads a drawing at ``path`` within: what was skipped is said in one warning when it is done."""
    token = _NOTES.set([])
    try:
        yield
        notes = _NOTES.get() or []
        if notes:
            more = f"; and {len(notes) - MAX_NOTES} more" if len(notes) > MAX_NOTES else ""
            _LOG.warning("%s: drew what is valid, skipped %s%s", path.name, "; ".join(notes[:MAX_NOTES]), more)
    finally:
        _NOTES.reset(token)
