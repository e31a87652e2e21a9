"""``<switch>`` and conditional attributes, as browsers read them (resvg's tests ``structure/switch`` and
``structure/systemLanguage``, whose references assume an English reader)."""

from __future__ import annotations

from pathlib import Path

import pytest

import tweenrender as tr

HEAD = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 30 10">'


def _columns_drawn(tmp_path: Path, body: str) -> list[bool]:
    """Which of three 10-unit columns hold ink, with a black dot drawn in the corner of each drawing."""
    svg = tmp_path / "s.svg"
    svg.write_text(HEAD + body + '<rect width="0.5" height="0.5"/></svg>')
    picture = tr.frame(tr.load_scene(svg), 0.0, size=(300, 100), background="#ffffff")[..., :3]
    return [bool((picture[40:60, 10 + 100 * c:90 + 100 * c] < 128).any()) for c in range(3)]


def _rect(column: int, attributes: str = "") -> str:
    return f'<rect x="{10 * column}" width="10" height="10" {attributes}/>'


@pytest.mark.parametrize("conditions, chosen", [
    (('requiredExtensions="http://example.org/x"', ""), 1),
    (('systemLanguage="ru-RU"', 'systemLanguage="en-GB"'), 1),
    (('systemLanguage="ru, en"', ""), 0),
    (('requiredFeatures="http://www.w3.org/TR/SVG11/feature#Shape"', ""), 0),
    (('display="none"', ""), None),  # the first that holds is chosen, even one not displayed
])
def test_a_switch_draws_its_first_child_whose_conditions_hold(tmp_path: Path, conditions: tuple[str, str],
                                                               chosen: int | None) -> None:
    body = "<switch><!-- a comment --><unknown/>" + _rect(0, conditions[0]) + _rect(1, conditions[1]) + \
           _rect(2) + "</switch>"
    assert _columns_drawn(tmp_path, body) == [c == chosen for c in range(3)]


def test_conditions_hold_outside_a_switch_too(tmp_path: Path) -> None:
    body = _rect(0, 'systemLanguage="fr"') + _rect(1, 'systemLanguage="en-US"') + \
           f'<g requiredExtensions="">{_rect(2)}</g>'
    assert _columns_drawn(tmp_path, body) == [False, True, False]


def test_a_text_a_switch_does_not_choose_is_not_refused(tmp_path: Path) -> None:
    body = "<switch>" + _rect(0) + '<text x="12" y="8">words</text></switch>'
    assert _columns_drawn(tmp_path, body) == [True, False, False]
