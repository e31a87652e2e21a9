"""Large ``points = [[x, y], ...]`` arrays of a TOML scene read by numpy instead of ``tomllib``.

``tomllib`` is written in Python: it turns a 2.9 MB scene of 300 000 coordinates into as
many Python objects in about 1.3 s, before any of them is checked. A key's ``points``
array written plainly (decimal numbers, no comment, underscore, ``inf`` or trailing comma
inside it) is lifted out of the text before ``tomllib`` sees it: matched as a whole by
one regular expression of that grammar, parsed by numpy's C number reader, and replaced
by a string naming it, followed by the array's own line breaks, so every line keeps its
number. Any array that does not match exactly is left where it is for ``tomllib`` and the
loader's checks, and so is every coordinate beyond the loader's range (see
``load.parse_scene``, which also reads the original text again on any error, or when a lifted
array was not where a key's ``points`` were read). The numbers are those ``tomllib``
gives: both parse decimal text to the nearest double.
"""

from __future__ import annotations

import re
import secrets

import numpy as np
from numpy.typing import NDArray

__all__ = ["lift_point_arrays", "SMALLEST_LIFTED"]

SMALLEST_LIFTED = 64
"""Fewest pairs in an array worth lifting: below that ``tomllib`` is as quick."""

_NUMBER = r"[+-]?(?:0|[1-9][0-9]{0,30})(?:\.[0-9]{1,40})?(?:[eE][+-]?[0-9]{1,3})?"
_PAIR = rf"\[[ \t]*{_NUMBER}[ \t]*,[ \t]*{_NUMBER}[ \t]*\]"
_ARRAY = re.compile(rf"\[\s*{_PAIR}(?:\s*,\s*{_PAIR})*\s*\]")
_START = re.compile(r"^[ \t]*points[ \t]*=[ \t]*(?=\[[ \t]*\[)", re.MULTILINE)
_REST_OF_LINE = re.compile(r"[ \t]*(?:#[^\n]*)?\r?(?:\n|\Z)")
_SEPARATORS = str.maketrans("[],\n\t", "     ")
_INTEGER_MINUS_ZERO = re.compile(r"-0(?=[\s,\]])")


def lift_point_arrays(text: str, limit: float) -> tuple[str, dict[str, NDArray[np.float64]]]:
    """``text`` with each plainly written ``points`` array of at least :data:`SMALLEST_LIFTED` pairs, every
    coordinate within ``±limit``, replaced by a string, and the arrays ``(N, 2)`` float64 by that string."""
    if text.count("[") < 2 * SMALLEST_LIFTED:
        return text, {}
    nonce = secrets.token_hex(8)
    pieces: list[str] = []
    lifted: dict[str, NDArray[np.float64]] = {}
    done = 0
    for start in _START.finditer(text):
        begin = start.end()
        if begin < done:
            continue
        array = _ARRAY.match(text, begin)
        if array is None or not _REST_OF_LINE.match(text, array.end()):
            continue
        body = text[begin:array.end()]
        values = np.fromstring(body.translate(_SEPARATORS), dtype=np.float64, sep=" ")
        if values.size < 2 * SMALLEST_LIFTED or values.size % 2 or not (np.abs(values) <= limit).all():
            continue
        if _INTEGER_MINUS_ZERO.search(body):  # tomllib reads it as the integer 0 (-0.0 is -0.0 to both): left to it
            continue
        name = f"\x1f{nonce}:{len(lifted)}"
        lifted[name] = values.reshape(-1, 2)
        pieces += [text[done:begin], f'"\\u001f{nonce}:{len(lifted) - 1}"', "\n" * body.count("\n")]
        done = array.end()
    if not lifted:
        return text, {}
    pieces.append(text[done:])
    return "".join(pieces), lifted
