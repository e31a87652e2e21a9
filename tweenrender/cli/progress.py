"""A one-line progress bar on stderr, shown only on a terminal."""

from __future__ import annotations

import sys
import time
from typing import TextIO

from ..errors import printable

__all__ = ["ProgressBar"]


class ProgressBar:
    """Call with ``(done, total)``; redraws at most ten times a second."""

    def __init__(self, label: str, stream: TextIO | None = None, enabled: bool | None = None) -> None:
        self.label = printable(label)
        self.stream = stream or sys.stderr
        self.enabled = self.stream.isatty() if enabled is None else enabled
        self.started = time.monotonic()
        self.last = 0.0

    def __call__(self, done: int, total: int) -> None:
        if not self.enabled:
            return
        now = time.monotonic()
        if done < total and now - self.last < 0.1:
            return
        self.last = now
        elapsed = max(now - self.started, 1e-9)
        width = 28
        filled = int(width * done / max(total, 1))
        bar = "█" * filled + "·" * (width - filled)
        rate = done / elapsed
        left = (total - done) / rate if rate > 0 else 0.0
        self.stream.write(f"\r{self.label} {bar} {done}/{total} frames  {rate:5.1f} fps  {left:4.0f} s left ")
        if done >= total:
            self.stream.write("\n")
        self.stream.flush()
