"""Find the line of a key path (``shape[1].key[0].points``) in a TOML scene's text.

tomllib keeps no positions, so the locator walks the table headers the way a
reader would: ``[[shape]]`` opens the next shape, ``[[shape.key]]`` the next key
of that shape. It finds what a conventional file holds; for anything it cannot
place (inline tables, arrays of tables written inline) it answers ``None``.
"""

from __future__ import annotations

import re

__all__ = ["line_of"]

_HEADER = re.compile(r"^\s*(\[\[?)\s*([A-Za-z0-9_.\-\" ]+?)\s*\]\]?\s*(#.*)?$")
_KEY = re.compile(r"^\s*([A-Za-z0-9_\-]+|\"[^\"]*\")\s*=")
_STEP = re.compile(r"([A-Za-z0-9_\-]+)(?:\[(\d+)\])?")


def _parse_path(path: str) -> list[tuple[str, int | None]]:
    return [(m.group(1), None if m.group(2) is None else int(m.group(2)))
            for m in _STEP.finditer(path)]


def line_of(text: str, path: str) -> int | None:
    """1-based line where ``path`` is set in TOML ``text``, or ``None`` if it cannot be placed."""
    steps = _parse_path(path)
    if not steps:
        return None
    counters: dict[tuple[object, str], int] = {}
    table: list[tuple[str, int | None]] = []  # the table the current line belongs to
    best: int | None = None
    for number, line in enumerate(text.splitlines(), start=1):
        header = _HEADER.match(line)
        if header:
            names = [n.strip().strip('"') for n in header.group(2).split(".")]
            if header.group(1) == "[[":
                parent = tuple(s for s in table[: len(names) - 1])
                # keyed by the parent's own index, so [[shape.key]] restarts in every shape
                key = (parent, names[-1])
                counters[key] = counters.get(key, -1) + 1
                table = list(parent) + [(names[-1], counters[key])]
            else:
                # [shape.key] under [[shape]] belongs to the latest shape: inherit its index
                table = [(n, table[i][1] if i < len(table) and table[i][0] == n else None)
                         for i, n in enumerate(names)]
            if _matches(table, steps):
                best = number
            continue
        key = _KEY.match(line)
        # an index on the last step points into the key's value: the key's line holds it
        if key and _matches(table + [(key.group(1).strip('"'), None)], steps[:-1] + [(steps[-1][0], None)]):
            return number
    return best


def _matches(table: list[tuple[str, int | None]], steps: list[tuple[str, int | None]]) -> bool:
    """Whether ``table`` is ``steps`` (an index-free step matches a plain table)."""
    if len(table) != len(steps):
        return False
    return all(n == s and (si is None or ti == si) for (n, ti), (s, si) in zip(table, steps))
