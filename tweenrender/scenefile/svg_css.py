"""CSS of an SVG drawing: its ``<style>`` sheets matched to its elements, and the cascade of one element.

Sheets are read by ``tinycss2`` and selectors matched by ``cssselect2`` (as CairoSVG and WeasyPrint do):
type, class, id, attribute, ``*``, the combinators (descendant, ``>``, ``+``, ``~``) and the structural
pseudo-classes (``:first-child``, ``:nth-child()``, ``:not()`` …), with their specificity. A sheet whose
``type`` is not ``text/css`` is not read; rules inside ``@media`` and ``@supports`` apply, other at-rules
do not. The cascade of one element (CSS 2.1 §6.4.1, SVG 2 §6.7), from weakest to strongest: presentation
attributes, the sheets' declarations (by specificity, then order), the ``style`` attribute, the sheets'
``!important`` declarations, the ``style`` attribute's ``!important`` ones.

Matching is counted: every selector tried and every element a combinator walks over is one unit of
work, and a drawing whose sheets take more than :data:`MAX_STYLE_WORK` units is refused, so that a
hostile sheet (``* * * * * rect`` over a deep tree, thousands of rules for one tag) cannot run for minutes.
"""

from __future__ import annotations

from functools import cache, lru_cache
from typing import Any, Iterator, Protocol

from .svg_flatten import Refusal


__all__ = ["MAX_STYLE_WORK", "Declarations", "cascade", "declarations", "sheet_declarations", "style_attribute"]

MAX_STYLE_WORK = 10_000_000
"""Selectors tried plus elements walked by combinators, summed over a drawing's elements (about 3 s of
matching; 20 000 paths in four groups each under ten ``.layer path`` rules take 1.5 million)."""


class Node(Protocol):
    """An element of the drawing's tree (:class:`.svg_document.Node`)."""

    tag: str
    attrs: dict[str, str]
    children: list[Node]
    text: str
    svg: bool


Declarations = dict[str, tuple[str, bool]]
"""Property name (lower case) → (value as written, ``!important``)."""

_APPLIED_AT_RULES = ("media", "supports")
_TOO_MUCH = (f"expected at most {MAX_STYLE_WORK} style rules applied over the drawing's elements, found more "
             "(a style sheet too large or selectors too deep to match)")


def declarations(tokens: Any) -> Declarations:
    """The declarations of a rule's body or of a ``style`` attribute (a string or tinycss2 tokens), later
    ones over earlier ones; what CSS cannot parse is skipped, as browsers do."""
    import tinycss2

    out: Declarations = {}
    for item in tinycss2.parse_blocks_contents(tokens, skip_comments=True, skip_whitespace=True):
        if item.type == "declaration":
            try:
                value = tinycss2.serialize(item.value).strip()
            except RecursionError:  # a value of blocks nested thousands deep: no property's value, dropped
                continue
            if value:
                out[item.lower_name] = (value, bool(item.important))
    return out


@lru_cache(maxsize=4096)
def style_attribute(text: str) -> Declarations:
    """The declarations of a ``style`` attribute (comments and ``!important`` read as CSS reads them);
    editors write the same few styles on many elements, so each text is parsed once (the result is
    shared: not to be changed)."""
    return declarations(text) if text.strip() else {}


def cascade(presentation: dict[str, str], sheet: tuple[Declarations, ...], inline: Declarations,
            wanted: frozenset[str]) -> dict[str, str]:
    """One element's own properties among ``wanted``: ``presentation`` attributes, then the ``sheet``'s
    declarations that match it (weakest first), then its ``inline`` style, then the ``!important`` ones of
    the sheet and of the inline style."""
    style = {name: value.strip() for name, value in presentation.items() if name in wanted}
    layers = (*sheet, inline)
    for important in (False, True):
        for layer in layers:
            style.update((name, value) for name, (value, strong) in layer.items()
                         if strong is important and name in wanted)
    return style


def _rules(sheet: list[Any], depth: int = 0) -> Iterator[Any]:
    """The qualified rules of a parsed sheet, those inside ``@media`` and ``@supports`` included."""
    import tinycss2

    for rule in sheet:
        if rule.type == "qualified-rule":
            yield rule
        elif rule.type == "at-rule" and rule.lower_at_keyword in _APPLIED_AT_RULES and rule.content and depth < 8:
            yield from _rules(tinycss2.parse_rule_list(rule.content, skip_comments=True, skip_whitespace=True),
                              depth + 1)


def _is_css(node: Node) -> bool:
    kind = node.attrs.get("type", "").strip().lower()
    return kind in ("", "text/css")


def sheet_declarations(root: Node) -> dict[int, tuple[Declarations, ...]]:
    """For every element some rule of the drawing's ``<style>`` sheets matches (keyed by ``id(node)``),
    the declarations of those rules from the weakest (least specific, earliest) to the strongest."""
    import tinycss2

    sheets = [node.text for node in _iterate(root) if node.tag == "style" and node.svg and _is_css(node)]
    if not any(text.strip() for text in sheets):
        return {}
    import cssselect2

    counted_wrapper, counted_matcher = _classes()
    matcher = counted_matcher()
    rules = (rule for text in sheets  # each sheet on its own: an unclosed block ends with its sheet
             for rule in _rules(tinycss2.parse_stylesheet(text, skip_comments=True, skip_whitespace=True)))
    for rule in rules:
        try:
            selectors = cssselect2.compile_selector_list(rule.prelude)
        except Exception:  # noqa: BLE001 - an invalid selector drops its rule, as in CSS (SelectorError, or
            continue  # RecursionError/SyntaxError/MemoryError on a hostile one that nests too deep)
        body = declarations(rule.content)
        if body:
            for selector in selectors:
                if selector.pseudo_element is None:
                    matcher.add_selector(selector, body)
    if not any((matcher.id_selectors, matcher.class_selectors, matcher.lower_local_name_selectors,
                matcher.namespace_selectors, matcher.lang_attr_selectors, matcher.other_selectors)):
        return {}
    wrapper_class = type("Wrapper", (counted_wrapper,), {"work": [0]})  # a count of its own
    tree, nodes = _element_tree(root)
    out: dict[int, tuple[Declarations, ...]] = {}
    for wrapper, node in zip(wrapper_class.from_xml_root(tree).iter_subtree(), nodes):
        found = matcher.match(wrapper)
        if found:
            out[id(node)] = tuple(body for _, _, _, body in found)
    return out


def _iterate(root: Node) -> Iterator[Node]:
    """Every element under ``root`` (itself included) in document order."""
    stack = [root]
    while stack:
        current = stack.pop()
        yield current
        stack.extend(reversed(current.children))


def _element_tree(root: Node) -> tuple[Any, list[Node]]:
    """An ElementTree copy of the tree (local names, attributes) and its nodes in document order."""
    from xml.etree.ElementTree import Element

    nodes = list(_iterate(root))
    copies = {id(node): Element(node.tag, node.attrs) for node in nodes}
    for node in nodes:
        copies[id(node)].extend(copies[id(child)] for child in node.children)
    return copies[id(root)], nodes


def _spend(wrapper: Any, units: int) -> None:
    wrapper.work[0] += units
    if wrapper.work[0] > MAX_STYLE_WORK:
        raise Refusal(_TOO_MUCH)


@cache
def _classes() -> tuple[type, type]:
    """cssselect2's wrapper and matcher, counting the elements combinators walk over and the selectors tried."""
    from cssselect2 import ElementWrapper, Matcher

    class CountedWrapper(ElementWrapper):  # type: ignore[misc]
        work: list[int] = [0]

        @property
        def ancestors(self) -> tuple[Any, ...]:
            found = ElementWrapper.ancestors.fget(self)
            _spend(self, len(found) + 1)
            return found

        @property
        def previous_siblings(self) -> tuple[Any, ...]:
            found = ElementWrapper.previous_siblings.fget(self)
            _spend(self, len(found) + 1)
            return found

        @property
        def etree_siblings(self) -> list[Any]:
            _spend(self, len(self._siblings) + 1)
            return self._siblings

        @etree_siblings.setter
        def etree_siblings(self, value: list[Any]) -> None:
            self._siblings = value

        def iter_children(self) -> Iterator[Any]:
            for child in ElementWrapper.iter_children(self):
                _spend(self, 1)
                yield child

    class CountedMatcher(Matcher):  # type: ignore[misc]
        def add_relevant_selectors(self, element: Any, selectors: list[Any], relevant: list[Any]) -> None:
            _spend(element, len(selectors))
            Matcher.add_relevant_selectors(element, selectors, relevant)

    return CountedWrapper, CountedMatcher
