"""One error hierarchy: every refusal is a :class:`TweenrenderError`, whose message is the line the CLI prints.

::

    TweenrenderError                 exit code 1 unless the subclass says otherwise
    ├── SceneError(path, where)      bad input in a scene file or a drawing (exit 2)
    ├── OptionError                  an option a call cannot honour: format, size, frames (exit 2)
    │   └── UsageError               bad command-line usage; raised by ``tweenrender.cli`` only
    ├── GeometryError (ValueError)   keys or arguments the core cannot work with (exit 2)
    ├── RenderError                  a failure while computing or drawing frames (exit 1)
    └── EncodeError                  a failure while writing an output (exit 1)
"""

from __future__ import annotations

import unicodedata
from pathlib import Path
from typing import Iterable

__all__ = ["TweenrenderError", "SceneError", "OptionError", "UsageError", "GeometryError", "RenderError",
           "EncodeError", "printable", "did_you_mean"]

# control characters (newlines, carriage returns, ESC, C1), lone surrogates, line and paragraph separators
_UNPRINTABLE = frozenset(("Cc", "Cs", "Zl", "Zp"))


def printable(text: str) -> str:
    """``text`` from outside (a scene's names, a file name) made safe for one line on a terminal:
    control characters, lone surrogates and line separators become Python escapes (``\\n``,
    ``\\x1b``, ``\\ud800``); everything else, accents and emoji included, is kept."""
    if text.isprintable():
        return text
    return "".join(repr(c)[1:-1] if unicodedata.category(c) in _UNPRINTABLE else c for c in text)


class TweenrenderError(Exception):
    """Base of every error tweenrender raises on purpose; ``exit_code`` is what the CLI returns."""

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

    def __reduce__(self) -> tuple[type[SceneError], tuple[str | None, str | None, str]]:
        return type(self), (self.path, self.where, self.message)


def did_you_mean(word: str, choices: Iterable[str]) -> str:
    """`` (did you mean 'x'?)`` for the choice closest to a misspelt ``word``, or ``""`` when none is close."""
    import difflib

    close = difflib.get_close_matches(str(word), list(choices), n=1, cutoff=0.6)
    return f" (did you mean {close[0]!r}?)" if close else ""


class OptionError(TweenrenderError):
    """An option a library call cannot honour (an unknown format, an odd size for H.264, no frames).

    ``option`` is the option's long name (``"fps"``) when one option is at fault: the library's
    message names it as the keyword argument (``fps=: …``), the command line as the flag
    (``--fps: …``); see :meth:`for_flag`.
    """

    exit_code = 2

    def __init__(self, message: str, option: str | None = None) -> None:
        self.message = message
        self.option = option
        super().__init__(str(self))

    def __str__(self) -> str:
        return f"{self.option}=: {self.message}" if self.option else self.message

    def for_flag(self) -> str:
        """The message as the command line says it: the option named as its flag."""
        return f"--{self.option.replace('_', '-')}: {self.message}" if self.option else self.message

    def __reduce__(self) -> tuple[type[OptionError], tuple[str, str | None]]:
        return type(self), (self.message, self.option)


class UsageError(OptionError):
    """Bad command-line usage (a flag's value, an impossible combination); raised by the CLI only."""


class GeometryError(TweenrenderError, ValueError):
    """Keys or arguments the interpolation core cannot work with (wrong shapes, bad joints, unknown names)."""

    exit_code = 2


class RenderError(TweenrenderError):
    """A failure while computing or drawing frames."""


class EncodeError(TweenrenderError):
    """A failure while writing an output (ffmpeg's own text included)."""
