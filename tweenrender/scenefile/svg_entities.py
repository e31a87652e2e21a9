"""Entities declared in a drawing's DOCTYPE, read where they are safe.

Illustrator writes its namespaces (and older versions their styles) as internal entities
(``<!ENTITY ns_svg "http://www.w3.org/2000/svg">``, ``xmlns="&ns_svg;"``), and renderers expand them.
An entity is expanded only when it is internal (its text written in the file, no ``SYSTEM`` or ``PUBLIC``
file behind it), general (no ``%`` parameter entity) and plain (its text names no other entity, so
references cannot nest); and only while what every reference expands to, summed over the file, stays
within :data:`MAX_EXPANDED_CHARS`. Anything else is refused before the XML is read: entities that expand
without bound ("billion laughs") or read other files have no place in a drawing.
"""

from __future__ import annotations

import re
from collections import Counter

from .svg_flatten import Refusal

__all__ = ["MAX_ENTITIES", "MAX_EXPANDED_CHARS", "UNSAFE", "check_entities", "safe_declaration"]

MAX_ENTITIES = 256
"""Entity declarations in one file."""
MAX_EXPANDED_CHARS = 4 * 1024 * 1024
"""Characters the references of a file expand to, summed: a drawing's styles and namespaces are far below."""
UNSAFE = ("expected plain SVG or internal entities with plain text, found {what} (refused: entities can "
          "expand without bound or read other files); save the drawing as plain SVG")

_DECLARATION = re.compile(rb"""<!ENTITY\b((?:[^>"']|"[^"]*"|'[^']*')*)>""", re.IGNORECASE)
_INTERNAL = re.compile(rb"""\s+([^\s%"'<>&;]+)\s+(?:"([^"]*)"|'([^']*)')\s*$""", re.DOTALL)
_CHARACTER_REFERENCE = re.compile(rb"&#(?:[0-9]+|x[0-9a-fA-F]+);")
_REFERENCE = re.compile(rb"&([^\s%\"'<>&;#]+);")


def check_entities(data: bytes) -> None:
    """Refuse ``data`` when its entity declarations are not all safe to expand (see the module); NULs are
    dropped first, so that UTF-16 and UTF-32 text is read as well."""
    text = data.replace(b"\x00", b"")
    if re.search(rb"<!ENTITY", text, re.IGNORECASE) is None:
        return
    declarations = _DECLARATION.findall(text)
    if len(declarations) > MAX_ENTITIES:
        raise Refusal(UNSAFE.format(what=f"more than {MAX_ENTITIES} entity declarations"))
    if len(declarations) != len(re.findall(rb"<!ENTITY", text, re.IGNORECASE)):
        raise Refusal(UNSAFE.format(what="an entity declaration that cannot be read"))
    references = Counter(_REFERENCE.findall(text))
    expanded = 0
    for body in declarations:
        found = _INTERNAL.match(body)
        if found is None:
            raise Refusal(UNSAFE.format(what=f"<!ENTITY{_excerpt(body)}>"))
        name, value = found.group(1), found.group(2) if found.group(2) is not None else found.group(3)
        if b"&" in _CHARACTER_REFERENCE.sub(b"", value) or b"%" in value:
            raise Refusal(UNSAFE.format(what=f"entity {name.decode('latin-1')} naming another entity"))
        expanded += references[name] * len(value)
        if expanded > MAX_EXPANDED_CHARS:
            raise Refusal(UNSAFE.format(what=f"entities expanding to more than {MAX_EXPANDED_CHARS} characters"))


def safe_declaration(is_parameter: bool, value: str | None, system_id: str | None, public_id: str | None,
                     notation: str | None) -> bool:
    """Whether an entity declaration as the XML parser reports it is one :func:`check_entities` lets through:
    internal, general and parsed."""
    return not is_parameter and value is not None and system_id is None and public_id is None and notation is None


def _excerpt(body: bytes) -> str:
    words = body.decode("latin-1", "replace").strip()
    return " " + (words if len(words) <= 40 else words[:40] + "…")
