"""The rules of a ``<style>`` sheet, found in one pass: each character is read a bounded number of times.

A regular expression such as ``([^{}]+)\\{([^{}]*)\\}`` restarts its search at every character of a
long run without braces, and ``/\\*.*?\\*/`` at every unclosed ``/*``: both are quadratic in the
sheet's length. This scanner only moves forward with ``str.find``.
"""

from __future__ import annotations

from typing import Iterator

__all__ = ["strip_comments", "style_rules"]


def strip_comments(text: str) -> str:
    """``text`` without its ``/* … */`` comments (``text`` itself when it has none); a comment never
    closed runs to the end, as in CSS."""
    start = text.find("/*")
    if start < 0:
        return text
    pieces = []
    at = 0
    while start >= 0:
        pieces.append(text[at:start])
        end = text.find("*/", start + 2)
        if end < 0:
            return "".join(pieces)
        at = end + 2
        start = text.find("/*", at)
    pieces.append(text[at:])
    return "".join(pieces)


def _braces(text: str) -> Iterator[int]:
    """The index of every ``{`` and ``}`` of ``text`` in order; each character is searched once per brace."""
    size = len(text)
    opening, closing = text.find("{"), text.find("}")
    opening, closing = (size if opening < 0 else opening), (size if closing < 0 else closing)
    while opening < size or closing < size:
        if opening < closing:
            yield opening
            found = text.find("{", opening + 1)
            opening = size if found < 0 else found
        else:
            yield closing
            found = text.find("}", closing + 1)
            closing = size if found < 0 else found


def style_rules(text: str) -> list[tuple[str, str]]:
    """``(selectors, declarations)`` of every rule ``selectors { declarations }`` whose parts hold no
    brace, in order (what ``re.findall(r"([^{}]+)\\{([^{}]*)\\}", …)`` finds): a rule nested in an
    at-rule is found, the at-rule's own prelude is not."""
    text = strip_comments(text)
    rules = []
    braces = _braces(text)
    segment = 0  # where the text after the last brace begins
    pending = next(braces, None)
    while pending is not None:
        following = next(braces, None)
        if text[pending] == "{" and pending > segment and following is not None and text[following] == "}":
            rules.append((text[segment:pending], text[pending + 1:following]))
            segment = following + 1
            pending = next(braces, None)
        else:
            segment = pending + 1
            pending = following
    return rules
