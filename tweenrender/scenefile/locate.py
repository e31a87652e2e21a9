"""Find the line of a key path (``shape[1].key[0].points``) in a TOML or JSON scene's text.

tomllib keeps no positions, so the locator walks the table headers the way a
reader would: ``[[shape]]`` opens the next shape, ``[[shape.key]]`` the next key
of that shape. It finds what a conventional file holds; for anything it cannot
place (inline tables, arrays of tables written inline) it answers ``None``.
JSON is walked along the path with the json module's own scanner.
"""

from __future__ import annotations

import json
import re

__all__ = ["line_of", "json_line_of"]

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


_SPACE = re.compile(r"[ \t\n\r]*")
_DECODER = json.JSONDecoder()


def json_line_of(text: str, path: str) -> int | None:
    """1-based line where ``path``'s value (or, for a key the document lacks, its object) starts in JSON ``text``."""
    try:
        return _json_line(text, _parse_path(path))
    except (ValueError, IndexError, RecursionError):
        return None


def _json_line(text: str, steps: list[tuple[str, int | None]]) -> int | None:
    at = _SPACE.match(text, 0).end()  # type: ignore[union-attr]
    hops: list[str | int] = []
    for name, index in steps:
        hops.append(name)
        if index is not None:
            hops.append(index)
    for hop in hops:
        found = _json_child(text, at, hop)
        if found is None:
            break
        at = found
    return text.count("\n", 0, at) + 1


def _json_child(text: str, at: int, hop: str | int) -> int | None:
    """Where the value of key or index ``hop`` starts in the object or array at ``at``, or None."""
    opening = text[at]
    if (opening == "{") != isinstance(hop, str) or opening not in "{[":
        return None
    at = _SPACE.match(text, at + 1).end()  # type: ignore[union-attr]
    count = 0
    while text[at] not in "}]":
        if opening == "{":
            key, at = json.decoder.scanstring(text, at + 1)
            at = _SPACE.match(text, at).end() + 1  # type: ignore[union-attr]  # past the colon
            at = _SPACE.match(text, at).end()  # type: ignore[union-attr]
            if key == hop:
                return at
        elif count == hop:
            return at
        _, at = _DECODER.raw_decode(text, at)
        at = _SPACE.match(text, at).end()  # type: ignore[union-attr]
        if text[at] == ",":
            at = _SPACE.match(text, at + 1).end()  # type: ignore[union-attr]
        count += 1
    return None
