"""One error hierarchy; the CLI turns each into a one-line message and an exit code."""

from __future__ import annotations

from pathlib import Path

__all__ = ["TweenrenderError", "SceneError", "UsageError", "RenderError", "EncodeError"]


class TweenrenderError(Exception):
    """Base of every error tweenrender raises on purpose."""

    exit_code: int = 1


class SceneError(TweenrenderError):
    """Bad input in a scene (or a file it refers to).

    ``where`` is a line (``"line 12"``) or a key path (``"shape[1].key[0].points"``),
    possibly both (``"shape[1].key[0].points (line 12)"``).
    """

    exit_code = 2

    def __init__(self, path: str | Path | None, where: str | None, message: str) -> None:
        self.path = None if path is None else str(path)
        self.where = where
        self.message = message
        super().__init__(str(self))

    def __str__(self) -> str:
        place = ": ".join(p for p in (self.path, self.where) if p)
        return f"{place}: {self.message}" if place else self.message


class UsageError(TweenrenderError):
    """Bad command-line usage (a flag's value, an impossible combination)."""

    exit_code = 2


class RenderError(TweenrenderError):
    """A failure while computing or drawing frames."""


class EncodeError(TweenrenderError):
    """A failure while writing an output (ffmpeg's own text included)."""
